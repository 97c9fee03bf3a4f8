"""Hypothesis strategies for exact plane geometry, shared by the test modules.

Import with ``from strategies import ...`` (pytest puts ``tests/`` on the path).

* numbers and maps: :func:`rationals`, :func:`rational_rotations` (Pythagorean
  parameters ``((1-t^2)/(1+t^2), 2t/(1+t^2))`` and the quarter turns),
  :func:`similarities` (rotation, optional reflection, positive scale,
  translation: all exact rationals), :func:`polar_similarities` (rational turn,
  reflection, scale: what keeps a configuration polar about the origin);
* configurations with a chosen symmetry group: :func:`rational_group_points`
  (C1, C2, C4, D1, D2, D4: orbits of random seeds under integer matrices) and
  :func:`polar_group_points` (Ck / Dk for any k, as ``(r, turn)`` pairs);
  both are filtered to have *exactly* that group by the brute-force oracles
  :func:`brute_force_group` and :func:`brute_force_polar_group`, which share no
  code with ``exactsym.truth.symmetry``;
* :func:`polar_configuration` / :func:`shuffled` build inputs from them.
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction

from hypothesis import strategies as st

from exactsym.io.fileformat import ConfigFile, PointSpec
from exactsym.geometry.configuration import Configuration, from_file
from exactsym.exact import fmpq
from exactsym.io.exprtree import Const

Q = fmpq


# ---------------------------------------------------------------- numbers and maps

def rationals(max_numerator: int = 30, max_denominator: int = 6, nonzero: bool = False,
              positive: bool = False):
    """Exact ``fmpq`` with small numerator and denominator."""
    lo = 1 if positive else -max_numerator
    nums = st.integers(lo, max_numerator)
    if nonzero and not positive:
        nums = nums.filter(bool)
    return st.builds(Q, nums, st.integers(1, max_denominator))


def rational_rotations():
    """``(cos, sin)`` of a rotation with rational entries: a quarter turn, or one from a
    Pythagorean parameter t: ``((1-t^2)/(1+t^2), 2t/(1+t^2))``."""
    quarter = st.sampled_from([(Q(1), Q(0)), (Q(0), Q(1)), (Q(-1), Q(0)), (Q(0), Q(-1))])
    pythagorean = rationals(12, 7).map(lambda t: ((1 - t * t) / (1 + t * t), 2 * t / (1 + t * t)))
    return st.one_of(quarter, pythagorean)


@dataclass(frozen=True)
class Similarity:
    """``p -> shift + scale * R (F p)`` with F the reflection ``(x, y) -> (x, -y)`` when
    ``reflect``, R the rotation ``((cos, -sin), (sin, cos))``; all exact."""
    cos: object
    sin: object
    reflect: bool
    scale: object
    shift: tuple

    def __call__(self, p):
        x, y = p
        if self.reflect:
            y = -y
        x, y = self.cos * x - self.sin * y, self.sin * x + self.cos * y
        return (self.shift[0] + self.scale * x, self.shift[1] + self.scale * y)


def similarities():
    """Exact rational similarities of the plane (orientation-reversing ones included)."""
    return st.builds(lambda cs, reflect, scale, shift: Similarity(cs[0], cs[1], reflect, scale,
                                                                  shift),
                     rational_rotations(), st.booleans(), rationals(9, 5, positive=True),
                     st.tuples(rationals(), rationals()))


@dataclass(frozen=True)
class PolarSimilarity:
    """``(r, turn) -> (scale * r, +-turn + rotate)`` (turn reduced to [0, 1)): the
    similarities fixing the origin that keep turns rational."""
    rotate: Fraction
    reflect: bool
    scale: Fraction

    def __call__(self, p):
        r, turn = p
        turn = -turn if self.reflect else turn
        return (self.scale * r, (turn + self.rotate) % 1)


def polar_similarities():
    return st.builds(PolarSimilarity,
                     st.builds(Fraction, st.integers(0, 59), st.sampled_from([1, 2, 7, 12, 60])),
                     st.booleans(),
                     st.builds(Fraction, st.integers(1, 9), st.integers(1, 5)))


def shuffled(items):
    """``(permuted, perm)``: ``permuted[j] == items[perm[j]]``."""
    return st.permutations(range(len(items))).map(
        lambda perm: ([items[i] for i in perm], list(perm)))


# ---------------------------------------------------------------- oracles

def _name(rotations: int, mirrors: int) -> str:
    return f"{'D' if mirrors else 'C'}{rotations}"


def brute_force_group(points) -> tuple[str, list[tuple[int, ...]]]:
    """``(name, permutations)`` of every isometry mapping the exact points onto themselves.

    O(n^2): every symmetry fixes the centroid c, so it is determined by the image b of one
    point a != c (|cb| = |ca|) and by being a rotation or a reflection; each candidate is
    applied to every point.  A single point gives ``("O2", [(0,)])``.
    """
    n = len(points)
    if n == 1:
        return "O2", [(0,)]
    zero = points[0][0] * 0
    cx = sum((p[0] for p in points), zero) / n
    cy = sum((p[1] for p in points), zero) / n
    index = {p: i for i, p in enumerate(points)}
    a = next(p for p in points if p != (cx, cy))
    ux, uy = a[0] - cx, a[1] - cy
    u2 = ux * ux + uy * uy
    rotations, reflections = [], []
    for b in points:
        vx, vy = b[0] - cx, b[1] - cy
        if vx * vx + vy * vy != u2:
            continue
        for kind, (m11, m12, m21, m22) in (
                ("rotation", _rotation_entries(ux, uy, vx, vy, u2)),
                ("reflection", _reflection_entries(ux, uy, vx, vy, u2))):
            perm = []
            for p in points:
                dx, dy = p[0] - cx, p[1] - cy
                image = (cx + m11 * dx + m12 * dy, cy + m21 * dx + m22 * dy)
                if image not in index:
                    break
                perm.append(index[image])
            else:
                (rotations if kind == "rotation" else reflections).append(tuple(perm))
    return _name(len(rotations), len(reflections)), rotations + reflections


def _rotation_entries(ux, uy, vx, vy, u2):
    c, s = (ux * vx + uy * vy) / u2, (ux * vy - uy * vx) / u2
    return c, -s, s, c


def _reflection_entries(ux, uy, vx, vy, u2):
    c, s = (ux * vx - uy * vy) / u2, (ux * vy + uy * vx) / u2
    return c, s, s, -c


def brute_force_polar_group(polar) -> tuple[str, list[tuple[int, ...]]]:
    """The same for points ``(r^2, turn)``, counting only isometries fixing the origin:
    the whole group whenever the origin is fixed by every symmetry (when it is the
    centroid or the SEC centre, e.g. when some rotation about it is a symmetry)."""
    n = len(polar)
    if n == 1:
        return "O2", [(0,)]
    norm = [(r2, _mod1(t) if r2 != 0 else 0) for r2, t in polar]
    index = {p: i for i, p in enumerate(norm)}
    ra, ta = next(p for p in norm if p[0] != 0)
    rotations, reflections = [], []
    for rb, tb in norm:
        if rb != ra:
            continue
        for kind, image in (("rotation", lambda t: t + tb - ta),
                            ("reflection", lambda t: ta + tb - t)):
            perm = []
            for r2, t in norm:
                key = (r2, _mod1(image(t)) if r2 != 0 else 0)
                if key not in index:
                    break
                perm.append(index[key])
            else:
                (rotations if kind == "rotation" else reflections).append(tuple(perm))
    return _name(len(rotations), len(reflections)), rotations + reflections


def _mod1(t):
    """An ``fmpq`` turn reduced to [0, 1)."""
    return t - (t.p // t.q)


# ---------------------------------------------------------------- configurations

#: Integer matrices ((a, b), (c, d)) of the finite groups with rational rotations.
RATIONAL_GROUPS = {
    "C1": [((1, 0), (0, 1))],
    "C2": [((1, 0), (0, 1)), ((-1, 0), (0, -1))],
    "C4": [((1, 0), (0, 1)), ((0, -1), (1, 0)), ((-1, 0), (0, -1)), ((0, 1), (-1, 0))],
    "D1": [((1, 0), (0, 1)), ((1, 0), (0, -1))],
    "D2": [((1, 0), (0, 1)), ((-1, 0), (0, -1)), ((1, 0), (0, -1)), ((-1, 0), (0, 1))],
}
RATIONAL_GROUPS["D4"] = RATIONAL_GROUPS["C4"] + [((1, 0), (0, -1)), ((0, 1), (1, 0)),
                                                 ((-1, 0), (0, 1)), ((0, -1), (-1, 0))]


def _orbit(seeds, matrices):
    seen, out = set(), []
    for x, y in seeds:
        for (a, b), (c, d) in matrices:
            p = (a * x + b * y, c * x + d * y)
            if p not in seen:
                seen.add(p)
                out.append(p)
    return out


def rational_group_points(name: str, max_seeds: int = 4, centre: bool | None = None):
    """Lists of distinct rational points whose symmetry group is exactly ``name``
    (one of :data:`RATIONAL_GROUPS`): orbits of 1..``max_seeds`` random seeds about the
    origin, optionally with the origin itself (the centre) for k >= 2, or a point on
    the mirror for D1; filtered with :func:`brute_force_group`."""
    min_seeds = 3 if name == "C1" else 2 if name in ("C2", "C4", "D1") else 1
    seeds = st.lists(st.tuples(rationals(), rationals()), min_size=min_seeds,
                     max_size=max(max_seeds, min_seeds), unique=True)
    with_centre = st.booleans() if centre is None else st.just(centre)

    def build(args):
        seed_list, add = args
        pts = _orbit(seed_list, RATIONAL_GROUPS[name])
        if add and name in ("C2", "C4", "D2", "D4"):
            pts.append((Q(0), Q(0)))
        elif add and name == "D1":
            pts.append((seed_list[0][0] + 1, Q(0)))
        return list(dict.fromkeys(pts))
    return st.tuples(seeds, with_centre).map(build).filter(
        lambda pts: len(pts) >= 1 and brute_force_group(pts)[0] == name)


def polar_group_points(k: int, dihedral: bool, max_seeds: int = 3, centre: bool | None = None):
    """Lists of distinct ``(r, turn)`` (``Fraction`` pairs, turn in [0, 1)) whose group is
    exactly Ck (``dihedral`` False) or Dk, k >= 2: orbits of random seeds under the
    rotations by j/k turn (and the reflection ``t -> -t``), optionally with the origin."""
    assert k >= 2
    seed = st.tuples(st.builds(Fraction, st.integers(1, 12), st.integers(1, 3)),
                     st.builds(Fraction, st.integers(0, 29), st.sampled_from([2 * k, 3 * k, 30])))
    seeds = st.lists(seed, min_size=1 if dihedral else 2, max_size=max_seeds,
                     unique_by=lambda s: (s[0], s[1] % 1))
    with_centre = st.booleans() if centre is None else st.just(centre)

    def build(args):
        seed_list, add = args
        pts = {}
        for r, t in seed_list:
            for j in range(k):
                for tt in ((t, -t) if dihedral else (t,)):
                    p = (r, (tt + Fraction(j, k)) % 1)
                    pts[p] = None
        out = list(pts)
        if add:
            out.append((Fraction(0), Fraction(0)))
        return out
    name = f"{'D' if dihedral else 'C'}{k}"
    return st.tuples(seeds, with_centre).map(build).filter(
        lambda pts: brute_force_polar_group([(Q(r.numerator, r.denominator) ** 2,
                                              Q(t.numerator, t.denominator)) for r, t in pts])[0]
        == name)


def near_symmetric_points(coord: int = 3):
    """Small sets of integer points, often symmetric and often nearly so: the orbit of a
    few seeds under a random group of :data:`RATIONAL_GROUPS`, with up to two points
    dropped and up to two added, translated by a random vector.  No filter: the
    interesting cases (every group, points at the centre, on mirrors) come often."""
    point = st.tuples(st.integers(-coord, coord), st.integers(-coord, coord))

    def build(args):
        name, seeds, drop, extra, (tx, ty) = args
        pts = _orbit(seeds, RATIONAL_GROUPS[name])
        pts = pts[drop:] if drop < len(pts) else pts
        pts = list(dict.fromkeys(pts + extra))
        return [(Q(x + tx), Q(y + ty)) for x, y in pts]
    return st.tuples(st.sampled_from(sorted(RATIONAL_GROUPS)),
                     st.lists(point, min_size=1, max_size=3, unique=True),
                     st.integers(0, 2), st.lists(point, max_size=2),
                     st.tuples(rationals(5, 3), rationals(5, 3))).map(build)


def near_symmetric_polar_points():
    """Small polar sets ``(r, turn)`` near symmetric: orbits of seeds under Ck or Dk
    (k in 2, 3, 4, 6, turns in twelfths), up to two points dropped, one added, and
    the origin sometimes."""
    seed = st.tuples(st.integers(1, 3), st.integers(0, 11))

    def build(args):
        k, dihedral, seeds, drop, extra, centre = args
        pts = {}
        for r, t in seeds:
            for j in range(k):
                for tt in ((t, -t) if dihedral else (t,)):
                    pts[(Fraction(r), Fraction((tt + 12 * j // k) % 12, 12))] = None
        out = list(pts)
        out = out[drop:] if drop < len(out) else out
        out = list(dict.fromkeys(out + [(Fraction(r), Fraction(t, 12)) for r, t in extra]))
        return out + ([(Fraction(0), Fraction(0))] if centre else [])
    return st.tuples(st.sampled_from([2, 3, 4, 6]), st.booleans(),
                     st.lists(seed, min_size=1, max_size=3, unique=True), st.integers(0, 2),
                     st.lists(seed, max_size=1), st.booleans()).map(build) \
        .filter(lambda pts: len(pts) >= 2)


def polar_configuration(points, model: str = "points") -> Configuration:
    """A :class:`Configuration` read as from a file of ``polar r turn`` lines
    (``points``: ``(r, turn)`` pairs of ``Fraction`` or int)."""
    specs = tuple(PointSpec(i, i + 1, 1, r=Const(Fraction(r)), turn=Fraction(t))
                  for i, (r, t) in enumerate(points))
    return from_file(ConfigFile(source="<polar>", points=specs, model=model))
