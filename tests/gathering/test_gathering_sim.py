"""The gathering simulator: the robot function, the world, each invariant firing and
holding, traces and replay, the command line."""

import json
from fractions import Fraction as F

import pytest

from exactsym.gathering import geometry as g
from exactsym.gathering.cli import main
from exactsym.gathering.invariants import ALL, Checker, Violation
from exactsym.gathering.pattern import generate
from exactsym.gathering.robot import Readings, compute, decide
from exactsym.gathering.schedulers import run
from exactsym.gathering.trace import read_trace, replay, same_result, write_trace
from exactsym.gathering.world import IDENTITY, MIRROR, Frame, World

# five robots on the circle of radius 20: G' is asymmetric, one level
ONE_CIRCLE = [(20, 0), (0, 20), (-20, 0), (0, -20), (12, 16)]
OBSTACLE = [(F(3, 2), 0), (F(-9, 5), 0), (8, 6), (-6, 8), (0, -10)]
ALL_ON = frozenset(ALL)


def only(*keys):
    return Checker(enabled=frozenset(keys))


def world(points, checker=None, readings=Readings(), **kw):
    return World(points, readings, checker=checker or Checker(), **kw)


# -- the robot function ---------------------------------------------------------------
def test_compute_is_frame_covariant_for_leader_moves():
    """A rotation + scale + translation frame (no reflection) gives the same world path."""
    w = world(ONE_CIRCLE)
    fr = Frame(F(3, 5) * 2, F(4, 5) * 2, False, F(7), F(-1, 3))
    d0, p0 = w.snapshot_decision(IDENTITY)
    d1, p1 = w.snapshot_decision(fr)
    assert d0.leader == d1.leader == 3
    assert p0 == p1 and p0[3][-1].final == g.point(0, 0)
    local = tuple(fr.to_local(p) for p in w.positions())
    assert compute(local, 3, unit=2) is not None and compute(local, 0, unit=2) is None


def test_paper_leader_depends_on_handedness():
    """The paper layer's Elect_Leader_Asym reads its strings in the observer's own
    handedness: the mirror image elects another robot (spec section 6, last bullet)."""
    w = world(ONE_CIRCLE)
    assert w.snapshot_decision(IDENTITY)[0].leader == 3
    assert w.snapshot_decision(MIRROR)[0].leader == 2


def test_form_pattern_paths():
    from exactsym.gathering.pattern import recognise
    from exactsym.gathering.robot import form_pattern_path
    c = g.point(0, 0)
    pts = tuple(generate(2)) + (g.point(3, -20),)
    pat = recognise(pts, c)
    assert pat.robots == frozenset({0, 1})
    path = form_pattern_path(pts[2], pts, pat, c, Readings())
    # radially to radius 2, then an arc about C to the slot next to the chain's end
    assert isinstance(path[0], g.Segment) and g.dist2(path[0].end, c) == 4
    assert all(isinstance(p, g.Arc) and p.sense == 1 for p in path[1:])
    end = path[-1].final
    assert g.dist2(end, c) == 4 and g.dist2(end, pts[1]) == 4 and end[1].sign() < 0
    straight = form_pattern_path(pts[2], pts, pat, c, Readings(A5="straight"))
    assert len(straight) == 1 and straight[0].end == end
    bent = form_pattern_path(pts[2], pts, pat, c, Readings(A5="arc-radial"))
    assert isinstance(bent[-1], g.Segment) and bent[-1].end == end
    # C free: straight to C; the last layer full: radially to the next layer
    assert form_pattern_path(pts[2], pts[1:], recognise(pts[1:], c), c, Readings()) == \
        [g.Segment(pts[2], c)]
    full = tuple(generate(7)) + (g.point(3, -20),)
    out = form_pattern_path(full[7], full, recognise(full, c), c, Readings())
    assert len(out) == 1 and g.dist2(out[0].end, c) == 16


def test_not_possible_and_terminated():
    square = [(20, 0), (0, 20), (-20, 0), (0, -20), (0, 0)]
    assert decide(tuple(g.point(*p) for p in square), Readings()).status == "not-possible"
    assert decide(tuple(generate(7)), Readings()).status == "terminated"
    # A1 = SEC of all robots: a complete pattern of 9 is not centred on its SEC, so the
    # robots do not recognise it and keep moving (the destination is not invariant)
    assert decide(tuple(generate(9)), Readings()).status != "terminated"
    res = run(square, "centralised", max_events=50)
    assert res.outcome == "not-possible"


