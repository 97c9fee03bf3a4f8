"""The audit's other frames (the observer-independence of the paper's leader, and the
observer of the other handedness): the configuration in another exact coordinate system,
and its levels read from the levels the analysis already made instead of computed again.

A similarity S (reflection, rotation, scale, translation; robot indices kept) maps the
SEC onto the SEC, keeps which robots are at equal distance from its centre C and the
order of the distances, multiplies each squared radius by ``scale^2`` and maps each
vector p - C by its linear part L: the copy's SEC centre is S(C), its level k holds the
same robots, with squared radius ``scale^2 r_k^2``, and the copy's vector of robot i is
exactly L(p_i - C) (S(p) - S(C) = L(p - C) in exact arithmetic).  Only the order inside
each level (counter-clockwise from the copy's +x ray) is made again: a rotation keeps the
cyclic order, a reflection reverses it, and the level starts at its robot of least
angle in the copy (exact comparisons of :class:`~exactsym.geometry.predicates.PseudoAngle`).
The result is equal, value for value, to :func:`exactsym.geometry.levels.levels_of` of the
copy, which the paper's procedure in that frame would otherwise compute from scratch
(issue 33: on 100,000 random points the two frames' levels and polygons were half of
the check).  The paper's procedure itself is still run in the frame: its being
independent of the frame is what the audit checks (``lemma-sym-ord``, ``lem-asym-ord``,
``Elect_Leader_Asym``; :mod:`exactsym.audit.statements`).
"""

from __future__ import annotations

from ..exact import fmpq
from ..exact.number import is_plain_rational
from ..geometry.configuration import Configuration, Similarity
from ..geometry.levels import Level, Levels, ScaledLevels, VectorTable, mapped_levels
from ..geometry.predicates import PseudoAngle
from ..geometry.sec import Circle
from ..paper.circle_polygon import CirclePolygon
from ..paper.family import Ring

__all__ = ["POLAR_FRAMES", "CARTESIAN_FRAMES", "FRAME_TEXT", "transformed", "frame_levels",
           "mapped_rational_levels", "reflected_frame", "slim", "rings_fit", "frame_rings"]

#: The frames the paper is recomputed in: polar configurations about C stay polar.
POLAR_FRAMES = {"reflection": Similarity(reflect=True),
                "similarity": Similarity(turn=fmpq(1, 7), scale=2)}
CARTESIAN_FRAMES = {"reflection": Similarity(reflect=True),
                    "similarity": Similarity(rotation=(fmpq(3, 5), fmpq(4, 5)), scale=2,
                                             shift=(fmpq(1, 3), fmpq(-1, 2)))}

FRAME_TEXT = {
    "identity": "the file's coordinates",
    "reflection": "reflected (x, y) -> (x, -y) (polar: turn -> -turn)",
    "similarity": "rotated (3/5, 4/5), scaled by 2, translated by (1/3, -1/2) "
                  "(polar: turn + 1/7, r -> 2r)",
}


def transformed(config: Configuration, ring_data: Levels, frame: str) -> Configuration:
    """``config`` in another coordinate system, robot indices unchanged.

    Polar configurations (about C): ``reflection`` turn -> -turn; ``similarity`` turn ->
    turn + 1/7, r -> 2r (both keep the configuration polar: its Cartesian coordinates are
    never built).  Otherwise: ``reflection`` (x, y) -> (x, -y); ``similarity`` the
    rotation (3/5, 4/5), the scale 2 and the translation (1/3, -1/2), all exact."""
    if frame == "identity":
        return config
    if ring_data.polar and config.radii is not None:
        return config.transformed(POLAR_FRAMES[frame])
    cartesian = config.cartesian() if config.polar is not None else config
    return _similar(cartesian, CARTESIAN_FRAMES[frame])


def _similar(config: Configuration, sim: Similarity) -> Configuration:
    """:meth:`Configuration.transformed` of a Cartesian ``config`` under one of
    :data:`CARTESIAN_FRAMES`, without its check that no two robots coincide (a
    similarity is one-to-one; these scale by at least 1)."""
    return config.transformed(sim, check=False)


