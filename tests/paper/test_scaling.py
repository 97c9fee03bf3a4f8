"""The family layer at scale: bounded work, bounded output, the same verdicts.

Not timed (timings are in ``bench/bench_check.py``).  On configurations with many levels
(random points: one robot per level; a polar C7 set: levels of 7) ``exactsym check``
completes with a trace of bounded length and says what it bounded
(``paper.bounded``, ``audit.bounded``); on configurations small enough to run the
unbounded procedure (:data:`exactsym.paper.family.UNBOUNDED`: every pair and triple,
no budget) the paper's and the audit's verdicts are the same.  The per-level verdicts of
``polygon_report`` shared between polygons of the same shape are those computed one by
one.
"""

from __future__ import annotations

import random
from fractions import Fraction
from math import gcd

import pytest

from exactsym.audit.statements import audit
from exactsym.geometry.configuration import Configuration, load
from exactsym.exact import fmpq
from exactsym.geometry.levels import levels_of
from exactsym.paper import family as F
from exactsym.paper import polygon_report
from exactsym.paper.circle_polygon import level_polygon, polygon_from_directions
from exactsym.report.check import check_report


TRACE_LIMIT = F.DEFAULT_LIMITS.trace_entries


def _q(num: int, den: int) -> str:
    g = gcd(num, den)
    num, den = num // g, den // g
    return str(num) if den == 1 else f"{num}/{den}"


def random_text(n: int, seed: int) -> str:
    """n random rational points (as ``bench/bench_truth.py`` makes them)."""
    rnd = random.Random(seed)
    return "".join(f"{rnd.randint(-10**6, 10**6)}/{rnd.randint(1, 1000)} "
                   f"{rnd.randint(-10**6, 10**6)}/{rnd.randint(1, 1000)}\n" for _ in range(n))


