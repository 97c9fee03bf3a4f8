"""Critical instants at roots of irreducible cubic and quartic factors, checked at the
instant (exactsym.gathering.algebraic_instants): the root is a number of K(alpha), the
movers' points there have coordinates in K(alpha), and the fresh Look runs on them; an
invariant that fails only at such an instant is caught there with the exact witness, and
holds when nothing happens; the number type obeys the field laws, its signs agree with
high-precision evaluation and its zero test is exact."""

from fractions import Fraction as F

import pytest
from flint import fmpq, fmpq_poly
from hypothesis import given, settings, strategies as st

from exactsym.exact.multiquadratic import MQ, sqrt_rational
from exactsym.gathering import geometry as g
from exactsym.gathering.algebraic_kernel import kernel_configuration, kernel_field
from exactsym.exact.algebraic.algebraic_tower import is_algebraic_tower
from exactsym.exact.algebraic.algebraic_numbers import algebraic_sqrt, is_algebraic
from exactsym.exact.algebraic.factor import factor_over_k
from exactsym.gathering.invariants import Checker, Violation
from exactsym.gathering.joint_instants import joint_look_points
from exactsym.gathering.pattern import recognise
from exactsym.exact.algebraic.polynomials import peval, pmul
from exactsym.exact.algebraic.roots import algebraic_root, mq_sqrt, roots_in_unit
from exactsym.gathering.robot import Decision, Move, Readings
from exactsym.gathering.world import IDENTITY, World

Q = MQ.rational
S2, S3 = sqrt_rational(2), sqrt_rational(3)
P = g.point


def poly(*cs):
    return tuple(MQ.coerce(c) for c in cs)


# -- factoring and roots ----------------------------------------------------------------------
def test_cubic_roots_are_exact_in_k_alpha():
    # 8 f^3 - f - sqrt(2)/4: irreducible over Q(sqrt 2) (a cubic without a root there)
    p = poly(-S2 / 4, -1, 0, 8)
    (r,) = roots_in_unit(p)
    assert is_algebraic(r.exact) and peval(p, r.exact) == 0
    assert (r.exact - r.lo).sign() > 0 and (r.exact - r.hi).sign() < 0


def test_a_cubic_reducible_over_k_gives_its_linear_and_quadratic_roots():
    # (f - sqrt(2)/2)(f^2 - 1/3): over Q(sqrt 2) the factors are found (Trager)
    p = pmul(poly(-S2 / 2, 1), poly(F(-1, 3), 0, 1))
    assert sorted(len(f) for f in factor_over_k(p)) == [2, 3]
    got = sorted(float(r.exact) for r in roots_in_unit(p))
    assert got == pytest.approx([1 / 3 ** 0.5, 2 ** 0.5 / 2])
    assert all(not is_algebraic(r.exact) for r in roots_in_unit(p))
    # a quartic, the product of two quadratics over Q(sqrt 2, sqrt 3): found as such,
    # its roots are then exact (multiquadratic or tower numbers)
    p2 = pmul(poly(F(-1, 5), -S2 / 3, 1), poly(-S3 / 7, F(1, 2), 1))
    assert sorted(len(f) for f in factor_over_k(p2)) == [3, 3]
    for r in roots_in_unit(p2):
        assert r.exact is not None and not is_algebraic(r.exact)
        assert peval(p2, r.exact).is_zero()


def test_quartics_s4_in_k_alpha_d4_nested():
    p = poly(F(-1, 2), 1, 0, 0, 1)                    # f^4 + f - 1/2: group S4
    (r,) = roots_in_unit(p)
    assert is_algebraic(r.exact) and peval(p, r.exact).is_zero()
    # (f^2 + f)^2 = 1/3: f^2 + f = 1/sqrt(3), a nested radical of group D4: a tower
    # number (quartic_instants), not a number of K(alpha)
    p = poly(F(-1, 3), 0, 1, 2, 1)
    (r,) = roots_in_unit(p)
    assert r.exact is not None and not is_algebraic(r.exact)
    assert peval(p, r.exact).is_zero()


