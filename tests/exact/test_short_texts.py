"""Short exact texts in a cyclotomic field of degree >= 512 (exactsym.paper.homogeneous):
the SEC centre, the squared radii and the paper layer's lines written as quotients of
numbers with small coefficients read back as the very numbers the analysis holds (tens
of thousands of characters at degree 660, where the divided numbers took megabytes; the
configuration syntax bounds an *input* expression at 10,000 characters, so the test
reads them with that bound raised)."""

from __future__ import annotations

import json
import random
import re

import pytest

from exactsym import load
from exactsym.analysis import Options, analyse
from exactsym.exact import evaluate
from exactsym.io.expr import parse_expression
from exactsym.exact.cyclotomic import MAX_DEGREE
from exactsym.exact.evaluate import dense_degree_limit
from exactsym.exact.sparse_cyclotomic import SparseCyclotomic
from exactsym.exact.tower import TowerElement
from exactsym.paper.family.concentric import ALL_LINES
from exactsym.exact.number import LARGE_DEGREE
from exactsym.paper.homogeneous import is_short
from exactsym.report.check import report_json

_PAIR = re.compile(r"\((-?1), ")


def _closing(text: str, start: int) -> int:
    """The index of the parenthesis closing the one at ``start``."""
    depth = 0
    for end in range(start, len(text)):
        depth += {"(": 1, ")": -1}.get(text[end], 0)
        if depth == 0:
            return end
    raise ValueError(f"unbalanced: {text[:80]}")


def _line_texts(text: str) -> list:
    """The ``(s, slope)`` pairs of a lines text: each "(s, " opens a pair whose slope runs
    to the parenthesis closing it (slopes nest parentheses to any depth)."""
    return [(m.group(1), text[m.end():_closing(text, m.start())])
            for m in _PAIR.finditer(text)]


def _quotient(text: str):
    """``(A, B)`` when ``text`` is the quotient "(A)/(B)", else None."""
    if not text.startswith("("):
        return None
    end = _closing(text, 0)
    if text[end + 1:end + 3] != "/(" or _closing(text, end + 2) != len(text) - 1:
        return None
    return text[1:end], text[end + 3:-1]


def _config(tmp_path, seed: int):
    """Six robots at turns j/331 (Q(zeta_1324), degree 660), radii up to 60, off centre."""
    draw = random.Random(seed)
    rows = "".join(f'  {{ r = "{draw.randrange(1, 60)}", turn = "{t}/331" }},\n'
                   for t in draw.sample(range(331), 6))
    path = tmp_path / f"c{seed}.toml"
    path.write_text("format = 1\npoints = [\n" + rows + "]\n")
    with dense_degree_limit(MAX_DEGREE):      # the dense field (sparse by default)
        config = load(path)
        config.system                         # chosen when first read
    return config


def _sparse_tower_config(tmp_path, case: tuple):
    """``n`` robots at turns j/997, two per radius sqrt(k), ``case = (n, seed)``: a tower
    of square roots over the sparse Q(zeta_1994), where a divided coordinate is a quotient
    of sparse sums per tower coefficient (the cases chosen have an SEC through three
    robots, an irrational D, and levels of two robots, with a line each)."""
    n, seed = case
    draw = random.Random(seed)
    radii = draw.sample(range(2, 400), (n + 1) // 2)
    rows = "".join(f'  {{ r = "sqrt({radii[i // 2]})", turn = "{t}/997" }},\n'
                   for i, t in enumerate(draw.sample(range(997), n)))
    path = tmp_path / f"t{n}_{seed}.toml"
    path.write_text("format = 1\npoints = [\n" + rows + "]\n")
    return load(path)


@pytest.mark.parametrize("make, seed", [(_config, 3), (_sparse_tower_config, (5, 1)),
                                        (_sparse_tower_config, (6, 1)),
                                        (_sparse_tower_config, (6, 4))])
def test_short_texts_read_back_as_the_numbers(tmp_path, monkeypatch, make, seed):
    from exactsym.io import expr
    monkeypatch.setattr(expr, "MAX_LENGTH", 10 ** 6)
    config = make(tmp_path, seed)
    if make is _config:
        assert config.system.field.degree >= LARGE_DEGREE
    else:
        assert isinstance(config.points[0][0], (SparseCyclotomic, TowerElement))
    analysis = analyse(config, options=Options())
    assert is_short(analysis.levels.sec.homogeneous)
    report = json.loads(json.dumps(report_json(analysis)))

    def number(text):
        assert len(text) <= 40_000
        return evaluate(parse_expression(text), config.system)

    def quotient(text):
        parts = _quotient(text)
        assert parts is not None, text[:80]
        return number(parts[0]), number(parts[1])

    # no field inverse and no exact radius made (in a tower over the sparse Q(zeta_N) an
    # exact radius costs seconds): the centre X/D by X == C_x D, a squared radius A/B by
    # A D^2 == B |D p - (X, Y)|^2 for a robot p on it, C = (X/D, Y/D) being proved
    levels = analysis.levels
    (x, d), (y, d2) = (quotient(t) for t in report["sec"]["center"])
    cx, cy = levels.sec.centre
    assert d == d2 and x == cx * d and y == cy * d

    def squared_radius_holds(text, p):
        a, b = quotient(text)
        u, v = d * p[0] - x, d * p[1] - y
        return a * d * d == b * (u * u + v * v)
    points = config.points
    assert squared_radius_holds(report["sec"]["radius_squared"],
                                points[levels.sec.support[0]])
    for entry, level in zip(report["levels"], levels.levels):
        assert squared_radius_holds(entry["radius_squared"], points[level.points[0]])
    checked = 0
    for ring, entry in zip(analysis.paper.G_rings, report["paper"]["G"]):
        if ring.polygon is None or ring.lines is ALL_LINES:     # C, or a skew polygon
            continue
        texts = _line_texts(entry["lines"])
        keys = sorted(ring.lines, key=lambda k: k.display_key())
        assert len(texts) == min(len(keys), 8)
        for key, (s, slope) in zip(keys, texts):
            x, y = key._vector                   # the doubled direction, made exactly
            num, den = _quotient(slope)          # slope y/x, written (Y')/(X')
            assert int(s) == x.sign() and number(num) * x == y * number(den)
            checked += 1
    assert checked >= 2
    # every number of the report is short: no megabyte texts anywhere
    assert len(json.dumps(report)) < 2_000_000
