"""The ground-truth section of ``exactsym check`` (``../shared/spec/cli-1.md``).

Importing this module appends :func:`truth_section` to :data:`exactsym.report.SECTIONS`;
it adds the keys ``group``, ``orderable``, ``ordering``, ``leader`` and
``symmetries`` (``{"rotations": k, "mirrors": m}``, both ``null`` for the O2 of a
single point), and a few lines for the table (``report["_table_lines"]``).
"""

from __future__ import annotations

from . import report as _report
from .exact import number_text
from .symmetry import Isometry, SymmetryGroup, symmetry_group

_MAX_LISTED = 12


def truth_section(config, rings, report: dict, options: dict | None = None) -> None:
    """Add the ground truth (:func:`exactsym.symmetry.symmetry_group`) to ``report``."""
    group = symmetry_group(config, rings)
    report["group"] = group.name
    report["orderable"] = group.orderable
    report["ordering"] = list(group.ordering) if group.ordering is not None else None
    report["leader"] = group.leader
    finite = group.name != "O2"
    report["symmetries"] = {"rotations": group.rotations if finite else None,
                            "mirrors": group.mirrors if finite else None}
    report.setdefault("_table_lines", []).extend(table_lines(group))


def table_lines(group: SymmetryGroup) -> list[str]:
    """Readable lines naming the group and the rotations and mirrors found."""
    centre = f"({number_text(group.centre[0])}, {number_text(group.centre[1])})"
    if group.name == "O2":
        lines = ["ground truth: group O2 (a single point: every rotation about it and "
                 "every mirror through it)"]
    else:
        k, m = group.rotations, group.mirrors
        what = f"{k} rotation{'s' if k > 1 else ''} about {centre}" + \
            (f" (by multiples of 1/{k} turn)" if k > 1 else ", the identity only")
        what += f", {m} mirror{'s' if m != 1 else ''}" + (" through it" if m else "")
        lines = [f"ground truth: group {group.name}: {what}"]
        if group.rotation_generator is not None:
            lines.append(f"  rotation by 1/{k} turn: {_moves(group.rotation_generator, group)}")
        if group.mirror is not None:
            lines.append(f"  mirror {_mirror_line(group.mirror)}: {_moves(group.mirror, group)}")
    if group.orderable:
        lines.append(f"  orderable: yes; leader {group.leader}; ordering "
                     f"{_listed(group.ordering)}")
    elif group.leader is not None:
        lines.append(f"  orderable: no; leader {group.leader} (fixed by every symmetry)")
    else:
        lines.append("  orderable: no; no leader (no robot is fixed by every symmetry)")
    return lines


def _mirror_line(mirror: Isometry) -> str:
    if mirror.turn is not None:
        return f"at {number_text(mirror.turn)} turn through the centre"
    (c, s), _ = mirror.matrix
    return (f"through the centre, matrix [[{number_text(c)}, {number_text(s)}], "
            f"[{number_text(s)}, {number_text(-c)}]]")


def _moves(g: Isometry, group: SymmetryGroup) -> str:
    perm = g.permutation
    fixed = [i for i, j in enumerate(perm) if i == j]
    ref = group.reference
    moved = f"point {ref} -> {perm[ref]}" if ref is not None and perm[ref] != ref else ""
    parts = [moved] if moved else []
    parts.append(f"fixes {'no point' if not fixed else 'points ' + _listed(fixed)}")
    return "; ".join(parts)


def _listed(indices) -> str:
    indices = list(indices)
    if len(indices) <= _MAX_LISTED:
        return str(indices)
    return "[" + ", ".join(map(str, indices[:_MAX_LISTED])) + f", ... ({len(indices)} in all)]"


if truth_section not in _report.SECTIONS:
    _report.SECTIONS.append(truth_section)
