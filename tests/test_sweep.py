"""Sweeps: serial against Dask, interruption and resume, counts, case files, evidence.

The analysis is the real one (``--what audit``) on the small family roots:12:<=5
(86 classes, about half a second serially).
"""

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest
from hypothesis import given, settings, strategies as st

from exactsym.sweep import analysis_bridge as bridge
from exactsym.sweep import job
from exactsym.sweep.cli import main
from exactsym.sweep.engine import SweepOptions, run_sweep
from exactsym.sweep.families import family_items, parse_family, rank
from exactsym.sweep.results import read_records
from exactsym.sweep.summary import ledger_evidence, summarise, write_cases

FAMILY = "roots:12:<=5"
ROOT = Path(__file__).resolve().parents[1]


def _lines(path) -> set:
    return set(Path(path).read_text().splitlines())


@pytest.fixture(scope="module")
def serial_run(tmp_path_factory):
    out = tmp_path_factory.mktemp("sweep") / "serial.jsonl"
    run = run_sweep(parse_family(FAMILY), "audit", out, options=SweepOptions(serial=True))
    assert run.complete and run.new == 86 and run.errors == 0
    return out


def test_serial_and_local_cluster_give_the_same_records(serial_run, tmp_path):
    out = tmp_path / "dask.jsonl"
    run = run_sweep(parse_family(FAMILY), "audit", out,
                    options=SweepOptions(workers=2, batch_size=5))
    assert run.complete and run.workers == 2 and run.new == 86
    assert _lines(out) == _lines(serial_run)
    assert summarise(out) == summarise(serial_run)


def test_counts_agree_with_a_direct_loop(serial_run):
    failures, applicable = {}, {}
    for item in family_items(parse_family(FAMILY)):
        result = bridge.analyse("audit", item.points)
        assert set(result["failed"]) <= set(result["applicable"])
        for label in result["failed"]:
            failures[label] = failures.get(label, 0) + 1
        for label in result["applicable"]:
            applicable[label] = applicable.get(label, 0) + 1
    summary = summarise(serial_run)
    assert summary.configurations == 86
    assert {e.label: e.failures for e in summary.labels if e.failures} == failures
    assert {e.label: e.applicable for e in summary.labels if e.applicable} == applicable


def test_smallest_counterexamples_are_smallest_and_load_back_as_passing_cases(serial_run,
                                                                              tmp_path):
    summary = summarise(serial_run)
    records = [r for r in read_records(serial_run) if r["failed"]]
    cases = write_cases(summary, tmp_path / "cases")
    assert set(cases) == {e.label for e in summary.labels if e.failures}
    for entry in summary.labels:
        if not entry.failures:
            continue
        failing = [r for r in records if entry.label in r["failed"]]
        best = min(failing, key=lambda r: (r["n"], r["denominator"], r["size"], r["key"]))
        assert entry.smallest == best
        assert bridge.check_case_file(cases[entry.label]) == []
        text = Path(cases[entry.label]).read_text()
        assert "[expect]" in text and "audit_agrees = false" in text
    # a singleton is in O_S by def-symmetric-conf yet orderable (docs/audit.md, finding 6)
    pasym = next(e for e in summary.labels if e.label == "Pasym-Pord")
    assert pasym.smallest["n"] == 1 and pasym.failures == 1


def test_rank_orders_robots_then_denominators_then_size():
    items = list(family_items(parse_family("roots:12:2..3")))
    ranks = sorted(items, key=rank)
    assert ranks[0].n == 2 and ranks[0].denominator == 2     # the diameter: turns 0, 1/2
    assert [i.n for i in ranks] == sorted(i.n for i in items)


def test_stopped_sweep_resumes_to_the_same_records(serial_run, tmp_path):
    out = tmp_path / "stopped.jsonl"
    family = parse_family(FAMILY)
    first = run_sweep(family, "audit", out,
                      options=SweepOptions(serial=True, batch_size=7, stop_after=30))
    assert not first.complete and 30 <= first.new < 86
    with open(out, "a") as f:                    # a write torn by the interruption
        f.write('{"key": "roots:12:1:0,1,2,3,4", "n": 5, "sta')
    second = run_sweep(family, "audit", out, resume=True,
                       options=SweepOptions(serial=True))
    assert second.complete and second.skipped == first.new
    assert second.new + second.skipped == 86
    assert _lines(out) == _lines(serial_run)
    assert len(Path(out).read_text().splitlines()) == 87     # header + each key once


