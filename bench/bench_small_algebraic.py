"""Benchmark: the small algebraic inputs of issue 9, truth alone and full ``check``.

Each input is written to a temporary TOML file; for each, the ground truth (load, rings,
symmetry_group) is timed in a child process, and so is the whole ``exactsym check --json``
(a subprocess with a timeout; wall seconds and the child's CPU seconds, user + system), and
the CPU seconds of the text summary (``exactsym check``, which writes no exact text it
does not print).  Run: ``python bench/bench_small_algebraic.py``
(``--timeout S`` per run, default 60; ``--only NAME`` for one input).

``--certify``: also the CPU seconds of ``exactsym certify`` (which runs the checker on what
it writes) and of ``exactsym verify`` on its certificate, beside those of ``check``.

``--in-process``: only the truth, timed inside the child after its imports (load + levels
+ symmetry_group, wall and CPU seconds; the best of ``--repeat`` fresh children, default
3, since the first call in a process also builds the number fields), against the 0.2 s
target for asymmetric inputs (group C1) and 1 s for the others, judged on CPU seconds
(the wall clock of a busy shared machine measures the other processes too).

Targets (issue 9): truth < 1 s and full check < 5 s for up to 100 points whose numbers are
square roots of rationals, cos/sin of rational multiples of pi or nested radicals of depth
up to 3; asymmetric ones < 0.2 s; a refusal only beyond documented bounds, within a second.
"""

from __future__ import annotations

import argparse
import math
from fractions import Fraction as fmpq_of
import random
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

TRUTH = """
import sys, time
from exactsym.geometry.configuration import load
from exactsym.geometry.levels import levels_of
from exactsym.truth.symmetry import symmetry_group
start, cpu = time.perf_counter(), time.process_time()
config = load(sys.argv[1])
group = symmetry_group(config, levels_of(config))
print(f"{time.perf_counter() - start:.4f} {time.process_time() - cpu:.4f} {group.name}")
"""


def _cartesian(points) -> str:
    return "format = 1\npoints = [\n" + "".join(f'  ["{x}", "{y}"],\n' for x, y in points) + "]\n"


def _polar(points) -> str:
    return "format = 1\npoints = [\n" + "".join(
        f'  {{ r = "{r}", turn = "{t}" }},\n' for r, t in points) + "]\n"


def inputs() -> dict[str, str]:
    """The inputs listed in issue 9, by name."""
    out = {}
    out["3 points, sqrt 2 3 5 7"] = _cartesian([("sqrt(2)", "sqrt(3)"), ("sqrt(5)", "0"),
                                                 ("0", "sqrt(7)")])
    out["3 points, + sqrt(11)"] = _cartesian([("sqrt(2)", "sqrt(3)"), ("sqrt(5)", "sqrt(11)"),
                                               ("0", "sqrt(7)")])
    out["nine square roots"] = _cartesian([("sqrt(2)", "sqrt(3)"), ("sqrt(5)+sqrt(7)", "sqrt(11)"),
                                           ("sqrt(13)-sqrt(17)", "sqrt(19)+sqrt(23)")])
    out["5-deep nested sqrt"] = _cartesian([("sqrt(2+sqrt(3+sqrt(5+sqrt(7+sqrt(11)))))", "0"),
                                            ("0", "1"), ("1", "1")])
    draw = random.Random(1)
    c4 = []
    for j in range(8):
        k = draw.randrange(1, 2310)
        for q in range(4):
            c4.append((f"{j + 1}*cos({k + 1155 * q}*pi/2310)", f"{j + 1}*sin({k + 1155 * q}*pi/2310)"))
    out["32-point C4, pi/2310"] = _cartesian(c4)
    out["32-point asym, pi/2310"] = _cartesian(c4[:-1] + [("8*cos(7*pi/2310)", "8*sin(7*pi/2310)")])
    out["k*cos(2pi j/117), 3 pts"] = _cartesian(
        [(f"{k}*cos(2*pi*{j}/117)", f"{k}*sin(2*pi*{j}/117)") for k, j in ((1, 1), (2, 5), (3, 17))])
    pentagon = [(f"cos(2*pi*{j}/5)", f"sin(2*pi*{j}/5)") for j in range(5)]
    out["pentagon moved 1e-300"] = _cartesian([("1 + 1e-300", "0")] + pentagon[1:])
    out["pentagon moved 1e-1000"] = _cartesian([("1 + 1e-1000", "0")] + pentagon[1:])
    out["polar sqrt(2),1 at 2/45.."] = _polar([("sqrt(2)", "2/45"), ("1", "47/90"),
                                               ("sqrt(2)", "59/315")])
    out["polar 7@1 + 7@sqrt(2)"] = _polar([("1", f"2/45 + {k}/7") for k in range(7)] +
                                          [("sqrt(2)", f"1/9 + {k}/7") for k in range(7)])
    out["polar 5, turns 1/7..5/13"] = _polar([("1", t) for t in ("0", "1/7", "2/5", "3/11", "5/13")])
    # three C7 orbits and two free points, turns of denominators 7 to 12, SEC off the
    # origin: Q(zeta_27720), degree 5760, elements with large coefficients
    off = [(str(r), f"{(fmpq_of(t) + fmpq_of(f'{j}/7')) % 1}") for r, t in
           ((1, "1/11"), (2, "3/8"), (3, "5/12")) for j in range(7)]
    out["polar C7 orbits off-centre"] = _polar(off + [("4", "1/9"), ("2", "7/10")])
    out["sqrt(2+sqrt(3)), 1 point"] = _cartesian([("sqrt(2+sqrt(3))", "0")])
    out["denestable sqrt(3+2sqrt2)"] = _cartesian([("sqrt(3+2*sqrt(2))", "0"), ("1", "0")])
    out["rhombus sqrt(9+4sqrt2)"] = _polar([("sqrt(9+4*sqrt(2))", "0"), ("sqrt(9+4*sqrt(2))", "1/2"),
                                            ("3/2", "1/4"), ("3/2", "3/4")])
    out.update(nested_inputs())
    out.update(mixed_inputs())
    out.update(level_inputs())
    return out


