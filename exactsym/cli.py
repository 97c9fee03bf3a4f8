"""The ``exactsym`` command: parse arguments, call the library, print.

Exit codes (``../shared/spec/cli-1.md``): 0 done and every claim holds; 1 a claim,
expectation or certificate is false; 2 unusable input or command line; 3 an
internal error (a bug: please report it with the input).
"""

from __future__ import annotations

import argparse
import json
import sys

from .errors import InputError

EXIT_OK, EXIT_FALSE, EXIT_INPUT, EXIT_BUG = 0, 1, 2, 3


class _Parser(argparse.ArgumentParser):
    def error(self, message):
        raise InputError(f"command line: {message}")


def _table(report: dict) -> str:
    lines = [f"n = {report['n']}   number field: {report.get('number_field', 'Q')}",
             f"SEC centre ({report['sec']['center'][0]}, {report['sec']['center'][1]}), "
             f"radius^2 = {report['sec']['radius_squared']}",
             f"{len(report['levels'])} level(s), nearest first (points counter-clockwise):"]
    for k, level in enumerate(report["levels"], 1):
        lines.append(f"  G{k}: radius^2 = {level['radius_squared']}   points {level['points']}")
        if "paper" in level and level["paper"]:
            lines.append(f"      paper: {level['paper']}")
    for extra in report.get("_table_lines", []):
        lines.append(extra)
    return "\n".join(lines)


def _cmd_check(args) -> int:
    from .configuration import load
    from .report import check_report, failed_expectations
    config = load(args.file)
    report = check_report(config, {"strings": getattr(args, "strings", False)})
    table_lines = report.pop("_table_lines", None)
    if args.json:
        print(json.dumps(report, indent=None if args.compact else 2))
    else:
        if table_lines:
            report["_table_lines"] = table_lines
        print(_table(report))
    failures = failed_expectations(config, report)
    for failure in failures:
        print(f"{config.source}: {failure}", file=sys.stderr)
    return EXIT_FALSE if failures else EXIT_OK


COMMANDS: dict = {"check": _cmd_check}


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(prog="exactsym", description="Exact checker for the leader election and "
                     "gathering algorithms of Gan Chaudhuri and Mukhopadhyaya.")
    sub = parser.add_subparsers(dest="command", required=True, parser_class=_Parser)
    check = sub.add_parser("check", help="analyse a configuration file ('-' for standard input)")
    check.add_argument("file")
    check.add_argument("--json", action="store_true", help="one JSON object on standard output")
    check.add_argument("--compact", action="store_true", help="with --json: on one line")
    check.add_argument("--strings", action="store_true", help="include the CW/ACW strings")
    for register in EXTRA_COMMANDS:
        register(sub)
    return parser


#: Functions ``(subparsers) -> None`` adding commands; later modules append to it.
EXTRA_COMMANDS: list = []


def main(argv: list[str] | None = None) -> int:
    try:
        _load_plugins()
        args = build_parser().parse_args(argv)
        return COMMANDS[args.command](args)
    except InputError as err:
        print(f"exactsym: {err}", file=sys.stderr)
        return EXIT_INPUT
    except KeyboardInterrupt:
        return 130
    except RecursionError:
        print("exactsym: input nested too deeply", file=sys.stderr)
        return EXIT_INPUT
    except Exception as err:  # a traceback reaching a user is a bug: say so in one line
        print(f"exactsym: internal error ({type(err).__name__}: {err}); please report it "
              "with the input file", file=sys.stderr)
        return EXIT_BUG


def _load_plugins() -> None:
    """Import the modules that add report sections and commands."""
    import importlib
    for name in PLUGINS:
        try:
            importlib.import_module(name)
        except ModuleNotFoundError as err:
            if err.name != name:      # only a layer not written yet may be absent
                raise


#: Modules imported before the command line is parsed (each registers its report
#: sections in ``report.SECTIONS`` and its commands in ``EXTRA_COMMANDS``/``COMMANDS``).
PLUGINS: list[str] = [
    "exactsym.truth_report",          # ground truth: group, orderable, ordering, leader
    "exactsym.certify_cli",           # certify / verify
    "exactsym.paper.polygon_report",  # the paper, one polygon at a time
    "exactsym.paper.family_report",   # the paper on whole configurations, audit
    "exactsym.cases_cli",             # cases: run the case library
]


def entry() -> None:
    sys.exit(main())


if __name__ == "__main__":
    entry()