@pytest.mark.parametrize("coeffs", [(-S2 / 4, -1, 0, 8), (F(-1, 2), 1, 0, 0, 1)])
def test_square_roots_in_k_alpha_and_its_multiquadratic_extensions(coeffs):
    """sqrt(w^2) = |w|, sqrt(3 w^2) = sqrt(3) |w| (cubic alpha: any multiquadratic
    factor is found through the norm), none in any K'(alpha) for w, alpha, or
    w^2 (5 + sqrt 2) (a nested radical)."""
    (r,) = roots_in_unit(poly(*coeffs))
    a = r.exact
    w = a * a + S2 * a + 1
    assert algebraic_sqrt(w * w) == abs(w) == mq_sqrt(w * w)
    assert (algebraic_sqrt(3 * w * w) == S3 * abs(w)) == (a.root.degree == 3)
    for x in (w, a, w * w * (5 + S2), -w * w):
        assert algebraic_sqrt(x) is None
    assert mq_sqrt(-w * w) is None


def test_square_roots_outside_k_alpha_are_a_tower_level_over_it():
    """Cubic alpha: sqrt(w) is a new level y over K(alpha) (w is a square in no
    K'(alpha)); sqrt(4 w) = 2 y and sqrt(3 w) = sqrt(3) y are found in it, sqrt(y) is
    a second level; a radial point at distance 4 is exact.  Quartic alpha: no level."""
    from exactsym.gathering.robot import radial_point
    (r,) = roots_in_unit(poly(-S2 / 4, -1, 0, 8))
    a = r.exact
    w = a * a + S2 * a + 1
    y = mq_sqrt(w)
    assert is_algebraic_tower(y) and y * y == w and y.sign() == 1
    assert mq_sqrt(4 * w) == 2 * y and mq_sqrt(3 * w) == S3 * y
    assert mq_sqrt(w) == y and hash(mq_sqrt(w)) == hash(y)
    assert (y + a) - a == y and (y + a) * (y - a) == w - a * a
    z = mq_sqrt(y)
    assert z * z == y and z.tower.levels == 2
    p = (3 * a, 5 + a)
    t = radial_point((Q(0), Q(0)), p, 4)
    assert g.dist2(t, (Q(0), Q(0))) == 16 and g.cross(t, p) == 0 and g.dot(t, p) > 0
    (q,) = roots_in_unit(poly(F(-1, 2), 1, 0, 0, 1))
    assert mq_sqrt(q.exact * q.exact + 1) is None


# -- the number type -------------------------------------------------------------------------
_ROOT = roots_in_unit(poly(-S2 / 4, -1, 0, 8))[0].exact     # alpha, in Q(sqrt 2)(alpha)
_QROOT = roots_in_unit(poly(F(-1, 2), 1, 0, 0, 1))[0].exact  # a quartic's (group S4)
small = st.fractions(min_value=-5, max_value=5, max_denominator=7)


@st.composite
def elements(draw, base=None):
    a = base if base is not None else draw(st.sampled_from([_ROOT, _QROOT]))
    cs = [draw(small) + draw(small) * S2 + draw(small) * S3 for _ in range(a.root.degree)]
    x = cs[0]
    for k, c in enumerate(cs[1:], start=1):
        x = x + c * a ** k
    return x


def _mp(x):
    """An MQ as an mpmath number (sympy's dependency: an evaluation independent of the
    number type's Arb balls)."""
    import mpmath
    return sum((mpmath.mpf(int(c.p)) / int(c.q) * mpmath.sqrt(m) for m, c in x.terms.items()),
               mpmath.mpf(0))


def _value(x):
    """x at 300 digits: alpha from mpmath's polyroots of its polynomial, the real root
    nearest to the float of alpha, the coefficients evaluated there."""
    import mpmath
    with mpmath.workdps(300):
        f = x.root.f
        roots = mpmath.polyroots([_mp(c) for c in reversed(f)], maxsteps=400, extraprec=600)
        a = min((r for r in roots if abs(mpmath.im(r)) < mpmath.mpf(10) ** -100),
                key=lambda r: abs(r - float(x.root.ball(60).mid())))
        return sum(_mp(c) * mpmath.re(a) ** k for k, c in enumerate(x.c))


@settings(max_examples=20, deadline=None)
@given(st.data())
def test_field_axioms(data):
    base = data.draw(st.sampled_from([_ROOT, _QROOT]))
    x, y, z = (data.draw(elements(base)) for _ in range(3))
    assert x + y == y + x and x * y == y * x
    assert (x + y) + z == x + (y + z) and (x * y) * z == x * (y * z)
    assert x * (y + z) == x * y + x * z
    assert x - x == 0 and (x + 0) == x and x * 1 == x
    if not (is_algebraic(y) is False and y == 0):
        assert (x / y) * y == x
        assert y * y.inverse() == 1 if is_algebraic(y) else True
    assert hash(x + y) == hash(y + x)


