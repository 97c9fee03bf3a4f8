"""Certificates (issue 3): round trips through the independent checker, and tampering caught.

Every certificate is serialised to JSON and read back before it is checked, as ``verify``
would see it.  Tampered certificates get their ``configuration_sha256`` recomputed (unless the
test is about that fingerprint), so that the mathematical checks, not the fingerprint, must
catch the change.
"""

from __future__ import annotations

import ast
import copy
import json
import math
import random
import subprocess
import sys
from fractions import Fraction
from pathlib import Path
from types import SimpleNamespace

import pytest
from flint import fmpq, fmpz_poly, nmod_poly

from exactsym import checker
from exactsym.checker.ext_primitive import irreducible_mod
from exactsym.certificates.certificate import CertificateError, make_certificate
from exactsym.cli.main import main as cli_main
from exactsym.geometry.configuration import Configuration, load
from exactsym.truth.symmetry import symmetry_group

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "cases" / "examples"


def write(tmp_path, name: str, text: str) -> Path:
    path = tmp_path / name
    path.write_text(text)
    return path


def certify(path) -> dict:
    return json.loads(json.dumps(make_certificate(load(path))))


def verify(cert: dict) -> tuple[bool, str]:
    return checker.verify_certificate(json.loads(json.dumps(cert)))


def rehash(cert: dict) -> dict:
    cert["configuration_sha256"] = checker.digest(cert["configuration"])
    return cert


def polar_lines(*rings) -> str:
    """``rings``: (r, [turns]) pairs."""
    return "".join(f"polar {r} {t}\n" for r, turns in rings for t in turns)


# ------------------------------------------------------------------ configurations
HEXAGON = "1 0\n1/2 sqrt(3)/2\n-1/2 sqrt(3)/2\n-1 0\n-1/2 -sqrt(3)/2\n1/2 -sqrt(3)/2\n"
# the same hexagon by trigonometry: the real cyclotomic field Q(2cos(2pi/12)) = Q(sqrt(3))
HEXAGON_TRIG = "".join(f"{sx}cos(pi/3) {sy}sin(pi/3)\n" for sx, sy in
                       (("", ""), ("-", ""), ("-", "-"), ("", "-"))) + "1 0\n-1 0\n"
# a chiral C3 set in Cartesian coordinates (sqrt(3)): an equilateral triangle and a turned copy
CHIRAL_C3 = ("2 0\n-1 sqrt(3)\n-1 -sqrt(3)\n3 1\n-3/2-sqrt(3)/2 3*sqrt(3)/2-1/2\n"
             "-3/2+sqrt(3)/2 -3*sqrt(3)/2-1/2\n")
CASES = {
    # name: (file text, group, orderable, coordinates, field method or None)
    "c1-rational": ("0 0\n3 1\n1 5\n7 2\n", "C1", True, "cartesian", None),
    "d1-kite": ("-1 0\n1 0\n0 3\n0 1\n", "D1", False, "cartesian", None),
    "d2-rectangle": ("0 0\n4 0\n4 2\n0 2\n", "D2", False, "cartesian", None),
    "d4-square-centre": ("0 0\n2 0\n2 2\n0 2\n1 1\n", "D4", False, "cartesian", None),
    "d4-two-orbits": ("3 1\n-1 3\n-3 -1\n1 -3\n1 3\n-3 1\n-1 -3\n3 -1\n5 0\n0 5\n-5 0\n0 -5\n",
                      "D4", False, "cartesian", None),
    "c4-rational": ("3 1\n-1 3\n-3 -1\n1 -3\n5 0\n0 5\n-5 0\n0 -5\n", "C4", False, "cartesian",
                    None),
    "collinear": ("0 0\n1 0\n3 0\n", "D1", True, "cartesian", None),
    "collinear-symmetric": ("0 0\n1 1\n3 3\n4 4\n", "D2", False, "cartesian", None),
    "two-points": ("0 0\n1 1\n", "D2", False, "cartesian", None),
    "one-point": ("5 7\n", "O2", True, "cartesian", None),
    "one-polar-point": ("polar 2 1/3\n", "O2", True, "polar", None),
    "hexagon-sqrt3": (HEXAGON, "D6", False, "cartesian", "radicands"),
    "hexagon-trig": (HEXAGON_TRIG, "D6", False, "cartesian", "real-cyclotomic"),
    "chiral-c3-sqrt3": (CHIRAL_C3, "C3", False, "cartesian", "radicands"),
    "sqrt2-sqrt3": ("0 0\nsqrt(2) 0\n0 sqrt(3)\n1 1\n", "C1", True, "cartesian",
                    "radicands"),
    "nested-radical": ("0 0\nsqrt(1+sqrt(2)) 0\n1 1\n", "C1", True, "cartesian", "tower"),
    "d7-polar": (polar_lines((1, [f"{j}/7" for j in range(7)])), "D7", False, "polar", None),
    "d7-polar-two-rings": (polar_lines((3, [f"{j}/7" for j in range(7)]),
                                       (1, [f"{2 * j + 1}/14" for j in range(7)]), (0, ["0"])),
                           "D7", False, "polar", None),
    "c7-polar": (polar_lines((2, [f"{j}/7" for j in range(7)]),
                             (1, [f"1/30+{j}/7" for j in range(7)])), "C7", False, "polar", None),
    "d1-polar": (polar_lines((2, ["0", "1/3", "2/3"]), (1, ["1/10", "-1/10"])), "D1", False,
                 "polar", None),
    "c1-polar": (polar_lines((2, ["0", "1/3", "2/3"]), (1, ["1/10", "1/7"])), "C1", True, "polar",
                 None),
    "c3-polar-irrational-radius": (polar_lines(("1+sqrt(2)", ["0", "1/3", "2/3"]),
                                               ("sqrt(5)", ["1/12", "5/12", "3/4"])),
                                   "C3", False, "polar", "radicands"),
    "polar-off-centre": ("polar 1 0\npolar 1 1/5\npolar 2 1/7\n", "C1", True, "cartesian",
                         "real-cyclotomic"),
}


