"""Stops at exact irrational critical instants (issue 30, point 3; ``gathering/stops.py``).

The adversary may stop a mover at a critical instant of its motion that is a root of a
polynomial (a graze, a tie), often irrational.  A trace records it by its index among the
motion's instants and an isolating interval; a replay recomputes it."""

from __future__ import annotations

import json
from fractions import Fraction

import pytest

from exactsym.gathering.adversary import apply_action, stop_fractions
from exactsym.gathering.invariants import Checker, Violation
from exactsym.gathering.output import schedule_lines
from exactsym.gathering.schedulers import TraceMismatch, run
from exactsym.gathering.state_key import point_key
from exactsym.gathering.stops import motion_roots, resolve, simplest_between
from exactsym.gathering.trace import replay, same_result, trace_dict
from exactsym.gathering.world import IDENTITY, World

#: five robots whose leader's radial move crosses an irrational critical instant
IRRATIONAL = [
    ([(-5, Fraction(7, 2)), (Fraction(5, 2), 0), (5, Fraction(10, 3)),
      (Fraction(-10, 3), 1), (10, Fraction(-15, 2))], 3),
    ([(Fraction(-1, 3), Fraction(13, 3)), (-14, -2), (5, 6),
      (Fraction(-11, 2), Fraction(-7, 3)), (-1, Fraction(1, 3))], 0),
]


#: the invariants checked along a motion and at its instants (I5, a planned path passing
#: near a robot, fires at the first configuration's Look, before any stop)
MOTION = frozenset({"I1", "I3", "I4", "I6", "I9"})


def _looked(points, i, checker=None):
    world = World(points, checker=checker)
    world.look(i, IDENTITY)
    assert world.robots[i].busy
    return world


def _irrational_stops(world, i):
    return [s for s in stop_fractions(world, i) if isinstance(s, dict)]


@pytest.mark.parametrize("points,i", IRRATIONAL)
def test_an_irrational_stop_is_a_critical_instant_and_not_rational(points, i):
    world = _looked(points, i)
    stops = _irrational_stops(world, i)
    assert stops
    for stop in stops:
        value = resolve(world, [i], stop)
        assert not value.is_rational()
        root = motion_roots(world, [i])[stop["instant"]]
        assert (value - root.exact).is_zero()
        assert Fraction(stop["lo"]) < float(stop["value"]) < Fraction(stop["hi"])


@pytest.mark.parametrize("points,i", IRRATIONAL)
def test_replay_of_a_trace_with_an_irrational_stop_reproduces_the_state(points, i):
    world = _looked(points, i)
    stop = _irrational_stops(world, i)[0]
    piece = world.robots[i].path[0]
    where = piece.at(resolve(world, [i], stop))
    actions = [{"a": "look", "robot": i, "frame": IDENTITY.as_list()},
               {"a": "advance", "robot": i, "stop": stop, "end": False}]
    settings = {"readings": {}, "invariants": sorted(MOTION), "rigid": True}
    res = run(points, max_events=10, actions=actions, checker=Checker(enabled=MOTION))
    assert res.outcome == "stopped" and res.actions == actions
    # through JSON, as a trace file holds it
    data = json.loads(json.dumps(trace_dict(points, res, settings)))
    again = replay(data)
    assert same_result(data["result"], again) == []
    for r in (res, again):
        moved = [s for s in r.log if s.kind == "advance"]
        assert point_key(moved[-1].pieces[0].final) == point_key(where)
        assert not all(x.is_rational() for x in where)       # an irrational point


@pytest.mark.parametrize("points,i", IRRATIONAL)
def test_a_translated_start_offers_the_same_irrational_stops(points, i):
    """Metamorphic: the instants are parameters of the motion; a translation by a
    rational vector changes none of them."""
    moved = [(x + Fraction(7, 3), y - 5) for x, y in points]
    assert stop_fractions(_looked(moved, i), i) == stop_fractions(_looked(points, i), i)


def test_a_stop_whose_interval_does_not_hold_the_instant_is_refused():
    points, i = IRRATIONAL[0]
    world = _looked(points, i)
    stop = dict(_irrational_stops(world, i)[0])
    stop["lo"], stop["hi"] = stop["hi"], "1"
    with pytest.raises(ValueError):
        resolve(world, [i], stop)
    bad = [{"a": "look", "robot": i, "frame": IDENTITY.as_list()},
           {"a": "advance", "robot": i, "stop": stop, "end": False}]
    with pytest.raises(TraceMismatch):
        run(points, max_events=10, actions=bad, checker=Checker(enabled=MOTION))


def _verdict(points, i, enabled, stop=None):
    """The invariant a Look of robot ``i``, a stop and the rest of its move violate (None:
    none), and where the robot ends."""
    world = _looked(points, i, Checker(enabled=enabled))
    try:
        if stop is not None:
            assert apply_action(world, {"a": "advance", "robot": i, "stop": stop,
                                        "end": False})
        while world.robots[i].busy:
            world.advance(i)
    except Violation as v:
        return v.invariant, None
    return None, point_key(world.robots[i].pos)


@pytest.mark.parametrize("enabled", [MOTION - {"I1"}, MOTION])
@pytest.mark.parametrize("points,i", IRRATIONAL)
def test_irrational_stops_raise_no_violation_by_themselves(points, i, enabled):
    """Property: a stop -- at an irrational critical instant, or any other the adversary
    offers -- changes no verdict: the move stopped there and then completed violates
    what the whole move violates, and nothing when the whole move is legal (here with
    the invariants checked at the instants: it is; with I1 too: the move grazes a robot,
    and so does the stopped one)."""
    full = _verdict(points, i, enabled)
    assert (full[0] is None) == ("I1" not in enabled)
    stops = stop_fractions(_looked(points, i), i)
    assert any(isinstance(s, dict) for s in stops)
    for stop in stops:
        assert _verdict(points, i, enabled, stop) == full, stop


def test_simplest_between():
    assert simplest_between(Fraction(1, 3), Fraction(1, 2)) == Fraction(2, 5)
    assert simplest_between(Fraction(0), Fraction(1, 3)) == Fraction(1, 4)
    assert simplest_between(Fraction(3, 10), Fraction(4, 10)) == Fraction(1, 3)
    assert simplest_between(Fraction(2), Fraction(7, 2)) == Fraction(3)
    for a, b in ((Fraction(15059, 32768), Fraction(481891, 1048576)),
                 (Fraction(1, 1000), Fraction(2, 1000))):
        q = simplest_between(a, b)
        assert a < q < b
        assert all(not (a < Fraction(p, d) < b) for d in range(1, q.denominator)
                   for p in range(d + 1))


def test_a_schedule_names_an_exact_stop_readably():
    points, i = IRRATIONAL[0]
    stop = _irrational_stops(_looked(points, i), i)[0]
    lines = schedule_lines([{"a": "advance", "robot": i, "stop": stop, "end": False}])
    assert f"robot {i} moves to critical instant {stop['instant']} of its motion" in lines[0]
    assert stop["value"] in lines[0] and "{" not in lines[0]
