"""The paper on whole configurations: the concentric polygons G = (G_1, ..., G_t).

Section 3 from ``def-sym-pair`` to ``cor-Pasym-Pord`` and the algorithms of Section 4
that work on G: ``ElectLeader``, ``Preprocess``, ``MakeAsym`` (with the helpers it names
but does not give, ``FindAsymmetry`` and ``Find_Asymmetry_Pair``) and the decision of
``GatheringPattern``.  Single polygons are :mod:`.polygon`'s business (Check_Symmetry_*,
Elect_Leader_Sym, Make_SymToAsym, Elect_Leader_Asym, polygon types); this module calls
them and never re-implements them.  It never imports the ground truth
(:mod:`exactsym.symmetry`): the audit (:mod:`exactsym.audit`) compares the two.

Every reading chosen where the paper is ambiguous is listed in
``docs/interpretations.md`` (section "The family layer"); the essentials:

Lines of symmetry and "common line" (``def-sym-pair``, ``def-sym-calG``)
    A line of symmetry of a polygon inscribed in a circle passes through the centre C
    (``lemma-LOS-Passes-CenterSECP``), so it is a direction modulo half a turn and is
    held as an exact *line key*: on the polar path the turn of the line in [0, 1/2), on
    the Cartesian path the ray of the doubled angle (the keys of
    :func:`.polygon.definition_mirrors`).  :func:`lines_of_symmetry` returns

    * :data:`ALL_LINES` when the polygon is skew symmetric (the half-turn about C maps it
      onto itself, :func:`.polygon.is_skew_symmetric`): by ``lem-skew-los`` *every* line
      through C is then a line of (skew) symmetry; likewise for the robot at C (a
      singleton: ``def-symmetric-conf`` says every line through it is a line of symmetry);
    * otherwise the finite set of its lines of straight symmetry (exact mirrors, from the
      definition; a single vertex has exactly the line through C and it, the paper's
      note after ``def-asymmetric-poly``).

    Two or more polygons have a common line iff these sets intersect (ALL_LINES is the
    neutral element).  So a skew symmetric polygon makes a symmetric pair with every
    symmetric polygon, whatever kind of line the other one has: the paper never says a
    "common" line must be of the same kind, and ``lem-3-pair-sym``'s proof uses exactly
    this (first bullet).

Radial projection (G_ij)
    "the vertices of G_i are projected radially on the circumference of the enclosing
    circle of G_j; construct a polygon G_ij with the full set of vertices on the circle":
    :func:`radial_projection` takes *directions only* (rational turns, or exact vectors
    from C scaled to the target circle when the ratio of the radii is rational) and puts
    the union on the target's circle.  When a vertex of G_i and one of G_j lie on one ray
    they would coincide on the circle (the paper ignores this); we merge them into *one*
    vertex whose label lists both robots (set semantics: "the full set of vertices"), and
    the projection records the coincidences (``Projection.coincident``): a finding, since
    G_ij then has fewer than n_i + n_j vertices and its symmetry can differ from the
    paper's counts (``obs-gcd``, ``obs-type-4``).  The robot at C has no direction and is
    never projected.

Vertex labels
    Every polygon here has vertex labels that are *tuples of configuration indices* (one
    robot, or several merged on a ray).  A vertex "of G_t" in a projection is one whose
    label holds a robot of G_t; it is mapped back to the robot of that label lying on
    G_t's own circle (else the innermost robot of the label).

Printed line numbers
    ``line`` in the trace counts, in the printed algorithm, every ``if``/``while``/``for``
    header and every statement ending in ``\\;``, in order; ``else`` and ``end`` are not
    counted (algorithm2e's numbering of those depends on options the source does not
    fix).  The numbers are listed in ``docs/interpretations.md``.

Bounds (near-linear time and memory for every input)
    On random configurations every level is a single robot (t = n).  Nothing computes all
    pairs eagerly: Preprocess builds G_ij only for pairs an exact prefilter cannot reject
    (shared rays counted by hashing exact ray keys), ``Find_Asymmetry_Pair`` finds the
    first pair through an index of lines, the projection of all polygons is built once.
    The Section-3 checks run on a documented selection of pairs and triples, failures are
    listed a few times and then counted, the trace and the lists of polygons are capped:
    :class:`Limits` (``UNBOUNDED``: everything, no budget), ``PaperResult.bounded`` says
    what was bounded; ``docs/interpretations.md``, "Bounds of the family layer".

The trace is a list of dicts ``{"algorithm", "line", "polygons", "statement", "detail"}``
with, where they apply, ``"robots"`` (configuration indices selected or moved), ``"branch"``
(a stable name of the branch taken), ``"holds"`` (False when the step's claim is false on
this configuration: a finding; the audit collects them) and ``"round"``.
"""

from __future__ import annotations

from bisect import bisect_left
from dataclasses import dataclass, field
from functools import cached_property, lru_cache
from itertools import combinations
from math import gcd
from typing import Iterable, Sequence

from ..configuration import Configuration, Polar, no_cycle_collection
from ..errors import InputError, MoveImpossible
from ..exact import FieldElement, exact_key, fmpq, normal_turn, number_text, rational_sqrt, sign
from ..levels import Levels, levels_of, polar_sec
from ..strings import find_all
from .circle_polygon import CirclePolygon, polygon_from_directions
from . import polygon as P

__all__ = [
    "ALL_LINES", "Ring", "Projection", "concentric_polygons", "lines_of_symmetry",
    "common_lines", "is_symmetric_polygon", "is_symmetric_pair", "is_symmetric_family",
    "radial_projection", "is_type4", "preprocess", "preprocess_literal", "LiteralRun",
    "find_asymmetry", "find_asymmetry_pair", "family_claims", "make_asym", "MakeAsymResult",
    "elect_leader", "ElectLeaderResult", "paper_procedure", "PaperResult", "line_text",
    "MAX_QUADRATIC_N", "BRANCHES", "mirror_lines", "centrally_symmetric", "LineKey",
    "Limits", "DEFAULT_LIMITS", "UNBOUNDED", "WorkBudgetExceeded", "select_pairs",
    "select_triples",
]

_HALF = fmpq(1, 2)

#: Polygons above this size are not given to the O(n^2) string steps of
#: Elect_Leader_Asym (the leader is then reported as not computed).
MAX_QUADRATIC_N = 600

#: Pair and triple statements are checked on at most this many pairs / triples
#: (the defaults of :class:`Limits`).
MAX_PAIRS = 600
MAX_TRIPLES = 3000


class WorkBudgetExceeded(Exception):
    """A step would exceed its work budget (:class:`Limits`); the caller records it."""


@dataclass(frozen=True)
class Limits:
    """Work budgets of the family layer, so that it runs in near-linear time and memory
    for every input (``docs/interpretations.md``, "Bounds of the family layer").  Every
    budget is ``None`` in :data:`UNBOUNDED` (the faithful procedure, exhaustive checks).

    * ``claim_pairs``: the Section-3 pair statements (``family_claims``, the audit's
      ``lem-sym-notord``/``lem-asym-pair-ord``) are checked on every pair when t(t-1)/2 is
      at most this, else on the pairs among the first and last :data:`END_LEVELS` levels
      and then evenly spaced consecutive pairs (i, i+1), up to this many pairs;
    * ``claim_vertices`` + ``claim_vertices_per_robot`` * n: the pairs checked have at most
      this many vertices in all (a pair costs n_i + n_j);
    * ``union_vertices``: ``theorem-los-g1n`` on the projection of every polygon onto the
      outermost circle (one polygon with a vertex on every ray: O(n log n), about a
      second of exact arithmetic per 50,000 Cartesian rays) is checked when the polygons
      have at most this many vertices in all;
    * ``claim_triples``: triples of G' (``lem-3-pair-sym``, ``lem-type4``): all when
      C(t', 3) is at most this, else those among the first and last polygons of G' (as
      many as keep C(m, 3) at most this);
    * ``claim_levels``: the audit's ``lem-asym-ord`` on at most this many asymmetric
      levels (the first and the last);
    * ``claim_examples``: a statement failing more often records this many failures and
      one entry with the count;
    * ``search_steps`` + ``search_steps_per_robot`` * n: work steps of
      ``Find_Asymmetry_Pair`` and of Preprocess's pair scan and printed loop (index steps;
      a G_ij built costs :data:`BUILD_COST` steps a vertex): exact below the budget,
      beyond it the step is reported as not carried out;
    * ``trace_entries``: entries kept in the trace (findings and selections always kept,
      the rest cut, with a final entry counting what was omitted); ``described``:
      polygons listed in ``G`` / ``G_prime``; ``preprocess_entries``: polygons whose
      Preprocess scan gets its own trace entries."""
    claim_pairs: int | None = MAX_PAIRS
    claim_vertices: int | None = 100_000
    claim_vertices_per_robot: int = 2
    claim_triples: int | None = MAX_TRIPLES
    claim_levels: int | None = 200
    claim_examples: int | None = 8
    union_vertices: int | None = 50_000
    search_steps: int | None = 5_000_000
    search_steps_per_robot: int = 50
    trace_entries: int | None = 200
    described: int | None = 200
    preprocess_entries: int | None = 40

    def vertex_budget(self, n: int) -> int | None:
        return None if self.claim_vertices is None else \
            self.claim_vertices + self.claim_vertices_per_robot * n

    def step_budget(self, n: int) -> int | None:
        return None if self.search_steps is None else \
            self.search_steps + self.search_steps_per_robot * n


DEFAULT_LIMITS = Limits()
UNBOUNDED = Limits(claim_pairs=None, claim_vertices=None, claim_triples=None,
                   claim_levels=None, claim_examples=None, union_vertices=None,
                   search_steps=None,
                   trace_entries=None, described=None, preprocess_entries=None)

#: With more than C(2 END_LEVELS, 2) pairs, the pairs among the first and last
#: END_LEVELS levels are checked first (then consecutive pairs).
END_LEVELS = 12

#: Every branch of the family algorithms, as recorded in the trace's ``"branch"`` key
#: (the test of the case library asserts that each is reached by some case).
BRANCHES = {
    "Preprocess": ("odd-merge-type4", "odd-pair-not-type4", "skip-j-even-or-same",
                   "skip-i-even", "skip-centre", "literal-nontermination"),
    "MakeAsym": ("asym-polygon-large", "asym-polygon-small-asym", "asym-polygon-small-sym",
                 "asym-pair-large", "asym-pair-small-asym", "asym-pair-small-sym",
                 "single-vertex", "not-orderable"),
    "ElectLeader": ("sym-degree-one", "asymmetric", "project-1t", "centre"),
    "GatheringPattern": ("not-possible", "possible"),
}


# ============================================================ lines of symmetry
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
            keys = _ray_keys(self.polygon)
            object.__setattr__(self, "keys", keys)
        return keys


def _name(levels: Sequence[int]) -> str:
    levels = sorted(levels)
    if len(levels) == 1:
        return f"G{levels[0]}"
    if len(levels) > 8:     # a readable name of bounded length
        return (f"G({','.join(map(str, levels[:3]))},...,{levels[-1]}: "
                f"{len(levels)} levels)")
    return "G(" + ",".join(map(str, levels)) + ")"


def _new_ring(name, polygon, radius_squared, levels, robots, own, keys=()) -> Ring:
    """A :class:`Ring` without the dataclass constructor's per-field overhead (the family
    layer builds one per level: on random configurations that is one per robot)."""
    ring = object.__new__(Ring)
    ring.__dict__.update(name=name, polygon=polygon, radius_squared=radius_squared,
                         levels=levels, robots=robots, own=own, keys=keys,
                         n=1 if polygon is None else len(polygon.labels))   # cached n
    return ring


def concentric_polygons(config: Configuration, ring_data: Levels | None = None) -> tuple:
    """G_1, ..., G_t of ``config`` (Section 3: "Elements of G are sorted according to
    their distances from the center"), as :class:`Ring`\\ s with tuple labels (the
    polygons of :func:`.circle_polygon.level_polygon`, labels wrapped in tuples)."""
    ring_data = ring_data if ring_data is not None else levels_of(config)
    out = []
    polar = ring_data.polar
    if polar:
        turns = config.polar
    else:
        cx, cy = ring_data.sec.centre
        pts = config.points
    new_polygon = object.__new__
    for k, level in enumerate(ring_data.levels):
        robots = tuple(level.points)
        if k == 0 and sign(level.radius_squared) == 0:      # only the nearest can be C
            out.append(_new_ring(f"G{k + 1}", None, level.radius_squared, (k + 1,), robots,
                                 robots))
            continue
        if polar:
            dirs = tuple([turns[i][1] for i in robots])
        else:
            dirs = tuple([(pts[i][0] - cx, pts[i][1] - cy) for i in robots])
        poly = new_polygon(CirclePolygon)       # CirclePolygon(labels, dirs, polar), faster
        poly.__dict__.update(labels=tuple([(i,) for i in robots]), directions=dirs,
                             polar=polar)
        out.append(_new_ring(f"G{k + 1}", poly, level.radius_squared, (k + 1,), robots,
                             robots))
    return tuple(out)


def _cross(u, v):
    return u[0] * v[1] - u[1] * v[0]


def _dot(u, v):
    return u[0] * v[0] + u[1] * v[1]


def _ray_key(polar: bool, d):
    """Exact hashable key of the ray from C with direction d (cheap to hash: numbers go
    through :func:`exactsym.exact.exact_key`)."""
    if polar:
        return _hkey(normal_turn(d))
    x, y = d
    if sign(x) != 0:
        return (sign(x), _hkey(y / x))
    return (0, sign(y))


def _ray_keys(poly: CirclePolygon) -> tuple:
    return tuple(_ray_key(poly.polar, d) for d in poly.directions)


def _hkey(key):
    """A cheap hashable form of an exact key (a number or a tuple of numbers)."""
    if isinstance(key, tuple):
        return tuple(_hkey(k) for k in key)
    if isinstance(key, (fmpq, FieldElement)):
        return exact_key(key)
    return key


