"""Nested radicals with cos/sin beyond the dense base bound (turns j/97 with sqrt(1 + sqrt(2))
need Q(zeta_2328) of degree 768 as a tower's base): the tower over the sparse Q(zeta_N), each
nested radical a level proved new by Legendre characters (exact/sparse_nested.py), a
denestable one read as its multiquadratic root, and its certificates.  Input still refuses
these (tests/reference/sparse_nested_reading.py says why), so every test here swaps that
reading in."""

from __future__ import annotations

import copy
import json
import time
from fractions import Fraction

import pytest
from flint import fmpq
from hypothesis import given, settings, strategies as st

from exactsym import checker
from exactsym.certificates.certificate import make_certificate
from exactsym.geometry.configuration import load
from exactsym.errors import InputError
from exactsym.exact import evaluate, evaluate_all
from reference.sparse_nested_reading import SparseNestedSystem, swap_in
from exactsym.exact.multiquadratic import MQ
from exactsym.exact.sparse_tower import SparseKummerTower
from exactsym.exact.tower import TowerElement
from exactsym.io.expr import parse_expression
from exactsym.geometry.levels import levels_of
from exactsym.truth.symmetry import symmetry_group
from certificate_checks import rejected
from exactsym.certificates.encoder import CertificateError, Encoder

#: the package's own writer of a nested level: it refuses (input does not reach one)
PACKAGE_NESTED_LEVELS = Encoder._nested_levels


@pytest.fixture(autouse=True)
def sparse_nested_reading(monkeypatch):
    swap_in(monkeypatch)


def _values(*texts):
    return evaluate_all([parse_expression(t) for t in texts])


def test_a_nested_radical_with_a_large_turn_is_a_level_over_the_sparse_base():
    system, (a, c, d) = _values("sqrt(1+sqrt(2))", "cos(2*pi/1009)", "sqrt(3+2*sqrt(2))")
    assert isinstance(system, SparseNestedSystem)
    tower = system.tower
    assert isinstance(tower, SparseKummerTower) and tower.nested == 1 and tower.levels == 2
    assert isinstance(a, TowerElement) and a * a == 1 + system.sqrt(fmpq(2))
    assert abs(float(a) - (1 + 2 ** 0.5) ** 0.5) < 1e-12
    assert d == 1 + system.sqrt(fmpq(2))                  # denested, no level
    assert abs(float(c) - 0.99998061) < 1e-8


def test_a_denestable_radical_is_read_as_its_root():
    """sqrt(3 + sqrt(5)) = (sqrt(10) + sqrt(2))/2: a square of the tower (sqrt(2) is a level,
    sqrt(5) in the base), which characters cannot prove new; read as the root."""
    system, (r, _) = _values("sqrt(3+sqrt(5))*cos(2*pi/97)", "sqrt(2)")
    assert system.tower.nested == 0 and list(system.denested.values()) == \
        [MQ.sqrt(fmpq(10)) / 2 + MQ.sqrt(fmpq(2)) / 2]
    assert r * r == evaluate(parse_expression("(3+sqrt(5))*cos(2*pi/97)^2"), system)
    _, (root,) = evaluate_all([parse_expression("(sqrt(10)+sqrt(2))/2*cos(2*pi/97)")])
    assert abs(float(r) - float(root)) < 1e-12


def _write(tmp_path, name, rows):
    path = tmp_path / name
    path.write_text("format = 1\npoints = [\n" + "".join(f'  ["{x}", "{y}"],\n' for x, y in rows)
                    + "]\n")
    return str(path)


def _ring(r, base, k, cx="1", cy="1/3"):
    rows = []
    for j in range(k):
        a = 2 * (Fraction(base) + Fraction(j, k))
        rows.append((f"{cx} + {r}*cos({a.numerator}/{a.denominator}*pi)",
                     f"{cy} + {r}*sin({a.numerator}/{a.denominator}*pi)"))
    return rows


@pytest.mark.parametrize("turns", [(Fraction(1, 97), Fraction(3, 101)),
                                   (Fraction(1, 999983), Fraction(3, 999979))])
