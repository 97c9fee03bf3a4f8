"""Sparse Q(zeta_N) (exact/sparse_cyclotomic.py, issue 9: turns of denominators near 10^6).

The zero test, signs, rationality and keys are compared with the dense Q(zeta_M) of
exact/cyclotomic.py on moderate conductors, on random sums and on sums built to vanish; printed
numbers read back; the big conductor of the issue is answered."""

from __future__ import annotations

import pytest
from flint import fmpq
from hypothesis import assume, given, settings, strategies as st

from exactsym.geometry.configuration import load
from exactsym.errors import FieldTooLargeError
from exactsym.exact import cyclotomic, evaluate, exact_key, number_text
from exactsym.exact.evaluate import SparseCyclotomicSystem, dense_degree_limit, number_system
from exactsym.exact.sparse_cyclotomic import (SparseCyclotomic, cos_turn, from_poly_element,
                                              is_zero_sum, sparse_context, sqrt_rational)
from exactsym.io.expr import parse_expression

CONDUCTORS = [12, 20, 27, 36, 45, 60, 63, 84, 90, 105, 120, 135, 180, 210, 225, 315, 420]
BIG = 4 * 5 * 13 * 999983 * 999979          # the issue's example


_FIELDS: dict = {}


def _dense(m: int, terms: dict):
    # one field object per conductor, as one configuration's numbers share theirs (the
    # paper layer's ratio keys of two field objects are unequal by design, ratio_keys)
    field = _FIELDS.get(m)
    if field is None:
        field = _FIELDS[m] = cyclotomic.cyclotomic_field(m)
    total = field(0)
    for e, c in terms.items():
        total = total + c * cyclotomic.root_of_unity(field, e)
    return total


