"""Issue 34, item 2: a user mistake exits 2 with one ``exactsym ...:`` line, never 3; valid
inputs with huge or tiny numbers print their summary (decimals from the exact values)."""

from __future__ import annotations

import re

import pytest

from exactsym.cli.main import main

NINE = "cases/examples/chiral-nine-gon.toml"


def _run(capsys, *argv):
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def _one_line(err: str, prefix: str) -> None:
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith(prefix), err


def test_plot_to_a_missing_directory_is_exit_2(tmp_path, capsys):
    code, _, err = _run(capsys, "plot", NINE, "-o", str(tmp_path / "no" / "dir" / "x.svg"))
    assert code == 2
    _one_line(err, "exactsym plot: cannot write ")


def test_plot_of_a_missing_file_says_exactsym(tmp_path, capsys):
    code, _, err = _run(capsys, "plot", str(tmp_path / "nofile.toml"), "-o",
                        str(tmp_path / "x.svg"))
    assert code == 2
    _one_line(err, "exactsym plot: ")
    assert "no such file" in err


def _file(tmp_path, points: str):
    path = tmp_path / "c.toml"
    path.write_text(f"format = 1\npoints = [{points}]\n", encoding="utf-8")
    return str(path)


BIG = "1" + "0" * 400
HUGE = "1" + "0" * 2400
SQUARE = "1" + "0" * 200
CASES = {
    # OverflowError in the near-symmetry hint's floats
    "coordinate 10^400": f'["1", "0"], ["0", "1"], ["-1", "0"], ["0", "-1"], ["{BIG}", "3"]',
    # "cannot convert float infinity to integer"
    "square at 10^200 and a point": (f'["{SQUARE}", "0"], ["0", "{SQUARE}"], '
                                     f'["-{SQUARE}", "0"], ["0", "-{SQUARE}"], ["1", "3"]'),
    # the int-to-text limit while printing sqrt of a 4,800-digit squared radius
    "radius about 10^2400": f'["{HUGE}", "1"], ["-{HUGE}", "0"]',
    "radius 10^-5000": '["sqrt(1/10^10000)", "0"], ["0", "sqrt(1/10^10000)"], '
                       '["-sqrt(1/10^10000)", "0"]',
}


@pytest.mark.parametrize("name", sorted(CASES))
@pytest.mark.parametrize("verbose", [False, True])
def test_huge_and_tiny_numbers_are_summarised(tmp_path, capsys, name, verbose):
    path = _file(tmp_path, CASES[name])
    code, out, err = _run(capsys, "check", path, *(["--verbose"] if verbose else []))
    assert code == 0 and err == "", err
    sec = next(line for line in out.splitlines() if line.startswith("SEC"))
    assert re.search(r"radius (\d|≈ \d\.\d+e[+-]\d+)", sec), sec


def test_refusal_beyond_the_degree_bound_names_file_line_column(tmp_path, capsys):
    path = _file(tmp_path, '["sqrt(2+cos(2*pi/1009))", "0"], ["0", "1"], ["-1", "0"]')
    code, _, err = _run(capsys, "check", path)
    assert code == 2
    _one_line(err, f"exactsym: {path}:2:")
    assert re.match(rf"exactsym: {re.escape(path)}:2:\d+: .*above the limit", err)
