"""``exactsym check --json`` on every case file gives exactly the stored output.

``tests/golden/<path under cases/>.json`` holds the output of the code before the
pipeline refactoring (issue 8): a move of code must change no verdict and no key of the
JSON schema (``docs/cli.md``).  Compared as parsed JSON, so whitespace is free.  When a
change of verdict is intended, regenerate the files with
``python tests/test_golden.py`` and review the diff.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

import pytest

from exactsym.cli.main import main

ROOT = Path(__file__).resolve().parent.parent
CASES, GOLDEN = ROOT / "cases", ROOT / "tests" / "golden"
SUFFIXES = (".toml", ".txt")


def _case_files():
    return sorted(p for p in CASES.rglob("*") if p.suffix in SUFFIXES and p.is_file())


def _golden(path: Path) -> Path:
    return GOLDEN / (str(path.relative_to(CASES)) + ".json")


def test_every_case_has_a_golden_file_and_no_golden_file_is_stale():
    wanted = {_golden(p) for p in _case_files()}
    stored = set(GOLDEN.rglob("*.json"))
    assert wanted == stored


@pytest.mark.parametrize("path", _case_files(), ids=lambda p: str(p.relative_to(CASES)))
def test_check_json_matches_golden(path, capsys):
    code = main(["check", "--json", str(path)])
    out = json.loads(capsys.readouterr().out)
    assert code == 0
    golden = json.loads(_golden(path).read_text(encoding="utf-8"))
    # "file" is the path as given: the golden files were written from the checkout's root
    assert out.pop("file") == str(path)
    assert golden.pop("file") == path.relative_to(ROOT).as_posix()
    assert out == golden


if __name__ == "__main__":   # regenerate: python tests/test_golden.py
    import contextlib
    import io
    import os
    os.chdir(ROOT)                      # "file": the path from the checkout's root
    for case in _case_files():
        buffer = io.StringIO()
        with contextlib.redirect_stdout(buffer):
            if main(["check", "--json", case.relative_to(ROOT).as_posix()]) != 0:
                sys.exit(f"{case}: check failed")
        target = _golden(case)
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_text(buffer.getvalue(), encoding="utf-8")