def _vanishing(data, m: int) -> dict:
    """A sum that is zero: (1 + w + ... + w^(p-1)) * zeta^s * (a random sum), w = zeta_p."""
    p = data.draw(st.sampled_from(sorted(cyclotomic.factorization(m))))
    s = data.draw(st.integers(0, m - 1))
    full = {(s + k * (m // p)) % m: fmpq(1) for k in range(p)}
    other = _random_terms(data, m, 3)
    out: dict = {}
    for e1, c1 in full.items():
        for e2, c2 in other.items():
            e = (e1 + e2) % m
            out[e] = out.get(e, fmpq(0)) + c1 * c2
    return {e: c for e, c in out.items() if c != 0}


def _random_terms(data, m: int, size: int = 6) -> dict:
    exps = data.draw(st.lists(st.integers(0, m - 1), min_size=1, max_size=size))
    out = {}
    for e in exps:
        out[e] = fmpq(data.draw(st.integers(-5, 5)), data.draw(st.integers(1, 4)))
    return {e: c for e, c in out.items() if c != 0}


def _add(a: dict, b: dict) -> dict:
    out = dict(a)
    for e, c in b.items():
        out[e] = out.get(e, fmpq(0)) + c
    return {e: c for e, c in out.items() if c != 0}


def _real(terms: dict, m: int) -> dict:
    """The cosine form {e: c} (sum c cos(2 pi e/m), 0 <= e <= m/2) of the real part of
    sum c zeta^e: the element's representation."""
    out: dict = {}
    for e, c in terms.items():
        k = min(e % m, m - e % m)
        out[k] = out.get(k, fmpq(0)) + c
    return {e: c for e, c in out.items() if c != 0}


def _dense_cos(m: int, cos_terms: dict):
    """sum c cos(2 pi e/m) = sum c (zeta^e + zeta^-e)/2 in the dense Q(zeta_m)."""
    return _dense(m, _add({e: c / 2 for e, c in cos_terms.items()},
                          {(-e) % m: c / 2 for e, c in cos_terms.items()}))


@settings(max_examples=150, deadline=None)
@given(st.data(), st.sampled_from(CONDUCTORS))
def test_zero_test_agrees_with_the_dense_field(data, m):
    terms = _random_terms(data, m)
    if data.draw(st.booleans()):
        terms = _add(terms, _vanishing(data, m))
    if data.draw(st.booleans()):
        terms = _vanishing(data, m)
    assert is_zero_sum(terms, m) == (_dense(m, terms) == 0)


@settings(max_examples=80, deadline=None)
@given(st.data(), st.sampled_from(CONDUCTORS))
def test_equal_numbers_written_differently(data, m):
    """x and x + (a vanishing sum): equal, same hash, same exact key, same sign."""
    context = sparse_context(m)
    a = _real(_random_terms(data, m), m)
    b = _add(a, _real(_vanishing(data, m), m))
    x, y = SparseCyclotomic(context, a), SparseCyclotomic(context, b)
    assert x == y and hash(x) == hash(y) and exact_key(x) == exact_key(y)
    assert x.sign() == y.sign() == _dense_cos(m, a).sign()
    dense = _dense_cos(m, a)
    assert x.is_rational() == dense.is_rational()
    if dense.is_rational():
        assert x.to_fmpq() == dense.to_fmpq() and exact_key(x) == exact_key(dense.to_fmpq())


@settings(max_examples=60, deadline=None)
@given(st.data(), st.sampled_from(CONDUCTORS))
def test_keys_injective_and_fractions(data, m):
    context = sparse_context(m)
    xs = [SparseCyclotomic(context, _real(_random_terms(data, m), m)) for _ in range(3)]
    ds = [_dense_cos(m, x.num) for x in xs]
    for x, dx in zip(xs, ds):
        for y, dy in zip(xs, ds):
            assert (exact_key(x) == exact_key(y)) == (dx == dy)
            assert (x < y) == (dx < dy)
            if dy != 0:
                q = x / y
                assert q * y == x and (exact_key(q) == exact_key(x / y))
                assert (q.sign() == (dx / dy).sign())
                assert q.is_rational() == (dx / dy).is_rational()


@settings(max_examples=60, deadline=None)
@given(st.data(), st.sampled_from(CONDUCTORS))
def test_images_in_f_p_agree_with_the_dense_field(data, m):
    """The two ring maps into F_p (cyclotomic_modular.images) send a sparse quotient
    num/den and the dense element it equals to the same residues; so the proofs of
    irrationality hold for it, and a rational ratio is found, never refuted."""
    from exactsym.exact.cyclotomic_modular import images, quotient_irrational
    from exactsym.exact.ratio import rational_ratio
    context = sparse_context(m)
    a, b = (_real(_random_terms(data, m), m) for _ in range(2))
    x, y = SparseCyclotomic(context, a), SparseCyclotomic(context, b)
    dx, dy = _dense_cos(m, a), _dense_cos(m, b)
    if dy == 0:
        return
    q = x / y                                       # held as num / den
    found, dense = images((q, x, fmpq(2, 3))), images((dx / dy, dx, fmpq(2, 3)))
    assert (found is None) == (dense is None)
    if found is not None:
        assert found == dense
    assert quotient_irrational(x, y) == quotient_irrational(dx, dy)
    assert quotient_irrational(x, y) <= (not (dx / dy).is_rational())
    k = fmpq(data.draw(st.integers(-9, 9)), 7)
    assert rational_ratio(k * y, y) == k
    ratio = rational_ratio(x, y)
    assert ratio == ((dx / dy).to_fmpq() if (dx / dy).is_rational() else None)


@settings(max_examples=40, deadline=None)
@given(st.data(), st.sampled_from(CONDUCTORS))
def test_sparse_line_keys_equal_the_dense_ones(data, m):
    """Lines through C keyed in a sparse field (lazily: signs from balls, irrationality
    from F_p, exact products only for an equality) are equal exactly when the same
    lines keyed in the dense field are."""
    from exactsym.paper.keys import bisector_key, line_key
    context = sparse_context(m)
    vectors = []
    for _ in range(3):
        x, y = (_real(_random_terms(data, m), m) for _ in range(2))
        if _dense_cos(m, x) == 0 and _dense_cos(m, y) == 0:
            return
        vectors.append(((SparseCyclotomic(context, x), SparseCyclotomic(context, y)),
                        (_dense_cos(m, x), _dense_cos(m, y))))
    # a vector and its multiple by a rational (one line), and the rest
    k = fmpq(data.draw(st.integers(1, 9)), 4)
    (sx, sy), (dx, dy) = vectors[0]
    vectors.append(((k * sx, k * sy), (k * dx, k * dy)))
    sparse = [line_key(False, v) for v, _ in vectors] + \
        [bisector_key(False, vectors[0][0], v) for v, _ in vectors[1:]]
    dense = [line_key(False, d) for _, d in vectors] + \
        [bisector_key(False, vectors[0][1], d) for _, d in vectors[1:]]
    for i in range(len(sparse)):
        for j in range(len(sparse)):
            assert (sparse[i] == sparse[j]) == (dense[i] == dense[j])
            if sparse[i] == sparse[j]:
                assert hash(sparse[i]) == hash(sparse[j])


@settings(max_examples=60, deadline=None)
@given(st.data(), st.sampled_from(CONDUCTORS))
def test_cosine_products_agree_with_the_dense_field(data, m):
    """Products and sums of cosine forms against the dense field, zero included (e = m/4)."""
    context = sparse_context(m)
    a, b = (_real(_random_terms(data, m), m) for _ in range(2))
    x, y = SparseCyclotomic(context, a), SparseCyclotomic(context, b)
    dx, dy = _dense_cos(m, a), _dense_cos(m, b)
    for value, dense in ((x * y, dx * dy), (x + y, dx + dy), (x - y, dx - dy),
                         (x * x * y, dx * dx * dy)):
        assert value.is_zero() == (dense == 0)
        assert value.sign() == dense.sign()
        assert _dense_cos(m, value.num) == dense
        # the residue carried along the operations is the one computed from the terms
        fresh = SparseCyclotomic(context, value.num, value.den)
        assert value.residue() == fresh.residue() and hash(value) == hash(fresh)
    if y != 0:
        q = (x + 1) / y
        assert q.residue() == SparseCyclotomic(context, q.num, q.den).residue()
    if m % 4 == 0:
        assert SparseCyclotomic(context, {m // 4: fmpq(3)}) == 0


@settings(max_examples=60, deadline=None)
@given(st.data(), st.sampled_from(CONDUCTORS), st.booleans())
def test_quotients_over_one_denominator_agree_with_the_dense_field(data, m, same_object):
    """(a/d) / (b/d) = a/b (sparse_cyclotomic.__truediv__, no product of sums), the
    denominator shared as one object or as equal dictionaries: value, sign, zero test and
    residue against the dense field."""
    context = sparse_context(m)
    a, b, d = (_real(_random_terms(data, m), m) for _ in range(3))
    assume(d and b)
    x = SparseCyclotomic(context, a, d)
    y = SparseCyclotomic(context, b, d if same_object else dict(d))
    dx, dy, dd = _dense_cos(m, a), _dense_cos(m, b), _dense_cos(m, d)
    assume(dd != 0 and dy != 0)
    q, dense = x / y, dx / dy
    assert q * y == x and q.sign() == dense.sign() and q.is_zero() == (dense == 0)
    assert _dense_cos(m, q.num) == dense * _dense_cos(m, q.den or {0: fmpq(1)})
    fresh = SparseCyclotomic(context, q.num, q.den)
    assert q.residue() == fresh.residue() and hash(q) == hash(fresh)


def test_mixing_with_the_dense_field():
    m = 60
    context = sparse_context(m)
    field = cyclotomic.cyclotomic_field(m)
    c = cyclotomic.cos_turn(field, fmpq(1, 5))
    assert from_poly_element(context, c) == cos_turn(context, fmpq(1, 5))
    assert cos_turn(context, fmpq(1, 5)) == c


def test_square_roots_are_gauss_sums():
    context = sparse_context(BIG)
    s5 = sqrt_rational(context, fmpq(5))
    assert s5 * s5 == 5 and s5 > 0 and not s5.is_rational()
    assert sqrt_rational(context, fmpq(20)) == 2 * s5
    assert 2 * cos_turn(context, fmpq(1, 5)) == (s5 - 1) / 2      # cos 72 degrees


@settings(max_examples=30, deadline=None)
@given(st.data())
def test_printed_numbers_read_back(data):
    """number_text of a sparse element parses back to the same number (big conductor)."""
    system = SparseCyclotomicSystem(BIG)
    turns = [fmpq(1, 999983), fmpq(3, 999979), fmpq(2, 5), fmpq(5, 13), fmpq(1, 4) - fmpq(7, 999983)]
    atoms = [system.cos_turn(t) for t in turns]
    x = system.coerce(fmpq(data.draw(st.integers(-3, 3)), 2))
    for _ in range(data.draw(st.integers(1, 3))):
        a, b = data.draw(st.sampled_from(atoms)), data.draw(st.sampled_from(atoms))
        x = x + data.draw(st.integers(-3, 3)) * a * b
    if data.draw(st.booleans()) and x != 0:
        x = data.draw(st.sampled_from(atoms)) / x
    text = number_text(x)
    assert evaluate(parse_expression(text), system) == x


def test_the_issue_conductor_is_sparse_and_decided():
    turns = [fmpq(1, 999983), fmpq(3, 999979), fmpq(2, 5), fmpq(5, 13)]
    system = number_system((), turns)
    assert isinstance(system, SparseCyclotomicSystem) and system.conductor == BIG
    c1, c2 = system.cos_turn(fmpq(1, 999983)), system.cos_turn(fmpq(999982, 999983))
    assert c1 == c2 and hash(c1) == hash(c2)
    s = system.sin_turn(fmpq(1, 999983))
    assert c1 * c1 + s * s == 1 and exact_key(c1 * c1 + s * s) == (1, 1)
    assert 0 < s < c1 < 1
    # cos(a) - cos(b) for turns 10^-12 apart: the ball needs precision, the sign is exact
    near = system.cos_turn(fmpq(1, 999983)) - system.cos_turn(fmpq(3, 999979))
    assert near.sign() == 1


def test_big_square_roots_are_levels_or_refused_in_one_line():
    """sqrt(1000003) would be a Gauss sum of 10^6 roots of unity: it is a tower level over
    the cosines' sparse field (exact/sparse_tower.py); sqrt(999983), whose prime divides
    N, is in that field only as such a sum: refused with one line."""
    from exactsym.exact import evaluate_all
    from exactsym.exact.evaluate import SparseKummerSystem
    system, (r,) = evaluate_all([parse_expression("sqrt(1000003)")], [fmpq(1, 999983)])
    assert isinstance(system, SparseKummerSystem) and r * r == 1000003 and r.sign() > 0
    with pytest.raises(FieldTooLargeError, match="roots of unity"):
        evaluate_all([parse_expression("sqrt(999983)")], [fmpq(1, 999983)])


# ------------------------------------------------------------------ whole files
def _write(tmp_path, name, rows):
    path = tmp_path / name
    path.write_text("format = 1\npoints = [\n" + ",\n".join(rows) + "\n]\n")
    return str(path)


def test_issue_example_is_answered(tmp_path):
    from exactsym.truth.symmetry import symmetry_group
    rows = ['{ r = "1", turn = "0" }', '{ r = "1", turn = "1/999983" }',
            '{ r = "2", turn = "2/5" }', '{ r = "3", turn = "3/999979" }',
            '{ r = "1", turn = "5/13" }']
    config = load(_write(tmp_path, "a.toml", rows))
    assert isinstance(config.system, SparseCyclotomicSystem)
    group = symmetry_group(config)
    assert group.name == "C1" and group.orderable and group.leader == 1


def _orbit_rows(k, radius, offset, shift=("1", "1/3")):
    rows = []
    for j in range(k):
        t = fmpq(j, k) + offset
        q = 2 * t
        rows.append(f'["{shift[0]} + {radius}*cos({q.p}/{q.q}*pi)", '
                    f'"{shift[1]} + {radius}*sin({q.p}/{q.q}*pi)"]')
    return rows


def _verdicts(report) -> object:
    """The report with every irrational number's text replaced: the sparse form is not
    canonical, so texts differ while the numbers are equal."""
    if isinstance(report, dict):
        return {k: _verdicts(v) for k, v in report.items() if k != "number_field"}
    if isinstance(report, list):
        return [_verdicts(v) for v in report]
    if isinstance(report, str) and ("cos(" in report or "sqrt(" in report):
        return "<number>"
    return report


def _report(path):
    from exactsym.analysis import Options, analyse
    from exactsym.report.check import report_json
    import json
    config = load(path)
    return config, json.loads(json.dumps(report_json(analyse(config, options=Options()))))


MODERATE = {
    "asymmetric": ['{ r = "1", turn = "0" }', '{ r = "1", turn = "1/7" }',
                   '{ r = "2", turn = "2/5" }', '{ r = "3", turn = "3/20" }'],
    "D5 off centre": _orbit_rows(5, 1, fmpq(1, 7)),
    "C5 off centre": _orbit_rows(5, 1, fmpq(1, 7)) + _orbit_rows(5, 2, fmpq(1, 9)),
    "D3 and a point": _orbit_rows(3, 1, fmpq(1, 7)) + ['["1", "1/3"]'],
    # two mirror pairs off the origin: the level polygons' denominators cleared
    # (circle_polygon._cleared, the per-level verdicts only)
    "two mirror pairs": [f'["1/3 + {r}*cos({2 * s * j}*pi/63)", '
                         f'"1/5 + {r}*sin({2 * s * j}*pi/63)"]'
                         for r, j in ((5, 19), (9, 6)) for s in (1, -1)],
}


@pytest.mark.parametrize("name", sorted(MODERATE))
def test_same_report_as_the_dense_field(tmp_path, name):
    """The same file through the dense Q(zeta_M) and, forced, through the sparse system:
    the same full report (truth, levels, paper layer, audit) up to the texts of numbers."""
    path = _write(tmp_path, "c.toml", MODERATE[name])
    with dense_degree_limit(cyclotomic.MAX_DEGREE):
        dense_config, dense = _report(path)
    assert not isinstance(dense_config.system, SparseCyclotomicSystem)
    with dense_degree_limit(0):
        sparse_config, sparse = _report(path)
    assert isinstance(sparse_config.system, SparseCyclotomicSystem)
    assert _verdicts(sparse) == _verdicts(dense)
    if name == "two mirror pairs":                  # the cleared path was taken
        from exactsym.geometry.levels import levels_of
        from exactsym.paper.circle_polygon import level_polygon
        levels = levels_of(sparse_config)
        assert any(level_polygon(sparse_config, levels, k, cleared=True).cleared
                   for k in range(len(levels.levels)))
        for k in range(len(levels.levels)):     # one positive multiple f (p - C) of all
            mine = level_polygon(sparse_config, levels, k, cleared=True).directions
            true = level_polygon(sparse_config, levels, k).directions
            (a0, b0), (u0, v0) = mine[0], true[0]
            for (a, b), (u, v) in zip(mine, true):
                assert a * v - b * u == 0 and (a * u + b * v).sign() > 0
                assert (a * a + b * b) * (u0 * u0 + v0 * v0) == \
                    (a0 * a0 + b0 * b0) * (u * u + v * v)


def _big_rows(shuffle=0, turn=fmpq(0), reflect=False):
    d = fmpq(1, 999983)
    orbits = [(5, 1, d), (5, 2, d + fmpq(1, 13))]
    rows = []
    for k, r, offset in orbits:
        for j in range(k):
            t = fmpq(j, k) + offset
            t = (-t if reflect else t) + turn
            q = 2 * t
            rows.append(f'["1 + {r}*cos({q.p}/{q.q}*pi)", "1/3 + {r}*sin({q.p}/{q.q}*pi)"]')
    return rows[shuffle:] + rows[:shuffle]


@pytest.mark.parametrize("shuffle, turn, reflect", [(0, fmpq(0), False),
                                                    (3, fmpq(1, 999979), False),
                                                    (7, fmpq(0), True)])
def test_big_turns_metamorphic(tmp_path, shuffle, turn, reflect):
    """A C5 configuration off the origin at turns 1/999983 (a field of degree ~10^12): the
    group is C5 about (1, 1/3) whatever the rotation (by a turn of denominator 999979),
    reflection or order of the points; the leader and orderability follow."""
    from exactsym.truth.symmetry import symmetry_group
    config = load(_write(tmp_path, "c.toml", _big_rows(shuffle, turn, reflect)))
    assert isinstance(config.system, SparseCyclotomicSystem)
    group = symmetry_group(config)
    assert group.name == "C5" and not group.orderable and group.leader is None


ASYMMETRIC = [(1, fmpq(0)), (1, fmpq(1, 999983)), (2, fmpq(2, 5)), (3, fmpq(3, 999979)),
              (1, fmpq(5, 13))]


@pytest.mark.parametrize("shuffle, turn, reflect", [(0, fmpq(0), False), (2, fmpq(0), False),
                                                    (0, fmpq(7, 999983), False),
                                                    (3, fmpq(1, 999979), True)])
def test_big_turns_ordering_maps_along(tmp_path, shuffle, turn, reflect):
    """The issue's asymmetric example (off the origin, so Cartesian in the sparse field) moved
    by a rotation of a turn near 10^-6, a reflection and a shuffle: C1, and the ordering and
    the leader are the same robots."""
    from exactsym.truth.symmetry import symmetry_group
    order = list(range(len(ASYMMETRIC)))
    order = order[shuffle:] + order[:shuffle]
    rows = []
    for i in order:
        r, t = ASYMMETRIC[i]
        t = (-t if reflect else t) + turn
        rows.append(f'{{ r = "{r}", turn = "{t.p}/{t.q}" }}')
    config = load(_write(tmp_path, "m.toml", rows))
    assert isinstance(config.system, SparseCyclotomicSystem)
    group = symmetry_group(config)
    assert group.name == "C1" and group.orderable
    robots = [order[j] for j in group.ordering]     # file indices -> the original robots
    assert robots == [1, 0, 4, 2, 3] and order[group.leader] == 1


def test_a_long_sparse_line_is_shown_by_its_decimal_on_the_screen():
    """The text summary shows a line of a sparse Q(zeta_N) whose slope is a long sum of
    cosines by the slope's decimal and the length of its exact text (which --json
    prints); short ones as they are."""
    from exactsym.paper.keys import line_key
    from exactsym.exact.text_numbers import LONG, approx
    context = sparse_context(4 * 999983)
    x = sum((SparseCyclotomic(context, {e: fmpq(e, 7)}) for e in (3, 10, 77, 1234)),
            SparseCyclotomic(context, {0: fmpq(1, 3)}))
    y = SparseCyclotomic(context, {5: fmpq(2)}) - SparseCyclotomic(context, {999: fmpq(1, 5)})
    key = line_key(False, (x, y))
    s, slope = key.value
    assert len(key.text) > LONG
    assert key.screen_text() == \
        f"({s}, ≈ {approx(slope)} (exact: {len(number_text(slope))} characters, in --json))"
    assert key.text == f"({s}, {number_text(slope)})"
    short = line_key(False, (SparseCyclotomic(context, {0: fmpq(1)}),
                             SparseCyclotomic(context, {0: fmpq(0)})))
    assert short.screen_text() == short.text


@pytest.mark.parametrize("shift", [("1/3", "1/5"), ("0", "-7/2")])
def test_a_rational_sec_centre_is_held_as_a_rational(tmp_path, shift):
    """A C7 set at turns j/7 + k/999983 translated by a rational vector: the SEC centre,
    a quotient X/D of sums of cosines, is held as the rational it is (sec._rational_centre), so
    the directions p - C stay sums of two cosines; the group is C7 and an unmoved copy has
    the same verdicts."""
    from exactsym.geometry.levels import levels_of
    from exactsym.truth.symmetry import symmetry_group
    rows = _orbit_rows(7, 1, fmpq(1, 999983), shift) + \
        _orbit_rows(7, 2, fmpq(3, 999983), shift)
    config = load(_write(tmp_path, "t.toml", rows))
    assert isinstance(config.system, SparseCyclotomicSystem)
    sec = levels_of(config).sec
    centre = sec.centre
    assert sec.homogeneous[2] == 1                   # proved rational (sec._rational_centre)
    assert list(centre) == [fmpq(shift[0]), fmpq(shift[1])]
    x, y = config.points[0]
    assert len((x - centre[0]).num) <= 2 and symmetry_group(config).name == "C7"
    _, moved = _report(_write(tmp_path, "t.toml", rows))
    _, origin = _report(_write(tmp_path, "o.toml", _orbit_rows(7, 1, fmpq(1, 999983), ("0", "0"))
                               + _orbit_rows(7, 2, fmpq(3, 999983), ("0", "0"))))
    # the verdicts, not the SEC or the file they were read from (the JSON head's "file")
    assert {k: v for k, v in _verdicts(moved).items() if k not in ("sec", "file")} == \
        {k: v for k, v in _verdicts(origin).items() if k not in ("sec", "file")}