@pytest.mark.parametrize("name", sorted(CASES))
def test_round_trip(tmp_path, name):
    text, group, orderable, coordinates, method = CASES[name]
    path = write(tmp_path, "c.txt", text)
    cert = certify(path)
    truth = symmetry_group(load(path))
    assert cert["format"] == "exactsym-certificate" and cert["version"] == 1
    assert cert["claim"] == {"group": group, "orderable": orderable,
                             "ordering": list(truth.ordering) if orderable else None,
                             "leader": truth.leader}
    assert cert["configuration"]["coordinates"] == coordinates
    field = cert["configuration"]["field"]
    kind = field and ("radicands" if "radicands" in field else "tower" if "tower" in field
                      else field["irreducible"]["method"])
    assert kind == method or (field is None and not method)
    proved = "ordering and leader" if orderable else "leader"
    assert verify(cert) == (True, f"group {group}, orderable {str(orderable).lower()}, {proved}")


def test_example_files_round_trip():
    for path in sorted(EXAMPLES.iterdir()):
        cert = certify(path)
        ok, message = verify(cert)
        assert ok, (path, message)
    pinwheel = certify(EXAMPLES / "chiral-nine-gon.toml")
    assert pinwheel["claim"] == {"group": "C3", "orderable": False, "ordering": None,
                                 "leader": None}
    assert pinwheel["configuration"]["coordinates"] == "polar"


def test_random_configurations_round_trip():
    """Random small sets, some made symmetric: the checker agrees with the tool every time."""
    rnd = random.Random(11)
    orbit_maps = [lambda x, y: [(x, y)], lambda x, y: [(x, y), (-x, -y)],
                  lambda x, y: [(x, y), (-y, x), (-x, -y), (y, -x)],
                  lambda x, y: [(x, y), (x, -y)],
                  lambda x, y: [(x, y), (-y, x), (-x, -y), (y, -x), (x, -y), (-y, -x), (-x, y),
                                (y, x)]]
    for _ in range(60):
        orbit = rnd.choice(orbit_maps)
        points = set()
        for _ in range(rnd.randint(1, 4)):
            points.update(orbit(rnd.randint(-4, 4), rnd.randint(-4, 4)))
        if rnd.random() < 0.3:
            points.add((rnd.randint(-4, 4), rnd.randint(-4, 4)))
        shift = Fraction(rnd.randint(-3, 3), rnd.randint(1, 3))
        config = Configuration.from_points([(x + shift, y) for x, y in sorted(points)])
        cert = json.loads(json.dumps(make_certificate(config)))
        ok, message = verify(cert)
        assert ok, (sorted(points), message)


def _explicit_image(points, ref, b, w, kind):
    """g(p_w) for the isometry g about the centroid c with g(p_ref) = p_b, by its matrix."""
    n = len(points)
    cx, cy = (sum(p[k] for p in points) / n for k in (0, 1))
    (ux, uy), (vx, vy), (x, y) = ((p[0] - cx, p[1] - cy) for p in
                                  (points[ref], points[b], points[w]))
    s = ux * ux + uy * uy
    if kind == "rotation":
        dot, cross = (ux * vx + uy * vy) / s, (ux * vy - uy * vx) / s
        return cx + dot * x - cross * y, cy + cross * x + dot * y
    e, f = (ux * vx - uy * vy) / s, (ux * vy + uy * vx) / s
    return cx + e * x + f * y, cy + f * x - e * y


