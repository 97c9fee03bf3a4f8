"""The paper on one polygon (exactsym.paper.circle_polygon, exactsym.paper.polygon).

Exact expected values for small polygons, and laws: the efficient algorithms equal the
paper's literal loops on random polygons (symmetric orbits, perturbations, arithmetic
progressions where chord strings are ambiguous); exact similarities (rotations, reflections,
Cartesian vs polar) do not change the paper's verdicts; the observer's handedness does not
change the checks.
"""

from __future__ import annotations

from fractions import Fraction

import pytest
from hypothesis import HealthCheck, given, settings, strategies as st

from exactsym.exact import as_fmpq, evaluate_all, fmpq, normal_turn
from exactsym.io.expr import parse_expression
from exactsym.paper import polygon as P
from exactsym.paper.circle_polygon import (CirclePolygon, level_polygon,
                                           polygon_from_directions)

Q = fmpq
SETTINGS = settings(max_examples=150, deadline=None,
                    suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])


def polar(turns, labels=None) -> CirclePolygon:
    turns = [t if isinstance(t, type(Q(0))) else as_fmpq(Fraction(t)) for t in turns]
    return polygon_from_directions(labels if labels is not None else range(len(turns)), turns,
                                   True)


# ---------------------------------------------------------------- strategies
@st.composite
def polar_polygons(draw, min_n=2, max_n=14):
    """Turns on a circle: orbits of Ck/Dk, perturbed; random subsets of a grid; arithmetic
    progressions (whose chord strings are ambiguous)."""
    kind = draw(st.sampled_from(["orbit", "orbit", "grid", "progression"]))
    if kind == "grid":
        den = draw(st.sampled_from([8, 10, 12, 16, 20, 24]))
        ks = draw(st.lists(st.integers(0, den - 1), min_size=min_n, max_size=min(max_n, den),
                           unique=True))
        turns = {Q(k, den) for k in ks}
    elif kind == "progression":
        den = draw(st.sampled_from([12, 16, 20, 30, 36]))
        step = draw(st.integers(1, 4))
        count = draw(st.integers(min_n, max_n))
        start = draw(st.integers(0, den - 1))
        turns = {normal_turn(Q(start + step * j, den)) for j in range(count)}
        extra = draw(st.lists(st.integers(0, den - 1), max_size=2))
        turns |= {Q(e, den) for e in extra}
    else:
        k = draw(st.integers(1, 6))
        dihedral = draw(st.booleans())
        den = draw(st.sampled_from([2 * k, 3 * k, 4 * k, 5 * k, 60]))
        seeds = draw(st.lists(st.integers(0, den - 1), min_size=1, max_size=3, unique=True))
        turns = set()
        for s in seeds:
            for j in range(k):
                for t in ((Q(s, den), Q(-s, den)) if dihedral else (Q(s, den),)):
                    turns.add(normal_turn(t + Q(j, k)))
        if draw(st.booleans()) and len(turns) > 2:       # perturb: drop or move one vertex
            victim = draw(st.sampled_from(sorted(turns)))
            turns.discard(victim)
            if draw(st.booleans()):
                turns.add(normal_turn(victim + Q(1, 7 * den)))
    turns = sorted(turns)
    if len(turns) > max_n:
        turns = turns[:max_n]
    if len(turns) < min_n:
        turns = sorted(set(turns) | {Q(j, 97) for j in range(min_n)})[:max(min_n, len(turns))]
    return polar(turns)


def same_partition(a, b) -> bool:
    la, lb = list(a[0]) + list(a[1]), list(b[0]) + list(b[1])
    return all((la[x] == la[y]) == (lb[x] == lb[y]) for x in range(len(la)) for y in range(x))


def rotate_reflect(polygon: CirclePolygon, turn, reflect: bool) -> CirclePolygon:
    turns = [(-t if reflect else t) + turn for t in polygon.directions]
    return polygon_from_directions(polygon.labels, [normal_turn(t) for t in turns], True)


_S3 = None


