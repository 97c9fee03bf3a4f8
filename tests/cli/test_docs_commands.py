"""Issue 34, item 1: every shell command block of README.md and docs/*.md that starts with
``exactsym`` runs as written and ends with the exit status the text promises.

A block is a fenced ``sh`` (or ``bash``, ``shell``, or unnamed) block whose first line is an
``exactsym`` command; synopses with placeholders (``FILE``, ``OUT``) are fenced ``text`` and
not run.  Each block runs, command after command, in a temporary copy of ``cases/`` and
``docs/`` (commands write pictures, traces and results there), through ``python -m
exactsym``.  A command's exit status is 0 unless its line says ``# exit N``.

Blocks preceded by ``<!-- commands: not run ... (REASON) -->`` are skipped with that
reason: those that need the network (``pip install``, a Dask scheduler on another host) or
run for minutes (a sweep of thousands of configurations, the test suite itself).
"""

from __future__ import annotations

import re
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
PAGES = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
BLOCK = re.compile(r"^(?:<!-- commands: not run[^(\n]*\((?P<reason>[^\n]*)\) -->\n)?"
                   r"```(?P<lang>\w*)\n(?P<body>.*?)^```", re.M | re.S)
SHELL = {"sh", "bash", "shell", ""}


def _blocks():
    for page in PAGES:
        text = page.read_text(encoding="utf-8")
        for m in BLOCK.finditer(text):
            lines = [line for line in m.group("body").splitlines() if line.strip()]
            if m.group("lang") not in SHELL or not lines or \
                    not lines[0].startswith("exactsym"):
                continue
            where = f"{page.relative_to(ROOT)}:{text[:m.start('body')].count(chr(10)) + 1}"
            marks = [pytest.mark.skip(reason=m.group("reason"))] if m.group("reason") else []
            yield pytest.param(lines, id=where, marks=marks)


BLOCKS = list(_blocks())


def test_the_pages_have_command_blocks():
    ids = [b.id for b in BLOCKS]
    assert any(i.startswith("README.md") for i in ids) and len(ids) >= 6, ids


def _expected_status(line: str) -> int:
    said = re.search(r"#.*\bexit (\d)\b", line)
    return int(said.group(1)) if said else 0


@pytest.mark.parametrize("lines", BLOCKS)
def test_command_block_runs_as_written(lines, tmp_path):
    for folder in ("cases", "docs"):
        shutil.copytree(ROOT / folder, tmp_path / folder)
    for line in lines:
        words = shlex.split(line, comments=True)
        assert words and words[0] == "exactsym", line
        done = subprocess.run([sys.executable, "-m", "exactsym", *words[1:]], cwd=tmp_path,
                              capture_output=True, text=True, timeout=600)
        assert done.returncode == _expected_status(line), (line, done.stderr[-2000:])
        assert "internal error" not in done.stderr, (line, done.stderr)