def test_readings_parse():
    assert Readings.parse(["A3=all", "A5=straight"]).A5 == "straight"
    with pytest.raises(ValueError):
        Readings.parse(["A3=sometimes"])


# -- the invariants: each fires once and holds once -----------------------------------
def test_I1_fires_and_holds():
    w = world([(0, 0), (5, 1), (20, 0), (0, 20), (-20, 0)], only("I1"))
    rob = w.robots[0]
    rob.path, rob.start = [g.Segment(rob.pos, g.point(10, 0))], rob.pos
    with pytest.raises(Violation) as err:
        w.advance(0)
    assert err.value.invariant == "I1" and err.value.robots == (0, 1)
    w = world([(0, 0), (5, 2), (20, 0), (0, 20), (-20, 0)], only("I1"))
    rob = w.robots[0]
    rob.path, rob.start = [g.Segment(rob.pos, g.point(10, 0))], rob.pos
    w.advance(0)                       # touching at (5, 0) is allowed
    assert w.checker.counts["I1"] == 1


def test_I2_fires_and_holds():
    w = world(ONE_CIRCLE, only("I2"))
    w.look(3, IDENTITY)
    w.look(1, IDENTITY)                # same handedness: robot 1 stays
    with pytest.raises(Violation) as err:
        w.look(2, MIRROR)              # other handedness: robot 2 is its leader
    assert err.value.invariant == "I2" and err.value.label == "lem-vl-move"
    assert set(err.value.robots) == {2, 3}


def test_I3_fires_and_holds():
    w = world(ONE_CIRCLE, only("I3"), Readings(A3="all"))
    w.look(3, IDENTITY)
    w.advance(3, F(1, 2))              # a fresh Look mid-way: same mover, same target C
    assert w.checker.counts["I3"] == 1
    # the 7-robot run: a robot sliding on layer 1 is, for a fresh Look, a second lone
    # robot of layer 1: the recogniser cannot tell which one is in P, another is elected
    pts = [(30, 0), (0, 31), (-33, 2), (5, -34), (21, 22), (-20, -23), (-9, 17)]
    res = run(pts, "centralised", 1, Readings(A3="all"), checker=only("I3"))
    assert res.violation["invariant"] == "I3" and res.violation["robots"] == [0, 5]


def test_I4_fires_and_holds():
    w = world(ONE_CIRCLE, only("I4"))
    w.look(3, IDENTITY)                # tied with every robot at the Look: allowed
    w.advance(3, F(1, 4))              # strictly nearest once moving
    assert w.checker.counts["I4"] == 2
    rob = w.robots[3]
    rob.path = [g.Segment(rob.pos, g.point(0, -30))]    # the adversary's own detour
    with pytest.raises(Violation) as err:
        w.advance(3)
    assert err.value.invariant == "I4" and err.value.label == "gather-min-distance"


def test_I5_fires_and_holds():
    res = run(OBSTACLE, "centralised", 1, Readings(A3="all"), checker=only("I5"))
    assert res.violation["invariant"] == "I5" and res.violation["robots"] == [0, 1]
    w = world(ONE_CIRCLE, only("I5"))
    w.look(3, IDENTITY)
    assert w.checker.counts["I5"] == 1


def test_I6_fires_and_holds():
    def P(t, r=20):
        cs, sn = (1 - t * t) / (1 + t * t), 2 * t / (1 + t * t)
        return (r * cs, r * sn)
    pts = [P(F(0)), P(F(1, 11)), P(F(1, 6)), P(F(4, 15)), (-20, 0)]
    w = world(pts, only("I6"))
    rob = w.robots[0]                 # the 0-degree robot leaves the SEC towards C
    rob.path, rob.role, rob.centre, rob.start = [g.Segment(rob.pos, g.point(0, 0))], \
        "leader", g.point(0, 0), rob.pos
    with pytest.raises(Violation) as err:
        w.advance(0, F(1, 2))
    assert err.value.invariant == "I6" and err.value.label == "conclusion (L1708-1710)"  # a leader move
    w = world(ONE_CIRCLE, only("I6"))
    w.look(3, IDENTITY)
    w.advance(3, F(1, 2))             # (20,0), (-20,0) keep the SEC
    # the piece's end, and every Look at or between its critical instants
    assert w.checker.counts["I6"] == 1 + w.checker.counts["instants"] >= 2