def frame_levels(config: Configuration, ring_data: Levels, moved: Configuration,
                 frame: str, rings=(), several: bool = False) -> Levels | None:
    """The levels of ``moved`` (``config`` in ``frame``, from :func:`transformed`) mapped
    from ``ring_data`` (the levels of ``config``) along the frame's similarity (the SEC,
    the levels and their radii are ground truth, not the paper's), or None (then the
    paper's procedure computes them): :func:`mapped_rational_levels` for a rational
    centre, :func:`exactsym.geometry.levels.mapped_levels` for the Arb-ball path of
    irrational coordinates.  ``rings``: the paper's own polygons G (their vectors p - C
    are mapped, not computed again)."""
    if ring_data.polar or moved.polar is not None:
        return None
    sim = CARTESIAN_FRAMES[frame]
    if ring_data.enclosures is None:
        return mapped_rational_levels(config, ring_data, moved, sim, several)
    enc = ring_data.enclosures
    if len(enc.points) != config.n or not all(a is b for a, b in zip(enc.points, config.points)):
        return None
    vectors = {label[0]: d for ring in rings if ring.polygon is not None
               and not ring.polygon.polar and len(ring.robots) == 1
               for label, d in zip(ring.polygon.labels, ring.polygon.directions)}
    return mapped_levels(ring_data, moved.points, sim, vectors)


def slim(result):
    """A frame's :class:`~exactsym.paper.family.PaperResult` without its polygons (``G_rings``
    and the described G, G'): the audit compares a frame's actions and trace only, and on
    a million robots a frame's polygons are gigabytes held while the next frame runs."""
    from dataclasses import replace
    return replace(result, G_rings=(), described=_nothing)


def _nothing() -> tuple:
    return [], []


def _linear(sim: Similarity):
    """The linear part of ``sim`` (no ``turn``) as a function of (x, y); a rotation's
    matrix is taken times the scale (k (c x - s y) = (k c) x - (k s) y exactly: two
    products fewer per point)."""
    k = sim.scale
    if sim.rotation is not None:
        c, s = sim.rotation
        if k != 1:
            c, s = k * c, k * s
        if sim.reflect:
            return lambda x, y: (c * x + s * y, s * x - c * y)
        return lambda x, y: (c * x - s * y, s * x + c * y)
    if sim.reflect:
        return (lambda x, y: (x, -y)) if k == 1 else (lambda x, y: (k * x, -k * y))
    return (lambda x, y: (x, y)) if k == 1 else (lambda x, y: (k * x, k * y))


def mapped_rational_levels(config: Configuration, ring_data: Levels, moved: Configuration,
                           sim: Similarity, several: bool = False) -> Levels | None:
    """See :func:`_mapped` (without the starts)."""
    found = _mapped(config, ring_data, moved, sim, several)
    return None if found is None else found[0]


