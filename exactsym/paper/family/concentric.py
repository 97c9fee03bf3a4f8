"""The G model: the concentric polygons G_1..G_t (Section 3) and their lines of
symmetry (``def-sym-pair``, ``def-sym-calG``, ``lem-skew-los``).

A line of symmetry passes through C (``lemma-LOS-Passes-CenterSECP``) and is held as an
exact line key (:mod:`exactsym.paper.keys`).  :func:`lines_of_symmetry` is
:data:`ALL_LINES` for a skew symmetric polygon (``lem-skew-los``: every line through C)
and for the robot at C (``def-symmetric-conf``), else the finite set of lines of straight
symmetry.  Two or more polygons have a common line iff these sets intersect (ALL_LINES is
neutral); a skew symmetric polygon thus pairs symmetrically with every symmetric polygon
(the reading of ``lem-3-pair-sym``'s proof; ``docs/interpretations.md``).

:class:`Ring` is one polygon of G or G' (one level of :class:`exactsym.geometry.levels.Levels`, or
several merged by Preprocess); its vertex labels are tuples of configuration indices.
"""

from __future__ import annotations

from contextvars import ContextVar
from dataclasses import dataclass, field
from functools import cached_property
from operator import attrgetter
from typing import Iterable, Sequence

from ...geometry.configuration import Configuration
from ...exact import number_text, sign
from ...geometry.levels import Levels, levels_of
from ...geometry.strings import find_all
from ..circle_polygon import CirclePolygon
from ..homogeneous import register
from ..keys import bisector_key, gap_ids, line_key, ray_keys


class _AllLines:
    """Every line through C (the lines of a skew symmetric polygon, ``lem-skew-los``)."""
    _instance = None

    def __new__(cls):
        if cls._instance is None:
            cls._instance = super().__new__(cls)
        return cls._instance

    def __repr__(self) -> str:
        return "ALL_LINES"


ALL_LINES = _AllLines()


@dataclass(frozen=True)
class Ring:
    """A polygon of G or G' (nearest first).

    ``polygon``: the vertices (labels are tuples of configuration indices), or None for
    the robot at the centre C; ``radius_squared``: of its circle; ``levels``: the
    1-based numbers of the levels of G it contains (several after a merge);
    ``robots``: every configuration index in it; ``own``: those on its own circle."""
    name: str
    polygon: CirclePolygon | None
    radius_squared: object
    levels: tuple
    robots: tuple
    own: tuple
    keys: tuple = field(default=(), compare=False, repr=False)   # hashable ray keys

    @cached_property
    def n(self) -> int:
        return 1 if self.polygon is None else self.polygon.n

    @property
    def at_centre(self) -> bool:
        return self.polygon is None

    @cached_property
    def lines(self):
        return _compute_lines(self)

    @property
    def ray_keys(self) -> tuple:
        """The exact hashable keys of the rays of its vertices (computed once, on demand)."""
        keys = self.keys
        if not keys and self.polygon is not None and self.polygon.n:
            keys = ray_keys(self.polygon)
            object.__setattr__(self, "keys", keys)
        return keys


def robot_count(rings: Iterable[Ring]) -> int:
    """The number of robots in ``rings`` (iterated in C: one ring per robot on random
    configurations, and the budgets of Preprocess and the claims read it)."""
    return sum(map(len, map(_ROBOTS, rings)))


_ROBOTS = attrgetter("robots")


def polygon_name(levels: Sequence[int]) -> str:
    levels = sorted(levels)
    if len(levels) == 1:
        return f"G{levels[0]}"
    if len(levels) > 8:     # a readable name of bounded length
        return (f"G({','.join(map(str, levels[:3]))},...,{levels[-1]}: "
                f"{len(levels)} levels)")
    return "G(" + ",".join(map(str, levels)) + ")"


