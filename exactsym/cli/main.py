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
import gc
import importlib
import io
import os
import sys
import textwrap

from ..version import __version__
from ..errors import EXIT_BUG, EXIT_FALSE, EXIT_INPUT, EXIT_OK, InputError


class _Parser(argparse.ArgumentParser):
    def error(self, message):
        raise InputError(f"command line: {message}")


def _check_arguments(parser) -> None:
    parser.add_argument("files", nargs="+", metavar="FILE",
                        help="configuration file(s); '-' reads standard input")
    parser.add_argument("--json", action="store_true",
                        help="one JSON object on standard output (one FILE only)")
    parser.add_argument("--compact", action="store_true", help="with --json: on one line")
    parser.add_argument("--strings", action="store_true",
                        help="include each level's CW/ACW strings")
    parser.add_argument("-v", "--verbose", action="store_true",
                        help="the per-level detail, the paper's trace, every discrepancy")


#: The last analysis of ``check`` when run as the command (:func:`entry`), else None.
_KEPT: list | None = None


def _check(args) -> int:
    # imported here, not at the top: `exactsym --version`, `--help` and the other commands
    # should not pay for the whole analysis (0.3 s of imports)
    from ..analysis import Options, analyse
    from ..geometry.configuration import load, no_cycle_collection
    from ..report.check import failed_expectations, report_json, report_text, write_json
    if len(args.files) > 1:
        return _check_several(args)
    # one pause of the cycle collector for the whole command: each re-enabling after a
    # bulk construction costs a full collection over every object built so far
    with no_cycle_collection():
        config = load(args.files[0])
        # the summary shows each false statement's first witness: list one per statement
        summary = not (args.json or args.verbose or config.expect)
        analysis = analyse(config, options=Options(strings=args.strings,
                                                   listed=1 if summary else None,
                                                   screen=summary))
        if _KEPT is not None:
            # freed at the end of the process, not object by object (:func:`entry`);
            # the cyclic collector, on again after this block, leaves them alone
            _KEPT[:] = [analysis]
            gc.freeze()
        # the JSON report (every exact text) only when printed or read by [expect]
        # printed and not read again: the levels' entries are made as they are written
        report = report_json(analysis, streamed=not config.expect) \
            if args.json or config.expect else None
        if args.json:
            write_json(report, sys.stdout, compact=args.compact)
        else:
            print(report_text(analysis, verbose=args.verbose))
    failures = failed_expectations(config, report) if config.expect else []
    for failure in failures:
        print(f"{config.source}: {failure}", file=sys.stderr)
    return EXIT_FALSE if failures else EXIT_OK


def _check_several(args) -> int:
    """One summary line per file (the full report each with --verbose); the exit status
    is the worst of the files' (a file that cannot be read does not stop the others)."""
    from ..analysis import Options, analyse
    from ..geometry.configuration import load
    from ..report.check import failed_expectations, report_json, report_text
    from ..report.summary import one_line
    worst = EXIT_OK
    for k, path in enumerate(args.files):
        try:
            config = load(path)
            summary = not (args.verbose or config.expect)      # one line: no witness shown
            analysis = analyse(config, options=Options(strings=args.strings,
                                                       listed=1 if summary else None,
                                                       screen=summary))
            failures = (failed_expectations(config, report_json(analysis))
                        if config.expect else [])
        except InputError as err:
            print(f"exactsym: {err}", file=sys.stderr)
            worst = max(worst, EXIT_INPUT)
            continue
        if args.verbose:
            print(("\n" if k else "") + report_text(analysis, verbose=True))
        else:
            print(one_line(analysis, len(failures)))
        for failure in failures:
            print(f"{config.source}: {failure}", file=sys.stderr)
        worst = max(worst, EXIT_FALSE if failures else EXIT_OK)
    return worst


def _deferred(module: str, name: str):
    """``module.name``, imported when first called: ``exactsym check`` need not import the
    other commands' modules (networkx, the gathering simulator, the ledger: a third of a
    second of CPU per run before any work)."""
    def call(*args):
        return getattr(importlib.import_module(module), name)(*args)
    call.__name__ = name
    call.__qualname__ = f"{module}.{name}"
    return call


