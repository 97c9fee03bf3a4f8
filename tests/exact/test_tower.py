"""Nested radicals in a tower of quadratic extensions (exact/tower.py, issue 9).

Laws: the canonical form is unique (keys injective: different keys only for numbers whose
Arb balls separate), the square-root test is complete (sqrt(y^2) == |y| without a new level),
arithmetic identities hold exactly, printed numbers read back, and the certificate's
non-square proofs are re-checked by the standard-library checker (tamper tests)."""

from __future__ import annotations

import copy
import json
import time

import pytest
from flint import fmpq
from hypothesis import given, settings, strategies as st

from exactsym import checker
from exactsym.certificates.certificate import make_certificate
from exactsym.geometry.configuration import load
from exactsym.errors import FieldTooLargeError, InputError
from exactsym.exact import evaluate, evaluate_all, exact_key, number_text
from exactsym.exact.multiquadratic import MQ
from exactsym.exact.tower import TowerElement
from exactsym.exact.tower_proof import nonsquare_witness
from exactsym.io.expr import MAX_LENGTH, parse_expression
from certificate_checks import rejected as _rejected

P = parse_expression

GENERATORS = ["sqrt(2+sqrt(3))", "sqrt(3+sqrt(2+sqrt(3)))", "sqrt(5-sqrt(2))", "sqrt(sqrt(2))",
              "sqrt(7+sqrt(3+sqrt(5)))"]


def _values(*texts):
    return evaluate_all([P(t) for t in texts])


def test_denesting_and_levels():
    system, (a, b) = _values("sqrt(3+2*sqrt(2))", "sqrt(9+4*sqrt(2))")
    assert isinstance(a, MQ) and a == 1 + MQ.sqrt(2) and b == 1 + 2 * MQ.sqrt(2)
    assert system.tower.levels == 0
    system, (c,) = _values("sqrt(2+sqrt(3))")
    assert isinstance(c, TowerElement) and system.tower.levels == 1
    # with sqrt(2) in the base field, sqrt(2+sqrt(3)) = (sqrt(6)+sqrt(2))/2 denests
    _, (d, e) = _values("sqrt(2+sqrt(3))", "(sqrt(6)+sqrt(2))/2")
    assert isinstance(d, MQ) and d == e and exact_key(d) == exact_key(e)
    # sqrt(2) is not in the base here, yet sqrt(8-4*sqrt(3)) = (4-2*sqrt(3))*sqrt(2+sqrt(3))
    system, (f, g) = _values("sqrt(8-4*sqrt(3))", "(4-2*sqrt(3))*sqrt(2+sqrt(3))")
    assert f == g and exact_key(f) == exact_key(g) and system.tower.levels == 1
    _, (h,) = _values("sqrt(2+sqrt(3))*sqrt(2-sqrt(3))")
    assert h == 1 and exact_key(h) == exact_key(fmpq(1))


def _random_element(system, gens, draw):
    x = MQ.rational(draw.draw(st.integers(-3, 3)))
    for g in gens:
        x = x + draw.draw(st.integers(-3, 3)) * g + fmpq(draw.draw(st.integers(-2, 2)), 3) * g * g
    return x * gens[draw.draw(st.integers(0, len(gens) - 1))] + draw.draw(st.integers(-2, 2))


@settings(max_examples=15, deadline=None)
@given(st.data(), st.lists(st.sampled_from(GENERATORS), min_size=1, max_size=3, unique=True))
def test_keys_are_injective_and_identities_hold(data, gens):
    system, values = _values(*gens, "sqrt(3)")
    xs = [_random_element(system, values, data) for _ in range(4)]
    xs += [x * x for x in xs[:2]] + [xs[0] + 0, fmpq(1, 2), MQ.sqrt(3)]
    for x in xs:
        for y in xs:
            same = exact_key(x) == exact_key(y)
            assert same == (x == y)
            if not same:      # unequal numbers: their difference has a certified sign
                assert (x - y).sign() != 0
                assert not (MQ.rational(0) + (x - y)).enclosure(200).contains(0)
    for x in xs[:4]:
        for y in xs[:4]:
            if y != 0:
                assert (x * y) / y == x and exact_key((x * y) / y) == exact_key(x)
                assert (x / y) * y == x
        assert (x + xs[1]) - xs[1] == x
        root = system.sqrt(x * x)
        assert root == abs(x)