def new_ring(name, polygon, radius_squared, levels, robots, own, keys=()) -> Ring:
    """A :class:`Ring` without the dataclass constructor's per-field overhead (the family
    layer builds one per level: on random configurations that is one per robot)."""
    ring = object.__new__(Ring)
    ring.__dict__.update(name=name, polygon=polygon, radius_squared=radius_squared,
                         levels=levels, robots=robots, own=own, keys=keys,
                         n=1 if polygon is None else len(polygon.labels))   # cached n
    return ring


class _OneVertex(CirclePolygon):
    """The polygon of a level of one robot (a single vertex on its circle), with slots for
    its fields instead of a dict per instance: one per robot of a random configuration in
    each frame the audit runs the paper in (issue 33: a million robots held two frames'
    polygons, ~0.9 KB per robot).  Equal to nothing but another such polygon, as the
    dataclass compares; caches of :class:`CirclePolygon` go to a dict made when needed."""

    __slots__ = ("labels", "directions", "polar")
    one_circle = True           # a level: one radius

    def __reduce__(self):
        return (_one_vertex, (self.labels, self.directions, self.polar))


def _one_vertex(labels, directions, polar) -> _OneVertex:
    poly = object.__new__(_OneVertex)
    setter = object.__setattr__
    setter(poly, "labels", labels)
    setter(poly, "directions", directions)
    setter(poly, "polar", polar)
    return poly


class _OneLevelRing(Ring):
    """A :class:`Ring` of one level (its name ``G<level>`` read from ``levels``) of one
    robot, in slots (see :class:`_OneVertex`); equal to nothing but another such ring."""

    __slots__ = ("polygon", "radius_squared", "levels", "robots", "keys", "_lines")
    n = 1

    @property
    def name(self) -> str:
        return f"G{self.levels[0]}"

    @property
    def own(self) -> tuple:
        return self.robots

    @property
    def lines(self):
        try:
            return self._lines
        except AttributeError:
            found = _compute_lines(self)
            object.__setattr__(self, "_lines", found)
            return found

    def __reduce__(self):
        return (_one_level_ring, (self.polygon, self.radius_squared, self.levels,
                                  self.robots, self.keys))


def _one_level_ring(polygon, radius_squared, levels, robots, keys=()) -> _OneLevelRing:
    ring = object.__new__(_OneLevelRing)
    setter = object.__setattr__
    setter(ring, "polygon", polygon)
    setter(ring, "radius_squared", radius_squared)
    setter(ring, "levels", levels)
    setter(ring, "robots", robots)
    setter(ring, "keys", keys)
    return ring


