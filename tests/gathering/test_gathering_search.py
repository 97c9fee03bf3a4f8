"""The adversary search (issue 30): exact de-duplication across copied towers, the
search's flags and schedules, shrinking, traces that replay."""

from __future__ import annotations

import copy
from fractions import Fraction
from pathlib import Path

import pytest

from exactsym.exact.multiquadratic import MQ, sqrt_rational
from exactsym.gathering.adversary import FRAMES, children, stop_fractions
from exactsym.gathering.cli import main
from exactsym.gathering.invariants import ALL, Checker
from exactsym.gathering.schedulers import run
from exactsym.gathering.search import Bounds, search
from exactsym.gathering.search import exhaustive
from exactsym.gathering.shrink import replay_actions, shrink
from exactsym.gathering.robot import Readings
from exactsym.gathering.state_key import number_key, state_key
from exactsym.gathering.stops import exact_instant, motion_roots, resolve
from exactsym.gathering.world import IDENTITY, World

Q = MQ.rational
S2 = sqrt_rational(2)
#: robot 4 at (1 + sqrt 2, 7): its radial target is a nested radical, in the run's tower
NESTED = ((Q(0), Q(0)), (Q(25), Q(0)), (Q(-7), Q(24)), (Q(0), Q(-25)), (1 + S2, Q(7)),
          (Q(10), Q(3)), (Q(-9), Q(5)))


def _tower_world():
    world = World(NESTED, Readings(A3="all"))
    world.look(4, IDENTITY)
    while world.robots[4].busy:
        world.advance(4)
    return world


def test_states_of_two_copied_towers_get_equal_keys_without_comparing_numbers():
    world = _tower_world()
    a, b = copy.deepcopy(world), copy.deepcopy(world)
    assert a.home.tower is not b.home.tower
    with pytest.raises(ValueError):           # why the old key (raw positions) crashed
        assert {tuple(r.pos for r in a.robots)} and \
            tuple(r.pos for r in b.robots) in {tuple(r.pos for r in a.robots)}
    assert state_key(a) == state_key(b) and hash(state_key(a)) == hash(state_key(b))
    assert state_key(a) in {state_key(b)}
    b.look(6, IDENTITY)                       # a different state: a different key
    assert state_key(a) != state_key(b)


def test_number_keys_are_exact():
    assert number_key(Q(1) + S2) == number_key(S2 + 1)
    assert number_key(Q(1) + S2) != number_key(Q(1) - S2)
    assert number_key(Q(1) / 3) != number_key(Q(1) / 3 + Q(1) / 10 ** 40)


@pytest.mark.parametrize("algorithm", ["corrected", "paper"])
def test_search_over_a_nested_radical_run_does_not_crash(algorithm):
    """issue 30: ``gather --algorithm corrected --search --invariants I1,I5`` exited 3,
    "numbers of two different towers cannot be compared here"."""
    settings = {"readings": Readings(A3="all").as_dict(), "invariants": ["I1", "I5"],
                "rigid": True, "delta": None, "max_events": 50, "algorithm": algorithm}
    assert exhaustive(NESTED, settings, max_depth=3, max_nodes=120) is None


# -- the searching adversary ---------------------------------------------------------------
CASES = Path(__file__).resolve().parents[2] / "cases" / "gathering"
TWO_MOVERS = CASES / "handedness-two-movers-collide.toml"
ONE_CIRCLE = [(20, 0), (0, 20), (-20, 0), (0, -20), (12, 16)]
#: two leaders of opposite handedness collide when they move at once
COLLIDE = {"readings": Readings().as_dict(), "invariants": sorted(set(ALL) - {"I2", "I9"}),
           "rigid": True, "delta": None, "max_events": 50, "algorithm": "paper",
           "scheduler": "async", "seed": 0}


def test_stops_are_at_and_between_the_critical_instants_of_the_motion():
    world = World(ONE_CIRCLE)
    world.look(3, IDENTITY)                  # robot 3 is the leader in the plain frame
    stops = stop_fractions(world, 3)
    roots = motion_roots(world, [3])
    assert roots and len(stops) >= 2                            # not only half way
    values = [MQ.coerce(resolve(world, [3], s)) for s in stops]
    assert values[0].sign() > 0 and (values[-1] - 1).sign() < 0
    assert all((b - a).sign() > 0 for a, b in zip(values, values[1:]))     # in order
    # one stop in each stretch between consecutive instants, and each held instant
    piece = world.robots[3].path[0]
    held = [x for x in (exact_instant(r, [piece]) for r in roots) if x is not None]
    assert held and all(any((v - x).is_zero() for v in values) for x in held)
    cuts = [MQ.rational(0)] + [MQ.coerce(x) for x in held] + [MQ.rational(1)]
    for a, b in zip(cuts, cuts[1:]):
        inside = [v for v in values if (v - a).sign() > 0 and (v - b).sign() < 0]
        assert len(inside) == 1
    acts = list(children(world))
    assert [a["stop"] for a in acts if a["a"] == "advance"] == [None] + stops
    looks = [a for a in acts if a["a"] == "look"]
    assert {a["frame"][2] for a in looks} == {False, True}      # both handednesses
    assert len(looks) == len(FRAMES) * (world.n - 1)