def twelfths_cartesian(ks, scale=1, reflect=False, labels=None):
    """The 12th-root directions k/12 turn as exact vectors in Q(sqrt 3)."""
    global _S3
    if _S3 is None:
        system, (root,) = evaluate_all([parse_expression("sqrt(3)")])
        _S3 = (system, root)
    system, s3 = _S3
    one, half, zero = system.coerce(Q(1)), system.coerce(Q(1, 2)), system.coerce(Q(0))
    cos = [one, s3 / 2, half, zero, -half, -s3 / 2, -one, -s3 / 2, -half, zero, half, s3 / 2]
    vecs = [(scale * cos[k % 12], (-1 if reflect else 1) * scale * cos[(k - 3) % 12]) for k in ks]
    return polygon_from_directions(labels if labels is not None else range(len(ks)), vecs, False)


def verdicts(polygon):
    check = P.check_symmetry(polygon)
    lines = P.straight_lines(polygon)
    kind = P.polygon_type(polygon)
    return (check.deg_sym, check.straight, check.skew, check.degree, len(lines),
            None if kind is None else str(kind), P.theorem1_asymmetric(polygon),
            P.is_skew_symmetric(polygon), len(P.definition_mirrors(polygon)))


# ---------------------------------------------------------------- circle_polygon
def test_separation_keys_order_chords():
    sq = polar(["0", "1/4", "1/2", "3/4"])
    assert sq.separation(0, 2) == Q(1, 2) and sq.separation(0, 1) == sq.separation(0, 3) == Q(1, 4)
    cart = polygon_from_directions(range(4), [(Q(1), Q(0)), (Q(0), Q(1)), (Q(-1), Q(0)),
                                              (Q(0), Q(-1))], False)
    assert cart.separation(0, 2) == 1 and cart.separation(0, 1) == 0
    assert cart.metric == "signed-squared-cosine" and sq.metric == "angular-distance"
    # an edge of the square: m' at 1/8; distances to the endpoints (1/8) < to the far ones (3/8)
    assert [sq.separation_from_edge(0, j) for j in range(4)] == [Q(1, 8), Q(1, 8), Q(3, 8), Q(3, 8)]
    assert cart.separation_from_edge(0, 2) > cart.separation_from_edge(0, 0)


def test_edge_point_beyond_half_turn_and_diameter():
    # edge from 3/4 to 0 wraps; edge 0 -> 5/8 spans more than half a turn: m' is the antipode
    p = polar(["0", "5/8", "3/4"])
    assert p.edge_direction(0) == normal_turn(Q(5, 16) + Q(1, 2))
    assert p.edge_direction(2) == Q(7, 8)
    d = polar(["0", "1/5", "1/2"])              # edge (1/2 -> 0) is a diameter: m = C
    assert d.edge_direction(2) is None
    assert {d.separation_from_edge(2, j) for j in range(3)} == {Q(1, 4)}


def test_polygon_from_directions_sorts_and_rejects_duplicates():
    p = polygon_from_directions("abc", [Q(2, 3), Q(0), Q(1, 3)], True)
    assert p.labels == ("b", "c", "a")
    with pytest.raises(ValueError):
        polygon_from_directions("ab", [Q(1, 3), Q(4, 3)], True)
    with pytest.raises(ValueError):
        polygon_from_directions("ab", [(Q(1), Q(1)), (Q(2), Q(2))], False)


def test_unequal_lengths_edge_point():
    p = polygon_from_directions(range(3), [(Q(1), Q(0)), (Q(0), Q(4)), (Q(-2), Q(-2))], False)
    assert p.edge_direction(0) == (Q(1), Q(1))       # |u_b| = 4 |u_a|: rescaled exactly
    with pytest.raises(NotImplementedError, match="different lengths"):
        p.edge_direction(1)                          # sqrt(8)/4 is irrational


