"""The shortcuts of the gathering benchmark's speed-up against the exact routines they
stand in for: the integer and Kronecker products of multiquadratic elements against the
term-by-term product in ``fmpq``, and the Arb filter for roots in (0, 1) against the
exact root isolation (a polynomial it clears has no exact root inside)."""

from flint import fmpq
from hypothesis import given, settings, strategies as st

from exactsym.exact import multiquadratic as mqm, mq_products as mqp
from exactsym.exact.multiquadratic import MQ, sqrt_rational
from exactsym.exact.algebraic import polynomials as poly, roots as pr

# radicands over the primes of the n = 30 run's last events, and small ones
PRIMES = (3, 5, 7, 17, 53)
RADICANDS = sorted({1, 2, 6, 10, 15, 21, 35, 3 * 53, 5 * 7 * 17, 3 * 5 * 7 * 17 * 53,
                    17 * 53, 2 * 3301, 5953, 3301 * 220057} | set(PRIMES))
dens = st.sampled_from([1, 2, 3, 7, 12, 35, 2 ** 61 - 1, 3 ** 40, 10 ** 30 + 7])
rationals = st.builds(lambda n, d: fmpq(n, d),
                      st.integers(-(1 << 300), 1 << 300) | st.integers(-40, 40), dens)
terms = st.dictionaries(st.sampled_from(RADICANDS), rationals, max_size=24).map(
    lambda d: {m: c for m, c in d.items() if c != 0})


@settings(max_examples=300, deadline=None)
@given(terms, terms)
def test_integer_and_dense_products_equal_the_rational_one(a, b):
    want = mqp.rational_product(a, b)
    assert mqp.integer_product(MQ(a), MQ(b)) == want
    base = mqp._coprime_base_of(frozenset(a) | frozenset(b))
    if base:
        assert mqp._dense_product(a, b, base) == want
    assert (MQ(a) * MQ(b)).terms == want


small = st.fractions(min_value=-6, max_value=6, max_denominator=12).map(
    lambda f: MQ.rational(fmpq(f.numerator, f.denominator)))
coeffs = st.tuples(small, st.sampled_from([1, 2, 3, 6, 15])).map(
    lambda t: t[0] * sqrt_rational(t[1]))
roots = st.fractions(min_value=-1, max_value=2, max_denominator=16).map(
    lambda f: MQ.rational(fmpq(f.numerator, f.denominator)))
irr_roots = st.tuples(roots, st.sampled_from([2, 3, 5])).map(
    lambda t: t[0] + sqrt_rational(t[1]) * fmpq(1, 4))


def _from_roots(rs, lead):
    p = (lead,)
    for r in rs:
        p = poly.pmul(p, (-r, MQ.rational(1)))
    return p


@settings(max_examples=300, deadline=None)
@given(st.lists(coeffs, min_size=2, max_size=6))
def test_filter_clears_only_polynomials_without_roots_inside(p):
    p = poly.trim(p)
    if pr.surely_no_root_in_unit(p):
        assert _exact_roots(p) == []


@settings(max_examples=200, deadline=None)
@given(st.lists(roots | irr_roots, min_size=1, max_size=4), coeffs.filter(bool),
       st.lists(coeffs, max_size=3))
def test_filter_never_clears_a_root_inside(rs, lead, extra):
    # roots at 0 and 1 exactly are divided out by the filter: they are not inside
    p = _from_roots(rs, lead)
    if extra and any(extra):
        p = poly.pmul(p, poly.padd(tuple(extra), (MQ.rational(0),)))
    inside = [r for r in rs if r.sign() > 0 and (r - 1).sign() < 0]
    if inside:
        assert not pr.surely_no_root_in_unit(p)
    if pr.surely_no_root_in_unit(p):
        assert _exact_roots(p) == []


def _exact_roots(p):
    """roots_in_unit without the filter (the exact isolation alone)."""
    saved = pr.surely_no_root_in_unit
    pr.surely_no_root_in_unit = lambda q, *a, **k: False
    try:
        return pr.roots_in_unit(p)
    finally:
        pr.surely_no_root_in_unit = saved


