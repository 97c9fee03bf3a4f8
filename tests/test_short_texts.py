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

from exactsym import load
from exactsym.analysis import Options, analyse
from exactsym.exact import evaluate
from exactsym.expr import parse_expression
from exactsym.exact.cyclotomic import MAX_DEGREE
from exactsym.exact.evaluate import dense_degree_limit
from exactsym.paper.homogeneous import SHORT_DEGREE
from exactsym.report import report_json

# a slope quotient "(Y)/(X)" inside a line's text "(s, (Y)/(X))"
_LINE = re.compile(r"\((-?1), (\((?:[^()]|\([^()]*\))*\)/\((?:[^()]|\([^()]*\))*\))\)")


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


def test_short_texts_read_back_as_the_numbers(tmp_path, monkeypatch):
    from exactsym import expr
    monkeypatch.setattr(expr, "MAX_LENGTH", 10 ** 6)
    config = _config(tmp_path, 3)
    assert config.system.field.degree >= SHORT_DEGREE
    analysis = analyse(config, options=Options())
    report = json.loads(json.dumps(report_json(analysis)))

    def number(text):
        assert len(text) <= 40_000
        return evaluate(parse_expression(text), config.system)
    levels = analysis.levels
    assert [number(t) for t in report["sec"]["center"]] == list(levels.sec.centre)
    assert number(report["sec"]["radius_squared"]) == levels.sec.radius_squared
    for entry, level in zip(report["levels"], levels.levels):
        assert number(entry["radius_squared"]) == level.radius_squared
    checked = 0
    for ring, entry in zip(analysis.paper.G_rings, report["paper"]["G"]):
        if ring.polygon is None:
            continue
        texts = _LINE.findall(entry["lines"])
        keys = sorted(ring.lines, key=lambda k: k.display_key())
        assert len(texts) == min(len(keys), 8)
        for key, (s, slope) in zip(keys, texts):
            x, y = key._vector                   # the doubled direction, made exactly
            assert int(s) == x.sign() and number(slope) == y / x
            checked += 1
    assert checked >= 3
    # every number of the report is short: no megabyte texts anywhere
    assert len(json.dumps(report)) < 2_000_000
