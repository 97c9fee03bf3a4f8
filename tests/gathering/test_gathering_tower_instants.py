"""Critical instants that need a nested radical, checked at the instant
(exactsym.exact.algebraic.tower_numbers, roots.exact_root_hook): the root is a tower
number, the mover's point there has tower coordinates, and the fresh Look runs on them;
an invariant that fails only at such an instant is caught with the exact witness; an
exact similarity of the whole scene changes nothing."""

from fractions import Fraction as F

import pytest
from flint import fmpq
from hypothesis import given, settings, strategies as st

from exactsym.exact.multiquadratic import MQ, sqrt_rational
from exactsym.gathering import geometry as g
from exactsym.gathering.instants import look_points
from exactsym.gathering.invariants import Checker, Violation
from exactsym.gathering.pattern import recognise
from exactsym.exact.algebraic.polynomials import peval, pmul
from exactsym.exact.algebraic.roots import mq_sqrt, roots_in_unit
from exactsym.gathering.robot import Decision, Move, Readings
from exactsym.exact.algebraic.tower_numbers import TowerNumber, is_tower, tower_sqrt
from exactsym.gathering.world import IDENTITY, World

Q = MQ.rational
S2 = sqrt_rational(2)
ORIGIN = (Q(0), Q(0))


def poly(*cs):
    return tuple(MQ.coerce(c) for c in cs)


# -- roots -------------------------------------------------------------------------------
def test_quadratic_root_in_a_tower_is_the_root():
    # f^2 + f/3 - (sqrt(2) - 1)/4: discriminant 1/9 + sqrt(2) - 1, a square in no
    # multiquadratic field
    p = poly((1 - S2) / 4, F(1, 3), 1)
    (r,) = roots_in_unit(p)
    assert is_tower(r.exact) and peval(p, r.exact).is_zero()
    assert (r.exact - r.lo).sign() > 0 and (r.exact - r.hi).sign() < 0


def test_biquadratic_quartic_root_in_a_tower():
    # f^4 - 2 f^2 + (1 - sqrt(2)/4)... roots f^2 = 1 -+ sqrt(sqrt(2)/4): f = sqrt(1 - 2^(1/4)/2)
    p = poly(1 - S2 / 4, 0, -2, 0, 1)
    roots = roots_in_unit(p)
    assert len(roots) == 1
    (r,) = roots
    assert is_tower(r.exact) and peval(p, r.exact).is_zero()
    assert abs(float(r.exact) - (1 - 2 ** 0.25 / 2) ** 0.5) < 1e-12


def test_quartic_with_an_even_factor_is_solved_by_its_factors():
    # an arc's denominator 1 + 2 f^2 times a quadratic with a nested-radical root; and
    # (2 f - 1)-free cubic (1 + f^2)(f - sqrt(2)/2): the linear factor, exact in MQ
    q = poly((1 - S2) / 4, F(1, 3), 1)
    p = pmul(poly(1, 0, 2), q)
    (r,) = roots_in_unit(p)
    assert is_tower(r.exact) and peval(q, r.exact).is_zero()
    (r,) = roots_in_unit(pmul(poly(1, 0, 1), (-S2 / 2, Q(1))))
    assert r.exact == S2 / 2


def test_denestable_discriminant_stays_in_the_multiquadratic_field():
    # f^2 - (3 - 2 sqrt 2)/4: root (sqrt(2) - 1)/2, no tower needed
    (r,) = roots_in_unit(poly((2 * S2 - 3) / 4, 0, 1))
    assert isinstance(r.exact, MQ) and r.exact == (S2 - 1) / 2


def test_tower_sqrt_denests_and_adds_levels_only_when_needed():
    (r,) = roots_in_unit(poly(1 - S2, 0, 1))          # y = sqrt(sqrt(2) - 1)
    y = r.exact
    u = y + 1
    assert is_tower(u * u) and tower_sqrt(u * u) == u       # denested in the tower
    assert mq_sqrt(u * u * 9) == 3 * u
    assert mq_sqrt(y * y) is None                  # sqrt(2) - 1: no root in any MQ field
    z = tower_sqrt(y)                        # a fourth root: a new level
    assert is_tower(z) and z * z == y and z.sign() > 0
    assert mq_sqrt(-y) is None


