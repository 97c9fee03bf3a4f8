"""Pictures of simulated runs (exactsym.gathering.drawing): the path log drawn, the
violation's pair and instant, one frame per event, replay draws the same picture."""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

pytest.importorskip("matplotlib")

from exactsym.cli.main import main  # noqa: E402
from exactsym.gathering import drawing  # noqa: E402
from exactsym.gathering.cases import run_settings, settings_of  # noqa: E402
from exactsym.gathering.paper_bridge import read_case  # noqa: E402
from exactsym.gathering.schedulers import run  # noqa: E402
from exactsym.pictures.run import frame_times, plot_run  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
CASE = ROOT / "cases/gathering/obstacle-beside-path.toml"
NO_I5 = "I1,I2,I3,I4,I6,I7,I8,I9,I10"


def svg_ids(path) -> set:
    return {e.get("id") for e in ET.parse(path).getroot().iter() if e.get("id")}


def svg_text(path) -> str:
    return " ".join("".join(t.itertext()) for t in ET.parse(path).getroot().iter()
                    if t.tag.endswith("text"))


def case_run(invariants=None):
    points, _name, expect, _src = read_case(CASE)
    s = settings_of(expect)
    if invariants:
        s["invariants"] = invariants.split(",")
    return points, run_settings(points, s)


def test_the_log_holds_every_look_and_advance():
    points, res = case_run(NO_I5)
    assert [(st.kind, st.event) for st in res.log][-2:] == [("advance", 5), ("advance", 6)]
    assert sum(st.kind == "look" for st in res.log) == res.looks
    assert len(res.log) == res.events
    # the pieces chain: each advance starts where its robot was
    where = {i: p for i, p in enumerate(points)}
    for st in res.log:
        if st.kind == "advance":
            assert st.pieces[0].start == tuple(map(type(st.pieces[0].start[0]).coerce,
                                                   where[st.robot]))
            where[st.robot] = st.pieces[0].end


def test_planned_path_that_is_not_free_is_drawn_with_its_pair(tmp_path):
    """I5 (the default): the run stops at the Look; the picture shows the planned path
    (dashed), the pair 0 and 1 and the zoom on them."""
    points, res = case_run()
    assert res.violation["invariant"] == "I5"
    pic = drawing.run_picture(points, res, "case")
    assert pic.violation.robots == (0, 1) and pic.violation.time == 4.0
    assert pic.moves == () and len(pic.planned) == len(res.log[-1].pieces) >= 1
    out = plot_run(pic, tmp_path / "run.svg")
    ids = svg_ids(out)
    assert {"violation", "planned-0", "layer-0", "zoom-robot-0", "zoom-window"} <= ids
    assert len([i for i in ids if re.fullmatch(r"robot-\d+", i)]) == 5
    assert "robots 0 and 1" in svg_text(out)


def test_collision_along_a_piece_is_drawn_at_the_contact(tmp_path):
    """I1: one path per advance, the pair drawn where the discs first touch (inside the
    last advance), so the frames are the start, each event and the contact."""
    points, res = case_run(NO_I5)
    assert res.violation["invariant"] == "I1" and res.violation["robots"] == [0, 1]
    pic = drawing.run_picture(points, res, "case")
    advances = sum(st.kind == "advance" for st in res.log)
    out = plot_run(pic, tmp_path / "run.svg")
    paths = [i for i in svg_ids(out) if re.fullmatch(r"path-\d+-\d+", i)]
    assert len(paths) == advances == len(pic.moves) == 2
    v = pic.violation
    assert res.events - 1 < v.time < res.events
    from exactsym.pictures.run import position
    pa, pb = position(pic, 0, v.time), position(pic, 1, v.time)
    assert abs(((pa[0] - pb[0]) ** 2 + (pa[1] - pb[1]) ** 2) ** 0.5 - 2.0) < 1e-6
    assert len(frame_times(pic)) == res.events + 2


def test_one_frame_per_event_on_a_longer_run():
    """Six robots, the paper's algorithm (A3=all, EL=unordered), centralised: the frames
    are the start and one per event (the violation is at a Look, an event)."""
    from fractions import Fraction as F
    from exactsym.gathering.robot import Readings
    points = [(F(-23, 3), F(67, 3)), (F(-63), F(47, 3)), (F(12), F(-71)), (F(19, 2), F(61, 2)),
              (F(-19), F(49, 2)), (F(35), F(28, 3))]
    res = run(points, "centralised", 1, Readings(A3="all", EL="unordered"), max_events=300)
    assert res.events > 10
    pic = drawing.run_picture(points, res, "six")
    assert len(frame_times(pic)) == res.events + 1
    assert len(pic.events) == res.events
    assert len(pic.moves) == sum(st.kind == "advance" for st in res.log) > 0


def test_gather_and_replay_draw_the_same_picture(tmp_path):
    trace, a, b = tmp_path / "t.json", tmp_path / "a.svg", tmp_path / "b.svg"
    assert main(["gather", str(CASE), "--invariants", NO_I5, "--trace", str(trace),
                 "--plot", str(a)]) == 1        # the case expects I5: [expect] is false
    assert main(["replay", str(trace), "--plot", str(b)]) == 0
    assert a.read_bytes() == b.read_bytes()