# ---------------------------------------------------------------- strings, exact values
def test_cw_string_starts_clockwise():
    p = polar(["0", "1/10", "1/4", "1/2", "7/10"])
    # vertex 0: clockwise neighbours are 7/10, 1/2, 1/4, 1/10
    assert P.cw_string(p, 0) == (Q(3, 10), Q(1, 2), Q(1, 4), Q(1, 10))
    assert P.acw_string(p, 0) == (Q(1, 10), Q(1, 4), Q(1, 2), Q(3, 10))
    assert P.cw_string(p, 0, -1) == P.acw_string(p, 0)
    # edge (0, 1): m' at 1/20; v_1 = vertex 0 (next clockwise), v_k = vertex 1
    assert P.cw_string_edge(p, 0) == (Q(1, 20), Q(7, 20), Q(9, 20), Q(1, 5), Q(1, 20))


def test_theorem1_and_1_1_on_examples():
    assert P.theorem1_asymmetric(polar(["0", "1/10", "1/4", "1/2", "7/10"]))
    c3 = polar(["0", "1/10", "1/4", "1/3", "13/30", "7/12", "2/3", "23/30", "11/12"])
    v = P.theorem1_violations(c3)
    assert v["1"] == [] and v["3"] == [] and (0, 3) in v["2"]
    assert not P.theorem1_asymmetric(c3) and not P.is_symmetric(c3)     # finding
    free = polar(["0", "1/8", "3/8", "5/8"])
    assert P.theorem1_violations(free)["1"] == [2] and not P.is_symmetric(free)


# ---------------------------------------------------------------- efficient == literal
@SETTINGS
@given(polar_polygons(), st.sampled_from([1, -1]))
def test_string_classes_equal_reference(polygon, orientation):
    assert same_partition(P.string_classes(polygon, orientation),
                          P.string_classes_reference(polygon, orientation))


@SETTINGS
@given(polar_polygons(min_n=2))
def test_checks_equal_paper_loops(polygon):
    for orientation in (1, -1):
        if polygon.n % 2:
            fast = P.check_symmetry_odd(polygon, orientation)
            slow = P.check_symmetry_odd_reference(polygon, orientation)
            literal = P.check_symmetry_odd_literal(polygon, orientation)
            assert literal.terminated == (fast.deg_sym == 0)
            if literal.terminated:
                assert literal.reports == slow.reports
        else:
            fast = P.check_symmetry_even(polygon, orientation)
            slow = P.check_symmetry_even_reference(polygon, orientation)
        assert fast.reports == slow.reports
        assert (fast.deg_sym, fast.degree, fast.straight, fast.skew, fast.axis_vertices) == \
            (slow.deg_sym, slow.degree, slow.straight, slow.skew, slow.axis_vertices)


@SETTINGS
@given(polar_polygons(min_n=2))
def test_palindromes_and_lines_equal_reference(polygon):
    assert P.edge_palindromes(polygon) == P.edge_palindromes(polygon, reference=True)
    fast = {(l.key, l.vertices, l.edges) for l in P.straight_lines(polygon)}
    slow = {(l.key, l.vertices, l.edges) for l in P.straight_lines(polygon, reference=True)}
    assert fast == slow
    assert P.theorem1_asymmetric(polygon) == P.theorem1_1_asymmetric(polygon)
    cw, acw = P.string_classes_reference(polygon)
    assert P.vertex_palindromes(polygon) == [i for i in range(polygon.n) if cw[i] == acw[i]]


def test_efficient_version_is_fast_on_large_polygons():
    import time
    n = 3000
    start = time.perf_counter()
    for turns in ([Q(i, n) for i in range(n)],
                  sorted({Q(0), Q(1, 2)} | {Q(c, 7 * n) for c in range(1, 3 * n, 3)}
                         | {Q(7 * n - c, 7 * n) for c in range(1, 3 * n, 3)})):
        p = polar(turns)
        P.check_symmetry(p)
        P.straight_lines(p)
        P.theorem1_asymmetric(p)
    assert time.perf_counter() - start < 15


# ---------------------------------------------------------------- exact similarities
@SETTINGS
@given(polar_polygons(min_n=2, max_n=10),
       st.builds(Fraction, st.integers(0, 59), st.sampled_from([1, 7, 12, 60])), st.booleans())
def test_verdicts_invariant_under_similarities(polygon, turn, reflect):
    image = rotate_reflect(polygon, as_fmpq(turn), reflect)
    assert verdicts(image) == verdicts(polygon)
    for orientation in (1, -1):
        assert P.check_symmetry(polygon, orientation).reports == \
            P.check_symmetry(polygon, 1).reports


