"""The Arb-ball filters of the truth for irrational coordinates (exactsym/geometry/algebraic_filtered.py)
decide exactly as the exact path: same levels (with their exact radii), same group, same
canonical ordering, leader, reference and symmetries, on adversarial near-ties (points
moved by 1e-30 off a symmetric position), on genuinely equal distances spelled with
different radicals, and under exact similarities (which change no verdict)."""

from __future__ import annotations

import pickle
from contextlib import contextmanager
from fractions import Fraction

import pytest
from flint import arb
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import exactsym.geometry.levels as levels_module
from exactsym.geometry.configuration import Similarity, _coincident, from_file
from exactsym.errors import InputError
from exactsym.exact import exact_key, fmpq, number_text
from exactsym.exact.field import PolyElement
from exactsym.io.fileformat import parse_config_text
from exactsym.geometry.levels import AlgebraicLevels, levels_of
from exactsym.truth.symmetry import _certified_c1, symmetry_group


def _config(rows: list[tuple[str, str]]):
    text = "format = 1\npoints = [\n" + "".join(f'  ["{x}", "{y}"],\n' for x, y in rows) + "]\n"
    return from_file(parse_config_text(text, "<test>.toml", "toml"))


@contextmanager
def _exact_only():
    levels_module.ALGEBRAIC_FILTER = False
    try:
        yield
    finally:
        levels_module.ALGEBRAIC_FILTER = True


def _verdict(config):
    """Everything the truth reports; numbers as their canonical text (two loads of one
    file may build two towers of fields, whose elements do not compare)."""
    ring = levels_of(config)
    group = symmetry_group(config, ring)
    return (tuple((level.points, number_text(level.radius_squared)) for level in ring.levels),
            tuple(ring.sec.support), group.name, group.ordering, group.leader,
            group.reference, group.orderable,
            tuple(s.permutation for s in group.symmetries()),
            tuple(number_text(v) for v in group.centre))


def _both(config):
    """(filtered, exact) verdicts of one configuration (the exact one on a fresh copy:
    nothing cached is shared)."""
    filtered = _verdict(config)
    with _exact_only():
        exact = _verdict(_config(config._rows))
    return filtered, exact


def _make(rows):
    config = _config(rows)
    config._rows = rows
    return config


# ---------------------------------------------------------------- configurations

def _orbit_rows(k: int, mirror: bool, seeds, denominator: int, nudge, extra):
    """Orbits of Ck (Dk with ``mirror``) of points ``r (cos, sin)(2 pi (s + j/k))``, written
    with cos/sin of rational multiples of pi; ``nudge``: (index, "1e-30") moves one
    coordinate; ``extra``: further rows."""
    rows = []
    for r, s in seeds:
        for j in range(k):
            for sign in ((1, -1) if mirror else (1,)):
                a = 2 * (sign * Fraction(s, denominator) + Fraction(j, k))
                rows.append((f"{r}*cos({a.numerator}*pi/{a.denominator})",
                             f"{r}*sin({a.numerator}*pi/{a.denominator})"))
    if nudge is not None:
        i, eps = nudge
        i %= len(rows)
        rows[i] = (f"{rows[i][0]} + {eps}", rows[i][1])
    return rows + list(extra)


RADII = ["1", "sqrt(2)", "3/2", "sqrt(3)", "2"]


@st.composite
def orbit_configurations(draw):
    k = draw(st.integers(1, 6))
    mirror = draw(st.booleans())
    radii = draw(st.lists(st.sampled_from(RADII), min_size=1, max_size=3, unique=True))
    denominator = draw(st.sampled_from([5, 8, 12]))
    # seeds off the mirror lines and the axes of Dk: 2s/denominator is no multiple of 1/k
    seeds = [(r, draw(st.integers(1, denominator - 1))) for r in radii]
    nudge = draw(st.one_of(st.none(), st.tuples(st.integers(0, 50),
                                                st.sampled_from(["1e-30", "-1e-30", "1/7"]))))
    extra = draw(st.sampled_from([(), (("1/3", "1/5"),), (("0", "0"),)]))
    rows = _orbit_rows(k, mirror, seeds, denominator, nudge, extra)
    if len(set(rows)) != len(rows):
        rows = list(dict.fromkeys(rows))
    return rows


@settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(orbit_configurations())
def test_filtered_equals_exact_on_orbits_and_near_misses(rows):
    try:
        config = _make(rows)
    except InputError:              # two seeds met (coincident points): not a case
        return
    filtered, exact = _both(config)
    assert filtered == exact


def test_near_miss_pentagon_is_certified_without_symmetry():
    pentagon = [(f"cos(2*pi*{j}/5)", f"sin(2*pi*{j}/5)") for j in range(5)]
    for eps in ("1e-30", "1e-100"):
        rows = [(f"1 + {eps}", "0")] + pentagon[1:] + [("1/2", "1/3")]
        config = _make(rows)
        filtered, exact = _both(config)
        assert filtered == exact
        assert filtered[2] == "C1"
        assert _certified_c1(config, levels_of(config)) is not None


def test_equal_distances_spelled_differently():
    # five points at distance sqrt(8) from the origin (the SEC centre: no gap over half a
    # turn), written with different radicals; one inside
    rows = [("sqrt(3)+1", "sqrt(3)-1"), ("2*sqrt(2)", "0"), ("2", "2"), ("0", "-sqrt(8)"),
            ("-sqrt(6)", "-sqrt(2)"), ("1/3", "1/5"), ("-1", "sqrt(2)")]
    config = _make(rows)
    filtered, exact = _both(config)
    assert filtered == exact
    levels = filtered[0]
    assert levels[-1] == ((1, 0, 2, 4, 3), "8")
    assert filtered[2] == "C1"


def test_genuine_ties_in_the_canonical_labelling():
    # a C4 set with one point removed: most gaps are equal in fours (confirmed exactly),
    # the group is C1, and the labelling must equal the exact one
    rows = _orbit_rows(4, False, [("1", 1), ("sqrt(2)", 2), ("2", 3)], 12, None, ())[:-1]
    config = _make(rows)
    filtered, exact = _both(config)
    assert filtered == exact
    assert filtered[2] == "C1"
    assert _certified_c1(config, levels_of(config)) is not None


@pytest.mark.parametrize("similarity", [
    Similarity(rotation=(fmpq(3, 5), fmpq(4, 5))),
    Similarity(reflect=True, scale=fmpq(7, 3)),
    Similarity(rotation=(fmpq(-5, 13), fmpq(12, 13)), shift=(fmpq(1, 2), fmpq(-3))),
])
def test_similarity_changes_no_verdict(similarity):
    rows = [("sqrt(2)", "sqrt(3)"), ("sqrt(5)+sqrt(7)", "1/2"), ("sqrt(7)-3", "-sqrt(3)"),
            ("1", "-1"), ("-2", "sqrt(5)/3")]
    config = _make(rows)
    moved = config.transformed(similarity)
    before, after = symmetry_group(config), symmetry_group(moved)
    assert before.name == after.name == "C1"
    assert before.ordering == after.ordering and before.leader == after.leader
    ring, moved_ring = levels_of(config), levels_of(moved)
    assert [set(level.points) for level in ring.levels] == \
        [set(level.points) for level in moved_ring.levels]
    with _exact_only():
        exact = symmetry_group(moved, levels_of(moved))
    assert exact.ordering == after.ordering


def test_lazy_values_equal_the_exact_ones():
    rows = [("sqrt(2)", "sqrt(3)"), ("sqrt(5)+sqrt(7)", "sqrt(11)"),
            ("sqrt(13)-sqrt(17)", "sqrt(19)+sqrt(23)")]
    config = _make(rows)
    ring = levels_of(config)
    group = symmetry_group(config, ring)
    assert isinstance(ring.levels, AlgebraicLevels)
    with _exact_only():
        exact_ring = levels_of(_config(rows))
    assert tuple(group.centre) == tuple(exact_ring.sec.centre) == tuple(ring.sec.centre)
    assert group.centre == exact_ring.sec.centre
    assert pickle.loads(pickle.dumps(ring.levels)) == exact_ring.levels
    assert ring.levels[0].radius_squared == exact_ring.levels[0].radius_squared