def test_refutations_are_judged_by_the_exact_image():
    """The checker decides "the candidate maps p_w onto a point of P" from invariants
    (distance from c, distance from p_b, side of the line c p_b), with no product of the
    centroid's sum by itself: for every candidate of every level and every point w, its
    verdict on a refutation [b, w] is that of the image computed by its matrix.  Symmetric
    sets are where a point at the right two distances lies on the wrong side (the twin of
    g(p_w) in the line c p_b is rho(p_w) for the rotation rho in the group with
    rho(p_ref) = p_b, when the reflection g is not in it, and the other way round)."""
    rnd = random.Random(5)
    sets = [[(3, 1), (-1, 3), (-3, -1), (1, -3), (1, 3), (-3, 1), (-1, -3), (3, -1)],   # C4 x2
            [(2, 1), (-1, 2), (-2, -1), (1, -2), (0, 0)],                              # C4
            [(-1, 0), (1, 0), (0, 3), (0, 1)],                                         # D1
            [(2, 1), (-2, 1), (2, -1), (-2, -1), (1, 2)],                              # D1
            [(0, 0), (4, 0), (4, 2), (0, 2)]]                                          # D2
    for _ in range(6):
        base_points = {(rnd.randint(-5, 5), rnd.randint(-5, 5)) for _ in range(3)}
        sets.append(sorted(base_points | {(-x, -y) for x, y in base_points}))       # C2
    judged, twins = {True: 0, False: 0}, 0     # twins: refuted only by the side
    for points in sets:
        points = [(Fraction(x) + Fraction(1, 3), Fraction(y)) for x, y in points]
        cert = json.loads(json.dumps(make_certificate(Configuration.from_points(points))))
        ref = cert["witness"]["reference"]
        n = len(points)
        c = (sum(p[0] for p in points) / n, sum(p[1] for p in points) / n)

        def d2(p):
            return (p[0] - c[0]) ** 2 + (p[1] - c[1]) ** 2
        level = [b for b in range(n) if d2(points[b]) == d2(points[ref])]
        for kind in ("rotation", "reflection"):
            for b in level:
                for w in range(n):
                    bad = copy.deepcopy(cert)
                    bad["witness"]["refutations"][kind] = [[b, w]]     # rotations first
                    ok, message = verify(bad)
                    inside = _explicit_image(points, ref, b, w, kind) in set(points)
                    assert ("onto a point of the configuration" in message) is inside, \
                        (points, kind, b, w, message)
                    judged[inside] += 1
                    twins += not inside and any(
                        d2(p) == d2(points[w]) and _dist2(p, points[b]) ==
                        _dist2(points[w], points[ref]) for p in points)
    assert judged[True] > 200 and judged[False] > 50 and twins > 10, (judged, twins)


def _dist2(p, q):
    return (p[0] - q[0]) ** 2 + (p[1] - q[1]) ** 2


def test_levels_by_balls_compare_only_overlapping_points_exactly():
    """witness._levels_by_balls: the levels of _sparsest (in the order of their first
    point, the centre left out), with exact squared distances asked only for the points
    whose balls meet another's or hold 0."""
    from flint import arb
    from exactsym.certificates.witness import _levels_by_balls
    norms = [Fraction(2), Fraction(5), Fraction(2), Fraction(0), Fraction(7), Fraction(9, 2),
             Fraction(5), Fraction(1, 3)]
    asked = []

    def exact(i):
        asked.append(i)
        return norms[i]
    tight = [arb(float(v), 1e-9) for v in norms]
    assert _levels_by_balls(tight, exact) == [[0, 2], [1, 6], [4], [5], [7]]
    assert sorted(asked) == [0, 1, 2, 3, 6]         # equal values, and the ball holding 0
    asked.clear()
    wide = tight[:5] + [arb(4.5, 2.6)] + tight[6:]  # 4.5 +- 2.6 meets 2, 5, 5 and 7
    assert _levels_by_balls(wide, exact) == [[0, 2], [1, 6], [4], [5], [7]]
    assert sorted(asked) == [0, 1, 2, 3, 4, 5, 6]
    asked.clear()
    assert _levels_by_balls([arb(0, "inf")] * 8, exact) == [[0, 2], [1, 6], [4], [5], [7]]
    assert sorted(asked) == list(range(8))


# ------------------------------------------------------------------ tampering
def base(tmp_path, name):
    return certify(write(tmp_path, "c.txt", CASES[name][0]))


def caught(cert: dict, *fragments: str, fingerprint: bool = True) -> str:
    if fingerprint:
        rehash(cert)
    ok, message = verify(cert)
    assert not ok, "tampered certificate accepted"
    assert any(f in message for f in fragments), message
    return message


def test_tampered_claims(tmp_path):
    cert = base(tmp_path, "d4-square-centre")
    for group in ("D2", "C4", "D8", "C1", "O2"):
        bad = copy.deepcopy(cert)
        bad["claim"]["group"] = group
        caught(bad, f"the claim says group '{group}' but the witness proves D4")
    bad = copy.deepcopy(cert)
    bad["claim"]["orderable"] = True
    caught(bad, "the claim says orderable True but group D4 makes it False")
    bad = base(tmp_path, "c1-rational")
    bad["claim"]["orderable"] = False
    caught(bad, "orderable False but group C1 makes it True")
    bad = base(tmp_path, "collinear")               # D1 of a collinear set: orderable
    bad["claim"]["orderable"] = False
    caught(bad, "group D1 makes it True")


