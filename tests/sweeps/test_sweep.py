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

from exactsym.sweeps import analysis_bridge as bridge
from exactsym.sweeps import job
from exactsym.sweeps.cli import main
from exactsym.sweeps.engine import SweepOptions, run_sweep
from exactsym.sweeps.families import family_items, parse_family, rank
from exactsym.sweeps.results import read_records
from exactsym.sweeps.summary import ledger_evidence, summarise, write_cases

FAMILY = "roots:12:<=5"
ROOT = Path(__file__).resolve().parents[2]


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
    # a singleton is in O_S by def-symmetric-conf yet orderable: outside Pasym-Pord's
    # hypotheses (lemma 1, n > 1), so not a failure; one ring of at most 5 robots on the
    # 12th roots has no chiral (C3) configuration, so Pasym-Pord does not fail here
    pasym = next(e for e in summary.labels if e.label == "Pasym-Pord")
    assert pasym.smallest is None and pasym.failures == 0 and pasym.outside == 1


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
    proc = subprocess.Popen([sys.executable, "-m", "exactsym.sweeps", FAMILY, "--what", "audit",
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
                        "undecided-at-budget", "max-events"}
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
    from exactsym.sweeps.results import IndexSet
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


def test_a_single_robot_is_outside_the_hypotheses_of_pasym_pord():
    # One robot is in O_S by def-symmetric-conf and trivially orderable: the literal
    # "only if" of Pasym-Pord fails, but its proof is lemma 1 (n > 1): not a failure.
    one = bridge.analyse("audit", [("polar", "1", "0")])
    assert {"Pasym-Pord", "cor-Pasym-Pord"} <= set(one["outside"])
    assert not {"Pasym-Pord", "cor-Pasym-Pord"} & set(one["failed"])
    assert not {"Pasym-Pord", "cor-Pasym-Pord", "GatheringPattern"} & set(one["applicable"])
    # three robots of a chiral C3 ring (turns 0, 1/3, 2/3 plus 1/12 shifts) do refute it
    c3 = [("polar", "1", t) for t in ("0", "1/3", "2/3")] + \
        [("polar", "2", t) for t in ("1/12", "5/12", "3/4")]
    res = bridge.analyse("audit", c3)
    assert "Pasym-Pord" in res["failed"] and res["outside"] == []
    assert res["truth"]["group"] == "C3"


def test_gathering_pattern_is_applicable_from_five_robots_only(serial_run):
    for record in read_records(serial_run):
        if record["status"] == "ok":
            assert ("GatheringPattern" in record["applicable"]) == (record["n"] >= 5)
            assert ("MakeAsym" in record["applicable"] + record["failed"]) <= \
                (record["n"] >= 5)
            assert set(record["outside"]) <= {"Pasym-Pord", "cor-Pasym-Pord", "MakeAsym"}
            assert not set(record["outside"]) - {"MakeAsym"} or record["n"] == 1
    summary = summarise(serial_run)
    by = {e.label: e for e in summary.labels}
    assert by["Pasym-Pord"].outside == 1 and by["cor-Pasym-Pord"].outside == 1
    evidence = {i["statement"]: i for i in ledger_evidence(summary, {})["evidence"]}
    assert "outside its hypotheses" in evidence["Pasym-Pord"]["text"]


def test_reading_and_procedure_findings_are_not_failures():
    # a scalene triangle on the grid: orderable (C1); the audit blames lem-asym-ord for
    # the paper electing nobody, differently in mirrored frames: the claim holds
    tri = [("xy", "0", "0"), ("xy", "1", "0"), ("xy", "2", "1")]
    res = bridge.analyse("audit", tri)
    assert res["truth"]["orderable"] and "lem-asym-ord" in res["procedure"]
    assert "lem-asym-ord" not in res["failed"] and "lem-asym-ord" in res["applicable"]
    # the isosceles right triangle: lemma-straight-sym false only under the literal reading
    right = [("polar", "1", t) for t in ("0", "1/4", "1/2")]
    res = bridge.analyse("audit", right)
    assert "lemma-straight-sym" in res["reading"] and "lemma-straight-sym" not in res["failed"]
    # a C3 ring is a genuine counterexample to lem-asym-ord: not orderable
    c3 = [("polar", "1", f"{t}/24") for t in (0, 1, 3, 8, 9, 11, 16, 17, 19)]
    res = bridge.analyse("audit", c3)
    assert res["truth"]["group"] == "C3" and "lem-asym-ord" in res["failed"]


def _records(path) -> list:
    return sorted(json.dumps(r, sort_keys=True) for r in read_records(path))


def test_killed_gzip_sweep_resumes_to_the_same_records(serial_run, tmp_path):
    """A .gz results file: killed with SIGKILL half-way (the gzip member left unterminated,
    maybe a torn block), resumed, it holds the same records as the plain serial run."""
    out = tmp_path / "killed.jsonl.gz"
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    proc = subprocess.Popen([sys.executable, "-m", "exactsym.sweeps", FAMILY, "--what", "audit",
                             "--serial", "--batch-size", "1", "--out", str(out)],
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env)
    deadline = time.monotonic() + 60
    while time.monotonic() < deadline and proc.poll() is None:
        if out.exists() and len(list(read_records(out))) > 20:
            break
        time.sleep(0.005)
    assert proc.poll() is None                    # killed half-way, not after the end
    proc.send_signal(signal.SIGKILL)
    proc.wait()
    assert 20 <= len(list(read_records(out))) < 86
    with open(out, "ab") as f:                    # a torn compressed block after the kill
        f.write(b"\x1f\x8b\x08\x00garbage")
    code = main([FAMILY, "--what", "audit", "--serial", "--resume", "--out", str(out),
                 "--json"])
    assert code == 1
    assert _records(out) == _records(serial_run)
    assert out.stat().st_size * 5 < serial_run.stat().st_size      # it is compressed
    # and a second resume of the complete file adds nothing
    again = run_sweep(parse_family(FAMILY), "audit", out, resume=True,
                      options=SweepOptions(serial=True))
    assert again.new == 0 and again.skipped == 86 and _records(out) == _records(serial_run)


def test_paper_sweep_sets_aside_instances_outside_the_hypotheses(tmp_path):
    # the family layer marks lem-los-gij / theorem-los-g1n instances outside the text's
    # hypotheses (within_hypotheses false), and MakeAsym runs below 5 robots here
    out = tmp_path / "p.jsonl.gz"
    run_sweep(parse_family("grid:4:<=4"), "paper", out, options=SweepOptions(serial=True))
    by = {e.label: e for e in summarise(out).labels}
    for label in ("lem-los-gij", "theorem-los-g1n", "MakeAsym"):
        assert by[label].failures == 0 and by[label].outside > 0, label
    assert by["MakeAsym"].applicable == 0 and by["obs-merg-asym-pair"].failures > 0


def test_workers_without_dask_is_one_line_exit_2(tmp_path, capsys, monkeypatch):
    """Dask is the 'sweep' extra: a base install asking for workers gets one line, exit 2."""
    monkeypatch.setitem(sys.modules, "distributed", None)     # import distributed fails
    code = main(["roots:6:<=3", "--what", "truth", "--workers", "2",
                 "--out", str(tmp_path / "w.jsonl")])
    err = capsys.readouterr().err
    assert code == 2 and "'.[sweep]'" in err and len(err.strip().splitlines()) == 1


def test_a_sweep_that_cannot_start_leaves_no_results_file(tmp_path, capsys, monkeypatch):
    """Issue 34: without Dask, ``--workers 2`` exits 2 and writes nothing, so the same
    command runs once Dask is there (it was refused: "results file exists")."""
    out = tmp_path / "r.jsonl"
    command = ["roots:6:<=3", "--what", "truth", "--workers", "2", "--out", str(out)]
    with monkeypatch.context() as m:
        m.setitem(sys.modules, "distributed", None)
        assert main(command) == 2
    assert not out.exists()
    capsys.readouterr()
    assert main(command[:3] + ["--serial", "--out", str(out)]) == 0
    assert out.exists() and "results file exists" not in capsys.readouterr().err