@settings(max_examples=20, deadline=None)
@given(st.data(), st.lists(st.sampled_from(GENERATORS), min_size=1, max_size=3, unique=True))
def test_printed_tower_numbers_read_back(data, gens):
    system, values = _values(*gens)
    x = _random_element(system, values, data)
    text = number_text(x)
    assert len(text) <= MAX_LENGTH and "sqrtsqrt" not in text
    assert evaluate(P(text), system) == x        # parsed into the same tower
    _, (a, b) = evaluate_all([P(text), P(text)])  # and in a fresh one
    assert a == b


def test_squares_are_found_without_new_levels():
    system, (y, z) = _values("sqrt(2+sqrt(3+sqrt(5)))", "sqrt(7-sqrt(2))")
    levels = system.tower.levels
    for x in (y, z, y * z - 3, 1 + y + y * z, -(y - 2 * z)):
        assert system.sqrt(x * x) == abs(x)
        assert system.sqrt(x * x * 2) * system.sqrt(MQ.rational(2)) == 2 * abs(x)
    assert system.tower.levels == levels


def test_five_deep_is_fast_and_depth_bound_is_refused_fast(tmp_path):
    start = time.perf_counter()
    _, (x,) = _values("sqrt(2+sqrt(3+sqrt(5+sqrt(7+sqrt(11)))))")
    assert number_text(x) == "sqrt(2 + sqrt(3 + sqrt(5 + sqrt(7 + sqrt(11)))))"
    deep = "sqrt(3)"
    for _ in range(20):
        deep = f"sqrt(2+{deep})"
    with pytest.raises(FieldTooLargeError, match="quadratic extensions"):
        _values(deep)
    path = tmp_path / "deep.toml"
    path.write_text(f'format = 1\npoints = [["{deep}", "0"], ["0", "1"]]\n')
    with pytest.raises(InputError, match="quadratic extensions"):
        load(str(path)).points
    assert time.perf_counter() - start < 5


@settings(max_examples=15, deadline=None)
@given(st.data(), st.lists(st.sampled_from(GENERATORS), min_size=1, max_size=3, unique=True),
       st.integers(-5, 5))
def test_rational_ratio_in_a_tower_needs_no_inverse(data, gens, k):
    """The paper layer's rationality test of num/den in a tower (read off one coordinate
    of the canonical form, checked by one product) agrees with dividing, on rational
    multiples and on random pairs."""
    from exactsym.exact.ratio import rational_ratio
    system, values = _values(*gens, "sqrt(3)")
    x, y = (_random_element(system, values, data) for _ in range(2))
    if y == 0:
        return
    q = fmpq(k, 7)
    assert rational_ratio(x * 0 + y * q, y) == q
    quotient = x / y
    expected = quotient.to_fmpq() if quotient.is_rational() else None
    assert rational_ratio(x, y) == expected


@settings(max_examples=15, deadline=None)
@given(st.data(), st.lists(st.sampled_from(GENERATORS), min_size=1, max_size=3, unique=True))
def test_tower_maps_into_f_p_are_ring_maps(data, gens):
    """The two maps of a tower into F_p (tower_proof.tower_maps) respect sums and
    products and send a rational to one residue: their disagreement proves a number
    irrational (the paper layer's line keys in a tower lean on it)."""
    import importlib
    tp = importlib.import_module("exactsym.exact.tower_proof")
    from exactsym.exact.cyclotomic_modular import images
    system, values = _values(*gens, "sqrt(3)")
    tower = system.tower
    if tower.levels == 0:
        return
    x, y = (_random_element(system, values, data) for _ in range(2))
    q = fmpq(data.draw(st.integers(-9, 9)), 5)
    found = images((x, y, x * y, x + y, q, x * 0 + q))
    if found is None:                     # no prime among the tries: nothing claimed
        return
    p, (one, two) = found
    for im in (one, two):
        assert im[2] == im[0] * im[1] % p and im[3] == (im[0] + im[1]) % p
        assert im[4] == im[5] == q.p * pow(q.q, -1, p) % p
    assert tp.tower_maps(tower) is not None