def level_inputs() -> dict[str, str]:
    """Many levels at turns j/997 (the sparse Q(zeta_3988), degree 1,992) and distinct
    radii, the SEC off the origin, so every robot is on a level of its own and the
    paper layer compares hundreds of pairs of levels; 100 such levels at turns j/999983;
    three robots whose moved configurations the paper and the audit analyse again; radii
    sqrt(k) (square roots as levels over the cosines' field)."""
    out = {}
    for n in (31, 100):
        draw = random.Random(n)
        turns = draw.sample(range(997), n)
        out[f"{n} levels, turns j/997"] = _polar(
            [(str(draw.randrange(1, 400)), f"{t}/997") for t in turns])
    # the same in the sparse Q(zeta_N), N = 4 * 999983 (degree far beyond any dense field)
    draw = random.Random(100)
    turns = draw.sample(range(999983), 100)
    out["100 levels, turns j/999983"] = _polar(
        [(str(draw.randrange(1, 400)), f"{t}/999983") for t in turns])
    # radii sqrt(k): square roots as Kummer levels over the cosines' field (exact/kummer.py)
    # three robots off-centre at turns j/997: the paper's moved configurations' SEC centres
    # and radii (integer radii: 24 s in the dense Q(zeta_3988); radii sqrt(k): past 90 s)
    out["3 radii, turns j/997"] = _polar([("12", "1/997"), ("19", "300/997"),
                                          ("3", "600/997")])
    out["3 sqrt radii, turns j/997"] = _polar([("sqrt(145)", "680/997"),
                                               ("sqrt(374)", "183/997"),
                                               ("sqrt(63)", "339/997")])
    for n, den in ((2, 997), (10, 999983), (31, 999983), (100, 997)):
        draw = random.Random(7000 + n)
        turns = draw.sample(range(1, den), n)
        out[f"{n} sqrt radii, turns j/{den}"] = _polar(
            [(f"sqrt({draw.randrange(2, 400)})", f"{t}/{den}") for t in turns])
    return out


def mixed_inputs() -> dict[str, str]:
    """Nested radicals with cos/sin (a tower over Q(zeta_M)): issue 9's five points, and
    100 points: 20 orbits of C5 on circles of depth-3 radii, and the same with one moved."""
    out = {"nested+cos(2pi/13), 5 pts": _cartesian([
        ("sqrt(1+sqrt(2))", "0"), ("cos(2*pi/13)", "sin(2*pi/13)"), ("1", "1"), ("0", "-1"),
        ("-1/2", "1/3")])}
    draw = random.Random(5)
    orbit = []
    for _ in range(20):
        r = f"{draw.randint(1, 9)}*sqrt(2+sqrt(3+sqrt(5)))/{draw.randint(1, 9)}"
        a = draw.randrange(1, 24)
        orbit += [(f"{r}*cos(2*pi*({24 * j + a})/120)", f"{r}*sin(2*pi*({24 * j + a})/120)")
                  for j in range(5)]
    out["nested3+cos, 100 pts C5"] = _cartesian(orbit)
    out["nested3+cos, 100 pts asym"] = _cartesian(orbit[:-1] + [("1/7", "2/7")])
    return out


