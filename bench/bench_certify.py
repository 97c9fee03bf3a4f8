"""Benchmark of certificates: ``exactsym verify`` (the independent checker) against
``exactsym check`` on the same configuration.  Run: ``python bench/bench_certify.py [--full]``.

Target (issue 3): verifying a certificate takes at most a third of the time of checking, on a
100,000-point D4 rational set and a 70,000-point polar C7 set.  "check" is timed as the part of
``exactsym check`` that reaches the verdict the certificate proves: reading the file, the SEC and
levels, and the symmetry group (the stricter comparison).  With ``--full`` the whole
``exactsym check`` command (with every report layer, the paper's algorithms included) is timed
too.  Also shown: ``certify`` (which also runs the checker once on what it writes), and the
part of ``verify`` that proves the canonical ordering and the leader (issue 9, point 6): the
verify time minus that of the same certificate without ``claim.ordering`` and ``claim.leader``.
The third input, 100,000 random rational points (C1, orderable), is where the whole ordering
is proved (the angular walk over 100,000 points and leastness over 100,000 rays); on the
symmetric sets only the leader is.  Timings on a shared machine vary by 2x between runs: the
ratio, measured in one process, is the figure to compare.
"""

from __future__ import annotations

import contextlib
import io
import json
import random
import sys
import tempfile
import time
from pathlib import Path

from exactsym import checker
from exactsym.cli.main import main as cli_main
from exactsym.geometry.configuration import load
from exactsym.geometry.levels import levels_of
from exactsym.truth.symmetry import symmetry_group


def d4_rational(path: Path, n: int = 100_000, seed: int = 3) -> None:
    """n points, n/8 free D4 orbits about (1/3, -2/7): no point on a mirror line."""
    rnd = random.Random(seed)
    cx, cy = (1, 3), (-2, 7)
    bases = set()
    while len(bases) < n // 8:
        a, b = rnd.randint(1, 10 ** 6), rnd.randint(1, 1000)
        c, d = rnd.randint(1, 10 ** 6), rnd.randint(1, 1000)
        if a * d > c * b:                       # 0 < y < x: off every mirror of D4
            bases.add(((a, b), (c, d)))
    lines = []
    for (a, b), (c, d) in bases:
        for sx, sy, swap in ((1, 1, 0), (-1, 1, 1), (-1, -1, 0), (1, -1, 1),
                             (1, -1, 0), (1, 1, 1), (-1, 1, 0), (-1, -1, 1)):
            (p, q), (r, s) = ((a, b), (c, d)) if not swap else ((c, d), (a, b))
            lines.append(f"{sx * p}/{q}+{cx[0]}/{cx[1]} {sy * r}/{s}+{cy[0]}/{cy[1]}\n")
    path.write_text("".join(lines))


def c7_polar(path: Path, n: int = 70_000, seed: int = 5) -> None:
    """n points, n/7 orbits of the rotation by 1/7 turn about the origin, no mirror."""
    rnd = random.Random(seed)
    bases = set()
    while len(bases) < n // 7:
        bases.add((rnd.randint(1, 1000), rnd.randint(0, 999_999)))
    lines = [f"polar {r} {t}/7000000+{j}/7\n" for r, t in bases for j in range(7)]
    path.write_text("".join(lines))


def c1_random(path: Path, n: int = 100_000, seed: int = 7) -> None:
    """n random rational points (asymmetric: orderable, the whole ordering certified)."""
    rnd = random.Random(seed)
    pts = set()
    while len(pts) < n:
        pts.add((rnd.randint(-10 ** 6, 10 ** 6), rnd.randint(-10 ** 6, 10 ** 6)))
    path.write_text("".join(f"{x}/997 {y}/991\n" for x, y in pts))


def timed(fn, *args, repeat: int = 2):
    """Best of ``repeat`` runs (the machine is shared: the minimum is the stable figure)."""
    best, result = float("inf"), None
    for _ in range(repeat):
        start = time.perf_counter()
        result = fn(*args)
        best = min(best, time.perf_counter() - start)
    return best, result


def run_truth(path: Path):
    config = load(path)
    return symmetry_group(config, levels_of(config)).name


def run_check(path: Path):
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        cli_main(["check", str(path), "--json", "--compact"])
    return json.loads(out.getvalue())["group"]


def run_certify(path: Path, cert: Path):
    with contextlib.redirect_stdout(io.StringIO()):
        return cli_main(["certify", str(path), "-o", str(cert)])


def run_verify(cert: Path, ordering: bool = True):
    with open(cert, encoding="utf-8") as fh:
        data = json.load(fh)
    if not ordering:                            # the group part only
        del data["claim"]["ordering"], data["claim"]["leader"]
    return checker.verify_certificate(data)


def main(argv: list[str]) -> int:
    full = "--full" in argv
    tmp = Path(tempfile.mkdtemp())
    cases = (("100,000-point D4 rational set", "d4.txt", d4_rational, "D4"),
             ("70,000-point polar C7 set", "c7.txt", c7_polar, "C7"),
             ("100,000 random rational points", "c1.txt", c1_random, "C1"))
    print(f"{'input':<32}{'check s':>9}{'certify s':>11}{'verify s':>10}{'ordering s':>12}"
          f"{'verify/check':>14}  target")
    ok = True
    for label, name, make, group in cases:
        path, cert = tmp / name, tmp / (name + ".cert.json")
        make(path)
        t_check, found = timed(run_truth, path)
        assert found == group, found
        t_certify, code = timed(run_certify, path, cert, repeat=1)
        assert code == 0, code
        t_verify, (valid, message) = timed(run_verify, cert, repeat=3)
        assert valid, message
        t_group, _ = timed(run_verify, cert, False, repeat=3)
        ratio = t_verify / t_check
        met = ratio <= 1 / 3
        ok &= met
        print(f"{label:<32}{t_check:>9.2f}{t_certify:>11.2f}{t_verify:>10.2f}"
              f"{t_verify - t_group:>12.2f}{ratio:>14.3f}  "
              f"<= 0.333: {'met' if met else 'MISSED'} ({message}; "
              f"{cert.stat().st_size / 1e6:.1f} MB)")
        if full:
            t_full, found = timed(run_check, path, repeat=1)
            print(f"{'  whole exactsym check':<32}{t_full:>9.2f}{'':>11}{t_verify:>10.2f}{'':>12}"
                  f"{t_verify / t_full:>14.3f}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