@dataclass(frozen=True)
class LineKey:
    """A line through C: ``value`` is the exact key of :mod:`.polygon` (the turn of the
    line in [0, 1/2), or the ray of its doubled angle); equality and hashing use ``h``,
    a canonical hashable form of it."""
    h: object
    value: object = field(compare=False)

    @classmethod
    def of(cls, value) -> "LineKey":
        return cls(_hkey(value), value)


def _line_key(polar: bool, d):
    """The key of the line through C with direction d (as :mod:`.polygon` keys lines)."""
    if polar:
        t = normal_turn(d)
        return t - _HALF if t >= _HALF else t
    x, y = d
    return _ray_value(x * x - y * y, 2 * x * y)


def _ray_value(x, y):
    """:mod:`.polygon`'s key of the ray of direction (x, y): (sign x, y/x) or (0, sign y)."""
    if sign(x) != 0:
        return (sign(x), y / x)
    return (0, sign(y))


def _bisector_line(polar: bool, a, b):
    """Key of the line through C bisecting directions a and b (the mirror a <-> b)."""
    if polar:
        return _line_key(True, (a + b) / 2)
    prod = (a[0] * b[0] - a[1] * b[1], a[0] * b[1] + a[1] * b[0])   # doubled angle
    return _ray_value(*prod)


def mirror_lines(poly: CirclePolygon, seq: list | None = None) -> list:
    """The lines of straight symmetry of ``poly`` (``def-straight-symmetric-poly``), as
    the line keys of :func:`.polygon.definition_mirrors`, in O(n) after the angular
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
        return [LineKey.of(_line_key(poly.polar, dirs[0]))]
    seq = seq if seq is not None else _gap_ids(poly)
    rev = seq[::-1]
    found = {}
    for p in find_all(seq, rev + rev[:-1]):
        s = (-p) % n
        if n == 2 and s == 0:
            continue
        found.setdefault(LineKey.of(_bisector_line(poly.polar, dirs[0], dirs[s])), None)
    return list(found)


def _gap_ids(poly: CirclePolygon) -> list:
    """Small integers, equal iff the counter-clockwise gaps between consecutive vertices
    are equal (exact)."""
    n, dirs = poly.n, poly.directions
    ids: dict = {}
    if not poly.polar and n > 1:
        lengths = [_dot(d, d) for d in dirs]
        if all(x == lengths[0] for x in lengths):
            # one circle: |a|^2 |b|^2 is the same for every gap, so the undivided key
            # orders (and identifies) the gaps of this polygon just as well
            def key(a, b):
                c, d = sign(_cross(a, b)), _dot(a, b)
                if c > 0:
                    return (0, _hkey(-sign(d) * d * d))
                if c < 0:
                    return (2, _hkey(sign(d) * d * d))
                return (1, 0) if sign(d) < 0 else (3, 0)
            return [ids.setdefault(key(dirs[i], dirs[(i + 1) % n]), len(ids))
                    for i in range(n)]
    return [ids.setdefault(_hkey(P.ccw_gap_key(poly.polar, dirs[i], dirs[(i + 1) % n])),
                           len(ids)) for i in range(n)]


def centrally_symmetric(poly: CirclePolygon, seq: list | None = None) -> bool:
    """``def-skew-symmetric-poly`` (the half-turn about C maps the polygon onto itself, as
    :func:`.polygon.is_skew_symmetric` reads it), in O(n): n even and the gap sequence
    has period n/2 (then n/2 consecutive gaps make half a turn)."""
    n = poly.n
    if n < 2 or n % 2:
        return False
    seq = seq if seq is not None else _gap_ids(poly)
    h = n // 2
    return all(seq[i] == seq[i + h] for i in range(h))


def _compute_lines(ring: Ring):
    if ring.polygon is None:
        return ALL_LINES
    seq = _gap_ids(ring.polygon) if ring.polygon.n > 1 else None
    if centrally_symmetric(ring.polygon, seq):
        return ALL_LINES
    return frozenset(mirror_lines(ring.polygon, seq))


def lines_of_symmetry(ring: Ring):
    """:data:`ALL_LINES` or the frozenset of line keys of ``ring`` (see module docstring)."""
    return ring.lines


def _intersect(a, b):
    if a is ALL_LINES:
        return b
    if b is ALL_LINES:
        return a
    return a & b


def common_lines(rings: Iterable[Ring]):
    """The lines of symmetry common to all ``rings`` (``ALL_LINES`` for none given)."""
    out = ALL_LINES
    for ring in rings:
        out = _intersect(out, ring.lines)
        if out is not ALL_LINES and not out:
            break
    return out


def _nonempty(lines) -> bool:
    return lines is ALL_LINES or bool(lines)


def is_symmetric_polygon(ring: Ring) -> bool:
    """``def-symmetric-poly`` (straight or skew symmetric; the robot at C and a single
    vertex are symmetric).  At most two vertices: always (a single vertex has the line
    through it, two vertices the perpendicular bisector), decided without the lines."""
    if ring.polygon is None or ring.polygon.n <= 2:
        return True
    return _nonempty(ring.lines)


def is_symmetric_pair(a: Ring, b: Ring) -> bool:
    """``def-sym-pair``: G_i and G_j have a common line of symmetry."""
    return _nonempty(_intersect(a.lines, b.lines))


def is_symmetric_family(rings: Sequence[Ring]) -> bool:
    """``def-sym-calG``: all polygons of G have a common line of symmetry."""
    return _nonempty(common_lines(rings))


def line_text(polar: bool, key) -> str:
    """A readable name of a line key."""
    if polar:
        return f"the line at {number_text(key)} turn"
    s, v = key
    return f"the line whose doubled angle has direction sign {s}, slope {number_text(v)}" \
        if s else f"the line whose doubled angle is vertical ({'+' if v > 0 else '-'})"


def lines_text(ring_or_lines, polar: bool) -> str:
    lines = ring_or_lines.lines if isinstance(ring_or_lines, Ring) else ring_or_lines
    if lines is ALL_LINES:
        return "every line through C"
    if not lines:
        return "no line"
    keys = sorted((k.value for k in lines), key=_display_order)
    shown = ", ".join(_value_text(k) for k in keys[:8])
    more = f", ... ({len(keys)} in all)" if len(keys) > 8 else ""
    unit = "turns" if polar else "doubled-angle rays"
    return f"{len(keys)} line{'s' if len(keys) != 1 else ''} ({unit} {shown}{more})"


def _display_order(v):
    return v if not isinstance(v, tuple) else (v[0], v[1] if v[0] else 0)


def _value_text(k) -> str:
    return number_text(k) if not isinstance(k, tuple) else \
        f"({k[0]}, {number_text(k[1]) if not isinstance(k[1], int) else k[1]})"


# ============================================================ radial projection
@dataclass(frozen=True)
class Projection:
    """G_ij: ``ring`` on the target's circle, ``coincident``: pairs of labels (source
    vertex, target vertex) that lay on one ray and were merged into one vertex."""
    ring: Ring
    coincident: tuple


def _scale_to(r2_to, r2_from):
    """sqrt(r2_to / r2_from) when rational, else None."""
    ratio = r2_to / r2_from
    if isinstance(ratio, FieldElement):
        if not ratio.is_rational():
            return None
        ratio = ratio.rational()
    return rational_sqrt(fmpq(ratio))


def radial_projection(source: Ring, target: Ring, name: str | None = None) -> Projection:
    """G_{source,target}: the vertices of ``source`` projected radially onto the circle of
    ``target``, together with target's own vertices (coincident rays merged)."""
    if source.polygon is None or target.polygon is None:
        raise ValueError("the robot at the centre C has no direction: it cannot be projected")
    polar = target.polygon.polar
    merged: dict = {}
    order = []
    coincident = []
    tgt = target.polygon
    tkeys = target.ray_keys
    skeys = source.ray_keys
    for lab, d, key in zip(tgt.labels, tgt.directions, tkeys):
        merged[key] = [lab, d]
        order.append(key)
    scale = None
    if not polar and source.radius_squared != target.radius_squared:
        scale = _scale_to(target.radius_squared, source.radius_squared)
    for lab, d, key in zip(source.polygon.labels, source.polygon.directions, skeys):
        if key in merged:
            if source is not target:
                coincident.append((lab, merged[key][0]))
                inner_first = not target.radius_squared < source.radius_squared
                both = lab + merged[key][0] if inner_first else merged[key][0] + lab
                merged[key][0] = tuple(dict.fromkeys(both))      # innermost robot first
            continue
        if scale is not None:
            d = (d[0] * scale, d[1] * scale)
        merged[key] = [lab, d]
        order.append(key)
    if polar:
        order.sort(key=lambda k: merged[k][1])
        poly = CirclePolygon(tuple(merged[k][0] for k in order),
                             tuple(merged[k][1] for k in order), True)
    else:
        labels = [merged[k][0] for k in order]
        dirs = [merged[k][1] for k in order]
        poly = polygon_from_directions(labels, dirs, polar)
        where = {lab: k for k, lab in zip(order, labels)}
        order = [where[lab] for lab in poly.labels]
    levels = tuple(sorted(set(source.levels) | set(target.levels)))
    robots = tuple(dict.fromkeys(source.robots + target.robots))
    ring = Ring(name or _name(levels), poly, target.radius_squared, levels, robots, target.own,
                tuple(order))
    return Projection(ring, tuple(coincident))


def _robot_in(label: tuple, ring: Ring) -> int | None:
    """The robot of ``label`` that belongs to ``ring``: one on its own circle first, else
    the first (innermost) of its robots; None when the label holds none of them."""
    own = set(ring.own)
    for r in label:
        if r in own:
            return r
    members = set(ring.robots)
    for r in label:
        if r in members:
            return r
    return None


# ============================================================ polygon types
def is_type4(ring: Ring) -> tuple[bool, str]:
    """Whether the polygon is a type 4 polygon (:func:`.polygon.polygon_type`), with the
    verdict's text.  When the Cartesian edge points cannot be built exactly (vectors of
    unequal lengths whose ratio is not a rational square) the definition is applied to
    the vertex strings only (for an odd polygon every line of straight symmetry passes
    through exactly one vertex, whose even-length string is then a palindrome)."""
    if ring.polygon is None:
        return False, "the robot at C"
    poly = ring.polygon
    try:
        verdict = P.polygon_type(poly)
    except NotImplementedError:
        n = poly.n
        lines = len(set(_line_key(poly.polar, poly.directions[i])
                        for i in P.vertex_palindromes(poly)))
        composite = n >= 4 and any(n % p == 0 for p in range(2, int(n ** 0.5) + 1))
        ok = n % 2 == 1 and composite and lines > 1 and lines < n and not P.is_regular(poly)
        return ok, ("type-4" if ok else "not type-4") + f" (vertex strings: {lines} lines)"
    if verdict is None:
        return False, "no line of straight symmetry"
    return str(verdict) == "type-4", f"{verdict} ({verdict.reason})"


# ============================================================ trace helpers
def _entry(trace: list, algorithm: str, line, polygons, statement: str, detail: str,
           **extra) -> dict:
    e = {"algorithm": algorithm, "line": line, "polygons": list(polygons),
         "statement": statement, "detail": detail}
    e.update({k: v for k, v in extra.items() if v is not None})
    trace.append(e)
    return e


def _odd(ring: Ring) -> bool:
    return ring.polygon is not None and ring.n % 2 == 1


# ============================================================ Preprocess
@lru_cache(maxsize=4096)
def _could_be_type4(m: int) -> bool:
    """A type 4 polygon has an odd, composite number of vertices (:func:`.polygon.polygon_type`:
    "odd, n not prime"; and ``is_type4``'s vertex-string test requires the same), so at
    least 9."""
    return m >= 9 and m % 2 == 1 and not P._is_prime(m)


#: Work steps charged for building one vertex of a G_ij and typing it (the polygon's
#: strings and lines cost about a hundred index steps per vertex).
BUILD_COST = 100