def test_I7_fires_and_holds():
    w = world(ONE_CIRCLE, only("I7"))
    w.checker.in_pattern.add(3)
    with pytest.raises(Violation) as err:
        w.look(3, IDENTITY)
    assert err.value.invariant == "I7"
    w = world(ONE_CIRCLE, only("I7"))
    w.look(3, IDENTITY)
    assert w.checker.counts["I7"] == 1


def test_I8_fires_and_holds():
    w = world(ONE_CIRCLE, only("I8"))
    w.look(3, IDENTITY)
    w.advance(3)                      # arrives at C: pattern {3}, valid
    assert w.checker.counts["I8"] == 1
    w.checker.in_pattern.add(0)       # pretend robot 0 had been in the pattern
    rob = w.robots[1]
    rob.path, rob.role, rob.centre, rob.start = [g.Segment(rob.pos, g.point(0, 19))], \
        "Make_SymToAsym", g.point(0, 0), rob.pos
    with pytest.raises(Violation) as err:
        w.advance(1)
    assert err.value.invariant == "I8" and err.value.robots == (0,)


def test_I9_fires_and_holds():
    w = world(ONE_CIRCLE, only("I9"))
    with pytest.raises(Violation) as err:
        w.look(3, Frame(F(3, 5), F(4, 5)))
    assert err.value.invariant == "I9" and err.value.label == "no chirality (L210-214)"
    w = world(OBSTACLE, only("I9"))   # Make_SymToAsym's mover is the same in every frame
    w.look(0, Frame(F(3, 5), F(4, 5), True))
    assert w.checker.counts["I9"] == 1


def test_I10_fires_and_holds():
    w = world(ONE_CIRCLE, only("I10"))
    w.look(3, IDENTITY)
    w.advance(3)
    assert w.checker.counts["I10"] == 1
    w = world(ONE_CIRCLE, only("I10"))
    w.look(3, IDENTITY)
    w.robots[3].path = [g.Segment(w.robots[3].pos, g.point(0, -5))]   # stops short of C
    with pytest.raises(Violation) as err:
        w.advance(3)
    assert err.value.invariant == "I10"


# -- runs, traces, replay ---------------------------------------------------------------
def test_default_reading_livelocks_on_a_single_vertex_G1():
    """A3=first: Make_SymToAsym's epsilon move of the single-vertex G_1 comes first in
    every cycle; the pattern never grows: the mover turns back and forth until the
    state repeats exactly, every robot having acted (a proved cycle)."""
    res = run(OBSTACLE, "centralised", 1, max_events=400)
    assert res.outcome == "stalled" and "a cycle" in res.detail


@pytest.mark.parametrize("scheduler", ["centralised", "fsync", "ssync", "async"])
def test_schedulers_run_and_replay_exactly(scheduler, tmp_path):
    settings = {"scheduler": scheduler, "seed": 3, "readings": Readings(A3="all").as_dict(),
                "invariants": list(ALL), "max_events": 60, "rigid": False, "delta": "1"}
    res = run(ONE_CIRCLE, scheduler, 3, Readings(A3="all"), rigid=False, delta=F(1),
              max_events=60)
    assert res.events > 0 and res.actions
    path = tmp_path / "t.json"
    write_trace(path, ONE_CIRCLE, res, settings)
    data = read_trace(path)
    again = replay(data)
    assert same_result(data["result"], again) == []
    assert again.actions == res.actions


def test_replay_detects_a_changed_trace(tmp_path):
    res = run(ONE_CIRCLE, "async", 2, max_events=40, checker=Checker(enabled=ALL_ON - {"I9"}))
    path = tmp_path / "t.json"
    write_trace(path, ONE_CIRCLE, res, {"scheduler": "async", "seed": 2, "readings": {},
                                        "invariants": sorted(ALL_ON - {"I9"})})
    data = json.loads(path.read_text())
    data["points"][4] = ["12", "-16"]
    path.write_text(json.dumps(data))
    assert main(["replay", str(path)]) in (1, 2)


def _case(tmp_path, points, expect=""):
    body = "format = 1\npoints = [\n" + "".join(f'  ["{x}", "{y}"],\n' for x, y in points) + \
        "]\n" + (f"\n[expect]\n{expect}\n" if expect else "")
    path = tmp_path / "c.toml"
    path.write_text(body)
    return path


