"""The symmetries of a configuration as exact isometries, built from its rays.

Ground truth: :mod:`exactsym.truth.symmetry` finds which maps of the rays carry the ray string
onto itself; this module turns one such map into an :class:`Isometry`, the exact matrix
(or rational turn on the polar path) with the permutation of the points it induces.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..exact import fmpq
from .rays_filtered import firsts


@dataclass(frozen=True)
class Isometry:
    """A symmetry of a configuration, exact.

    ``g(p) = centre + M (p - centre)``.  On the polar path ``turn`` says which
    one: a rotation by ``turn`` full turns (counter-clockwise), or the reflection
    ``t -> 2*turn - t`` in the mirror line at angle ``turn`` (in ``[0, 1/2)``);
    ``matrix`` is then None.  On the Cartesian path ``matrix`` is the exact
    orthogonal matrix ``((a, b), (c, d))`` (a :class:`LazyMatrix`, read as that tuple,
    when built from rays) and ``turn`` is None.
    ``permutation[i]`` is the index of the image of point ``i``.
    """
    kind: str
    centre: tuple
    turn: fmpq | None
    matrix: tuple | None
    permutation: tuple[int, ...]


@dataclass(frozen=True)
class Layout:
    """The rays about the centre, counter-clockwise: what the symmetries are built from."""
    centre: tuple
    reference: int               # the point whose image fixes a Cartesian matrix
    centre_index: int | None     # the point at the centre, if any
    rays: tuple                  # tuple of tuples of indices, each by increasing radius
    ray_turns: tuple | None      # polar path: the turn of each ray
    points: tuple | None         # Cartesian path: config.points
    n: int
    period: int                  # rotation by `period` rays is the rotation by 1/k turn
    mirror_offsets: tuple        # reflections map ray i to ray (j - i) mod m, j in this tuple


class LazyMatrix:
    """The exact orthogonal matrix ``((a, b), (c, d))`` of a Cartesian symmetry, computed
    on first read (iteration, indexing, equality, hash) and then kept.  Deciding a group
    needs only the permutations; the matrix costs a field inverse (seconds in a
    cyclotomic field of degree thousands) and only the report and the certificate of the
    whole configuration's group read it, not the audit's groups of sub-configurations."""

    __slots__ = ("_make", "_rows")

    def __init__(self, make):
        self._make, self._rows = make, None

    def rows(self) -> tuple:
        if self._rows is None:
            self._rows, self._make = self._make(), None
        return self._rows

    def __iter__(self):
        return iter(self.rows())

    def __getitem__(self, i):
        return self.rows()[i]

    def __len__(self) -> int:
        return 2

    def __eq__(self, other):
        if isinstance(other, LazyMatrix):
            other = other.rows()
        return self.rows() == other

    def __hash__(self):
        return hash(self.rows())

    def __repr__(self) -> str:
        return repr(self.rows())


def identity(polar: bool, centre) -> Isometry:
    """The identity of a single point (its permutation ``(0,)``)."""
    if polar:
        return Isometry("rotation", centre, fmpq(0), None, (0,))
    one, zero = _one_zero(centre)
    return Isometry("rotation", centre, None, ((one, zero), (zero, one)), (0,))


def _one_zero(centre):
    zero = centre[0] * 0
    return zero + 1, zero


def _permutation(layout: Layout, image_ray) -> tuple[int, ...]:
    """``perm[i]``: the image of point i when ray r goes to ray ``image_ray(r)`` (a
    function that also maps a NumPy array of ray indices)."""
    rays = layout.rays
    m = len(rays)
    if m > 64 and layout.n == m + (layout.centre_index is not None):  # one point per ray
        first = firsts(rays)
        perm = np.arange(layout.n)
        perm[first] = first[image_ray(np.arange(m))]
        return tuple(perm.tolist())
    perm = list(range(layout.n))
    for r, ray in enumerate(rays):
        target = rays[image_ray(r)]
        for i, j in zip(ray, target):
            perm[i] = j
    return tuple(perm)


def _reference_image(layout: Layout, image_ray):
    """``(u, v)``: the reference point and its image, relative to the centre."""
    ref = layout.reference
    for r, ray in enumerate(layout.rays):
        if ref in ray:
            image = layout.rays[image_ray(r)][ray.index(ref)]
            break
    cx, cy = layout.centre
    a, b = layout.points[ref], layout.points[image]
    return (a[0] - cx, a[1] - cy), (b[0] - cx, b[1] - cy)


def rotation(layout: Layout, shift: int) -> Isometry:
    """The rotation mapping ray r to ray r + shift (counter-clockwise by the angle from
    ray 0 to ray ``shift``)."""
    m = len(layout.rays)

    def image_ray(r):
        return (r + shift) % m

    perm = _permutation(layout, image_ray)
    if layout.ray_turns is not None:
        turns = layout.ray_turns
        return Isometry("rotation", layout.centre, turns[shift] - turns[0], None, perm)
    if shift == 0:
        one, zero = _one_zero(layout.centre)
        return Isometry("rotation", layout.centre, None, ((one, zero), (zero, one)), perm)

    def matrix():
        (ux, uy), (vx, vy) = _reference_image(layout, image_ray)
        inverse = 1 / (ux * ux + uy * uy)      # one field inverse, not two
        cos, sin = (ux * vx + uy * vy) * inverse, (ux * vy - uy * vx) * inverse
        return ((cos, -sin), (sin, cos))
    return Isometry("rotation", layout.centre, None, LazyMatrix(matrix), perm)


def reflection(layout: Layout, offset: int) -> Isometry:
    """The reflection mapping ray r to ray offset - r."""
    m = len(layout.rays)

    def image_ray(r):
        return (offset - r) % m

    perm = _permutation(layout, image_ray)
    if layout.ray_turns is not None:
        turns = layout.ray_turns
        axis = (turns[0] + turns[offset]) / 2
        if axis >= fmpq(1, 2):
            axis -= fmpq(1, 2)
        return Isometry("reflection", layout.centre, axis, None, perm)

    def matrix():
        (ux, uy), (vx, vy) = _reference_image(layout, image_ray)
        inverse = 1 / (ux * ux + uy * uy)      # one field inverse, not two
        c, s = (ux * vx - uy * vy) * inverse, (ux * vy + uy * vx) * inverse
        return ((c, s), (s, -c))
    return Isometry("reflection", layout.centre, None, LazyMatrix(matrix), perm)