def test_fingerprint(tmp_path):
    cert = base(tmp_path, "c1-rational")
    cert["configuration"]["points"][1][0] = "4"     # a changed point, fingerprint left stale
    caught(cert, "configuration_sha256 does not match", fingerprint=False)


def test_tampered_points(tmp_path):
    cert = base(tmp_path, "d4-two-orbits")
    bad = copy.deepcopy(cert)
    bad["configuration"]["points"][0] = ["3", "2"]  # the centroid moves
    caught(bad, "the centre is not the centroid")
    bad = copy.deepcopy(cert)                       # an orbit moved, the centroid stays
    for i, pt in enumerate(((3, 2), (-2, 3), (-3, -2), (2, -3))):
        bad["configuration"]["points"][i] = [str(pt[0]), str(pt[1])]
    caught(bad, "is not point")
    bad = copy.deepcopy(cert)
    bad["configuration"]["points"][1] = bad["configuration"]["points"][0]
    caught(bad, "points 0 and 1 coincide")
    bad = base(tmp_path, "d7-polar")
    bad["configuration"]["points"][3][1] = "3/8"
    caught(bad, "rotation: the image of point")
    bad = base(tmp_path, "d7-polar-two-rings")
    bad["configuration"]["points"][0][0] = "1/2"    # the outer ring loses a point
    caught(bad, "the origin is not the centre of the smallest enclosing circle", "image of point")
    bad = base(tmp_path, "d7-polar")
    bad["configuration"]["points"][2][0] = "-1"
    caught(bad, "a squared radius is negative")
    for name in ("hexagon-trig", "hexagon-sqrt3"):
        bad = base(tmp_path, name)
        bad["configuration"]["points"][1][1] = ["0", "1/3"] if name == "hexagon-trig" else \
            {"3": "1/3"}
        caught(bad, "the centre is not the centroid", "is not point")
    bad = base(tmp_path, "c3-polar-irrational-radius")
    bad["configuration"]["points"][0][0] = {"1": "3", "2": "3"}  # 3 + 3 sqrt(2), not 3 + 2 sqrt(2)
    caught(bad, "image of point", "the origin is not the centre")


def test_tampered_generators(tmp_path):
    cert = base(tmp_path, "d4-square-centre")
    for which in ("rotation", "mirror"):
        perm = cert["witness"][which]["permutation"]
        bad = copy.deepcopy(cert)
        j = next(i for i in range(len(perm)) if perm[i] != i)
        k = perm.index(j)
        bad["witness"][which]["permutation"][j], bad["witness"][which]["permutation"][k] = \
            perm[k], perm[j]
        caught(bad, f"{which}: the image of point")
        bad = copy.deepcopy(cert)
        bad["witness"][which]["permutation"][0] = 99
        caught(bad, f"{which}: not a list of 5 indices")
        bad = copy.deepcopy(cert)
        bad["witness"][which]["matrix"][0][0] = "1/2"
        caught(bad, f"{which}: the matrix is not orthogonal")
        bad = copy.deepcopy(cert)
        bad["witness"][which]["centre"][0] = "0"
        caught(bad, f"{which}: the centre is not the centroid")
    bad = copy.deepcopy(cert)                       # a reflection passed off as a rotation
    bad["witness"]["rotation"] = copy.deepcopy(cert["witness"]["mirror"])
    caught(bad, "rotation: the matrix does not have determinant 1")
    bad = copy.deepcopy(cert)                       # rotation by a quarter -> by a half
    bad["witness"]["rotation"]["matrix"] = [["-1", "0"], ["0", "-1"]]
    caught(bad, "rotation: the image of point")
    bad = copy.deepcopy(cert)                       # the mirror left out: D4 -> C4
    bad["witness"]["mirror"] = None
    caught(bad, "the reflection taking point")
    bad = base(tmp_path, "hexagon-trig")            # an algebraic matrix entry
    bad["witness"]["rotation"]["matrix"][1][0] = ["0", "1/3"]
    caught(bad, "rotation: the matrix is not orthogonal")
    bad = base(tmp_path, "hexagon-sqrt3")           # the same, in the square-root field
    bad["witness"]["rotation"]["matrix"][1][0] = {"3": "1/3"}
    caught(bad, "rotation: the matrix is not orthogonal")
    polar = base(tmp_path, "d7-polar")
    for which, turn in (("rotation", "2/7"), ("rotation", "1/8"), ("mirror", "1/14"),
                        ("mirror", "1/5")):
        bad = copy.deepcopy(polar)
        bad["witness"][which]["turn"] = turn
        caught(bad, f"{which}: the image of point")
    bad = copy.deepcopy(polar)
    bad["witness"]["rotation"]["permutation"][0] = 2
    caught(bad, "rotation: the image of point 0 is not point 2")
    bad = base(tmp_path, "c1-rational")             # a fake symmetry for an asymmetric set
    bad["witness"]["rotation"] = {"centre": ["11/4", "2"], "matrix": [["-1", "0"], ["0", "-1"]],
                                  "permutation": [2, 3, 0, 1]}
    caught(bad, "rotation: the image of point 0 is not point 2")