def test_killed_subprocess_resumes_to_the_same_records(serial_run, tmp_path):
    out = tmp_path / "killed.jsonl"
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    proc = subprocess.Popen([sys.executable, "-m", "exactsym.sweep", FAMILY, "--what", "audit",
                             "--serial", "--batch-size", "1", "--out", str(out)],
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env)
    deadline = time.monotonic() + 60
    while time.monotonic() < deadline and proc.poll() is None:
        if out.exists() and len(out.read_text().splitlines()) > 20:
            break
        time.sleep(0.005)
    assert proc.poll() is None                    # killed half-way, not after the end
    proc.send_signal(signal.SIGKILL)
    proc.wait()
    assert 1 < len(out.read_text().splitlines()) < 87
    code = main([FAMILY, "--what", "audit", "--serial", "--resume", "--out", str(out),
                 "--json"])
    assert code == 1                              # some statement fails in this family
    assert _lines(out) == _lines(serial_run)


def test_a_failing_configuration_is_recorded_and_the_sweep_goes_on(tmp_path, monkeypatch):
    real = bridge.analyse

    def flaky(what, points, budget=0):
        if len(points) == 3 and points[1][2] == "1/12":
            raise ArithmeticError("injected")
        return real(what, points, budget)

    monkeypatch.setattr(bridge, "analyse", flaky)
    out = tmp_path / "errors.jsonl"
    run = run_sweep(parse_family("roots:12:<=3"), "truth", out,
                    options=SweepOptions(serial=True))
    errors = [r for r in read_records(out) if r["status"] == "error"]
    assert run.complete and run.errors == len(errors) >= 1
    assert all("ArithmeticError: injected" in r["error"] and r["points"] for r in errors)
    summary = summarise(out)
    assert summary.errors == len(errors)
    assert summary.configurations + summary.errors == 1 + 6 + 12


def test_command_json_summary_and_exit_codes(serial_run, tmp_path, capsys):
    out = tmp_path / "cli.jsonl"
    code = main([FAMILY, "--what", "audit", "--serial", "--out", str(out), "--json"])
    data = json.loads(capsys.readouterr().out)
    assert code == 1
    summary = summarise(serial_run)
    assert data["configurations"] == 86
    assert data["failures"] == {e.label: e.failures for e in summary.labels if e.failures}
    for label, small in data["smallest"].items():
        assert Path(small["case"]).exists() and small["robots"] >= 1
    evidence = json.loads(Path(data["evidence"]).read_text())
    assert evidence["configurations"] == 86
    # the same file again without --resume is refused; a bad family is refused
    assert main([FAMILY, "--serial", "--out", str(out)]) == 2
    assert main(["roots:0:3", "--serial", "--out", str(tmp_path / "x.jsonl")]) == 2
    assert "already" not in capsys.readouterr().err


def test_truth_sweep_counts_groups(tmp_path):
    out = tmp_path / "truth.jsonl"
    run_sweep(parse_family("roots:6:<=6"), "truth", out, options=SweepOptions(serial=True))
    summary = summarise(out)
    # 1 + 3 + 3 + 3 + 1 + 1 classes of 1..6 robots on the hexagon's vertices
    assert summary.configurations == 12
    assert summary.groups == {"O2": 1, "C1": 1, "D1": 4, "D2": 4, "D3": 1, "D6": 1}
    assert all(e.failures == 0 for e in summary.labels)


def test_ledger_evidence_says_what_was_found(serial_run):
    summary = summarise(serial_run)
    evidence = ledger_evidence(summary, {}, "results.jsonl")
    assert evidence["configurations"] == 86 and evidence["family"] == FAMILY
    for item in evidence["evidence"]:
        if item["failures"]:
            assert item["verdict"] == "fails" and item["smallest"]["robots"] >= 1
            assert item["text"].startswith(f"fails on {item['failures']} of 86")
        elif item["applicable"] == 0:
            assert item["verdict"] == "vacuous"
        else:
            assert item["verdict"] == "holds"
            assert item["text"].startswith(f"holds on all 86 configurations of {FAMILY}")


