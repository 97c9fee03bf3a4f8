"""Issue 34, item 4: a progress bar on standard error for the long commands, quiet when
standard error is not a terminal; bokeh in the sweep extra (the Dask dashboard)."""

from __future__ import annotations

import io
import sys
import time
import tomllib
from pathlib import Path

from exactsym.cli.main import main
from exactsym.progress import Progress, ticking

ROOT = Path(__file__).resolve().parent.parent
GATHER = ROOT / "cases" / "gathering" / "last-three-no-leader.toml"
SHORT = [str(GATHER), "--scheduler", "centralised", "--max-events", "5", "--no-expect"]


class Terminal(io.StringIO):
    """A standard error that says it is a terminal."""

    def isatty(self) -> bool:
        return True


def test_the_bar_counts_and_clears_its_line():
    out = Terminal()
    with Progress("work", total=4, stream=out, unit=" files") as bar:
        bar.update(note="a")
        bar.update(note="b")
        bar.draw(force=True)
        drawn = out.getvalue()
    assert "work: [" + "#" * 12 + "." * 12 + "] 2/4 files  50%" in drawn and "b" in drawn
    assert out.getvalue().endswith("\r")          # cleared: the next output starts clean


def test_quiet_when_not_a_terminal():
    out = io.StringIO()
    with Progress("work", total=3, stream=out) as bar:
        for _ in range(3):
            bar.update()
    assert out.getvalue() == "" and bar.done == 3
    with ticking("work", 1, timed=True, stream=out):
        time.sleep(0.3)
    assert out.getvalue() == ""


def test_a_time_bounded_bar_fills_with_the_clock():
    out = Terminal()
    with ticking("search", 2, timed=True, stream=out) as bar:
        time.sleep(1.3)
    assert "search: [" in out.getvalue() and "/2 s" in out.getvalue()
    assert 1 <= bar.done <= 2


def test_commands_print_no_progress_when_stderr_is_not_a_terminal(capsys, tmp_path):
    assert main(["gather", *SHORT]) == 0
    assert capsys.readouterr().err == ""
    assert main(["gather", *SHORT, "--search", "--budget", "10"]) == 0
    assert capsys.readouterr().err == ""
    assert main(["sweep", "grid:3:<=3", "--what", "truth", "--serial",
                 "--out", str(tmp_path / "r.jsonl")]) == 0
    assert "conf/s" not in capsys.readouterr().err


def test_the_reading_matrix_and_the_sweep_draw_a_bar_on_a_terminal(monkeypatch, tmp_path):
    err = Terminal()
    monkeypatch.setattr(sys, "stderr", err)
    assert main(["gather", *SHORT, "--readings", "all", "--budget", "3", "--time", "3"]) == 0
    assert "gather --readings all: [" in err.getvalue() and " readings " in err.getvalue()
    err.seek(0)
    err.truncate()
    assert main(["sweep", "grid:3:<=3", "--what", "truth", "--serial",
                 "--out", str(tmp_path / "r.jsonl")]) == 0
    assert "sweep grid:3:<=3: [" in err.getvalue() and "27/27 conf" in err.getvalue()


def test_ledger_check_draws_one_step_per_case(monkeypatch, tmp_path):
    import exactsym.ledger.cli as ledger_cli
    seen = []

    def fake_check(ledger, root, progress=None):
        for path in ("cases/a.toml", "cases/b.toml"):
            time.sleep(0.3)                   # past the redraw interval
            progress(path)
            seen.append(path)
        return []
    monkeypatch.setattr(ledger_cli, "check_evidence", fake_check)
    err = Terminal()
    monkeypatch.setattr(sys, "stderr", err)
    assert main(["ledger", "--check", "--root", str(ROOT)]) == 0
    assert seen and "ledger --check: [" in err.getvalue() and "cases/b.toml" in err.getvalue()


def test_bokeh_is_in_the_sweep_extra():
    data = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
    extra = data["project"]["optional-dependencies"]["sweep"]
    assert any(d.startswith("bokeh") for d in extra)
    assert any(d.startswith("dask[distributed]") for d in extra)


def test_the_default_sweep_runs_where_it_pays_off(monkeypatch):
    from types import SimpleNamespace

    from exactsym.sweeps import cli as sweep_cli
    from exactsym.sweeps.families import parse_family
    from exactsym.sweeps.analysis_bridge import file_points
    small, large = (parse_family(f, file_points) for f in ("roots:12:<=6", "grid:5:<=5"))
    plain = SimpleNamespace(serial=False, scheduler=None, workers=None)
    monkeypatch.setattr(sweep_cli.os, "cpu_count", lambda: 2)
    assert sweep_cli._where(plain, large) == (True, 1)          # 2 cores: in this process
    monkeypatch.setattr(sweep_cli.os, "cpu_count", lambda: 16)
    assert sweep_cli._where(plain, small) == (True, 1)          # 136: the start costs more
    monkeypatch.setattr(sweep_cli.importlib.util, "find_spec", lambda name: object())
    assert sweep_cli._where(plain, large) == (False, sweep_cli.MAX_DEFAULT_WORKERS)
    asked = SimpleNamespace(serial=False, scheduler=None, workers=3)
    assert sweep_cli._where(asked, small) == (False, 3)         # what the command says
