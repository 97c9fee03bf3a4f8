""""Stalled" is proved or not said (issue 30, point 5): a run is stalled when no robot
plans a move in any frame (the world's and the reflected one stand for all frames), or
when an exact state repeats after every robot acted (a fair cycle); otherwise, past the
budget, the outcome is "undecided-at-budget"."""

import re
from dataclasses import replace
from fractions import Fraction as F
from pathlib import Path

import pytest

from exactsym.gathering.cases import read_case, run_settings, settings_of
from exactsym.gathering.robot import Readings
from exactsym.gathering.schedulers import no_mover_in_any_frame, run
from exactsym.gathering.world import Frame, World

CASES = Path(__file__).resolve().parents[2] / "cases" / "gathering"
# hand-made obstacle configurations whose obstacle shows under A3=all; under the
# default A3=first each ran into Make_SymToAsym's loop and was called "stalled" by a
# count of moves without growth
A3_ALL_OBSTACLES = ["obstacle-beside-path", "obstacle-beyond-destination",
                    "radial-arrival-overlaps-layer", "slide-fresh-look-elects-another",
                    "stale-look-targets-old-centre"]


def replayed_states(points, actions, readings):
    """``{event: state key}`` after every action that leaves nobody busy, and the
    robots acting at each event, replayed without the checker."""
    w = World(points, readings)
    states, actors = {0: w.state_key()}, {}
    for act in actions:
        if act["a"] == "look":
            w.look(act["robot"], Frame.from_list(act["frame"]))
            who = {act["robot"]}
        elif act["a"] == "advance":
            stop = act.get("stop")
            w.advance(act["robot"], None if stop is None else F(stop), act.get("end", False))
            who = {act["robot"]}
        else:
            w.advance_together([(i, None if s is None else F(s), e)
                                for i, s, e in act["moves"]])
            who = {m[0] for m in act["moves"]}
        actors[w.events] = who
        if not w.busy():
            states[w.events] = w.state_key()
    return states, actors


@pytest.mark.parametrize("name", A3_ALL_OBSTACLES)
def test_default_reading_loops_are_proved_cycles(name):
    """Each case's own setting, with A3=first instead of A3=all."""
    points, _name, expect, _src = read_case(CASES / f"{name}.toml")
    first = [r for r in expect["gather_readings"] if not r.startswith("A3=")]
    settings = settings_of({**expect, "gather_readings": first})
    res = run_settings(points, settings)
    assert res.outcome in ("stalled", "undecided-at-budget"), res.detail
    if res.outcome == "undecided-at-budget":
        return
    m = re.search(r"state after event (\d+) is exactly the state after event (\d+)",
                  res.detail)
    assert m, res.detail
    later, earlier = int(m.group(1)), int(m.group(2))
    states, actors = replayed_states(points, res.actions, Readings(**settings["readings"]))
    assert states[later] is not None and states[later] == states[earlier]
    acted = set().union(*(actors[e] for e in range(earlier + 1, later + 1)))
    assert acted == set(range(len(points)))


def test_without_a_cycle_a_loop_is_undecided_at_budget(monkeypatch):
    """The same loop with cycle detection off: a count of moves without growth proves
    nothing, and the run says so."""
    monkeypatch.setattr(World, "state_key", lambda self: None)
    points, _name, _expect, _src = read_case(CASES / "make-sym-to-asym-livelock.toml")
    res = run(points, "centralised", 1, Readings(), max_events=400)
    assert res.outcome == "undecided-at-budget", res.detail
    assert "no state repeated" in res.detail


def test_a_move_in_the_reflected_frame_is_no_stall(monkeypatch):
    """Handedness-dependent rules: the world's frame plans nothing, the reflected one a
    move.  Not stalled (before: "stalled" from the world's frame alone)."""
    points = [(F(x), F(y)) for x, y in [(3, 0), (0, 5), (-7, 0), (0, -9), (4, 4)]]
    w = World(points, Readings())
    real = World.fresh_decision

    def one_handed(self, frame):
        d = real(self, frame)
        status = "move" if frame.reflect else "stay"
        return replace(d, status=status)

    monkeypatch.setattr(World, "fresh_decision", one_handed)
    assert no_mover_in_any_frame(w) is None
    monkeypatch.setattr(World, "fresh_decision",
                        lambda self, frame: replace(real(self, frame), status="stay"))
    assert no_mover_in_any_frame(w)[0] == "stalled"