def test_tampered_refutations(tmp_path):
    cert = base(tmp_path, "c1-rational")
    refutations = cert["witness"]["refutations"]
    ref = cert["witness"]["reference"]
    kind = "rotation" if refutations["rotation"] else "reflection"
    bad = copy.deepcopy(cert)                       # the witness point: the reference itself
    bad["witness"]["refutations"][kind][0][1] = ref
    caught(bad, "it refutes nothing")
    bad = copy.deepcopy(cert)
    bad["witness"]["refutations"][kind][0][1] = 17
    caught(bad, "bad point 17")
    bad = copy.deepcopy(cert)
    del bad["witness"]["refutations"][kind][0]
    caught(bad, "is neither in the claimed group nor refuted")
    bad = copy.deepcopy(cert)
    bad["witness"]["refutations"] = {}
    caught(bad, "is neither in the claimed group nor refuted")
    pinwheel = certify(EXAMPLES / "chiral-nine-gon.toml")   # C3: reflections are refuted
    bad = copy.deepcopy(pinwheel)
    b, w = bad["witness"]["refutations"]["reflection"][0]
    bad["witness"]["refutations"]["reflection"][0] = [b, bad["witness"]["reference"]]
    caught(bad, "it refutes nothing")
    bad = copy.deepcopy(pinwheel)
    off_level = next(i for i, p in enumerate(bad["configuration"]["points"])
                     if p[0] != bad["configuration"]["points"][bad["witness"]["reference"]][0])
    bad["witness"]["refutations"]["reflection"].append([off_level, 0])
    caught(bad, f"point {off_level} is not on the level of the reference point")


def test_tampered_reference(tmp_path):
    cert = base(tmp_path, "d4-square-centre")
    cert["witness"]["reference"] = 4                # the point at the centre
    caught(cert, "the reference point is the centre")
    cert = base(tmp_path, "c1-rational")
    ref = cert["witness"]["reference"]
    for other in range(4):
        if other != ref:
            bad = copy.deepcopy(cert)
            bad["witness"]["reference"] = other
            caught(bad, "is not on the level of the reference point",
                   "is neither in the claimed group nor refuted", "it refutes nothing")
    cert["witness"]["reference"] = 9
    caught(cert, "bad reference point 9")
    polar = base(tmp_path, "d7-polar-two-rings")
    polar["witness"]["reference"] = 14              # the point at the origin
    caught(polar, "the reference point is the centre")
    pinwheel = certify(EXAMPLES / "chiral-nine-gon.toml")
    pinwheel["witness"]["reference"] = (pinwheel["witness"]["reference"] + 3) % 9   # other ring
    caught(pinwheel, "is not on the level of the reference point", "neither in the claimed")


def test_tampered_field(tmp_path):
    cert = base(tmp_path, "hexagon-trig")
    field = cert["configuration"]["field"]
    assert field["minpoly"] == ["-3", "0", "1"] and field["irreducible"]["conductor"] == 12
    for minpoly, reason in ((["-2", "0", "1"], "not that of 2cos(2pi/12)"),
                            (["-5", "0", "1"], "does not change sign"),
                            (["5"], "degree >= 2"),
                            # (x^2 - 3)(x^2 - 5): a reducible polynomial with the same root
                            (["15", "0", "-8", "0", "1"], "not that of 2cos(2pi/12)")):
        bad = copy.deepcopy(cert)
        bad["configuration"]["field"]["minpoly"] = minpoly
        caught(bad, reason)
    bad = copy.deepcopy(cert)                       # the reducible one, with a "prime" proof
    bad["configuration"]["field"]["minpoly"] = ["15", "0", "-8", "0", "1"]
    bad["configuration"]["field"]["irreducible"] = {"method": "prime", "prime": 7}
    caught(bad, "not irreducible modulo 7")
    for interval, reason in ((["2", "3"], "does not change sign"),
                             (["-2", "2"], "does not change sign"),
                             (["2", "1"], "does not change sign"),
                             (["1", "x"], "not an exact rational")):
        bad = copy.deepcopy(cert)
        bad["configuration"]["field"]["interval"] = interval
        caught(bad, reason)
    bad = copy.deepcopy(cert)                       # x^3 - 3x: roots 0 and +-sqrt(3)
    bad["configuration"]["field"]["minpoly"] = ["0", "-3", "0", "1"]
    bad["configuration"]["field"]["interval"] = ["-1", "2"]
    caught(bad, "does not change sign", "does not isolate one root")
    bad = copy.deepcopy(cert)
    bad["configuration"]["field"]["interval"] = ["-2", "2"]
    bad["configuration"]["field"]["minpoly"] = ["-3", "0", "1"]
    caught(bad, "does not change sign")
    for proof, reason in (({"method": "real-cyclotomic", "conductor": 24}, "2cos(2pi/24)"),
                          ({"method": "prime", "prime": 11}, "not irreducible modulo 11"),
                          ({"method": "prime", "prime": 15}, "15 is not a prime"),
                          ({"method": "trust me"}, "unknown irreducibility proof")):
        bad = copy.deepcopy(cert)
        bad["configuration"]["field"]["irreducible"] = proof
        caught(bad, reason)
    good = copy.deepcopy(cert)                      # x^2 - 3 is irreducible mod 5: still valid
    good["configuration"]["field"]["irreducible"] = {"method": "prime", "prime": 5}
    assert verify(rehash(good))[0]
    nested = base(tmp_path, "nested-radical")
    nested["configuration"]["field"]["tower"]["levels"][0]["prime"] = 2
    caught(nested, "not an odd prime")