def _mapped(config: Configuration, ring_data: Levels, moved: Configuration,
            sim: Similarity, several: bool = False) -> tuple | None:
    """The levels of ``moved`` = ``config`` under ``sim`` (robot indices kept), read from
    ``ring_data`` (see the module docstring), or None unless the SEC centre of
    ``ring_data`` is rational (homogeneous D = 1), its levels are built (a tuple, as
    :func:`exactsym.analysis.built_levels` leaves them), every robot is on one level,
    ``sim`` has no ``turn`` and both configurations' coordinates are plain rationals.
    ``Levels.vectors`` of the result holds the copy's vector S(p) - S(C) of every robot
    (taken by the family layer's polygons; ``several``: of the robots on levels of
    several robots only, for :func:`frame_rings`).  Returns ``(levels, starts)``: ``starts[k]``,
    for a level of several robots, where the copy's order starts in the first frame's
    order (reversed under a reflection)."""
    lv = ring_data.levels
    circle = ring_data.sec
    x, y, d = circle.homogeneous
    n = config.n
    if not isinstance(lv, tuple) or sim.turn is not None or n == 0 or moved.n != n \
            or not (is_plain_rational(d) and d == 1) \
            or not all(is_plain_rational(v) for v in (x, y)) \
            or not is_plain_rational(config.points[0][0]) \
            or not is_plain_rational(moved.points[0][0]) \
            or sum(len(level.points) for level in lv) != n:
        return None
    linear = _linear(sim)
    k2 = fmpq(sim.scale) ** 2
    # the copy's SEC: the image of the centre, the radius scaled; D stays 1
    ncx, ncy = linear(x, y)
    if sim.shift is not None:
        ncx, ncy = ncx + sim.shift[0], ncy + sim.shift[1]
    radius = circle.radius_squared * k2
    sec = Circle((ncx, ncy), radius, circle.support, (ncx, ncy, d))
    # the copy's vectors S(p) - S(C): two subtractions of the copy's coordinates (the
    # linear map of p - C costs products), or the sign of y of the first frame's vector
    # under a reflection alone
    known = ring_data.vectors
    old = known[1] if known is not None and known[0] is config.points else None
    mirror = sim.reflect and sim.rotation is None and sim.scale == 1 and sim.shift is None
    if several:
        # only the robots on levels of several robots (a one-robot level's ring in the
        # frame maps the first frame's vector on demand: frame_rings)
        mp = moved.points
        robots = [i for level in lv if len(level.points) > 1 for i in level.points]
        if old is not None and mirror and all(i in old for i in robots):
            vectors = {i: (old[i][0], -old[i][1]) for i in robots}
        else:
            vectors = {i: (mp[i][0] - ncx, mp[i][1] - ncy) for i in robots}
    elif old is not None and len(old) == n and mirror and \
            (not isinstance(old, VectorTable) or old.complete()):
        vectors = {i: (vx, -vy) for i, (vx, vy) in old.items()}
    else:
        vectors = {i: (px - ncx, py - ncy) for i, (px, py) in enumerate(moved.points)}
    new, setter = object.__new__, object.__setattr__
    built = []
    starts = {}
    if several and k2 != 1:
        own = {}
        for k, level in enumerate(lv):
            if len(level.points) > 1:
                members, starts[k] = _counter_clockwise(level.points, vectors, sim.reflect)
                own[k] = Level(level.radius_squared * k2, members)
        return Levels(sec, ScaledLevels(lv, k2, own), False,
                      vectors=(moved.points, vectors)), starts
    for k, level in enumerate(lv):
        members = level.points
        if len(members) > 1:
            members, starts[k] = _counter_clockwise(members, vectors, sim.reflect)
        elif k2 == 1:
            built.append(level)         # the same robot at the same squared radius
            continue
        r2 = level.radius_squared
        out = new(Level)                # Level(r2 * k2, members) without the frozen __init__
        setter(out, "radius_squared", r2 if k2 == 1 else r2 * k2)
        setter(out, "points", members)
        built.append(out)
    return Levels(sec, tuple(built), False, vectors=(moved.points, vectors)), starts


def _counter_clockwise(members: tuple, vectors: dict, reflect: bool) -> tuple[tuple, int]:
    """A level's robots (counter-clockwise in the first frame) counter-clockwise from the
    copy's +x ray: the cyclic order reversed by a reflection, then started at the robot
    of least angle.  Counter-clockwise, the angles in [0, 1) turn increase from that robot
    on, so the half-planes (upper with the +x ray: angle below half a turn; lower) run
    upper... lower...: when both occur the start is the one robot of the upper half after
    one of the lower (signs only); else the least exact pseudo-angle.  Returns the order
    and where it starts in ``order`` (None: the robot at C, the level kept)."""
    order = members[::-1] if reflect else members
    lower = []
    for i in order:
        vx, vy = vectors[i]
        if vy == 0 and vx == 0:            # the robot at C (a level of its own)
            return members, None
        lower.append(vy < 0 or (vy == 0 and vx < 0))
    starts = [k for k in range(len(order)) if lower[k - 1] and not lower[k]]
    if len(starts) == 1:
        start = starts[0]
    else:                                   # every robot in one half-plane
        start, least = 0, None
        for k, i in enumerate(order):
            angle = PseudoAngle(*vectors[i])
            if least is None or angle < least:
                start, least = k, angle
    return tuple(order[start:]) + tuple(order[:start]), start


