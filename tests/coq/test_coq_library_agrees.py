"""The Coq library's decisions against exactsym's ground truth (issue 35).

The library ``proofs/coq/Exactsym.v`` is the trusted base of the Coq refutations; its
negative facts rest on (T1)-(T3) of its header.  Here one ``coqc`` run evaluates, on every
rational polar configuration of ``cases/`` (up to 12 points), whether C is the SEC centre,
the number of rotations and of mirrors among its candidate symmetries, and O_A; each must
agree with :func:`exactsym.symmetry_group` and exactsym's certificate (exact, and
independent of the library; the group only where the origin is the SEC centre), and stay
the same after a rotation, a mirror image and a scale of the configuration; so must
``only_identity`` (every symmetry about C fixes each point: the library then proves the
set orderable) against exactsym's "orderable".  A second run
evaluates the types 0-4 and CW_v = ACW_v on every level against exactsym.paper.
"""

from __future__ import annotations

import re
import shutil
import subprocess
from fractions import Fraction
from pathlib import Path

import pytest

from exactsym.certificates.certificate import make_certificate
from exactsym.certificates.coq_refutation import library_text
from exactsym.geometry.configuration import from_file
from exactsym.io.fileformat import read_config
from exactsym.truth.symmetry import symmetry_group

ROOT = Path(__file__).resolve().parents[2]
COQC = shutil.which("coqc")


def _polar_cases() -> list:
    out = []
    for path in sorted((ROOT / "cases").rglob("*.toml")):
        try:
            config = from_file(read_config(str(path)))
        except Exception:                       # not a configuration file (or unreadable)
            continue
        if config.polar is not None and 3 <= config.n <= 12:
            points = [(Fraction(str(r)), Fraction(str(t))) for r, t in config.polar]
            # exactsym's certificate stays polar iff the origin is the SEC centre
            centred = make_certificate(config)["configuration"]["coordinates"] == "polar"
            out.append((path.relative_to(ROOT).as_posix(), points, symmetry_group(config),
                        centred))
    return out


def _q(f: Fraction) -> str:
    return f"(Qmake ({f.numerator}) {f.denominator})"


def _variants(points):
    """The configuration, turned by 3/11, mirrored, and scaled by 4 (squared: 16)."""
    yield points
    yield [(r, t + Fraction(3, 11)) for r, t in points]
    yield [(r, -t) for r, t in points]
    yield [(16 * r, t) for r, t in points]


@pytest.mark.skipif(COQC is None, reason="coqc is not installed (apt-get install coq): the "
                    "Coq library is not evaluated")
def test_the_library_decides_groups_as_the_ground_truth(tmp_path):
    cases = _polar_cases()
    assert len(cases) >= 20
    lines = [library_text(), "Definition rotations (P : list pt) : nat :=",
             "  length (filter (fun g => match g with Rot _ => true | _ => false end) "
             "(symmetries P)).", ""]
    expected = []
    for k, (_, points, group, centred) in enumerate(cases):
        for j, variant in enumerate(_variants(points)):
            name = f"P{k}_{j}"
            lines.append(f"Definition {name} : list pt := ["
                         + "; ".join(f"Pt {_q(r)} {_q(t)}" for r, t in variant) + "].")
            lines.append(f"Eval vm_compute in (sec_centred {name}, rotations {name}, "
                         f"length (mirrors {name}), in_O_A {name}, only_identity {name}).")
            rotations = group.rotations
            mirrors = group.mirrors
            in_o_a = not (group.name.startswith("D") and not group.orderable
                          or rotations % 2 == 0)
            expected.append((k, j, centred, rotations, mirrors, in_o_a, group.orderable))
    (tmp_path / "Agree.v").write_text("\n".join(lines) + "\n")
    run = subprocess.run([COQC, "-q", "Agree.v"], cwd=tmp_path, capture_output=True,
                         text=True, timeout=900)
    assert run.returncode == 0, run.stderr[-2000:]
    got = re.findall(r"= \((true|false), (\d+)%nat, (\d+)%nat, (true|false), (true|false)\)",
                     run.stdout)
    assert len(got) == len(expected)
    assert sum(1 for e in expected if e[2]) >= 80
    orderable = 0
    for (sec, rot, mir, oa, ident), (k, j, centred, rotations, mirrors, in_o_a, ordered) in \
            zip(got, expected):
        where = f"{cases[k][0]} (variant {j})"
        assert (sec == "true") == centred, where
        if not centred:
            continue                    # the library's candidates are about the origin
        assert (int(rot), int(mir)) == (rotations, mirrors), where
        assert (oa == "true") == in_o_a, where
        # only_identity, the check orderable_of_only_identity proves orderability from
        assert (ident == "true") == ordered, where
        orderable += ordered
    assert orderable >= 20


def _levels(cases) -> list:
    """Every level of 3 to 12 points of the polar cases: its turns in [0, 1), sorted
    (counter-clockwise), once per distinct polygon."""
    seen, out = set(), []
    for _, points, _, _ in cases:
        for r in sorted({r for r, _ in points if r > 0}):
            turns = tuple(sorted({t % 1 for q, t in points if q == r}))
            if 3 <= len(turns) <= 12 and turns not in seen:
                seen.add(turns)
                out.append(turns)
    return out


@pytest.mark.skipif(COQC is None, reason="coqc is not installed (apt-get install coq): the "
                    "Coq library is not evaluated")
def test_the_library_decides_types_and_strings_as_exactsym(tmp_path):
    """The polygon predicates the algorithm refutations rest on (the types 0-4 before
    obs-exh-poly, CW_v = ACW_v, regular) against exactsym.paper's own (review of the Coq
    library, finding 10): on every level of the polar cases, one coqc run."""
    from flint import fmpq

    from exactsym.paper.circle_polygon import CirclePolygon
    from exactsym.paper.polygon.types import polygon_type, vertex_palindromes
    levels = _levels(_polar_cases())
    assert len(levels) >= 30
    lines = [library_text(), ""]
    expected = []
    for k, turns in enumerate(levels):
        lines.append(f"Definition G{k} : list pt := ["
                     + "; ".join(f"Pt 1 {_q(t)}" for t in turns) + "].")
        lines.append(f"Eval vm_compute in (type0 G{k}, type1 G{k}, type2 G{k}, type3 G{k}, "
                     f"type4 G{k}, length (filter (cw_sym G{k}) G{k})).")
        poly = CirclePolygon(tuple(range(len(turns))),
                             tuple(fmpq(t.numerator, t.denominator) for t in turns), True)
        verdict = polygon_type(poly)
        name = str(verdict) if verdict is not None else None
        expected.append((turns, name, len(vertex_palindromes(poly))))
    (tmp_path / "Types.v").write_text("\n".join(lines) + "\n")
    run = subprocess.run([COQC, "-q", "Types.v"], cwd=tmp_path, capture_output=True,
                         text=True, timeout=900)
    assert run.returncode == 0, run.stderr[-2000:]
    got = re.findall(r"= \((true|false), (true|false), (true|false), (true|false), "
                     r"(true|false), (\d+)%nat\)", run.stdout)
    assert len(got) == len(expected)
    kinds = set()
    for g, (turns, name, palindromes) in zip(got, expected):
        coq_types = [f"type-{i}" for i in range(5) if g[i] == "true"]
        want = [] if name in (None, "unclassified") else [name]
        assert coq_types == want, (turns, coq_types, name)
        assert int(g[5]) == palindromes, (turns, g[5], palindromes)
        kinds.add(name)
    assert {"type-0", "type-2", "type-3", "type-4", "unclassified", None} <= kinds, kinds