def test_malformed_certificates(tmp_path):
    cert = base(tmp_path, "c1-rational")
    assert verify([]) == (False, "not an exactsym certificate of version 1")
    for key in ("format", "version"):
        bad = copy.deepcopy(cert)
        bad[key] = "2"
        assert verify(bad) == (False, "not an exactsym certificate of version 1")
    for mutate, reason in (
            (lambda c: c.pop("witness"), "malformed certificate (KeyError"),
            (lambda c: c["configuration"].update(points=[]), "points must be pairs"),
            (lambda c: c["configuration"]["points"].append(["1"]), "points must be pairs"),
            (lambda c: c["configuration"].update(coordinates="spherical"), "unknown coordinates"),
            (lambda c: c["configuration"]["points"].__setitem__(0, ["0.5", "1"]),
             "not an exact rational: '0.5'"),
            (lambda c: c["configuration"]["points"].__setitem__(0, ["1/0", "1"]),
             "not an exact rational: '1/0'"),
            (lambda c: c["configuration"]["points"].__setitem__(0, [1.5, "1"]),
             "not an exact rational: 1.5"),
            (lambda c: c["witness"]["refutations"].update(rotation=[[1]]), "malformed")):
        bad = copy.deepcopy(cert)
        mutate(bad)
        caught(bad, reason)


# ------------------------------------------------------------------ hand-made symmetry data
def test_certificate_from_hand_made_group():
    """make_certificate needs only the group's generators and permutations: a group written by
    hand (no exactsym.truth.symmetry) gives a certificate that verifies, and a wrong one does not."""
    config = Configuration.from_points([(0, 0), (2, 0), (2, 2), (0, 2)])
    one, zero = fmpq(1), fmpq(0)
    iso = lambda kind, matrix, perm: SimpleNamespace(kind=kind, centre=(one, one), turn=None,
                                                     matrix=matrix, permutation=perm)
    group = SimpleNamespace(
        name="D4", orderable=False, polar=False, centre=(one, one), ordering=None, leader=None,
        rotation_generator=iso("rotation", ((zero, -one), (one, zero)), (1, 2, 3, 0)),
        mirror=iso("reflection", ((one, zero), (zero, -one)), (3, 2, 1, 0)))
    cert = json.loads(json.dumps(make_certificate(config, group)))
    assert cert["witness"]["refutations"] == {"rotation": [], "reflection": []}
    assert verify(cert) == (True, "group D4, orderable false, leader")
    smaller = SimpleNamespace(**{**vars(group), "name": "C4", "mirror": None})
    with pytest.raises(CertificateError, match="symmetry missing from the group"):
        make_certificate(config, smaller)           # certify never writes a false claim


def test_hand_written_polar_certificate():
    """A certificate typed by hand, from the format documentation alone."""
    points = [["1", f"{j}/5"] for j in range(5)] + [["1/4", "1/10"]]
    cert = {"format": "exactsym-certificate", "version": 1,
            "configuration": {"coordinates": "polar", "field": None, "points": points},
            "claim": {"group": "D1", "orderable": False},
            "witness": {"reference": 5, "rotation": None,
                        "mirror": {"turn": "1/10", "permutation": [1, 0, 4, 3, 2, 5]},
                        "refutations": {"rotation": [], "reflection": []}}}
    assert verify(rehash(cert)) == (True, "group D1, orderable false")
    cert["claim"]["orderable"] = True
    caught(cert, "makes it False")


def test_polar_certificate_needs_the_origin_at_the_sec_centre():
    """Two points on one ray from the origin: about the origin only the mirror through the
    ray maps them onto themselves (D1, orderable), but their true group is D2 about their
    midpoint.  The origin is not their SEC centre, and the checker says so."""
    cert = {"format": "exactsym-certificate", "version": 1,
            "configuration": {"coordinates": "polar", "field": None,
                              "points": [["1", "0"], ["4", "0"]]},
            "claim": {"group": "D1", "orderable": True},
            "witness": {"reference": 0, "rotation": None,
                        "mirror": {"turn": "0", "permutation": [0, 1]},
                        "refutations": {"rotation": [], "reflection": []}}}
    caught(cert, "the origin is not the centre of the smallest enclosing circle")


