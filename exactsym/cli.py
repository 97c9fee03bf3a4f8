"""The ``exactsym`` command: parse arguments, call the library, print.

Exit codes (``docs/cli.md``): 0 done and every claim holds; 1 a claim, expectation or
certificate is false; 2 unusable input or command line; 3 an internal error (a bug:
please report it with the input).

Every command is one row of :data:`COMMANDS`: its name, its help line, a function adding
its arguments to its subparser and a function running it (``args -> exit code``).  To add
a command, write those two functions in its module and add one row here.
"""

from __future__ import annotations

import argparse
import json
import sys

from . import audit_cli, cases_cli, certify_cli
from .gathering import cli as gather_cli
from .ledger import cli as ledger_cli
from .plot import cli as plot_cli
from .analysis import Options, analyse
from .configuration import load
from .errors import EXIT_BUG, EXIT_FALSE, EXIT_INPUT, EXIT_OK, InputError
from .report import failed_expectations, report_json, report_text


class _Parser(argparse.ArgumentParser):
    def error(self, message):
        raise InputError(f"command line: {message}")


def _check_arguments(parser) -> None:
    parser.add_argument("file")
    parser.add_argument("--json", action="store_true", help="one JSON object on standard output")
    parser.add_argument("--compact", action="store_true", help="with --json: on one line")
    parser.add_argument("--strings", action="store_true", help="include the CW/ACW strings")


def _check(args) -> int:
    config = load(args.file)
    analysis = analyse(config, options=Options(strings=args.strings))
    report = report_json(analysis)
    if args.json:
        print(json.dumps(report, indent=None if args.compact else 2))
    else:
        print(report_text(analysis))
    failures = failed_expectations(config, report)
    for failure in failures:
        print(f"{config.source}: {failure}", file=sys.stderr)
    return EXIT_FALSE if failures else EXIT_OK


#: name -> (help, add the arguments to a subparser, run: args -> exit code)
COMMANDS = {
    "check": ("analyse a configuration file ('-' for standard input)",
              _check_arguments, _check),
    "audit": ("the paper's family algorithms against the ground truth (exit 1 when some "
              "statement fails on the configuration)", audit_cli.add_arguments, audit_cli.run),
    "certify": ("write a certificate of the symmetry verdict",
                certify_cli.add_certify_arguments, certify_cli.run_certify),
    "verify": ("check a certificate with the independent checker",
               certify_cli.add_verify_arguments, certify_cli.run_verify),
    "cases": ("run the case library (every file under DIR)",
              cases_cli.add_arguments, cases_cli.run),
    "gather": ("simulate the paper's gathering algorithm under an adversarial scheduler "
               "(exit 1 when an [expect] claim is false)", gather_cli.add_arguments,
               gather_cli.run),
    "replay": ("re-run a gathering trace exactly, event for event",
               gather_cli.add_replay_arguments, gather_cli.run_replay),
    "ledger": ("the statement ledger (proofs/): grades, dependencies, docs/audit.md; --check "
               "re-runs the evidence", ledger_cli.add_arguments, ledger_cli.run),
    "plot": ("draw a configuration (needs the 'plot' extra: matplotlib)",
             plot_cli.add_arguments, plot_cli.run),
}


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(prog="exactsym", description="Exact checker for the leader election and "
                     "gathering algorithms of Gan Chaudhuri and Mukhopadhyaya.")
    sub = parser.add_subparsers(dest="command", required=True, parser_class=_Parser)
    for name, (text, add_arguments, _) in COMMANDS.items():
        add_arguments(sub.add_parser(name, help=text))
    return parser


def main(argv: list[str] | None = None) -> int:
    try:
        args = build_parser().parse_args(argv)
        return COMMANDS[args.command][2](args)
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


def entry() -> None:
    sys.exit(main())


if __name__ == "__main__":
    entry()