#: name -> (help, add the arguments to a subparser, run: args -> exit code)
COMMANDS = {
    "check": ("analyse configuration files ('-' for standard input): a summary of each "
              "(one line per file when several; --verbose: the detail; --json: everything)",
              _check_arguments, _check),
    "audit": ("the paper's family algorithms against the ground truth (exit 1 when some "
              "statement fails on the configuration)",
              _deferred("exactsym.cli.audit", "add_arguments"),
              _deferred("exactsym.cli.audit", "run")),
    "certify": ("write a certificate of the symmetry verdict",
                _deferred("exactsym.cli.certify", "add_certify_arguments"),
                _deferred("exactsym.cli.certify", "run_certify")),
    "verify": ("check a certificate with the independent checker",
               _deferred("exactsym.cli.certify", "add_verify_arguments"),
               _deferred("exactsym.cli.certify", "run_verify")),
    "cases": ("run the case library (every file under DIR)",
              _deferred("exactsym.cli.cases", "add_arguments"),
              _deferred("exactsym.cli.cases", "run")),
    "gather": ("simulate the paper's gathering algorithm under an adversarial scheduler "
               "(exit 1 when an [expect] claim is false)",
               _deferred("exactsym.gathering.cli", "add_arguments"),
               _deferred("exactsym.gathering.cli", "run")),
    "replay": ("re-run a gathering trace exactly, event for event",
               _deferred("exactsym.gathering.cli", "add_replay_arguments"),
               _deferred("exactsym.gathering.cli", "run_replay")),
    "ledger": ("the statement ledger (proofs/, in a checkout): grades and dependencies; "
               "--check re-runs the evidence, --write regenerates docs/audit.md",
               _deferred("exactsym.ledger.cli", "add_arguments"),
               _deferred("exactsym.ledger.cli", "run")),
    "sweep": ("search a whole family of configurations for counterexamples, serially or "
              "on a Dask cluster (exit 1 when some statement fails)",
              _deferred("exactsym.sweeps.cli", "add_arguments"),
              _deferred("exactsym.sweeps.cli", "run")),
    "plot": ("draw a configuration: robots, SEC, levels, mirrors, leader (svg, png or pdf)",
             _deferred("exactsym.pictures.cli", "add_arguments"),
             _deferred("exactsym.pictures.cli", "run")),
}


#: An example for each command's --help (``exactsym COMMAND --help``).
EXAMPLES = {
    "check": ["exactsym check cases/examples/chiral-nine-gon.toml",
              "exactsym check --verbose cases/polygon/kite-polar.toml",
              "exactsym check cases/polygon/*.toml          # one line per file",
              "exactsym check --json --compact cases/examples/rational-pentagon.txt"],
    "audit": ["exactsym audit cases/examples/chiral-nine-gon.toml"],
    "certify": ["exactsym certify cases/polygon/kite-polar.toml -o kite.cert.json"],
    "verify": ["exactsym verify kite.cert.json"],
    "cases": ["exactsym cases", "exactsym cases --lemma Pasym-Pord",
              "exactsym cases --labels"],
    "gather": ["exactsym gather cases/gathering/obstacle-beside-path.toml",
               "exactsym gather FILE --scheduler async --seed 3 --trace run.json",
               "exactsym gather FILE --search --reading A3=all"],
    "replay": ["exactsym replay run.json"],
    "ledger": ["exactsym ledger", "exactsym ledger --check", "exactsym ledger --write",
               "exactsym ledger --sweep r12.evidence.json --save roots_12_le6"],
    "sweep": ["exactsym sweep 'roots:12:<=6' --what audit --workers 2 --out r12.jsonl",
              "exactsym sweep 'grid:4:<=4' --what paper --serial --out g4.jsonl --json",
              "exactsym sweep 'roots:12:<=6' --what audit --out r12.jsonl --resume",
              "exactsym sweep 'roots:24:<=6' --what audit --out r24.jsonl.gz"],
    "plot": ["exactsym plot cases/examples/chiral-nine-gon.toml -o nine.svg --show-audit"],
}

#: Options that apply only together with another one: command -> {option: needed option}.
NEEDS_OPTION = {"check": {"compact": "json"}}
#: Options that do not apply together: command -> pairs of options.
EXCLUSIVE = {"check": [("json", "verbose")], "cases": [("labels", "lemma")]}


def _flag(dest: str) -> str:
    return "--" + dest.replace("_", "-")


def _reject_options_that_do_not_apply(args) -> None:
    for option, needed in NEEDS_OPTION.get(args.command, {}).items():
        if getattr(args, option, None) and not getattr(args, needed, None):
            raise InputError(f"command line: {_flag(option)} applies only with {_flag(needed)}")
    for a, b in EXCLUSIVE.get(args.command, []):
        if getattr(args, a, None) and getattr(args, b, None):
            raise InputError(f"command line: {_flag(a)} and {_flag(b)} do not go together")
    if args.command == "check" and args.json and len(args.files) > 1:
        raise InputError("command line: --json takes one FILE (run once per file)")


