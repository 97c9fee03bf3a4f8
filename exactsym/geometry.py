"""Exact plane geometry: predicates return enums or ints, constructions return exact points.

Points are pairs ``(x, y)`` of exact numbers of :mod:`exactsym.exact` (``fmpq`` or
``FieldElement`` of one field).  Nothing here rounds.
"""

from __future__ import annotations

from enum import IntEnum
from functools import cmp_to_key

from .exact import sign

Point = tuple


class Turn(IntEnum):
    """Orientation of an ordered triple: the sign of the cross product."""
    RIGHT = -1      # clockwise
    COLLINEAR = 0
    LEFT = 1        # counter-clockwise


def cross(o: Point, a: Point, b: Point):
    """``(a - o) x (b - o)``."""
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def orientation(p: Point, q: Point, r: Point) -> Turn:
    return Turn(sign(cross(p, q, r)))


def squared_distance(p: Point, q: Point):
    dx, dy = p[0] - q[0], p[1] - q[1]
    return dx * dx + dy * dy


def compare_distance(c: Point, p: Point, q: Point) -> int:
    """Sign of ``|cp|^2 - |cq|^2``: -1 when p is nearer to c than q."""
    return sign(squared_distance(c, p) - squared_distance(c, q))


def midpoint(p: Point, q: Point) -> Point:
    return ((p[0] + q[0]) / 2, (p[1] + q[1]) / 2)


def circumcentre(a: Point, b: Point, c: Point) -> Point:
    """Centre of the circle through three non-collinear points (raises ValueError otherwise)."""
    bx, by = b[0] - a[0], b[1] - a[1]
    cx, cy = c[0] - a[0], c[1] - a[1]
    d = 2 * (bx * cy - by * cx)
    if d == 0:
        raise ValueError("collinear points have no circumcentre")
    b2, c2 = bx * bx + by * by, cx * cx + cy * cy
    return (a[0] + (cy * b2 - by * c2) / d, a[1] + (bx * c2 - cx * b2) / d)


def half_plane(d: Point) -> int:
    """0 for directions with angle in [0, pi), 1 for [pi, 2 pi); ``d`` must not be zero."""
    sy = sign(d[1])
    return 0 if sy > 0 or (sy == 0 and sign(d[0]) > 0) else 1


def compare_directions(d1: Point, d2: Point) -> int:
    """Compare the angles in [0, 2 pi) of two non-zero vectors: -1, 0 or 1."""
    h1, h2 = half_plane(d1), half_plane(d2)
    if h1 != h2:
        return -1 if h1 < h2 else 1
    return -sign(d1[0] * d2[1] - d1[1] * d2[0])


def angular_sort(centre: Point, points: list[Point], indices: list[int]) -> list[int]:
    """``indices`` sorted counter-clockwise about ``centre``, starting at angle 0 (the +x ray).

    Points at the centre itself come first.
    """
    def direction(i):
        return (points[i][0] - centre[0], points[i][1] - centre[1])

    def cmp(i, j):
        di, dj = direction(i), direction(j)
        zi, zj = di[0] == 0 and di[1] == 0, dj[0] == 0 and dj[1] == 0
        if zi or zj:
            return (zj - zi)
        return compare_directions(di, dj)

    return sorted(indices, key=cmp_to_key(cmp))
