"""Which number kinds ``exactsym certify`` answers, and how fast ``verify`` is on each.

Run: ``python bench/certify_fields.py [--timeout S] [--only SUBSTRING]``.  For every small
configuration of :data:`CASES` (one per number kind the parser accepts and per mix of kinds,
symmetric and asymmetric) it runs ``exactsym certify`` (which checks its own certificate) and
``exactsym verify`` in this process and prints one table row: the outcome (``ok``, ``refused``
with the reason, ``crash``, ``timeout``), the truth's group, the certificate's field and the
times.  Issue 9 ("certify succeeds wherever check does") is met when every row is ``ok``.
The configurations are also the inputs of ``tests/test_certify_fields.py``.
"""

from __future__ import annotations

import contextlib
import io
import json
import signal
import sys
import tempfile
import time
from pathlib import Path


def ring(r: str, k: int, offset: str = "0") -> list[str]:
    """k polar points at radius r, turns offset + j/k."""
    return [f'{{ r = "{r}", turn = "{offset}+{j}/{k}" }}' for j in range(k)]


def trig_ring(k: int, scale: str = "1", half: bool = False) -> list[str]:
    """k Cartesian points scale*(cos, sin)(2 pi j/k) (offset by pi/k when half)."""
    out = []
    for j in range(k):
        q = f"({2 * j + (1 if half else 0)}/{k})"
        out.append(f'["{scale}*cos({q}*pi)", "{scale}*sin({q}*pi)"]')
    return out


def cart(*pairs: tuple[str, str]) -> list[str]:
    return [f'["{x}", "{y}"]' for x, y in pairs]


# name: (kind, list of TOML point entries)
CASES: dict[str, tuple[str, list[str]]] = {
    "rational C1": ("rational", cart(("0", "0"), ("3", "1"), ("1", "5"), ("7/2", "2"))),
    "rational D4": ("rational", cart(("0", "0"), ("2", "0"), ("2", "2"), ("0", "2"))),
    "sqrt C1": ("sqrt", cart(("sqrt(2)", "0"), ("1", "1"), ("0", "3"))),
    "sqrt D6 hexagon": ("sqrt", cart(("1", "0"), ("1/2", "sqrt(3)/2"), ("-1/2", "sqrt(3)/2"),
                                     ("-1", "0"), ("-1/2", "-sqrt(3)/2"), ("1/2", "-sqrt(3)/2"))),
    "several sqrt C1": ("several sqrt", cart(("sqrt(2)", "sqrt(3)"), ("sqrt(5)", "0"),
                                             ("0", "1"))),
    "nine sqrt C1": ("several sqrt", cart(("sqrt(2)", "sqrt(3)"), ("sqrt(5)+sqrt(7)", "sqrt(11)"),
                                          ("sqrt(13)-sqrt(17)", "sqrt(19)+sqrt(23)"))),
    "several sqrt D2": ("several sqrt", cart(("sqrt(2)", "sqrt(3)"), ("-sqrt(2)", "sqrt(3)"),
                                             ("-sqrt(2)", "-sqrt(3)"), ("sqrt(2)", "-sqrt(3)"))),
    "trig D5 pentagon": ("trig", trig_ring(5)),
    "trig D7 heptagon": ("trig", trig_ring(7)),
    "trig C1 pi/9": ("trig", cart(("cos(pi/9)", "sin(pi/9)"), ("1", "0"), ("0", "1/2"))),
    "trig C8 two rings": ("trig", trig_ring(8) + [
        f'["2*cos(({2 * j}/8+1/12)*pi)", "2*sin(({2 * j}/8+1/12)*pi)"]' for j in range(8)]),
    "polar rational C7": ("polar rational", ring("1", 7) + ring("2", 7, "1/20")),
    "polar rational D5": ("polar rational", ring("1", 5) + ring("3", 5, "1/10")),
    "polar sqrt radius C5": ("polar sqrt", ring("1", 5) + ring("sqrt(2)", 5, "1/20")),
    "polar sqrt radius D4": ("polar sqrt", ring("sqrt(3)", 4) + ring("1", 4, "1/8")),
    "polar sqrt radius C1": ("polar sqrt", [ring("sqrt(2)", 3)[0], ring("1", 5)[1],
                                            ring("1", 7)[3]]),
    "polar C7 sqrt r, turns /45": ("polar sqrt", ring("1", 7, "2/45") + ring("sqrt(2)", 7, "1/9")),
    "off-centre polar turns 0,1/7,2/5": ("off-centre polar", [
        '{ r = "1", turn = "0" }', '{ r = "1", turn = "1/7" }', '{ r = "1", turn = "2/5" }']),
    "off-centre polar sqrt r": ("off-centre polar", [
        '{ r = "sqrt(2)", turn = "0" }', '{ r = "1", turn = "1/5" }',
        '{ r = "1", turn = "1/3" }']),
    "off-centre polar D1": ("off-centre polar", [
        '{ r = "1", turn = "1/5" }', '{ r = "1", turn = "-1/5" }', '{ r = "2", turn = "0" }']),
    "nested O2": ("nested", cart(("sqrt(2+sqrt(3))", "0"))),
    "nested C1": ("nested", cart(("sqrt(2+sqrt(3))", "1"), ("1", "sqrt(2)"), ("0", "0"))),
    "nested D4": ("nested", cart(("sqrt(2+sqrt(3))", "0"), ("0", "sqrt(2+sqrt(3))"),
                                 ("-sqrt(2+sqrt(3))", "0"), ("0", "-sqrt(2+sqrt(3))"))),
    "nested sqrt(1+sqrt(2)) C1": ("nested", cart(("sqrt(1+sqrt(2))", "0"), ("0", "1"),
                                                 ("1", "1"))),
    "sqrt + trig/5 C1": ("sqrt+trig", cart(("sqrt(2)", "0"), ("cos(2*pi/5)", "1"),
                                           ("0", "sin(2*pi/5)"))),
    "sqrt + trig/7 C1": ("sqrt+trig", cart(("sqrt(2)", "0"), ("cos(2*pi/7)", "1"), ("0", "1/3"))),
    "sqrt + trig/5 D5": ("sqrt+trig", trig_ring(5, "sqrt(2)")),
    "sqrt 3 + trig/5 ring D5 x2": ("sqrt+trig", trig_ring(5) + trig_ring(5, "sqrt(3)", True)),
    "polar sqrt r + turns/5 off-centre": ("polar sqrt+trig", [
        '{ r = "sqrt(2)", turn = "0" }', '{ r = "1", turn = "1/5" }', '["1/3", "1/7"]']),
    "polar sqrt r + turns/10 C5": ("polar sqrt+trig", ring("sqrt(2)", 5) + ring("1", 5, "1/10")),
    "polar r sqrt(2) turns 2/45,47/90,59/315": ("polar sqrt+trig", [
        '{ r = "sqrt(2)", turn = "2/45" }', '{ r = "1", turn = "47/90" }',
        '{ r = "1", turn = "59/315" }']),
    "nested + trig/5 C1": ("nested+trig", cart(("sqrt(2+sqrt(3))", "0"), ("cos(2*pi/5)", "1"),
                                               ("0", "0"))),
    "nested + trig/7 C1": ("nested+trig", cart(("sqrt(2+sqrt(3))", "0"), ("cos(2*pi/7)", "1"),
                                               ("0", "0"))),
    "nested + trig/13 C1 (degree 24)": ("nested+trig", cart(("sqrt(2+sqrt(3))", "0"),
                                                            ("cos(2*pi/13)", "1"), ("0", "0"))),
    "nested + trig/16 C1 (sqrt 2 in K)": ("nested+trig", cart(("sqrt(2+sqrt(3))", "0"),
                                                              ("cos(2*pi/16)", "1"), ("0", "0"))),
    "nested + sqrt(5) C1": ("nested+sqrt", cart(("sqrt(2+sqrt(3))", "0"), ("sqrt(5)", "1"),
                                                ("0", "0"))),
    "nested + polar turns/5 C1": ("nested+polar", [
        '{ r = "sqrt(2+sqrt(3))", turn = "0" }', '{ r = "1", turn = "1/5" }',
        '{ r = "1", turn = "1/2" }']),
    "nested D5 ring": ("nested+trig", trig_ring(5, "sqrt(2+sqrt(3))")),
}


