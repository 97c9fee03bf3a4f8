"""Square roots of rationals over Q(zeta_M) as tower levels decided by Kummer theory
(exact/kummer.py; issue 9: square-root radii at turns j/997 were Gauss sums of hundreds of
terms in the sparse Q(zeta_N), and two robots ran past a minute)."""

from __future__ import annotations

import copy
import json
from itertools import combinations

import pytest
from flint import fmpq
from hypothesis import given, settings, strategies as st

from exactsym import checker
from exactsym.certificates.certificate import make_certificate
from exactsym.geometry.configuration import load
from exactsym.errors import FieldTooLargeError
from exactsym.exact import evaluate_all
from exactsym.exact.evaluate import CyclotomicTowerSystem
from exactsym.exact.factor import factorization
from exactsym.exact.kummer import SquareClasses
from exactsym.exact.tower import TowerElement
from exactsym.io.expr import parse_expression
from exactsym.truth.symmetry import symmetry_group
from certificate_checks import rejected as _rejected


def _free_primes(q: fmpq, base) -> frozenset:
    """The primes of q's squarefree part outside ``base``."""
    return frozenset(p for p, e in factorization(int(q.p) * int(q.q)).items()
                     if e % 2 and p not in base)


def _in_span(target: frozenset, vectors: list) -> list | None:
    """Brute force: a subset of ``vectors`` whose symmetric difference is ``target``."""
    for k in range(len(vectors) + 1):
        for subset in combinations(range(len(vectors)), k):
            acc: frozenset = frozenset()
            for i in subset:
                acc = acc ^ vectors[i]
            if acc == target:
                return list(subset)
    return None


@settings(max_examples=60, deadline=None)
@given(st.sampled_from([4, 12, 28, 60, 3988]),
       st.lists(st.integers(2, 60), min_size=1, max_size=7),
       st.lists(st.integers(1, 400), min_size=1, max_size=5),
       st.integers(1, 9))
def test_square_classes_agree_with_brute_force(m, radicands, queries, den):
    """express(q) is not None exactly when q's class lies in the span of the radicands'
    classes modulo the base primes (odd primes of M, 2 when 8 | M); its levels then leave
    a quotient made of base primes and squares only."""
    classes = SquareClasses(m)
    base = {p for p in factorization(m) if p != 2 or m % 8 == 0}
    added: list = []
    for r in radicands:
        q = fmpq(r, den)
        if classes.express(q) is None:
            assert _in_span(_free_primes(q, base), [_free_primes(a, base) for a in added]) \
                is None
            classes.add(q)
            added.append(q)
        else:
            assert _in_span(_free_primes(q, base), [_free_primes(a, base) for a in added]) \
                is not None
    vectors = [_free_primes(a, base) for a in added]
    for n in queries:
        q = fmpq(n, den)
        levels = classes.express(q)
        assert (levels is None) == (_in_span(_free_primes(q, base), vectors) is None)
        if levels is not None:
            rest = q
            for i in levels:
                rest /= added[i]
            assert not _free_primes(rest, base)


def test_square_classes_refuse_a_repeated_class():
    classes = SquareClasses(28)
    classes.add(fmpq(5))
    with pytest.raises(ValueError):
        classes.add(fmpq(20))                 # 20 = 4 * 5
    assert classes.express(fmpq(35)) == [0]   # 35 = 7 * 5, sqrt(7) in Q(zeta_28)
    assert classes.express(fmpq(3)) is None   # sqrt(3) needs 12 | M


def _system(points: list[str]):
    return evaluate_all([parse_expression(p) for p in points])


def test_square_roots_beyond_the_dense_field_become_levels():
    """cos(2 pi/7) with sqrt(1499), sqrt(1511): Q(zeta_(4*7*1499*1511)) is far beyond the
    dense limit and the Gauss sums have 1,499 terms; the cosines' Q(zeta_28) holds the base
    and each new square-root class is one level."""
    system, (c, a, b, ab, a4, s7) = _system(
        ["cos(2*pi/7)", "sqrt(1499)", "sqrt(1511)", "sqrt(1499*1511)", "sqrt(4*1499)",
         "sqrt(7)"])
    assert isinstance(system, CyclotomicTowerSystem) and system.tower.conductor == 28
    assert system.tower.levels == 2 and system.tower.classes is not None
    assert isinstance(a, TowerElement) and isinstance(b, TowerElement)
    assert a * a == 1499 and b * b == 1511
    assert ab == a * b and a4 == 2 * a              # found in the field: no new level
    assert s7 * s7 == 7 and type(s7.v) is not tuple     # in the base Q(zeta_28)
    assert a != b and (a - b).sign() < 0 and c.sign() > 0


def test_a_nested_radical_over_a_large_base_is_refused_at_once():
    """The complete square-root test over Q(zeta_404) (phi = 200, beyond the base bound 192)
    would factor norms of degree 400: refused (one line, exit 2) instead of running for
    minutes."""
    system, (a,) = _system(["sqrt(1499)*cos(2*pi/101)"])
    assert isinstance(system, CyclotomicTowerSystem) and system.tower.field.degree == 200
    with pytest.raises(FieldTooLargeError, match="beyond the limits"):
        system.sqrt(a + 50)


