"""Certificates of square roots of rationals as tower levels over the sparse Q(zeta_N)
(certificate.Encoder._sparse_tower, checker/ext_sparse_tower.py): the case files certify and
verify, the levels' proof (Legendre symbols at primes p = 1 mod N of full rank over F_2) and
the numbers are re-checked, and tampering with either is caught.

The format carries no Legendre symbols: the checker computes them from the radicands and the
primes, so tampering with "a Legendre claim" is tampering with a radicand or a prime."""

from __future__ import annotations

import copy
import json
from pathlib import Path

import pytest
from flint import fmpq

from exactsym import checker
from exactsym.certificates.certificate import make_certificate
from exactsym.checker.numbers import Invalid
from exactsym.checker.ext_sparse_tower import SparseKummerTower
from exactsym.cli.main import main as cli_main
from exactsym.geometry.configuration import load
from exactsym.exact.cyclotomic_sqrt import split_primes
from exactsym.exact.kummer import SquareClasses
from exactsym.exact.sparse_cyclotomic import sparse_context
from certificate_checks import rejected

ROOT = Path(__file__).resolve().parents[2]
CASE_997 = ROOT / "cases" / "numbers" / "square-roots-over-turns-997.toml"
CASE_999983 = ROOT / "cases" / "numbers" / "square-roots-over-turns-999983.toml"


@pytest.fixture(scope="module")
def cert_997():
    return make_certificate(load(str(CASE_997)))


@pytest.fixture(scope="module")
def cert_999983():
    return make_certificate(load(str(CASE_999983)))


def _base(n: int) -> dict:
    context = sparse_context(n)
    return {"sparse-cyclotomic": {
        "conductor": str(n), "factors": [[str(p), a] for p, a in sorted(context.factors.items())],
        "prime": str(context.ell), "root": str(context.g)}}


def _tower(n: int, radicands: list, primes: list) -> dict:
    return {"base": _base(n), "levels": [{"radicand": str(r), "kummer": True} for r in radicands],
            "kummer": [{"prime": str(p)} for p in primes]}


# ------------------------------------------------------------------ the case files
def test_the_997_case_certifies(cert_997):
    field = cert_997["configuration"]["field"]["tower"]
    assert field["base"]["sparse-cyclotomic"]["conductor"] == "3988"
    assert field["levels"] == [{"radicand": "145", "kummer": True},
                               {"radicand": "374", "kummer": True}]
    # (145 | 3989) = 1, (374 | 3989) = -1; (145 | 47857) = (374 | 47857) = -1: rank 2
    assert field["kummer"] == [{"prime": "3989"}, {"prime": "47857"}]
    assert cert_997["configuration"]["points"][0] == [[1, "0", {"4": "1"}],
                                                      [1, "0", {"993": "1"}]]
    assert cert_997["witness"]["mirror"]["scale"] != "1"      # a quotient, written k M
    assert checker.verify_certificate(cert_997) == (True, "group D2, orderable false, leader")


def test_the_999983_case_certifies(cert_999983):
    field = cert_999983["configuration"]["field"]["tower"]
    assert field["base"]["sparse-cyclotomic"]["conductor"] == "3999932"
    assert [lev["radicand"] for lev in field["levels"]] == ["145", "374", "7"]
    assert field["kummer"] == [{"prime": "11999797"}, {"prime": "35999389"},
                               {"prime": "71998777"}]
    assert cert_999983["claim"] == {"group": "C1", "orderable": True, "ordering": [2, 0, 1],
                                    "leader": 2}
    assert checker.verify_certificate(cert_999983) == (
        True, "group C1, orderable true, ordering and leader")


def test_cli_certify_and_verify(tmp_path, capsys):
    out_path = tmp_path / "c.json"
    assert cli_main(["certify", str(CASE_997), "-o", str(out_path)]) == 0
    assert cli_main(["verify", str(out_path)]) == 0
    out, _ = capsys.readouterr()
    assert f"{out_path}: valid: group D2, orderable false, leader" in out
    cert = json.loads(out_path.read_text())
    cert["configuration"]["field"]["tower"]["kummer"].pop()
    cert["configuration_sha256"] = checker.digest(cert["configuration"])
    out_path.write_text(json.dumps(cert))
    assert cli_main(["verify", str(out_path)]) == 1
    _, err = capsys.readouterr()
    assert "have rank 1 over F_2, not 2" in err


