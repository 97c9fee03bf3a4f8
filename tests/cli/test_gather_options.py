"""Issue 34, item 7: ``gather --no-expect`` ignores the file's ``[expect]``, ``--help``
explains the readings in words, ``replay``'s errors name ``replay``."""

from __future__ import annotations

import json
from pathlib import Path

from exactsym.cli.main import main
from exactsym.gathering.robot import READINGS

ROOT = Path(__file__).resolve().parents[2]
# [expect] gather_outcome = "stalled": five events cannot prove it, so the claim is false
CASE = ROOT / "cases" / "gathering" / "last-three-no-leader.toml"
SHORT = [str(CASE), "--scheduler", "centralised", "--max-events", "5"]


def test_a_false_expectation_exits_1_and_no_expect_exits_0(capsys):
    assert main(["gather", *SHORT]) == 1
    assert "[expect]" in capsys.readouterr().err
    assert main(["gather", *SHORT, "--no-expect"]) == 0
    assert capsys.readouterr().err == ""


def test_no_expect_with_json_reports_no_failures(capsys):
    assert main(["gather", *SHORT, "--no-expect", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["expect_failures"] == [] and out["outcome"] == "max-events"


def test_no_expect_keeps_input_errors_exit_2(tmp_path, capsys):
    assert main(["gather", str(tmp_path / "missing.toml"), "--no-expect"]) == 2
    assert capsys.readouterr().err.startswith("exactsym gather:")


def test_gather_help_explains_every_reading_in_words(capsys):
    assert main(["gather", "--help"]) == 0
    text = capsys.readouterr().out
    out = " ".join(text.split())
    bare = "".join(text.split())               # argparse may wrap at a hyphen
    for option in ("--seed", "--max-events", "--no-expect"):
        assert option in out
    for key, values in READINGS.items():
        assert f"{key}={'|'.join(values)}(" in bare, key
    for words in ("the SEC of R", "no disc covers C", "sorted pairs", "random adversary"):
        assert words.replace(" ", "") in bare, words


def test_replay_errors_name_replay(tmp_path, capsys):
    bad = tmp_path / "t.json"
    bad.write_text("{}", encoding="utf-8")
    assert main(["replay", str(bad)]) == 2
    err = capsys.readouterr().err
    assert err.startswith("exactsym replay:") and err.count("\n") == 1
    assert main(["replay", str(tmp_path / "missing.json")]) == 2
    assert capsys.readouterr().err.startswith("exactsym replay:")
