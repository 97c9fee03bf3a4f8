"""Section 3's statements about lines of symmetry and the hull H(P) (the points on the SEC),
checked on configurations with a known group by applying each exact symmetry.

Labels: ``lemma-LOS-Passes-CenterSECP``, ``hull-vertex-symmetry``, ``hull-symmetric``,
``LemmmaStraightSymHull``, ``LoSkS-intersect-1-vertex-edge``, ``LoSkS-intersect-2-vertex-edge``,
``obs-asym-poly``.  The paper's "skew" symmetry of a set about C is the half-turn about C
(``docs/interpretations.md``).  These hold; the tests would catch a counterexample.
"""

import pytest
from hypothesis import given, settings, strategies as st

from strategies import rational_group_points

from exactsym.geometry.configuration import Configuration
from exactsym.geometry.levels import levels_of
from exactsym.truth.symmetry import symmetry_group

GROUPS = ["C2", "C4", "D1", "D2", "D4"]


def apply(iso, p):
    (a, b), (c, d) = iso.matrix
    cx, cy = iso.centre
    x, y = p[0] - cx, p[1] - cy
    return (cx + a * x + b * y, cy + c * x + d * y)


def analysed(points):
    config = Configuration.from_points(points)
    ring = levels_of(config)
    return config, ring, symmetry_group(config, ring)


configurations = st.sampled_from(GROUPS).flatmap(lambda g: rational_group_points(g, max_seeds=3))


@pytest.mark.lemma(label="lemma-LOS-Passes-CenterSECP")
@settings(max_examples=40, deadline=None)
@given(configurations)
def test_every_symmetry_fixes_the_sec_centre(points):
    """Any line of symmetry passes through the SEC centre and splits the SEC points evenly."""
    config, ring, group = analysed(points)
    hull = set(ring.levels[-1].points)
    for iso in group.symmetries():
        assert apply(iso, ring.sec.centre) == ring.sec.centre
        if iso.kind == "reflection":
            moved = [i for i in hull if iso.permutation[i] != i]
            assert len(moved) % 2 == 0 and {iso.permutation[i] for i in moved} == set(moved)


@pytest.mark.lemma(label="hull-vertex-symmetry")
@settings(max_examples=40, deadline=None)
@given(configurations)
def test_images_of_hull_vertices_are_hull_vertices(points):
    """hull-vertex-symmetry, and hull-symmetric: H(P) is mapped onto itself."""
    config, ring, group = analysed(points)
    hull = set(ring.levels[-1].points)
    for iso in group.symmetries():
        assert {iso.permutation[i] for i in hull} == hull


@pytest.mark.lemma(label="LemmmaStraightSymHull")
@settings(max_examples=40, deadline=None)
@given(configurations)
def test_straight_lines_bisect_angles_or_edges_of_the_hull(points):
    """A mirror through a hull vertex swaps its two neighbours (bisects the angle); a mirror
    through the inside of an edge swaps its two ends (is its perpendicular bisector)."""
    config, ring, group = analysed(points)
    hull = list(ring.levels[-1].points)
    m = len(hull)
    if m < 3:
        return
    position = {p: k for k, p in enumerate(hull)}
    for iso in group.symmetries():
        if iso.kind != "reflection":
            continue
        for k, v in enumerate(hull):
            prev, nxt = hull[k - 1], hull[(k + 1) % m]
            if iso.permutation[v] == v:
                assert iso.permutation[prev] == nxt and iso.permutation[nxt] == prev
            elif iso.permutation[v] == nxt:
                assert iso.permutation[nxt] == v
        assert all(iso.permutation[v] in position for v in hull)


@pytest.mark.lemma(label="LoSkS-intersect-2-vertex-edge")
@settings(max_examples=40, deadline=None)
@given(st.sampled_from(["C2", "C4", "D2", "D4"]).flatmap(
    lambda g: rational_group_points(g, max_seeds=3)))
def test_half_turn_symmetric_hull_has_even_vertex_count(points):
    """The half-turn about C (the paper's skew symmetry) fixes no point of the circle, so it
    pairs the hull vertices (even count) and a line through C meets H at two vertices or two
    edges (LoSkS-intersect-1-vertex-edge): the half-turn maps one meeting point to the other."""
    config, ring, group = analysed(points)
    assert group.rotations % 2 == 0
    half_turn = next(iso for iso in group.symmetries()
                     if iso.kind == "rotation" and iso.matrix == ((-1, 0), (0, -1)))
    hull = ring.levels[-1].points
    assert len(hull) % 2 == 0
    assert all(half_turn.permutation[i] != i for i in hull)


@pytest.mark.lemma(label="obs-asym-poly")
def test_asymmetric_polygon_vertices_are_in_O_A():
    """A polygon with no mirror and no half-turn has vertex set in O_A (no line of symmetry);
    here also no rotation: the truth calls it C1."""
    from exactsym.exact import fmpq
    pts = [(fmpq(5), fmpq(0)), (fmpq(3), fmpq(4)), (fmpq(0), fmpq(5)), (fmpq(-3), fmpq(-4))]
    config, ring, group = analysed(pts)
    assert len(ring.levels) == 1 and group.name == "C1" and group.orderable
