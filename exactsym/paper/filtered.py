"""Certified ball filters for the paper layer's sign predicates (issue 9, the CGAL way).

The sign of a cross or dot product of two exact direction vectors is first read from Arb
balls: each coordinate's enclosure (computed once per number object, at 64 bits) and
ball arithmetic, which is rigorous (the exact value lies in the result ball).  When the
ball excludes zero its sign is the exact sign; only when it contains zero is the exact
product computed (two multiplications in a number field of degree up to hundreds, about
a millisecond each, which the filter saves).  A ball never decides anything it does not
contain, so every answer equals the exact one.

Rationals (``fmpq``, ``int``) skip the filter: their exact products are cheap.
"""

from __future__ import annotations

from flint import arb

from ..exact import exact_key, sign
from ..exact.number import any_algebraic, is_algebraic
from ..exact.context import Cache

_PREC = 64
_BALLS = Cache("paper balls")     # id(x) -> (x, ball)
_LIMIT = 1 << 14


def ball(x) -> arb:
    """An Arb ball containing the exact number ``x`` (cached per object: the entry holds
    the object itself, so an id is never mistaken for another object's)."""
    balls = _BALLS.table()
    hit = balls.get(id(x))
    if hit is not None and hit[0] is x:
        return hit[1]
    if is_algebraic(x):
        b = x.enclosure(_PREC)
    else:
        b = arb(x)
    if len(balls) >= _LIMIT:
        balls.clear()
    balls[id(x)] = (x, b)
    return b


def _exact_type(u) -> bool:
    return not any_algebraic(u)


def ball_sign(b: arb) -> int:
    if b > 0:
        return 1
    if b < 0:
        return -1
    return 0        # undecided: the ball contains zero


def cross_sign(u, v) -> int:
    """The exact sign of u_x v_y - u_y v_x."""
    if _exact_type(u) and _exact_type(v):
        return sign(u[0] * v[1] - u[1] * v[0])
    s = ball_sign(ball(u[0]) * ball(v[1]) - ball(u[1]) * ball(v[0]))
    return s if s else sign(u[0] * v[1] - u[1] * v[0])


def dot_sign(u, v) -> int:
    """The exact sign of u . v."""
    if _exact_type(u) and _exact_type(v):
        return sign(u[0] * v[0] + u[1] * v[1])
    s = ball_sign(ball(u[0]) * ball(v[0]) + ball(u[1]) * ball(v[1]))
    return s if s else sign(u[0] * v[0] + u[1] * v[1])


def half_plane(d) -> int:
    """0 for directions with angle in [0, pi), 1 for [pi, 2 pi) (``d`` not zero)."""
    sy = sign(d[1])
    return 0 if sy > 0 or (sy == 0 and sign(d[0]) > 0) else 1


def compare_directions(d1, d2) -> int:
    """Compare the angles in [0, 2 pi) of two non-zero vectors: -1, 0 or 1 (as
    :func:`exactsym.geometry.predicates.compare_directions`, with the cross product filtered)."""
    h1, h2 = half_plane(d1), half_plane(d2)
    if h1 != h2:
        return -1 if h1 < h2 else 1
    return -cross_sign(d1, d2)


def gap_classes_on_circle(dirs) -> list:
    """For non-zero exact vectors of one length, in counter-clockwise order: one hashable
    token per gap (d_i, d_{i+1}), equal iff the counter-clockwise angles are equal
    (:func:`circle_gap_tokens` with every scale 1)."""
    n = len(dirs)
    return circle_gap_tokens([(dirs[i], dirs[(i + 1) % n], None) for i in range(n)])


def circle_gap_tokens(pairs) -> list:
    """One hashable token per ``(a, b, scale)`` of ``pairs`` (non-zero exact vectors, a
    scale an exact positive number or None for 1), equal iff the counter-clockwise angles
    from a to b are equal -- provided |a| |b| scale is the same for every pair.

    The angle is fixed by the sign of the cross product (below, at or above half a turn)
    and the dot product times the scale (|a| |b| scale cos(angle), the common factor
    being positive); balls sort those, and only pairs in a cluster of overlapping balls
    get exact products -- distinct gaps cost no exact product at all.  (Scales let one
    call compare the gaps of a polygon on one circle of squared radius L, scale L, with
    gaps to a vector of length L^(3/2), scale 1: a reflection u^2 conj(w) made without
    dividing by L, :func:`exactsym.paper.polygon.strings.string_classes`.)"""
    classes, dots = [], []
    for a, b, scale in pairs:
        classes.append(cross_sign(a, b))
        d = ball(a[0]) * ball(b[0]) + ball(a[1]) * ball(b[1])
        dots.append(d if scale is None else d * ball(scale))
    tokens: list = [None] * len(pairs)
    by_class: dict = {}
    for i, c in enumerate(classes):
        by_class.setdefault(c, []).append(i)
    for c, members in by_class.items():
        if c == 0:       # a half or a full turn: the sign of the dot product tells them apart
            for i in members:
                tokens[i] = (0, dot_sign(pairs[i][0], pairs[i][1]))
            continue
        members.sort(key=lambda i: dots[i].lower())     # interval merging: overlapping
        # balls (the only ones that may hold equal values) end up in one cluster
        cluster: list = []
        upper = None
        for i in members + [None]:
            if i is not None and cluster and not (dots[i].lower() > upper):
                cluster.append(i)
                upper = max(upper, dots[i].upper())
                continue
            if len(cluster) == 1:
                tokens[cluster[0]] = (c, "alone", cluster[0])
            else:
                for j in cluster:
                    a, b, scale = pairs[j]
                    d = a[0] * b[0] + a[1] * b[1]
                    tokens[j] = (c, exact_key(d if scale is None else d * scale))
            if i is not None:
                cluster, upper = [i], dots[i].upper()
    return tokens


__all__ = ["ball", "cross_sign", "dot_sign", "compare_directions", "gap_classes_on_circle",
           "circle_gap_tokens"]