# ------------------------------------------------------------------ tampering
def _level(cert, i):
    return cert["configuration"]["field"]["tower"]["levels"][i]


def test_tampered_radicands(cert_997):
    for i, radicand, why in ((1, "9", "rank 1 over F_2, not 2"),       # a square
                             (1, "580", "rank 1 over F_2, not 2"),     # 4 * 145: level 1's class
                             (1, "144565", "rank 1 over F_2, not 2"),  # 997 * 145 (sqrt(997)
                             (0, "-145", "positive rational"),         # is in Q(zeta_3988))
                             (0, "0", "positive rational"),
                             (0, "146", "the matrix is not orthogonal")):  # a valid level, but
        bad = copy.deepcopy(cert_997)                                # not these numbers'
        _level(bad, i)["radicand"] = radicand
        rejected(bad, why)
    bad = copy.deepcopy(cert_997)
    _level(bad, 1)["radicand"] = {"1": "1"}
    rejected(bad, "positive rational")
    bad = copy.deepcopy(cert_997)
    _level(bad, 1)["radicand"] = [1, "0", "1"]
    rejected(bad, "positive rational")
    bad = copy.deepcopy(cert_997)
    del _level(bad, 0)["kummer"]                  # then a nested level, without its proof
    rejected(bad, "a nested level needs a prime and zeta")


def test_tampered_primes(cert_997):
    def with_primes(primes):
        bad = copy.deepcopy(cert_997)
        bad["configuration"]["field"]["tower"]["kummer"] = [{"prime": p} for p in primes]
        return bad
    rejected(with_primes(["3991", "47857"]), "3991 is not an odd prime = 1 mod 3988")
    rejected(with_primes(["3989", "7977"]), "7977 is not an odd prime = 1 mod 3988")  # 3*2659
    rejected(with_primes(["3989"]), "rank 1 over F_2, not 2")
    # 23929 has the symbols of 3989, 63809 none at -1: no rank added
    rejected(with_primes(["3989", "23929", "63809"]), "rank 1 over F_2, not 2")
    rejected(with_primes([]), "rank 0 over F_2, not 2")
    bad = with_primes(["3989", "47857"])
    del bad["configuration"]["field"]["tower"]["kummer"]
    rejected(bad, "a \"kummer\" list of primes")
    bad = with_primes(["3989", "47857"])
    bad["configuration"]["field"]["tower"]["kummer"][0] = {"prime": True}
    rejected(bad, "not an object with a prime")
    good = with_primes([3989, "75773"])                                 # ints read too
    good["configuration_sha256"] = checker.digest(good["configuration"])
    assert checker.verify_certificate(good) == (True, "group D2, orderable false, leader")


def test_tampered_numbers(cert_997, cert_999983):
    bad = copy.deepcopy(cert_997)
    bad["configuration"]["points"][0][0] = [1, "0", {"5": "1"}]
    rejected(bad, "the centre is not the centroid")
    bad = copy.deepcopy(cert_997)
    bad["witness"]["rotation"]["centre"][0][1][2] = {"4": "1/3"}
    rejected(bad, "the centre is not the centroid")
    bad = copy.deepcopy(cert_997)
    entry = bad["witness"]["mirror"]["matrix"][0][0]
    entry[1] = {**entry[1], "8": "-33205/31"}
    rejected(bad, "the matrix is not orthogonal")
    bad = copy.deepcopy(cert_997)
    bad["witness"]["mirror"]["scale"]["0"] = "587586/64"
    rejected(bad, "mirror")
    bad = copy.deepcopy(cert_997)
    bad["configuration"]["points"][1][0][0] = 1     # y_2 cos -> y_1 cos: a point coincides
    rejected(bad)
    bad = copy.deepcopy(cert_999983)
    bad["witness"]["sec"]["centre"][1][2] = {"200017": "1/3"}
    rejected(bad, "sec")
    bad = copy.deepcopy(cert_999983)
    bad["configuration"]["points"][2][0] = [3, "0", {"1599932": "10"}]
    rejected(bad, "sec: a point lies outside the circle")


