"""Issue 34, point 3: pictures of motion -- direction arrows, time order by colour, a zoom
where moves are small, moves too small to draw said in words; rendered and checked for
what is drawn (SVG ids and texts, PNG pixels)."""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

pytest.importorskip("matplotlib")

from exactsym.pictures.run import (Layer, Move, Run, Segment, plot_run,  # noqa: E402
                                   time_colour)

ROOT = Path(__file__).resolve().parents[2]


def ids(path) -> set:
    return {e.get("id") for e in ET.parse(path).getroot().iter() if e.get("id")}


def texts(path) -> str:
    return " ".join("".join(t.itertext()) for t in ET.parse(path).getroot().iter()
                    if t.tag.endswith("text"))


def far_apart(step: float) -> Run:
    """Three robots far apart; robot 0 makes three moves of length ``step`` in a row."""
    moves = tuple(Move(0, float(k), k + 1.0, Segment((k * step, 0.0), ((k + 1) * step, 0.0)))
                  for k in range(3))
    return Run("small moves", "fat", ((0.0, 0.0), (40.0, 0.0), (0.0, 40.0)), moves)


def test_arrows_and_the_time_scale(tmp_path):
    out = plot_run(far_apart(6.0), tmp_path / "big.svg")
    got = ids(out)
    assert {f"arrow-0-{k}" for k in range(3)} <= got
    assert "time-bar" in got
    assert "zoom-moves-window" not in got          # the moves are large: no zoom
    assert "True" not in texts(out) and "False" not in texts(out)


def test_small_moves_get_a_zoom_and_invisible_ones_a_ring(tmp_path):
    small = plot_run(far_apart(0.5), tmp_path / "small.svg")
    assert "zoom-moves-window" in ids(small)
    assert {f"zoom-moves-arrow-0-{k}" for k in range(3)} <= ids(small)
    # an epsilon move: its ends are one point in doubles; the size says how small
    eps = Run("epsilon", "fat", ((0.0, 0.0), (40.0, 0.0), (0.0, 40.0)),
              tuple(Move(0, float(k), k + 1.0, Segment((0.0, 0.0), (0.0, 0.0)), 1e-19)
                    for k in range(4)))
    out = plot_run(eps, tmp_path / "eps.svg")
    assert "tiny-0" in ids(out)
    assert "robot 0: 4 moves of 1.0e-19 at most" in texts(out)


def test_the_pattern_at_the_end_is_zoomed_when_small(tmp_path):
    run = Run("gathered", "fat", ((0.0, 0.0), (2.0, 0.0), (60.0, 0.0)),
              (Move(2, 0.0, 1.0, Segment((60.0, 0.0), (0.0, 2.0))),),
              (Layer("L1", (0.0, 0.0), 2.0),))
    assert "zoom-pattern-window" in ids(plot_run(run, tmp_path / "p.svg"))


def test_png_shows_the_first_and_last_moves_in_their_time_colours(tmp_path):
    import matplotlib.image as mpimg
    png = plot_run(far_apart(6.0), tmp_path / "run.png")
    img = mpimg.imread(png)[..., :3]
    first, last = time_colour(0.5 / 3), time_colour(2.5 / 3)

    def has(colour) -> bool:
        d = ((img - colour[:3]) ** 2).sum(axis=-1)
        return bool((d < 0.003).sum() > 20)
    assert has(first) and has(last)
    assert math.dist(first[:3], last[:3]) > 0.3     # early and late are told apart
