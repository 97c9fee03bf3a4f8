"""The audit's frames on rational configurations (:func:`exactsym.audit.frames.mapped_rational_levels`):
the levels of the copy read from the analysis's levels equal those computed from scratch
in the copy (SEC centre and radius, every level with its exact squared radius and its
robots counter-clockwise from the copy's +x ray, the vectors p - C), and the paper's
procedure run on them gives the same result as on the recomputed ones.  Inputs with ties:
orbits of the square's rotations and reflections (levels of 4 and 8 robots), a robot at
the centre, and more than 64 robots (the levels of the certified-float path)."""

from __future__ import annotations

from fractions import Fraction

from hypothesis import given, settings, strategies as st

from exactsym.analysis import built_levels
from exactsym.audit.frames import frame_levels, mapped_rational_levels, transformed
from exactsym.audit.statements import FRAMES
from exactsym.geometry.configuration import from_file
from exactsym.geometry.levels import levels_of
from exactsym.io.fileformat import parse_config_text
from exactsym.paper.family import paper_procedure


def _config(points):
    text = "".join(f"{x} {y}\n" for x, y in points)
    return from_file(parse_config_text(text, "<test>", "txt"))


@st.composite
def rational_sets(draw):
    """Orbits under D4 (or its rotations) of a few seeds about a rational centre, plus
    free points; sometimes a robot at the centre; sometimes more than 64 robots."""
    cx = Fraction(draw(st.integers(-3, 3)), draw(st.integers(1, 3)))
    cy = Fraction(draw(st.integers(-3, 3)), draw(st.integers(1, 3)))
    pts = set()
    mirror = draw(st.booleans())
    for _ in range(draw(st.integers(1, 12))):
        a, b = draw(st.integers(-9, 9)), draw(st.integers(-9, 9))
        orbit = [(a, b), (-b, a), (-a, -b), (b, -a)]
        if mirror:
            orbit += [(a, -b), (b, a), (-a, b), (-b, -a)]
        pts.update(orbit)
    for _ in range(draw(st.integers(0, 3))):
        pts.add((draw(st.integers(-12, 12)), draw(st.integers(-12, 12))))
    if draw(st.booleans()):
        pts.add((0, 0))
    else:
        pts.discard((0, 0))
    if len(pts) < 2:
        pts.update([(1, 0), (-1, 0)])
    return _config([(str(cx + x), str(cy + y)) for x, y in sorted(pts)])


def _assert_equal_levels(mapped, fresh, moved):
    assert tuple(mapped.sec.centre) == tuple(fresh.sec.centre)
    assert mapped.sec.radius_squared == fresh.sec.radius_squared
    assert tuple(mapped.levels) == tuple(fresh.levels)
    cx, cy = fresh.sec.centre
    owner, vectors = mapped.vectors
    assert owner is moved.points
    assert vectors == {i: (x - cx, y - cy) for i, (x, y) in enumerate(moved.points)}


@settings(max_examples=60, deadline=None)
@given(rational_sets())
def test_mapped_rational_levels_equal_the_recomputed_ones(config):
    ring = built_levels(levels_of(config))
    for frame in FRAMES[1:]:
        moved = transformed(config, ring, frame)
        mapped = frame_levels(config, ring, moved, frame)
        assert mapped is not None
        _assert_equal_levels(mapped, levels_of(moved), moved)


@settings(max_examples=15, deadline=None)
@given(rational_sets())
def test_the_paper_reads_the_mapped_levels_as_the_recomputed_ones(config):
    ring = built_levels(levels_of(config))
    for frame in FRAMES[1:]:
        moved = transformed(config, ring, frame)
        kw = dict(claims=False, check_vl=False, describe_polygons=False)
        a = paper_procedure(moved, frame_levels(config, ring, moved, frame), **kw)
        b = paper_procedure(moved, levels_of(moved), **kw)
        assert (a.leader, a.orderable, a.moves, a.trace) == (b.leader, b.orderable, b.moves,
                                                             b.trace)


