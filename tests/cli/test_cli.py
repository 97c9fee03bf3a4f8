"""The command line: exit codes 0/1/2, JSON keys, and no traceback on bad input."""

import json
import subprocess
import sys

import pytest

from exactsym.cli.main import main

EXAMPLES = "cases/examples"


def run(capsys, *argv, stdin=None, monkeypatch=None):
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def test_check_json_on_a_rational_file(capsys):
    code, out, err = run(capsys, "check", f"{EXAMPLES}/rational-pentagon.txt", "--json")
    assert code == 0, err
    report = json.loads(out)
    assert report["n"] == 5
    assert report["sec"] == {"center": ["2", "7/3"], "radius_squared": "85/9"}
    assert [lv["radius_squared"] for lv in report["levels"]] == ["64/9", "85/9"]
    assert [lv["points"] for lv in report["levels"]] == [[3], [2, 4, 0, 1]]


def test_check_polar_example_meets_its_expectations(capsys):
    code, out, err = run(capsys, "check", f"{EXAMPLES}/chiral-nine-gon.toml")
    assert code == 0, err
    assert "centre C = (0, 0), radius 4\n" in out


def test_algebraic_file(tmp_path, capsys):
    f = tmp_path / "hexagon.txt"
    f.write_text("1 0\n1/2 sqrt(3)/2\n-1/2 sqrt(3)/2\n-1 0\n-1/2 -sqrt(3)/2\n1/2 -sqrt(3)/2\n")
    code, out, err = run(capsys, "check", str(f), "--json")
    assert code == 0, err
    report = json.loads(out)
    assert report["sec"]["center"] == ["0", "0"] and report["sec"]["radius_squared"] == "1"
    assert report["levels"][0]["points"] == [0, 1, 2, 3, 4, 5]


def test_false_expectation_exits_1(tmp_path, capsys):
    f = tmp_path / "wrong.toml"
    f.write_text('format = 1\npoints = [["0","0"], ["2","0"]]\n[expect]\nsec_radius_squared = "2"\n')
    code, out, err = run(capsys, "check", str(f))
    assert code == 1 and "sec_radius_squared" in err and "finds '1'" in err


BAD = {
    "malformed.toml": 'format = 1\npoints = [["0", "0"\n',
    "unknown-key.toml": 'format = 1\npoinst = [["0","0"]]\n',
    "bad-expr.txt": "1 2\n3 foo(4)\n",
    "bare-pi.txt": "pi 1\n",
    "negative-sqrt.txt": "sqrt(2-3) 1\n",
    "negative-nested.txt": "sqrt(sqrt(2)-2) 1\n",
    "div-zero.txt": "1/(1-1) 2\n",
    "duplicates.txt": "0 0\n1 1\n2/2 1\n",
    "no-points.txt": "# nothing\n",
    "huge-exponent.txt": "2^100000000 1\n",
    "deep.txt": "(" * 5000 + "1" + ")" * 5000 + " 1\n",
    "python.txt": "__import__('os').system('echo pwned') 1\n",
    "power-tower.txt": "((2^10000)^10000)^10000 1\n",
    "field-power.txt": "(1+sqrt(2))^10000000 1\n",
    "fat.toml": 'format = 1\nmodel = "fat"\npoints = [["0","0"], ["1","1"]]\n',
    "negative-radius.toml": 'format = 1\npoints = [{ r = "-1", turn = "0" }]\n',
}


@pytest.mark.parametrize("name", sorted(BAD))
def test_bad_input_exits_2_with_one_line(tmp_path, capsys, name):
    f = tmp_path / name
    f.write_text(BAD[name])
    code, out, err = run(capsys, "check", str(f))
    assert code == 2, (out, err)
    assert "Traceback" not in err and "pwned" not in out
    assert len(err.strip().splitlines()) == 1 and name in err


def test_duplicate_and_overlap_messages_name_indices(tmp_path, capsys):
    f = tmp_path / "d.txt"
    f.write_text("0 0\n1 1\n2/2 1\n")
    assert run(capsys, "check", str(f))[2].strip().endswith("points 1 and 2 coincide")
    g = tmp_path / "fat.toml"
    g.write_text('format = 1\nmodel = "fat"\npoints = [["0","0"], ["2","0"], ["3", "1"]]\n')
    assert "fat robots 1 and 2 overlap" in run(capsys, "check", str(g))[2]


def test_touching_fat_robots_are_allowed(tmp_path, capsys):
    g = tmp_path / "fat.toml"
    g.write_text('format = 1\nmodel = "fat"\npoints = [["0","0"], ["2","0"], ["1", "sqrt(3)"]]\n')
    assert run(capsys, "check", str(g))[0] == 0


def test_missing_file_and_bad_command_line(capsys):
    assert run(capsys, "check", "no/such/file.toml")[0] == 2
    assert run(capsys, "frobnicate")[0] == 2


def test_standard_input_and_console_entry_point():
    proc = subprocess.run([sys.executable, "-m", "exactsym", "check", "-", "--json"],
                          input="0 0\n4 0\n0 3\n", capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    assert json.loads(proc.stdout)["sec"] == {"center": ["2", "3/2"], "radius_squared": "25/4"}


def test_long_flat_sums_evaluate(tmp_path, capsys):
    """A 1,200-term sum is a tree 1,200 levels deep: evaluated, not a RecursionError."""
    f = tmp_path / "sum.txt"
    f.write_text("+".join(["sqrt(2)"] * 1200) + ", 0\n0 1\n")
    code, out, err = run(capsys, "check", str(f), "--json")
    assert code == 0, err
