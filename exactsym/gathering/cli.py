"""``gather FILE`` and ``replay TRACE``: thin command-line front ends.

``add_arguments(parser)`` / ``run(args)`` for ``gather`` and ``add_replay_arguments`` /
``run_replay`` for ``replay`` let the main CLI wire the commands; :func:`main` builds a
standalone parser (``python -m exactsym.gathering gather FILE ...``).
Exit codes: 0 done and every ``[expect]`` gathering claim holds; 1 done but a claim is
false (or a replay diverges); 2 unusable input (one line on stderr).
"""

from __future__ import annotations

import argparse
import json
import sys
from fractions import Fraction
from pathlib import Path

from . import drawing
from .cases import expectation_failures, run_settings, settings_of
from .invariants import ALL
from .paper_bridge import GatheringInputError, read_case
from .robot import READINGS, Readings
from .schedulers import SCHEDULERS, TraceMismatch
from .output import (checks_line, invariant_title, matrix_table, readings_help, schedule_lines,
                     with_decimals)
from .reading_matrix import differs_from_base, reading_matrix, reading_rows
from ..progress import Progress, ticking
from .search import Bounds, search
from ..version import json_head
from .trace import read_trace, replay, result_dict, same_result, trace_points, write_trace


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("file", help="configuration file (format 1), rational points")
    parser.add_argument("--scheduler", choices=SCHEDULERS, default=None,
                        help="adversary policy (default: the case's, else async)")
    rig = parser.add_mutually_exclusive_group()
    rig.add_argument("--rigid", action="store_true", help="moves reach their target (default)")
    rig.add_argument("--non-rigid", metavar="DELTA", default=None,
                     help="the adversary may stop a move after DELTA (a rational)")
    parser.add_argument("--reading", action="append", default=None, metavar="A1=...",
                        help="a reading of an ambiguous line of the paper, repeatable "
                        "(the first value is the default): " + readings_help(READINGS))
    parser.add_argument("--algorithm", choices=("paper", "corrected"), default=None,
                        help="paper: GatheringPattern and FormGPattern as printed (default, "
                        "or the case's gather_algorithm); corrected: a repaired variant "
                        "(docs/gathering.md)")
    parser.add_argument("--seed", type=int, default=None,
                        help="the random adversary's choices (default: the case's "
                        "gather_seed, else 0); the same seed, the same run")
    parser.add_argument("--search", action="store_true",
                        help="search the adversary's choices for a shortest violation "
                        "(docs/gathering.md, 'The search')")
    parser.add_argument("--budget", type=int, default=None, metavar="N",
                        help="--search: states generated at most (default 10000; "
                        "--readings all: per reading, default 400)")
    parser.add_argument("--depth", type=int, default=16, metavar="D",
                        help="--search: adversary actions per schedule at most (default 16)")
    parser.add_argument("--time", type=float, default=None, metavar="SECONDS",
                        help="--search: wall-clock bound (default 60; --readings all: "
                        "per reading, default 30); a search cut by it is not reproducible "
                        "by its seed alone")
    parser.add_argument("--readings", choices=("all",), default=None,
                        help="all: the reading matrix, one row per named reading "
                        "(docs/interpretations.md)")
    parser.add_argument("--max-events", type=int, default=None, metavar="N",
                        help="stop the run after N events, outcome max-events (default: "
                        "the case's gather_max_events, else 2000)")
    parser.add_argument("--invariants", default=None,
                        help="comma-separated invariants to check (default: all, I1..I10)")
    parser.add_argument("--mid-run", action="store_true",
                        help="the file is a state inside a run: robots may touch (as in a "
                        "partial pattern; any touching pair is accepted), not overlap; the "
                        "paper's hypothesis is a separated start, so a finding from such a "
                        "state is not a counterexample by itself")
    parser.add_argument("--json", action="store_true", help="one JSON object on stdout")
    parser.add_argument("--trace", metavar="OUT", default=None, help="write the trace here")
    parser.add_argument("--no-expect", action="store_true",
                        help="ignore the file's [expect] claims: exit 0 whatever the "
                        "outcome (2 still on an error)")
    drawing.add_arguments(parser)


def add_replay_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("trace", help="a trace written by gather --trace")
    parser.add_argument("file", nargs="?", default=None,
                        help="the configuration file the trace must match (optional)")
    parser.add_argument("--json", action="store_true",
                        help="one JSON object on stdout: the replayed result and the keys "
                        "where it differs from the recorded one")
    drawing.add_arguments(parser)


def _fail(msg: str, command: str = "gather") -> int:
    print(f"exactsym {command}: {msg}", file=sys.stderr)
    return 2