def test_cli_gather_and_replay(tmp_path, capsys):
    case = _case(tmp_path, OBSTACLE, 'gather_outcome = "violated"\ngather_robots = [0, 1]\n'
                 'gather_readings = ["A3=all"]\ngather_scheduler = "centralised"')
    trace = tmp_path / "run.json"
    assert main(["gather", str(case), "--trace", str(trace), "--seed", "1"]) == 0
    out = capsys.readouterr().out
    assert "outcome: violated (gather-no-obstacle)" in out and "robots [0, 1]" in out
    assert main(["replay", str(trace), str(case)]) == 0
    assert "identical to the recorded run" in capsys.readouterr().out
    assert main(["gather", str(case), "--json", "--reading", "A3=first",
                 "--max-events", "50"]) == 1          # the expectation is false then
    data = json.loads(capsys.readouterr().out)
    assert data["outcome"] in ("stalled", "max-events") and data["expect_failures"]


@pytest.mark.parametrize("points, message", [
    ([(0, 0), (10, 0), (0, 10), (-10, 0)], "at least 5 robots"),
    ([(0, 0), (2, 0), (0, 10), (-10, 0), (0, -10)], "overlap or touch"),
])
def test_cli_bad_input(tmp_path, capsys, points, message):
    assert main(["gather", str(_case(tmp_path, points))]) == 2
    err = capsys.readouterr().err
    assert message in err and err.count("\n") == 1


def test_cli_bad_options_and_trace(tmp_path, capsys):
    case = _case(tmp_path, ONE_CIRCLE)
    assert main(["gather", str(case), "--reading", "A9=x"]) == 2
    assert main(["gather", str(case), "--invariants", "I11"]) == 2
    bad = tmp_path / "bad.json"
    bad.write_text("{}")
    assert main(["replay", str(bad)]) == 2
    trace = tmp_path / "t.json"
    assert main(["gather", str(case), "--max-events", "5", "--trace", str(trace)]) == 0
    other = _case(tmp_path, OBSTACLE)
    assert main(["replay", str(trace), str(other)]) == 2
    assert "other starting points" in capsys.readouterr().err


def test_search_finds_a_shortest_violation():
    from exactsym.gathering.search import exhaustive, search_violation
    settings = {"readings": Readings().as_dict(), "invariants": sorted(ALL_ON - {"I9"}),
                "rigid": True, "delta": None, "max_events": 50}
    found = exhaustive(ONE_CIRCLE, settings, max_depth=4)
    assert [a["a"] for a in found] == ["look", "look"]          # two Looks, two handednesses
    assert {a["robot"] for a in found} == {2, 3}
    assert exhaustive(ONE_CIRCLE, settings, max_depth=1) is None  # one action never suffices
    res = search_violation(ONE_CIRCLE, settings, max_depth=4)
    assert res.violation["invariant"] == "I2" and res.events == 2


@pytest.mark.parametrize("k", [3, 7, 10])
@pytest.mark.parametrize("readings", [Readings(), Readings(A3="all", EL="unordered"),
                                      Readings(A1="sec-r")])
def test_two_robots_left_is_not_possible(k, readings):
    """Once R has two robots left (a complete pattern of k robots about the SEC centre),
    G' is two points, always symmetric: GatheringPattern reports 'not possible' whatever
    the reading, so the literal algorithm never gathers (the conclusion's claim)."""
    pts = tuple(generate(k)) + (g.point(30, 1), g.point(-30, -1))
    d = decide(pts, readings)
    assert d.pattern.robots == frozenset(range(k)) and d.status == "not-possible"


def test_unordered_reading_rescues_handedness():
    w = world(ONE_CIRCLE, readings=Readings(EL="unordered"))
    assert w.snapshot_decision(IDENTITY)[0].leader == w.snapshot_decision(MIRROR)[0].leader


@pytest.mark.parametrize("case", [OBSTACLE, ONE_CIRCLE])
def test_runs_are_invariant_under_an_exact_similarity(case):
    """Rotating (Pythagorean), scaling by 1 and translating the input changes no outcome,
    event count or violation: every Look is made in a frame anyway."""
    c, s = F(3, 5), F(4, 5)
    moved = [(c * x - s * y + 7, s * x + c * y - F(1, 3)) for x, y in case]
    for readings in (Readings(), Readings(A3="all")):
        a = run(case, "async", 5, readings, max_events=60, reflections=False)
        b = run(moved, "async", 5, readings, max_events=60, reflections=False)
        assert (a.outcome, a.events, a.looks, a.label) == (b.outcome, b.events, b.looks, b.label)
        assert (a.violation or {}).get("robots") == (b.violation or {}).get("robots")


