"""The ``plot`` command: ``exactsym plot FILE [-o OUT] [--show-paper] [--show-audit]``.

:func:`add_arguments` and :func:`run` are for the main command line to wire; :func:`main`
is a standalone entry (``python -m exactsym.pictures FILE -o out.svg``).
"""

from __future__ import annotations

import argparse
import sys

EXAMPLE = "example: exactsym plot cases/examples/chiral-nine-gon.toml -o nine.svg --show-audit"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("file", help="configuration file ('-' reads standard input)")
    parser.add_argument("-o", "--output", default=None,
                        help="picture to write: .svg, .png or .pdf (default: FILE's name "
                             "with .svg, in the current directory)")
    parser.add_argument("--show-paper", action="store_true",
                        help="also draw the lines of symmetry the paper's tests report "
                             "and the paper's leader")
    parser.add_argument("--show-audit", action="store_true",
                        help="also draw the witness of each statement of the paper that "
                             "fails here")


def _default_output(file: str) -> str:
    from pathlib import Path
    return "stdin.svg" if file == "-" else Path(file).with_suffix(".svg").name


def run(args) -> int:
    """Draw ``args.file``; print the path written.  Exit status 0, or 2 (unusable input,
    unknown format, matplotlib missing) with one line on standard error."""
    from . import PlotUnavailable, plot
    from ._bridge import InputError
    out = args.output or _default_output(args.file)
    try:
        plot(args.file, out, show_paper=args.show_paper, show_audit=args.show_audit)
    except PlotUnavailable as err:
        print(f"exactsym plot: {err}", file=sys.stderr)
        return 2
    except ValueError as err:       # unknown picture format
        print(f"exactsym plot: {err}", file=sys.stderr)
        return 2
    except InputError as err:       # the library's: "file:line:col: ..."
        print(f"exactsym plot: {err}", file=sys.stderr)
        return 2
    except OSError as err:          # the picture cannot be written: a path, a permission,
        # a full disk (reading errors are InputErrors above)
        print(f"exactsym plot: cannot write {out}: {err.strerror or err}", file=sys.stderr)
        return 2
    print(out)
    return 0


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(
        prog="python -m exactsym.pictures",
        description="Draw a configuration: robots, SEC, levels, the ground truth's mirrors "
                    "and rotation centre, its leader and ordering.", epilog=EXAMPLE)
    add_arguments(parser)
    return run(parser.parse_args(argv))
