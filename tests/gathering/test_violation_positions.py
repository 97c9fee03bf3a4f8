"""Issue 34, point 5: a gathering violation gives the named robots' centres as data
(exact texts that read back) beside its prose."""

import json
from pathlib import Path

from exactsym.exact import evaluate, number_system
from exactsym.gathering.cli import main
from exactsym.io.expr import parse_expression

CASES = Path(__file__).resolve().parents[2] / "cases" / "gathering"


def _violation(capsys, name, *extra):
    assert main(["gather", str(CASES / name), "--json", "--no-expect", *extra]) == 0
    return json.loads(capsys.readouterr().out)["violation"]


def _value(text):
    expr = parse_expression(text, written=True)
    return evaluate(expr, number_system([expr]))


def test_a_planned_path_violation_names_where_both_robots_stand(capsys):
    v = _violation(capsys, "obstacle-beyond-destination.toml")
    assert v["invariant"] == "I5" and v["robots"] == [0, 1]
    # robot 1 stands at (-9/5, 0): the prose says so, and so does the data
    assert v["positions"]["1"] == ["-9/5", "0"]
    assert "(-9/5, 0)" in v["witness"]
    # the mover's centre reads back and is within 2 of C = (0, 0) as well
    x, y = (_value(t) for t in v["positions"]["0"])
    assert x * x + y * y < 4


def test_an_instant_violation_places_the_mover_at_that_instant(capsys):
    v = _violation(capsys, "pocket-move-out-not-nearest.toml")
    assert v["invariant"] == "I4" and set(v["positions"]) == {"7", "8"}
    # robot 8 of R at 37/10 from C; the mover at 4 from C (the end of its move out)
    for robot, r2 in (("8", "1369/100"), ("7", "16")):
        x, y = (_value(t) for t in v["positions"][robot])
        assert x * x + y * y == _value(r2)
