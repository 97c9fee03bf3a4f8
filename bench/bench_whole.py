"""Issue 33's rows for ``exactsym check`` as the user runs it: the whole command in a process
of its own (start-up, imports, reading, analysis, writing the JSON to a pipe that is
thrown away), against the float yardstick run the same way (``--float FILE``: Python,
NumPy's import, :func:`bench_truth.float_pipeline` on the same file), in alternating
processes (A B A B ...): each row's ratio is the median of the pairs' ratios of CPU
seconds (user + system of the finished child, ``os.wait4``), so that a machine whose
speed drifts moves both sides of a pair alike.  Peak memory is the child's ``ru_maxrss``.

Run: ``python bench/bench_whole.py`` (all rows), or name rows: ``random100k d4 random1m
random1m-summary``; ``--runs N`` pairs per row (default 3).  Print ``uptime`` beside the
figures: the machine may be shared.

Targets (issue 33): 100,000 random rational points at most 6 times the yardstick; the
100,000-point D4 set at most 5 times; 1,000,000 random points under 15 s and 1.5 GB
(``--json`` and the summary).

Last figures (December 2026, 3 pairs per row, load falling from 7.6 to 2.2 on 2 cores;
yardstick, check, ratio, peak RSS): 100,000 random 0.61 s, 2.28 s, 3.7x, 189 MB (met);
D4 0.57 s, 3.35 s, 5.9x, 233 MB (missed; 5.4x in a run under load 18); 10^6 random
``--json`` 5.13 s, 20.3 s, 4.2x, 1,474 MB (memory met, time missed), summary 20.4 s,
1,475 MB.  Before this round (same rows): 5.0-5.6x; 5.8x; 31 s and 2,218 MB.
"""

from __future__ import annotations

import os
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))


def _inputs():
    from bench_truth import d4_text, random_text
    return {"random100k": lambda: random_text(100_000, 7),
            "d4": lambda: d4_text(100_000, 8),
            "random1m": lambda: random_text(1_000_000, 7)}


#: row -> (what, input, the command's arguments after the file, target: (ratio, seconds, MB))
ROWS = {
    "random100k": ("100,000 random rational points, check --json", "random100k",
                   ["--json"], (6, None, None)),
    "d4": ("100,000 points D4, check --json", "d4", ["--json"], (5, None, None)),
    "random1m": ("1,000,000 random points, check --json", "random1m", ["--json"],
                 (None, 15, 1536)),
    "random1m-summary": ("1,000,000 random points, check (summary)", "random1m", [],
                         (None, 15, 1536)),
}


def run_process(argv: list[str]) -> tuple[float, float, float]:
    """``(cpu seconds, wall seconds, peak RSS in MB)`` of one whole process, its output
    read through a pipe and thrown away."""
    import time
    t0 = time.perf_counter()
    proc = subprocess.Popen(argv, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL)
    while proc.stdout.read(1 << 20):
        pass
    _, status, usage = os.wait4(proc.pid, 0)
    proc.returncode = os.waitstatus_to_exitcode(status)
    wall = time.perf_counter() - t0
    if proc.returncode not in (0, 1):
        raise RuntimeError(f"{argv} exited {proc.returncode}")
    return usage.ru_utime + usage.ru_stime, wall, usage.ru_maxrss / 1024


def float_main(path: str) -> int:
    from bench_truth import float_pipeline
    print(float_pipeline(Path(path)))
    return 0


def main(argv: list[str]) -> int:
    if len(argv) == 2 and argv[0] == "--float":
        return float_main(argv[1])
    runs = 3
    if "--runs" in argv:
        runs = int(argv[argv.index("--runs") + 1])
    rows = [a for a in argv if a in ROWS] or list(ROWS)
    made = {}
    tmp = Path(tempfile.mkdtemp())
    with open("/proc/loadavg") as f:
        print(f"load average at start: {' '.join(f.read().split()[:3])}")
    print(f"CPU seconds of whole processes, median of {runs} alternating pairs "
          "(exactsym, yardstick); ratio = median of the pairs' ratios; peak RSS of the command")
    print(f"{'row':<46}{'yard':>7}{'check':>8}{'ratio':>7}{'wall':>7}{'RSS MB':>8}  target")
    ok = True
    for row in rows:
        what, key, extra, (limit, seconds, mb) = ROWS[row]
        if key not in made:
            made[key] = tmp / f"{key}.txt"
            made[key].write_text(_inputs()[key]())
        path = str(made[key])
        a_cmd = [sys.executable, "-m", "exactsym", "check", path, *extra]
        b_cmd = [sys.executable, str(HERE / "bench_whole.py"), "--float", path]
        pairs = []
        for _ in range(runs):
            a = run_process(a_cmd)
            b = run_process(b_cmd)
            pairs.append((a, b))
        cpu = statistics.median(a[0] for a, _ in pairs)
        wall = statistics.median(a[1] for a, _ in pairs)
        rss = statistics.median(a[2] for a, _ in pairs)
        yard = statistics.median(b[0] for _, b in pairs)
        ratio = statistics.median(a[0] / b[0] for a, b in pairs)
        met = True
        target = []
        if limit is not None:
            met &= ratio <= limit
            target.append(f"<= {limit}x")
        if seconds is not None:
            met &= cpu < seconds and rss < mb
            target.append(f"< {seconds} s, < {mb / 1024:.1f} GB")
        ok &= met
        print(f"{what:<46}{yard:>7.2f}{cpu:>8.2f}{ratio:>7.1f}{wall:>7.2f}{rss:>8.0f}  "
              f"{', '.join(target)}: {'met' if met else 'MISSED'}", flush=True)
    with open("/proc/loadavg") as f:
        print(f"load average at end: {' '.join(f.read().split()[:3])}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