@settings(max_examples=25, deadline=None)
@given(st.lists(st.tuples(st.integers(0, 3), st.integers(0, 3)), min_size=3, max_size=9))
def test_duplicate_check_by_balls_equals_the_exact_scan(picks):
    # coordinates from spellings of a few numbers (equal values, different spellings), in
    # a cyclotomic field (the last row's cosine): the duplicate check uses the balls
    spellings = [["cos(pi/5)", "(1+sqrt(5))/4", "sin(pi/10)+1/2"], ["1", "cos(0)", "2*cos(pi/3)"],
                 ["sqrt(3)+1", "2*sin(pi/3)+1", "1+sqrt(12)/2"], ["1/3", "2/6", "cos(pi/3)-1/6"]]
    rows = [(spellings[a][i % 3], spellings[b][(i + 1) % 3]) for i, (a, b) in enumerate(picks)]
    rows.append(("cos(pi/7)", "5"))
    text = "format = 1\npoints = [\n" + "".join(f'  ["{x}", "{y}"],\n' for x, y in rows) + "]\n"
    expected = None
    seen: dict = {}
    for i, v in enumerate(picks):
        j = seen.setdefault(v, i)
        if j != i:
            expected = (j, i)
            break
    try:
        config = from_file(parse_config_text(text, "<test>.toml", "toml"))
        found = None
        assert isinstance(config.points[-1][0], PolyElement)
    except InputError as err:
        found = tuple(int(w) for w in str(err).split("points ")[1].split(" coincide")[0]
                      .split(" and "))
    assert found == expected


def test_coincident_irrational_matches_exact_keys():
    rows = [("cos(pi/5)", "1"), ("1", "0"), ("(1+sqrt(5))/4", "1"), ("1", "sqrt(1)"),
            ("1", "0")]
    text = "format = 1\npoints = [\n" + "".join(f'  ["{x}", "{y}"],\n' for x, y in rows) + "]\n"
    with pytest.raises(InputError, match="points 0 and 2 coincide"):
        from_file(parse_config_text(text, "<test>.toml", "toml"))
    config = _config([("cos(pi/5)", "1"), ("1", "0"), ("sqrt(5)", "1/2")])
    points = config.points
    keys = [(exact_key(x), exact_key(y)) for x, y in points]
    assert len(set(keys)) == 3 and _coincident(config) is None


def test_levels_pickle_without_their_balls():
    config = _make([("sqrt(2)", "sqrt(3)"), ("sqrt(5)", "0"), ("0", "sqrt(7)")])
    ring = levels_of(config)
    copy = pickle.loads(pickle.dumps(ring))
    assert copy.enclosures is None and copy.levels == ring.levels
    assert symmetry_group(config, copy).ordering == symmetry_group(config, ring).ordering


@pytest.mark.parametrize("t", ["1e-45", "-1e-45"])
@pytest.mark.parametrize("moved", [0, 5])
def test_gap_near_tie_beyond_the_balls_decided_exactly(t, moved):
    # C4 rings at 10 and 50 degrees and one point on the ray at 140 degrees (so the balls
    # certify C1, the gaps unchanged); one ring point turned about C by an exact
    # Pythagorean rotation of about 2e-45 rad, radius unchanged: two gaps between the same
    # levels differ by less than the balls resolve, and that decides the labelling
    rows = []
    for j in range(4):
        rows.append((f"cos({1 + 9 * j}*pi/18)", f"sin({1 + 9 * j}*pi/18)"))
        rows.append((f"2*cos({5 + 9 * j}*pi/18)", f"2*sin({5 + 9 * j}*pi/18)"))
    rows.append(("3/2*cos(14*pi/18)", "3/2*sin(14*pi/18)"))
    x, y = rows[moved]
    c, s = f"((1-({t})^2)/(1+({t})^2))", f"(2*({t})/(1+({t})^2))"
    rows[moved] = (f"{c}*{x} - {s}*{y}", f"{s}*{x} + {c}*{y}")
    config = _make(rows)
    filtered, exact = _both(config)
    assert filtered == exact
    assert _certified_c1(config, levels_of(config)) is not None