def _settings(args, expect: dict) -> dict:
    s = settings_of(expect)
    if args.scheduler:
        s["scheduler"] = args.scheduler
    if args.seed is not None:
        s["seed"] = args.seed
    if args.algorithm is not None:
        s["algorithm"] = args.algorithm
    if args.max_events is not None:
        s["max_events"] = args.max_events
    if args.reading:
        Readings.parse(args.reading)                    # validates every item
        base = dict(s["readings"])
        base.update(r.split("=", 1) for r in args.reading)
        s["readings"] = Readings(**base).as_dict()
    if args.non_rigid is not None:
        try:
            delta = Fraction(args.non_rigid)
        except (ValueError, ZeroDivisionError):
            raise ValueError(f"--non-rigid needs a rational DELTA, not {args.non_rigid!r}") \
                from None
        if delta <= 0:
            raise ValueError("--non-rigid needs a positive DELTA")
        s["rigid"], s["delta"] = False, str(delta)
    elif args.rigid:
        s["rigid"], s["delta"] = True, None
    if args.invariants is not None:
        inv = [x.strip() for x in args.invariants.split(",") if x.strip()]
        bad = [x for x in inv if x not in ALL]
        if bad:
            raise ValueError(f"unknown invariants {bad} (the invariants are {', '.join(ALL)})")
        s["invariants"] = inv
    return s


MID_RUN_NOTE = ("start: a state inside a run (--mid-run / gather_mid_run: robots may touch); "
                "the paper's start is separated robots, so a finding from here is not by "
                "itself a counterexample")


def _validate_start(points, source, mid_run: bool = False) -> None:
    """The paper's start: at least 5 robots, separated (L1568, L1707-1708).  A mid-run
    state (``--mid-run``, ``[expect] gather_mid_run``) may have touching robots (a
    partial pattern), never overlapping ones."""
    n = len(points)
    if n < 5:
        raise GatheringInputError(f"gathering needs at least 5 robots, the file has {n}",
                                  source)
    for i in range(n):
        for j in range(i + 1, n):
            dx, dy = points[i][0] - points[j][0], points[i][1] - points[j][1]
            d2 = dx * dx + dy * dy
            if mid_run and d2 < 4:
                raise GatheringInputError(f"robots {i} and {j} overlap (centres less than 2 "
                                          "apart)", source)
            if not mid_run and d2 <= 4:
                raise GatheringInputError(f"robots {i} and {j} overlap or touch at the start "
                                          "(centres at most 2 apart; the paper's robots "
                                          "start separated: a state inside a run, with a "
                                          "partial pattern, needs --mid-run)", source)


def _text(res, settings) -> str:
    lines = [f"outcome: {res.outcome}" + (f" ({res.label})" if res.label else ""),
             f"detail: {res.detail}",
             f"algorithm: {settings.get('algorithm', 'paper')}, "
             f"scheduler: {settings['scheduler']}, seed {settings['seed']}, "
             f"{'rigid' if settings['rigid'] else 'non-rigid ' + settings['delta']}, readings "
             + ", ".join(f"{k}={v}" for k, v in settings["readings"].items()),
             f"events: {res.events}, Looks: {res.looks}",
             "invariant checks: " + checks_line(res.checks),
             f"fresh Looks at and between critical instants: {res.checks.get('instants', 0)}"
             f" ({res.checks.get('nested', 0)} at nested radicals, in a tower; "
             f"{res.checks.get('algebraic', 0)} at roots of cubic or quartic factors; "
             f"{res.checks.get('sided', 0)} instants seen on both sides only: no exact "
             f"value held); Looks the kernel could not hold: "
             f"{res.checks.get('skipped', 0)}"]
    if res.violation:
        v = res.violation
        lines.append(f"violation: {invariant_title(v['invariant'], v['label'])} at event "
                     f"{v['instant']}, robots {v['robots']}")
    if res.pattern:
        p = res.pattern
        lines.append(f"final pattern: {p['size']} robots about ({p['centre'][0]}, "
                     f"{p['centre'][1]}), centre robot {p['centre_robot']}, layers "
                     f"{p['layers']}")
    return with_decimals("\n".join(lines))


def _bounds(args, matrix: bool) -> Bounds:
    budget = args.budget if args.budget is not None else (400 if matrix else 10_000)
    seconds = args.time if args.time is not None else (30.0 if matrix else 60.0)
    if budget < 1 or args.depth < 1 or seconds <= 0:
        raise ValueError("--budget, --depth and --time need positive values")
    return Bounds(budget=budget, depth=args.depth, seed=args.seed or 0, seconds=seconds)


def _search_note(report) -> str:
    r = report.as_dict()
    head = (f"search: {r['states']} states, {r['expanded']} expanded, depth {r['depth']}, "
            f"{r['seconds']} s, ended by {r['stopped']}")
    if report.actions is None:
        return head + "; no violation found: the seeded run follows"
    return (head + f"; a violating schedule of {r['found_length']} actions ({r['phase']}), "
            f"shrunk to {r['length']}:\n" + "\n".join(schedule_lines(report.actions)))