def test_rings_off_the_origin_keep_their_rotations(tmp_path, turns):
    rows = _ring("sqrt(1+sqrt(2))", turns[0], 7) + _ring("3", turns[1], 7)
    config = load(_write(tmp_path, "c7.toml", rows))
    assert isinstance(config.system, SparseNestedSystem)
    assert symmetry_group(config, levels_of(config)).name == "C7"


def test_a_mirror_through_a_denested_radius(tmp_path):
    rows = []
    for t in (Fraction(1, 97), Fraction(5, 97), Fraction(30, 97)):
        a = 2 * t
        c, s = f"cos({a.numerator}/{a.denominator}*pi)", f"sin({a.numerator}/{a.denominator}*pi)"
        rows += [(f"1 + sqrt(1+sqrt(2))*{c}", f"sqrt(1+sqrt(2))*{s}"),
                 (f"1 + sqrt(1+sqrt(2))*{c}", f"-sqrt(1+sqrt(2))*{s}")]
    rows.append(("1 + 1/2*sqrt(3+sqrt(5))", "0"))
    config = load(_write(tmp_path, "d1.toml", rows))
    assert symmetry_group(config, levels_of(config)).name == "D1"


def test_a_square_the_characters_cannot_settle_is_refused_at_once(tmp_path):
    """(1 + cos(2 pi/1009))^2 is a square of the field, and not written with square roots of
    rationals only: no root is computed, the input is refused with one line, at once."""
    path = _write(tmp_path, "sq.toml", [("sqrt((1+cos(2*pi/1009))^2)", "sqrt(1+sqrt(2))"),
                                         ("0", "1")])
    start = time.process_time()
    with pytest.raises(InputError, match="characters do not prove new"):
        load(path).points
    assert time.process_time() - start < 2


# ------------------------------------------------------------------ certificates
def _certificate(path):
    cert = json.loads(json.dumps(make_certificate(load(path))))
    ok, message = checker.verify_certificate(cert)
    assert ok, message
    return cert


def _tower(cert):
    return cert["configuration"]["field"]["tower"]


def test_nested_levels_over_the_sparse_base_certify(tmp_path):
    rows = _ring("sqrt(1+sqrt(2))", Fraction(1, 97), 7) + _ring("3", Fraction(3, 101), 7)
    cert = _certificate(_write(tmp_path, "c7.toml", rows))
    assert cert["claim"]["group"] == "C7"
    levels = _tower(cert)["levels"]
    assert [lev.get("kummer", False) for lev in levels] == [True, False]
    assert levels[1]["radicand"] == [1, "1", "1"]               # 1 + sqrt(2), over level 1
    assert "sparse-cyclotomic" in _tower(cert)["base"]


def test_the_package_alone_does_not_certify_a_nested_level(tmp_path, monkeypatch):
    """Without the reference's writer (tests/reference/sparse_nested_reading.py) the
    producer refuses a nested level over the sparse base instead of writing it."""
    monkeypatch.setattr(Encoder, "_nested_levels", PACKAGE_NESTED_LEVELS)
    rows = _ring("sqrt(1+sqrt(2))", Fraction(1, 97), 7) + _ring("3", Fraction(3, 101), 7)
    with pytest.raises(CertificateError, match="nested level over the sparse base"):
        make_certificate(load(_write(tmp_path, "c7.toml", rows)))


def test_tampered_nested_level_proofs_are_rejected(tmp_path):
    path = _write(tmp_path, "two.toml", [("sqrt(2+sqrt(5))*cos(2*pi/97)", "sqrt(1+sqrt(2))"),
                                          ("0", "1"), ("1", "1/3")])
    cert = _certificate(path)
    levels = _tower(cert)["levels"]
    top = len(levels) - 1
    assert "zeta" in levels[top] and len(levels[top]["roots"]) == top
    p, w = int(levels[top]["prime"]), int(levels[top]["zeta"])

    def tampered(change, fragment):
        bad = copy.deepcopy(cert)
        change(_tower(bad)["levels"])
        rejected(bad, fragment)

    def root_plus_one(lv):
        lv[top]["roots"][0] = str((int(lv[top]["roots"][0]) + 1) % p)
    tampered(root_plus_one, "is not a root of radicand 1")
    tampered(lambda lv: lv[top].update(zeta=str(pow(w, 2, p))), "order N")   # N is even
    tampered(lambda lv: lv[top].update(prime=str(p + 2)), "not an odd prime")
    tampered(lambda lv: lv[top].update(zeta=str(w), roots=lv[top]["roots"][:-1]),
             "one root per level")
    tampered(lambda lv: lv.insert(top + 1, dict(lv[0])), "a kummer level above a nested one")


