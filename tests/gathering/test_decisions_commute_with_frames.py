"""The paper's algorithm as a robot runs it sees the snapshot in its own frame: a rotation,
a scale and a translation of that frame (a similarity with rational entries) must change
no decision -- the same movers, and the same targets once mapped back to the world.  The
proof of a stall reads two frames only (the world's and the reflected one:
``schedulers.no_mover_in_any_frame``); this is the property it rests on.  (A reflection may
change the decision: the paper's rules use a handedness, which I9 checks at every Look.)"""

from __future__ import annotations

from fractions import Fraction as F
from pathlib import Path

from flint import fmpq
from hypothesis import HealthCheck, given, settings, strategies as st

from exactsym.gathering.geometry import point
from exactsym.gathering.paper_bridge import read_case
from exactsym.gathering.robot import Readings, decide
from exactsym.gathering.world import Frame

CASES = Path(__file__).resolve().parents[2] / "cases" / "gathering"
#: Pythagorean rotations with a scale: (a, b) with a^2 + b^2 a rational square
ROTATIONS = ((F(3, 5), F(4, 5)), (F(6, 5), F(8, 5)), (F(-5, 13), F(12, 13)),
             (F(8, 17), F(-15, 17)))


def _targets(d, frame=None) -> dict:
    return {m.robot: frame.to_world(m.path[-1].final) if frame else m.path[-1].final
            for m in d.moves}


def _same_in(points, frame: Frame, readings: Readings) -> None:
    world = tuple(point(x, y) for x, y in points)
    base = decide(world, readings)
    local = tuple(point(*frame.to_local((F(x), F(y)))) for x, y in points)
    unit = frame.unit
    seen = decide(local, readings, fmpq(unit.numerator, unit.denominator))
    assert seen.status == base.status, (frame, base.detail, seen.detail)
    assert _targets(seen, frame) == _targets(base), frame


def _frames():
    return st.builds(lambda ab, tx, ty: Frame(ab[0], ab[1], False, F(tx), F(ty)),
                     st.sampled_from(ROTATIONS), st.fractions(-9, 9, max_denominator=7),
                     st.fractions(-9, 9, max_denominator=7))


def _rational_starts():
    """Five to seven separated robots on a small grid."""
    cell = st.tuples(st.integers(-6, 6), st.integers(-6, 6))

    def separated(pts):
        return all((a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2 > 1 for i, a in enumerate(pts)
                   for b in pts[i + 1:])
    return st.lists(cell, min_size=5, max_size=7, unique=True).map(
        lambda pts: [(F(3 * x), F(3 * y)) for x, y in pts]).filter(separated)


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(points=_rational_starts(), frame=_frames(), a3=st.sampled_from(("first", "all")))
def test_the_papers_decision_does_not_depend_on_rotation_scale_or_origin(points, frame, a3):
    _same_in(points, frame, Readings(A3=a3))


def test_on_every_rational_gathering_case():
    frame = Frame(F(6, 5), F(8, 5), False, F(7, 3), F(-5, 2))
    checked = 0
    for path in sorted(CASES.glob("*.toml")):
        pts, _name, expect, _src = read_case(path)
        if not all(isinstance(c, fmpq) for p in pts for c in p):
            continue
        rational = [(F(int(x.numer()), int(x.denom())), F(int(y.numer()), int(y.denom())))
                    for x, y in pts]
        for a3 in ("first", "all"):
            _same_in(rational, frame, Readings(A3=a3))
            checked += 1
    assert checked >= 40