class _Type4Pairs:
    """Preprocess's test "G_ij is a type 4 polygon" on pairs of odd polygons, with an
    *exact* prefilter (``docs/interpretations.md``, "Bounds of the family layer").

    G_ij (the inner one projected onto the outer one's circle) has n_i + n_j - s
    vertices, s the number of rays holding a vertex of both (``radial_projection`` merges
    them): for two odd polygons that count is odd iff s is odd, and a type 4 polygon has
    an odd composite number of vertices.  So G_ij is built only for the pairs that share
    an odd number of rays and leave an odd composite count; every other pair is rejected
    without building it, exactly as the faithful loop would reject it.  Shared rays are
    counted with an index from exact ray keys (the rational turn, or the ray key of the
    vector) to the odd polygons on that ray; a polygon is indexed only when some other
    odd polygon is large enough to make 9 vertices with it (n + max n >= 10), so
    configurations of small polygons cost nothing.  Verdicts of pairs built are kept by
    identity (the polygons are immutable and kept alive here), so later passes and the
    literal loop do not rebuild them.  ``budget``: index steps plus vertices of G_ij built
    (None: unbounded); exceeding it raises :class:`WorkBudgetExceeded`."""

    def __init__(self, budget: int | None):
        self.budget = budget
        self.steps = 0
        self.built = 0
        self.memo: dict = {}
        self.index: dict = {}
        self.indexed: dict = {}
        self.max_n = 0
        self.any_pair = False
        self.ray_sets: dict = {}
        self.by_rays: dict = {}

    def spend(self, k: int) -> None:
        self.steps += k
        if self.budget is not None and self.steps > self.budget:
            raise WorkBudgetExceeded(f"more than {self.budget} steps")

    def reset(self, G) -> None:
        odd = [g for g in G if g.n % 2 == 1 and g.polygon is not None]
        sizes = sorted((g.n for g in odd), reverse=True)[:2]
        self.max_n = sizes[0] if sizes else 0
        self.any_pair = len(sizes) == 2 and sizes[0] + sizes[1] >= 10
        if not self.any_pair:
            return
        for g in odd:
            self.add(g)

    def possible(self, G) -> bool:
        """Whether two odd polygons of G can make a G_ij of 9 or more vertices (only then
        can a scan build anything: n_i + n_j - s >= 9 with s >= 1)."""
        return self.any_pair

    def add(self, ring: Ring) -> None:
        if id(ring) in self.indexed or ring.n + self.max_n < 10:
            return
        self.indexed[id(ring)] = ring
        keys = ring.ray_keys
        self.spend(len(keys))
        for k in keys:
            self.index.setdefault(k, {})[id(ring)] = ring

    def remove(self, ring: Ring) -> None:
        if self.indexed.pop(id(ring), None) is None:
            return
        for k in ring.ray_keys:
            bucket = self.index.get(k)
            if bucket is not None:
                bucket.pop(id(ring), None)
                if not bucket:
                    del self.index[k]

    def replaced(self, old: Sequence[Ring], new: Ring, G) -> None:
        """``old`` left G and ``new`` (odd) entered it."""
        if not self.any_pair:
            raise AssertionError("no merge is possible without a candidate pair")
        for ring in old:
            self.remove(ring)
        if new.n > self.max_n:
            before, self.max_n = self.max_n, new.n
            if before < 9:              # smaller polygons may have become eligible
                self.spend(len(G))
                for g in G:
                    if _odd(g):
                        self.add(g)
        self.add(new)

    def shared(self, gi: Ring) -> dict:
        """``{id(gj): s}`` for the indexed odd polygons gj != gi sharing s >= 1 rays with gi."""
        counts: dict = {}
        if id(gi) not in self.indexed:
            return counts
        keys = gi.ray_keys
        self.spend(len(keys))
        index = self.index
        for k in keys:
            bucket = index.get(k)
            if bucket is None or len(bucket) == 1:
                continue
            self.spend(len(bucket))
            for rid in bucket:
                counts[rid] = counts.get(rid, 0) + 1
        counts.pop(id(gi), None)
        return counts

    def candidates(self, gi: Ring, counts: dict) -> list:
        """The polygons whose G_ij may be type 4, in the order of G (nearest first)."""
        indexed, n_i = self.indexed, gi.n
        out = [indexed[rid] for rid, s in counts.items()
               if s % 2 == 1 and _could_be_type4(n_i + indexed[rid].n - s)]
        out.sort(key=lambda g: g.levels[-1])
        return out

    def _ray_set(self, ring: Ring):
        rid = id(ring)
        got = self.ray_sets.get(rid)
        if got is None:
            self.spend(ring.n)
            got = self.ray_sets[rid] = (ring, frozenset(ring.ray_keys))
        return got[1]

    def verdict(self, gi: Ring, gj: Ring):
        """``(is type 4, projection or None, text)`` for G_ij, built at most once per pair.
        On the polar path G_ij's vertices are the union of the two sets of rational turns
        and its type depends on them only, so a pair of ray sets already found not type 4
        is rejected without building G_ij again (many aligned polygons cost one build)."""
        inner, outer = (gi, gj) if _radius_less(gi, gj) else (gj, gi)
        key = (id(inner), id(outer))
        hit = self.memo.get(key)
        if hit is None:
            shape = None
            if outer.polygon.polar and inner.polygon.polar:
                shape = (self._ray_set(inner), self._ray_set(outer))
                known = self.by_rays.get(shape)
                if known is not None and not known[0]:
                    hit = self.memo[key] = (inner, outer, False, None, known[1])
                    return hit[2], hit[3], hit[4]
            self.spend(BUILD_COST * (gi.n + gj.n))
            proj = radial_projection(inner, outer)
            ok, why = is_type4(proj.ring)
            hit = self.memo[key] = (inner, outer, ok, proj, why)
            if shape is not None:
                self.by_rays[shape] = (ok, why)
            self.built += 1
        return hit[2], hit[3], hit[4]


def _built_size(gi: Ring, gj: Ring, proj, counts: dict) -> int:
    return proj.ring.n if proj is not None else gi.n + gj.n - counts.get(id(gj), 0)


def _prefilter_text(gi: Ring, gj: Ring, counts: dict) -> str:
    """Why the pair is rejected without building G_ij."""
    if gi.n + gj.n < 9:
        return f"{gj.name} (at most {gi.n + gj.n} vertices)"
    m = gi.n + gj.n - counts.get(id(gj), 0)
    what = "even" if m % 2 == 0 else ("below 9" if m < 9 else "prime")
    return f"{gj.name} ({m} vertices: {what}, not type 4; G_ij not built)"


#: Preprocess lists the polygons it passes over by name when G has at most this many.
SMALL_FAMILY = 64


def preprocess(G: Sequence[Ring], trace: list | None = None, limits: Limits | None = None,
               stats: dict | None = None, prefilter: bool = True) -> tuple:
    """``Preprocess`` (Section 4.2), evident reading: for each G_i with an odd number of
    vertices, scan j = 1..t for G_j (j != i) with an odd number of vertices whose G_ij
    (the inner one projected onto the outer one's circle) is a type 4 polygon; replace
    *both* G_i and G_j by G_ij (the text before ``lem-los-gij``: "replace both G_i and
    G_j by G_ij"), placed at the outer one's level, and rescan j with the merged polygon
    as G_i; after the scan i++ (also for odd G_i).  Passes are repeated until none
    merges ("We repeat this process of merging polygons until ...").  The robot at C is
    not a polygon with a direction and is skipped.  Returns G'.

    The scan builds G_ij only for the pairs :class:`_Type4Pairs` cannot reject exactly
    (``prefilter=False`` runs the unfiltered loop, which builds every G_ij of two odd
    polygons with n_i + n_j >= 9: the same G').  ``limits``: the work budget
    (``search_steps``) and the number of polygons whose scan gets trace entries of its
    own (the rest are counted in one entry).  ``stats`` (a dict) receives
    ``complete`` (False when the budget stopped the scan: G' then holds the merges made
    so far), ``pairs_built``, ``steps``, ``passes``."""
    if not prefilter:
        return _preprocess_unfiltered(G, trace)
    limits = limits if limits is not None else DEFAULT_LIMITS
    trace = trace if trace is not None else []
    stats = stats if stats is not None else {}
    G = list(G)
    n_robots = sum(len(g.robots) for g in G)
    pairs = _Type4Pairs(limits.step_budget(n_robots))
    detail_left = [limits.preprocess_entries]
    omitted: dict = {}

    def bulk(line, polygons, detail, branch):
        if detail_left[0] is not None and detail_left[0] <= 0:
            omitted[branch] = omitted.get(branch, 0) + 1
            return
        _entry(trace, "Preprocess", line, polygons, "Preprocess", detail, branch=branch)

    def scanned():
        if detail_left[0] is not None:
            detail_left[0] -= 1

    passes, complete = 0, True
    try:
        pairs.reset(G)
        if not pairs.possible(G):
            # no two odd polygons make 9 vertices: every scan rejects every G_j without
            # building G_ij (the loop below would say so polygon by polygon)
            passes = 1
            for gi in G:
                if detail_left[0] is not None and detail_left[0] <= 0:
                    branch = "skip-centre" if gi.at_centre else (
                        "skip-i-even" if not _odd(gi) else "odd-pair-not-type4")
                    omitted[branch] = omitted.get(branch, 0) + 1
                    continue
                if gi.at_centre:
                    bulk(3, [gi.name], "the robot at C has no direction: not projected, "
                         "skipped", "skip-centre")
                elif not _odd(gi):
                    bulk(12, [gi.name], f"{gi.name} has {gi.n} (even) vertices: i++",
                         "skip-i-even")
                else:
                    _scan_entries(bulk, G if len(G) <= SMALL_FAMILY else None, gi, None, {},
                                  {})
                scanned()
        merged_any = pairs.possible(G)
        while merged_any:
            merged_any = False
            passes += 1
            i = 0
            while i < len(G):
                gi = G[i]
                pairs.spend(1)
                if gi.at_centre:
                    bulk(3, [gi.name], "the robot at C has no direction: not projected, "
                         "skipped", "skip-centre")
                    scanned()
                    i += 1
                    continue
                if not _odd(gi):
                    bulk(12, [gi.name], f"{gi.name} has {gi.n} (even) vertices: i++",
                         "skip-i-even")
                    scanned()
                    i += 1
                    continue
                restart = True
                while restart:
                    restart = False
                    counts = pairs.shared(gi)
                    found, built = None, {}
                    for gj in pairs.candidates(gi, counts):
                        ok, proj, why = pairs.verdict(gi, gj)
                        if ok:
                            found = (gj, proj, why)
                            break
                        built[id(gj)] = (proj, why)
                    # the order the scan saw (for the listing of a small family)
                    before = G[:] if len(G) <= SMALL_FAMILY else None
                    if found is not None:
                        gj, proj, why = found
                        new = proj.ring
                        inner, outer = (gi, gj) if _radius_less(gi, gj) else (gj, gi)
                        _entry(trace, "Preprocess", 9, [gi.name, gj.name, new.name],
                               "obs-type-4",
                               f"G_ij = {new.name} ({new.n} vertices) is {why}: replace "
                               f"{gi.name} and {gj.name} by it (on the circle of {outer.name})"
                               + _coincidence_note(proj), branch="odd-merge-type4")
                        pairs.spend(2 * len(G))
                        G[_index_of(G, outer)] = new
                        G.pop(_index_of(G, inner))
                        pairs.replaced((gi, gj), new, G)
                        old_gi, gi = gi, new
                        i = _index_of(G, new)
                        merged_any = True
                        restart = True
                    else:
                        old_gi = gi
                    if detail_left[0] is None or detail_left[0] > 0:
                        _scan_entries(bulk, before, old_gi, found, built, counts)
                    else:
                        omitted["odd-pair-not-type4"] = omitted.get("odd-pair-not-type4", 0) + 1
                scanned()
                i += 1
    except WorkBudgetExceeded as err:
        complete = False
        _entry(trace, "Preprocess", None, [g.name for g in G[:8]], "Preprocess",
               f"Preprocess stopped: its pair scan exceeded the work budget ({err}); G' "
               f"below holds the merges made so far, and the procedure is reported as not "
               f"carried out exactly", branch=None, kind="budget")
    if omitted:
        _entry(trace, "Preprocess", None, [], "Preprocess",
               f"{sum(omitted.values())} further entries of the scan omitted ("
               + ", ".join(f"{v} {k}" for k, v in sorted(omitted.items())) + ")",
               omitted=dict(sorted(omitted.items())))
    stats.update(complete=complete, pairs_built=pairs.built, steps=pairs.steps,
                 passes=passes)
    return tuple(G)


def _scan_entries(bulk, G: list | None, gi: Ring, found, built: dict, counts: dict) -> None:
    """The trace entries of one scan of j for G_i: the G_j rejected (lines 8, 10) and the
    G_j passed over (even, or j = i: line 11), up to the partner when one was found;
    listed by name when ``G`` (the family as the scan saw it) is given, else counted."""
    stop = found[0] if found is not None else None
    if G is not None:
        skipped, rejected = [], []
        for gj in G:
            if gj is stop:
                break
            if gj is gi or not _odd(gj):
                skipped.append(gj.name)
            elif id(gj) in built:
                proj, why = built[id(gj)]
                rejected.append(f"{gj.name} ({_built_size(gi, gj, proj, counts)} vertices, "
                                f"{why}" + (_coincidence_note(proj) if proj else "") + ")")
            else:
                rejected.append(_prefilter_text(gi, gj, counts))
        if rejected:
            bulk(10, [gi.name], "G_ij is not type 4 for G_j = " + "; ".join(rejected[:12])
                 + (f"; ... ({len(rejected)} in all)" if len(rejected) > 12 else "")
                 + ": j++", "odd-pair-not-type4")
        if skipped:
            bulk(11, [gi.name], f"j = i or G_j even: j++ past {', '.join(skipped[:12])}"
                 + (f", ... ({len(skipped)} in all)" if len(skipped) > 12 else ""),
                 "skip-j-even-or-same")
        return
    shown = [f"{proj.ring.name} ({proj.ring.n} vertices, {why})" if proj is not None else
             f"a G_ij with the rays of one built before ({why})"
             for proj, why in list(built.values())[:6]]
    bulk(10, [gi.name], "G_ij is not type 4 for the odd G_j "
         + ("before " + stop.name if stop is not None else "scanned")
         + (": built and rejected " + "; ".join(shown) if shown else "")
         + "; every other odd G_j is rejected without building G_ij (n_i + n_j - shared "
         "rays is even, prime or below 9): j++", "odd-pair-not-type4")
    bulk(11, [gi.name], "j = i or G_j even: j++ past them", "skip-j-even-or-same")


def _preprocess_unfiltered(G: Sequence[Ring], trace: list | None = None) -> tuple:
    """The faithful loop without the prefilter: G_ij is built for every pair of odd
    polygons with n_i + n_j >= 9 (the reference the prefiltered :func:`preprocess` is
    tested against; quadratic in t)."""
    trace = trace if trace is not None else []
    G = list(G)
    passes, merged_any = 0, True
    while merged_any:
        merged_any = False
        passes += 1
        i = 0
        while i < len(G):
            gi = G[i]
            if gi.at_centre:
                _entry(trace, "Preprocess", 3, [gi.name], "Preprocess",
                       "the robot at C has no direction: not projected, skipped",
                       branch="skip-centre")
                i += 1
                continue
            if not _odd(gi):
                _entry(trace, "Preprocess", 12, [gi.name], "Preprocess",
                       f"{gi.name} has {gi.n} (even) vertices: i++", branch="skip-i-even")
                i += 1
                continue
            restart = True
            while restart:
                restart = False
                skipped, rejected = [], []
                for j, gj in enumerate(G):
                    if j == i or not _odd(gj):
                        skipped.append(gj.name)
                        continue
                    if gi.n + gj.n < 9:
                        # a type 4 polygon is odd, composite and not regular: n >= 9
                        rejected.append(f"{gj.name} (at most {gi.n + gj.n} vertices)")
                        continue
                    inner, outer = (gi, gj) if _radius_less(gi, gj) else (gj, gi)
                    proj = radial_projection(inner, outer)
                    ok, why = is_type4(proj.ring)
                    if ok:
                        new = proj.ring
                        _entry(trace, "Preprocess", 9, [gi.name, gj.name, new.name],
                               "obs-type-4",
                               f"G_ij = {new.name} ({new.n} vertices) is {why}: replace "
                               f"{gi.name} and {gj.name} by it (on the circle of {outer.name})"
                               + _coincidence_note(proj), branch="odd-merge-type4")
                        G[_index_of(G, outer)] = new
                        G.pop(_index_of(G, inner))
                        gi = new
                        i = _index_of(G, new)
                        merged_any = True
                        restart = True
                        break
                    rejected.append(f"{gj.name} ({proj.ring.n} vertices, {why}"
                                    + _coincidence_note(proj) + ")")
                if rejected:
                    _entry(trace, "Preprocess", 10, [gi.name], "Preprocess",
                           "G_ij is not type 4 for G_j = " + "; ".join(rejected[:12])
                           + (f"; ... ({len(rejected)} in all)" if len(rejected) > 12 else "")
                           + ": j++", branch="odd-pair-not-type4")
                if skipped:
                    _entry(trace, "Preprocess", 11, [gi.name], "Preprocess",
                           f"j = i or G_j even: j++ past {', '.join(skipped[:12])}"
                           + (f", ... ({len(skipped)} in all)" if len(skipped) > 12 else ""),
                           branch="skip-j-even-or-same")
            i += 1
    return tuple(G)