@settings(max_examples=20, deadline=None)
@given(st.data())
def test_sign_agrees_with_high_precision_evaluation(data):
    base = data.draw(st.sampled_from([_ROOT, _QROOT]))
    x = data.draw(elements(base))
    if not is_algebraic(x):
        assert x.sign() == (x > 0) - (x < 0)
        return
    v = _value(x)
    assert abs(v) > 1e-200                      # never zero: x is not in K
    assert x.sign() == (1 if v > 0 else -1)
    assert (x > 0) == (v > 0) and (x < 0) == (v < 0)


@settings(max_examples=30, deadline=None)
@given(st.data())
def test_zero_test_is_exact(data):
    """g(alpha) = 0 iff f | g: a multiple of alpha's polynomial is 0, a tiny
    perturbation of it is not (and its sign is the perturbation's)."""
    base = data.draw(st.sampled_from([_ROOT, _QROOT]))
    h = data.draw(elements(base))
    f = base.root.f
    fa = peval(f, base)
    assert fa == 0 and not is_algebraic(fa)
    assert h * fa == 0
    eps = Q(fmpq(1, 10 ** 30))
    w = peval(f, base) + eps
    assert w != 0 and w.sign() == 1


def test_numbers_of_two_instants_are_not_mixed():
    with pytest.raises(ValueError):
        _ = _ROOT == _QROOT
    with pytest.raises(ValueError):
        _ = _ROOT + _QROOT


def test_the_same_root_found_twice_shares_its_field():
    a = algebraic_root(poly(-S2 / 4, -1, 0, 8), fmpq(0), fmpq(1))
    b = algebraic_root(pmul(poly(-S2 / 4, -1, 0, 8), poly(-3, 1)), fmpq(1, 4), fmpq(3, 4))
    assert a == b and hash(a) == hash(b)


# -- the checker at a cubic instant of a joint step -------------------------------------------
#: robot 0 on the segment (-12, 8) -> (12, 12), robot 1 on the arc about (0, -39) from
#: (-7, -15) to (7, -15): they are on one line through C = 0 at a root of an irreducible
#: cubic (the joint `ray` family: a linear times a quadratic over the arc's denominator)
CENTRE = P(0, 0)


def _scene(sim=None):
    sim = sim or (lambda p: p)
    pts = [sim(P(-12, 8)), sim(P(-7, -15)), sim(P(40, 40)), sim(P(-40, 40)), sim(P(0, -90))]
    return pts, sim(CENTRE), sim(P(12, 12)), sim(P(0, -39)), sim(P(7, -15))


def _stub(centre, target, stays):
    """A test algorithm (not the paper's): robot 0 goes to ``target`` unless ``stays``
    (of the snapshot) holds.  Plain-frame Looks only."""
    def decide(snapshot, readings=Readings(), unit=fmpq(1)):
        pts = list(snapshot)
        pat = recognise(pts, centre)
        if stays(pts, centre):
            return Decision("stay", (), centre, pat, None, "robots 0, 1 and C collinear")
        move = Move(0, (g.Segment(pts[0], target),), "leader")
        return Decision("move", (move,), centre, pat, 0, "to the target")
    return decide


def _collinear(pts, c):
    return g.cross(g.sub(pts[0], c), g.sub(pts[1], c)).is_zero()


def _run(stays, sim=None, sense=-1):
    pts, centre, target, k, end1 = _scene(sim)
    w = World(pts, Readings(), checker=Checker(enabled=frozenset({"I3"})))
    w.decide = _stub(centre, target, stays)
    w.look(0, IDENTITY)
    (arc,) = g.arc_path(k, pts[1], end1, sense)
    w.robots[1].path = [arc]                   # a made-up move: no Look, no target
    w.robots[1].centre = centre
    pieces = {0: w.robots[0].path[0], 1: arc}
    points, sided = joint_look_points(pieces, w)
    return w, points, sided


def _cubic_instant(points):
    alg = [jp for jp in points if jp.exact and is_algebraic(jp.tau)
           and "robots 0 and 1 on one line through C" in jp.where]
    assert len(alg) == 1 and alg[0].tau.root.degree == 3
    return alg[0]


