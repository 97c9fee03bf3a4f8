"""Pictures of a run from its JSON form (:func:`exactsym.pictures.run.run_from_dict`).

``python -m exactsym.pictures.run_cli RUN.json --plot run.svg --frames DIR --gif run.gif
--html run.html``.  :func:`add_arguments` / :func:`outputs` are for ``exactsym gather``
to reuse once the simulator gives a :class:`exactsym.pictures.run.Run`.
"""

from __future__ import annotations

import argparse
import json
import sys


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--plot", metavar="OUT", help="the whole run in one picture "
                        "(.svg, .png or .pdf)")
    parser.add_argument("--frames", metavar="DIR", help="one PNG per event in DIR")
    parser.add_argument("--gif", metavar="OUT", help="an animated GIF of the frames")
    parser.add_argument("--html", metavar="OUT", help="one self-contained HTML page to step "
                        "through the frames (no server)")


def outputs(run, args) -> list[str]:
    """Write what ``args`` asks for; return lines to print."""
    from .run import plot_run, write_frames, write_gif, write_html
    lines = []
    if args.plot:
        lines.append(str(plot_run(run, args.plot)))
    if args.frames:
        frames = write_frames(run, args.frames)
        lines.append(f"{args.frames}: {len(frames)} frames")
    if args.gif:
        gif = write_gif(run, args.gif)
        lines.append(str(gif) if gif else
                     f"{args.gif}: not written (the GIF needs pillow: pip install pillow)")
    if args.html:
        lines.append(str(write_html(run, args.html)))
    return lines


def main(argv=None) -> int:
    from .draw import PlotUnavailable
    from .run import run_from_dict
    parser = argparse.ArgumentParser(prog="python -m exactsym.pictures.run_cli",
                                     description="Draw a run given as JSON.",
                                     epilog="example: python -m exactsym.pictures.run_cli "
                                            "docs/examples/synthetic-run.json --html run.html")
    parser.add_argument("run", help="the run, as JSON")
    add_arguments(parser)
    args = parser.parse_args(argv)
    try:
        with open(args.run, encoding="utf-8") as f:
            run = run_from_dict(json.load(f))
        for line in outputs(run, args):
            print(line)
    except (OSError, ValueError, KeyError, TypeError, PlotUnavailable) as err:
        print(f"{args.run}: {err}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