def _index_of(G: list, ring: Ring) -> int:
    return next(k for k, g in enumerate(G) if g is ring)


def _radius_less(a: Ring, b: Ring) -> bool:
    return a.radius_squared < b.radius_squared


def _coincidence_note(proj: Projection) -> str:
    if not proj.coincident:
        return ""
    pairs = ", ".join(f"{a}~{b}" for a, b in proj.coincident[:4])
    return (f"; {len(proj.coincident)} vertex pair(s) on a common ray merged into one vertex "
            f"({pairs}{', ...' if len(proj.coincident) > 4 else ''})")


@dataclass(frozen=True)
class LiteralRun:
    """The printed Preprocess loop run as printed: ``terminated`` False when a state
    (i, j, G) repeated (proof of non-termination) or ``max_steps`` passed."""
    terminated: bool
    steps: int
    reason: str
    result: tuple
    budget_exceeded: bool = False


def preprocess_literal(G: Sequence[Ring], max_steps: int | None = None,
                       limits: Limits | None = None, fast_off: bool = False) -> LiteralRun:
    """``Preprocess`` exactly as printed::

        i = 1; while i <= t: if G_i odd: j = 1; while j <= t:
            if j != i & G_j odd: compute G_ij; if type 4: replace G_i by G_ij else j++
            else j++
        else i++

    After a replacement j is not incremented (and G_j stays), and i is never
    incremented for an odd G_i, so the loop never ends once an odd polygon is reached
    (the state (i, j, G) repeats: detected exactly) -- a finding.

    "G_ij is type 4" uses the exact prefilter of :func:`preprocess` (G_ij is built only
    when it can be type 4).  A state is (i, j, the version of G): G changes only by a
    replacement, and each content of G (the levels, robots and size of each polygon, in
    order) gets one version number, so a repeated state is still detected exactly while
    a state costs O(1) (not O(t)).  When no two odd polygons can make a G_ij of 9
    vertices, the run is counted without stepping through it (``fast_off`` steps through
    it; the same result, tested).  Over the work budget of ``limits`` the run stops
    (``terminated`` False, the reason says so)."""
    limits = limits if limits is not None else DEFAULT_LIMITS
    G = list(G)
    t = len(G)
    max_steps = max_steps if max_steps is not None else 20 * (t + 2) ** 2
    pairs = _Type4Pairs(limits.step_budget(sum(len(g.robots) for g in G)))
    versions: dict = {}

    def version() -> int:
        pairs.spend(t)
        return versions.setdefault(tuple((g.levels, g.robots, g.n) for g in G), len(versions))

    seen = set()
    i, j, steps = 1, None, 0
    candidates: dict = {}
    try:
        pairs.reset(G)
        if not pairs.possible(G) and not fast_off:
            # no G_ij can be type 4: the loop passes the polygons before the first odd
            # one (one step each), then sweeps j = 1..t (t steps), ends the inner loop
            # (one step) and re-enters it in the state it started from (one step)
            first = next((k for k, g in enumerate(G, 1) if not g.at_centre and _odd(g)),
                         None)
            if first is None:
                return LiteralRun(True, t, "terminated", tuple(G))
            steps = first - 1 + t + 2
            return LiteralRun(False, steps, f"the state (i={first}, j=1, G) repeats after "
                              f"{steps} steps: the printed loop never ends", tuple(G))
        current = version()
        while i <= t:
            steps += 1
            if steps > max_steps:
                return LiteralRun(False, steps, f"no end within {max_steps} steps", tuple(G))
            gi = G[i - 1]
            if gi.at_centre or not _odd(gi):
                i += 1
                continue
            if j is None:
                j = 1
            state = (i, j, current)
            if state in seen:
                return LiteralRun(False, steps, f"the state (i={i}, j={j}, G) repeats after "
                                  f"{steps} steps: the printed loop never ends", tuple(G))
            seen.add(state)
            if j > t:
                j = None       # the inner loop ended; the outer loop re-enters with the same i
                continue
            gj = G[j - 1]
            if j != i and _odd(gj):
                cands = candidates.get(id(gi))
                if cands is None:
                    cands = candidates[id(gi)] = (gi, {id(g) for g in pairs.candidates(
                        gi, pairs.shared(gi))})
                if id(gj) in cands[1]:
                    ok, proj, _ = pairs.verdict(gi, gj)
                    if ok:
                        G[i - 1] = proj.ring    # "Replace G_i by G_ij"; j is not incremented
                        pairs.replaced((gi,), proj.ring, G)
                        current = version()
                        continue
            j += 1
    except WorkBudgetExceeded as err:
        return LiteralRun(False, steps, f"not run to its end: the work budget was exceeded "
                          f"({err})", tuple(G), True)
    return LiteralRun(True, steps, "terminated", tuple(G))


# ============================================================ FindAsymmetry
def find_asymmetry(G: Sequence[Ring]) -> int | None:
    """``FindAsymmetry`` (named, not given): the evident meaning, the first polygon of G'
    (nearest first) that is asymmetric (``def-asymmetric-poly``: no line of straight or
    skew symmetry); its index, or None.  (The paper's "binary search on G_1 u ... u G_t"
    cannot find an asymmetric polygon faster than looking at each: we look at each.)"""
    for i, ring in enumerate(G):
        if not is_symmetric_polygon(ring):
            return i
    return None


def find_asymmetry_pair(G: Sequence[Ring], budget: int | None = None) -> tuple[int, int] | None:
    """``Find_Asymmetry_Pair`` (named, not given): the first asymmetric pair (no common
    line, ``def-sym-pair``) <G_i, G_j>, i < j, in lexicographic order of (i, j) (the
    order ``lem-all-pair-asym-ord``'s proof uses); None when every pair is symmetric.

    Exact, without looking at every pair: when all polygons have a common line every pair
    shares it (None at once); a polygon without a line pairs asymmetrically with the next
    one; otherwise the next few polygons are tried, and then an index from each line to
    the polygons having it counts the polygons after G_i that share a line with it (or
    have every line): G_i has an asymmetric partner iff that count falls short, and the
    first partner is then located.  ``budget``: index steps (None: unbounded); exceeding
    it raises :class:`WorkBudgetExceeded`."""
    t = len(G)
    if t < 2 or _nonempty(common_lines(G)):
        return None
    steps = 0

    def spend(k):
        nonlocal steps
        steps += k
        if budget is not None and steps > budget:
            raise WorkBudgetExceeded(f"Find_Asymmetry_Pair: more than {budget} steps")

    quick = 8
    index = None
    for i in range(t - 1):
        li = G[i].lines
        if not _nonempty(li):
            return i, i + 1
        end = min(t, i + 1 + quick)
        spend(end - i)
        for j in range(i + 1, end):
            if not _nonempty(_intersect(li, G[j].lines)):
                return i, j
        if end == t:
            continue
        if index is None:
            spend(t)
            index, all_after, next_empty = _line_index(G)
        # polygons at positions >= end compatible with G_i
        if li is ALL_LINES:
            j = next_empty[end]
            if j < t:
                return i, j
            continue
        sharing = set()
        for line in li:
            positions = index.get(line, ())
            lo = bisect_left(positions, end)
            spend(len(positions) - lo + 1)
            sharing.update(positions[lo:])
        if len(sharing) + all_after[end] == t - end:
            continue
        for j in range(end, t):
            spend(1)
            if j not in sharing and G[j].lines is not ALL_LINES:
                return i, j
    return None


def _line_index(G: Sequence[Ring]):
    """``(line -> sorted positions of the polygons with that line (finite sets only),
    all_after[k] = number of polygons at positions >= k with every line, next_empty[k] =
    first position >= k of a polygon without a line (len(G) when none))``."""
    t = len(G)
    index: dict = {}
    all_after = [0] * (t + 1)
    next_empty = [t] * (t + 1)
    for k in range(t - 1, -1, -1):
        lines = G[k].lines
        all_after[k] = all_after[k + 1] + (lines is ALL_LINES)
        next_empty[k] = k if lines is not ALL_LINES and not lines else next_empty[k + 1]
    for k, g in enumerate(G):
        lines = g.lines
        if lines is not ALL_LINES:
            for line in lines:
                index.setdefault(line, []).append(k)
    return index, all_after, next_empty


# ============================================================ Section 3 claims
def _claim(trace, statement: str, holds: bool, polygons, detail: str, witness=None):
    return _entry(trace, "Section 3", None, polygons, statement, detail, holds=holds,
                  witness=witness)