def test_I3_fires_exactly_at_a_cubic_instant():
    w, points, sided = _run(_collinear)
    assert sided == 0
    jp = _cubic_instant(points)
    p0, p1 = w.robots[0].path[0].at(jp.tau), w.robots[1].path[0].at(jp.tau)
    assert g.cross(p0, p1) == 0                        # exactly collinear with C
    # every other Look point (both sides of the instant included) is not collinear
    others = [q for q in points if q is not jp]
    assert all(g.cross(w.robots[0].path[0].at(q.tau), w.robots[1].path[0].at(q.tau)) != 0
               for q in others)
    with pytest.raises(Violation) as err:
        w.advance_together([(0, None, False), (1, None, False)])
    v = err.value
    assert v.invariant == "I3" and v.robots == (0,)
    assert f"robot 0 at {g.fmt_point(p0)}" in v.witness
    assert "on one line through C" in v.witness and "no move" in v.witness
    assert w.checker.counts["sided"] == 0


def test_I3_holds_over_the_step_when_nothing_happens_there():
    w, points, sided = _run(lambda pts, c: False)
    _cubic_instant(points)
    w.advance_together([(0, None, False), (1, None, False)])
    assert w.checker.counts["sided"] == 0 and w.checker.counts["instants"] >= len(points)
    # the cubic collinearity and the quartic tie: Looks at points of K(alpha)
    assert w.checker.counts["algebraic"] == sum(1 for jp in points if is_algebraic(jp.tau)) >= 2


def test_a_quartic_distance_tie_is_exact_too():
    """The same step's tie |p0| = |p1| is a root of an S4 quartic: exact, and a stub
    staying at the tie is caught there."""
    def tie(pts, c):
        return g.dist2(pts[0], c) == g.dist2(pts[1], c)
    w, points, sided = _run(tie)
    quartic = [jp for jp in points if jp.exact and is_algebraic(jp.tau)
               and jp.tau.root.degree == 4]
    assert sided == 0 and len(quartic) == 1 and "as far from C" in quartic[0].where
    with pytest.raises(Violation) as err:
        w.advance_together([(0, None, False), (1, None, False)])
    assert "as far from C" in err.value.witness


def _similarity(p):
    """An exact similarity: the rotation (3/5, 4/5), scale 2, a translation."""
    x, y = p
    return (2 * (x * F(3, 5) - y * F(4, 5)) + 7, 2 * (x * F(4, 5) + y * F(3, 5)) - 1)


def test_an_exact_similarity_changes_nothing():
    w, points, sided = _run(_collinear, _similarity)
    assert _cubic_instant(points) is not None and sided == 0
    with pytest.raises(Violation) as err:
        w.advance_together([(0, None, False), (1, None, False)])
    assert err.value.invariant == "I3" and "on one line through C" in err.value.witness


def test_rational_norm_agrees_with_flint():
    """The norm-based factoring gives the factors of a rational polynomial that flint
    gives (K = Q) and an irreducible cubic over Q(sqrt 2) stays one."""
    p = poly(-6, 11, -6, 1)                       # (f-1)(f-2)(f-3)
    assert sorted(f[0].to_fmpq() for f in factor_over_k(p)) == [-3, -2, -1]
    f = fmpq_poly([-1, -8, 0, 64])
    assert len(factor_over_k(poly(-1, -8, 0, 64))) == len(f.factor()[1]) == 2
    assert len(factor_over_k(poly(-S2 / 4, -1, 0, 8))) == 1


@settings(max_examples=8, deadline=None)
@given(st.integers(-12, -4), st.integers(2, 12), st.integers(4, 12), st.integers(2, 12),
       st.integers(-40, -30))
def test_joint_ray_and_tie_instants_are_exact(x0, y0, x1, y1, ky):
    """A segment (x0, y0) -> (x1, y1) and an arc about (0, ky) of radius 25 moving at
    once: every instant where the two are on one line through C or as far from C is
    exact (no sided instant), the relation holds exactly there and not at the Looks
    just before and after it."""
    pts = [P(x0, y0), P(-7, ky + 24), P(40, 40), P(-40, 40), P(0, -90)]
    (arc,) = g.arc_path(P(0, ky), pts[1], P(7, ky + 24), -1)
    seg = g.Segment(pts[0], P(x1, y1))
    w = World(pts, Readings(), checker=None)
    for i, piece in ((0, seg), (1, arc)):
        w.robots[i].path, w.robots[i].centre = [piece], CENTRE
    points, sided = joint_look_points({0: seg, 1: arc}, w)
    assert sided == 0

    def rel(tau, what):
        p, q = seg.at(tau), arc.at(tau)
        return g.cross(p, q) if "one line" in what else g.dist2(p, CENTRE) - g.dist2(q, CENTRE)

    for k, jp in enumerate(points):
        for what in ("robots 0 and 1 on one line through C", "robots 0 and 1 as far from C"):
            if jp.exact and what in jp.where:
                assert rel(jp.tau, what) == 0
                before, after = points[k - 1], points[k + 1]
                assert rel(before.tau, what) != 0 and rel(after.tau, what) != 0