@settings(max_examples=15, deadline=None)
@given(st.data(), st.lists(st.sampled_from(GENERATORS), min_size=1, max_size=2, unique=True))
def test_tower_line_keys_are_equal_exactly_when_the_lines_are(data, gens):
    """Lines through C keyed lazily in a tower (signs from balls, irrationality from the
    two maps) are equal exactly when their doubled directions are parallel with the same
    signs, as the exact keys say; a vector and its rational multiple give one line."""
    from exactsym.paper.keys import bisector_key, complex_product, line_key
    system, values = _values(*gens, "sqrt(3)")
    vs = []
    for _ in range(3):
        v = (_random_element(system, values, data), _random_element(system, values, data))
        if v[0] == 0 and v[1] == 0:
            return
        vs.append(v)
    k = fmpq(data.draw(st.integers(1, 9)), 4)
    vs.append((k * vs[0][0], k * vs[0][1]))
    keys = [line_key(False, v) for v in vs] + [bisector_key(False, vs[0], v) for v in vs[1:]]
    dirs = [complex_product(v, v) for v in vs] + [complex_product(vs[0], v) for v in vs[1:]]
    for a, da in zip(keys, dirs):
        for b, db in zip(keys, dirs):
            same = da[0] * db[1] == da[1] * db[0] and \
                (da[0].sign(), da[1].sign()) == (db[0].sign(), db[1].sign())
            assert (a == b) == same
            if same:
                assert hash(a) == hash(b)


PRIMES = [2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41]


def test_thirteen_independent_radicands_are_refused_before_the_tower_is_built():
    """sqrt(1 + sqrt(p)) for 13 primes: the radicands are independent modulo squares of
    the base (F_p characters), so 13 levels are needed: number_system refuses before any
    level is built (it took a minute of square-root tests before); 12 are not refused
    there."""
    import importlib
    E = importlib.import_module("exactsym.exact.evaluate")
    nodes = [P(f"sqrt(1+sqrt({p}))") for p in PRIMES]
    with pytest.raises(FieldTooLargeError, match="more than 12 quadratic"):
        E.number_system(nodes)
    assert isinstance(E.number_system(nodes[:12]), E.TowerSystem)    # levels made later


@settings(max_examples=30, deadline=None)
@given(st.lists(st.lists(st.booleans(), min_size=5, max_size=5), min_size=1, max_size=7),
       st.lists(st.integers(1, 5), min_size=7, max_size=7))
def test_square_class_rank_is_a_lower_bound_and_exact_here(exponents, squares):
    """Products of subsets of five independent classes (1 + sqrt p) times squares: the
    proved rank never exceeds the true rank (the F_2 rank of the exponent vectors), and
    here reaches it."""
    from exactsym.exact.multiquadratic import sqrt_rational
    from exactsym.exact.modular import square_class_rank
    gens = [1 + sqrt_rational(p) for p in PRIMES[:5]]
    values = []
    for row, k in zip(exponents, squares):
        v = MQ.rational(fmpq(1))
        for g, e in zip(gens, row):
            if e:
                v = v * g
        values.append(v * (k + sqrt_rational(3)) ** 2)
    basis = []
    for row in exponents:
        mask = sum(1 << i for i, e in enumerate(row) if e)
        for b in basis:
            mask = min(mask, mask ^ b)
        if mask:
            basis.append(mask)
            basis.sort(reverse=True)
    assert square_class_rank(PRIMES[:5], values) == len(basis)


# ------------------------------------------------------------------ certificates
def _cert(tmp_path, rows: list[str]) -> dict:
    path = tmp_path / "c.toml"
    path.write_text("format = 1\npoints = [\n" + ",\n".join(rows) + "\n]\n")
    cert = json.loads(json.dumps(make_certificate(load(str(path)))))
    ok, message = checker.verify_certificate(cert)
    assert ok, message
    return cert