def test_many_random_robots_and_an_orbit():
    # more than 64 robots (the certified-float levels): D4 orbits of 8 about the origin,
    # which hold the SEC, and single robots well inside it
    import random
    rnd = random.Random(5)
    pts = set()
    for _ in range(30):
        a, b = rnd.randint(500, 1000), rnd.randint(1, 499)
        pts.update([(a, b), (-b, a), (-a, -b), (b, -a), (a, -b), (b, a), (-a, b), (-b, -a)])
    pts.update((Fraction(rnd.randint(-10**4, 10**4), rnd.randint(50, 99)),
                Fraction(rnd.randint(-10**4, 10**4), rnd.randint(50, 99))) for _ in range(100))
    config = _config([(str(x), str(y)) for x, y in sorted(pts)])
    ring = built_levels(levels_of(config))
    assert any(len(level.points) == 8 for level in ring.levels)
    assert any(len(level.points) == 1 for level in ring.levels)
    for frame in FRAMES[1:]:
        moved = transformed(config, ring, frame)
        mapped = frame_levels(config, ring, moved, frame)
        assert mapped is not None
        _assert_equal_levels(mapped, levels_of(moved), moved)


def test_no_mapping_off_the_rational_path():
    # a lazy (unbuilt) sequence of levels is not mapped: the frame computes its own
    config = _config([("0", "0"), ("1", "0"), ("0", "1")])
    ring = levels_of(config)
    moved = transformed(config, ring, "similarity")
    lazy = type(ring)(ring.sec, list(ring.levels), False)
    from exactsym.audit.frames import CARTESIAN_FRAMES
    assert mapped_rational_levels(config, lazy, moved, CARTESIAN_FRAMES["similarity"]) is None


@settings(max_examples=40, deadline=None)
@given(rational_sets())
def test_the_reflected_polygons_carry_the_recomputed_keys(config):
    """The reflected copy's polygons (:func:`exactsym.audit.frames.reflected_frame`) take
    the first frame's integer vectors and gap ids: they equal those computed from the
    copy's own directions, and the paper's mirror run on them equals the run from
    scratch."""
    from exactsym.audit.frames import reflected_frame
    from exactsym.paper.circle_polygon import CirclePolygon
    from exactsym.paper.keys import gap_ids, integer_directions
    ring = built_levels(levels_of(config))
    paper = paper_procedure(config, ring)
    moved = transformed(config, ring, "reflection")
    levels, polygons = reflected_frame(config, ring, moved, paper.G_rings)
    assert polygons is not None and len(polygons) == len(levels.levels)
    for level, poly in zip(levels.levels, polygons):
        if len(level.points) < 2:
            assert poly is None
            continue
        assert poly.labels == level.points
        fresh = CirclePolygon(level.points, poly.directions, False)
        assert poly.__dict__.get("integer_vectors") == integer_directions(poly.directions)
        if "gap_ids" in poly.__dict__:
            assert poly.__dict__["gap_ids"] == gap_ids(fresh)
    kw = dict(claims=False, describe_polygons=False)
    a = paper_procedure(moved, levels, level_polygons=polygons, **kw)
    b = paper_procedure(moved, levels_of(moved), **kw)
    assert (a.leader, a.orderable, a.moves, a.trace) == (b.leader, b.orderable, b.moves,
                                                         b.trace)


def _ring_fields(ring):
    poly = ring.polygon
    return (ring.name, ring.levels, ring.robots, ring.own, ring.radius_squared, ring.n,
            ring.at_centre, None if poly is None else
            (poly.labels, poly.directions, poly.polar, poly.n, poly.one_circle),
            ring.lines)