def _toml(points) -> str:
    return "format = 1\npoints = [\n" + "".join(
        f'  {{ r = "{r}", turn = "{t}" }},\n' for r, t in points) + "]\n"


def test_two_robots_with_square_root_radii_at_turns_j_997(tmp_path):
    """The survey's input (two robots, radii sqrt(145) and sqrt(374)): the SEC is the circle
    on their segment, so the group is D2 whatever the turns; rotating both by k/997 keeps
    it (metamorphic)."""
    for shift in (0, 5, 400):
        path = tmp_path / f"two{shift}.toml"
        path.write_text(_toml([("sqrt(145)", f"{1 + shift}/997"),
                               ("sqrt(374)", f"{300 + shift}/997")]))
        config = load(str(path))
        assert symmetry_group(config).name == "D2"


def _k7(tmp_path):
    path = tmp_path / "k7.toml"
    path.write_text(_toml([("sqrt(1499)", "1/7"), ("sqrt(1511)", "3/7"), ("2", "6/7")]))
    cert = json.loads(json.dumps(make_certificate(load(str(path)))))
    ok, message = checker.verify_certificate(cert)
    assert ok, message
    return cert


def test_kummer_levels_certify_and_tampering_is_caught(tmp_path):
    cert = _k7(tmp_path)
    tower = cert["configuration"]["field"]["tower"]
    assert [lev["radicand"] for lev in tower["levels"]] == ["1499", "1511"]
    assert all(lev["kummer"] is True for lev in tower["levels"])
    assert 2 <= len(tower["kummer"]) and all(k["prime"] % 28 == 1 for k in tower["kummer"])

    bad = copy.deepcopy(cert)                       # one prime: rank 1 < 2
    primes = bad["configuration"]["field"]["tower"]["kummer"]
    bad["configuration"]["field"]["tower"]["kummer"] = primes[:1]
    _rejected(bad, "rank 1 over F_2, not 2")

    bad = copy.deepcopy(cert)                       # a prime repeated adds no rank
    first = bad["configuration"]["field"]["tower"]["kummer"][0]
    bad["configuration"]["field"]["tower"]["kummer"] = [first, copy.deepcopy(first)]
    _rejected(bad, "rank 1 over F_2, not 2")

    bad = copy.deepcopy(cert)                       # the second radicand a square class
    bad["configuration"]["field"]["tower"]["levels"][1]["radicand"] = str(1499 * 4)
    _rejected(bad, "over F_2")

    bad = copy.deepcopy(cert)                       # a composite "prime"
    entry = bad["configuration"]["field"]["tower"]["kummer"][0]
    entry["prime"] = entry["prime"] * 3
    _rejected(bad, "is not an odd prime")

    bad = copy.deepcopy(cert)                       # a wrong root of Psi_28
    entry = bad["configuration"]["field"]["tower"]["kummer"][0]
    entry["theta"][0] = str((int(entry["theta"][0]) + 1) % entry["prime"])
    _rejected(bad, "modulo")

    bad = copy.deepcopy(cert)                       # a non-rational radicand
    bad["configuration"]["field"]["tower"]["levels"][0]["radicand"] = {"theta": ["1", "1"]}
    _rejected(bad, "positive rational")


def test_turns_j_997_put_square_roots_over_the_sparse_base(tmp_path):
    """Beyond phi(M) = 256 (Q(zeta_3988)) the levels sit over the sparse base: a moved
    configuration's SEC centre is then a quotient, not a dense inverse of seconds; certify
    writes the sparse Kummer tower (tests/test_sparse_kummer_certificates.py)."""
    from exactsym.exact.evaluate import KUMMER_DENSE_DEGREE, SparseKummerSystem
    system, _ = _system(["sqrt(145)*cos(2*pi/997)"])
    assert isinstance(system, SparseKummerSystem) and system.tower.conductor == 3988
    assert KUMMER_DENSE_DEGREE < 1992
    path = tmp_path / "two.toml"
    path.write_text(_toml([("sqrt(145)", "1/997"), ("sqrt(374)", "300/997")]))
    cert = make_certificate(load(str(path)))
    assert set(cert["configuration"]["field"]["tower"]["base"]) == {"sparse-cyclotomic"}
    assert checker.verify_certificate(cert) == (True, "group D2, orderable false, leader")


# ------------------------------------------------------------------ over the sparse Q(zeta_N)
def test_square_roots_over_the_sparse_field_are_levels(tmp_path):
    """Turns j/999983 put the cosines in the sparse Q(zeta_3999932); sqrt(145), sqrt(374)
    are levels above it (Gauss sums of 112 and 640 terms before): exact arithmetic, the
    group of two robots D2 for every rotation of the turns (metamorphic)."""
    from exactsym.exact.evaluate import SparseKummerSystem
    system, (a, b, ab, c) = evaluate_all(
        [parse_expression(e) for e in ("sqrt(145)", "sqrt(374)", "sqrt(145*374)",
                                       "cos(2*pi/999983)")])
    assert isinstance(system, SparseKummerSystem) and system.tower.levels == 2
    assert a * a == 145 and b * b == 374 and ab == a * b and ab != 145
    assert (a * c) * (a * c) == 145 * c * c and (a * c - b * c).sign() < 0
    for shift in (0, 7, 500000):
        path = tmp_path / f"s{shift}.toml"
        path.write_text(_toml([("sqrt(145)", f"{1 + shift}/999983"),
                               ("sqrt(374)", f"{300000 + shift}/999983")]))
        assert symmetry_group(load(str(path))).name == "D2"


