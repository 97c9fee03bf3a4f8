"""``exactsym sweep FAMILY --what truth|paper|audit|gather|gather-corrected --out RESULTS``: the command.

Thin: parse, call :func:`.engine.run_sweep` and :mod:`.summary`, print.  The lead wires it
into ``exactsym`` with :func:`add_arguments` and :func:`run`; :func:`main` is the same
command on its own (``python -m exactsym.sweeps``).

Exit codes (``docs/cli.md``): 0 done and no statement fails on any configuration
examined; 1 some statement fails, or some configuration could not be analysed (both named
on stderr); 2 unusable family, results file or command line (or the gathering simulator
is missing); 3 an internal error.
"""

from __future__ import annotations

import argparse
import importlib.util
import json
import os
import sys
from pathlib import Path

from . import analysis_bridge as bridge
from .engine import DEFAULT_TIMEOUT, SweepOptions, run_sweep
from .families import FamilyError, family_size, parse_family
from .results import ResultsError, remove_if_unstarted
from .summary import ledger_evidence, summarise, summary_json, summary_table, write_cases
from ..version import json_head

__all__ = ["add_arguments", "run", "main"]

EXIT_OK, EXIT_FALSE, EXIT_INPUT, EXIT_BUG = 0, 1, 2, 3


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """The sweep's arguments, on ``parser`` (a subcommand's parser)."""
    parser.add_argument("family", metavar="FAMILY",
                        help="roots:M:K[:RINGS], grid:N:K, random:K:SEED:COUNT, "
                             "algebraic:K:M:SEED:COUNT, perturb:FILE:EPS:COUNT or "
                             "gather:BUDGET[+STATES]:FAMILY (K: 5, <=6, 3..6)")
    parser.add_argument("--what", choices=bridge.WHATS, default="audit",
                        help="the analysis run on each configuration (default audit)")
    where = parser.add_mutually_exclusive_group()
    where.add_argument("--workers", type=int, default=None, metavar="N",
                       help="workers of a local Dask cluster (default: in this process on "
                       "2 cores or fewer or below 1,000 configurations, else a cluster of "
                       "one worker per core, at most 8: docs/sweeps.md)")
    where.add_argument("--scheduler", metavar="ADDRESS",
                       help="an existing Dask scheduler, e.g. tcp://host:8786")
    where.add_argument("--serial", action="store_true",
                       help="no Dask: analyse in this process (for comparison)")
    parser.add_argument("--out", required=True, metavar="RESULTS",
                        help="the results file (JSON lines, keyed by canonical form)")
    parser.add_argument("--resume", action="store_true",
                        help="continue an interrupted sweep in RESULTS")
    parser.add_argument("--json", action="store_true", help="print the summary as JSON")
    parser.add_argument("--cases", metavar="DIR",
                        help="where the smallest counterexamples' case files go "
                             "(default: RESULTS without its suffix, plus -cases)")
    parser.add_argument("--evidence", metavar="FILE",
                        help="the ledger evidence file (default: RESULTS without its "
                             "suffix, plus .evidence.json)")
    parser.add_argument("--batch-size", type=int, metavar="N",
                        help="configurations per Dask task (default: adaptive, ~1 s each)")
    parser.add_argument("--timeout", type=float, default=DEFAULT_TIMEOUT, metavar="SECONDS",
                        help="record a configuration taking longer as an error "
                             f"(default {DEFAULT_TIMEOUT:g}; 0: no limit)")
    parser.add_argument("--stop-after", type=int, metavar="N",
                        help="stop after N new results, as an interrupted sweep would")


#: Below this many configurations a local cluster's start (2 to 3 s) costs more than its
#: workers save; on 2 cores the workers share the cores with the scheduler and each other
#: (docs/sweeps.md, "When workers pay off": 136 configurations took 1.9 s serially and
#: 4.0 s on 2 workers, 2,432 took 36.9 s and 35.3 s)
CLUSTER_MIN = 1000
MAX_DEFAULT_WORKERS = 8


def _where(args, family) -> tuple[bool, int]:
    """``(serial, workers)``: what the command line says, else the measured default."""
    if args.serial or args.scheduler or args.workers is not None:
        return args.serial, args.workers or 2
    cores = os.cpu_count() or 1
    if cores <= 2 or family_size(family) < CLUSTER_MIN or \
            importlib.util.find_spec("distributed") is None:
        return True, 1
    return False, min(cores, MAX_DEFAULT_WORKERS)