def test_frames_gif_and_html_from_the_command(tmp_path, capsys):
    assert main(["gather", str(CASE), "--frames", str(tmp_path / "f"), "--gif",
                 str(tmp_path / "r.gif"), "--html", str(tmp_path / "r.html"), "--json"]) == 0
    assert len(list((tmp_path / "f").glob("frame-*.png"))) == 4 + 1
    assert (tmp_path / "r.html").read_text().count('class="frame"') == 5
    assert (tmp_path / "r.gif").stat().st_size > 0
    err = capsys.readouterr().err
    assert "picture:" in err                     # --json keeps stdout one JSON object


def test_missing_matplotlib_names_the_plot_extra(tmp_path, monkeypatch, capsys):
    import exactsym.pictures.draw as draw

    def unavailable():
        raise draw.PlotUnavailable("no matplotlib")
    monkeypatch.setattr(draw, "matplotlib_modules", unavailable)
    assert main(["gather", str(CASE), "--plot", str(tmp_path / "x.svg")]) == 2
    err = capsys.readouterr().err
    assert "plot" in err and "extra" in err and "matplotlib" in err
    assert not (tmp_path / "x.svg").exists()


def test_planned_paths_and_contact_points_survive_the_json_form():
    import json
    from exactsym.pictures.run import run_from_dict, run_to_dict
    points, res = case_run()
    pic = drawing.run_picture(points, res, "case")
    assert pic.violation.at is not None
    assert run_from_dict(json.loads(json.dumps(run_to_dict(pic)))) == pic


def test_a_gathered_run_has_one_frame_per_event_and_ends_in_the_pattern():
    from exactsym.gathering.cases import run_case_file
    path = ROOT / "cases/gathering/corrected-obstacle-beside-path.toml"
    points = read_case(path)[0]
    res = run_case_file(path).result
    assert res.outcome == "gathered"
    pic = drawing.run_picture(points, res, "corrected")
    assert pic.violation is None and pic.planned == ()
    assert len(frame_times(pic)) == res.events + 1
    from exactsym.pictures.run import position
    ends = [position(pic, i, res.events) for i in range(len(points))]
    c = pic.layers[0].centre
    # every robot ends at C or on layer 1 (distance 2), drawn from the exact log
    assert sorted(round(((x - c[0]) ** 2 + (y - c[1]) ** 2) ** 0.5, 9) for x, y in ends) == \
        [0.0, 2.0, 2.0, 2.0, 2.0]


def test_two_movers_colliding_are_drawn_both_at_the_exact_instant(tmp_path):
    """Two robots moving at once (SSYNC, handedness-two-movers-collide): the picture's
    pair is at the joint check's instant 14/15 of the step, robot 2 at (-4/3, 0) and
    robot 3 at (0, -4/3) -- both in motion, not one against the other's end (C)."""
    points, _n, expect, _s = read_case(ROOT / "cases/gathering/handedness-two-movers-collide.toml")
    res = run_settings(points, settings_of(expect))
    v = res.violation
    assert v["invariant"] == "I1" and sorted(v["robots"]) == [2, 3]
    pic = drawing.run_picture(points, res, "case")
    w = pic.violation
    assert w.time == pytest.approx(v["instant"] - 1 + 14 / 15)
    a, b = w.at
    assert a == pytest.approx((-4 / 3, 0)) and b == pytest.approx((0, -4 / 3))
    assert "move at once" in w.text
    assert plot_run(pic, tmp_path / "run.svg").exists()


def test_joint_witness_of_free_movers_is_none():
    from exactsym.gathering import geometry as g
    seg = g.Segment(g.point(0, 0), g.point(10, 0))
    assert drawing._joint_witness(seg, g.Segment(g.point(0, 2), g.point(10, 2))) is None
    tau, (p, q) = drawing._joint_witness(g.Segment(g.point(0, -5), g.point(0, 5)),
                                         g.Segment(g.point(-5, 0), g.point(5, 0)))
    assert tau == 0.5 and p == q == (0.0, 0.0)


def test_a_fresh_look_inside_a_step_is_drawn_at_its_instant(tmp_path):
    """joint-step-fresh-look-plans-makeasym: I3 at time 419429/1048576 of the step of
    event 4; the picture's pair is at t = 3 + that, robots 2 and 3 part way (robot 2 at
    (-3145735/262144, 0), as the witness says), not at the step's end (both at C); the
    pair is far apart, so no zoom window."""
    path = ROOT / "cases/gathering/joint-step-fresh-look-plans-makeasym.toml"
    points, _n, expect, _s = read_case(path)
    res = run_settings(points, settings_of(expect))
    assert res.violation["time"] == "419429/1048576"
    pic = drawing.run_picture(points, res, "case")
    when = 3 + 419429 / 1048576
    assert pic.violation.time == pytest.approx(when)
    from exactsym.pictures.run import position
    assert position(pic, 2, when) == pytest.approx((-3145735 / 262144, 0))
    assert position(pic, 3, when) == pytest.approx((0, 3145735 / 262144 * -1))
    out = tmp_path / "run.svg"
    plot_run(pic, out)
    # no zoom on the pair (a zoom on the moves or the final pattern may be drawn)
    assert not any(i.startswith("zoom") and not i.startswith(("zoom-moves-", "zoom-pattern-"))
                   for i in svg_ids(out))