def test_a_residue_radicand_is_rejected(tmp_path):
    """A nested level whose radicand is written as a square (4 = 2^2 over the levels below)
    is refused by the Legendre test at the listed prime."""
    path = _write(tmp_path, "one.toml", [("sqrt(1+sqrt(2))*cos(2*pi/97)", "0"), ("0", "1"),
                                          ("1", "1/3")])
    cert = _certificate(path)
    levels = _tower(cert)["levels"]
    top = len(levels) - 1
    bad = copy.deepcopy(cert)
    _tower(bad)["levels"][top]["radicand"] = "4"
    rejected(bad, "not a non-residue")


def test_a_rational_centre_keeps_the_plain_directions(tmp_path):
    """C = (1, 1/3) is proved rational when the SEC is made (sec._rational_centre), so the
    levels and the per-level polygons use p - C (as short as p) rather than D p - (X, Y),
    which carries the determinant D of three support points into every coordinate (100
    robots with nested radii at turns j/97: 8 s of products, 1.9 s plain); the verdicts
    are the same."""
    from exactsym.analysis import built_levels
    from exactsym.paper.circle_polygon import level_polygon
    from exactsym.paper.polygon_report import level_verdicts
    rows = _ring("sqrt(1+sqrt(2))", Fraction(1, 97), 7) + _ring("3", Fraction(3, 101), 7)
    config = load(_write(tmp_path, "c7.toml", rows))
    levels = built_levels(levels_of(config))
    cx, cy = levels.sec.centre
    assert (cx, cy) == (1, fmpq(1, 3)) and levels.sec.homogeneous == (1, fmpq(1, 3), 1)
    for index in range(len(levels.levels)):
        polygon = level_polygon(config, levels, index, cleared=True)
        assert not polygon.__dict__["cleared"]
        assert polygon.directions == tuple((config.points[i][0] - cx, config.points[i][1] - cy)
                                           for i in polygon.labels)
        assert level_verdicts(polygon) == level_verdicts(level_polygon(config, levels, index))


@settings(max_examples=6, deadline=None)
@given(st.integers(2, 5), st.lists(st.integers(1, 96), min_size=2, max_size=3),
       st.integers(0, 96), st.sampled_from([("0", "0"), ("1", "1/3"), ("-2/5", "7")]),
       st.booleans())
def test_turning_and_translating_keeps_the_group(tmp_path_factory, k, offsets, turn, shift,
                                                 mirror):
    """Metamorphic: orbits of C_k at radii sqrt(1+sqrt(2)), 2, 3 with offsets j/97 (over the
    sparse base) keep their group when every turn gains turn/97 and the set is translated
    by a rational vector; the group is C_k, D_k with each offset's mirror image added."""
    tmp = tmp_path_factory.mktemp("turned")
    radii = ("sqrt(1+sqrt(2))", "2", "3")

    def rows(extra, centre):
        out = []
        for r, j in zip(radii, offsets):
            for base in ([j, -j] if mirror else [j]):
                out += _ring(r, Fraction(base + extra, 97), k, *centre)
        return out
    groups = []
    for extra, centre in ((0, ("0", "0")), (turn, shift)):
        config = load(_write(tmp, f"g{extra}.toml", rows(extra, centre)))
        assert isinstance(config.system, SparseNestedSystem)
        groups.append(symmetry_group(config, levels_of(config)).name)
    assert groups[0] == groups[1]
    # a mirror common to rings turned by j/97 and j'/97 needs 97 | j - j' (k <= 5)
    assert groups[0] == (f"D{k}" if mirror or len(set(offsets)) == 1 else f"C{k}")