# ------------------------------------------------------------------ the checker's field
def test_checker_arithmetic_equality_and_signs():
    field = SparseKummerTower(_tower(3988, [145, 374], [3989, 47857]))
    y1, y2 = field.num([1, "0", "1"]), field.num([2, "0", "1"])
    assert y1 * y1 == 145 and y2 * y2 == 374 and y1 * y2 != y2
    assert (y1 * y2).v[0] == 2 and (y1 * y2) * (y1 * y2) == 145 * 374
    assert (y1 - 12).sign() == 1 and (y1 - 13).sign() == -1     # 12 < sqrt(145) < 13
    assert (y2 - y1 - 8).sign() == -1 and (y2 - y1 - 7).sign() == 1  # 19.34 - 12.04 = 7.30
    # cos(2 pi 997/3988) = cos(pi/2) = 0: another form of the same number, the same hash
    a, b = field.num([1, "0", {"4": "1", "997": "1"}]), field.num([1, "0", {"4": "1"}])
    assert a == b and hash(a) == hash(b)
    c = field.num([1, {"997": "2"}, {"4": "1"}])
    assert c == b and c.v[1] == 0
    # sqrt(145) cos(2 pi 4/3988) - sqrt(374) cos(2 pi 600/3988): 12.04 - 19.34 * 0.586 > 0
    d = field.num([2, [1, "0", {"4": "1"}], {"600": "-1"}])
    assert d.sign() == 1 and (-d).sign() == -1
    assert (d - d).sign() == 0 and d - d == 0


def test_the_base_class_is_no_new_level():
    """sqrt(997) is a Gauss sum of Q(zeta_3988), so sqrt(997 * 145) = sqrt(997) sqrt(145) is
    in K_1: no list of primes p = 1 mod 3988 proves it a new level ((997 | p) = 1 there)."""
    primes = []
    for p in split_primes(3988, start=3):
        primes.append(p)
        if len(primes) == 40:
            break
    with pytest.raises(Invalid, match="rank 1 over F_2, not 2"):
        SparseKummerTower(_tower(3988, [145, 997 * 145], primes))
    with pytest.raises(Invalid, match="divides a radicand"):
        SparseKummerTower(_tower(3988, [3989], [3989]))
    assert SparseKummerTower(_tower(3988, [145], primes)).r[0] == 145


def test_the_checker_agrees_with_the_square_classes():
    """Over Q(zeta_60) (base primes 3, 5): radicands that SquareClasses finds new are proved
    by the solver's primes, and whenever one of them is not new the checker refuses the
    tower with the first 60 primes p = 1 mod 60 (exact expected verdicts)."""
    primes = []
    for p in split_primes(60, start=3):
        primes.append(p)
        if len(primes) == 60:
            break
    verdicts = {}
    for radicands in ([2], [7], [3], [15], [2, 7], [2, 8], [2, 6], [7, 21, 11], [2, 7, 14],
                      [2, 7, 11, 13, 17], [1, 2], [fmpq(1, 7), 7]):
        classes = SquareClasses(60)
        new = True
        for r in radicands:
            if classes.express(fmpq(r)) is not None:
                new = False
                break
            classes.add(fmpq(r))
        texts = [f"{fmpq(r).p}/{fmpq(r).q}" for r in radicands]
        try:
            SparseKummerTower(_tower(60, texts, primes))
            verdicts[tuple(texts)] = True
        except Invalid:
            verdicts[tuple(texts)] = False
        assert verdicts[tuple(texts)] is new, radicands
    assert [k for k, v in verdicts.items() if v] == [
        ("2/1",), ("7/1",), ("2/1", "7/1"), ("2/1", "7/1", "11/1", "13/1", "17/1")]