@pytest.mark.parametrize("rows, group", [
    (['["sqrt(2+sqrt(3))", "0"]', '["0", "sqrt(2+sqrt(3))"]', '["-sqrt(2+sqrt(3))", "0"]',
      '["0", "-sqrt(2+sqrt(3))"]'], "D4"),
    (['["sqrt(2+sqrt(3+sqrt(5+sqrt(7+sqrt(11)))))", "0"]', '["0", "1"]', '["1", "1"]'], "C1"),
    (['["sqrt(sqrt(2))", "1"]', '["-1", "sqrt(sqrt(2))"]', '["-sqrt(sqrt(2))", "-1"]',
      '["1", "-sqrt(sqrt(2))"]', '["sqrt(3+sqrt(2))", "1/2"]',
      '["-1/2", "sqrt(3+sqrt(2))"]', '["-sqrt(3+sqrt(2))", "-1/2"]',
      '["1/2", "-sqrt(3+sqrt(2))"]'], "C4"),
])
def test_towers_certify(tmp_path, rows, group):
    cert = _cert(tmp_path, rows)
    assert cert["claim"]["group"] == group
    assert "tower" in cert["configuration"]["field"]


def test_tower_certificates_are_checked(tmp_path):
    cert = _cert(tmp_path, ['["sqrt(2+sqrt(3+sqrt(5)))", "0"]', '["0", "1"]', '["1", "1"]'])
    tower = cert["configuration"]["field"]["tower"]
    assert len(tower["levels"]) == 2
    level = tower["levels"][1]
    bad = copy.deepcopy(cert)
    bad["configuration"]["field"]["tower"]["levels"][1]["roots"][0] = str(
        (int(level["roots"][0]) + 1) % level["prime"])
    _rejected(bad, "is not a root of radicand 1")
    bad = copy.deepcopy(cert)
    bad["configuration"]["field"]["tower"]["levels"][0]["base"][0] = "0"
    _rejected(bad, "is not a root of")
    bad = copy.deepcopy(cert)
    bad["configuration"]["field"]["tower"]["levels"][0]["prime"] = 9
    _rejected(bad, "not an odd prime")
    # a radicand that IS a square (3 + 2 sqrt(5) is not; 6 + 2 sqrt(5) = (1 + sqrt(5))^2):
    # no homomorphism makes it a non-residue, so the given one must fail
    bad = copy.deepcopy(cert)
    bad["configuration"]["field"]["tower"]["levels"][0]["radicand"] = {"1": "6", "5": "2"}
    _rejected(bad, "is a square modulo")
    bad = copy.deepcopy(cert)                 # a zero y coefficient is not canonical
    bad["configuration"]["points"][1][0] = [1, "0", "0"]
    _rejected(bad, "zero y coefficient")
    bad = copy.deepcopy(cert)                 # a level that does not exist
    bad["configuration"]["points"][1][0] = [3, "0", "1"]
    _rejected(bad, "bad level")
    bad = copy.deepcopy(cert)                 # a negative radicand (its root is not real)
    bad["configuration"]["field"]["tower"]["levels"][0]["radicand"] = {"1": "-3", "5": "1"}
    ok, message = checker.verify_certificate(rehash(bad))
    assert not ok


def rehash(cert: dict) -> dict:
    cert["configuration_sha256"] = checker.digest(cert["configuration"])
    return cert


def test_square_radicand_has_no_witness():
    system, (y,) = _values("sqrt(2+sqrt(3))")
    tower = system.tower
    tower.radicands.append(MQ.rational(4) + 2 * MQ.sqrt(3))       # (1 + sqrt(3))^2: a square
    assert nonsquare_witness(tower, 2, limit=3000) is None
    tower.radicands[-1] = MQ.rational(3) + MQ.sqrt(3)            # not a square
    assert nonsquare_witness(tower, 2) is not None


_BASE = (2, 3, 5, 7, 11)
_mq = st.dictionaries(st.sampled_from([1, 2, 3, 5, 6, 7, 10, 11, 14, 15, 21, 22, 35, 77, 2310]),
                      st.integers(-4, 4).filter(bool).map(fmpq), min_size=1, max_size=5
                      ).map(MQ)