def test_interval_must_isolate_one_root():
    """Psi_7 = x^3 + x^2 - 2x - 1 has its three roots 2cos(2k pi/7) in (-2, 2): a sign
    change there does not say which root theta is."""
    spec = {"minpoly": ["-1", "-2", "1", "1"], "interval": ["-2", "2"],
            "irreducible": {"method": "real-cyclotomic", "conductor": 7}}
    with pytest.raises(checker.Invalid, match="does not isolate one root"):
        checker.Field(spec)
    field = checker.Field({**spec, "interval": ["1", "3/2"]})   # 2cos(2pi/7) = 1.2469...
    assert checker.sgn(field.num(["0", "1"]) - Fraction(5, 4)) == -1
    assert checker.sgn(field.num(["0", "1"]) - Fraction(6, 5)) == 1


# ------------------------------------------------------------------ the checker's parts
CHECKER = ROOT / "exactsym" / "checker"
CHECKER_CORE = ("__init__", "__main__", "numbers", "dispatch", "groups", "ordering", "refutations")
CHECKER_MODULES = CHECKER_CORE + ("ext_boxes", "ext_polygons", "ext_primes", "ext_primitive",
                                  "ext_sparse", "ext_sparse_tower", "ext_tower")


def test_checker_imports_only_the_standard_library():
    """Every checker module imports the standard library and, relatively, the other checker
    modules: nothing else of exactsym, and no fallback for running as loose files."""
    allowed = {"__future__", "fractions", "json", "math", "sys", "argparse", "dataclasses",
               "typing", "itertools", "functools", "collections", "hashlib", "re", "gc",
               "importlib"}
    assert sorted(p.stem for p in CHECKER.glob("*.py")) == sorted(CHECKER_MODULES)
    siblings = set(CHECKER_MODULES)
    for module in CHECKER_MODULES:
        tree = ast.parse((CHECKER / f"{module}.py").read_text())
        imported = set()
        for node in ast.walk(tree):
            if isinstance(node, ast.Import):
                imported.update(alias.name.split(".")[0] for alias in node.names)
            elif isinstance(node, ast.ImportFrom):
                if node.level:
                    assert node.level == 1 and (node.module is None or node.module in siblings), \
                        (module, node.module)
                else:
                    imported.add(node.module.split(".")[0])
            elif isinstance(node, ast.ExceptHandler):       # no loose-file fallbacks
                assert "ImportError" not in ast.dump(node.type or ast.Pass()), module
        assert imported <= allowed, (module, imported - allowed)
    code = ("import sys, exactsym.checker; print(sorted(m for m in sys.modules if "
            "m.split('.')[0] in ('exactsym', 'flint', 'sympy', 'networkx')))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT)
    assert out.stdout.split() == [
        "['exactsym',", "'exactsym.checker',", "'exactsym.checker.dispatch',",
        "'exactsym.checker.groups',", "'exactsym.checker.numbers',", "'exactsym.checker.ordering',",
        "'exactsym.checker.refutations',", "'exactsym.version']"], out


def test_psi_is_the_minimal_polynomial_of_2cos():
    """The checker's Psi_m (pure Python, Moebius) against flint's cyclotomic polynomials."""
    for m in list(range(3, 80)) + [105, 210, 420, 4620]:
        phi = [int(c) for c in fmpz_poly.cyclotomic(m).coeffs()]
        h = (len(phi) - 1) // 2
        psi = fmpz_poly(checker.psi(m))
        assert psi.degree() == h and psi.coeffs()[-1] == 1
        # z^h Psi(z + 1/z) == Phi(z)
        z = fmpz_poly([0, 1])
        total = sum((int(c) * (z * z + 1) ** k * z ** (h - k)
                     for k, c in enumerate(psi.coeffs())), fmpz_poly([0]))
        assert total == fmpz_poly(phi), m


def test_irreducible_mod_agrees_with_flint():
    rnd = random.Random(5)
    for _ in range(150):
        d = rnd.randint(2, 7)
        coeffs = [rnd.randint(-9, 9) for _ in range(d)] + [rnd.choice([1, 2, 3])]
        ell = rnd.choice([2, 3, 5, 7, 11, 13])
        content = math.gcd(*coeffs)
        primitive = [c // content for c in coeffs]  # the integer multiple the checker uses
        factors = nmod_poly([c % ell for c in primitive], ell).factor()[1]
        expected = primitive[-1] % ell != 0 and len(factors) == 1 and factors[0][1] == 1
        p = [Fraction(c, coeffs[-1]) for c in coeffs]
        assert irreducible_mod(p, ell) == expected, (coeffs, ell)


def test_one_root_agrees_with_sympy():
    """One Descartes sign change <=> exactly one root; sympy counts the roots exactly."""
    import sympy
    x = sympy.Symbol("x")
    rnd = random.Random(9)
    for _ in range(200):
        coeffs = [rnd.randint(-6, 6) for _ in range(rnd.randint(2, 6))] + [1]
        poly = sympy.Poly(list(reversed(coeffs)), x)
        if sympy.degree(sympy.gcd(poly, poly.diff(x)), x) > 0:
            continue                                # squarefree polynomials only
        lo = Fraction(rnd.randint(-12, 11), 4)
        hi = lo + Fraction(rnd.choice([1, 2, 8, 24]), 4)
        if poly.eval(sympy.Rational(lo.numerator, lo.denominator)) == 0 or \
                poly.eval(sympy.Rational(hi.numerator, hi.denominator)) == 0:
            continue
        count = poly.count_roots(sympy.Rational(lo.numerator, lo.denominator),
                                 sympy.Rational(hi.numerator, hi.denominator))
        if checker.one_root([Fraction(c) for c in coeffs], lo, hi):
            assert count == 1, (coeffs, lo, hi)
        elif hi - lo <= Fraction(1, 4) and count == 1 and len(coeffs) <= 3:
            pytest.fail(f"a short interval around the one root of a quadratic: {coeffs}")


def test_field_signs_and_canonical_form():
    field = checker.Field({"minpoly": ["-3", "0", "1"], "interval": ["1", "2"],
                           "irreducible": {"method": "prime", "prime": 5}})
    root3 = field.num(["0", "1"])
    assert root3 * root3 == 3 and (root3 * root3).c == (3,)
    assert checker.sgn(root3 - Fraction(173, 100)) == 1
    assert checker.sgn(Fraction(1733, 1000) - root3) == 1        # sqrt(3) = 1.73205...
    assert checker.sgn(root3 * 2 - field.num(["0", "2"])) == 0
    assert field.num(["1/2", "1/3", "0"]) == field.num(["3/6", "2/6"])
    assert hash(field.num(["1/2", "1/3"])) == hash(field.num(["3/6", "2/6"]))
    half = checker.Field({"minpoly": ["-1/2", "0", "1"], "interval": ["0", "1"],   # sqrt(1/2)
                          "irreducible": {"method": "prime", "prime": 3}})
    theta = half.num(["0", "1"])
    assert theta * theta == Fraction(1, 2) and (theta * theta).c == (1,)
    assert (theta + 1) * (theta + 1) == half.num(["3/2", "2"])
    assert checker.sgn(theta * 10 - 7) == 1 and checker.sgn(theta * 100 - 71) == -1


# ------------------------------------------------------------------ the command line
def test_cli_certify_and_verify(tmp_path, capsys):
    config = write(tmp_path, "hexagon.txt", HEXAGON)
    cert_path = tmp_path / "hexagon.cert.json"
    assert cli_main(["certify", str(config), "-o", str(cert_path)]) == 0
    out, err = capsys.readouterr()
    assert "group D6, orderable false" in out
    assert cli_main(["verify", str(cert_path)]) == 0
    out, err = capsys.readouterr()
    assert out.startswith(f"{cert_path}: valid: group D6")
    cert = json.loads(cert_path.read_text())
    cert["claim"]["group"] = "C6"
    bad = tmp_path / "bad.json"
    bad.write_text(json.dumps(cert))
    assert cli_main(["verify", str(bad)]) == 1
    out, err = capsys.readouterr()
    assert "the claim says group 'C6' but the witness proves D6" in err
    bad.write_text('{"format": ')
    assert cli_main(["verify", str(bad)]) == 2
    out, err = capsys.readouterr()
    assert f"{bad}:1:12: not JSON" in err and "Traceback" not in err
    assert cli_main(["verify", str(tmp_path / "missing.json")]) == 2
    assert cli_main(["certify", str(tmp_path / "missing.txt"), "-o", str(cert_path)]) == 2
    assert cli_main(["certify", str(config)]) == 2          # -o is required
    capsys.readouterr()
    assert cli_main(["certify", str(config), "-o", "-"]) == 0
    out, _ = capsys.readouterr()
    assert json.loads(out)["claim"] == {"group": "D6", "orderable": False, "ordering": None,
                                     "leader": None}


def test_checker_as_a_program(tmp_path):
    config = write(tmp_path, "square.txt", "0 0\n2 0\n2 2\n0 2\n")
    cert_path = tmp_path / "square.cert.json"
    cert_path.write_text(json.dumps(certify(config)))
    run = lambda *args: subprocess.run([sys.executable, *args], capture_output=True, text=True,
                                       cwd=ROOT)
    done = run("-m", "exactsym.checker", str(cert_path))
    assert done.returncode == 0 and "valid: group D4, orderable false" in done.stdout
    alone = tmp_path / "alone"                  # the checker's package copied anywhere
    (alone / "checker").mkdir(parents=True)
    for module in CHECKER_MODULES:
        (alone / "checker" / f"{module}.py").write_text((CHECKER / f"{module}.py").read_text())
    done = subprocess.run([sys.executable, "-m", "checker", str(cert_path)], capture_output=True,
                          text=True, cwd=alone)
    assert done.returncode == 0 and "valid: group D4" in done.stdout, done.stderr
    cert = json.loads(cert_path.read_text())
    cert["witness"]["mirror"]["permutation"] = [0, 1, 2, 3]
    cert_path.write_text(json.dumps(cert))
    done = run("-m", "exactsym.checker", str(cert_path))
    assert done.returncode == 1 and "mirror: the image of point" in done.stderr
    cert_path.write_text("not json")
    assert run("-m", "exactsym.checker", str(cert_path)).returncode == 2
