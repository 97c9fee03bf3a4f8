"""The paper's verdicts on one polygon against the ground truth (exactsym.truth.symmetry).

Random inscribed polygons (orbits of Ck/Dk with rational turns, perturbed, arithmetic
progressions) become one-level configurations; the paper's verdicts (Theorem 1, the checks,
the lines the strings find, the types, the leader elections) are compared with the symmetry
group of the vertex set.  Every disagreement is classified; every class must be a *known*
class, documented by a minimal case under ``cases/discrepancies/`` (or ``cases/polygon/``)
which shows that class (:data:`KNOWN`).  A new kind of disagreement fails the test.

Exact laws that must hold without exception are asserted separately: the definitions
(def-straight/skew-symmetric-poly) agree with the truth, the strings never miss a mirror,
Theorem 1's "asymmetric" is sound, Check_Symmetry_Odd's degree is the number of mirrors.
"""

from __future__ import annotations

from fractions import Fraction
from pathlib import Path

import pytest
from hypothesis import HealthCheck, assume, event, given, settings

from exactsym.exact import normal_turn
from exactsym.geometry.configuration import load
from exactsym.geometry.levels import levels_of
from exactsym.paper import polygon as P
from exactsym.paper.keys import HALF, line_value, ray_value
from exactsym.paper.circle_polygon import level_polygon
from strategies import polar_configuration
from test_paper_polygon import polar_polygons

symmetry = pytest.importorskip("exactsym.truth.symmetry")

CASES = Path(__file__).resolve().parents[2] / "cases"

#: class of disagreement -> the case file that shows it (relative to cases/).
KNOWN = {
    "theorem1-rotation-only": "discrepancies/c3-nonagon-rotation-only.toml",
    "theorem1-free-middle": "discrepancies/c1-quadrilateral-free-middle.toml",
    "spurious-vertex-line": "discrepancies/half-hexagon-trapezoid.toml",
    "spurious-odd-edge-line": "discrepancies/isosceles-triangle.toml",
    "spurious-diameter-edge-line": "discrepancies/diameter-edge-quadrilateral.toml",
    "check-odd-rotation-only": "discrepancies/c3-nonagon-rotation-only.toml",
    "check-even-straight-missed": "discrepancies/isosceles-trapezoid-rational.toml",
    "check-even-straight-spurious": "discrepancies/c1-quadrilateral-free-middle.toml",
    "check-even-skew-spurious": "polygon/kite-polar.toml",
    "check-even-skew-missed": "discrepancies/square-degree.toml",
    "check-even-degree": "discrepancies/square-degree.toml",
    "type-unclassified": "discrepancies/d4-octagon.toml",
    "elect-sym-1sym_le": "discrepancies/kite-hexagon-1sym.toml",
    "elect-asym-chirality": "discrepancies/asym-leader-chirality.toml",
    "elect-asym-tie": "discrepancies/c3-nonagon-rotation-only.toml",
    "elect-asym-none": "discrepancies/scalene-triangle.toml",
}


def _edge_line_key(polygon, e):
    w = polygon.edge_direction(e)
    if w is None:
        w = P.perpendicular(polygon, polygon.directions[e])
    return line_value(polygon.polar, w)


def truth_lines(polygon, mirror_keys):
    """The true lines of straight symmetry as StraightLine records (vertices and edges on them)."""
    out = []
    for key in mirror_keys:
        vertices = tuple(i for i, d in enumerate(polygon.directions)
                         if line_value(polygon.polar, d) == key)
        edges = tuple(e for e in range(polygon.n) if _edge_line_key(polygon, e) == key)
        out.append(P.StraightLine(key, vertices, edges, ()))
    return out


def truth_type(polygon, mirror_keys) -> str | None:
    """The type the paper's definitions give with the *true* lines of straight symmetry."""
    kind = P.polygon_type(polygon, list(mirror_keys))
    return None if kind is None else str(kind)


def mirror_line_keys(polygon, group) -> set:
    keys = set()
    for iso in group.symmetries():
        if iso.kind != "reflection":
            continue
        if iso.turn is not None:
            keys.add(line_value(polygon.polar, iso.turn))
        else:                          # matrix ((c, s), (s, -c)): doubled angle (c, s)
            (c, s), _ = iso.matrix
            keys.add(ray_value(c, s))
    return keys