def test_filter_examples():
    f = MQ.rational
    assert pr.surely_no_root_in_unit((f(1), f(1)))                 # 1 + t
    assert not pr.surely_no_root_in_unit((f(-1), f(3)))            # root 1/3
    assert pr.surely_no_root_in_unit((f(0), f(1)))                 # root 0 only
    assert pr.surely_no_root_in_unit((f(1), f(-1)))                # root 1 only
    assert pr.surely_no_root_in_unit(_from_roots([f(0), f(1), f(2)], f(1)))
    assert not pr.surely_no_root_in_unit(_from_roots([f(0), f(fmpq(1, 2))], f(1)))
    assert not pr.surely_no_root_in_unit(())                       # identically zero
    # a double root inside (no sign change): never cleared
    assert not pr.surely_no_root_in_unit(_from_roots([sqrt_rational(fmpq(1, 2))] * 2,
                                                     f(1)))


# -- sum_of_products, squares, remembered inverses ------------------------------------
@settings(max_examples=200, deadline=None)
@given(st.lists(st.tuples(st.sampled_from([1, -1, 2]), terms, terms), max_size=4))
def test_sum_of_products_equals_the_plain_sum(items):
    items = [(s, MQ(a), MQ(b)) for s, a, b in items]
    want = MQ()
    for s, a, b in items:
        want = want + MQ(mqp.rational_product(a.terms, b.terms)) * s
    assert mqm.sum_of_products(items) == want


@settings(max_examples=200, deadline=None)
@given(terms)
def test_square_equals_the_product_of_two_copies(a):
    x, y = MQ(a), MQ(dict(a))
    assert (x * x).terms == mqp.rational_product(a, dict(a)) == (x * y).terms


small_terms = st.dictionaries(st.sampled_from([1, 2, 3, 5, 6, 10, 15, 30, 7, 21]),
                              st.integers(-9, 9).filter(bool).map(fmpq),
                              min_size=mqm._REMEMBERED_INVERSE, max_size=10)


@settings(max_examples=30, deadline=None)
@given(small_terms)
def test_remembered_inverse_is_the_inverse(a):
    x = MQ(a)
    assert x.inverse() == x._inverse() and (x * x.inverse()) == 1
    assert MQ(dict(a)).inverse() == x._inverse()        # an equal value, another object


def test_dist2_reuse_is_by_identity():
    from exactsym.gathering import geometry as g
    p = (MQ.rational(1), sqrt_rational(2))
    q = (MQ.rational(4), MQ.rational(0))
    assert g.dist2(p, q) == MQ.rational(11)
    assert g.dist2(p, q) == MQ.rational(11)            # remembered: the same value
    p2 = (MQ.rational(1), sqrt_rational(3))           # another tuple: computed afresh
    assert g.dist2(p2, q) == MQ.rational(12)