@settings(max_examples=60, deadline=None)
@given(st.lists(st.integers(0, 11), min_size=2, max_size=9, unique=True),
       st.integers(0, 11), st.booleans(), st.integers(1, 5))
def test_cartesian_sqrt3_equals_polar(ks, shift, reflect, scale):
    """The same polygon as 12th roots of unity in Q(sqrt 3) (rotated, reflected, scaled) and as
    rational turns: identical verdicts and string partitions."""
    ks = sorted(ks)
    polar_p = polar([Fraction(k, 12) for k in ks])
    image = [((-k if reflect else k) + shift) % 12 for k in ks]
    cart = twelfths_cartesian(image, scale)
    assert verdicts(cart) == verdicts(polar_p)
    assert same_partition(P.string_classes(cart), P.string_classes_reference(cart))


# ---------------------------------------------------------------- Check_Symmetry_* values
def test_check_symmetry_odd_literal_does_not_terminate():
    p = polar(["0", "1/6", "3/8", "5/8", "5/6"])
    literal = P.check_symmetry_odd_literal(p, max_steps=50)
    assert not literal.terminated and literal.steps == 50 and literal.deg_sym == 50
    assert P.check_symmetry_odd(p).degree == 1
    asym = polar(["0", "1/10", "1/4", "1/2", "7/10"])
    assert P.check_symmetry_odd_literal(asym).terminated


@pytest.mark.parametrize("turns, deg_sym, degree, straight, skew", [
    (["0", "1/4", "1/2", "3/4"], 4, Q(2), True, False),                 # square: 4 lines
    (["0", "1/3", "1/2", "2/3"], 3, Q(3, 2), True, True),               # kite: 1 line
    (["0", "1/3", "1/2", "5/6"], 6, Q(3), False, True),                 # rectangle: 2 lines
    (["0", "1/8", "3/8", "5/8"], 1, Q(1, 2), True, False),              # asymmetric!
    (["0", "1/6", "1/3", "1/2", "2/3", "5/6"], 6, Q(3), True, False),   # regular hexagon
])
def test_check_symmetry_even_counts(turns, deg_sym, degree, straight, skew):
    r = P.check_symmetry_even(polar(turns))
    assert (r.deg_sym, r.degree, r.straight, r.skew) == (deg_sym, degree, straight, skew)


# ---------------------------------------------------------------- types
@pytest.mark.parametrize("turns, expected", [
    (["0", "1/5", "2/5", "3/5", "4/5"], "type-0"),
    (["0", "1/3", "1/2", "5/6"], "type-1"),                                   # rectangle
    (["0", "1/3", "1/2", "2/3"], "type-2"),                                   # kite
    (["0", "1/6", "3/8", "5/8", "5/6"], "type-3"),
    (["0", "1/3", "2/3", "1/10", "13/30", "23/30", "9/10", "7/30", "17/30"], "type-4"),
    (["1/20", "1/5", "3/10", "9/20", "11/20", "7/10", "4/5", "19/20"], "unclassified"),  # D4
    (["0", "1/10", "1/4", "2/5", "1/2", "3/5", "3/4", "9/10"], "unclassified"),         # D2
    (["0", "1/10", "1/4", "1/2", "7/10"], None),
])
def test_polygon_types(turns, expected):
    kind = P.polygon_type(polar(turns))
    assert (None if kind is None else str(kind)) == expected
    if kind is not None:
        assert kind.reason


def test_lemma_sym_regular_counterexample_by_definition():
    """D2 octagon: two mirrors, each through two vertices, not regular."""
    p = polar(["0", "1/10", "1/4", "2/5", "1/2", "3/5", "3/4", "9/10"])
    lines = P.straight_lines(p)
    assert len(P.definition_mirrors(p)) == 2 and len(lines) == 2
    assert all(len(line.vertices) == 2 for line in lines) and not P.is_regular(p)