POOLS = {"square roots": ["sqrt(2)", "sqrt(3)", "sqrt(6)", "1", "sqrt(5)"],
         "nested radicals": ["sqrt(2+sqrt(3))", "sqrt(5-sqrt(2))", "1", "sqrt(3)"],
         "cos and sin": ["cos(pi/7)", "sin(pi/7)", "cos(2*pi/9)", "1", "sqrt(3)"]}


@st.composite
def mixed_configurations(draw):
    """Points whose coordinates are small combinations a + b*w of numbers w of one pool,
    possibly completed to a C2, C4 or mirror-symmetric set, possibly moved off it."""
    pool = POOLS[draw(st.sampled_from(sorted(POOLS)))]
    term = st.builds(lambda a, b, w: f"{a} + {b}*{w}", st.integers(-3, 3), st.integers(-2, 2),
                     st.sampled_from(pool))
    base = draw(st.lists(st.tuples(term, term), min_size=3, max_size=6))
    rows = list(base)
    mode = draw(st.sampled_from(["plain", "c2", "c4", "mirror"]))
    if mode == "c2":
        rows += [(f"-({x})", f"-({y})") for x, y in base]
    elif mode == "c4":
        rows += [(f"-({y})", x) for x, y in base] + [(f"-({x})", f"-({y})") for x, y in base] \
            + [(y, f"-({x})") for x, y in base]
    elif mode == "mirror":
        rows += [(x, f"-({y})") for x, y in base]
    if mode != "plain" and draw(st.booleans()):
        i = draw(st.integers(0, len(rows) - 1))
        rows[i] = (f"{rows[i][0]} + {draw(st.sampled_from(['1e-30', '1e-60', '1/1000']))}",
                   rows[i][1])
    return rows


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(mixed_configurations())
def test_filtered_equals_exact_on_mixed_fields(rows):
    try:
        config = _make(rows)
    except InputError:              # coincident points
        return
    filtered, exact = _both(config)
    assert filtered == exact


@pytest.mark.parametrize("rows", [
    [("cos(2*pi/5)^3 - 1/2", "sin(pi/5)*3/4 + (1 + 1e-40) - 1"),
     ("2/(1+cos(pi/5))", "sqrt(5)"), ("sqrt(0)", "cos(pi/10)^-1")],
    [("sqrt(2+sqrt(3))/2", "(sqrt(3)-1)^-2"), ("1", "0"), ("0", "sqrt(5-sqrt(2))")],
])
def test_expression_balls_enclose_the_exact_values(rows):
    from exactsym.geometry.algebraic_filtered import coordinate_balls
    config = _config(rows)
    xs, ys = coordinate_balls(config.points, specs=config.specs)
    for (x, y), bx, by in zip(config.points, xs, ys):
        for value, ball in ((x, bx), (y, by)):
            exact = value.enclosure(200) if hasattr(value, "enclosure") else arb(value)
            assert ball.is_finite() and ball.overlaps(exact)
            assert ball.rad() < 1e-30


@pytest.mark.parametrize("den", [13, 38, 997])
def test_radii_from_the_divided_centre_are_the_squared_distances(den):
    """AlgebraicLevels writes |p - C|^2 as |p|^2 - 2 p.C + |C|^2 (|C|^2 once): each level's
    squared radius equals (x - cx)^2 + (y - cy)^2 of its points, exactly, for polar files
    about a centre off the origin (Q(zeta_4 den): the radicals p and 2p fold too)."""
    from exactsym.io.fileformat import parse_config_text as parse
    # the SEC through three robots of radii 5, 6, 7 a third of a turn apart: C = (X/D, Y/D)
    # with D irrational
    turns = [(5, 0), (6, den // 3), (7, 2 * den // 3), (1, 1), (2, 2), (3, den // 2)]
    text = "format = 1\npoints = [\n" + "".join(
        f'  {{ r = "{r}", turn = "{t}/{den}" }},\n' for r, t in turns) + "]\n"
    config = from_file(parse(text, "<test>.toml", "toml"))
    ring = levels_of(config)
    assert isinstance(ring.levels, AlgebraicLevels)
    cx, cy = ring.sec.centre
    assert len(ring.sec.support) == 3 and not ring.levels.enclosures.unit
    for level in ring.levels:
        for i in level.points:
            x, y = config.points[i]
            assert level.radius_squared == (x - cx) * (x - cx) + (y - cy) * (y - cy)