#: nested radicals of depth 2, 3 and 5 (issue 9: truth < 1 s, check < 5 s up to depth 3)
NESTED = {2: ("sqrt(2+sqrt(3))", "sqrt(5-sqrt(2))"),
          3: ("sqrt(2+sqrt(3+sqrt(5)))", "sqrt(7-sqrt(2+sqrt(3)))"),
          5: ("sqrt(2+sqrt(3+sqrt(5+sqrt(7+sqrt(11)))))", "sqrt(3+sqrt(2))")}


def nested_inputs() -> dict[str, str]:
    """3 points and 100 points (a C4 set of 25 orbits, and the same with one point moved:
    asymmetric) whose coordinates are small rational combinations of nested radicals; ten
    and twelve points on distinct nested radicals."""
    out = {}
    for depth, (r1, r2) in NESTED.items():
        out[f"nested depth {depth}, 3 pts"] = _cartesian([(r1, "0"), ("0", r2), ("1", "1")])
        draw = random.Random(depth)
        orbit = []
        for _ in range(25):
            a, b, c, d = (draw.randint(-9, 9) for _ in range(4))
            x, y = f"{a} + {b or 1}*{r1}", f"{c} + {d or 1}*{r2}"
            orbit += [(x, y), (f"-({y})", x), (f"-({x})", f"-({y})"), (y, f"-({x})")]
        out[f"nested depth {depth}, 100 pts C4"] = _cartesian(orbit)
        out[f"nested depth {depth}, 100 pts asym"] = _cartesian(orbit[:-1] + [("1/7", "2/7")])
    # ten and twelve distinct nested radicals sqrt(1 + sqrt(p)): towers of 10 and 12 levels
    # over Q(sqrt 2, ..., sqrt 29 or 37), where a "no" of the square-root test took 30 s
    primes = (2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37)
    for k in (10, 12):
        out[f"{k} nested radicals, {k} pts"] = _cartesian(
            [(f"sqrt(1+sqrt({p}))", str(i)) for i, p in enumerate(primes[:k])])
    # mirror pairs at turns +-2j/997 (the sparse Q(zeta_N)): the per-level polygon section
    # took 29 s with rational radii (1.5 s since its directions are cleared of the
    # centre's denominator); with radii sqrt(k) (a tower over the sparse base) two pairs
    # took minutes and four past ten minutes, in the level section and the family layer
    # (now homogeneous directions D p - (X, Y), string classes without an inverse, family
    # gap and line keys from the homogeneous forms); at j/31 (dense) 0.3 s
    pairs = ((123, 304), (280, 100), (191, 469), (244, 321))
    for label, radius, shift, count in (
            ("rational radii, off centre", lambda k: str(k % 17 + 1), ("1/3", "1/5"), 2),
            ("sqrt radii, about 0", lambda k: f"sqrt({k})", ("0", "0"), 2),
            ("sqrt radii, off centre", lambda k: f"sqrt({k})", ("1/3", "1/5"), 2),
            ("sqrt radii, off centre", lambda k: f"sqrt({k})", ("1/3", "1/5"), 4)):
        out[f"{count} mirror pairs j/997, {label}"] = _cartesian(
            [(f"{shift[0]} + {radius(k)}*cos({2 * s * j}*pi/997)",
              f"{shift[1]} + {radius(k)}*sin({2 * s * j}*pi/997)")
             for k, j in pairs[:count] for s in (1, -1)])
    return out


def input_files(only: str | None):
    """``(name, path)`` of each input (those whose name contains ``only``), written in
    turn to one temporary file."""
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "input.toml"
        for name, text in inputs().items():
            if only and only not in name:
                continue
            path.write_text(text)
            yield name, path


def _children_cpu() -> float:
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


#: CPU seconds (user + system) of the last finished :func:`run` child: on a shared
#: machine the wall clock also measures the other processes
LAST_CPU = [0.0]