def test_tower_numbers_keep_the_mq_interface_through_arithmetic():
    (r,) = roots_in_unit(poly(1 - S2, 0, 1))
    y = r.exact
    for v in (y + 1, 1 - y, y * S2, S2 / y, y / 3, -y, y ** 2 * y, 2 * y - S2):
        assert isinstance(v, (TowerNumber, MQ))
        assert v.is_zero() is False or v == 0
    assert isinstance(y * y, MQ)                       # back at level 0
    with pytest.raises(ValueError):
        y.to_fmpq()


# -- the checker at a nested-radical instant ------------------------------------------------
def _scene(sim=None):
    """The mover (robot 0) on the segment x = sqrt 2 from y = 1 to y = 9, C = 0; robot 1
    at (1, 2 + sqrt 2), squared distance 7 + 4 sqrt 2 from C: the mover is as far from C
    at y^2 = 5 + 4 sqrt 2, y = sqrt(5 + 4 sqrt 2), a nested radical (no denesting).
    ``sim``: an exact similarity applied to everything."""
    sim = sim or (lambda p: p)
    pts = [sim((S2, Q(1))), sim((Q(1), 2 + S2)), sim((Q(0), Q(30))), sim((Q(21), Q(0))),
           sim((Q(-40), Q(1)))]
    return pts, sim(ORIGIN), sim((S2, Q(9)))


def _stub_decide(centre, target):
    """A test algorithm (not the paper's): robot 0 goes to ``target`` unless it is exactly
    as far from C as robot 1 (then everybody stays).  Plain-frame Looks only."""
    def decide(snapshot, readings=Readings(), unit=fmpq(1)):
        pts = list(snapshot)
        pat = recognise(pts, centre)
        if g.dist2(pts[0], centre) == g.dist2(pts[1], centre):
            return Decision("stay", (), centre, pat, None, "a tie with robot 1")
        move = Move(0, (g.Segment(pts[0], target),), "leader")
        return Decision("move", (move,), centre, pat, 0, "to the target")
    return decide


def _run(sim=None):
    pts, centre, target = _scene(sim)
    w = World(pts, Readings(), checker=Checker(enabled=frozenset({"I3"})))
    w.decide = _stub_decide(centre, target)
    w.look(0, IDENTITY)
    seg = w.robots[0].path[0]
    points, sided = look_points(seg, w, 0, centre)
    with pytest.raises(Violation) as err:
        w.advance(0)
    return w, centre, points, sided, err.value


def test_invariant_failing_only_at_a_nested_radical_instant_is_caught_exactly():
    w, centre, points, sided, v = _run()
    assert sided == 0
    ties = [lp for lp in points if lp.exact and "distance" in lp.families]
    assert len(ties) == 1
    tie = ties[0]
    assert is_tower(tie.f) and is_tower(tie.point[1])
    d1 = g.dist2(w.robots[1].pos, centre)
    assert g.dist2(tie.point, centre) == d1                         # exactly the tie
    assert tie.point[1] * tie.point[1] == 5 + 4 * S2
    # every other Look point (both sides of the tie included) plans the move
    assert all(g.dist2(lp.point, centre) != d1 for lp in points if lp is not tie)
    assert v.invariant == "I3" and v.robots == (0,)
    assert f"robot 0 at {g.fmt_point(tie.point)}" in v.witness
    assert "as far from C as robot 1" in v.witness
    assert "no move" in v.witness
    counts = w.checker.counts
    assert counts["nested"] >= 1 and counts["sided"] == 0
    assert w.robots[0].pos == _scene()[2]          # at the piece end again after the Looks


