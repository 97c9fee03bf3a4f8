"""``exactsym check`` as its own process (:func:`exactsym.cli.main.entry`, which ends the
process without freeing the analysis object by object): the same output as
:func:`exactsym.cli.main.main` in this process, its exit status (1 for a false
``[expect]`` claim, with the claim on standard error), and a reader that stops early."""

from __future__ import annotations

import contextlib
import io
import subprocess
import sys
from pathlib import Path

from exactsym.cli.main import main

ROOT = Path(__file__).resolve().parents[2]
CASE = ROOT / "cases" / "examples" / "chiral-nine-gon.toml"


def _run(*args):
    return subprocess.run([sys.executable, "-m", "exactsym", *args], capture_output=True,
                          text=True, cwd=ROOT)


def test_the_process_prints_what_main_prints():
    for extra in (["--json"], ["--json", "--compact"], []):
        done = _run("check", str(CASE), *extra)
        buffer = io.StringIO()
        with contextlib.redirect_stdout(buffer):
            code = main(["check", str(CASE), *extra])
        assert (done.returncode, done.stdout) == (code, buffer.getvalue()) == (0, done.stdout)


def test_a_false_claim_exits_1_with_the_claim_on_stderr(tmp_path):
    wrong = tmp_path / "wrong.toml"
    wrong.write_text(CASE.read_text().replace('group = "C3"', 'group = "D3"'))
    done = _run("check", str(wrong), "--json")
    assert done.returncode == 1
    assert "group" in done.stderr and "D3" in done.stderr
    assert done.stdout.startswith("{") and done.stdout.endswith("}\n")


def test_a_reader_that_stops_early():
    proc = subprocess.Popen([sys.executable, "-m", "exactsym", "check", str(CASE), "--json"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, cwd=ROOT)
    assert proc.stdout.read(1) == b"{"
    proc.stdout.close()
    assert proc.wait(timeout=120) == 0
    assert proc.stderr.read() == b""
