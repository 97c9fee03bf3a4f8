"""The shortcuts of the full check (issue 9) equal what they replace."""

from __future__ import annotations

from hypothesis import given, settings, strategies as st

from exactsym.analysis import built_levels
from exactsym.configuration import Configuration
from exactsym.levels import Level, RationalLevels, levels_of

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
    from exactsym.report import _item
    assert _item(value) == json.dumps(value, separators=(", ", ": "))


@settings(max_examples=15, deadline=None)
@given(st.lists(st.tuples(st.integers(-50, 50), st.integers(-50, 50)), min_size=3, max_size=40,
                unique=True))
def test_verdict_templates_write_what_the_encoder_writes(points):
    import json
    from exactsym.paper.polygon_report import LabelledVerdict
    from exactsym.report import _item, check_report
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
    from exactsym.report import check_report
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