def test_the_ordering_filter_agrees_with_exact_products():
    """The ordering's angles in a boxed plane (ext_boxes.BoxedAngle; a tower over the sparse
    Q(zeta_N)): the signs of u . v and u x v and the order of two angles read from boxes are the exact
    ones (an unboxed plane of the same directions computes the products), and ties -- two
    points on one ray, equal angles -- fall back to the exact products."""
    from exactsym.checker.ordering import _Plane
    field = SparseKummerTower(_tower(3999932, [145, 374, 7], ["11999797", "35999389",
                                                             "71998777"]))
    nums = [field.num(v) for v in ([1, "0", {"4": "1"}], [2, "1/3", {"600": "-1"}],
                                   [3, [1, "0", {"17": "2"}], {"990": "1"}], {"1000": "5"},
                                   [2, "-2", {"999": "1"}])]
    dirs = [(a, b) for a in nums for b in nums if a is not b]
    dirs += [(x * 2, y * 2) for x, y in (dirs[1], dirs[7])]       # 20, 21: on the rays of 1, 7
    boxed = _Plane(False, [0] * len(dirs), dirs, 1, Angle=field.Angle)
    exact = _Plane(False, [0] * len(dirs), dirs, 1)
    pairs = [(0, j) for j in range(len(dirs))] + [(1, 20), (1, 7), (20, 21), (7, 5)]
    angles = [(boxed.angle(i, j), exact.angle(i, j)) for i, j in pairs]
    for a, e in angles:
        assert [a.sign(k) for k in (0, 1)] == [e[k].sign() for k in (0, 1)]
    seen = set()
    for a, e in angles:
        for b, f in angles:
            found = boxed.cmp_angle(a, b)
            assert found == exact.cmp_angle(e, f)
            seen.add(found)
    assert seen == {-1, 0, 1}
    same_ray = boxed.angle(1, 20)                   # (2 u) . u > 0, u x 2u = 0: exact
    assert same_ray.sign(1) == 0 and same_ray._exact is not None
    assert boxed.angle(0, 4)._exact is None         # never made: the boxes decided
    assert boxed.cmp_angle(boxed.angle(0, 1), boxed.angle(0, 20)) == 0     # one ray
    assert boxed.cmp_angle(boxed.angle(1, 7), boxed.angle(20, 21)) == 0    # equal angles


def test_checker_tower_products_by_a_lower_level():
    """Tower.mul of a factor below the other's level multiplies the two halves (a + b y) c
    = a c + (b c) y, where the full formula walked the other factor twice per level: the
    same products as the full formula, on numbers spread over three levels."""
    from exactsym.checker.ext_tower import _add, _make, _split, _level
    field = SparseKummerTower(_tower(3999932, [145, 374, 7], ["11999797", "35999389",
                                                             "71998777"]))

    def full(x, y):
        if not isinstance(x, tuple) and not isinstance(y, tuple):
            return x * y
        lev = max(_level(x), _level(y))
        (xa, xb), (ya, yb) = _split(x, lev), _split(y, lev)
        cross = _add(full(xa, yb), full(xb, ya))
        return _make(lev, _add(full(xa, ya), full(field.r[lev - 1], full(xb, yb))), cross)
    raw = [field.num(v).v for v in (
        "3/7", {"4": "1", "17": "-2"}, [1, "0", {"4": "1"}], [2, "1/3", {"600": "-1"}],
        [3, [1, "0", {"17": "2"}], {"990": "1"}], [3, [2, [1, "1", "2"], "-1"], [1, "0", "5"]],
        [2, "0", [1, {"8": "1"}, "1"]])]
    for x in raw:
        for y in raw:
            assert field.mul(x, y) == full(x, y) == field.mul(y, x)
    y1, y2, y3 = (field.num([i, "0", "1"]) for i in (1, 2, 3))
    assert (y1 * y2 * y3) * (y3 * y2 * y1) == 145 * 374 * 7


# ------------------------------------------------------------------ Cartesian certificates
def _polar_file(tmp_path, rows) -> str:
    path = tmp_path / "c.toml"
    path.write_text("format = 1\npoints = [\n" + "".join(
        f'  {{ r = "{r}", turn = "{t}" }},\n' for r, t in rows) + "]\n")
    return str(path)


TEN = [("sqrt(280)", "990378/999983"), ("sqrt(58)", "842326/999983"),
       ("sqrt(198)", "98956/999983"), ("sqrt(60)", "625529/999983"),
       ("sqrt(332)", "997227/999983"), ("sqrt(386)", "889866/999983"),
       ("sqrt(9)", "341287/999983"), ("sqrt(144)", "459986/999983"),
       ("sqrt(134)", "328628/999983"), ("sqrt(77)", "78439/999983")]