def _paths(args) -> tuple[Path, Path]:
    out = Path(args.out)
    stem = out.with_suffix("") if out.suffix else out
    if out.suffix == ".gz" and stem.suffix:          # r.jsonl.gz: r-cases, r.evidence.json
        stem = stem.with_suffix("")
    cases = Path(args.cases) if args.cases else Path(f"{stem}-cases")
    evidence = Path(args.evidence) if args.evidence else Path(f"{stem}.evidence.json")
    return cases, evidence


def run(args) -> int:
    """Run the command on parsed ``args``; returns the exit code."""
    try:
        return _run(args)
    except (FamilyError, ResultsError, bridge.BridgeInputError) as err:
        print(f"exactsym sweep: {err}", file=sys.stderr)
        return EXIT_INPUT
    except KeyboardInterrupt:
        print("exactsym sweep: interrupted; continue with --resume", file=sys.stderr)
        return 130


def _run(args) -> int:
    if args.workers is not None and args.workers < 1:
        raise FamilyError("--workers must be at least 1")
    family = parse_family(args.family, bridge.file_points)
    if family.kind == "gather" and family.states and args.what != "gather-corrected":
        raise FamilyError("gather:EVENTS+STATES: the searching adversary is run with "
                          "--what gather-corrected")
    if family.kind == "gather" and args.what not in ("gather", "gather-corrected"):
        raise FamilyError("a gather: family is swept with --what gather or gather-corrected")
    serial, workers = _where(args, family)
    options = SweepOptions(workers=workers, scheduler=args.scheduler,
                           serial=serial, batch_size=args.batch_size,
                           stop_after=args.stop_after, progress=sys.stderr,
                           timeout=args.timeout if args.timeout and args.timeout > 0 else None)
    fresh = not Path(args.out).exists()
    try:
        sweep = run_sweep(family, args.what, args.out, args.resume, options)
    except BaseException:
        # a run that could not start (no Dask, no scheduler) leaves no results file
        # behind: the same command must work once the cause is fixed
        if fresh:
            remove_if_unstarted(args.out)
        raise
    summary = summarise(args.out)
    cases_dir, evidence_path = _paths(args)
    cases = write_cases(summary, cases_dir)
    evidence = ledger_evidence(summary, cases, str(args.out))
    evidence_path.write_text(json.dumps(evidence, indent=1) + "\n", encoding="utf-8")
    if args.json:
        data = json_head("exactsym-sweep", str(args.out), args.family)
        data.update(summary_json(summary, cases))
        data.update(complete=sweep.complete, new=sweep.new, skipped=sweep.skipped,
                    seconds=round(sweep.seconds, 3), workers=sweep.workers,
                    utilisation=None if sweep.utilisation is None else
                    round(sweep.utilisation, 3), evidence=str(evidence_path))
        print(json.dumps(data, indent=1))
    else:
        print(summary_table(summary, cases))
        print(f"this run: {sweep.new:,} new, {sweep.skipped:,} already in {args.out}, "
              f"{sweep.seconds:.1f} s on "
              f"{'this process' if args.serial else f'{sweep.workers} worker(s)'}"
              + ("" if sweep.utilisation is None else
                 f" (workers analysing {sweep.utilisation:.0%} of the time)")
              + ("" if sweep.complete else "; stopped early: continue with --resume"))
        print(f"evidence for the ledger: {evidence_path}")
    failing = [e.label for e in summary.labels if e.failures]
    if failing:
        print(f"exactsym sweep: false on some configuration of {family.text}: "
              f"{', '.join(failing)}", file=sys.stderr)
    if summary.errors:
        print(f"exactsym sweep: {summary.errors} configuration(s) could not be analysed "
              f"(status \"error\" in {args.out}, with their input)", file=sys.stderr)
    return EXIT_FALSE if failing or summary.errors else EXIT_OK


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m exactsym.sweeps",
                                     description="Sweep a family of configurations.")
    add_arguments(parser)
    args = parser.parse_args(argv)
    try:
        return run(args)
    except Exception as err:  # a traceback reaching a user is a bug: say so in one line
        print(f"exactsym sweep: internal error ({type(err).__name__}: {err}); please "
              "report it with the command line", file=sys.stderr)
        return EXIT_BUG
