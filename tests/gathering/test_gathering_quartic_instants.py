"""Critical instants at roots of quartic factors of group D4, C4 or V4 over K
(exactsym.gathering.quartic_instants, Ferrari over K): the root is an MQ or a tower
number, a root of the polynomial exactly, inside its isolating interval, and the float
root of a high-precision solver (a comparison only); where no real root is built the
answer is None, never a wrong value; a joint step whose distance tie is such a quartic
is checked at the tie (no ``sided`` instant)."""

from fractions import Fraction as F

import mpmath
from hypothesis import assume, given, settings, strategies as st

from exactsym.exact.multiquadratic import MQ, sqrt_rational
from exactsym.gathering import geometry as g
from exactsym.exact.algebraic import quartic as quartic_instants, roots as root_isolation
from exactsym.exact.algebraic.algebraic_numbers import is_algebraic
from exactsym.exact.algebraic.factor import factor_over_k, stable as _stable
from exactsym.gathering.joint_instants import joint_look_points
from exactsym.exact.algebraic.polynomials import pderiv, peval, pgcd, shift as _shift
from exactsym.exact.algebraic.roots import roots_in_unit
from exactsym.exact.algebraic.quartic import depressed, quartic_root, resolvent
from exactsym.gathering.robot import Readings
from exactsym.exact.algebraic.tower_numbers import is_tower
from exactsym.gathering.world import World

Q = MQ.rational
S2, S3 = sqrt_rational(2), sqrt_rational(3)
P = g.point


def poly(*cs):
    return tuple(MQ.coerce(c) for c in cs)


def ferrari_family(u, v, w, h):
    """``(x^2 - u)^2 - v (x - w)^2`` at ``x - h``: a resolvent root ``z = -2u``
    (``t = v``), monic, lowest degree first."""
    p, q, r = -2 * u - v, 2 * v * w, u * u - v * w * w
    return _shift(poly(r, q, p, 0, 1), MQ.coerce(-h))


def _mp(c: MQ):
    return sum(mpmath.mpf(int(x.p)) / int(x.q) * mpmath.sqrt(m) for m, x in c.terms.items())


def _float_roots(f) -> list:
    with mpmath.workdps(60):
        rts = mpmath.polyroots([_mp(c) for c in reversed(f)], maxsteps=200, extraprec=200)
        return [float(mpmath.re(x)) for x in rts if abs(mpmath.im(x)) < mpmath.mpf(10) ** -30]


# -- the number: exact, inside its interval, the float root --------------------------------
_FIELD = st.sampled_from([Q(1), S2])          # coefficients in Q or in Q(sqrt 2)


def _element(draw):
    a = draw(st.fractions(min_value=-2, max_value=2, max_denominator=6))
    b = draw(st.fractions(min_value=-1, max_value=1, max_denominator=4))
    return Q(a) + Q(b) * draw(_FIELD)


@settings(max_examples=40, deadline=None)
@given(st.data())
def test_reducible_resolvent_roots_are_exact_tower_numbers(data):
    u, w = _element(data.draw), _element(data.draw)
    v = data.draw(st.sampled_from([Q(3), Q(F(5, 4)), 1 + S2, 2 + S2, 3 - S2, S3 + 2]))
    h = Q(data.draw(st.fractions(min_value=-1, max_value=1, max_denominator=5)))
    f = ferrari_family(u, v, w, h)
    factors = factor_over_k(f)
    assume(factors is not None and len(factors) == 1)        # irreducible over K
    assume(len(pgcd(f, pderiv(f))) <= 1)    # square-free: (t^2 - 3/4)^2 is one factor too
    assert not _stable(f)                                   # group D4, C4 or V4
    roots = roots_in_unit(f)
    assume(roots)
    floats = [x for x in _float_roots(f) if 0 < x < 1]
    assert len(roots) == len(floats)
    for r in roots:
        x = r.exact
        assert x is not None and not is_algebraic(x)
        assert is_tower(x) or isinstance(x, MQ)
        assert peval(f, x).is_zero()
        assert (x - r.lo).sign() > 0 and (x - r.hi).sign() < 0
        lo, hi = int(r.lo.p) / int(r.lo.q), int(r.hi.p) / int(r.hi.q)
        near = [y for y in floats if lo <= y <= hi]
        assert len(near) == 1 and abs(float(x) - near[0]) < 1e-12


def test_ferrari_by_hand():
    # (f^2 + f)^2 = 1/3 (an MQ s = 1): the root -1/2 + sqrt(1/4 + sqrt(3)/3)
    f = poly(F(-1, 3), 0, 1, 2, 1)
    (r,) = roots_in_unit(f)
    assert is_tower(r.exact)
    y = r.exact + Q(F(1, 2))
    assert y * y == Q(F(1, 4)) + S3 / 3
    # two levels: s = sqrt(1 + sqrt 2) is a square in no multiquadratic field
    f = ferrari_family(Q(F(1, 4)), 1 + S2, Q(F(1, 3)), Q(0))
    xs = [r.exact for r in roots_in_unit(f)]
    assert len(xs) == 2 and all(is_tower(x) and peval(f, x).is_zero() for x in xs)
    assert all(x.tower.levels <= 2 for x in xs)         # s, then sqrt(D): one tower each
    p, q, r = depressed(f)
    assert (p, q, r) == (-2 * Q(F(1, 4)) - (1 + S2), 2 * (1 + S2) / 3,
                         Q(F(1, 16)) - (1 + S2) / 9)
    assert peval(resolvent(p, q, r), Q(F(-1, 2))).is_zero()         # z = -2u