def build_parser(only: str | None = None) -> argparse.ArgumentParser:
    """The parser of every command; with ``only``, the other commands' subparsers get no
    arguments (their modules are not imported: they will not run)."""
    parser = _Parser(prog="exactsym", description="Exact checker for the leader election and "
                     "gathering algorithms\nof Gan Chaudhuri and Mukhopadhyaya.",
                     epilog="example: exactsym check cases/examples/chiral-nine-gon.toml\n"
                            "help on a command: exactsym COMMAND --help",
                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--version", action="version", version=f"exactsym {__version__}")
    sub = parser.add_subparsers(dest="command", required=True, parser_class=_Parser)
    for name, (text, add_arguments, _) in COMMANDS.items():
        examples = EXAMPLES.get(name, [])
        epilog = ("example" + ("s" if len(examples) > 1 else "") + ":\n" +
                  "\n".join("  " + e for e in examples)) if examples else None
        description = textwrap.fill(text[:1].upper() + text[1:] + ".", 88)
        command = sub.add_parser(name, help=text, description=description, epilog=epilog,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
        if only is None or name == only:
            add_arguments(command)
    return parser


class _QuietStdout:
    """Standard output that ends quietly when the reader goes away (``exactsym check F |
    head -1``): from the first broken pipe on, output goes to /dev/null and the command
    runs to its end, so its exit status is still the true one."""

    def __init__(self, stream):
        self._stream = stream
        self.reader_gone = False

    def _gone(self) -> None:
        self.reader_gone = True
        try:
            devnull = os.open(os.devnull, os.O_WRONLY)
            os.dup2(devnull, self._stream.fileno())   # the buffer's rest goes nowhere
            os.close(devnull)
        except (OSError, ValueError, io.UnsupportedOperation):
            pass

    def write(self, text: str) -> int:
        if not self.reader_gone:
            try:
                try:
                    return self._stream.write(text)
                except UnicodeEncodeError:      # a terminal without UTF-8: plain ASCII
                    return self._stream.write(_ascii(text))
            except BrokenPipeError:
                self._gone()
        return len(text)

    def flush(self) -> None:
        if not self.reader_gone:
            try:
                self._stream.flush()
            except BrokenPipeError:
                self._gone()

    def __getattr__(self, name):
        return getattr(self._stream, name)


def _ascii(text: str) -> str:
    for wide, narrow in (("≈", "~"), ("…", "...")):
        text = text.replace(wide, narrow)
    return text.encode("ascii", "replace").decode("ascii")


def main(argv: list[str] | None = None) -> int:
    stdout = sys.stdout = _QuietStdout(sys.stdout)
    try:
        return _main(argv)
    finally:
        sys.stdout.flush()
        if sys.stdout is stdout:
            sys.stdout = stdout._stream


def _main(argv: list[str] | None) -> int:
    try:
        try:
            words = sys.argv[1:] if argv is None else argv
            if not words:                   # `exactsym` alone: what it can do
                build_parser("").print_help()
                return EXIT_OK
            # `--version`, `--help` before any command: no command's arguments are built
            # (building them imports every command's modules: 0.7 s for a version string)
            only = words[0] if words[0] in COMMANDS else "" if all(
                w in ("--version", "-h", "--help") for w in words) else None
            args = build_parser(only).parse_args(argv)
        except SystemExit as done:          # --help, --version
            return done.code if isinstance(done.code, int) else EXIT_OK
        _reject_options_that_do_not_apply(args)
        return COMMANDS[args.command][2](args)
    except InputError as err:
        print(f"exactsym: {err}", file=sys.stderr)
        return EXIT_INPUT
    except KeyboardInterrupt:
        return 130
    except RecursionError:
        print("exactsym: input nested too deeply", file=sys.stderr)
        return EXIT_INPUT
    except BrokenPipeError:                 # a pipe other than standard output
        return EXIT_OK
    except Exception as err:  # a traceback reaching a user is a bug: say so in one line
        print(f"exactsym: internal error ({type(err).__name__}: {err}); please report it "
              "with the input file", file=sys.stderr)
        return EXIT_BUG


def entry() -> None:
    global _KEPT
    _KEPT = []
    code = main()
    if not _KEPT or sys.getprofile() is not None or sys.gettrace() is not None:
        # not a check of one file, or under a profiler or a coverage tracer (which write
        # their data at exit): end as usual, atexit handlers run
        sys.exit(code)
    # a check's output is complete: end the process without freeing what it built one
    # object at a time (a check of 100,000 robots holds millions of small objects, and
    # freeing them cost a tenth of the command; at a million, seconds).  Only `check`
    # of one file, from the command's own entry point; main() returns as any function.
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except (BrokenPipeError, ValueError, OSError):
            pass
    os._exit(code if isinstance(code, int) else EXIT_OK)


if __name__ == "__main__":
    entry()