def test_certify_proves_levels_over_the_sparse_field(tmp_path):
    path = tmp_path / "s.toml"
    path.write_text(_toml([("sqrt(145)", "1/999983"), ("sqrt(374)", "3/999983")]))
    cert = make_certificate(load(str(path)))
    tower = cert["configuration"]["field"]["tower"]
    assert [lev["radicand"] for lev in tower["levels"]] == ["145", "374"]
    assert checker.verify_certificate(cert) == (True, "group D2, orderable false, leader")


def test_a_nested_radical_over_the_sparse_field_is_refused():
    system, (a,) = evaluate_all([parse_expression("sqrt(145)*cos(2*pi/999983)")])
    with pytest.raises(FieldTooLargeError, match="sparse"):
        system.sqrt(a + 20)


@settings(max_examples=30, deadline=None)
@given(st.lists(st.integers(-6, 6), min_size=4, max_size=4),
       st.lists(st.integers(-6, 6), min_size=4, max_size=4),
       st.integers(1, 9), st.integers(1, 9), st.sampled_from(["997", "999983"]))
def test_kummer_maps_never_refute_a_rational_ratio(xs, ys, p, q, den):
    """Two ring maps of a Kummer tower into F_p (tower_proof._kummer_maps) prove ratios
    irrational; a rational multiple is never 'proved' irrational, and rational_ratio finds
    the multiple exactly (dense Q(zeta_3988) and sparse Q(zeta_3999932) bases)."""
    from exactsym.exact.cyclotomic_modular import quotient_irrational
    from exactsym.exact.ratio import rational_ratio
    atoms = ["1", f"cos(2*pi/{den})", "sqrt(145)", f"sqrt(145)*cos(6*pi/{den})"]
    _, values = evaluate_all([parse_expression(e) for e in atoms])
    x = sum((k * v for k, v in zip(xs, values)), fmpq(0))
    y = sum((k * v for k, v in zip(ys, values)), fmpq(0))
    if not y:
        return
    k = fmpq(p, q)
    assert not quotient_irrational(k * y, y)
    assert rational_ratio(k * y, y) == k
    ratio = rational_ratio(x, y)
    if ratio is not None:
        assert x == ratio * y
    if quotient_irrational(x, y):
        assert ratio is None


def test_sums_over_one_denominator_keep_it():
    """x/N + y/N with N built twice (equal dictionaries, two objects): the sum keeps the
    denominator N instead of N^2 (a tower's products made such pairs at every sum)."""
    from exactsym.exact.sparse_context import sparse_context
    from exactsym.exact.sparse_cyclotomic import SparseCyclotomic
    ctx = sparse_context(3999932)
    den = {0: fmpq(3), 5: fmpq(1)}
    u = SparseCyclotomic(ctx, {1: fmpq(1)}, dict(den))
    v = SparseCyclotomic(ctx, {2: fmpq(2)}, dict(den))
    total = u + v
    assert total.den == den and total == SparseCyclotomic(ctx, {1: fmpq(1), 2: fmpq(2)}, den)
    assert total - v == u


@settings(max_examples=30, deadline=None)
@given(st.lists(st.integers(-4, 4), min_size=8, max_size=8), st.integers(1, 9),
       st.sampled_from(["997", "999983"]))
def test_angle_keys_refuted_in_f_p_only_when_unequal(cs, k, den):
    """The F_p filter of AngleKey equality (ratio_keys._angles_differ_mod_p) says "unequal
    angles" only when conj(a) b and conj(a2) b2 are not parallel exactly, and never for
    the same angle between scaled vectors."""
    from exactsym.exact.fused import complex_product, cross_is_zero
    from exactsym.paper.ratio_keys import _angles_differ_mod_p
    atoms = ["1", f"cos(2*pi/{den})", "sqrt(145)", f"sqrt(374)*cos(6*pi/{den})"]
    _, values = evaluate_all([parse_expression(e) for e in atoms])
    x = sum((c * v for c, v in zip(cs[:4], values)), fmpq(0))
    y = sum((c * v for c, v in zip(cs[4:], values)), fmpq(0))
    a, b = (x, y), (y + 1, x - 2)
    s = fmpq(k, 3)
    assert not _angles_differ_mod_p(a, b, (s * x, s * y), (2 * b[0], 2 * b[1]))
    a2, b2 = (x + 1, y), b
    if _angles_differ_mod_p(a, b, a2, b2):
        assert not cross_is_zero(complex_product((a[0], -a[1]), b),
                                 complex_product((a2[0], -a2[1]), b2))