def run(args: list[str], timeout: float, discard: bool = False) -> tuple[float, str]:
    """``(wall seconds, the last word of the output or the failure)``; ``discard``: the
    output is thrown away (a JSON report in a field of degree thousands is gigabytes)."""
    start, cpu = time.perf_counter(), _children_cpu()
    try:
        done = subprocess.run(args, stdout=subprocess.DEVNULL if discard else subprocess.PIPE,
                              stderr=subprocess.PIPE, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        LAST_CPU[0] = float("nan")
        return time.perf_counter() - start, f"timeout {timeout:.0f} s"
    elapsed = time.perf_counter() - start
    LAST_CPU[0] = _children_cpu() - cpu
    if done.returncode not in (0, 1):
        last = (done.stderr.strip().splitlines() or ["?"])[-1]
        return elapsed, f"exit {done.returncode}: {last[:70]}"
    if discard:
        return elapsed, "answered"
    return elapsed, done.stdout.split()[-1] if done.stdout.split() else "?"


def in_process(opts) -> None:
    """The truth's time inside a fresh interpreter, imports excluded (best of repeats)."""
    print(f"{'input':32} {'wall s':>7} {'cpu s':>7} {'group':>6}  target (cpu; C1 < 0.2 s)")
    for name, path in input_files(opts.only):
        best = None
        for _ in range(opts.repeat):
            try:
                done = subprocess.run([sys.executable, "-c", TRUTH, str(path)],
                                      capture_output=True, text=True, timeout=opts.timeout)
            except subprocess.TimeoutExpired:
                best = None
                break
            fields = done.stdout.split()
            if done.returncode != 0 or len(fields) != 3:
                break
            wall, cpu, group = float(fields[0]), float(fields[1]), fields[2]
            if best is None or wall < best[0]:
                best = (wall, cpu, group)
        if best is None:
            print(f"{name:32} {'-':>7} {'-':>7} {'-':>6}  refused or timeout", flush=True)
            continue
        wall, cpu, group = best
        # judged on CPU seconds: on a shared machine the wall clock measures the others
        limit = 0.2 if group == "C1" else 1.0
        target = f"< {limit:g} s " + ("ok" if cpu < limit else "MISSED")
        print(f"{name:32} {wall:7.3f} {cpu:7.3f} {group:>6}  {target}", flush=True)


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--timeout", type=float, default=60.0)
    parser.add_argument("--only")
    parser.add_argument("--in-process", action="store_true",
                        help="only the truth, timed inside the child, imports excluded")
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--certify", action="store_true",
                        help="also time certify and verify (CPU seconds)")
    opts = parser.parse_args()
    if opts.in_process:
        in_process(opts)
        return
    exactsym = [sys.executable, "-m", "exactsym"]
    print(f"{'input':28} {'truth s':>8} {'group':>8} {'check s':>8} {'cpu s':>7}  "
          f"{'summary cpu s':>13}  outcome" + ("  certify cpu s  verify cpu s"
                                               if opts.certify else ""))
    for name, path in input_files(opts.only):
        t_truth, group = run([sys.executable, "-c", TRUTH, str(path)], opts.timeout)
        if group.startswith("timeout"):
            group = "timeout"
        elif group.startswith("exit"):
            group = "refused"
        t_check, outcome = run(exactsym + ["check", "--json", str(path)], opts.timeout,
                               discard=True)
        c_check = LAST_CPU[0]
        run(exactsym + ["check", str(path)], opts.timeout, discard=True)    # the summary
        c_summary = LAST_CPU[0]
        if not outcome.startswith(("timeout", "exit")):
            outcome = "answered"
        certified = ""
        if opts.certify:
            cert = path.with_suffix(".cert.json")
            _, done = run(exactsym + ["certify", str(path), "-o", str(cert)], opts.timeout)
            c_certify = LAST_CPU[0] if not done.startswith(("timeout", "exit")) else math.nan
            run(exactsym + ["verify", str(cert)], opts.timeout)
            c_verify = LAST_CPU[0] if c_certify == c_certify else math.nan
            certified = f"  {c_certify:13.2f}  {c_verify:12.2f}"
        print(f"{name:28} {t_truth:8.2f} {group:>8} {t_check:8.2f} {c_check:7.2f}  "
              f"{c_summary:13.2f}  {outcome}{certified}", flush=True)


if __name__ == "__main__":
    main()
