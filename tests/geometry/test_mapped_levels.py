"""The audit's frames read the SEC and the levels of the configuration mapped along the
frame's exact similarity (:func:`exactsym.geometry.levels.mapped_levels`, ``audit._frame_levels``)
instead of recomputing them: the mapped levels equal those computed from scratch in the
moved frame (the same SEC centre and radius, the same levels with the same exact squared
radii and the same counter-clockwise order from the new +x ray), on configurations with
ties: whole orbits of rotations (equal radii), points on the SEC, a robot at the centre."""

from __future__ import annotations

from hypothesis import given, settings, strategies as st

from exactsym.analysis import built_levels
from exactsym.audit.frames import frame_levels as _frame_levels, transformed
from exactsym.audit.statements import FRAMES
from exactsym.geometry.configuration import from_file
from exactsym.io.fileformat import parse_config_text
from exactsym.geometry.levels import levels_of


@st.composite
def configurations(draw):
    """Polar orbits of C_k (k in 2..6) at radii 1, 2, 3/2 with phases in sixtieths, and
    one or two free points that pull the SEC off the origin."""
    points = []
    for _ in range(draw(st.integers(1, 3))):
        k = draw(st.integers(2, 6))
        r = draw(st.sampled_from(["1", "2", "3/2"]))
        phase = draw(st.integers(0, 59))
        points += [(r, f"{phase}/60 + {j}/{k}") for j in range(k)]
    for _ in range(draw(st.integers(1, 2))):
        points.append((draw(st.sampled_from(["5/2", "3", "2"])),
                       f"{draw(st.integers(0, 59))}/60"))
    seen, unique = set(), []
    for r, t in points:                     # distinct positions (equal turns, equal radii)
        key = (r, t)
        if key not in seen:
            seen.add(key)
            unique.append((r, t))
    text = "format = 1\npoints = [\n" + "".join(
        f'  {{ r = "{r}", turn = "{t}" }},\n' for r, t in unique) + "]\n"
    try:
        return from_file(parse_config_text(text, "<test>", "toml"))
    except Exception:                       # two turns naming one position
        return None


@settings(max_examples=40, deadline=None)
@given(configurations())
def test_mapped_levels_equal_the_recomputed_ones(config):
    if config is None:
        return
    ring = built_levels(levels_of(config))
    for frame in FRAMES[1:]:
        moved = transformed(config, ring, frame)
        mapped = _frame_levels(config, ring, moved, frame)
        if mapped is None:
            assert ring.polar
            continue
        fresh = levels_of(moved)
        assert tuple(mapped.sec.centre) == tuple(fresh.sec.centre)
        assert mapped.sec.radius_squared == fresh.sec.radius_squared
        assert tuple(mapped.levels) == tuple(fresh.levels)
        assert mapped.polar == fresh.polar
        if ring.enclosures is not None:         # the Arb-ball path (else: rational)
            assert mapped.enclosures.centre_index == fresh.enclosures.centre_index


@settings(max_examples=25, deadline=None)
@given(configurations())
def test_lazy_radii_and_centre_equal_the_exact_path(config):
    """AlgebraicLevels reads |p - C|^2 from the divided SEC centre (one inverse of D, no
    1/D^2): the levels equal those of the exact path (no Arb filters), and the centre is
    (X/D, Y/D)."""
    if config is None:
        return
    from exactsym.geometry import levels as L
    filtered = levels_of(config)
    L.ALGEBRAIC_FILTER = False
    try:
        exact = levels_of(config)
    finally:
        L.ALGEBRAIC_FILTER = True
    assert tuple(filtered.levels) == tuple(exact.levels)
    x, y, d = filtered.sec.homogeneous
    assert tuple(filtered.sec.centre) == (x / d, y / d)


@settings(max_examples=25, deadline=None)
@given(configurations(), st.data())
def test_groups_of_unions_of_levels_by_balls_equal_the_exact_ones(config, data):
    """audit_groups.group_about_centre hands the union of levels the whole configuration's
    coordinate balls (the truth may certify C1 by them): the same group, ordering and
    leader as the exact path (levels without enclosures)."""
    if config is None:
        return
    from exactsym.audit.groups import group_about_centre
    from exactsym.geometry.levels import Levels
    ring = built_levels(levels_of(config))
    bare = Levels(ring.sec, ring.levels, ring.polar)
    t = len(ring.levels)
    chosen = sorted(set(data.draw(st.lists(st.integers(1, t), min_size=1, max_size=3))))
    robots = [i for k in chosen for i in ring.levels[k - 1].points]
    (g1, r1), (g2, r2) = (group_about_centre(config, ring, robots, chosen),
                          group_about_centre(config, bare, robots, chosen))
    assert r1 == r2
    assert (g1.name, g1.orderable, g1.ordering, g1.leader) == \
        (g2.name, g2.orderable, g2.ordering, g2.leader)


@settings(max_examples=25, deadline=None)
@given(configurations())
def test_mapped_vectors_are_the_moved_points_minus_the_centre(config):
    """A reflected frame takes the paper's vectors p - C with one sign changed: each is
    the moved point minus the moved centre, exactly; a frame that rotates or scales maps
    none (it would cost what the subtraction costs); the paper's actions are the same
    with the mapped vectors as without them."""
    if config is None:
        return
    from exactsym.paper.family import paper_procedure
    ring = built_levels(levels_of(config))
    paper = paper_procedure(config, ring)
    for frame in FRAMES[1:]:
        moved = transformed(config, ring, frame)
        mapped = _frame_levels(config, ring, moved, frame, paper.G_rings)
        if mapped is None:
            continue
        if frame != "reflection" and ring.enclosures is not None:   # the Arb-ball path
            assert mapped.vectors is None
            continue
        if mapped.vectors is None:          # no level of one robot: nothing to map
            assert not any(ring.polygon is not None and len(ring.robots) == 1
                           for ring in paper.G_rings)
            continue
        owner, vectors = mapped.vectors
        assert owner is moved.points and vectors
        cx, cy = mapped.sec.centre
        for i, (vx, vy) in vectors.items():
            x, y = moved.points[i]
            assert vx == x - cx and vy == y - cy
        plain = paper_procedure(moved, _frame_levels(config, ring, moved, frame))
        with_vectors = paper_procedure(moved, mapped)
        assert [m["robot"] for m in with_vectors.moves] == [m["robot"] for m in plain.moves]
        assert with_vectors.leader == plain.leader