def test_slide_direction_nearer_end_and_inside_the_chain_arc():
    from exactsym.gathering.pattern import recognise
    from exactsym.gathering.robot import form_pattern_path
    c = g.point(0, 0)
    base = tuple(generate(2))            # centre and one robot at (2, 0)
    # from about 100 degrees: the ccw end's slot (60 degrees) is nearer, clockwise
    p = g.point(-3, 17)
    path = form_pattern_path(p, base + (p,), recognise(base + (p,), c), c, Readings())
    assert path[-1].sense == -1 and path[-1].final[1].sign() > 0
    # from about 30 degrees: the radial arrival lies between the robot and its slot: the
    # short way, counter-clockwise to the 60-degree slot (and the plan overlaps: I5)
    p = g.point(17, 10)
    path = form_pattern_path(p, base + (p,), recognise(base + (p,), c), c, Readings())
    assert len(path) == 2 and path[-1].sense == 1 and path[-1].final[1].sign() > 0
    assert g.piece_hits(path[0], base[1])


def test_critical_points_of_a_segment_and_an_arc():
    from exactsym.exact.multiquadratic import MQ, sqrt_rational
    from exactsym.gathering.invariants import critical_points
    w = world([(10, -10), (0, 12), (20, 0), (-20, 0), (0, -20)])
    seg = g.Segment(g.point(10, -10), g.point(-10, -10))
    pts = {str(p[0]): p for _, p in critical_points(seg, g.point(0, 0), w, 0)}
    # on the line through C and robot 1: x = 0; as far from C as robot 1: x = +-sqrt(44)
    assert g.point(0, -10) in pts.values()
    assert (2 * sqrt_rational(11), MQ.rational(-10)) in pts.values()
    assert (-2 * sqrt_rational(11), MQ.rational(-10)) in pts.values()
    arc = g.Arc(g.point(0, 0), g.point(5, 0), g.point(0, 5), 1)
    crossings = [p for _, p in critical_points(arc, g.point(0, 0), world(
        [(5, 0), (8, 8), (0, -9), (-30, 1), (30, 2)]), 0)]
    r = sqrt_rational(F(25, 2))
    assert (r, r) in crossings and len(crossings) == 2      # robots 1 and 4 (3.8 degrees)


def test_a_complete_pattern_is_gathered():
    res = run(generate(7), "async", 0, max_events=20)
    assert res.outcome == "gathered" and res.events == 0
    assert res.pattern["size"] == 7 and res.pattern["layers"] == [[1, 2, 3, 4, 5, 6]]


#: two antipodal robots on the SEC (G_t, |G_t| = 2) and an asymmetric G_{t-1} of three
#: robots on the circle of radius 5: MakeAsym moves a G_{t-1} robot radially out to
#: G_t's circle (L1526), the second case of lem-vl-move
TO_GT_CIRCLE = [(20, 0), (-20, 0), (3, 4), (-5, 0), (4, -3)]


def test_I3_of_a_move_to_G_t_circle_is_named_lem_vl_move():
    from exactsym.gathering.invariants import i3_label
    assert i3_label("MakeAsym", "to-G_t-circle") == "lem-vl-move"
    assert i3_label("MakeAsym", "epsilon") == "obs-v-move"
    assert i3_label("Make_SymToAsym", "epsilon") == "obs-v-move"
    assert i3_label("leader") == "FormGPattern (L1642-1643)"
    # holds: robot 2 Looks, moves to (12, 16); fresh Looks on the way name it again
    w = world(TO_GT_CIRCLE, only("I3"))
    d = w.look(2, IDENTITY)
    assert d.move_of(2).kind == "to-G_t-circle" and w.robots[2].kind == "to-G_t-circle"
    assert w.robots[2].target == g.point(12, 16)
    w.advance(2, F(1, 2))
    w.advance(2)
    assert w.checker.counts["I3"] == 2 and w.robots[2].kind == "" and not w.busy()
    # fires: under ASYNC (I2, I9 off) a fresh Look with robot 2 part-way elects robot 3
    # through ElectLeader (Make_SymToAsym)
    res = run(TO_GT_CIRCLE, "async", 1, checker=Checker(enabled=ALL_ON - {"I2", "I9"}),
              max_events=40)
    v = res.violation
    assert v["invariant"] == "I3" and v["label"] == "lem-vl-move" and v["robots"] == [2, 3]
    assert "robot 2 is on its way to (12, 16)" in v["witness"]