def test_ten_robots_off_centre(tmp_path):
    """Ten robots at radii sqrt(k), turns j/999983 (the SEC off the origin: a Cartesian
    certificate over the sparse tower): the distances from the centroid and from the SEC
    centre are compared by keys without the square of the centre, the angles by boxes;
    the claim is the truth's, and tampering with the SEC, the reference, the refutation,
    the ordering or the frame is caught."""
    config = load(_polar_file(tmp_path, TEN))
    cert = json.loads(json.dumps(make_certificate(config)))
    assert "base" in cert["configuration"]["field"]["tower"]
    assert cert["configuration"]["coordinates"] == "cartesian"
    assert cert["claim"] == {"group": "C1", "orderable": True,
                             "ordering": [1, 5, 0, 4, 2, 9, 8, 6, 7, 3], "leader": 1}
    assert cert["witness"]["sec"]["support"] == [4, 5, 7]
    assert cert["witness"]["refutations"] == {"rotation": [], "reflection": [[0, 1]]}
    assert checker.verify_certificate(cert) == (
        True, "group C1, orderable true, ordering and leader")

    def tampered(change, why):
        bad = copy.deepcopy(cert)
        change(bad)
        rejected(bad, why)
    tampered(lambda c: c["witness"]["sec"]["support"].__setitem__(2, 8),
             "sec: the support points are not on one circle")
    tampered(lambda c: c["witness"]["sec"].__setitem__("support", [4, 5]),
             "sec: the centre is not the midpoint of the support")
    tampered(lambda c: c["witness"]["sec"]["centre"][0].__setitem__(1, "1/3"), "sec")
    tampered(lambda c: c["witness"]["refutations"]["reflection"].__setitem__(0, [0, 0]),
             "maps point 0 onto a point of the configuration: it refutes nothing")
    tampered(lambda c: c["witness"].__setitem__("reference", 3),
             "point 0 is not on the level of the reference point 3")
    tampered(lambda c: c["claim"]["ordering"].__setitem__(slice(1, 3), [0, 5]),
             "ordering: point 5 is not in angular order")
    tampered(lambda c: c["witness"]["canonical"].__setitem__("orientation", "cw"),
             "ordering: point 0 is not in angular order")
    tampered(lambda c: c["claim"].__setitem__("leader", 5),
             "claim.leader is not the first of the ordering")


def test_a_mirror_off_centre(tmp_path):
    """D1 off the origin over the sparse tower: the rotations taking the reference point to
    its mirror image are refuted by the side of the line c p_b (the mirror maps each point
    to a point at the right two distances), the leader is the nearer of the two points on
    the mirror whose reading is least; a claimed C1 is refuted by the mirror."""
    rows = [("sqrt(145)", "1/999983"), ("sqrt(145)", "-1/999983"),
            ("sqrt(7)", "300000/999983"), ("sqrt(7)", "-300000/999983"), ("3", "0"),
            ("2", "1/2")]
    cert = json.loads(json.dumps(make_certificate(load(_polar_file(tmp_path, rows)))))
    assert cert["configuration"]["coordinates"] == "cartesian"
    assert cert["claim"] == {"group": "D1", "orderable": False, "ordering": None, "leader": 4}
    assert cert["witness"]["canonical"] == {"orientation": "ccw", "order": [0, 2, 4, 5, 3, 1]}
    assert checker.verify_certificate(cert) == (True, "group D1, orderable false, leader")
    bad = copy.deepcopy(cert)
    bad["claim"]["leader"] = 5
    rejected(bad, "claim.leader must be point 4")
    bad = copy.deepcopy(cert)                      # the mirror left out: C1 claimed
    bad["witness"]["mirror"] = None
    bad["claim"].update(group="C1", orderable=True, ordering=[4, 0, 2, 5, 3, 1], leader=4)
    rejected(bad, "the reflection taking point")
    bad["witness"]["refutations"]["reflection"] = [[4, 0]]      # the mirror itself
    rejected(bad, "the reflection taking point 4 to point 4 maps point 0 onto a point")
    # the two pairs alone: the reference point 0 has its mirror image 1 on its level
    cert = json.loads(json.dumps(make_certificate(load(_polar_file(tmp_path, rows[:4])))))
    assert cert["claim"] == {"group": "D1", "orderable": False, "ordering": None,
                             "leader": None}
    assert cert["witness"]["reference"] == 0 and cert["witness"]["mirror"]["permutation"] \
        == [1, 0, 3, 2]
    # the rotation taking 0 to 1 would take 1 to the twin of the mirror's image 0
    assert cert["witness"]["refutations"] == {"rotation": [[1, 1]], "reflection": [[0, 1]]}
    assert checker.verify_certificate(cert) == (True, "group D1, orderable false, leader")
    for w in range(4):                             # the mirror maps every point into P
        bad = copy.deepcopy(cert)
        bad["witness"]["refutations"]["reflection"] = [[1, w]]
        rejected(bad, f"the reflection taking point 0 to point 1 maps point {w} onto a point")