def toml(points: list[str]) -> str:
    return "format = 1\npoints = [\n  " + ",\n  ".join(points) + ",\n]\n"


class _Timeout(Exception):
    pass


def run_case(path: Path, timeout: float) -> dict:
    """certify then verify ``path``; the outcome, times, group and field of the certificate."""
    from exactsym.cli.main import main as cli_main
    cert = path.with_suffix(".cert.json")
    row = {"outcome": "ok", "certify": None, "verify": None, "group": "", "field": "", "why": ""}

    def alarm(*_):
        raise _Timeout

    old = signal.signal(signal.SIGALRM, alarm)
    signal.setitimer(signal.ITIMER_REAL, timeout)
    err = io.StringIO()
    try:
        start = time.perf_counter()
        with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(err):
            code = cli_main(["certify", str(path), "-o", str(cert)])
        row["certify"] = time.perf_counter() - start
        if code != 0:
            row["outcome"] = "refused" if code == 2 else f"exit {code}"
            row["why"] = err.getvalue().strip().splitlines()[-1] if err.getvalue() else ""
            return row
        data = json.loads(cert.read_text())
        row["group"] = data["claim"]["group"]
        field = data["configuration"]["field"]
        row["field"] = ("Q" if field is None else "radicands" if "radicands" in field
                        else field.get("irreducible", {}).get("method", "?")
                        if "minpoly" in field else "+".join(sorted(field)))
        start = time.perf_counter()
        with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(err):
            code = cli_main(["verify", str(cert)])
        row["verify"] = time.perf_counter() - start
        if code != 0:
            row["outcome"] = f"verify exit {code}"
            row["why"] = err.getvalue().strip().splitlines()[-1]
    except _Timeout:
        row["outcome"] = "timeout"
    except Exception as exc:                    # a crash is a finding, not the end of the run
        row["outcome"] = "crash"
        row["why"] = f"{type(exc).__name__}: {exc}"[:120]
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)
    return row


def main(argv: list[str]) -> int:
    timeout = float(argv[argv.index("--timeout") + 1]) if "--timeout" in argv else 120.0
    only = argv[argv.index("--only") + 1] if "--only" in argv else ""
    tmp = Path(tempfile.mkdtemp())
    print(f"{'configuration':<42}{'kind':<18}{'outcome':<9}{'group':<6}{'field':<16}"
          f"{'certify s':>10}{'verify s':>10}")
    bad = 0
    for i, (name, (kind, points)) in enumerate(CASES.items()):
        if only not in name:
            continue
        path = tmp / f"case{i}.toml"
        path.write_text(toml(points))
        row = run_case(path, timeout)
        bad += row["outcome"] != "ok"
        fmt = lambda t: f"{t:>10.2f}" if t is not None else f"{'-':>10}"
        print(f"{name:<42}{kind:<18}{row['outcome']:<9}{row['group']:<6}{row['field']:<16}"
              f"{fmt(row['certify'])}{fmt(row['verify'])}" + (f"  {row['why']}" if row["why"]
                                                                 else ""), flush=True)
    print(f"{bad} of the configurations not certified and verified")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
