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

from flint import arb, ctx, fmpq, fmpq_poly

from ..exact import FieldElement, exact_key, sign
from ..exact.field import PolyElement

_PREC = 64
_BALLS: dict = {}
_LIMIT = 1 << 14


def ball(x) -> arb:
    """An Arb ball containing the exact number ``x`` (cached per object: the entry holds
    the object itself, so an id is never mistaken for another object's)."""
    hit = _BALLS.get(id(x))
    if hit is not None and hit[0] is x:
        return hit[1]
    if isinstance(x, FieldElement):
        b = x.enclosure(_PREC)
    else:
        b = arb(x)
    if len(_BALLS) >= _LIMIT:
        _BALLS.clear()
    _BALLS[id(x)] = (x, b)
    return b


def _exact_type(u) -> bool:
    return not isinstance(u[0], FieldElement) and not isinstance(u[1], FieldElement)


def _ball_sign(b: arb) -> int:
    if b > 0:
        return 1
    if b < 0:
        return -1
    return 0        # undecided: the ball contains zero


def cross_sign(u, v) -> int:
    """The exact sign of u_x v_y - u_y v_x."""
    if _exact_type(u) and _exact_type(v):
        return sign(u[0] * v[1] - u[1] * v[0])
    s = _ball_sign(ball(u[0]) * ball(v[1]) - ball(u[1]) * ball(v[0]))
    return s if s else sign(u[0] * v[1] - u[1] * v[0])


def dot_sign(u, v) -> int:
    """The exact sign of u . v."""
    if _exact_type(u) and _exact_type(v):
        return sign(u[0] * v[0] + u[1] * v[1])
    s = _ball_sign(ball(u[0]) * ball(v[0]) + ball(u[1]) * ball(v[1]))
    return s if s else sign(u[0] * v[0] + u[1] * v[1])


def half_plane(d) -> int:
    """0 for directions with angle in [0, pi), 1 for [pi, 2 pi) (``d`` not zero)."""
    sy = sign(d[1])
    return 0 if sy > 0 or (sy == 0 and sign(d[0]) > 0) else 1


def compare_directions(d1, d2) -> int:
    """Compare the angles in [0, 2 pi) of two non-zero vectors: -1, 0 or 1 (as
    :func:`exactsym.geometry.compare_directions`, with the cross product filtered)."""
    h1, h2 = half_plane(d1), half_plane(d2)
    if h1 != h2:
        return -1 if h1 < h2 else 1
    return -cross_sign(d1, d2)


def gap_classes_on_circle(dirs) -> list:
    """For non-zero exact vectors of one length, in counter-clockwise order: one hashable
    token per gap (d_i, d_{i+1}), equal iff the counter-clockwise angles are equal.

    The angle is fixed by the sign of the cross product (below, at or above half a turn)
    and the dot product (the lengths being equal); balls sort the dot products, and only
    gaps in a cluster of overlapping balls get exact dot products -- distinct gaps cost no
    exact product at all."""
    n = len(dirs)
    classes, dots = [], []
    for i in range(n):
        a, b = dirs[i], dirs[(i + 1) % n]
        c = cross_sign(a, b)
        classes.append(c)
        dots.append(ball(a[0]) * ball(b[0]) + ball(a[1]) * ball(b[1]))
    tokens: list = [None] * n
    by_class: dict = {}
    for i, c in enumerate(classes):
        by_class.setdefault(c, []).append(i)
    for c, members in by_class.items():
        if c == 0:       # a half or a full turn: the sign of the dot product tells them apart
            for i in members:
                tokens[i] = (0, dot_sign(dirs[i], dirs[(i + 1) % n]))
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
                    a, b = dirs[j], dirs[(j + 1) % n]
                    tokens[j] = (c, exact_key(a[0] * b[0] + a[1] * b[1]))
            if i is not None:
                cluster, upper = [i], dots[i].upper()
    return tokens


#: polynomial fields from this degree get :class:`RatioKey`\ s: an inverse there costs
#: from 0.1 s (degree 5,760: xgcd and Newton lift) to seconds, a product milliseconds
RATIO_KEY_DEGREE = 64
_CELLS = 1 << 24           # hash cells: floor(2^24 * value)