def _matrix(points, settings, args, name) -> int:
    bounds = _bounds(args, matrix=True)
    with Progress("gather --readings all", total=len(list(reading_rows(settings["readings"]))),
                  unit=" readings") as bar:
        def step(done, _total, name):
            bar.done, bar.note = done, name
            bar.draw(force=True)
        rows = reading_matrix(points, settings, bounds, progress=step)
    other = differs_from_base(rows)
    if args.json:
        print(json.dumps({**json_head("exactsym-gather-readings", args.file, name),
                          "settings": settings, "matrix": rows,
                          "differs_from_base": [r["reading"] for r in other]}))
        return 0
    print(f"reading matrix of {args.file} (base: the case's readings, "
          + ", ".join(f"{k}={v}" for k, v in settings["readings"].items()) + ")")
    print(matrix_table(rows))
    for r in rows:
        if r["schedule"] and not r["same_as"]:
            print(f"\n{r['reading']}: {with_decimals(r['detail'])}")
            print("\n".join(schedule_lines(r["schedule"])))
    if other:
        print("\nhint: " + ", ".join(r["reading"] for r in other)
              + f" end otherwise than the base reading ({rows[0]['outcome']})")
    return 0


def _pictures(points, res, args, name: str, command: str = "gather") -> int | None:
    """Write the pictures asked for (messages on stderr when --json); 2 on failure."""
    if not drawing.wants_pictures(args):
        return None
    try:
        with ticking("pictures"):
            lines = drawing.write_pictures(points, res, args, name)
    except drawing.PicturesUnavailable as err:
        return _fail(str(err), command)
    except (OSError, ValueError) as err:
        return _fail(f"cannot write the pictures: {err}", command)
    for line in lines:
        print(f"picture: {line}", file=sys.stderr if args.json else sys.stdout)
    return None


def run(args) -> int:
    try:
        points, name, expect, source = read_case(args.file)
        mid_run = bool(args.mid_run or expect.get("gather_mid_run", False))
        _validate_start(points, source, mid_run)
        settings = _settings(args, expect)
    except GatheringInputError as err:
        return _fail(str(err))
    except (ValueError, ZeroDivisionError) as err:
        return _fail(str(err))
    note, report = None, None
    try:
        if args.readings == "all":
            return _matrix(points, settings, args, name)
        bounds = _bounds(args, matrix=False) if args.search else None
    except ValueError as err:
        return _fail(str(err))
    if args.search:
        with ticking("gather --search", bounds.seconds, timed=True):
            report = search(points, settings, bounds)
        note = _search_note(report)
        res = report.result if report.result is not None else run_settings(points, settings)
    else:
        with ticking("gather"):         # on a terminal only; the run reports nothing
            res = run_settings(points, settings)
    failures = [] if args.no_expect else expectation_failures(expect, res)
    if args.trace:
        try:
            write_trace(args.trace, points, res, settings, Path(args.file).name)
        except OSError as err:
            return _fail(f"cannot write the trace: {err}")
    if args.json:
        out = json_head("exactsym-gather", args.file, name)
        out.update(result_dict(res))
        out.update(settings=settings, expect_failures=failures,
                   search=None if report is None else report.as_dict(),
                   start="mid-run" if mid_run else "separated")
        print(json.dumps(out))
    else:
        if mid_run:
            print(MID_RUN_NOTE)
        if note:
            print(note)
        print(_text(res, settings))
        if res.outcome == "max-events" and args.trace:
            print(f"stopped at --max-events; trace written to {args.trace}")
    failed = _pictures(points, res, args, Path(args.file).name)
    if failed:
        return failed
    for f in failures:
        print(f"{args.file}: {f}", file=sys.stderr)
    return 1 if failures else 0


def run_replay(args) -> int:
    try:
        data = read_trace(args.trace)
        points = None
        if args.file is not None:
            points = read_case(args.file)[0]
        res = replay(data, points)
    except (TraceMismatch, GatheringInputError) as err:
        return _fail(str(err), "replay")
    diff = same_result(data["result"], res)
    if args.json:
        print(json.dumps({**json_head("exactsym-replay", args.trace, data.get("name")),
                          "replayed": result_dict(res), "differs_on": diff}))
    else:
        print(f"replayed {len(data['actions'])} actions: outcome {res.outcome}"
              + (f" ({res.label})" if res.label else "")
              + f", {res.events} events, {res.looks} Looks")
        print("identical to the recorded run" if not diff else
              f"DIFFERS from the recorded run on: {', '.join(diff)}")
    failed = _pictures(points if points is not None else trace_points(data), res, args,
                       data.get("name") or Path(args.trace).name, "replay")
    if failed:
        return failed
    return 1 if diff else 0


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m exactsym.gathering")
    sub = parser.add_subparsers(dest="command", required=True)
    add_arguments(sub.add_parser("gather", help="run the gathering simulator on a file"))
    add_replay_arguments(sub.add_parser("replay", help="re-run a trace exactly"))
    try:
        args = parser.parse_args(argv)
    except SystemExit as exc:
        return int(exc.code or 0)
    return run(args) if args.command == "gather" else run_replay(args)
