"""The float baselines' reader, shared by the benchmarks: the same text files as exactsym
reads (``x y`` with integers or ``p/q``, ``polar r turn``), parsed as doubles."""

from __future__ import annotations

import math
from pathlib import Path


def frac(text: str) -> float:
    if "/" in text:
        p, q = text.split("/")
        return int(p) / int(q)
    return float(text)


def read_float_points(path: Path) -> tuple[list[float], list[float]]:
    xs, ys = [], []
    for line in path.read_text().splitlines():
        line = line.split("#", 1)[0].strip()
        if not line:
            continue
        if line.startswith("polar"):
            _, r, t = line.split()
            r, t = frac(r), frac(t)
            xs.append(r * math.cos(2 * math.pi * t))
            ys.append(r * math.sin(2 * math.pi * t))
        else:
            a, b = line.split()
            xs.append(frac(a))
            ys.append(frac(b))
    return xs, ys