@settings(max_examples=6, deadline=None)
@given(st.sampled_from([(2, 1), (3, 2), (1, 0)]), st.booleans(), st.integers(-5, 5),
       st.integers(-5, 5))
def test_exact_isometry_moves_the_witness_along(rot, reflect, tx, ty):
    # robots are unit discs, so only isometries (Pythagorean rotations, reflections,
    # translations) keep the layers and the contacts, hence the instants
    a, b = rot
    c, s = Q(F(a * a - b * b, a * a + b * b)), Q(F(2 * a * b, a * a + b * b))

    def sim(p):
        x, y = p[0], (-p[1] if reflect else p[1])
        return (c * x - s * y + tx, s * x + c * y + ty)

    _, _, base_points, _, base_v = _run()
    w, centre, points, sided, v = _run(sim)
    assert sided == 0 and v.invariant == base_v.invariant and v.robots == base_v.robots
    assert [lp.f for lp in points] == [lp.f for lp in base_points]    # same instants
    tie = next(lp for lp in points if lp.exact and "distance" in lp.families)
    base_tie = next(lp for lp in base_points if lp.exact and "distance" in lp.families)
    assert tie.point == sim(base_tie.point)                            # mapped exactly
    assert f"robot 0 at {g.fmt_point(tie.point)}" in v.witness
    assert w.checker.counts["nested"] >= 1


# -- squares in the multiquadratic closure (what lets a tower level be built) ---------------
_RADICANDS = (1, 2, 3, 5, 6, 7, 10, 15)


@settings(max_examples=40, deadline=None)
@given(st.lists(st.fractions(min_value=-5, max_value=5, max_denominator=7),
                min_size=len(_RADICANDS), max_size=len(_RADICANDS)),
       st.sampled_from([1, 2, 3, 11, 13, 22, 39]))
def test_decided_sqrt_finds_every_root_in_a_larger_field(coeffs, m):
    from exactsym.exact.mq_closure import decided_sqrt
    z = sum((Q(c) * sqrt_rational(r) for c, r in zip(coeffs, _RADICANDS)), MQ())
    x = z * z * m
    root, decided = decided_sqrt(x)
    assert decided and root == abs(z) * sqrt_rational(m)
    # and z^2 times a number that is not a square anywhere: no root, decided
    if not z.is_zero():
        root, decided = decided_sqrt(x * (5 + 4 * S2))
        assert decided and root is None


def test_a_run_checks_its_nested_radical_instants_at_the_instant():
    # the corrected variant's detour (an arc, then a segment) meets instants that need
    # nested radicals; before towers they were seen on both sides only (sided 4).  The
    # count follows the variant's paths (issue 31): four with the detour points built from
    # distances to C (the frame fix; two with the integer-direction points before it)
    from pathlib import Path
    from exactsym.gathering.cases import run_case_file
    case = Path(__file__).resolve().parents[2] / "cases" / "gathering" / \
        "corrected-obstacle-beside-path.toml"
    run = run_case_file(case)
    assert not run.failures and run.result.outcome == "gathered"
    assert run.result.checks["nested"] == 4 and run.result.checks["sided"] == 0


def test_numbers_of_two_towers_are_never_declared_different():
    """sqrt(5+4*sqrt(2)) and 2*sqrt((5+4*sqrt(2))/4) are one number held in two towers
    (their first radicands differ): their canonical forms differ, so no answer is given
    (ValueError: the decision that needs it is undecided) rather than a wrong one."""
    import pytest
    from exactsym.exact.multiquadratic import MQ, sqrt_rational
    from exactsym.exact.algebraic.tower_numbers import mq_sqrt_any
    r = MQ.rational(5) + 4 * sqrt_rational(2)
    a, b = mq_sqrt_any(r), 2 * mq_sqrt_any(r / 4)
    assert a.tower is not b.tower
    with pytest.raises(ValueError):
        a == b
    assert a == mq_sqrt_any(r)                      # one tower: decided exactly