def concentric_polygons(config: Configuration, ring_data: Levels | None = None,
                        level_polygons=None) -> tuple:
    """G_1, ..., G_t of ``config`` (Section 3: "Elements of G are sorted according to
    their distances from the center"), as :class:`Ring`\\ s with tuple labels (the
    polygons of :func:`exactsym.paper.circle_polygon.level_polygon`, labels wrapped in tuples).
    ``level_polygons``: those polygons of ``ring_data``'s levels (None where not built):
    their directions and integer vectors are taken, not recomputed."""
    ring_data = ring_data if ring_data is not None else levels_of(config)
    out = []
    polar = ring_data.polar
    if polar:
        turns = config.polar
    else:
        cx, cy = ring_data.sec.centre
        pts = config.points
        homogeneous = ring_data.sec.homogeneous
    # the levels' vectors p - C, when computed with their radii for these very points
    known = getattr(ring_data, "vectors", None)
    vectors = known[1] if not polar and known is not None and known[0] is config.points \
        else None
    new_polygon = object.__new__
    for k, level in enumerate(ring_data.levels):
        robots = tuple(level.points)
        if k == 0 and sign(level.radius_squared) == 0:      # only the nearest can be C
            out.append(new_ring(f"G{k + 1}", None, level.radius_squared, (k + 1,), robots,
                                robots))
            continue
        if len(robots) == 1:        # one robot per level on random input: no list made
            i = robots[0]
            if polar:
                dirs = (turns[i][1],)
            else:
                vector = vectors.get(i) if vectors is not None else None
                if vector is None:
                    x, y = pts[i]
                    vector = (x - cx, y - cy)
                    register(vector, pts[i], homogeneous)    # its short text
                dirs = (vector,)
            # slotted (issue 33): labels share the robots' tuple
            out.append(_one_level_ring(_one_vertex((robots,), dirs, polar),
                                       level.radius_squared, (k + 1,), robots))
            continue
        else:
            labels = tuple([(i,) for i in robots])
            built = level_polygons[k] if level_polygons is not None else None
            if built is not None and built.labels == robots and \
                    not built.__dict__.get("cleared"):      # its directions are p - C
                poly = new_polygon(CirclePolygon)
                poly.__dict__.update(labels=labels, directions=built.directions,
                                     polar=polar, one_circle=True)
                for kept in ("integer_vectors", "gap_ids"):     # computed once per level
                    if kept in built.__dict__:
                        poly.__dict__[kept] = built.__dict__[kept]
                out.append(new_ring(f"G{k + 1}", poly, level.radius_squared, (k + 1,),
                                    robots, robots))
                continue
            if polar:
                dirs = tuple([turns[i][1] for i in robots])
            else:
                dirs = tuple([(pts[i][0] - cx, pts[i][1] - cy) for i in robots])
                for i, d in zip(robots, dirs):
                    register(d, pts[i], homogeneous)
        poly = new_polygon(CirclePolygon)       # CirclePolygon(labels, dirs, polar), faster
        poly.__dict__.update(labels=labels, directions=dirs,
                             polar=polar, one_circle=True)    # a level: one radius
        out.append(new_ring(f"G{k + 1}", poly, level.radius_squared, (k + 1,), robots,
                            robots))
    return tuple(out)


def mirror_lines(poly: CirclePolygon, seq: list | None = None) -> list:
    """The lines of straight symmetry of ``poly`` (``def-straight-symmetric-poly``), as
    the line keys of :func:`exactsym.paper.polygon.definition_mirrors`, in O(n) after the angular
    order: a reflection maps v_i to v_{s-i} iff the counter-clockwise gap sequence g
    satisfies g_i = g_{s-1-i} for all i, i.e. iff g occurs in the doubled reversed
    sequence (exact ids, KMP); its axis bisects v_0 and v_s.  The line through both
    vertices of a 2-gon is excluded (it contains all the points); a single vertex has
    the line through C and itself."""
    n = poly.n
    if n == 0:
        return []
    dirs = poly.directions
    if n == 1:
        return [line_key(poly.polar, dirs[0])]
    seq = seq if seq is not None else gap_ids(poly)
    rev = seq[::-1]
    found = {}
    for p in find_all(seq, rev + rev[:-1]):
        s = (-p) % n
        if n == 2 and s == 0:
            continue
        found.setdefault(bisector_key(poly.polar, dirs[0], dirs[s]), None)
    return list(found)


def centrally_symmetric(poly: CirclePolygon, seq: list | None = None) -> bool:
    """``def-skew-symmetric-poly`` (the half-turn about C maps the polygon onto itself, as
    :func:`exactsym.paper.polygon.is_skew_symmetric` reads it), in O(n): n even and the gap sequence
    has period n/2 (then n/2 consecutive gaps make half a turn)."""
    n = poly.n
    if n < 2 or n % 2:
        return False
    seq = seq if seq is not None else gap_ids(poly)
    h = n // 2
    return all(seq[i] == seq[i + h] for i in range(h))


def _compute_lines(ring: Ring):
    if ring.polygon is None:
        return ALL_LINES
    seq = gap_ids(ring.polygon) if ring.polygon.n > 1 else None
    if centrally_symmetric(ring.polygon, seq):
        return ALL_LINES
    return frozenset(mirror_lines(ring.polygon, seq))


def lines_of_symmetry(ring: Ring):
    """:data:`ALL_LINES` or the frozenset of line keys of ``ring`` (see module docstring)."""
    return ring.lines