@settings(max_examples=60, deadline=None)
@given(_mq, _mq)
def test_base_square_roots_with_the_legendre_filter(y, z):
    """Tower._mq_root over Q(sqrt 2, ..., sqrt 11): the F_p filter never refuses a square
    (y^2 has its root found, and every Legendre character is 1 on it), and a product it
    refuses has a non-residue image (a character -1)."""
    from exactsym.exact.tower import Tower
    from exactsym.exact.modular import square_class_rank
    tower = Tower(_BASE)
    x = y * y
    assert square_class_rank(_BASE, [x], tries=2, signs=4) == 0
    root = tower._mq_root(x, len(_BASE))
    assert root is not None and root * root == x
    w = y * z
    if w.sign() > 0 and tower._mq_root(w, len(_BASE)) is not None:
        assert square_class_rank(_BASE, [w], tries=2, signs=4) == 0


def test_products_of_the_levels_radicands_are_squares_above_them():
    """Levels sqrt(1+sqrt(p)) over Q(sqrt 2, sqrt 3, sqrt 5, sqrt 7): a product of
    radicands times a square of K_0 has its root above the levels (Kummer theory: the
    Legendre characters find it dependent), any other number a new level."""
    system, (a, b, c, ab, abc, new) = _values(
        "sqrt(1+sqrt(2))", "sqrt(1+sqrt(3))", "sqrt(1+sqrt(5))",
        "sqrt((1+sqrt(2))*(1+sqrt(3)))", "sqrt((1+sqrt(2))*(1+sqrt(3))*(1+sqrt(5))*(3+sqrt(7))^2)",
        "sqrt(1+sqrt(7))")
    assert ab == a * b and abc == a * b * c * (3 + MQ.sqrt(7))
    assert system.tower.levels == 4 and new * new == 1 + MQ.sqrt(7)


@settings(max_examples=40, deadline=None)
@given(st.lists(st.booleans(), min_size=4, max_size=4), _mq, _mq)
def test_roots_over_levels_of_k0_agree_with_the_complete_search(subset, y, z):
    """Tower.root_in for x of K_0 over levels sqrt(1 + sqrt p), p = 2, 3, 5, 7: the Kummer
    shortcut (the one product of radicands Legendre characters allow) answers as the
    recursion over the levels does, for x = y^2 * prod(r_j : j in S) (always a square up
    there) and for x = y z * prod(...) (a square or not); a root squares back to x."""
    from exactsym.exact.tower import Tower, _UNDECIDED
    tower = Tower(_BASE)
    for p in (2, 3, 5, 7):
        tower.radicands.append(1 + MQ.sqrt(p))
    product = MQ.rational(1)
    for r, chosen in zip(tower.radicands, subset):
        if chosen:
            product = product * r
    search = Tower(_BASE)
    search.radicands = tower.radicands
    search._kummer_root = lambda x, lev: _UNDECIDED          # the recursion alone
    for x in (y * y * product, y * z * product):
        if x.sign() <= 0:
            continue
        root = tower.root_in(x, 4)
        assert (root is None) == (search.root_in(x, 4) is None)
        if root is not None:
            assert tower.mul(root, root) == x
    assert tower.root_in(y * y * product, 4) is not None


def test_a_tower_with_balls_deep_copies_and_grows_on_its_own():
    """The gathering search forks worlds by a deep copy, tower included: a tower whose
    balls were asked for (flint's arb cannot be deep-copied) copies, the copy's numbers
    keep their values, and a level added to the copy is not added to the original."""
    system, (a,) = _values("sqrt(1+sqrt(2))")
    tower = system.tower
    assert abs(float(a.enclosure(80).mid()) - (1 + 2 ** 0.5) ** 0.5) < 1e-12   # balls cached
    twin_tower, twin = copy.deepcopy((tower, a))
    assert twin_tower is not tower and twin_tower.levels == tower.levels == 1
    assert twin * twin == 1 + MQ.sqrt(2)
    twin_tower.radicands.append(1 + MQ.sqrt(3))
    assert tower.levels == 1