def _frame_family(config, ring, paper, frame):
    """``(moved, levels, rings, polygons)`` of ``frame`` as the audit builds them."""
    from exactsym.audit.frames import frame_rings, reflected_frame, rings_fit
    moved = transformed(config, ring, frame)
    assert rings_fit(paper.G_rings, ring)
    if frame == "reflection":
        levels, polygons = reflected_frame(config, ring, moved, paper.G_rings, True)
    else:
        levels, polygons = frame_levels(config, ring, moved, frame, paper.G_rings, True), None
    rings = frame_rings(paper.G_rings, levels, moved, frame, polygons)
    assert rings is not None
    return moved, levels, rings, polygons


@settings(max_examples=40, deadline=None)
@given(rational_sets(), st.integers(0, 30))
def test_frame_rings_equal_the_family_layers_polygons(config, singles):
    """The frame's G mapped from the first frame's (:func:`exactsym.audit.frames.frame_rings`:
    one-robot levels seen through the frame's linear map) equals ring by ring the G the
    family layer builds from the copy's levels, computed from scratch, and the paper's
    procedure given it acts as on the copy analysed from scratch; the copy's levels
    (a lazy sequence under the similarity) equal the recomputed ones."""
    import random
    from exactsym.paper.family import concentric_polygons
    rnd = random.Random(singles)
    pts = [tuple(Fraction(str(c)) for c in p) for p in config.points]
    far = max(abs(c) for p in pts for c in p) + 1
    taken = set(pts)
    for _ in range(singles):       # robots of levels of their own, inside the SEC
        p = (Fraction(rnd.randint(-99, 99), 101) * far / 2,
             Fraction(rnd.randint(-99, 99), 103) * far / 2)
        if p not in taken:
            taken.add(p)
            pts.append(p)
    config = _config([(str(x), str(y)) for x, y in pts])
    ring = built_levels(levels_of(config))
    paper = paper_procedure(config, ring)
    for frame in FRAMES[1:]:
        moved, levels, rings, polygons = _frame_family(config, ring, paper, frame)
        fresh_levels = levels_of(moved)
        assert tuple(levels.levels) == tuple(fresh_levels.levels)
        fresh = concentric_polygons(moved, fresh_levels)
        assert len(rings) == len(fresh)
        for a, b in zip(rings, fresh):
            assert _ring_fields(a) == _ring_fields(b)
        kw = dict(claims=False, check_vl=False, describe_polygons=False)
        a = paper_procedure(moved, levels, level_polygons=polygons, rings=rings, **kw)
        b = paper_procedure(moved, fresh_levels, **kw)
        assert (a.leader, a.orderable, a.moves, a.trace, a.complete) == \
            (b.leader, b.orderable, b.moves, b.trace, b.complete)


@settings(max_examples=40, deadline=None)
@given(rational_sets())
def test_transformed_equals_the_configurations_own_map(config):
    """The audit's copy (no coincidence check: a similarity is one-to-one) has the points
    :meth:`Configuration.transformed` computes."""
    from exactsym.audit.frames import CARTESIAN_FRAMES
    ring = levels_of(config)
    for frame in FRAMES[1:]:
        assert transformed(config, ring, frame).points == \
            config.transformed(CARTESIAN_FRAMES[frame]).points


def test_scaled_levels_equal_their_tuple():
    from exactsym.exact import fmpq
    from exactsym.geometry.levels import Level, ScaledLevels
    base = (Level(fmpq(1, 3), (4,)), Level(fmpq(1, 2), (0, 2)), Level(fmpq(2), (1, 3)))
    own = {1: Level(fmpq(2), (2, 0))}
    lazy = ScaledLevels(base, fmpq(4), own)
    want = (Level(fmpq(4, 3), (4,)), Level(fmpq(2), (2, 0)), Level(fmpq(8), (1, 3)))
    assert len(lazy) == 3 and tuple(lazy) == want and lazy == want
    assert lazy[-1] == want[-1] and lazy[1:] == want[1:] and hash(lazy) == hash(want)