def reflected_frame(config: Configuration, ring_data: Levels, moved: Configuration,
                    rings, several: bool = False) -> tuple:
    """``(levels, polygons)`` of the reflected copy ``moved`` (x, y) -> (x, -y) of ``config``:
    the levels as :func:`frame_levels` maps them, and the polygons of its levels of two or
    more robots as the paper's procedure takes them (``level_polygons``; None where a
    level has one robot), or ``(frame_levels(...), None)`` off the rational path.

    A polygon's vertices are the level's robots counter-clockwise in the copy, its
    directions the copy's vectors, its integer vectors those of the first frame's polygon
    (``rings``: the paper's G) with y negated -- what
    :func:`exactsym.paper.keys.integer_directions` of the copy's directions gives (the same
    denominators) -- and its gap ids those of the first frame's polygon in the copy's
    order (a reflection keeps every angle), renumbered in order of occurrence as
    :func:`exactsym.paper.keys.gap_ids` numbers them: not computed again."""
    sim = CARTESIAN_FRAMES["reflection"]
    found = None
    if not ring_data.polar and moved.polar is None and ring_data.enclosures is None:
        found = _mapped(config, ring_data, moved, sim, several)
    if found is None:
        return frame_levels(config, ring_data, moved, "reflection", rings), None
    levels, starts = found
    vectors = levels.vectors[1]
    first = {}
    for ring in rings:
        poly = ring.polygon
        if poly is not None and not poly.polar and len(ring.robots) > 1:
            first[ring.levels[0] - 1] = poly.__dict__
    out = []
    new = object.__new__
    for k, level in enumerate(levels.levels):
        robots = level.points
        m = len(robots)
        if m < 2:
            out.append(None)
            continue
        poly = new(CirclePolygon)
        fields = poly.__dict__
        fields.update(labels=robots, directions=tuple([vectors[i] for i in robots]),
                      polar=False, one_circle=True)
        known, start = first.get(k), starts.get(k)
        ints = None if known is None else known.get("integer_vectors")
        if ints is not None and start is not None and len(ints) == m:
            # the copy's vertex j is the first frame's vertex m - 1 - (start + j) mod m
            where = [m - 1 - (start + j) % m for j in range(m)]
            fields["integer_vectors"] = [(ints[t][0], -ints[t][1]) for t in where]
            gaps = known.get("gap_ids")
            if gaps is not None:
                # the copy's gap from vertex j to j + 1 is the first frame's gap from
                # its vertex where[j + 1] to where[j] = where[j + 1] + 1
                ids: dict = {}
                fields["gap_ids"] = [ids.setdefault(gaps[where[(j + 1) % m]], len(ids))
                                     for j in range(m)]
        out.append(poly)
    return levels, out


# ------------------------------------------------------------ the frame's G, mapped
def rings_fit(G, ring_data: Levels) -> bool:
    """Whether ``G`` (the paper's G of ``ring_data``'s configuration, one Cartesian ring
    per level) can be mapped into a frame by :func:`frame_rings`."""
    lv = ring_data.levels
    if ring_data.polar or ring_data.enclosures is not None or not isinstance(lv, tuple) \
            or len(G) != len(lv):
        return False
    return all(g.levels == (k + 1,) and g.robots == level.points
               for k, (g, level) in enumerate(zip(G, lv)))


