"""Benchmark: issue 33's near-miss inputs and its ten nested radicals, as whole processes.

Robots at cos/sin of j/468 and j/702 turns on the unit circle, forming a C12 set (two orbits
of 12, turns (39k + 5)/468 and (39k + 17)/468) and a D9 set (one orbit of 18, turns
(78k +- 7)/702), with one robot moved off by a hair, so that the whole ``exactsym check``
must decide exactly that the set is asymmetric: its x plus 1/10^9 (off the circle: each
point lies on the SEC to within 2e-16 in doubles), its turn plus 1/10^9 (on the circle,
in a sparse Q(zeta_N) with N near 10^12), its radius times 1 + 1/10^9.  (A C12 set of 18
points on one circle does not exist: its orbits have 12 points; the issue's C12 row is
read as a C12 set of 24.)  The last row is bench/bench_small_algebraic.py's ten points on
ten nested radicals sqrt(1 + sqrt(p)).

Each input is written to a temporary file and ``exactsym check --json FILE`` runs in a
child process (its output thrown away); the CPU seconds (user + system) of the child are
the median of ``--repeat`` runs (default 3), printed beside the figure before the change
of issue 33 (:data:`BEFORE`, same machine, medians of three runs) and their
ratio, against the target of issue 33 (< 5 s).  Run: ``python bench/bench_near_miss.py``
(``--only NAME``, ``--timeout S``; ``--print NAME`` writes one input to stdout).
``--against DIR``: the "before" column is measured, not quoted: the same input checked by
the source tree in DIR (a checkout of an earlier commit, put first on PYTHONPATH), in
alternation with this one (the machine's load falls on both alike).
"""

from __future__ import annotations

import argparse
import os
import resource
import statistics
import subprocess
import sys
import tempfile
from fractions import Fraction
from pathlib import Path

HAIR = Fraction(1, 10 ** 9)
TARGET = 5.0

#: CPU seconds of ``check --json`` before issue 33's changes to the exact layer (the dense
#: products of cosine forms, the Kummer proof of a non-square radicand): medians of three
#: runs in alternation with the new code, load 13-20 on 2 cores, December 2026
BEFORE = {
    "near C12 j/468, x + hair": 2.89,
    "near C12 j/468, turn + hair": 0.96,
    "near C12 j/468, radius + hair": 2.59,
    "near D9 j/702, x + hair": 13.24,
    "near D9 j/702, turn + hair": 1.13,
    "near D9 j/702, radius + hair": 4.25,
    "10 nested radicals, 10 pts": 5.96,
}


def _cos_sin(turn: Fraction, factor: str = "", shift: str = "") -> tuple[str, str]:
    turn %= 1
    angle = f"2*pi*{turn.numerator}/{turn.denominator}"
    return f"{factor}cos({angle}){shift}", f"{factor}sin({angle})"


def _cartesian(points) -> str:
    return "format = 1\npoints = [\n" + "".join(f'  ["{x}", "{y}"],\n' for x, y in points) + "]\n"


def near_miss(turns: list[Fraction], how: str) -> str:
    """The points at ``turns`` with the first moved by a hair: ``x`` (its x plus 1/10^9),
    ``turn`` (its turn plus 1/10^9) or ``radius`` (its radius times 1 + 1/10^9)."""
    first = {"x": _cos_sin(turns[0], shift=f" + {HAIR}"),
             "turn": _cos_sin(turns[0] + HAIR),
             "radius": _cos_sin(turns[0], factor=f"{1 + HAIR}*")}[how]
    return _cartesian([first] + [_cos_sin(t) for t in turns[1:]])


def inputs() -> dict[str, str]:
    """The inputs by name."""
    c12 = [Fraction(39 * k + a, 468) for a in (5, 17) for k in range(12)]
    d9 = [Fraction(78 * k + a, 702) for k in range(9) for a in (7, -7)]
    out = {}
    for label, turns in (("near C12 j/468", c12), ("near D9 j/702", d9)):
        for how in ("x", "turn", "radius"):
            out[f"{label}, {how} + hair"] = near_miss(turns, how)
    primes = (2, 3, 5, 7, 11, 13, 17, 19, 23, 29)
    out["10 nested radicals, 10 pts"] = _cartesian(
        [(f"sqrt(1+sqrt({p}))", str(i)) for i, p in enumerate(primes)])
    return out


def _children_cpu() -> float:
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def check_cpu(path: Path, timeout: float, source: str | None = None) -> float | None:
    """CPU seconds of one ``exactsym check --json`` child, or None (timeout or failure);
    ``source``: the source tree the child imports exactsym from (else the installed one)."""
    env = None
    if source is not None:
        env = dict(os.environ, PYTHONPATH=os.pathsep.join(
            [source] + [p for p in [os.environ.get("PYTHONPATH")] if p]))
    before = _children_cpu()
    try:
        done = subprocess.run([sys.executable, "-m", "exactsym", "check", "--json", str(path)],
                              stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, timeout=timeout,
                              env=env)
    except subprocess.TimeoutExpired:
        return None
    return _children_cpu() - before if done.returncode in (0, 1) else None


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--only")
    parser.add_argument("--timeout", type=float, default=300.0)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--print", dest="show")
    parser.add_argument("--against", help="source tree of the earlier version, run in turn")
    opts = parser.parse_args()
    if opts.show:
        sys.stdout.write(inputs()[opts.show])
        return
    print(f"{'input (check --json, CPU s)':32} {'now':>7} {'before':>7} {'ratio':>6}  target")
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "input.toml"
        for name, text in inputs().items():
            if opts.only and opts.only not in name:
                continue
            path.write_text(text)
            runs, earlier = [], []
            for _ in range(opts.repeat):
                if opts.against:
                    earlier.append(check_cpu(path, opts.timeout, opts.against))
                runs.append(check_cpu(path, opts.timeout))
            if None in runs:
                print(f"{name:32} {'-':>7}  failed or timeout ({opts.timeout:.0f} s)", flush=True)
                continue
            now = statistics.median(runs)
            before = BEFORE.get(name) if not opts.against else \
                None if None in earlier else statistics.median(earlier)
            ratio = f"{now / before:6.2f}" if before else f"{'-':>6}"
            shown = f"{before:7.2f}" if before else f"{'-':>7}"
            verdict = "ok" if now < TARGET else "MISSED"
            print(f"{name:32} {now:7.2f} {shown} {ratio}  < {TARGET:g} s {verdict}", flush=True)


if __name__ == "__main__":
    main()
