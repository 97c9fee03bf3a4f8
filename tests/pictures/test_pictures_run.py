"""Pictures of a run (exactsym.pictures.run) on a synthetic run: positions along segments
and arcs, the still picture's paths and violation, one frame per event, the GIF and the
standalone HTML stepper."""

from __future__ import annotations

import json
import math
import re
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from exactsym.pictures.run import (Arc, Event, Layer, Move, Run, Segment, Violation, frame_times,
                               plot_run, position, run_from_dict, run_to_dict, write_frames,
                               write_gif, write_html)
from exactsym.pictures.run_cli import main

ROOT = Path(__file__).resolve().parents[2]
SVG = "{http://www.w3.org/2000/svg}"


def synthetic() -> Run:
    return Run("synthetic", "fat", ((-6.0, 0.0), (0.0, -7.0), (5.0, 0.0), (2.0, -3.0)),
               (Move(0, 0.0, 2.0, Segment((-6.0, 0.0), (-4.0, 0.0))),
                Move(2, 0.0, 2.5, Arc((0.0, 0.0), 5.0, 0.0, math.pi / 2)),
                Move(1, 1.0, 3.0, Segment((0.0, -7.0), (1.4, -4.2))),
                Move(3, 2.0, 3.0, Segment((2.0, -3.0), (1.9, -3.6)))),
               (Layer("L1", (0.0, 0.0), 4.0), Layer("L2", (0.0, 0.0), 5.0)),
               (Event(1.0, "robot 1 starts"), Event(2.0, "robot 3 starts")),
               Violation((1, 3), 3.0))


def test_positions_along_segments_and_arcs():
    run = synthetic()
    assert position(run, 0, -1) == (-6.0, 0.0)
    assert position(run, 0, 1.0) == pytest.approx((-5.0, 0.0))
    assert position(run, 0, 9.0) == pytest.approx((-4.0, 0.0))
    x, y = position(run, 2, 1.25)                       # half way along a quarter circle
    assert (x, y) == pytest.approx((5 * math.cos(math.pi / 4), 5 * math.sin(math.pi / 4)))
    assert position(run, 1, 0.5) == (0.0, -7.0)         # not started yet
    assert frame_times(run) == [0.0, 1.0, 2.0, 2.5, 3.0]


def test_overlapping_moves_are_rejected():
    with pytest.raises(ValueError, match="overlap"):
        Run("bad", "points", ((0.0, 0.0),), (Move(0, 0, 2, Segment((0, 0), (1, 0))),
                                              Move(0, 1, 3, Segment((1, 0), (2, 0)))))


def test_json_form_round_trips():
    run = synthetic()
    assert run_from_dict(json.loads(json.dumps(run_to_dict(run)))) == run


def test_still_picture_shows_paths_layers_and_the_colliding_pair(tmp_path):
    out = plot_run(synthetic(), tmp_path / "run.svg")
    ids = {e.get("id"): e for e in ET.parse(out).getroot().iter() if e.get("id")}
    assert sorted(i for i in ids if re.fullmatch(r"path-\d+-\d+", i)) == \
        ["path-0-0", "path-1-2", "path-2-1", "path-3-3"]
    assert {"layer-0", "layer-1", "violation"} <= set(ids)
    assert len([i for i in ids if re.fullmatch(r"robot-\d", i)]) == 4
    # the violation segment joins the two robots where they are at t = 3
    d = " ".join(p.get("d") for p in ids["violation"].iter(f"{SVG}path"))
    (x0, y0), (x1, y1) = [tuple(map(float, m)) for m in
                          re.findall(r"(-?\d+\.?\d*) (-?\d+\.?\d*)", d)[:2]]
    (a0, b0), (a1, b1) = position(synthetic(), 1, 3.0), position(synthetic(), 3, 3.0)
    assert math.hypot(x1 - x0, y1 - y0) > 0
    assert (x1 - x0) / (y1 - y0) == pytest.approx(-(a1 - a0) / (b1 - b0), rel=1e-3)
    text = " ".join("".join(t.itertext()) for t in ET.parse(out).getroot().iter(f"{SVG}text"))
    assert "robots 1 and 3" in text


def test_frames_gif_and_html(tmp_path):
    run = synthetic()
    frames = write_frames(run, tmp_path / "frames")
    assert [f.name for f in frames] == [f"frame-{k:03d}.png" for k in range(5)]
    assert len({f.read_bytes() for f in frames}) == 5             # every frame differs
    gif = write_gif(run, tmp_path / "run.gif")
    from PIL import Image
    with Image.open(gif) as im:
        assert im.n_frames == 5
    page = write_html(run, tmp_path / "run.html").read_text()
    assert page.count('<div class="frame"') == 5 and page.count("<svg") == 5
    assert "<script>" in page and "http" not in page.split("<script>")[1]
    ids = re.findall(r'id="(f\d+-robot-\d)"', page)
    assert len(ids) == len(set(ids)) == 20                         # unique across frames


def test_run_cli(tmp_path, capsys):
    src = ROOT / "docs/examples/synthetic-run.json"
    assert main([str(src), "--plot", str(tmp_path / "r.png"), "--html",
                 str(tmp_path / "r.html")]) == 0
    assert (tmp_path / "r.png").stat().st_size > 1000
    assert main([str(tmp_path / "missing.json")]) == 2
    assert "missing.json" in capsys.readouterr().err


def test_arc_through_its_end_points_in_either_sense():
    ccw = Arc.through((1.0, 1.0), (3.0, 1.0), (1.0, 3.0), 1)         # a quarter turn up
    assert ccw.radius == 2 and ccw.end_angle - ccw.start_angle == pytest.approx(math.pi / 2)
    assert ccw.end == pytest.approx((1.0, 3.0)) and ccw.at(0.5)[1] > 1
    cw = Arc.through((1.0, 1.0), (3.0, 1.0), (1.0, 3.0), -1)         # three quarters down
    assert cw.end_angle - cw.start_angle == pytest.approx(-3 * math.pi / 2)
    assert cw.end == pytest.approx((1.0, 3.0)) and cw.at(0.5)[1] < 1