def frame_rings(G, levels: Levels, moved: Configuration, frame: str,
                level_polygons=None) -> tuple | None:
    """G of the frame ``frame`` (``moved``, its levels ``levels`` from :func:`_mapped`
    with ``several``), equal ring by ring to
    :func:`exactsym.paper.family.concentric_polygons` of ``moved``, ``levels`` and
    ``level_polygons`` (tests/audit/test_frames.py), from the first frame's ``G``
    (:func:`rings_fit`): a level of one robot becomes a :class:`_FrameRing`, which holds
    the first frame's ring and makes its vector L(p - C) when it is read (issue 33: on a
    million robots each frame built a polygon, a ring and a vector per robot, about
    850 MB, though a one-robot level's verdicts are fixed); a level of several robots
    is built as the family layer builds it.  None when ``levels`` are not so mapped."""
    from ..paper.family.concentric import new_ring
    from ..paper.homogeneous import is_short, register
    linear = _linear(CARTESIAN_FRAMES[frame])
    k2 = fmpq(CARTESIAN_FRAMES[frame].scale) ** 2
    # the frame's map as a class attribute of a class of its own: a ring holds its base
    # only (64 bytes a ring)
    kind = type("_FrameRing", (_FrameRing,), {"__slots__": (), "frame": _VectorMap(linear, k2)})
    set_base = _FrameRing.base.__set__
    cx, cy = levels.sec.centre
    homogeneous = levels.sec.homogeneous
    pts = moved.points
    out = []
    make = object.__new__
    mapped = levels.levels
    if not isinstance(mapped, (tuple, ScaledLevels)) or len(mapped) != len(G):
        return None
    for k, base in enumerate(G):
        if len(base.robots) == 1 and base.polygon is not None:
            ring = make(kind)
            set_base(ring, base)
            out.append(ring)
            continue
        level = mapped[k]
        robots = level.points
        if base.polygon is None:                # the robot at C
            out.append(new_ring(base.name, None, level.radius_squared, base.levels, robots,
                                robots))
            continue
        labels = tuple([(i,) for i in robots])
        built = level_polygons[k] if level_polygons is not None else None
        poly = make(CirclePolygon)
        if built is not None and built.labels == robots and \
                not built.__dict__.get("cleared"):      # its directions are p - C
            poly.__dict__.update(labels=labels, directions=built.directions, polar=False,
                                 one_circle=True)
            for kept in ("integer_vectors", "gap_ids"):
                if kept in built.__dict__:
                    poly.__dict__[kept] = built.__dict__[kept]
        else:
            dirs = tuple([(pts[i][0] - cx, pts[i][1] - cy) for i in robots])
            if is_short(homogeneous):       # else register records nothing
                for i, d in zip(robots, dirs):
                    register(d, pts[i], homogeneous)
            poly.__dict__.update(labels=labels, directions=dirs, polar=False,
                                 one_circle=True)
        out.append(new_ring(base.name, poly, level.radius_squared, base.levels, robots,
                            robots))
    return tuple(out)


class _VectorMap:
    """The linear part of a frame's similarity, applied to a vector p - C, and the
    square of its scale (the factor of every squared radius)."""
    __slots__ = ("linear", "k2")

    def __init__(self, linear, k2):
        self.linear, self.k2 = linear, k2


class _FrameRing(Ring, CirclePolygon):
    """The ring of a one-robot level in a frame, and its polygon (one vertex; the ring is
    its own polygon: the family layer reads a ring's polygon millions of times): the
    first frame's ring ``base`` (its name, level, robot) seen through the frame's
    :class:`_VectorMap` ``frame`` (a class attribute: :func:`frame_rings` makes a subclass
    per frame).  The vertex's direction is L(d) for the first frame's
    direction d = p - C, made when first read and kept; the squared radius is the first
    frame's times scale^2.  Equal to another such ring with equal fields."""

    __slots__ = ("base",)
    frame: _VectorMap           # a class attribute of the frame's subclass
    n = 1
    at_centre = False
    polar = False
    one_circle = True

    @property
    def polygon(self) -> "_FrameRing":
        return self

    @property
    def name(self) -> str:
        return self.base.name

    @property
    def levels(self) -> tuple:
        return self.base.levels

    @property
    def robots(self) -> tuple:
        return self.base.robots

    @property
    def own(self) -> tuple:
        return self.base.robots

    @property
    def labels(self) -> tuple:
        return self.base.polygon.labels

    @property
    def radius_squared(self):
        k2 = self.frame.k2
        r2 = self.base.radius_squared
        return r2 if k2 == 1 else r2 * k2

    @property
    def directions(self) -> tuple:
        # kept in the instance dict, made only for the rings whose direction is read
        found = self.__dict__.get("_dirs")
        if found is None:
            found = self.__dict__["_dirs"] = (self.frame.linear(*self.base.polygon.directions[0]),)
        return found

    def _fields(self) -> tuple:
        return (self.name, self.radius_squared, self.levels, self.robots, self.directions)

    def __eq__(self, other):
        if other.__class__ is not self.__class__:
            return NotImplemented
        return self._fields() == other._fields()

    def __hash__(self) -> int:
        return hash((self.name, self.robots))

    def __repr__(self) -> str:
        return f"<{self.name} in a frame: robot {self.robots[0]}, direction {self.directions[0]}>"
