"""Radial projection G_ij and the type 4 test (Section 3, ``obs-type-4``).

"the vertices of G_i are projected radially on the circumference of the enclosing circle
of G_j; construct a polygon G_ij with the full set of vertices on the circle":
:func:`radial_projection` takes directions only and puts the union on the target's circle.
Two vertices on one ray are merged into one vertex whose label lists both robots (set
semantics), and the projection records the coincidences (a finding: ``obs-gcd``,
``obs-type-4`` count n_i + n_j vertices).  The robot at C is never projected.  A vertex
"of G_t" in a projection is mapped back to the robot of its label lying on G_t's circle
(:func:`robot_in`).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

from .. import polygon as P
from ...exact import rational_sqrt
from ..circle_polygon import CirclePolygon, polygon_from_directions
from ..inverses import inverse_length
from ..homogeneous import scaled as scaled_form
from ...exact.number import big_field, rational_value
from ...exact.ratio import rational_ratio
from .concentric import Ring, mirror_lines, polygon_name


@dataclass(frozen=True)
class Projection:
    """G_ij: ``ring`` on the target's circle, ``coincident``: pairs of labels (source
    vertex, target vertex) that lay on one ray and were merged into one vertex."""
    ring: Ring
    coincident: tuple


def scale_to(r2_to, r2_from):
    """sqrt(r2_to / r2_from) when rational, else None."""
    if big_field(r2_to, r2_from):        # degree thousands: rational or not, no inverse
        ratio = rational_ratio(r2_to, r2_from)
        return None if ratio is None else rational_sqrt(ratio)
    ratio = r2_to * inverse_length(r2_from)          # cached: no inverse per projection
    ratio = rational_value(ratio)
    return None if ratio is None else rational_sqrt(ratio)


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
        scale = scale_to(target.radius_squared, source.radius_squared)
    for lab, d, key in zip(source.polygon.labels, source.polygon.directions, skeys):
        if key in merged:
            if source is not target:
                coincident.append((lab, merged[key][0]))
                inner_first = not target.radius_squared < source.radius_squared
                both = lab + merged[key][0] if inner_first else merged[key][0] + lab
                merged[key][0] = tuple(dict.fromkeys(both))      # innermost robot first
            continue
        if scale is not None:
            d, source_d = (d[0] * scale, d[1] * scale), d
            scaled_form(d, source_d, scale)          # its short text (..homogeneous)
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
    ring = Ring(name or polygon_name(levels), poly, target.radius_squared, levels, robots,
                target.own, tuple(order))
    return Projection(ring, tuple(coincident))


def robot_in(label: tuple, ring: Ring) -> int | None:
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


def is_type4(ring: Ring) -> tuple[bool, str]:
    """Preprocess's "G_ij is a type 4 polygon", by the definition: the type of
    :func:`exactsym.paper.polygon.polygon_type` computed from the exact mirrors of the
    polygon (:func:`exactsym.paper.family.mirror_lines`, O(n)), never from the lines the
    CW/ACW strings find (an edge string of odd length has a free middle entry, so the
    strings can give an asymmetric odd polygon several "lines").  Returns the verdict
    and its text."""
    if ring.polygon is None:
        return False, "the robot at C"
    poly = ring.polygon
    verdict = P.polygon_type(poly, mirror_lines(poly))
    if verdict is None:
        return False, "no line of straight symmetry"
    return str(verdict) == "type-4", f"{verdict} ({verdict.reason})"


@lru_cache(maxsize=4096)     # a bounded function of an int: nothing of a configuration kept
def could_be_type4(m: int) -> bool:
    """A type 4 polygon has an odd, composite number of vertices (k > 1 mirrors of an odd
    polygon that is not regular: k divides n and 1 < k < n), so at least 9."""
    return m >= 9 and m % 2 == 1 and not P.is_prime(m)


def radius_less(a: Ring, b: Ring) -> bool:
    return a.radius_squared < b.radius_squared


def coincidence_note(proj: Projection) -> str:
    if not proj.coincident:
        return ""
    pairs = ", ".join(f"{a}~{b}" for a, b in proj.coincident[:4])
    return (f"; {len(proj.coincident)} vertex pair(s) on a common ray merged into one vertex "
            f"({pairs}{', ...' if len(proj.coincident) > 4 else ''})")
