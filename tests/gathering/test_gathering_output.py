"""The reading matrix and readable output of ``gather`` (issue 30, points 4 and 7)."""

from __future__ import annotations

import json
from pathlib import Path

from exactsym.gathering.cli import main
from exactsym.gathering.output import (invariant_title, matrix_table, schedule_lines,
                                       with_decimals)
from exactsym.gathering.reading_matrix import differs_from_base, reading_matrix, reading_rows
from exactsym.gathering.robot import READINGS, Readings
from exactsym.gathering.search import Bounds
from exactsym.gathering.world import MIRROR

CASES = Path(__file__).resolve().parents[2] / "cases" / "gathering"
TWO_MOVERS = CASES / "handedness-two-movers-collide.toml"
ONE_CIRCLE = [(20, 0), (0, 20), (-20, 0), (0, -20), (12, 16)]

#: the JSON of ``gather FILE --json`` (docs/gathering.md, "Output and JSON"): pinned
RUN_KEYS = {"outcome", "label", "detail", "events", "looks", "checks", "violation",
            "pattern", "settings", "expect_failures", "search", "start"}
SEARCH_KEYS = {"found", "actions", "found_length", "length", "states", "expanded", "depth",
               "stopped", "phase", "seconds", "shrink_replays"}
ROW_KEYS = {"reading", "readings", "mirrored", "outcome", "label", "invariant", "robots",
            "schedule", "length", "detail", "search", "same_as"}
MATRIX_KEYS = {"settings", "matrix", "differs_from_base"}
VIOLATION_KEYS = {"invariant", "label", "instant", "robots", "witness"}
#: the keys every JSON output begins with (docs/json.md)
HEAD_KEYS = {"format", "schema_version", "file", "name"}


def test_every_named_reading_has_a_row_and_both_handednesses_too():
    rows = reading_rows(Readings().as_dict())
    names = [r[0] for r in rows]
    assert names[0] == "base"
    for switch, values in READINGS.items():
        for value in values:
            assert f"{switch}={value}" in names or Readings().as_dict()[switch] == value
    assert {"A6=nearer", "A7=largest", "A8=rational-rotation"} <= set(names)
    assert names[-4:] == ["hand=plain", "hand=mirrored", "A3=all, hand=plain",
                          "A3=all, hand=mirrored"]
    assert [r[3] for r in rows[-4:]] == [False, True, False, True]   # the mirror image
    assert all(not f.reflect for f in rows[-1][2])
    assert rows[-1][1]["A3"] == "all" and rows[-3][1]["A3"] == "first"


def test_the_matrix_finds_the_collision_in_both_handednesses_and_differs(capsys):
    settings = {"readings": Readings().as_dict(), "invariants": ["I1", "I5"],
                "rigid": True, "delta": None, "max_events": 30, "algorithm": "paper",
                "scheduler": "centralised", "seed": 0}
    rows = reading_matrix(ONE_CIRCLE, settings, Bounds(budget=200, depth=3))
    assert all(set(r) == ROW_KEYS for r in rows)
    by = {r["reading"]: r for r in rows}
    # two leaders of opposite handedness collide: the base reading shows it
    assert by["base"]["outcome"] == "violated" and by["base"]["invariant"] == "I1"
    assert by["base"]["schedule"] and by["base"]["length"] == 3
    # with every Look in one handedness one leader is elected: no collision
    assert by["hand=plain"]["outcome"] != "violated"
    assert by["hand=mirrored"]["outcome"] != "violated"
    # EL=unordered: both handednesses elect the same leader
    assert by["EL=unordered"]["outcome"] != "violated"
    assert {"hand=plain", "hand=mirrored", "EL=unordered"} <= \
        {r["reading"] for r in differs_from_base(rows)}
    assert by["A6=nearer"]["same_as"] == "base"
    json.dumps(rows)                                          # plain data
    table = matrix_table(rows)
    assert "violated I1 no overlap (gather-no-obstacle)" in table
    assert "hand=mirrored (mirror image)" in table


def test_gather_json_keys_are_pinned(capsys):
    assert main(["gather", str(TWO_MOVERS), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert set(data) == RUN_KEYS | HEAD_KEYS and data["search"] is None
    assert set(data["violation"]) >= VIOLATION_KEYS
    assert main(["gather", str(TWO_MOVERS), "--json", "--search", "--budget", "200",
                 "--depth", "3"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert set(data) == RUN_KEYS | HEAD_KEYS and set(data["search"]) == SEARCH_KEYS
    assert data["search"]["found"] and data["search"]["length"] == 3


def test_gather_readings_all(capsys):
    assert main(["gather", str(TWO_MOVERS), "--readings", "all", "--budget", "40",
                 "--depth", "3", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert set(data) == MATRIX_KEYS | HEAD_KEYS and all(set(r) == ROW_KEYS for r in data["matrix"])
    assert main(["gather", str(TWO_MOVERS), "--readings", "all", "--budget", "40",
                 "--depth", "3"]) == 0
    out = capsys.readouterr().out
    assert out.splitlines()[1].split()[:4] == ["reading", "outcome", "schedule", "search"]
    assert "hint: " in out and "end otherwise than the base reading" in out


def test_readable_text():
    assert invariant_title("I1") == "I1 no overlap (gather-no-obstacle)"
    assert invariant_title("I3", "obs-v-move") == "I3 a fresh Look agrees (obs-v-move)"
    long = "at (16333553612205046246241981156724874149885/5, -1/3)"
    assert with_decimals(long) == ("at (16333553612205046246241981156724874149885/5 "
                                   "[~ 3.26671e+39], -1/3)")
    assert with_decimals("x = 22/7") == "x = 22/7"
    lines = schedule_lines([{"a": "look", "robot": 2, "frame": MIRROR.as_list()},
                            {"a": "advance", "robot": 2, "stop": "3/8", "end": True},
                            {"a": "step", "moves": [[2, None, False], [3, "1/2", False]]}])
    assert lines == ["  1. robot 2 Looks in the mirrored frame",
                     "  2. robot 2 moves to 3/8 of its piece, and the adversary ends the "
                     "move there",
                     "  3. at once: robot 2 to the end of its piece, robot 3 to 1/2 of its "
                     "piece"]
