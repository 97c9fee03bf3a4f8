"""Benchmark of the whole ``exactsym check --json`` pipeline (library calls, not a
subprocess per check): load, ``check_report`` with every section (ground truth, the paper
per level, the family layer and its audit) and the JSON text as the command writes it,
against the truth-only part (load + rings + symmetry_group, as ``bench/bench_truth.py``
times it) and against the float yardstick (``bench_truth.float_pipeline``: the same file
read as doubles, centroid, polar sort, tolerant rotation test), all in CPU seconds of one
child process.

Run: ``python bench/bench_check.py`` (``--quick`` skips the 100,000-point cases,
``--small`` runs only the small algebraic inputs; or name cases: ``random100k d4``).

Targets: issue 9, full check at most 6 times the float yardstick on 100,000 random
rational points and at most 10 times on the 100,000-point D4 set, and under 5 s on small
algebraic inputs (three points with sqrt(2), sqrt(3), sqrt(5), sqrt(7); 32 points with
C4 symmetry written with cos/sin of multiples of pi/2310); the family layer's bounds
(``docs/interpretations.md``): under 1 GB on 100,000 random points, seconds on a polar
C7-symmetric set of 70,000 points and a polar regular 10,000-gon.  Each case runs in a
child process of its own, so that its peak RSS is its own.
"""

from __future__ import annotations

import json
import random
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from bench_truth import c7_polar_text, d4_text, float_pipeline, random_text  # noqa: E402


def polygon_text(n: int) -> str:
    """A polar regular n-gon on the unit circle."""
    return "".join(f"polar 1 {k}/{n}\n" for k in range(n))


def sqrt_text() -> str:
    """Three points with four square roots (one field of degree 192)."""
    return "sqrt(2) sqrt(3)\nsqrt(5) 0\n0 sqrt(7)\n"


def c4_cos_text(seeds: int = 8, seed: int = 4) -> str:
    """C4 orbits of ``seeds`` points r (cos, sin)(k pi/2310) (32 points for 8 seeds)."""
    rnd = random.Random(seed)
    lines = []
    for _ in range(seeds):
        k, r = rnd.randint(1, 2309), rnd.randint(1, 9)
        c, s = f"{r}*cos({k}*pi/2310)", f"{r}*sin({k}*pi/2310)"
        lines += [f"{c} {s}", f"-{r}*sin({k}*pi/2310) {c}", f"-{c} -{r}*sin({k}*pi/2310)",
                  f"{s} -{c}"]
    return "\n".join(lines) + "\n"


#: Small algebraic inputs: no float yardstick (its reader takes rationals only).
SMALL = ("sqrt4", "c4cos32")

CASES = {
    "random100k": ("100,000 random rational points", lambda: random_text(100_000, 7)),
    "d4": ("D4-symmetric, 100,000 rational", lambda: d4_text(100_000, 8)),
    "c7polar": ("C7-symmetric polar, 70,000", lambda: c7_polar_text(70_000, 9)),
    "gon10k": ("polar regular 10,000-gon", lambda: polygon_text(10_000)),
    "sqrt4": ("3 points, sqrt(2), sqrt(3), sqrt(5), sqrt(7)", sqrt_text),
    "c4cos32": ("32 points C4, cos/sin of k pi/2310", c4_cos_text),
}


def run_case(key: str) -> dict:
    from exactsym.geometry.configuration import load, no_cycle_collection
    from exactsym.geometry.levels import levels_of
    from exactsym.report.check import check_report, json_text
    from exactsym.truth.symmetry import symmetry_group

    path = Path(tempfile.mkdtemp()) / f"{key}.txt"
    path.write_text(CASES[key][1]())
    clock = time.process_time
    t0 = clock()
    config = load(path)
    group = symmetry_group(config, levels_of(config))
    t1 = clock()
    with no_cycle_collection():        # as the command does
        config = load(path)
        report = check_report(config)
        t_report = clock()
        text = json_text(report)
    t2 = clock()
    yardstick = float("inf")
    for _ in range(1 if key in SMALL else 3):       # the fastest of three: a shared machine
        f0 = clock()
        if key not in SMALL:
            float_pipeline(path)
        yardstick = min(yardstick, clock() - f0)
    paper, audit = report["paper"], report["audit"]
    return {"truth": t1 - t0, "check": t2 - t1, "json": t2 - t_report, "group": group.name,
            "float": yardstick,
            "levels": len(report["levels"]), "trace": len(paper["trace"]),
            "json_mb": len(text) / 1e6, "bounded": paper.get("bounded", {}),
            "paper_orderable": paper["orderable"], "leader": paper["leader"],
            "audit_agrees": audit["agrees"],
            "rss_mb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024}


def main(argv: list[str]) -> int:
    if len(argv) == 2 and argv[0] == "--child":
        print(json.dumps(run_case(argv[1])))
        return 0
    named = [a for a in argv if a in CASES]
    if named:
        keys = named
    elif "--small" in argv:
        keys = list(SMALL)
    else:
        keys = [k for k in CASES if not ("--quick" in argv and k in ("random100k", "d4"))]
    print("CPU seconds; 'truth' = load + rings + symmetry_group, 'check' = load + "
          "check_report (all sections) + JSON text (as the command writes it); "
          "'(json)' = the JSON text's share; 'float' = the float yardstick on the same file (fastest of 3)")
    print(f"{'input':<44}{'levels':>7}{'float':>7}{'truth':>8}{'check':>8}{'x float':>8}"
          f"{'(json)':>7}{'RSS MB':>8}{'JSON MB':>8}  target")
    ok = True
    for key in keys:
        out = subprocess.run([sys.executable, __file__, "--child", key], capture_output=True,
                             text=True)
        if out.returncode != 0:
            print(f"{CASES[key][0]:<44} failed:\n{out.stderr}")
            ok = False
            continue
        r = json.loads(out.stdout)
        ratio = r["check"] / r["float"] if key not in SMALL else float("nan")
        if key == "random100k":
            met, target = ratio <= 6 and r["rss_mb"] < 1024, "<= 6x float, < 1 GB"
        elif key == "d4":
            met, target = ratio <= 10, "<= 10x float"
        elif key in SMALL:
            met, target = r["check"] < 5, "< 5 s"
        else:
            met, target = r["check"] < 30, "seconds (< 30 s)"
        ok &= met
        print(f"{CASES[key][0]:<44}{r['levels']:>7}{r['float'] if key not in SMALL else '-':>7.3}"
              f"{r['truth']:>8.2f}"
              f"{r['check']:>8.2f}{ratio:>8.1f}{r['json']:>7.2f}{r['rss_mb']:>8.0f}"
              f"{r['json_mb']:>8.1f}  {target}: {'met' if met else 'MISSED'}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
