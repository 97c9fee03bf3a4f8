"""Per-level polygons and family keys over a tower of square roots (issue 9).

Two mirror pairs at radii sqrt(k) and turns +-t: the SEC centre C = (X/D, Y/D) is of a
tower, and the level section reads the homogeneous directions D p - (X, Y) (positive
multiples of p - C); the strings of a polygon on one circle are classed without an
inverse (:func:`exactsym.paper.filtered.circle_gap_tokens`); the family layer's gap and
line keys are made from the homogeneous forms.  Each must give what the plain directions
give.  (Over the sparse Q(zeta_N) these took minutes: ``bench/bench_small_algebraic.py``.)
"""

from __future__ import annotations

import pytest
from exactsym.analysis import analyse, built_levels
from exactsym.geometry.configuration import load
from exactsym.geometry.levels import levels_of
from exactsym.paper import polygon as P
from exactsym.paper.circle_polygon import level_polygon
from exactsym.paper.family import concentric_polygons
from exactsym.paper.family.concentric import mirror_lines
from exactsym.paper.filtered import cross_sign, dot_sign
from exactsym.exact.context import AnalysisContext
from exactsym.paper.keys import gap_ids
from exactsym.paper.polygon_report import level_verdicts

from test_paper_polygon import same_partition


def mirror_pairs(tmp_path, pairs, denominator, shift=("0", "0")):
    """Robots at radius sqrt(k) and turns +-j/denominator about ``shift``, per (k, j)."""
    rows = []
    for k, j in pairs:
        for s in (1, -1):
            angle = f"{2 * s * j}*pi/{denominator}"
            rows.append(f'  ["{shift[0]} + sqrt({k})*cos({angle})", '
                        f'"{shift[1]} + sqrt({k})*sin({angle})"],\n')
    path = tmp_path / "pairs.toml"
    path.write_text("format = 1\npoints = [\n" + "".join(rows) + "]\n")
    return load(path)


DENSE = ([(123, 7), (280, 3)], 31, ("1/3", "1/5"))
SPARSE = ([(123, 304), (280, 100)], 997, ("0", "0"))


@pytest.mark.parametrize("pairs, denominator, shift", [DENSE, SPARSE])
def test_level_polygons_are_scaled_copies(tmp_path, pairs, denominator, shift):
    config = mirror_pairs(tmp_path, pairs, denominator, shift)
    levels = built_levels(levels_of(config))
    for index in range(len(levels.levels)):
        plain = level_polygon(config, levels, index)
        cleared = level_polygon(config, levels, index, cleared=True)
        assert cleared.__dict__["cleared"] and cleared.labels == plain.labels
        for u, v in zip(plain.directions, cleared.directions):
            assert cross_sign(u, v) == 0 and dot_sign(u, v) > 0      # the same ray
        assert same_partition(P.string_classes(cleared), P.string_classes_reference(cleared))
        reference = P.check_symmetry_even_reference if cleared.n % 2 == 0 else \
            P.check_symmetry_odd_reference
        for orientation in (1, -1):
            assert P.check_symmetry(cleared, orientation).reports == \
                reference(cleared, orientation).reports
        if denominator == 31:       # the plain directions are quick in the dense field only
            assert level_verdicts(cleared) == level_verdicts(plain)
            assert same_partition(P.string_classes(cleared), P.string_classes(plain))


@pytest.mark.parametrize("pairs, denominator, shift", [DENSE, SPARSE])
def test_family_keys_from_homogeneous_forms(tmp_path, pairs, denominator, shift):
    """Gap classes and mirror lines of every family polygon (and of their union) are the
    same with the homogeneous forms recorded as without them."""
    config = mirror_pairs(tmp_path, pairs, denominator, shift)
    levels = built_levels(levels_of(config))
    with AnalysisContext().active():        # the forms are recorded in an analysis's caches
        rings = concentric_polygons(config, levels)
        with_forms = [(gap_ids(r.polygon), set(mirror_lines(r.polygon))) for r in rings]
    # outside an analysis no forms (nor any other cache): the keys are made from p - C itself
    without = [(gap_ids(r.polygon), set(mirror_lines(r.polygon))) for r in rings]
    assert with_forms == without
    assert all(len(lines) == 1 for _, lines in with_forms)   # the x-axis mirror of each pair


def test_sparse_mirror_pairs_whole_check(tmp_path):
    """Four mirror pairs over the sparse tower (minutes before): the paper's lines and the
    truth's mirror agree, and each level's verdict is its definition's."""
    config = mirror_pairs(tmp_path, [(123, 304), (280, 67), (191, 469), (244, 321)], 997,
                          ("1/3", "1/5"))
    result = analyse(config)
    assert (result.truth.name, result.truth.mirrors) == ("D1", 1)
    assert not result.truth.orderable and not result.paper.orderable
    for verdict in result.level_verdicts:
        assert verdict["definition"]["mirrors"] == 1 and not verdict["definition"]["skew"]