def c7_polar_text(n: int, seed: int) -> str:
    """Orbits under C7 of n/7 polar seeds, turn denominators near 10,000."""
    rnd = random.Random(seed)
    seen, lines = set(), []
    while len(lines) < n:
        q = 7 * rnd.randint(1400, 1460)
        a = rnd.randint(0, q // 7 - 1)
        r = (rnd.randint(1, 10**4), rnd.randint(1, 100))
        if (r[0] * 1000 // r[1], a * 100000 // q) in seen:
            continue
        seen.add((r[0] * 1000 // r[1], a * 100000 // q))
        lines.extend(f"polar {_q(*r)} {_q(a + j * (q // 7), q)}\n" for j in range(7))
    return "".join(lines[:n])


def _load_text(tmp_path, name: str, text: str) -> Configuration:
    path = tmp_path / name
    path.write_text(text)
    return load(path)


def _paper_verdict(res: F.PaperResult) -> tuple:
    return (res.orderable, res.gathering_possible, res.leader,
            [m["robot"] for m in res.moves], res.first_actor, res.complete, res.make_asym,
            res.elect_leader)


def _audit_verdict(report: dict) -> tuple:
    return (report["agrees"], report["conclusions_agree"], report["truth"],
            sorted({d["statement"] for d in report["discrepancies"]}))


# ---------------------------------------------------------------- large inputs
@pytest.mark.parametrize("name, text, levels", [
    ("random3000.txt", lambda: random_text(3000, 7), 2900),
    ("c7polar2100.txt", lambda: c7_polar_text(2100, 9), 250),
])
def test_check_completes_with_bounded_trace(tmp_path, name, text, levels):
    config = _load_text(tmp_path, name, text())
    report = check_report(config)
    assert len(report["levels"]) >= levels                    # t is large
    paper, result = report["paper"], report["audit"]
    assert len(paper["trace"]) <= TRACE_LIMIT
    assert len(paper["G"]) <= F.DEFAULT_LIMITS.described + 1
    bounded = paper["bounded"]
    t = len(report["levels"])
    assert bounded["of"] == t * (t - 1) // 2
    assert bounded["family_claims_pairs_checked"] <= F.MAX_PAIRS
    assert "obs-merg-asym-pair" in bounded["family_claims_partial"]
    assert bounded["preprocess_complete"]
    assert result["bounded"]["pairs_checked"] <= F.MAX_PAIRS
    # a statement failing on many pairs is listed a few times, then counted
    for statement, count in bounded["family_claims_failures"].items():
        listed = [e for e in paper["trace"] if e["statement"] == statement
                  and e.get("holds") is False and e["algorithm"] == "Section 3"]
        assert len(listed) <= F.DEFAULT_LIMITS.claim_examples + 1
    assert len(result["discrepancies"]) <= 40
    assert isinstance(result["agrees"], bool) and isinstance(paper["orderable"], bool)


# ---------------------------------------------------------------- bounded == unbounded
@pytest.mark.parametrize("name, text", [
    ("random150.txt", lambda: random_text(150, 4)),
    ("random60.txt", lambda: random_text(60, 5)),
    ("c7polar350.txt", lambda: c7_polar_text(350, 6)),
])
def test_bounded_and_unbounded_procedures_agree(tmp_path, name, text):
    """Where the unbounded procedure is cheap enough to run, the bounded one reaches the
    same verdicts: the paper's conclusions and moves, the audit's conclusions and the
    statements it finds false."""
    config = _load_text(tmp_path, name, text())
    ring_data = levels_of(config)
    t = len(ring_data.levels)
    assert t * (t - 1) // 2 > F.MAX_PAIRS                      # the bounds do cut
    bounded = F.paper_procedure(config, ring_data)
    unbounded = F.paper_procedure(config, ring_data, limits=F.UNBOUNDED)
    assert _paper_verdict(bounded) == _paper_verdict(unbounded)
    assert bounded.bounded["family_claims_pairs_checked"] < \
        unbounded.bounded["family_claims_pairs_checked"] == t * (t - 1) // 2
    assert unbounded.bounded["trace_entries_omitted"] == 0
    report_b = audit(config, ring_data, bounded)
    report_u = audit(config, ring_data, unbounded, {"limits": F.UNBOUNDED})
    assert _audit_verdict(report_b) == _audit_verdict(report_u)
    assert report_u["bounded"]["pairs_checked"] == t * (t - 1) // 2


# ---------------------------------------------------------------- shared verdicts
def _rotated(poly, delta, labels):
    """The polar polygon turned by ``delta`` (no vertex crosses the +x ray: the storage
    order is kept), with other labels."""
    return polygon_from_directions(labels, [d + delta for d in poly.directions], True)


@pytest.mark.parametrize("seed", range(12))
def test_shared_verdicts_are_the_computed_ones_polar(seed):
    rnd = random.Random(seed)
    n = rnd.choice([1, 2, 3, 4, 5, 6, 7, 8, 9, 12])
    k = rnd.choice([1, 2, 3, n])
    base = sorted({Fraction(rnd.randint(1, 59), 60 * k)} |
                  {Fraction(rnd.randint(1, 59), 60 * k) + Fraction(j, k)
                   for j in range(k) for _ in range(max(1, n // k))})
    base = [t for t in base if 0 < t < 1]
    poly = polygon_from_directions(range(len(base)), [fmpq(t.numerator, t.denominator)
                                                      for t in base], True)
    first, last = poly.directions[0], poly.directions[-1]
    memo = polygon_report.VerdictMemo()
    assert memo.verdicts(poly) == polygon_report.level_verdicts(poly)
    for delta in (-first / 2, (1 - last) / 3):
        other = _rotated(poly, delta, [100 + i for i in range(poly.n)])
        assert polygon_report.shape_key(other) == polygon_report.shape_key(poly)
        assert memo.verdicts(other) == polygon_report.level_verdicts(other)


_NORM25 = [(25, 0), (24, 7), (20, 15), (15, 20), (7, 24), (0, 25), (-7, 24), (-15, 20),
           (-20, 15), (-24, 7), (-25, 0), (-24, -7), (-20, -15), (-15, -20), (-7, -24),
           (0, -25), (7, -24), (15, -20), (20, -15), (24, -7)]


@pytest.mark.parametrize("seed", range(8))
def test_shared_verdicts_are_the_computed_ones_cartesian(seed):
    """Rational points of one circle; a copy turned and scaled exactly (a Pythagorean
    rotation that keeps the storage order when it keeps the key)."""
    rnd = random.Random(seed)
    chosen = sorted(rnd.sample(range(20), rnd.randint(1, 9)))
    pts = [(fmpq(_NORM25[i][0]), fmpq(_NORM25[i][1])) for i in chosen]
    poly = polygon_from_directions(range(len(pts)), pts, False)
    memo = polygon_report.VerdictMemo()
    assert memo.verdicts(poly) == polygon_report.level_verdicts(poly)
    for c, s, scale in ((fmpq(24, 25), fmpq(7, 25), 3), (fmpq(4, 5), fmpq(3, 5), 2),
                        (fmpq(0), fmpq(1), 5)):
        turned = [(scale * (c * x - s * y), scale * (s * x + c * y)) for x, y in pts]
        other = polygon_from_directions([50 + i for i in range(len(pts))], turned, False)
        assert memo.verdicts(other) == polygon_report.level_verdicts(other)


def test_polygon_section_of_many_levels_is_the_levelwise_one(tmp_path):
    """Single robots (the shared single-vertex verdict), polar C7 levels (one shape)."""
    for name, text in (("r.txt", random_text(120, 3)), ("c.txt", c7_polar_text(140, 2))):
        config = _load_text(tmp_path, name, text)
        ring_data = levels_of(config)
        verdicts, strings = polygon_report.level_reports(config, ring_data)
        assert strings is None and len(verdicts) == len(ring_data.levels)
        for k, verdict in enumerate(verdicts):
            want = polygon_report.level_verdicts(level_polygon(config, ring_data, k))
            assert verdict == want


@pytest.mark.parametrize("name, text", [
    ("random120.txt", lambda: random_text(120, 8)),
    ("polar120.txt", lambda: "".join(f"polar {r} {r * r % 127}/127\n" for r in range(1, 120))
     + "".join(f"polar 1000 {k}/3\n" for k in range(3))),
])
def test_check_audit_with_the_pipeline_group_is_the_audit_on_its_own(tmp_path, name, text):
    """Within ``check`` the audit takes the group from the pipeline's truth instead of
    computing it again: the same audit as computed on its own."""
    config = _load_text(tmp_path, name, text())
    report = check_report(config)
    assert report["group"] == "C1"
    ring_data = levels_of(config)
    assert report["audit"] == audit(config, ring_data,
                                    F.paper_procedure(config, ring_data)).as_dict()