def _sampled_pairs(t: int, count: int):
    """Pairs among the first and last :data:`END_LEVELS` levels (lexicographic), then
    consecutive pairs (i, i + 1) evenly spaced over the rest, ``count`` in all at most."""
    k = END_LEVELS
    ends = sorted(set(range(min(k, t))) | set(range(max(0, t - k), t)))
    made = 0
    for x, a in enumerate(ends):
        for b in ends[x + 1:]:
            if made >= count:
                return
            made += 1
            yield a, b
    ends_set = set(ends)
    middle = [i for i in (range(k - 1, t - k) if t > 2 * k else ())
              if not (i in ends_set and i + 1 in ends_set)] if t <= 4 * count + 4 * k else None
    if middle is None:       # avoid a list of t indices: the same spacing, computed
        lo, hi = k - 1, t - k            # i in [lo, hi): (i, i + 1) not both at the ends
        span = hi - lo
        left = count - made
        for x in range(min(left, span)):
            yield lo + (x * span) // min(left, span), lo + (x * span) // min(left, span) + 1
        return
    left = count - made
    if len(middle) <= left:
        chosen = middle
    else:
        chosen = [middle[(x * len(middle)) // left] for x in range(left)]
    for i in chosen:
        yield i, i + 1


def select_pairs(G: Sequence[Ring], limits: Limits | None = None) -> tuple[list, int]:
    """``(pairs, total)``: the pairs (i, j), i < j, of ``G`` on which pair statements are
    checked (``family_claims``, the audit), and the number of pairs.  All pairs in
    lexicographic order when there are at most ``limits.claim_pairs``; else the pairs
    among the first and last :data:`END_LEVELS` levels, then evenly spaced consecutive
    pairs; a pair is skipped when its vertices would exceed the vertex budget."""
    limits = limits if limits is not None else DEFAULT_LIMITS
    t = len(G)
    total = t * (t - 1) // 2
    cap = limits.claim_pairs
    budget = limits.vertex_budget(sum(len(g.robots) for g in G))
    if cap is None or total <= cap:
        order = ((i, j) for i in range(t) for j in range(i + 1, t))
    else:
        order = _sampled_pairs(t, cap)
    out, used = [], 0
    for i, j in order:
        if cap is not None and len(out) >= cap:
            break
        cost = G[i].n + G[j].n
        if budget is not None and used + cost > budget:
            continue
        used += cost
        out.append((i, j))
    return out, total


def select_triples(tp: int, limits: Limits | None = None) -> tuple[Iterable, int]:
    """``(triples, total)``: every triple of the tp polygons of G' when there are at most
    ``limits.claim_triples``, else every triple among the first and last m polygons
    (C(m, 3) at most the limit)."""
    limits = limits if limits is not None else DEFAULT_LIMITS
    total = tp * (tp - 1) * (tp - 2) // 6
    cap = limits.claim_triples
    if cap is None or total <= cap:
        return combinations(range(tp), 3), total
    m = 3
    while (m + 1) * m * (m - 1) // 6 <= cap:
        m += 1
    idx = list(range((m + 1) // 2)) + list(range(tp - m // 2, tp))
    return combinations(idx, 3), total


def _union_lines(rings: Sequence[Ring]):
    """The lines of the projection of every polygon of ``rings`` onto the outermost
    circle (radial projection one after the other, nearest first): that polygon has one
    vertex on every ray holding a vertex of some polygon, and its lines depend on these
    rays only (:func:`mirror_lines` and :func:`centrally_symmetric` compare directions),
    so it is built once from the distinct rays (O(n log n), not O(t n)); equal to the
    chained projections (tested)."""
    polar = rings[0].polygon.polar
    seen: dict = {}
    for g in rings:
        for d, key in zip(g.polygon.directions, g.ray_keys):
            if key not in seen:
                seen[key] = d
    dirs = list(seen.values())
    if polar:
        dirs.sort()
    else:
        dirs.sort(key=_angle_order_key)
    poly = CirclePolygon(tuple((k,) for k in range(len(dirs))), tuple(dirs), polar)
    ring = _new_ring("G*", poly, rings[-1].radius_squared, (), (), ())
    return ring.lines, poly.n


def _angle_order_key(d):
    """An exact key increasing with the angle of the vector d in [0, 2 pi) from the +x
    ray (the order of :func:`.circle_polygon.polygon_from_directions`)."""
    x, y = d
    sy = sign(y)
    if sy > 0:
        return (1, -x / y)
    if sy < 0:
        return (3, -x / y)
    return (0, 0) if sign(x) > 0 else (2, 0)


def family_claims(G: Sequence[Ring], Gp: Sequence[Ring], trace: list | None = None,
                  polar: bool = True, limits: Limits | None = None,
                  stats: dict | None = None) -> list[dict]:
    """Evaluate, with the paper's own notions (exact), the family statements of Section 3
    on G and G' and record each failure (``holds`` False, with a witness) and one
    summary per statement that holds.  Claims about orderability need the truth and are
    the audit's (``lem-sym-notord``, ``lem-asym-pair-ord``, ...).

    Bounded by ``limits`` (:class:`Limits`; :data:`UNBOUNDED` checks everything): pair
    statements on :func:`select_pairs`, triple statements on :func:`select_triples`,
    ``theorem-los-g1n`` on the projection of every polygon within the vertex budget,
    ``theorem-sym-pair-symG`` within the search budget.  A statement failing on more than
    ``limits.claim_examples`` instances records that many and then one entry with the
    count.  ``stats`` (a dict) receives what was checked: ``pairs_checked``, ``pairs``,
    ``triples_checked``, ``triples``, ``partial`` (the statements not checked on every
    instance), ``failures`` (per statement)."""
    limits = limits if limits is not None else DEFAULT_LIMITS
    trace = trace if trace is not None else []
    stats = stats if stats is not None else {}
    out: list[dict] = []
    failures: dict = {}
    examples = limits.claim_examples
    partial: set = set()

    def fail(statement, polygons, detail, witness=None):
        failures[statement] = failures.get(statement, 0) + 1
        if examples is None or failures[statement] <= examples:
            out.append(_claim(trace, statement, False, polygons, detail, witness))

    checked: dict = {}
    n_robots = sum(len(g.robots) for g in G)
    pairs, total_pairs = select_pairs(G, limits)
    if len(pairs) < total_pairs:
        partial.update(("obs-pair-asym-ord", "obs-merg-asym-pair", "lem-los-gij", "obs-gcd",
                        "obs-type-4"))
    for i, j in pairs:
        a, b = G[i], G[j]
        names = [a.name, b.name]
        common = _intersect(a.lines, b.lines)
        # obs-pair-asym-ord: an asymmetric polygon makes an asymmetric pair
        if not is_symmetric_polygon(a) or not is_symmetric_polygon(b):
            checked["obs-pair-asym-ord"] = checked.get("obs-pair-asym-ord", 0) + 1
            if _nonempty(common):
                fail("obs-pair-asym-ord", names, "an asymmetric polygon in a symmetric pair")
        if a.at_centre or b.at_centre:
            continue
        proj = None
        # obs-merg-asym-pair and lem-los-gij (as stated: no hypothesis on n_i, n_j)
        proj = radial_projection(a, b)
        gij = proj.ring
        if not _nonempty(common):
            checked["obs-merg-asym-pair"] = checked.get("obs-merg-asym-pair", 0) + 1
            if is_symmetric_polygon(gij):
                fail("obs-merg-asym-pair", names + [gij.name],
                     f"<{a.name}, {b.name}> is an asymmetric pair but G_ij = {gij.name} has "
                     f"{lines_text(gij, polar)}" + _coincidence_note(proj),
                     {"G_ij lines": lines_text(gij, polar)})
        checked["lem-los-gij"] = checked.get("lem-los-gij", 0) + 1
        extra = _lines_not_in(gij.lines, common)
        if extra:
            # the text around lem-los-gij assumes n_i, n_j odd, neither dividing the other,
            # gcd > 1, a common line
            context = (_odd(a) and _odd(b) and gcd(a.n, b.n) > 1 and _nonempty(common)
                       and a.n % b.n != 0 and b.n % a.n != 0)
            fail("lem-los-gij", names + [gij.name],
                 f"G_ij = {gij.name} has {lines_text(gij, polar)}, but "
                 f"<{a.name}, {b.name}> have {lines_text(common, polar)} in common"
                 + _coincidence_note(proj)
                 + ("" if context else " (outside the hypotheses of the surrounding text: "
                    "n_i, n_j odd, neither dividing the other, gcd > 1, a common line)"),
                 {"line": extra, "n_i": a.n, "n_j": b.n, "within_hypotheses": context,
                  "coincident_vertices": len(proj.coincident)})
        if _odd(a) and _odd(b) and _nonempty(common):
            g = gcd(a.n, b.n)
            count = "all" if common is ALL_LINES else len(common)
            checked["obs-gcd"] = checked.get("obs-gcd", 0) + 1
            if count != g:
                fail("obs-gcd", names, f"n_i = {a.n}, n_j = {b.n} odd with a common line: "
                     f"gcd = {g} but they have {count} common line(s)",
                     {"gcd": g, "common_lines": count})
            if g > 1:
                ok, why = is_type4(gij)
                checked["obs-type-4"] = checked.get("obs-type-4", 0) + 1
                if not ok:
                    neither = a.n % b.n != 0 and b.n % a.n != 0
                    fail("obs-type-4", names + [gij.name],
                         f"n_i = {a.n}, n_j = {b.n} odd, a common line, gcd = {g} > 1, but "
                         f"G_ij ({gij.n} vertices) is {why}" + _coincidence_note(proj)
                         + ("" if neither else "; note n_i and n_j divide one another "
                            "(Preprocess's text excludes that case)"),
                         {"G_ij vertices": gij.n, "type": why, "neither_divides": neither,
                          "coincident_vertices": len(proj.coincident)})
    # theorem-los-g1n on the projection of every polygon onto the outermost circle,
    # and on every merged polygon of G'
    with_dir = [g for g in G if not g.at_centre]
    if len(with_dir) >= 2 and limits.union_vertices is not None and \
            sum(g.n for g in with_dir) > limits.union_vertices:
        partial.add("theorem-los-g1n")
    elif len(with_dir) >= 2:
        whole_lines, whole_n = _union_lines(with_dir)
        whole_name = _name([k for g in with_dir for k in g.levels])
        common = common_lines(with_dir)
        checked["theorem-los-g1n"] = checked.get("theorem-los-g1n", 0) + 1
        extra = _lines_not_in(whole_lines, common)
        if extra:
            fail("theorem-los-g1n", _few_names(with_dir) + [whole_name],
                 f"G_(1..n) = {whole_name} (every polygon projected onto the outermost "
                 f"circle) has {lines_text(whole_lines, polar)}, but the polygons have "
                 f"{lines_text(common, polar)} in common",
                 {"line": extra, "within_hypotheses": False})
    by_level = {g.levels[0]: g for g in G}
    for g in Gp:
        if len(g.levels) > 1:
            parts = [by_level[k] for k in g.levels]
            common = common_lines(parts)
            checked["theorem-los-g1n"] = checked.get("theorem-los-g1n", 0) + 1
            extra = _lines_not_in(g.lines, common)
            if extra:
                fail("theorem-los-g1n", _few_names(parts) + [g.name],
                     f"the merged polygon {g.name} of G' has {lines_text(g, polar)}, but its "
                     f"parts have {lines_text(common, polar)} in common",
                     {"line": extra, "within_hypotheses": True})
    # triples of G': lem-type4, lem-3-pair-sym
    tp = len(Gp)
    triples, total_triples = select_triples(tp, limits)
    triples_checked = 0
    for i, j, k in triples:
        triples_checked += 1
        trio = (Gp[i], Gp[j], Gp[k])
        pairwise = all(is_symmetric_pair(x, y) for x, y in ((trio[0], trio[1]),
                                                             (trio[1], trio[2]),
                                                             (trio[0], trio[2])))
        if not pairwise:
            continue
        names = [g.name for g in trio]
        checked["lem-3-pair-sym"] = checked.get("lem-3-pair-sym", 0) + 1
        if not is_symmetric_family(trio):
            fail("lem-3-pair-sym", names, "pairwise symmetric without a common line")
        counts = [g.n for g in trio]
        if all(_odd(g) for g in trio) and len(set(counts)) == 3 and not any(
                x % y == 0 for x in counts for y in counts if x != y):
            checked["lem-type4"] = checked.get("lem-type4", 0) + 1
            if any(gcd(x, y) > 1 for x in counts for y in counts if x != y):
                fail("lem-type4", names, f"pairwise symmetric with n = {counts}, not "
                     "pairwise coprime", {"n": counts})
    if triples_checked < total_triples:
        partial.update(("lem-3-pair-sym", "lem-type4"))
    # theorem-sym-pair-symG on G', obs1-Gprime-equiG on G and G', Gprime-equiG
    steps = limits.step_budget(n_robots)
    symmetric_p = is_symmetric_family(Gp)
    symmetric_g = is_symmetric_family(G)
    try:
        all_pairs_sym = find_asymmetry_pair(Gp, steps) is None
    except WorkBudgetExceeded:
        all_pairs_sym = None
        partial.add("theorem-sym-pair-symG")
    if tp >= 2 and all_pairs_sym is not None:   # one polygon: "every pair" is vacuous
        checked["theorem-sym-pair-symG"] = 1
        if all_pairs_sym != symmetric_p:
            fail("theorem-sym-pair-symG", _few_names(Gp),
                 f"every pair of G' symmetric: {all_pairs_sym}; a common line for all: "
                 f"{symmetric_p}")
    for label, fam in (("G", G), ("G'", Gp)):
        if is_symmetric_family(fam):
            checked["obs1-Gprime-equiG"] = checked.get("obs1-Gprime-equiG", 0) + 1
            bad = find_asymmetry_pair(fam)    # None at once: the common line is shared
            if bad is not None:
                fail("obs1-Gprime-equiG", [fam[bad[0]].name, fam[bad[1]].name],
                     f"{label} is symmetric but this pair is not")
    checked["Gprime-equiG"] = 1
    if symmetric_p != symmetric_g:
        fail("Gprime-equiG", _few_names(Gp), f"G symmetric: {symmetric_g}; G' "
             f"symmetric: {symmetric_p}")
    for statement, count in failures.items():
        if examples is not None and count > examples:
            out.append(_claim(trace, statement, False, [],
                              f"fails on {count} of the {checked.get(statement, count)} "
                              f"instance(s) checked; the first {examples} are listed",
                              {"failures": count, "checked": checked.get(statement, count),
                               "listed": examples}))
    for statement, count in checked.items():
        if statement not in failures:
            note = (" (a bounded part of the instances: see paper.bounded)"
                    if statement in partial else "")
            _claim(trace, statement, True, [], f"holds on the {count} instance(s) checked"
                   + note)
    stats.update(pairs_checked=len(pairs), pairs=total_pairs,
                 triples_checked=triples_checked, triples=total_triples,
                 partial=sorted(partial), failures=dict(sorted(failures.items())))
    return out


def _few_names(rings: Sequence[Ring], k: int = 8) -> list:
    """The names of ``rings``, at most k of them (the first and the last)."""
    if len(rings) <= k:
        return [g.name for g in rings]
    return [g.name for g in rings[:k // 2]] + ["..."] + [g.name for g in rings[-(k // 2):]]


def _lines_not_in(lines, allowed):
    """A line of ``lines`` that is not in ``allowed`` (as text), or None."""
    if allowed is ALL_LINES:
        return None
    if lines is ALL_LINES:
        return "every line through C (skew symmetric)"
    extra = [k for k in lines if k not in allowed]
    if not extra:
        return None
    return _value_text(extra[0].value)


# ============================================================ robot positions and moves
class _Placement:
    """Mutable robot positions used to apply the paper's moves exactly, and to build the
    configuration after them (polar when the input is polar about C): exact numbers
    only; the configuration after the moves is :meth:`Configuration.with_positions`."""

    def __init__(self, config: Configuration, ring_data: Levels):
        self.config = config
        self.ring_data = ring_data
        self.polar = ring_data.polar and config.polar is not None and config.radii is not None
        self.changed: set = set()
        if self.polar:
            self.radii = list(config.radii)
            self.turns = [t for _, t in config.polar]
            self.r2 = [r2 for r2, _ in config.polar]
        else:
            self.points = list(config.points)
            self.centre = ring_data.sec.centre

    # -- reading
    def direction(self, i):
        if self.polar:
            return self.turns[i]
        p = self.points[i]
        return (p[0] - self.centre[0], p[1] - self.centre[1])

    # -- moves
    def set_turn(self, i, turn):
        self.turns[i] = normal_turn(turn)
        self.changed.add(i)

    def set_polar(self, i, r, turn):
        self.radii[i], self.r2[i], self.turns[i] = r, r * r, normal_turn(turn)
        self.changed.add(i)

    def set_vector(self, i, v):
        self.points[i] = (self.centre[0] + v[0], self.centre[1] + v[1])
        self.changed.add(i)

    def radius_from(self, i, j):
        """Put robot i on the circle of robot j, same direction (exact or False)."""
        if self.polar:
            self.set_polar(i, self.radii[j], self.turns[i])
            return True
        v = self.direction(i)
        scale = _scale_to(self.r2_of(j), self.r2_of(i))
        if scale is None:
            return False
        self.set_vector(i, (v[0] * scale, v[1] * scale))
        return True

    def r2_of(self, i):
        if self.polar:
            return self.r2[i]
        v = self.direction(i)
        return _dot(v, v)

    def configuration(self) -> Configuration:
        """The configuration after the moves (raises :class:`MoveImpossible`)."""
        if self.polar:
            return self.config.with_positions({i: Polar(self.radii[i], self.turns[i])
                                               for i in sorted(self.changed)})
        return self.config.with_positions({i: self.points[i] for i in sorted(self.changed)})


def _global_gap(place: _Placement, robots: Iterable[int]):
    """Smallest counter-clockwise gap between consecutive distinct rays of ``robots``
    (polar: a turn; Cartesian: a gap key), for the size of epsilon."""
    dirs = [place.direction(i) for i in robots]
    dirs = [d for d in dirs if place.polar or (sign(d[0]) != 0 or sign(d[1]) != 0)]
    if place.polar:
        ts = sorted(set(normal_turn(t) for t in dirs))
        if len(ts) < 2:
            return fmpq(1)
        gaps = [b - a for a, b in zip(ts, ts[1:])] + [ts[0] + 1 - ts[-1]]
        return min(gaps)
    return None


def _rotate_vector(v, tau, times: int = 1):
    c, s = (1 - tau * tau) / (1 + tau * tau), 2 * tau / (1 + tau * tau)
    for _ in range(times):
        v = (v[0] * c - v[1] * s, v[0] * s + v[1] * c)
    return v


def _epsilon_rotation(place: _Placement, robot: int, orientation: int, accept,
                      all_robots: Sequence[int], max_halvings: int = 6):
    """Move ``robot`` by epsilon along its circle, clockwise for the observer of this
    handedness (the direction Make_SymToAsym calls "its right side"; MakeAsym names
    none).  Polar: epsilon = a quarter of the smallest angular gap between rays of the
    configuration, halved (at most ``max_halvings`` times) until ``accept(place)`` holds.
    Cartesian: the rational rotation of Pythagorean parameter tau = -orientation/4,
    halved until four such rotations stay inside the gap to the neighbouring ray, then
    until ``accept`` holds.  When no epsilon tried is accepted, the first one is used.
    Returns ``(amount_text, accepted)``; the placement is left moved."""
    if place.polar:
        start = place.turns[robot]
        first = _global_gap(place, [i for i in all_robots if place.r2[i] != 0]) / 4
        delta = first
        for _ in range(max_halvings + 1):
            place.set_turn(robot, start - orientation * delta)
            if accept(place):
                return f"{number_text(-orientation * delta)} turn", True
            delta /= 2
        place.set_turn(robot, start - orientation * first)
        return f"{number_text(-orientation * first)} turn", False
    u = place.direction(robot)
    others = [place.direction(i) for i in all_robots if i != robot]
    others = [d for d in others if sign(d[0]) != 0 or sign(d[1]) != 0]
    tau = fmpq(-orientation, 4)
    nearest = _nearest_turn(u, others, orientation)
    for _ in range(64):                      # fit inside the gap (always possible)
        if _inside_gap(u, _rotate_vector(u, tau, 4), nearest, orientation):
            break
        tau /= 2
    first = tau
    for _ in range(max_halvings + 1):
        place.set_vector(robot, _rotate_vector(u, tau))
        if accept(place):
            return f"rotation with tau = {number_text(tau)}", True
        tau /= 2
    place.set_vector(robot, _rotate_vector(u, first))
    return f"rotation with tau = {number_text(first)}", False


def _turn_key(u, v, orientation):
    """Exact key increasing with the angle from u to v in the moving sense (clockwise for
    orientation +1)."""
    return P.ccw_gap_key(False, v, u) if orientation == 1 else P.ccw_gap_key(False, u, v)


def _nearest_turn(u, others, orientation):
    """The smallest :func:`_turn_key` from u to a direction of ``others`` off u's ray
    (None when there is none): computed once, so that each epsilon tried costs O(1)."""
    ray = _ray_key(False, u)
    keys = [_turn_key(u, d, orientation) for d in others if _ray_key(False, d) != ray]
    return min(keys) if keys else None


def _inside_gap(u, far, nearest, orientation) -> bool:
    """``far`` is reached from u, turning clockwise (orientation +1) or counter-clockwise,
    before any direction of the others (which may share u's ray): before ``nearest``,
    the smallest turn to one of them (:func:`_nearest_turn`)."""
    reach = _turn_key(u, far, orientation)
    if reach == P.ccw_gap_key(False, u, u):
        return False
    return nearest is None or reach < nearest


# ============================================================ MakeAsym
@dataclass
class MakeAsymResult:
    """``outcome``: "orderable" or "not-orderable" (or "undecided" when exactsym cannot
    place a robot exactly); ``moves``: the robots moved, in order; ``config``: the
    configuration after the moves; ``branch``: see :data:`BRANCHES`."""
    outcome: str
    branch: str
    moves: list = field(default_factory=list)
    config: Configuration | None = None


def _first_of_ring_in_ordering(poly: CirclePolygon, leader: P.AsymLeader, ring: Ring):
    """The first vertex of the ordering whose label holds a robot of ``ring``:
    ``(storage index, robot)`` or ``(None, None)``."""
    for idx in leader.ordering:
        robot = _robot_in(poly.labels[idx], ring)
        if robot is not None:
            return idx, robot
    return None, None


def _elect_asym(trace, alg, line, ring_poly: Ring, target: Ring, orientation, reading,
                statement, branch=None, rnd=None):
    """Elect_Leader_Asym on ``ring_poly`` and the first vertex of ``target`` in its ordering.
    Records a failure when the lexicographic minimum is tied (the polygon is symmetric:
    the claim that it is orderable is false)."""
    poly = ring_poly.polygon
    if poly.n > MAX_QUADRATIC_N:
        _entry(trace, alg, line, [ring_poly.name], statement,
               f"Elect_Leader_Asym not run: {poly.n} vertices (O(n^2) strings; limit "
               f"{MAX_QUADRATIC_N})", branch=branch, round=rnd)
        return None, "too-large"
    res = P.elect_leader_asym(poly, orientation, reading)
    idx, robot = _first_of_ring_in_ordering(poly, res, target)
    printed = None if res.leader is None else _robot_in(poly.labels[res.leader], ring_poly)
    detail = (f"Elect_Leader_Asym({ring_poly.name}): lexicographic minimum at "
              f"{list(poly.labels[res.v_m])}, ordering by {res.direction}; the printed "
              f"v_l is robot {printed}; the first vertex of {target.name} in the ordering is "
              f"robot {robot}")
    _entry(trace, alg, line, [ring_poly.name, target.name], statement, detail,
           robots=[robot] if robot is not None else None, branch=branch, round=rnd,
           uses="Elect_Leader_Asym")
    if res.tie:
        _entry(trace, alg, line, [ring_poly.name],
               "obs-merg-asym-pair" if len(ring_poly.levels) > 1 else "lem-asym-ord",
               f"{ring_poly.name} is assumed asymmetric (orderable) but the lexicographic "
               f"minimum of the (CW, ACW) tuples is attained at more than one vertex",
               holds=False, labelling_dependent=True, round=rnd)
    return robot, None


def make_asym(config: Configuration, ring_data: Levels, Gp: Sequence[Ring], trace: list,
              orientation: int = 1, reading: str = "literal", rnd: int = 1,
              limits: Limits | None = None) -> MakeAsymResult:
    """``MakeAsym`` (Section 4.2) on G' whose G_t is symmetric, every branch.

    Epsilon moves: :func:`_epsilon_rotation` (exact: a rational turn, or a rational
    rotation keeping the robot on its circle).  "Move v_l to the circumference of the
    enclosing circle of G_t": radially, same direction (exact when polar or when the
    radii's ratio is rational).  "Move v, epsilon distance" for a single-vertex polygon:
    along its circle (the robot at C moves to a quarter of the smallest radius, towards
    the first vertex of G_t counter-clockwise from the observer's x axis: no invariant
    direction exists there)."""
    alg = "MakeAsym"
    t = len(Gp)
    Gt = Gp[-1]
    place = _Placement(config, ring_data)
    everyone = list(range(config.n))
    moves: list = []

    def accept_asym(ring_index):
        def check(pl: _Placement):
            ring = Gp[ring_index]
            return not is_symmetric_polygon(_moved_ring(ring, pl))
        return check

    def move_eps(robot, line, branch, accept, why):
        amount, ok = _epsilon_rotation(place, robot, orientation, accept, everyone)
        moves.append({"robot": robot, "algorithm": alg, "line": line, "kind": "epsilon",
                      "amount": amount})
        _entry(trace, alg, line, [Gt.name], alg,
               f"move robot {robot} by epsilon along its circle ({amount}, clockwise for "
               f"this observer)" + ("" if ok else f"; no epsilon tried makes {why}"),
               robots=[robot], branch=branch, round=rnd, uses="epsilon-move")
        if not ok:
            _entry(trace, alg, line, [Gt.name], alg,
                   f"the move is meant to make {why}, but no epsilon tried does",
                   holds=False, round=rnd)

    def move_out(robot, line, branch):
        target = Gt.own[0]
        ok = place.radius_from(robot, target)
        moves.append({"robot": robot, "algorithm": alg, "line": line, "kind": "to-G_t-circle"})
        if not ok:
            _entry(trace, alg, line, [Gt.name], alg,
                   f"move robot {robot} to the circle of {Gt.name}: the point is not exact "
                   "in this number field (ratio of radii not a rational square)",
                   robots=[robot], branch=branch, round=rnd)
            return False
        _entry(trace, alg, line, [Gp[-2].name if t > 1 else Gt.name, Gt.name], alg,
               f"move robot {robot} radially to the circle of {Gt.name}", robots=[robot],
               branch=branch, round=rnd)
        return True

    a = find_asymmetry(Gp)
    _entry(trace, alg, 1, _few_names(Gp), "lem-one-pair-asym-ord",
           f"FindAsymmetry(G'): {'found ' + Gp[a].name if a is not None else 'none'}",
           round=rnd)
    if a is not None:
        Ga = Gp[a]
        if Gt.n > 3:
            branch = "asym-polygon-large"
            proj = radial_projection(Ga, Gt)
            robot, problem = _elect_asym(trace, alg, 4, proj.ring, Gt, orientation, reading,
                                         "lem-one-pair-asym-ord", branch, rnd)
            if robot is None:
                return MakeAsymResult("undecided", branch, moves, None)
            move_eps(robot, 5, branch, accept_asym(t - 1), f"{Gt.name} asymmetric")
            _entry(trace, alg, 6, [Gt.name], alg,
                   "Report: an orderable G' where G_t is asymmetric", round=rnd)
            return MakeAsymResult("orderable", branch, moves, _safe_config(place, trace, rnd))
        return _small_gt(config, place, Gp, Ga, None, trace, orientation, reading, rnd, moves,
                         move_out, polygon_branch=True)
    limits = limits if limits is not None else DEFAULT_LIMITS
    try:
        pair = find_asymmetry_pair(Gp, limits.step_budget(config.n))
    except WorkBudgetExceeded as err:
        _entry(trace, alg, 13, _few_names(Gp), "lem-all-pair-asym-ord",
               f"Find_Asymmetry_Pair(G') not carried out: {err} (work budget)", round=rnd,
               kind="budget")
        return MakeAsymResult("undecided", "asym-pair-large", moves, None)
    _entry(trace, alg, 13, _few_names(Gp), "lem-all-pair-asym-ord",
           "Find_Asymmetry_Pair(G'): " + ("none" if pair is None else
                                           f"<{Gp[pair[0]].name}, {Gp[pair[1]].name}>"),
           round=rnd)
    if pair is not None:
        gi, gj = Gp[pair[0]], Gp[pair[1]]
        if Gt.n > 3:
            branch = "asym-pair-large"
            gij = radial_projection(gi, gj).ring if not gi.at_centre else gj
            gijt = radial_projection(gij, Gt).ring
            robot, problem = _elect_asym(trace, alg, 16, gijt, Gt, orientation, reading,
                                         "lem-all-pair-asym-ord", branch, rnd)
            if robot is None:
                return MakeAsymResult("undecided", branch, moves, None)
            move_eps(robot, 17, branch, accept_asym(t - 1), f"{Gt.name} asymmetric")
            _entry(trace, alg, 18, [Gt.name], alg,
                   "Report: an orderable G where G_t is asymmetric", round=rnd)
            return MakeAsymResult("orderable", branch, moves, _safe_config(place, trace, rnd))
        return _small_gt(config, place, Gp, gi, gj, trace, orientation, reading, rnd, moves,
                         move_out, polygon_branch=False)
    single = next((k for k, g in enumerate(Gp) if g.n == 1), None)
    if single is not None:
        branch = "single-vertex"
        gi = Gp[single]
        v = gi.robots[0]
        on_line = _nonempty(_intersect(gi.lines, Gt.lines))
        _entry(trace, alg, 25, [gi.name, Gt.name], "obs-v-move",
               f"{gi.name} is the single robot {v}" + (" (on a line of symmetry of G_t)"
                                                       if on_line else
                                                       " (not on a line of symmetry of G_t)"),
               robots=[v], branch=branch, round=rnd)
        if gi.at_centre:
            first = Gt.own[0] if Gt.polygon is None else _robot_in(Gt.polygon.labels[0], Gt)
            ok = _move_off_centre(place, v, first, Gp)
            moves.append({"robot": v, "algorithm": alg, "line": 26, "kind": "off-centre"})
            _entry(trace, alg, 26, [gi.name], "obs-v-move",
                   f"move robot {v} off C by a quarter of the smallest radius, towards robot "
                   f"{first} (the first vertex of {Gt.name} from this observer's x axis)"
                   + ("" if ok else ": not exact here"), robots=[v], branch=branch, round=rnd,
                   labelling_dependent=True)
            if not ok:
                return MakeAsymResult("undecided", branch, moves, None)
            pair_ok = True
        else:
            def accept_pair(pl):
                return not is_symmetric_pair(_moved_ring(gi, pl), Gt)
            amount, pair_ok = _epsilon_rotation(place, v, orientation, accept_pair, everyone)
            moves.append({"robot": v, "algorithm": alg, "line": 26, "kind": "epsilon",
                          "amount": amount})
            _entry(trace, alg, 26, [gi.name], "obs-v-move",
                   f"move robot {v} by epsilon ({amount})", robots=[v], branch=branch,
                   round=rnd)
        if not pair_ok:
            _entry(trace, alg, 26, [gi.name, Gt.name], alg,
                   f"<{gi.name}, {Gt.name}> is meant to become asymmetric, but it stays "
                   f"symmetric for every epsilon tried ({Gt.name} has "
                   f"{lines_text(Gt, Gt.polygon.polar if Gt.polygon else True)})",
                   holds=False, round=rnd)
        try:
            place.configuration()          # raises MoveImpossible when the move is impossible
        except MoveImpossible as err:
            _entry(trace, alg, 26, [gi.name], alg, f"the move is impossible: {err}",
                   holds=False, round=rnd)
            return MakeAsymResult("undecided", branch, moves, None)
        new_gi = _moved_ring(gi, place)
        new_gt = _moved_ring(Gt, place)
        if new_gi.at_centre:
            return MakeAsymResult("undecided", branch, moves, None)
        proj = radial_projection(new_gi, new_gt)
        robot, problem = _elect_asym(trace, alg, 27, proj.ring, new_gt, orientation, reading,
                                     "obs-v-move", branch, rnd)
        if robot is None:
            return MakeAsymResult("undecided", branch, moves, None)
        _check_v_move(trace, place, gi, Gt, v, robot, orientation, reading, rnd)
        move_eps(robot, 28, branch, accept_asym(t - 1), f"{Gt.name} asymmetric")
        return MakeAsymResult("orderable", branch, moves, _safe_config(place, trace, rnd))
    _entry(trace, alg, 29, _few_names(Gp), "theorem-sym-pair-symG",
           "Report: G' is not orderable (no asymmetric polygon, no asymmetric pair, no "
           "single-vertex polygon)", branch="not-orderable", round=rnd)
    return MakeAsymResult("not-orderable", "not-orderable", moves, None)


def _safe_config(place: _Placement, trace, rnd):
    try:
        return place.configuration()
    except MoveImpossible as err:
        _entry(trace, "MakeAsym", None, [], "MakeAsym",
               f"the moves lead to an invalid configuration: {err}", holds=False, round=rnd)
        return None


def _small_gt(config, place, Gp, first, second, trace, orientation, reading, rnd, moves,
              move_out, polygon_branch: bool) -> MakeAsymResult:
    """MakeAsym lines 7-12 (``polygon_branch``) or 19-24: |G_t| <= 3."""
    alg = "MakeAsym"
    base = 7 if polygon_branch else 19
    kind = "polygon" if polygon_branch else "pair"
    t = len(Gp)
    Gt = Gp[-1]
    if t < 2:
        _entry(trace, alg, base, [Gt.name], alg, "there is no G_{t-1}", holds=False,
               round=rnd)
        return MakeAsymResult("undecided", f"asym-{kind}-small-asym", moves, None)
    prev = Gp[-2]
    if prev.at_centre:
        check_sym, deg = True, "1 (the robot at C)"
    else:
        check = P.check_symmetry(prev.polygon, orientation)
        check_sym, deg = check.symmetric, str(check.degree)
    _entry(trace, alg, base, [prev.name], alg,
           f"CheckSymmetry({prev.name}): {'symmetric' if check_sym else 'asymmetric'} "
           f"(degree {deg})", round=rnd)
    if not check_sym:
        branch = f"asym-{kind}-small-asym"
        robot, problem = _elect_asym(trace, alg, base + 2, prev, prev, orientation, reading,
                                     alg, branch, rnd)
    else:
        branch = f"asym-{kind}-small-sym"
        if polygon_branch:
            src = first
            what = f"G_a(t-1) = {first.name} projected onto {prev.name}"
        else:
            src = radial_projection(first, second).ring if not first.at_centre else second
            what = f"G_ij(t-1) = {src.name} projected onto {prev.name}"
        if src.at_centre or prev.at_centre:
            _entry(trace, alg, base + 3, [prev.name], alg,
                   f"{what}: the robot at C cannot be projected", branch=branch, round=rnd)
            return MakeAsymResult("undecided", branch, moves, None)
        proj = radial_projection(src, prev)
        robot, problem = _elect_asym(trace, alg, base + 3, proj.ring, prev, orientation,
                                     reading, alg, branch, rnd)
    if robot is None:
        return MakeAsymResult("undecided", branch, moves, None)
    if not move_out(robot, base + 4, branch):
        return MakeAsymResult("undecided", branch, moves, None)
    _entry(trace, alg, base + 5, [Gt.name], alg,
           "Report: an orderable G' where G_t is asymmetric", round=rnd)
    return MakeAsymResult("orderable", branch, moves, _safe_config(place, trace, rnd))


def _moved_ring(ring: Ring, place: _Placement) -> Ring:
    """``ring`` with its robots' current directions (projected vertices keep theirs)."""
    if ring.polygon is None:
        return ring
    poly = ring.polygon
    dirs = []
    moved_to_centre = False
    own_set = set(ring.own)
    for lab, d in zip(poly.labels, poly.directions):
        own = [r for r in lab if r in own_set]
        r = own[0] if own else lab[0]
        nd = place.direction(r)
        if not place.polar and sign(nd[0]) == 0 and sign(nd[1]) == 0:
            moved_to_centre = True
        dirs.append(nd if (own or len(lab) == 1) else d)
    if moved_to_centre:
        return ring
    moved = polygon_from_directions(poly.labels, dirs, poly.polar)
    return _new_ring(ring.name, moved, ring.radius_squared, ring.levels, ring.robots,
                     ring.own)


def _move_off_centre(place: _Placement, v: int, towards: int, Gp) -> bool:
    """The robot at C moves to a quarter of the smallest non-zero radius, on the ray of
    robot ``towards``."""
    if place.polar:
        inner = min((i for i in range(len(place.r2)) if place.r2[i] != 0),
                    key=lambda i: place.r2[i])
        place.set_polar(v, place.radii[inner] / 4, place.turns[towards])
        return True
    q = place.direction(towards)
    r2q = _dot(q, q)
    inner = min((_dot(place.direction(i), place.direction(i)) for i in range(len(place.points))
                 if i != v), key=lambda x: x)
    f = inner / (4 * r2q)
    place.set_vector(v, (q[0] * f, q[1] * f))
    return True


def _check_v_move(trace, place, gi, Gt, v, robot, orientation, reading, rnd):
    """``obs-v-move``: the leader selected through G_it is the same whether v is in motion
    (half way to its new position) or epsilon apart.  Polar configurations only (half a
    rational turn is exact; half a Cartesian rotation is not rational in general)."""
    if gi.at_centre or not place.polar:
        return
    saved = place.turns[v]
    start = gi.polygon.directions[0]
    place.set_turn(v, start + (normal_turn(saved - start + _HALF) - _HALF) / 2)
    try:
        half_gi = _moved_ring(gi, place)
        half_gt = _moved_ring(Gt, place)
        proj = radial_projection(half_gi, half_gt).ring
        if proj.polygon.n <= MAX_QUADRATIC_N:
            res = P.elect_leader_asym(proj.polygon, orientation, reading)
            _, other = _first_of_ring_in_ordering(proj.polygon, res, half_gt)
            _entry(trace, "MakeAsym", 27, [gi.name, Gt.name], "obs-v-move",
                   f"with robot {v} half way, the first vertex of {Gt.name} in the ordering "
                   f"of G_it is robot {other} (robot {robot} with v epsilon apart)",
                   holds=other == robot, round=rnd)
    finally:
        place.set_turn(v, saved)


# ============================================================ ElectLeader
@dataclass
class ElectLeaderResult:
    """``leader``: the configuration index elected (None when none); ``moves``: robots
    moved by Make_SymToAsym; ``branch``: see :data:`BRANCHES`."""
    leader: int | None
    branch: str
    moves: list = field(default_factory=list)
    computed: bool = True


def elect_leader(Gp: Sequence[Ring], trace: list, orientation: int = 1,
                 reading: str = "literal", degree: str = "paper",
                 rnd: int = 1) -> ElectLeaderResult:
    """``ElectLeader`` (Section 4.2) on G' (meant for G' with G_t asymmetric).

    Lines 1-3: Check_Symmetry_Even/Odd(G_1).  Line 4: "G_1 is symmetric with degree of
    symmetry one and the line passes through a single vertex or two vertices" -- exactly
    when :func:`.polygon.elect_leader_sym` elects a leader; then Make_SymToAsym(G_1) and
    Elect_Leader_Asym on the moved G_1.  Line 8: G_1 asymmetric (as Check_Symmetry
    reports): Elect_Leader_Asym(G_1).  Line 11-12: G_1t (G_1 projected onto G_t's
    circle) and Elect_Leader_Asym(G_1t); the output must be "a leader vertex from G_1":
    the first vertex of G_1 in the ordering of G_1t.  The robot at C as G_1 is a single
    vertex with CW = ACW = (): it is elected (it cannot move on a circle of radius 0)."""
    alg = "ElectLeader"
    g1 = Gp[0]
    gt = Gp[-1]
    if g1.at_centre:
        v = g1.robots[0]
        _entry(trace, alg, 3, [g1.name], "obs-asymmetric-polygon",
               f"{g1.name} is the robot {v} at C: Check_Symmetry_Odd reports degree 1 "
               "(CW = ACW = ())", round=rnd)
        _entry(trace, alg, 6, [g1.name], alg, f"leader: robot {v} (at C)", robots=[v],
               branch="centre", round=rnd)
        return ElectLeaderResult(v, "centre")
    poly = g1.polygon
    check = P.check_symmetry(poly, orientation)
    _entry(trace, alg, 2 if poly.n % 2 == 0 else 3, [g1.name], "obs-asymmetric-polygon",
           f"{check.algorithm}({g1.name}): " + "; ".join(check.reports), round=rnd)
    sym = P.elect_leader_sym(poly, orientation, degree) if check.symmetric else None
    if sym is not None and sym.leader is not None:
        branch = "sym-degree-one"
        axis = list(sym.check.axis_vertices)
        if poly.n % 2 == 0 and len(axis) >= 2 and \
                P.cw_string(poly, axis[0], orientation) == P.cw_string(poly, axis[1], orientation):
            _entry(trace, alg, 5, [g1.name], "1sym_le",
                   f"Elect_Leader_Sym: VI = VJ for the two vertices on the line (robots "
                   f"{[_robot_in(poly.labels[a], g1) for a in axis[:2]]}), so 'if VI > VJ "
                   f"return v_i else v_j' picks by the labelling, not by the geometry",
                   holds=False, labelling_dependent=True, round=rnd)
        moved = P.make_sym_to_asym(poly, orientation, degree)
        mover = _robot_in(poly.labels[moved.leader], g1) if moved.leader is not None else None
        moves = [{"robot": mover, "algorithm": "Make_SymToAsym", "line": 2, "kind": "epsilon",
                  "amount": number_text(moved.parameter) if moved.parameter is not None
                  else None}] if mover is not None else []
        _entry(trace, alg, 5, [g1.name], "1sym_le",
               f"degree of symmetry one: Make_SymToAsym moves robot {mover} to its right side "
               f"({'asymmetric now' if moved.asymmetric else 'still symmetric'})",
               robots=[mover] if mover is not None else None, branch=branch, round=rnd,
               uses="Make_SymToAsym")
        if not moved.asymmetric and poly.n > 1:
            _entry(trace, alg, 5, [g1.name], "Make_SymToAsym",
                   "Make_SymToAsym is meant to make G_1 asymmetric; it is not", holds=False,
                   round=rnd)
        if moved.polygon.n > MAX_QUADRATIC_N:
            return ElectLeaderResult(None, branch, moves, False)
        res = P.elect_leader_asym(moved.polygon, orientation, reading)
        leader = None if res.leader is None else _robot_in(moved.polygon.labels[res.leader], g1)
        if res.tie:
            _entry(trace, alg, 6, [g1.name], "lem-asym-ord",
                   "the lexicographic minimum of the (CW, ACW) tuples is tied", holds=False,
                   labelling_dependent=True, round=rnd)
        _entry(trace, alg, 6, [g1.name], "lem-asym-ord",
               f"Elect_Leader_Asym(moved {g1.name}): leader robot {leader}",
               robots=[leader] if leader is not None else None, branch=branch, round=rnd,
               uses="Elect_Leader_Asym")
        return ElectLeaderResult(leader, branch, moves)
    if not check.symmetric:
        branch = "asymmetric"
        if poly.n > MAX_QUADRATIC_N:
            _entry(trace, alg, 9, [g1.name], alg, "too large for Elect_Leader_Asym",
                   branch=branch, round=rnd)
            return ElectLeaderResult(None, branch, [], False)
        res = P.elect_leader_asym(poly, orientation, reading)
        leader = None if res.leader is None else _robot_in(poly.labels[res.leader], g1)
        _entry(trace, alg, 9, [g1.name], "lem-asym-ord",
               f"{g1.name} asymmetric: Elect_Leader_Asym elects robot {leader}",
               robots=[leader] if leader is not None else None, branch=branch, round=rnd,
               uses="Elect_Leader_Asym")
        if res.tie:
            _entry(trace, alg, 9, [g1.name], "lem-asym-ord",
                   "the lexicographic minimum of the (CW, ACW) tuples is tied", holds=False,
                   labelling_dependent=True, round=rnd)
        return ElectLeaderResult(leader, branch)
    branch = "project-1t"
    if gt.at_centre:
        return ElectLeaderResult(None, branch)
    proj = radial_projection(g1, gt)
    _entry(trace, alg, 11, [g1.name, gt.name, proj.ring.name], "obs-merg-asym-pair",
           f"compute G_1t = {proj.ring.name} ({proj.ring.n} vertices)"
           + _coincidence_note(proj), branch=branch, round=rnd)
    robot, problem = _elect_asym(trace, alg, 12, proj.ring, g1, orientation, reading,
                                 "lem-asym-pair-ord", branch, rnd)
    return ElectLeaderResult(robot, branch, [], problem is None)


# ============================================================ the whole procedure
@dataclass
class PaperResult:
    """What the paper's algorithms conclude on a configuration.

    ``orderable``: False when GatheringPattern reports "gathering is not possible" (G' in
    O_S) or MakeAsym reports "G' is not orderable"; ``gathering_possible``: the former
    decision alone; ``leader``: the robot ElectLeader elects after MakeAsym's moves
    (None when none is elected or it cannot be computed); ``moves``: robots moved, in
    order (MakeAsym, Make_SymToAsym); ``first_actor``: the first robot the procedure
    moves, else the leader; ``complete``: False when exactsym could not carry out a step
    exactly (then the leader is None); ``G``/``Gprime``: names and sizes."""
    orderable: bool
    gathering_possible: bool
    leader: int | None
    moves: list
    first_actor: int | None
    complete: bool
    trace: list
    G: list
    Gprime: list
    make_asym: str | None
    elect_leader: str | None
    bounded: dict = field(default_factory=dict)
    G_rings: tuple = field(default=(), repr=False, compare=False)   # G, as Rings (family.Ring)


def _describe(rings: Sequence[Ring], polar: bool, limit: int | None = None) -> list:
    """One dict per polygon; above ``limit`` polygons the first and last limit/2, with
    ``{"omitted": k}`` between them."""
    def one(g):
        return {"name": g.name, "vertices": g.n, "robots": list(g.robots),
                "levels": list(g.levels), "lines": lines_text(g, polar)}
    if limit is None or len(rings) <= limit:
        return [one(g) for g in rings]
    head, tail = rings[:limit // 2], rings[len(rings) - limit // 2:]
    return [one(g) for g in head] + [{"omitted": len(rings) - len(head) - len(tail)}] + \
        [one(g) for g in tail]


def _family_text(rings: Sequence[Ring], k: int = 8) -> str:
    """``"G1: 3, G2: 5, ..."`` for at most k polygons (the first and last)."""
    if len(rings) <= k:
        return ", ".join(f"{g.name}: {g.n}" for g in rings)
    part = lambda gs: ", ".join(f"{g.name}: {g.n}" for g in gs)     # noqa: E731
    return (f"{part(rings[:k // 2])}, ... ({len(rings)} polygons), "
            f"{part(rings[-(k // 2):])}")


#: Trace entries always kept by :func:`compact_trace` (findings, selections, budgets).
def _essential(e: dict) -> bool:
    return e.get("holds") is False or bool(e.get("robots")) or "uses" in e or \
        e.get("kind") == "budget" or e.get("algorithm") == "Section 3"


def compact_trace(trace: list, limit: int | None) -> tuple[list, int]:
    """At most ``limit`` entries (plus the essential ones: findings, robots selected or
    moved, steps over a budget, the Section-3 summaries): the other entries are kept in
    order until the limit and a final entry counts the omitted ones by algorithm and
    branch.  Returns ``(trace, omitted)``."""
    if limit is None or len(trace) <= limit:
        return trace, 0
    essential = sum(1 for e in trace if _essential(e))
    room = max(0, limit - essential - 1)
    out, omitted, counts = [], 0, {}
    for e in trace:
        if _essential(e) or room > 0:
            if not _essential(e):
                room -= 1
            out.append(e)
            continue
        omitted += 1
        key = f"{e['algorithm']}" + (f"/{e['branch']}" if e.get("branch") else "")
        counts[key] = counts.get(key, 0) + 1
    out.append({"algorithm": "exactsym", "line": None, "polygons": [],
                "statement": "trace", "detail": f"{omitted} trace entries omitted (limit "
                f"{limit}): " + ", ".join(f"{v} {k}" for k, v in sorted(counts.items())),
                "omitted": omitted, "omitted_by_kind": dict(sorted(counts.items()))})
    return out, omitted


def _is_polar(G) -> bool:
    return next((g.polygon.polar for g in G if g.polygon is not None), True)


def paper_procedure(config: Configuration, ring_data: Levels | None = None,
                    orientation: int = 1, reading: str = "literal", degree: str = "paper",
                    max_rounds: int = 3, claims: bool = True,
                    check_vl: bool = True, limits: Limits | None = None) -> PaperResult:
    """See :func:`_paper_procedure` (run with the cyclic garbage collector paused: the
    family layer builds many small acyclic objects, one polygon per level)."""
    with no_cycle_collection():
        return _paper_procedure(config, ring_data, orientation, reading, degree, max_rounds,
                                claims, check_vl, limits)


def _paper_procedure(config: Configuration, ring_data: Levels | None = None,
                     orientation: int = 1, reading: str = "literal", degree: str = "paper",
                     max_rounds: int = 3, claims: bool = True,
                     check_vl: bool = True, limits: Limits | None = None) -> PaperResult:
    """Run the paper on ``config``: GatheringPattern's decision (lines 1-5) and the leader
    election of Section 4.2 (Preprocess, MakeAsym when G_t is symmetric, ElectLeader).

    The leader election is run even when GatheringPattern stops at line 5 (the paper
    presents it on its own, and MakeAsym has branches -- a single-vertex polygon, "not
    orderable" -- that only a symmetric G' reaches).  After MakeAsym moves robots, every
    robot recomputes from scratch on the new configuration (they are oblivious): the
    next round runs Preprocess again, MakeAsym again if G_t is still symmetric (at most
    ``max_rounds`` rounds; each extra round is a finding), then ElectLeader.
    ``orientation``: the observer's handedness (+1: that of the file's axes).
    ``limits``: the work budgets (:class:`Limits`, default :data:`DEFAULT_LIMITS`;
    :data:`UNBOUNDED` for the exhaustive procedure); ``PaperResult.bounded`` says what
    was bounded."""
    limits = limits if limits is not None else DEFAULT_LIMITS
    ring_data = ring_data if ring_data is not None else levels_of(config)
    trace: list = []
    bounded: dict = {}
    G = concentric_polygons(config, ring_data)
    polar = _is_polar(G)
    _entry(trace, "GatheringPattern", 2, _few_names(G), "def-sym-calG",
           f"G = ({_family_text(G)}) about the SEC centre", round=1)
    pre_stats: dict = {}
    Gp = preprocess(G, trace, limits, pre_stats)
    literal = preprocess_literal(G, limits=limits)
    if literal.budget_exceeded:
        _entry(trace, "Preprocess", 12, _few_names(G), "Preprocess",
               f"as printed: {literal.reason}", kind="budget", round=1)
    elif not literal.terminated:
        _entry(trace, "Preprocess", 12, _few_names(G), "Preprocess",
               f"as printed: {literal.reason}", branch="literal-nontermination",
               holds=False, kind="literal-reading", round=1)
    _entry(trace, "GatheringPattern", 3, _few_names(Gp), "Gprime-equiG",
           f"G' = ({_family_text(Gp)})", round=1)
    bounded["preprocess_complete"] = pre_stats.get("complete", True)
    bounded["preprocess_pairs_built"] = pre_stats.get("pairs_built", 0)
    if claims:
        claim_stats: dict = {}
        family_claims(G, Gp, trace, polar, limits, claim_stats)
        bounded.update(family_claims_pairs_checked=claim_stats["pairs_checked"],
                       of=claim_stats["pairs"],
                       family_claims_triples_checked=claim_stats["triples_checked"],
                       family_claims_triples=claim_stats["triples"],
                       family_claims_partial=claim_stats["partial"],
                       family_claims_failures=claim_stats["failures"])
    symmetric = is_symmetric_family(Gp)
    gathering = not symmetric
    _entry(trace, "GatheringPattern", 4, _few_names(Gp), "def-sym-calG",
           f"common lines of all polygons of G': {lines_text(common_lines(Gp), polar)}",
           round=1)
    if symmetric:
        _entry(trace, "GatheringPattern", 5, _few_names(Gp), "cor-Pasym-Pord",
               "G' is in O_S: gathering is not possible", branch="not-possible", round=1)
    else:
        _entry(trace, "GatheringPattern", 6, _few_names(Gp), "cor-Pasym-Pord",
               "G' is in O_A: call MakeAsym(G_t), then ElectLeader(G')", branch="possible",
               round=1)
    moves: list = []
    complete = True
    ma_outcome = None
    current, cur_rings, cur_Gp = config, ring_data, Gp
    orderable = gathering
    if config.n == 1:
        # a single robot: nothing to make asymmetric (MakeAsym's branches need a G_t
        # with a circle); ElectLeader elects it (it is at C)
        el = elect_leader(Gp, trace, orientation, reading, degree, 1)
        return _finish(limits, bounded, config,
                       orderable, gathering, el.leader, [], True, trace, G, Gp,
                       None, el.branch, polar)
    rnd = 1
    while True:
        gt = cur_Gp[-1]
        if not is_symmetric_polygon(gt):
            break
        if rnd > max_rounds:
            _entry(trace, "MakeAsym", None, [gt.name], "MakeAsym",
                   f"G_t is still symmetric after {max_rounds} rounds", holds=False,
                   round=rnd)
            complete = False
            break
        if rnd > 1:
            _entry(trace, "MakeAsym", 6, [gt.name], "MakeAsym",
                   f"after MakeAsym's moves G_t = {gt.name} is still symmetric "
                   f"({lines_text(gt, polar)})", holds=False, round=rnd)
        result = make_asym(current, cur_rings, cur_Gp, trace, orientation, reading, rnd,
                           limits)
        ma_outcome = result.outcome if ma_outcome is None else ma_outcome
        moves.extend(result.moves)
        if result.outcome == "not-orderable":
            if rnd == 1:
                orderable = False
            el = None
            return _finish(limits, bounded, config,
                           orderable, gathering, None, moves, complete, trace, G, Gp,
                           ma_outcome, el, polar)
        if result.outcome == "undecided" or result.config is None:
            complete = False
            return _finish(limits, bounded, config,
                           orderable, gathering, None, moves, complete, trace, G, Gp,
                           ma_outcome, None, polar)
        new = result.config
        if ring_data.polar and new.polar is not None and polar_sec(new.polar) is None:
            # the moves changed the SEC (its centre left C): the paper says this cannot
            # happen; analysing the new configuration would need the Cartesian path in a
            # cyclotomic field of the moved turns' denominators -- we stop here
            _entry(trace, "MakeAsym", None, [gt.name], "MakeAsym",
                   "the SEC changed during the move (the paper: |G_t| > 3 ensures it does "
                   "not); the configuration after the moves is not analysed", holds=False,
                   round=rnd)
            return _finish(limits, bounded, config,
                           orderable, gathering, None, moves, False, trace, G, Gp,
                           ma_outcome, None, polar)
        try:
            new_rings = levels_of(new)
        except (ArithmeticError, NotImplementedError, InputError) as err:
            _entry(trace, "MakeAsym", None, [gt.name], "MakeAsym",
                   f"exactsym cannot analyse the configuration after the moves ({err})",
                   round=rnd)
            return _finish(limits, bounded, config,
                           orderable, gathering, None, moves, False, trace, G, Gp,
                           ma_outcome, None, polar)
        if not _same_sec(ring_data, new_rings):
            _entry(trace, "MakeAsym", None, [gt.name], "MakeAsym",
                   "the SEC changed during the move (the paper: |G_t| > 3 ensures it does "
                   "not)", holds=False, round=rnd)
        if check_vl:
            _check_vl_move(trace, current, new, result, orientation, reading, rnd, limits)
        rnd += 1
        current, cur_rings = new, new_rings
        G2 = concentric_polygons(current, cur_rings)
        stats2: dict = {}
        cur_Gp = preprocess(G2, [], limits, stats2)
        if not stats2.get("complete", True):
            bounded["preprocess_complete"] = False
        _entry(trace, "GatheringPattern", 3, _few_names(cur_Gp), "Preprocess",
               f"after the moves, G' = ({_family_text(cur_Gp)})", round=rnd)
    el = elect_leader(cur_Gp, trace, orientation, reading, degree, rnd)
    moves.extend(el.moves)
    leader = el.leader
    complete = complete and el.computed
    return _finish(limits, bounded, config,
                   orderable, gathering, leader, moves, complete, trace, G, Gp,
                   ma_outcome, el.branch, polar)


def _finish(limits: Limits, bounded: dict, config, orderable, gathering, leader, moves,
            complete, trace, G, Gp, ma, el, polar) -> PaperResult:
    if not bounded.get("preprocess_complete", True):
        complete, leader = False, None        # G' is not the one the paper computes
    first = moves[0]["robot"] if moves else leader
    trace, omitted = compact_trace(trace, limits.trace_entries)
    bounded["trace_entries_omitted"] = omitted
    if limits.described is not None and max(len(G), len(Gp)) > limits.described:
        bounded["polygons_described"] = limits.described
    return PaperResult(orderable, gathering, leader, moves, first, complete, trace,
                       _describe(G, polar, limits.described),
                       _describe(Gp, polar, limits.described), ma, el, bounded, tuple(G))


def _same_sec(a: Levels, b: Levels) -> bool:
    return a.sec.centre[0] == b.sec.centre[0] and a.sec.centre[1] == b.sec.centre[1] and \
        a.sec.radius_squared == b.sec.radius_squared


def _check_vl_move(trace, before: Configuration, after: Configuration, result: MakeAsymResult,
                   orientation, reading, rnd, limits: Limits | None = None) -> None:
    """``lem-vl-move``: "When v_l is moving no other robot will be selected as leader".
    We stop the last moving robot half way (polar configurations: half the turn, or half
    way out radially) and run one round of the procedure there: its first actor must be
    the same robot (or nobody moves and ElectLeader elects it)."""
    if not result.moves or before.radii is None or after.radii is None:
        return
    last = result.moves[-1]
    v = last["robot"]
    (r2a, ta), (r2b, tb) = before.polar[v], after.polar[v]
    if r2a == r2b:
        half_way = Polar(after.radius(v), ta + (normal_turn(tb - ta + _HALF) - _HALF) / 2)
    else:
        half_way = Polar((before.radius(v) + after.radius(v)) / 2, tb)
    try:
        mid = after.moved(v, half_way)
    except MoveImpossible:
        return
    sub = paper_procedure(mid, orientation=orientation, reading=reading, max_rounds=1,
                          claims=False, check_vl=False, limits=limits)
    actor = sub.first_actor
    holds = actor == v or actor is None and sub.leader == v
    _entry(trace, "MakeAsym", last["line"], [], "lem-vl-move",
           f"with robot {v} half way, the procedure's first robot to act is {actor}",
           robots=[actor] if actor is not None else None, holds=holds, round=rnd)