def analyse(config):
    """``(classes, facts)`` for a one-level polar configuration."""
    ring = levels_of(config)
    polygon = level_polygon(config, ring, len(ring.levels) - 1)
    group = symmetry.symmetry_group(config, ring)
    mirror_keys = mirror_line_keys(polygon, group)
    mirrors, rotations = group.mirrors, group.rotations
    n = polygon.n
    check = P.check_symmetry(polygon)
    lines = P.straight_lines(polygon)
    line_keys = {line.key for line in lines}
    t1_sym = not P.theorem1_asymmetric(polygon)
    kind = P.polygon_type(polygon)          # by the definition (exact mirrors)
    kind = None if kind is None else str(kind)
    central = rotations % 2 == 0
    classes = set()

    # exact laws (asserted, not classified)
    defs = P.definition_mirrors(polygon)
    assert set(defs) == mirror_keys, "def-straight-symmetric-poly disagrees with the truth"
    assert P.is_skew_symmetric(polygon) == central
    assert mirror_keys <= line_keys, "the strings missed a mirror"
    if not t1_sym:
        assert rotations == 1 and mirrors == 0, "Theorem 1 'asymmetric' is unsound"
    if n % 2:
        assert check.deg_sym == mirrors and check.straight == (mirrors > 0)

    if t1_sym and rotations == 1 and mirrors == 0:
        classes.add("theorem1-free-middle")
    if rotations > 1 and mirrors == 0 and not central:
        classes.add("theorem1-rotation-only")        # Theorem 1 symmetric, definitions not
    for line in lines:
        if line.key in mirror_keys:
            continue
        for where, index in line.found_at:
            if where == "vertex":
                classes.add("spurious-vertex-line")
            elif polygon.edge_direction(index) is None:
                classes.add("spurious-diameter-edge-line")
            else:
                classes.add("spurious-odd-edge-line" if n % 2 else "spurious-even-edge-line")
    if n % 2:
        if rotations > 1 and mirrors == 0:
            classes.add("check-odd-rotation-only")
    else:
        if mirrors and not check.straight:
            classes.add("check-even-straight-missed")
        if check.straight and not mirrors:
            classes.add("check-even-straight-spurious")
        if check.skew and not central:
            classes.add("check-even-skew-spurious")
        if central and not check.skew:
            classes.add("check-even-skew-missed")
        if (mirrors or central) and check.degree != mirrors:
            classes.add("check-even-degree")
    # the type follows the definition: equal to the type of the true mirrors (exact law);
    # the lines the strings find are lines_by_strings, classified above
    assert kind == truth_type(polygon, mirror_keys), "the type disagrees with the definition"
    if n % 2:
        assert kind != "unclassified", "an odd straight symmetric polygon always has a type"
    if kind == "unclassified":
        classes.add("type-unclassified")
    # leader election, for small polygons
    if n <= 10:
        if mirrors == 1 and rotations == 1 and truth_lines(polygon, mirror_keys)[0].vertices:
            if P.elect_leader_sym(polygon).leader is None:
                classes.add("elect-sym-1sym_le")
        if not check.symmetric:
            plus, minus = P.elect_leader_asym(polygon, 1), P.elect_leader_asym(polygon, -1)
            if plus.tie or minus.tie:
                classes.add("elect-asym-tie")
            elif plus.leader != minus.leader:
                classes.add("elect-asym-chirality")
            if group.orderable and plus.leader is None:
                classes.add("elect-asym-none")
    return classes, dict(group=group.name, check=check, lines=len(lines), type=kind)


def one_level(polygon):
    config = polar_configuration([(1, Fraction(int(t.p), int(t.q))) for t in polygon.directions])
    ring = levels_of(config)
    assume(ring.polar and len(ring.levels) == 1)
    return config


@settings(max_examples=250, deadline=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])
@given(polar_polygons(min_n=3, max_n=12))
def test_every_disagreement_is_a_known_class(polygon):
    classes, facts = analyse(one_level(polygon))
    for cls in sorted(classes):
        event(cls)
    unknown = classes - set(KNOWN)
    assert not unknown, f"new kind of disagreement {unknown} on {polygon.directions}: {facts}"


@pytest.mark.parametrize("cls", sorted(KNOWN))
def test_each_known_class_has_a_case_that_shows_it(cls):
    config = load(CASES / KNOWN[cls])
    classes, _ = analyse(config)
    assert cls in classes, f"{KNOWN[cls]} does not show {cls}: {classes}"


@pytest.mark.parametrize("path", sorted((CASES / "polygon").glob("*.toml"))
                         + sorted((CASES / "discrepancies").glob("*.toml")),
                         ids=lambda p: p.name)
def test_case_classes_are_known(path):
    config = load(path)
    if len(levels_of(config).levels) != 1:
        pytest.skip("several levels")
    classes, _ = analyse(config)
    assert classes <= set(KNOWN)


# ---------------------------------------------------------------- statements that hold
def _half_turn(group) -> bool:
    return group.rotations % 2 == 0


@settings(max_examples=150, deadline=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])
@given(polar_polygons(min_n=3, max_n=12))
def test_skew_statements_hold(polygon):
    """lemma-skewed-sym (lines through two opposite vertices: CW_m = CW_m' or ACW_m = ACW_m'
    iff the half-turn is a symmetry), obs-parallel-edge-equal (skew symmetric iff every edge has
    a parallel edge of equal length) and lem-rectangle (parallel equal edges are opposite sides
    of an inscribed rectangle) against the truth, with the skewed mirror image read as the
    half-turn about C (docs/interpretations.md)."""
    config = one_level(polygon)
    polygon = level_polygon(config, levels_of(config), 0)
    central = _half_turn(symmetry.symmetry_group(config))
    turns = polygon.directions
    n = polygon.n
    where = {t: i for i, t in enumerate(turns)}
    for i, t in enumerate(turns):
        j = where.get(normal_turn(t + HALF))
        if j is not None:
            criterion = (P.cw_string(polygon, i) == P.cw_string(polygon, j)
                         or P.acw_string(polygon, i) == P.acw_string(polygon, j))
            assert criterion == central
    if n < 3:
        return

    def chord(a):             # (direction class of the chord, its length key)
        b = (a + 1) % n
        return normal_turn(turns[a] + turns[b]), polygon.separation(a, b)
    partners = {}
    for a in range(n):
        for b in range(n):
            if a != b and chord(a) == chord(b):
                partners.setdefault(a, []).append(b)
                assert {turns[b], turns[(b + 1) % n]} == {
                    normal_turn(turns[a] + HALF), normal_turn(turns[(a + 1) % n] + HALF)}
    assert (len(partners) == n) == central
