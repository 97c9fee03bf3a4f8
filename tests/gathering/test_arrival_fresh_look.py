"""gather-min-distance under the reading "R recognised afresh during the motion"
(\\label{gathering_algorithm}, FormGPattern L1642-1643): a leader arriving radially on
layer 1 beside a lone robot of that layer is exactly as far from C as that robot, and a
fresh Look elects the lone robot.  The configuration is written here (rational polar, a
state inside a run: the robot of layer 1 touches the robot at C); the verdict must not
change under a mirror image or a quarter turn about C, and another outer triangle (which
changes the projection G_1t the fresh Look elects from) re-elects the mover instead."""

import json
from fractions import Fraction as F

import pytest

from exactsym.gathering.cli import main

ROBOTS = [("0", "0"), ("2", "0"), ("5", "3/8"), ("5", "2/3"), ("5", "1/2"), ("5", "7/8"),
          ("10", "1/8"), ("10", "1/2"), ("10", "19/24")]
ARGS = ["--mid-run", "--reading", "A3=all", "--reading", "EL=unordered", "--scheduler",
        "centralised", "--seed", "1", "--invariants", "I3", "--json"]


def _run(tmp_path, capsys, robots, turn=lambda t: t):
    rows = ",\n".join(f'  {{ r = "{r}", turn = "{turn(F(t)) % 1}" }}' for r, t in robots)
    path = tmp_path / "state.toml"
    path.write_text(f'format = 1\nname = "arrival"\nmodel = "fat"\npoints = [\n{rows}\n]\n',
                    encoding="utf-8")
    assert main(["gather", str(path), *ARGS]) == 0
    return json.loads(capsys.readouterr().out)


@pytest.mark.parametrize("turn", [lambda t: t, lambda t: -t, lambda t: t + F(1, 4)],
                         ids=["as-is", "mirror", "quarter-turn"])
def test_a_fresh_look_at_the_arrival_elects_the_lone_robot(tmp_path, capsys, turn):
    out = _run(tmp_path, capsys, ROBOTS, turn)
    assert out["outcome"] == "violated"
    v = out["violation"]
    assert (v["invariant"], v["instant"], v["robots"]) == ("I3", 10, [1, 2])
    assert "plans robot 1 (leader)" in v["witness"]


def test_another_outer_triangle_keeps_the_mover(tmp_path, capsys):
    # the outer triangle decides, through the projection G_1t, whom the fresh Look elects:
    # with turns 1/8, 5/12, 3/4 it re-elects the mover (another target, still I3)
    robots = ROBOTS[:6] + [("10", "1/8"), ("10", "5/12"), ("10", "3/4")]
    v = _run(tmp_path, capsys, robots)["violation"]
    assert (v["invariant"], v["robots"]) == ("I3", [2])
    assert "plans robot 2 (leader)" in v["witness"]
