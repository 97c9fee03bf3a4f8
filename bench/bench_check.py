"""Benchmark of the whole ``exactsym check --json`` pipeline (library calls, not a
subprocess per check): load, ``check_report`` with every section (ground truth, the paper
per level, the family layer and its audit) and the JSON text, against the truth-only part
(load + rings + symmetry_group, as ``bench/bench_truth.py`` times it).

Run: ``python bench/bench_check.py`` (``--quick`` skips the 100,000-point case).

Targets (the family layer's bounds, ``docs/interpretations.md``): on 100,000 random
rational points the whole check at most about 2 times the truth-only part and under 1 GB;
on a polar C7-symmetric set of 70,000 points and a polar regular 10,000-gon, seconds.
Each case runs in a child process of its own, so that its peak RSS is its own.
"""

from __future__ import annotations

import json
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from bench_truth import c7_polar_text, random_text  # noqa: E402


def polygon_text(n: int) -> str:
    """A polar regular n-gon on the unit circle."""
    return "".join(f"polar 1 {k}/{n}\n" for k in range(n))


CASES = {
    "random100k": ("100,000 random rational points", lambda: random_text(100_000, 7)),
    "c7polar": ("C7-symmetric polar, 70,000", lambda: c7_polar_text(70_000, 9)),
    "gon10k": ("polar regular 10,000-gon", lambda: polygon_text(10_000)),
}


def run_case(key: str) -> dict:
    from exactsym.configuration import load
    from exactsym.levels import levels_of
    from exactsym.report import check_report
    from exactsym.symmetry import symmetry_group

    path = Path(tempfile.mkdtemp()) / f"{key}.txt"
    path.write_text(CASES[key][1]())
    t0 = time.perf_counter()
    config = load(path)
    group = symmetry_group(config, levels_of(config))
    t1 = time.perf_counter()
    config = load(path)
    report = check_report(config)
    t_report = time.perf_counter()
    text = json.dumps(report, indent=2)
    t2 = time.perf_counter()
    paper, audit = report["paper"], report["audit"]
    return {"truth": t1 - t0, "check": t2 - t1, "json": t2 - t_report, "group": group.name,
            "levels": len(report["levels"]), "trace": len(paper["trace"]),
            "json_mb": len(text) / 1e6, "bounded": paper.get("bounded", {}),
            "paper_orderable": paper["orderable"], "leader": paper["leader"],
            "audit_agrees": audit["agrees"],
            "rss_mb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024}


def main(argv: list[str]) -> int:
    if len(argv) == 2 and argv[0] == "--child":
        print(json.dumps(run_case(argv[1])))
        return 0
    keys = [k for k in CASES if not ("--quick" in argv and k == "random100k")]
    print("seconds (wall clock); 'truth' = load + rings + symmetry_group, 'check' = load + "
          "check_report (all sections) + JSON text (indent 2, as the command writes it); "
          "'(json)' = the JSON text's share")
    print(f"{'input':<34}{'levels':>8}{'truth':>8}{'check':>8}{'ratio':>7}{'(json)':>8}"
          f"{'RSS MB':>8}{'trace':>7}{'JSON MB':>9}  pairs checked   target")
    ok = True
    for key in keys:
        out = subprocess.run([sys.executable, __file__, "--child", key], capture_output=True,
                             text=True)
        if out.returncode != 0:
            print(f"{CASES[key][0]:<34} failed:\n{out.stderr}")
            ok = False
            continue
        r = json.loads(out.stdout)
        ratio = r["check"] / r["truth"]
        if key == "random100k":
            met, target = ratio <= 2.2 and r["rss_mb"] < 1024, "ratio <= ~2, < 1 GB"
        else:
            met, target = r["check"] < 30, "seconds (< 30 s)"
        ok &= met
        b = r["bounded"]
        pairs = f"{b.get('family_claims_pairs_checked', '-')}/{b.get('of', '-')}"
        print(f"{CASES[key][0]:<34}{r['levels']:>8}{r['truth']:>8.2f}{r['check']:>8.2f}"
              f"{ratio:>7.1f}{r['json']:>8.2f}{r['rss_mb']:>8.0f}{r['trace']:>7}"
              f"{r['json_mb']:>9.1f}  "
              f"{pairs:<15} {target}: {'met' if met else 'MISSED'}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