# -- the bounded split with primality asked lazily --------------------------------------
def _eager_split(n, hints=()):
    """The bounded split as it was: every part's primality proved as it is found."""
    from math import gcd, isqrt
    from flint import fmpz
    from exactsym.exact.mq_closure import SMOOTH_BITS, _cut
    parts = {}
    open_ = _cut(n, hints)
    for bits in (24, 32, 40, SMOOTH_BITS):
        left = []
        for b, e in open_:
            for f, k in fmpz(b).factor_smooth(bits):
                f, k = int(f), int(k) * e
                if f in parts:
                    parts[f][0] += k
                    continue
                prime = bool(fmpz(f).is_prime())
                if k % 2 == 0 or prime or isqrt(f) ** 2 == f:
                    parts[f] = [k, prime]
                else:
                    left.append((f, k))
        open_ = left
        if not open_:
            break
    if open_:
        return None
    check = 1
    for b, (e, _) in parts.items():
        check *= b ** e
    keys = list(parts)
    if check != n or any(gcd(a, b) != 1 for k, a in enumerate(keys) for b in keys[k + 1:]):
        return None
    s, m = 1, 1
    for b, (e, prime) in parts.items():
        if e % 2 == 0:
            s *= b ** (e // 2)
        elif prime:
            s, m = s * b ** (e // 2), m * b
        elif isqrt(b) ** 2 == b:
            s *= isqrt(b) ** e
        else:
            return None
    return s, m


BIG_PRIMES = [2 ** 61 - 1, 2 ** 89 - 1, 2 ** 107 - 1, 2 ** 127 - 1, 1000000007]
COMPOSITE = (2 ** 61 - 1) * (2 ** 89 - 1)          # no small factor: ECM at 48 bits misses


@settings(max_examples=40, deadline=None)
@given(st.lists(st.tuples(st.sampled_from(BIG_PRIMES + [2, 3, 5, 7, 3301]),
                          st.integers(1, 4)), min_size=1, max_size=4),
       st.booleans(), st.lists(st.sampled_from(BIG_PRIMES + [6, 35, 3301]), max_size=3))
def test_bounded_split_with_lazy_primality_equals_the_eager_one(factors, hard, hints):
    """(With the full factoring of small composites off, FULL_FACTOR_BITS = 0: the
    reference has none; it is tested in test_mq_closure.)"""
    from exactsym.exact import mq_closure
    n = 1
    for p, e in factors:
        n *= p ** e
    if hard:
        n *= COMPOSITE
    saved, mq_closure.FULL_FACTOR_BITS = mq_closure.FULL_FACTOR_BITS, 0
    try:
        got = mq_closure.bounded_squarefree_split.__wrapped__(n, tuple(hints))
    finally:
        mq_closure.FULL_FACTOR_BITS = saved
    assert got == _eager_split(n, tuple(hints))
    if got is not None:
        s, m = got
        assert s * s * m == n


# -- the SEC family's ball filters against the exact family ------------------------------
def _roots_key(roots):
    return [(r.lo, r.hi, None if r.exact is None else r.exact.text(), sorted(r.tags))
            for r in roots]


coord = st.integers(-12, 12)


@settings(max_examples=40, deadline=None)
@given(st.lists(st.tuples(coord, coord), min_size=4, max_size=7, unique=True),
       st.tuples(coord, coord), st.booleans(), st.booleans())
def test_sec_family_balls_leave_the_instants_unchanged(others, end, arc, radical):
    from exactsym.gathering import instants
    from exactsym.gathering.invariants import Checker
    from exactsym.gathering.robot import Readings
    from exactsym.gathering.world import World
    from exactsym.gathering import geometry as g
    start = (MQ.rational(fmpq(1, 3)), sqrt_rational(2) if radical else MQ.rational(1))
    pts = [start] + [(MQ.rational(x * 3), MQ.rational(y * 3)) for x, y in others]
    w = World(pts, Readings(), checker=Checker())
    stop = (MQ.rational(end[0] * 4), MQ.rational(end[1] * 4 + 1))
    if arc:
        c = g.point(0, 0)
        r2 = g.dist2(start, c)
        piece = g.Arc(c, start, g.rotate(start, MQ.rational(fmpq(3, 5)),
                                          MQ.rational(fmpq(4, 5))), 1)
        assert g.dist2(piece.end, c) == r2
    else:
        piece = g.Segment(start, stop)
    with_balls = instants.critical_roots(piece, w, 0, g.point(0, 0))
    saved = instants.MotionBall

    def no_balls(m):
        raise TypeError("balls off")
    instants.MotionBall = no_balls
    try:
        exact = instants.critical_roots(piece, w, 0, g.point(0, 0))
    finally:
        instants.MotionBall = saved
    assert _roots_key(with_balls) == _roots_key(exact)


def test_fresh_snapshot_reuses_local_points_of_unmoved_robots():
    from fractions import Fraction
    from exactsym.gathering.robot import Readings
    from exactsym.gathering.world import IDENTITY, MIRROR, Frame, World
    w = World([(0, 0), (5, 1), (-3, 7), (9, -4), (2, 11)], Readings())
    frame = Frame(Fraction(3, 5), Fraction(4, 5), True, Fraction(1, 3), Fraction(-2, 7))
    for fr in (IDENTITY, MIRROR, frame):
        first = w._snapshot(fr)
        assert first == tuple(fr.to_local(p) for p in w.positions())
    old = w.robots[2].pos
    w.robots[2].pos = (sqrt_rational(2), MQ.rational(7))
    again = w._snapshot(frame)
    assert again == tuple(frame.to_local(p) for p in w.positions())
    assert again[0] is w._snapshot(frame)[0]          # an unmoved robot: the same object
    assert again[2] != frame.to_local(old)