def intersect_lines(a, b):
    if a is ALL_LINES:
        return b
    if b is ALL_LINES:
        return a
    return a & b


def common_lines(rings: Iterable[Ring]):
    """The lines of symmetry common to all ``rings`` (``ALL_LINES`` for none given)."""
    out = ALL_LINES
    for ring in rings:
        out = intersect_lines(out, ring.lines)
        if out is not ALL_LINES and not out:
            break
    return out


def has_lines(lines) -> bool:
    return lines is ALL_LINES or bool(lines)


def is_symmetric_polygon(ring: Ring) -> bool:
    """``def-symmetric-poly`` (straight or skew symmetric; the robot at C and a single
    vertex are symmetric).  At most two vertices: always (a single vertex has the line
    through it, two vertices the perpendicular bisector), decided without the lines."""
    if ring.n <= 2:         # n: 1 for the robot at C (cached on the ring)
        return True
    return has_lines(ring.lines)


def is_symmetric_pair(a: Ring, b: Ring) -> bool:
    """``def-sym-pair``: G_i and G_j have a common line of symmetry."""
    return has_lines(intersect_lines(a.lines, b.lines))


def is_symmetric_family(rings: Sequence[Ring]) -> bool:
    """``def-sym-calG``: all polygons of G have a common line of symmetry."""
    return has_lines(common_lines(rings))


def line_text(polar: bool, key) -> str:
    """A readable name of a line key."""
    if polar:
        return f"the line at {number_text(key)} turn"
    s, v = key
    return f"the line whose doubled angle has direction sign {s}, slope {number_text(v)}" \
        if s else f"the line whose doubled angle is vertical ({'+' if v > 0 else '-'})"


#: True while a failure's text is written for the screen only (:class:`.claims._Record`
#: of a text summary): :func:`lines_text` then writes a slope whose exact text would be
#: megabytes by its decimal, as the summary shows it, instead of writing it to be cut.
SCREEN_ONLY: ContextVar[bool] = ContextVar("screen_only", default=False)


def line_text(key) -> str:
    """The text of a line key (:attr:`LineKey.text`; for the screen while
    :data:`SCREEN_ONLY` is set)."""
    return key.screen_text() if SCREEN_ONLY.get() else key.text


def lines_data(ring_or_lines, polar: bool) -> dict:
    """The lines of :func:`lines_text` as data: ``{"unit": "turns" or "doubled-angle
    rays", "values": [exact texts, all of them]}`` (``values`` null for every line)."""
    lines = ring_or_lines.lines if isinstance(ring_or_lines, Ring) else ring_or_lines
    unit = "turns" if polar else "doubled-angle rays"
    if lines is ALL_LINES:
        return {"unit": unit, "values": None}
    return {"unit": unit,
            "values": [k.text for k in sorted(lines, key=lambda k: k.display_key())]}


def lines_text(ring_or_lines, polar: bool) -> str:
    lines = ring_or_lines.lines if isinstance(ring_or_lines, Ring) else ring_or_lines
    if lines is ALL_LINES:
        return "every line through C"
    if not lines:
        return "no line"
    keys = sorted(lines, key=lambda k: k.display_key())
    shown = ", ".join(line_text(k) for k in keys[:8])
    more = f", ... ({len(keys)} in all)" if len(keys) > 8 else ""
    unit = "turns" if polar else "doubled-angle rays"
    return f"{len(keys)} line{'s' if len(keys) != 1 else ''} ({unit} {shown}{more})"


def first_shown(lines):
    """The first of ``lines`` (line keys) in the order :func:`lines_text` shows them:
    exact, so a witness picked this way is the same in every run (the line sets are
    frozensets, whose iteration order follows string hashes)."""
    return min(lines, key=lambda k: k.display_key())


def is_odd(ring: Ring) -> bool:
    return ring.polygon is not None and ring.n % 2 == 1


def is_polar(G) -> bool:
    return next((g.polygon.polar for g in G if g.polygon is not None), True)