def test_joint_steps_stop_at_the_joint_instants():
    world = World(ONE_CIRCLE, checker=None)
    world.look(3, IDENTITY)
    world.look(2, FRAMES[1])                 # robot 2 in the mirrored frame
    steps = [a for a in children(world) if a["a"] == "step"]
    assert steps and {m[0] for a in steps for m in a["moves"]} == {2, 3}
    assert len({str(a["moves"][0][1]) for a in steps}) >= 2     # the end and inner stops


def test_the_search_finds_shrinks_and_replays_the_collision():
    rep = search(ONE_CIRCLE, COLLIDE, Bounds(budget=400, depth=4, seed=3))
    assert rep.stopped == "violation" and rep.result.violation["invariant"] == "I1"
    assert [a["a"] for a in rep.actions] == ["look", "look", "step"]
    assert rep.states <= 400 and rep.found_length >= len(rep.actions)
    again = replay_actions(ONE_CIRCLE, COLLIDE, rep.actions)
    assert again.violation == rep.result.violation


def test_the_search_is_deterministic_for_a_seed_and_keeps_its_bounds():
    a = search(ONE_CIRCLE, COLLIDE, Bounds(budget=300, depth=4, seed=7))
    b = search(ONE_CIRCLE, COLLIDE, Bounds(budget=300, depth=4, seed=7))
    assert a.actions == b.actions and a.states == b.states
    short = search(ONE_CIRCLE, COLLIDE, Bounds(budget=5000, depth=2))
    assert short.actions is None and short.stopped == "exhausted" and short.depth <= 2
    small = search(ONE_CIRCLE, COLLIDE, Bounds(budget=6, depth=4))
    assert small.actions is None and small.stopped == "budget" and small.states <= 6


def test_shrinking_drops_the_actions_the_violation_does_not_need():
    noise = [{"a": "look", "robot": 2, "frame": IDENTITY.as_list()},
             {"a": "advance", "robot": 2, "stop": "1/4", "end": False}]
    rep = search(ONE_CIRCLE, COLLIDE, Bounds(budget=400, depth=4))
    # robot 0 Looks first and stays (it is not elected): an action the collision does
    # not need, kept by a replay but dropped by the shrinking
    padded = [{"a": "look", "robot": 0, "frame": IDENTITY.as_list()}] + rep.actions
    assert replay_actions(ONE_CIRCLE, COLLIDE, padded).outcome == "violated"
    shrunk, replays = shrink(ONE_CIRCLE, COLLIDE, padded)
    assert len(shrunk) == 3 and replays >= 2
    assert replay_actions(ONE_CIRCLE, COLLIDE, shrunk).violation["invariant"] == "I1"
    assert shrink(ONE_CIRCLE, COLLIDE, noise)[0] == noise       # no violation: unchanged


def test_a_long_seeded_violation_shrinks():
    settings = {**COLLIDE, "invariants": ["I1", "I3", "I4", "I5", "I6", "I7", "I8", "I10"]}
    res = run(ONE_CIRCLE, "ssync", 6, Readings(), True, None, 50,
              Checker(enabled=frozenset(settings["invariants"])))
    assert res.outcome == "violated"
    shrunk, _ = shrink(ONE_CIRCLE, settings, res.actions)
    assert len(shrunk) <= len(res.actions)
    assert replay_actions(ONE_CIRCLE, settings, shrunk).violation["invariant"] == \
        res.violation["invariant"]


def test_gather_search_flags_and_a_trace_that_replays(tmp_path, capsys):
    trace = tmp_path / "t.json"
    assert main(["gather", str(TWO_MOVERS), "--search", "--budget", "300", "--depth", "4",
                 "--seed", "2", "--time", "120", "--trace", str(trace)]) == 0
    out = capsys.readouterr().out
    assert "search: " in out and "shrunk to 3" in out and "  3. at once: robot" in out
    assert "violation: I1 no overlap (gather-no-obstacle)" in out
    assert main(["replay", str(trace), str(TWO_MOVERS)]) == 0
    assert "identical to the recorded run" in capsys.readouterr().out
    assert main(["gather", str(TWO_MOVERS), "--search", "--budget", "0"]) == 2


def test_the_best_first_phase_finds_what_a_small_breadth_first_share_misses():
    """Half of a budget of 200 states is not enough breadth-first (the collision is met
    after about 157): best-first on the badness score goes on and finds it."""
    rep = search(ONE_CIRCLE, COLLIDE, Bounds(budget=200, depth=4))
    assert rep.stopped == "violation" and rep.phase == "best-first"
    assert rep.result.violation["invariant"] == "I1"


def test_a_stop_at_a_nested_instant_of_a_rational_piece_stays_in_the_run_tower(capsys):
    """issue 31, R-C3 finding 9: a stop at a nested-radical instant of a piece with MQ
    ends was left in the instant's own one-level tower while another robot stood in the
    run's tower; the next fresh Look mixed the two ("elements of two different number
    fields do not mix", exit 3).  :meth:`.world.World.advance` re-homes both halves."""
    case = CASES / "corrected-roots-12-five-stall.toml"
    assert main(["gather", str(case), "--algorithm", "corrected", "--search",
                 "--budget", "300", "--time", "120"]) == 0
    out = capsys.readouterr().out
    assert "no violation found" in out and "internal error" not in out