def test_job_records_carry_points_only_when_needed():
    item = next(family_items(parse_family("roots:12:1")))
    record = job.analyse_item(item, "truth")
    assert record["status"] == "ok" and "points" not in record
    assert record["truth"] == {"group": "O2", "orderable": True}


def test_gather_runs_the_simulator_on_each_start(tmp_path):
    """gather:BUDGET:random... runs the real simulator once per configuration: every
    record names an outcome of the simulator, and a run that neither gathers nor
    violates counts against ``gathering-within-budget``."""
    out = tmp_path / "gather.jsonl"
    family = parse_family("gather:60:random:5:7:3")
    run = run_sweep(family, "gather", out, options=SweepOptions(serial=True))
    assert run.complete
    records = [r for r in map(json.loads, out.read_text().splitlines()) if "status" in r]
    assert len(records) == 3 and all(r["status"] == "ok" for r in records)
    outcomes = {r["gather"]["outcome"] for r in records}
    assert outcomes <= {"gathered", "stalled", "violated", "not-possible", "undecided",
                        "max-events"}
    for r in records:
        assert (r["failed"] == []) == (r["gather"]["outcome"] == "gathered")


def test_gather_is_not_applicable_below_five_robots(tmp_path):
    out = tmp_path / "small.jsonl"
    run = run_sweep(parse_family("gather:10:random:3:1:2"), "gather", out,
                    options=SweepOptions(serial=True))
    records = [r for r in map(json.loads, out.read_text().splitlines()) if "status" in r]
    assert run.complete and all(r["failed"] == [] for r in records)
    assert all(r["gather"]["gathered"] is None for r in records)


@settings(max_examples=60, deadline=None)
@given(st.lists(st.integers(0, 60), max_size=80))
def test_index_set_is_a_set_held_as_intervals(indices):
    from exactsym.sweep.results import IndexSet
    s, plain = IndexSet(), set()
    for i in indices:
        assert s.add(i) == (i not in plain)
        plain.add(i)
    assert len(s) == len(plain)
    assert all((i in s) == (i in plain) for i in range(-1, 62))
    intervals = s.intervals()
    assert all(a < b for a, b in intervals)
    assert all(b1 < a2 for (_, b1), (a2, _) in zip(intervals, intervals[1:]))   # merged


def test_resume_refuses_another_family(serial_run, tmp_path, capsys):
    out = tmp_path / "other.jsonl"
    out.write_text(Path(serial_run).read_text())
    assert main(["roots:12:<=4", "--serial", "--resume", "--out", str(out)]) == 2
    assert "holds a sweep of roots:12:<=5" in capsys.readouterr().err


def test_command_on_an_existing_scheduler(serial_run, tmp_path, capsys):
    from distributed import LocalCluster
    out = tmp_path / "sched.jsonl"
    with LocalCluster(n_workers=1, threads_per_worker=1, processes=True,
                      dashboard_address=None) as cluster:
        code = main([FAMILY, "--what", "audit", "--scheduler", cluster.scheduler_address,
                     "--out", str(out), "--json"])
    data = json.loads(capsys.readouterr().out)
    assert code == 1 and data["workers"] == 1 and data["complete"]
    assert _lines(out) == _lines(serial_run)


def test_a_configuration_over_the_time_limit_is_recorded_and_the_sweep_goes_on(tmp_path,
                                                                               monkeypatch):
    real = bridge.analyse

    def slow(what, points, budget=0):
        if len(points) == 2 and points[1][2] == "1/2":
            time.sleep(1.5)
        return real(what, points, budget)

    monkeypatch.setattr(bridge, "analyse", slow)
    out = tmp_path / "slow.jsonl"
    run = run_sweep(parse_family("roots:12:<=2"), "truth", out,
                    options=SweepOptions(serial=True, timeout=0.2))
    records = list(read_records(out))
    late = [r for r in records if r.get("timeout")]
    assert run.complete and len(records) == 1 + 6
    assert [r["key"] for r in late] == ["roots:12:1:0,6"]          # the diameter
    assert late[0]["status"] == "error" and late[0]["points"]