# -- the paper layer at a K(alpha) instant (algebraic_kernel) ---------------------------------
@settings(max_examples=20, deadline=None)
@given(st.data())
def test_kernel_field_is_a_field_isomorphism(data):
    """x -> its element of Q(gamma) keeps sums, products, quotients, equality and signs."""
    base = data.draw(st.sampled_from([_ROOT, _QROOT]))
    x, y = data.draw(elements(base)), data.draw(elements(base))
    _, to_kernel = kernel_field(base.root, [x, y, S2, S3])
    kx, ky = to_kernel(x), to_kernel(y)
    assert to_kernel(x + y) == kx + ky and to_kernel(x * y) == kx * ky
    assert (x == y) == (kx == ky) and (x - y).sign() == (kx - ky).sign()
    if not (y == 0):
        assert to_kernel(x / y) == kx / ky


def test_the_paper_layer_reads_a_cubic_instant_through_the_kernel():
    """``paper_bridge.configuration_of`` reads K(alpha) snapshots through
    :func:`kernel_configuration`, so the paper's decision at the cubic instant is not
    the kernel's "undecided" but the paper layer's own:
    MakeAsym's move of robot 0 to G_t's circle, whose end needs a square root outside
    K(alpha) (a level over it, :mod:`.algebraic_tower`); and the kernel configuration's
    squared distances are the simulator's."""
    from exactsym.gathering import paper_bridge, robot
    pts, centre, target, k, end1 = _scene()
    seg = g.Segment(pts[0], target)
    (arc,) = g.arc_path(k, pts[1], end1, -1)
    w = World(pts, Readings(), checker=None)
    for i, piece in ((0, seg), (1, arc)):
        w.robots[i].path, w.robots[i].centre = [piece], CENTRE
    points, _ = joint_look_points({0: seg, 1: arc}, w)
    jp = _cubic_instant(points)
    snap = [seg.at(jp.tau), arc.at(jp.tau)] + pts[2:]
    config = kernel_configuration(snap)
    kd = [config.points[0][0] ** 2 + config.points[0][1] ** 2,
          config.points[1][0] ** 2 + config.points[1][1] ** 2]
    _, to_kernel = kernel_field(jp.tau.root, [c for p in snap for c in p])
    assert kd == [to_kernel(g.dist2(p, CENTRE)) for p in snap[:2]]
    w.robots[0].pos, w.robots[1].pos = snap[0], snap[1]
    assert paper_bridge.configuration_of(snap).points == config.points
    robot.decide.cache_clear()
    d, _ = w.snapshot_decision(IDENTITY)
    assert d.status == "move" and d.detail == "MakeAsym moves first"
    (move,) = d.moves
    end = move.path[-1].final
    assert move.robot == 0 and move.kind == "to-G_t-circle"
    assert is_algebraic_tower(end[0]) or is_algebraic_tower(end[1])
    robot.decide.cache_clear()


def test_k_alpha_does_not_mix_with_a_runs_tower():
    """A robot standing at a nested-radical position (a run's tower number): the cubic
    instant is seen on both sides only (sided), no K(alpha) point is built.  (Positions
    in a run's tower exist once robots can move to nested-radical targets: run_tower.)"""
    pytest.importorskip("exactsym.exact.algebraic.run_tower")
    from exactsym.exact.algebraic.tower_numbers import mq_sqrt_any
    y = mq_sqrt_any(1 + S2)                          # sqrt(1 + sqrt 2): a tower number
    pts, centre, target, k, end1 = _scene()
    seg = g.Segment(pts[0], target)
    (arc,) = g.arc_path(k, pts[1], end1, -1)
    w = World(pts, Readings(), checker=None)
    w.robots[2].pos = (y + 39, Q(40))                # moved there earlier in the run
    for i, piece in ((0, seg), (1, arc)):
        w.robots[i].path, w.robots[i].centre = [piece], CENTRE
    points, sided = joint_look_points({0: seg, 1: arc}, w)
    assert sided >= 1 and not any(is_algebraic(jp.tau) for jp in points)
    assert any("robots 0 and 1 on one line through C" in jp.where for jp in points)