# ---------------------------------------------------------------- leader election
def _reflected(polygon):
    """The reflection t -> -t and a map from the image's storage indices to the original's."""
    image = P.reflect_polygon(polygon)
    back = {k: polygon.labels.index(label) for k, label in enumerate(image.labels)}
    return image, back


@pytest.mark.parametrize("turns, leader", [
    (["0", "1/6", "3/8", "5/8", "5/6"], 0),            # odd D1: the vertex on the line
    (["1/4", "5/8", "7/8"], 0),
])
def test_elect_leader_sym_odd(turns, leader):
    p = polar(turns)
    for orientation in (1, -1):
        assert P.elect_leader_sym(p, orientation).leader == leader
    image, back = _reflected(p)
    assert back[P.elect_leader_sym(image).leader] == leader


def test_elect_leader_sym_even_literal_degree_fails():
    kite = polar(["0", "1/3", "1/2", "2/3"])
    assert P.elect_leader_sym(kite).leader is None                   # degree 3/2 (finding)
    by_lines = P.elect_leader_sym(kite, degree="lines")
    assert by_lines.leader == 0                                      # CW(v_0) > CW(v_2)
    assert P.elect_leader_sym(kite, -1, degree="lines").leader == 0


sym_polygons = st.builds(
    lambda seeds, axis, den: polar(sorted({normal_turn(Q(axis, den) + s * Q(k, den))
                                           for k in seeds for s in (1, -1)}
                                          | {Q(axis, den)})),
    st.lists(st.integers(1, 14), min_size=1, max_size=4, unique=True),
    st.integers(0, 29), st.sampled_from([30, 31]))


@settings(max_examples=60, deadline=None)
@given(sym_polygons, st.sampled_from([1, -1]))
def test_make_sym_to_asym_polar(polygon, orientation):
    """The leader moves by a rational turn, passes no vertex, and the result is asymmetric
    (Theorem 1: no isometry at all); the two handednesses give mirror images."""
    moved = P.make_sym_to_asym(polygon, orientation, degree="lines")
    if moved.leader is None:
        return
    assert moved.asymmetric and P.theorem1_asymmetric(moved.polygon)
    assert not P.is_symmetric(moved.polygon)
    old = polygon.labels
    start = moved.polygon.labels.index(old[0])
    assert moved.polygon.labels[start:] + moved.polygon.labels[:start] == old   # order kept
    other = P.make_sym_to_asym(polygon, -orientation, degree="lines")
    assert other.leader == moved.leader
    mirrored = rotate_reflect(other.polygon, 2 * polygon.directions[moved.leader], True)
    assert sorted(mirrored.directions) == sorted(moved.polygon.directions)


def test_make_sym_to_asym_cartesian_exact_on_circle():
    p = twelfths_cartesian([0, 3, 5, 7, 9])            # mirror through vertex at 3 (turn 1/4)
    moved = P.make_sym_to_asym(p, 1, degree="lines")
    assert moved.leader is not None and moved.asymmetric
    i = moved.polygon.labels.index(moved.label)
    u, v = p.directions[moved.leader], moved.polygon.directions[i]
    assert u[0] ** 2 + u[1] ** 2 == v[0] ** 2 + v[1] ** 2             # exactly on the circle
    assert isinstance(moved.parameter, type(Q(1)))


def _rotation_loop(polygon, orientation, max_halvings):
    """Make_SymToAsym's Cartesian loop for a single vertex, run in full (the reference
    for the shortcut of make_sym_to_asym: a one-vertex polygon is never asymmetric)."""
    tau, u, moved = Q(-orientation, 4), polygon.directions[0], polygon
    for _ in range(max_halvings):
        c, s = (1 - tau * tau) / (1 + tau * tau), 2 * tau / (1 + tau * tau)
        moved = polygon_from_directions(polygon.labels,
                                        [(u[0] * c - u[1] * s, u[0] * s + u[1] * c)], False)
        assert not P.theorem1_asymmetric(moved)
        tau /= 2
    return moved, tau


@settings(max_examples=40, deadline=None)
@given(st.integers(-50, 50), st.integers(-50, 50), st.sampled_from([1, -1]),
       st.integers(1, 12))