def test_the_same_factor_gives_the_same_numbers():
    f = ferrari_family(Q(F(1, 4)), 1 + S2, Q(F(1, 3)), Q(0))
    a = [r.exact for r in roots_in_unit(f)]
    b = [r.exact for r in roots_in_unit(f)]
    assert all(x.tower is y.tower and x == y for x, y in zip(a, b))


# -- no value rather than a wrong one --------------------------------------------------------
def test_no_root_in_the_interval_gives_none():
    f = ferrari_family(Q(F(1, 4)), 1 + S2, Q(F(1, 3)), Q(0))
    roots = roots_in_unit(f)
    # (0, 1/8) holds no root of f (they are near 0.198 and 0.394)
    assert len(roots) == 2 and not any(0 < x < 1 / 8 for x in _float_roots(f))
    assert quartic_root(f, F(0), F(1, 8)) is None
    assert quartic_root(f, F(-3), F(-2)) is None


def test_resolvent_root_with_t_negative_gives_none():
    # (x^2 + 1)^2 + 3 (x - 1/2)^2: the K-root z = -2 of the resolvent has t = z - p = -3
    # (it pairs complex roots); no real root at all
    f = ferrari_family(Q(-1), Q(-3), Q(F(1, 2)), Q(0))
    assert len(factor_over_k(f)) == 1 and not _stable(f)
    assert quartic_root(f, F(0), F(1)) is None
    assert roots_in_unit(f) == []


def test_a_failed_check_gives_none(monkeypatch):
    """The candidate is returned only when f(root) == 0 holds in the tower: a corrupted
    split (its constant terms moved) is caught, not returned."""
    f = ferrari_family(Q(F(1, 5)), Q(3), Q(F(1, 2)), Q(F(1, 7)))
    lo, hi = roots_in_unit(f)[0].lo, roots_in_unit(f)[0].hi
    assert quartic_root(f, lo, hi) is not None
    real = quartic_instants._factor
    eps = Q(F(1, 10 ** 6))

    def corrupted(g, sign):
        s, c = real(g, sign)
        return s, c + eps
    quartic_instants._quadratic_roots.cache_clear()
    monkeypatch.setattr(quartic_instants, "_factor", corrupted)
    try:
        assert quartic_root(f, lo, hi) is None
    finally:
        quartic_instants._quadratic_roots.cache_clear()


# -- a joint step whose distance tie is a D4 quartic -------------------------------------------
def _scene():
    """Robot 0 on a vertical segment with MQ ends, robot 1 on the arc about (0, -39) from
    (-7, -15) to (7, -15), C = 0: their distances from C are equal at the roots of
    ``(x^2 - u)^2 - v (x - w)^2`` at ``x + 1`` (u = -1, w = 3/2, v = 4867600/2401, the
    segment solved for it), an irreducible quartic of group D4 over Q with two roots
    in (0, 1)."""
    s0, s1, s2 = F(2960026, 15301), F(115248, 15301), F(28812, 15301)   # |seg(f)|^2
    r2 = sqrt_rational(s2)
    a = (-sqrt_rational(s0 - s1 * s1 / (4 * s2)), Q(s1) * r2 / (2 * Q(s2)))
    seg = g.Segment(a, (a[0], a[1] + r2))
    pts = [a, P(-7, -15), P(40, 40), P(-40, 40), P(0, -90)]
    (arc,) = g.arc_path(P(0, -39), pts[1], P(7, -15), -1)
    w = World(pts, Readings(), checker=None)
    for i, piece in ((0, seg), (1, arc)):
        w.robots[i].path, w.robots[i].centre = [piece], P(0, 0)
    return w, seg, arc


def test_a_d4_distance_tie_of_a_joint_step_is_checked_at_the_instant(monkeypatch):
    w, seg, arc = _scene()
    tie = ferrari_family(Q(-1), Q(F(4867600, 2401)), Q(F(3, 2)), Q(-1))
    assert len(factor_over_k(tie)) == 1 and not _stable(tie)

    def rel(tau):
        return g.dist2(seg.at(tau), P(0, 0)) - g.dist2(arc.at(tau), P(0, 0))

    points, sided = joint_look_points({0: seg, 1: arc}, w)
    assert sided == 0
    ties = [k for k, jp in enumerate(points)
            if jp.exact and "robots 0 and 1 as far from C" in jp.where]
    assert len(ties) == 2
    for k in ties:
        tau = points[k].tau
        assert is_tower(tau) and peval(tie, tau).is_zero()
        assert rel(tau) == 0                                  # exactly the tie
        assert rel(points[k - 1].tau) != 0 and rel(points[k + 1].tau) != 0
    # without the Ferrari hook (as before): both ties seen on both sides only
    monkeypatch.setattr(root_isolation, "quartic_root", lambda f, lo, hi: None)
    points, sided = joint_look_points({0: seg, 1: arc}, w)
    assert sided == 2
    assert not any(jp.exact and "as far from C" in jp.where for jp in points)
