"""The static geometry of the robots that stand still: hull, centroid, mirror lines.

Exact (signs of cross and dot products of exact points); used by the critical
instants of one mover (:mod:`.instants`) and of a joint step (:mod:`.joint_symmetry`).
"""

from __future__ import annotations

import functools

from flint import fmpq

from ..exact.multiquadratic import MQ
from . import geometry as g

__all__ = ["hull_indices", "smallest_distance_group", "mirror_lines", "reflect", "centroid"]


def hull_indices(pts: dict) -> list:
    """Indices of the vertices of the convex hull of ``{index: point}`` (exact)."""
    items = sorted(pts.items(), key=lambda kv: (float(kv[1][0]), float(kv[1][1]), kv[0]))
    # the float key only orders the scan; ties and near-ties are settled below exactly
    items = _exact_sort(items)

    def turn(o, a, b):
        return g.cross(g.sub(a, o), g.sub(b, o)).sign()

    def chain(seq):
        out = []
        for k, p in seq:
            while len(out) >= 2 and turn(out[-2][1], out[-1][1], p) <= 0:
                out.pop()
            out.append((k, p))
        return out

    lower, upper = chain(items), chain(items[::-1])
    return sorted({k for k, _ in lower[:-1] + upper[:-1]} or {k for k, _ in items})


def _exact_sort(items):
    def cmp(x, y):
        s = (x[1][0] - y[1][0]).sign() or (x[1][1] - y[1][1]).sign()
        return s or (x[0] > y[0]) - (x[0] < y[0])
    return sorted(items, key=functools.cmp_to_key(cmp))


def reflect(x, z, u):
    v = g.sub(x, z)
    k = g.dot(v, u) * 2 / g.dot(u, u)
    return g.sub(g.add(z, g.scale(u, k)), v)


def smallest_distance_group(pts, z) -> list:
    """The robots of ``pts`` (other than ``z``) at the distance from ``z`` that the fewest
    share: a symmetry about ``z`` maps the group onto itself, so its first robot's image
    is one of them (empty when fewer than two robots are not at ``z``)."""
    others = [p for p in pts if p != z]
    if len(others) < 2:
        return []
    groups: dict = {}
    for p in others:
        groups.setdefault(g.dist2(p, z), []).append(p)
    return min(groups.values(), key=len)


def mirror_lines(pts, z) -> list:
    """Directions ``u`` of the lines through ``z`` in which the point set ``pts`` is its
    own mirror image (exact; every candidate line is tested on every point)."""
    group = smallest_distance_group(pts, z)
    if not group:
        return []
    y0 = group[0]
    have = set(pts)
    out: list = []
    for y in group:
        u = g.sub(y0, z) if y == y0 else g.sub(g.scale(g.add(y0, y), MQ.rational(fmpq(1, 2))), z)
        if u[0].is_zero() and u[1].is_zero():
            u = g.quarter(g.sub(y0, z), 1)
        if any(g.cross(u, w).is_zero() for w in out):
            continue
        if all(reflect(p, z, u) in have for p in pts):
            out.append(u)
    return out


def centroid(pts):
    n = MQ.rational(len(pts))
    return (sum((p[0] for p in pts), MQ()) / n, sum((p[1] for p in pts), MQ()) / n)
