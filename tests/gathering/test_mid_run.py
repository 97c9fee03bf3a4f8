"""A state inside a run (a partial pattern of touching robots) is run only when asked:
the paper's robots start separated (L1568, L1707-1708)."""

from pathlib import Path

from exactsym.gathering.cli import main

CASE = Path(__file__).resolve().parents[2] / "cases/gathering/pocket-move-out-not-nearest.toml"


def _without_flag(tmp_path) -> Path:
    text = CASE.read_text(encoding="utf-8").replace("gather_mid_run = true\n", "")
    out = tmp_path / "pocket.toml"
    out.write_text(text, encoding="utf-8")
    return out


def test_touching_start_needs_mid_run(tmp_path, capsys):
    path = _without_flag(tmp_path)
    assert main(["gather", str(path)]) == 2
    assert "needs --mid-run" in capsys.readouterr().err
    # asked for, it runs (exit 0: the [expect] block holds): the leader's move out to
    # layer 2 passes robot 8 (I4)
    assert main(["gather", str(path), "--mid-run", "--json"]) == 0
    assert '"label": "gather-min-distance"' in capsys.readouterr().out


def test_the_case_declares_it_and_overlaps_stay_refused(tmp_path, capsys):
    assert main(["gather", str(CASE), "--json"]) == 0
    assert '"start": "mid-run"' in capsys.readouterr().out
    assert main(["gather", str(CASE)]) == 0
    assert capsys.readouterr().out.startswith("start: a state inside a run")
    text = CASE.read_text(encoding="utf-8").replace('["2", "0"]', '["19/10", "0"]')
    bad = tmp_path / "overlap.toml"
    bad.write_text(text, encoding="utf-8")
    assert main(["gather", str(bad), "--mid-run"]) == 2
    assert "robots 0 and 1 overlap" in capsys.readouterr().err     # (the file reader's check)