def _ball_at(x, prec: int) -> arb:
    if isinstance(x, FieldElement):
        return x.enclosure(prec)
    with ctx.workprec(prec):
        return arb(x)


def _big_field(x) -> bool:
    return isinstance(x, PolyElement) and x.field.degree >= RATIO_KEY_DEGREE


class RatioKey:
    """The exact number num/den (den > 0), irrational, held without dividing: equal iff
    num * den' == num' * den (two exact products), hashed by the cell floor(2^24 *
    num/den), a function of the value alone read from Arb balls (when the ball of the
    value straddles a cell boundary j, the exact sign of 2^24 num - j den settles the
    cell: balls only filter).  It stands for ``exact_key(num / den)`` where that key is
    compared for equality only (ray keys, line keys: sets and dicts), saving the inverse
    of den in a field of degree thousands.  Never equal to another kind of key: the
    caller gives rational values their ``exact_key`` (decided exactly, see
    :func:`ray_ratio_key`), so one value always gets one kind of key."""

    __slots__ = ("num", "den", "_hash")

    def __init__(self, num, den, x, y):
        self.num, self.den = num, den
        self._hash = hash(("ratio", self._cell(x, y)))

    def _cell(self, x, y) -> int:
        """floor(2^24 num / den), num / den = x^2 / (x^2 + y^2), from balls of x and y
        at rising precision (a tiny vector needs more bits), the boundary by an exact sign."""
        prec = _PREC
        while True:
            bx, by = (ball(x), ball(y)) if prec == _PREC else (_ball_at(x, prec),
                                                                 _ball_at(y, prec))
            xx = bx * bx
            scaled = xx / (xx + by * by) * _CELLS
            if scaled.is_finite() and scaled.rad() < 0.25:
                break
            prec *= 4
        cell = scaled.floor().unique_fmpz()
        if cell is not None:
            return int(cell)
        j = int(scaled.upper().floor().unique_fmpz())     # the one boundary in the ball
        return j if sign(_CELLS * self.num - j * self.den) >= 0 else j - 1

    def __hash__(self) -> int:
        return self._hash

    def __eq__(self, other) -> bool:
        if self is other:
            return True
        if not isinstance(other, RatioKey):
            return False
        if self._hash != other._hash:        # the cells differ: the values differ
            return False
        return self.num * other.den == other.num * self.den

    def __ne__(self, other) -> bool:
        return not self.__eq__(other)

    def __repr__(self) -> str:
        return f"RatioKey({self.num!r} / {self.den!r})"


def ray_ratio_key(x, y):
    """``exact_key(x^2 / (x^2 + y^2))`` for a non-zero vector with a coordinate in a
    polynomial field of degree >= :data:`RATIO_KEY_DEGREE`, or None (other vectors: the
    caller divides).  A rational value (decided exactly: x^2 is a rational multiple of
    the squared length, compared coefficient by coefficient) keys as before; an irrational
    one as a :class:`RatioKey`, hashed from the balls of x and y (cached per object)."""
    if not (_big_field(x) or _big_field(y)):
        return None
    xx = x * x
    length = xx + y * y
    if not isinstance(xx, FieldElement):
        num = fmpq_poly([xx])
    else:
        num = xx.poly
    den = length.poly if isinstance(length, PolyElement) else fmpq_poly([length])
    if num.is_zero():
        return exact_key(fmpq(0))
    coeffs = den.coeffs()
    i = next(k for k, c in enumerate(coeffs) if c != 0)
    top = num.coeffs()
    q = (top[i] if i < len(top) else fmpq(0)) / coeffs[i]
    if num == q * den:                      # x^2 = q |d|^2: the value is the rational q
        return exact_key(q)
    return RatioKey(xx, length, x, y)


__all__ = ["ball", "cross_sign", "dot_sign", "compare_directions", "gap_classes_on_circle",
           "RatioKey", "ray_ratio_key"]
