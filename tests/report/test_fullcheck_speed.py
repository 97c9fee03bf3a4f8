"""The shortcuts of the full check (issue 9) equal what they replace."""

from __future__ import annotations

from hypothesis import given, settings, strategies as st

from exactsym.analysis import built_levels
from exactsym.geometry.configuration import Configuration
from exactsym.geometry.levels import Level, RationalLevels, levels_of

# many points on few circles about the origin (levels of several points, and ties of
# squared radii), plus distinct random points: levels_of then keeps RationalLevels
_ring_points = st.lists(st.sampled_from([(3, 4), (-4, 3), (5, 0), (0, -5), (-3, -4), (4, -3),
                                         (1, 1), (-1, 1), (1, -1), (-1, -1), (0, 2), (2, 0)]),
                        min_size=0, max_size=12, unique=True)


@settings(max_examples=25, deadline=None)
@given(_ring_points, st.lists(st.tuples(st.integers(-10**6, 10**6), st.integers(-10**6, 10**6)),
                              min_size=70, max_size=120, unique=True))
def test_built_levels_equal_the_lazy_levels(ring, extra):
    points = list(dict.fromkeys([*ring, *extra]))
    levels = levels_of(Configuration.from_points(points))
    built = built_levels(levels)
    assert isinstance(built.levels, tuple)
    assert all(type(level) is Level for level in built.levels)
    assert built.levels == tuple(levels.levels)          # radii and point orders
    assert [hash(a) for a in built.levels] == [hash(b) for b in levels.levels]
    assert built.sec == levels.sec and built.polar == levels.polar
    if isinstance(levels.levels, RationalLevels):
        assert built_levels(built) is built                # already a tuple: unchanged


@settings(max_examples=200, deadline=None)
@given(st.integers(-10**60, 10**60), st.integers(1, 10**60))
def test_flint_writes_a_rational_as_number_text(p, q):
    from flint import fmpq
    from exactsym.exact import number_text
    assert str(fmpq(p, q)) == number_text(fmpq(p, q))


_json = st.recursive(st.none() | st.booleans() | st.integers() | st.text(max_size=8),
                     lambda inner: st.lists(inner, max_size=4)
                     | st.dictionaries(st.text(max_size=5), inner, max_size=4), max_leaves=20)


@settings(max_examples=200, deadline=None)
@given(_json)
def test_prebuilt_encoder_writes_as_json_dumps(value):
    import json
    from exactsym.report.check import _item
    assert _item(value) == json.dumps(value, separators=(", ", ": "))


@settings(max_examples=15, deadline=None)
@given(st.lists(st.tuples(st.integers(-50, 50), st.integers(-50, 50)), min_size=3, max_size=40,
                unique=True))
def test_verdict_templates_write_what_the_encoder_writes(points):
    import json
    from exactsym.paper.polygon_report import LabelledVerdict
    from exactsym.report.check import _item, check_report
    report = check_report(Configuration.from_points(points))
    templated = 0
    for entry in report["levels"]:
        paper = entry.get("paper")
        want = json.dumps(entry, separators=(", ", ": "))
        assert _item(entry) == want
        if type(paper) is LabelledVerdict and paper.json_parts is not None:
            templated += 1
            assert paper.json_text() == json.dumps(dict(paper), separators=(", ", ": "))
    singles = sum(len(e["points"]) == 1 for e in report["levels"])
    assert templated <= singles


def test_single_robot_levels_carry_a_template():
    from exactsym.paper.polygon_report import LabelledVerdict
    from exactsym.report.check import check_report
    report = check_report(Configuration.from_points([(0, 0), (1, 0), (0, 2), (3, 1), (-5, 2)]))
    singles = [e["paper"] for e in report["levels"] if len(e["points"]) == 1]
    assert len(singles) == 3
    assert all(type(v) is LabelledVerdict and v.json_parts is not None for v in singles)


@settings(max_examples=15, deadline=None)
@given(st.lists(st.tuples(st.integers(-6, 6), st.integers(-6, 6)), min_size=3, max_size=40,
                unique=True))
def test_family_rings_from_the_polygon_layer_equal_the_computed_ones(points):
    from exactsym.paper.family.concentric import concentric_polygons
    from exactsym.paper.keys import gap_ids, integer_directions, polygon_integer_directions
    from exactsym.paper.polygon_report import level_section
    config = Configuration.from_points(points)
    levels = levels_of(config)
    section = level_section(config, levels)
    shared = concentric_polygons(config, levels, section.polygons)
    computed = concentric_polygons(config, levels)
    assert shared == computed
    for a, b in zip(shared, computed):
        assert (a.polygon is None) == (b.polygon is None)
        if a.polygon is not None:
            assert a.polygon.directions == b.polygon.directions
            assert polygon_integer_directions(a.polygon) == \
                integer_directions(b.polygon.directions)
            assert gap_ids(a.polygon) == gap_ids(b.polygon)
            assert a.lines == b.lines


@settings(max_examples=15, deadline=None)
@given(st.lists(st.tuples(st.integers(-10**6, 10**6), st.integers(1, 1000),
                          st.integers(-10**6, 10**6), st.integers(1, 1000)),
                min_size=64, max_size=100, unique=True))
