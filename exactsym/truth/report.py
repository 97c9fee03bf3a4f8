"""The ground truth in the report of ``exactsym check`` (``docs/cli.md``).

:func:`truth_json` gives the keys ``group``, ``orderable``, ``ordering``, ``leader`` and
``symmetries`` (``{"rotations": k, "mirrors": m}``, both ``null`` for the O2 of a
single point); :func:`table_lines` the lines of the text report.
"""

from __future__ import annotations

from ..exact import number_text
from .symmetry import Isometry, SymmetryGroup

_MAX_LISTED = 12


def truth_json(group: SymmetryGroup) -> dict:
    """The report's keys of the ground truth (:func:`exactsym.truth.symmetry.symmetry_group`)."""
    finite = group.name != "O2"
    return {"group": group.name, "orderable": group.orderable,
            "ordering": list(group.ordering) if group.ordering is not None else None,
            "leader": group.leader,
            "symmetries": {"rotations": group.rotations if finite else None,
                           "mirrors": group.mirrors if finite else None}}


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