def test_make_sym_to_asym_one_vertex_is_the_full_loop(x, y, orientation, halvings):
    """A single vertex (Cartesian): the result made from the last rotation only is the
    loop's, polygon and parameter, for every budget of halvings."""
    if x == 0 and y == 0:
        return
    polygon = polygon_from_directions([7], [(Q(x, 3), Q(y, 5))], False)
    moved = P.make_sym_to_asym(polygon, orientation, degree="lines", max_halvings=halvings)
    expected, tau = _rotation_loop(polygon, orientation, halvings)
    assert moved.leader == 0 and not moved.asymmetric
    assert moved.polygon.directions == expected.directions and moved.parameter == tau


@settings(max_examples=80, deadline=None)
@given(polar_polygons(min_n=4, max_n=9))
def test_elect_leader_asym_reflection_law(polygon):
    """For both readings: what the mirrored observer elects in G is what the observer elects in
    the mirror image of G (mapped back).  The unordered reading is independent of the
    handedness; the literal one is not always (see the next test)."""
    if not P.theorem1_asymmetric(polygon):
        return
    image, back = _reflected(polygon)
    for reading in ("literal", "unordered"):
        a = P.elect_leader_asym(polygon, -1, reading)
        b = P.elect_leader_asym(image, 1, reading)
        assert (a.leader is None and b.leader is None) or a.leader == back[b.leader]
    plus = P.elect_leader_asym(polygon, 1, "unordered")
    minus = P.elect_leader_asym(polygon, -1, "unordered")
    assert plus.leader == minus.leader


def test_elect_leader_asym_depends_on_handedness():
    p = polar(["0", "1/10", "3/10", "7/10"])
    assert P.elect_leader_asym(p, 1).leader == 3
    assert P.elect_leader_asym(p, -1).leader == 2
    assert P.elect_leader_asym(p, 1, "unordered").leader == \
        P.elect_leader_asym(p, -1, "unordered").leader


def test_elect_leader_asym_triangle_has_no_leader():
    p = polar(["0", "1/5", "11/20"])
    assert P.theorem1_asymmetric(p)
    assert P.elect_leader_asym(p, 1).leader is None and P.elect_leader_asym(p, -1).leader is None


def test_level_polygon_cartesian_and_radius_zero():
    from exactsym.geometry.configuration import Configuration
    from exactsym.geometry.levels import levels_of
    config = Configuration.from_points([(0, 0), (5, 0), (0, 5), (-5, 0), (3, -4)])
    ring = levels_of(config)
    with pytest.raises(ValueError):
        level_polygon(config, ring, 0)
    poly = level_polygon(config, ring, 1)
    assert poly.labels == (1, 2, 3, 4) and not poly.polar


@settings(max_examples=60, deadline=None)
@given(st.lists(st.builds(Fraction, st.integers(-9, 9), st.integers(1, 5)), min_size=2,
                max_size=6, unique=True),
       st.booleans(), st.booleans(), st.integers(0, 3))
def test_rational_circle_points_under_pythagorean_similarities(params, mirror, reflect, which):
    """Rational points of the unit circle (Pythagorean parameters, optionally closed under
    the x-axis mirror), rotated by a rational rotation, maybe reflected and scaled: the
    verdicts do not change (Cartesian path, signed squared cosines)."""

    def point(t):
        t = as_fmpq(t)
        return ((1 - t * t) / (1 + t * t), 2 * t / (1 + t * t))
    ts = set(params) | ({-t for t in params} if mirror else set())
    pts = list(dict.fromkeys(point(t) for t in ts))
    base = polygon_from_directions(range(len(pts)), pts, False)
    c, s = [(Q(3, 5), Q(4, 5)), (Q(0), Q(1)), (Q(-5, 13), Q(12, 13)), (Q(8, 17), Q(-15, 17))][which]
    moved = []
    for x, y in pts:
        if reflect:
            y = -y
        moved.append((3 * (c * x - s * y), 3 * (s * x + c * y)))
    image = polygon_from_directions(range(len(pts)), moved, False)
    assert verdicts(image) == verdicts(base)
    assert same_partition(P.string_classes(base), P.string_classes_reference(base))