def test_family_rings_from_the_levels_vectors_equal_the_computed_ones(coords):
    """built_levels keeps each one-point level's vector p - C; the family layer's rings
    built from them equal those it computes (and another point sequence ignores them)."""
    from flint import fmpq
    from exactsym.paper.family.concentric import concentric_polygons
    points = list(dict.fromkeys((fmpq(a, b), fmpq(c, d)) for a, b, c, d in coords))
    config = Configuration.from_points(points)
    lazy = levels_of(config)
    built = built_levels(lazy)
    if isinstance(lazy.levels, RationalLevels):
        assert built.vectors is not None and built.vectors[0] is config.points
        cx, cy = built.sec.centre
        for i, (dx, dy) in built.vectors[1].items():
            assert (dx, dy) == (points[i][0] - cx, points[i][1] - cy)
    shared, computed = concentric_polygons(config, built), concentric_polygons(config, lazy)
    assert shared == computed
    for a, b in zip(shared, computed):
        assert a.polygon.directions == b.polygon.directions and a.n == b.n
        assert a.lines == b.lines
    # the vectors name their own point sequence: an equal copy of it does not use them
    other = Configuration.from_points(points)
    assert concentric_polygons(other, built) == computed


_radius_texts = st.text(max_size=6) | st.builds(lambda p, q: f"{p}/{q}", st.integers(),
                                                 st.integers(1, 10**30))


@settings(max_examples=100, deadline=None)
@given(_radius_texts, st.sampled_from([[7], [0], [True], [7, 8], ["7"], [7.5], []]),
       st.booleans())
def test_one_robot_level_text_is_what_the_encoder_writes(radius, points, strings):
    """report._item's one-robot shortcut, and the keys it falls back on, write what
    json.dumps writes."""
    import json
    from exactsym.paper.polygon_report import LabelledVerdict
    from exactsym.report.check import _item, check_report
    report = check_report(Configuration.from_points([(0, 0), (1, 0), (0, 2), (3, 1), (-5, 2)]))
    paper = next(e["paper"] for e in report["levels"] if len(e["points"]) == 1)
    assert type(paper) is LabelledVerdict and paper.json_parts is not None
    entry = {"radius_squared": radius, "points": points, "paper": paper}
    if strings:
        entry["strings"] = {"cw": [radius]}
    assert _item(entry) == json.dumps(entry, separators=(", ", ": "))
    reordered = {"points": points, "radius_squared": radius, "paper": paper}
    assert _item(reordered) == json.dumps(reordered, separators=(", ", ": "))


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(st.integers(-10**9, 10**9), st.integers(1, 10**6)), max_size=6),
       st.integers(1, 10**6), st.integers(1, 10**6))
def test_adjoin_sqrt_of_rational_numbers_as_of_their_mq_copies(numbers, p, q):
    """adjoin_sqrt leaves rational numbers unconverted (they have no radicand): the same
    system and root as when every number is an MQ rational."""
    from flint import fmpq
    from exactsym.exact.adjoin_sqrt import adjoin_sqrt
    from exactsym.exact.evaluate import RationalSystem
    from exactsym.exact.multiquadratic import MQ
    rationals = [fmpq(a, b) for a, b in numbers]
    fast = adjoin_sqrt(RationalSystem(), rationals, fmpq(p, q))
    slow = adjoin_sqrt(RationalSystem(), [MQ.rational(v) for v in rationals], fmpq(p, q))
    assert (fast is None) == (slow is None)
    if fast is not None:
        assert type(fast[0]) is type(slow[0]) and fast[0].name == slow[0].name
        assert fast[1] == slow[1]


@settings(max_examples=20, deadline=None)
@given(st.lists(st.tuples(st.integers(-10**6, 10**6), st.integers(1, 1000)), min_size=128,
                max_size=160))
def test_coincident_points_found_with_the_shared_floats(coords):
    """Configuration.float_points (the floats the coincidence check and the levels share)
    are float_coordinates of the points; coincident points are still refused, first pair
    named, also when they differ only beyond a double's precision."""
    import numpy as np
    import pytest
    from flint import fmpq
    from exactsym.errors import InputError
    from exactsym.geometry.predicates import float_coordinates
    xs = [fmpq(a, b) for a, b in coords[:64]]
    ys = [fmpq(a, b) for a, b in coords[64:128]]
    points = list(dict.fromkeys(zip(xs, ys)))
    if len(points) < 64:
        return
    config = Configuration.from_points(points)
    fx, fy = config.float_points
    want = float_coordinates(config.points)
    assert np.array_equal(fx, want[0]) and np.array_equal(fy, want[1])
    near = (points[5][0] + fmpq(1, 10**30), points[5][1])     # equal floats, distinct
    Configuration.from_points(points + [near])
    with pytest.raises(InputError, match=f"points 5 and {len(points)} coincide"):
        Configuration.from_points(points + [points[5]])


def test_robot_count_counts_every_robot():
    from exactsym.paper.family.concentric import concentric_polygons, robot_count
    config = Configuration.from_points([(0, 0), (1, 0), (0, 1), (-1, 0), (3, 4), (5, 0)])
    rings = concentric_polygons(config, levels_of(config))
    assert robot_count(rings) == sum(len(r.robots) for r in rings) == config.n
    assert robot_count(iter(rings)) == config.n and robot_count([]) == 0
