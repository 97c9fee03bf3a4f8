"""Keys of quotients num/den held without dividing, for fields of large degree (issue 9).

In a cyclotomic field of degree thousands an inverse costs 0.1 s to seconds (an xgcd
modulo a prime and a Newton lift, :mod:`exactsym.exact.inverse`), a product milliseconds;
with coefficients of thousands of digits an inverse costs as much at degree 4.
The paper layer's ray keys (x^2 / |d|^2) and gap keys (d^2 / (|a|^2 |b|^2)) are only
compared for equality (sets, dicts, small integer ids), so there they are held as
:class:`RatioKey`: equal iff num den' == num' den, exactly; hashed by the cell
floor(2^24 num / den), a function of the value alone, read from Arb balls; a ball only
filters: when it straddles a cell boundary j, the exact sign of 2^24 num - j den settles
the cell.  The value is never computed, and no decision reads a ball.
"""

from __future__ import annotations

from flint import arb, ctx

from ..exact import exact_key, sign
from ..exact.cyclotomic_modular import images, ratio_irrational
from ..exact.fused import complex_product, cross_is_zero
from ..exact.number import big_field, is_algebraic, largest_field
from ..exact.ratio import rational_ratio
from .filtered import ball
from .inverses import squared_length

_CELLS = 1 << 24           # hash cells: floor(2^24 * value)
_PREC = 64


def ball_at(x, prec: int) -> arb:
    """An Arb ball of the exact number ``x`` at about ``prec`` bits (the 64-bit balls of
    :func:`exactsym.paper.filtered.ball` are cached per object)."""
    if prec == _PREC:
        return ball(x)
    if is_algebraic(x):
        return x.enclosure(prec)
    with ctx.workprec(prec):
        return arb(x)


class RatioKey:
    """The exact number num/den (den > 0) as a hashable key, without a division.

    ``parts()`` returns ``(num, den)``, exact (called at most once, when an equality or
    a cell boundary needs them); ``value_ball(prec)`` an Arb ball of num/den from balls
    at ``prec`` bits.  Equal iff the values are equal (exact products); the hash is the
    value's cell (module docstring).  Never equal to another kind of key: a caller that
    mixes kinds must give every value of one kind (:func:`ray_ratio_key` gives rational
    values their ``exact_key``, decided exactly).  ``home``: the number field the value
    would lie in (keys of two fields are unequal, as their exact keys were: those
    name the field object)."""

    __slots__ = ("_parts", "_exact", "_hash", "home")

    def __init__(self, parts, value_ball, home):
        self._parts, self._exact, self.home = parts, None, home
        self._hash = hash(("ratio", self._cell(value_ball)))

    def exact(self) -> tuple:
        if self._exact is None:
            self._exact = self._parts()
            self._parts = None
        return self._exact

    def _cell(self, value_ball) -> int:
        """floor(2^24 num / den): balls at rising precision (a tiny vector needs more
        bits) until the ball is narrow, then the cell, or at a boundary an exact sign."""
        prec = _PREC
        while True:
            # every operation at the balls' precision (at the default 53 bits a value of
            # 10^16, from a level's directions scaled to clear the centre's denominator,
            # never got narrow; and a floor rounded to 53 bits is not the cell)
            with ctx.workprec(prec + 16):
                scaled = value_ball(prec) * _CELLS
                if scaled.is_finite() and scaled.rad() < 0.25:
                    cell = scaled.floor().unique_fmpz()
                    if cell is not None:
                        return int(cell)
                    j = int(scaled.upper().floor().unique_fmpz())   # the one boundary in it
                    break
            prec *= 4
        num, den = self.exact()
        return j if sign(_CELLS * num - j * den) >= 0 else j - 1

    def __hash__(self) -> int:
        return self._hash

    def __eq__(self, other) -> bool:
        if self is other:
            return True
        if not isinstance(other, RatioKey):
            return False
        if self._hash != other._hash or self.home is not other.home:
            return False    # the cells differ; or two fields, whose exact_keys differed too
        (a, b), (c, d) = self.exact(), other.exact()
        return a * d == c * b

    def __ne__(self, other) -> bool:
        return not self.__eq__(other)

    def __repr__(self) -> str:
        num, den = self.exact()
        return f"RatioKey({num!r} / {den!r})"


class OrderedKey(RatioKey):
    """A :class:`RatioKey` of an exact number ``value()`` (denominator 1) that is also
    ordered: Arb balls at rising precision decide ``<`` when they are apart, the exact
    sign of the difference when they never are.  For a polygon's chords in a field of
    degree thousands (:func:`chord_key`): the strings compare and hash them, and an
    exact chord is two products of megabyte numbers."""

    __slots__ = ("_ball_at", "_pair")

    def __init__(self, value, value_ball, home, pair=None, parts=None):
        # parts: ``() -> (num, den)``, den > 0, instead of ``(value(), 1)``: a quotient
        # held undivided (off one circle the chord key divides by two squared lengths)
        self._ball_at = value_ball
        self._pair = pair
        super().__init__(parts or (lambda: (value(), 1)), value_ball, home)

    def __eq__(self, other) -> bool:
        # the keys of one pair of vector objects, either way round (a string's chord
        # v_i v_j and another's v_j v_i): equal without the product u.v, which in a tower
        # over the sparse Q(zeta_N) can cost seconds
        p = self._pair
        if p is not None and isinstance(other, OrderedKey) and other._pair is not None:
            q = other._pair
            if (p[0] is q[0] and p[1] is q[1]) or (p[0] is q[1] and p[1] is q[0]):
                return True
        return RatioKey.__eq__(self, other)

    def __ne__(self, other) -> bool:
        return not self.__eq__(other)

    def _cmp(self, other) -> int:
        if self == other:
            return 0
        prec = _PREC
        while prec <= 1024:
            with ctx.workprec(prec + 16):
                a, b = self._ball_at(prec), other._ball_at(prec)
            if a < b:
                return -1
            if a > b:
                return 1
            prec *= 4
        (a, b), (c, d) = self.exact(), other.exact()
        if _is_one(b) and _is_one(d):
            return sign(a - c)
        return sign(a * d - c * b)           # b, d > 0

    def __lt__(self, other) -> bool:
        return self._cmp(other) < 0

    def __le__(self, other) -> bool:
        return self._cmp(other) <= 0

    def __gt__(self, other) -> bool:
        return self._cmp(other) > 0

    def __ge__(self, other) -> bool:
        return self._cmp(other) >= 0

    __hash__ = RatioKey.__hash__


def _is_one(x) -> bool:
    return isinstance(x, int) and x == 1


def chord_key(polygon, i: int, j: int) -> OrderedKey:
    """:meth:`~exactsym.paper.circle_polygon.CirclePolygon.chord_key` of a polygon (on one
    circle ``-u.v``, else the signed squared cosine) as an :class:`OrderedKey`: equal,
    ordered and hashed as that exact key, read from balls of the vectors (the products
    only for equal or touching balls)."""
    n = polygon.n
    u, v = polygon.directions[i % n], polygon.directions[j % n]
    one_circle = polygon.one_circle

    def value_ball(prec):
        ux, uy, vx, vy = (ball_at(c, prec) for c in (u[0], u[1], v[0], v[1]))
        d = ux * vx + uy * vy
        if one_circle:
            return -d
        # off one circle the key is -sign(u.v) (u.v)^2 / (|u|^2 |v|^2) (_cosine_key):
        # -d |d| / ..., continuous, so a ball of it from the balls of d and the lengths
        return -d * abs(d) / ((ux * ux + uy * uy) * (vx * vx + vy * vy))
    if one_circle:
        return OrderedKey(lambda: polygon.chord_key(i, j), value_ball, largest_field(u + v),
                          (u, v))

    def parts():
        # (-sign(d) d^2, |u|^2 |v|^2): the key undivided -- an inverse in the gathering
        # search's Q(gamma) (coefficients of 19,000 bits) cost seconds (issue 30)
        d = u[0] * v[0] + u[1] * v[1]
        return -sign(d) * d * d, squared_length(u) * squared_length(v)
    return OrderedKey(None, value_ball, largest_field(u + v), (u, v), parts)


def ray_ratio_key(x, y):
    """``exact_key(x^2 / (x^2 + y^2))`` for a non-zero vector with a coordinate in a big
    field (:func:`big_field`), or None (other vectors: the caller divides).  A rational
    value (decided exactly, :func:`rational_ratio`) keys as ``exact_key`` did; an
    irrational one as a :class:`RatioKey`."""
    if not big_field(x, y):
        return None
    if ratio_irrational(x, y):
        # proved irrational by two embeddings into F_p (exact, microseconds): the squares,
        # products of degree thousands, are made only if an equality needs them
        def parts():
            xx = x * x
            return xx, xx + y * y
        return RatioKey(parts, _ratio_ball(x, y), largest_field((x, y)))
    xx = x * x
    length = xx + y * y
    q = rational_ratio(xx, length)
    if q is not None:
        return exact_key(q)

    return RatioKey(lambda: (xx, length), _ratio_ball(x, y), largest_field((x, y)))


def _ratio_ball(x, y):
    """``prec -> `` an Arb ball of x^2 / (x^2 + y^2)."""
    def value_ball(prec):
        bx, by = ball_at(x, prec), ball_at(y, prec)
        sq = bx * bx
        return sq / (sq + by * by)
    return value_ball


class AngleKey(RatioKey):
    """The counter-clockwise angle from a to b as the value of :func:`gap_ratio_key`
    (-sign(d) c d^2 / (|a|^2 |b|^2), hashed by its cell like a :class:`RatioKey`), but
    compared as angles: equal iff (a.b, a x b) and (a'.b', a' x b') are positively
    proportional (equal signs of the dot products, the cross products' signs being equal
    in the key's class, and d e' == e d'): products of degree 4 in the coordinates, not
    the degree 8 of cross-multiplied quotients (in a tower of radicals a product costs
    more the larger its operands)."""

    __slots__ = ("a", "b", "dot_sign", "_de")

    def __init__(self, a, b, dot_sign: int, parts, value_ball, home):
        self.a, self.b, self.dot_sign, self._de = a, b, dot_sign, None
        super().__init__(parts, value_ball, home)

    def dot_cross(self) -> tuple:
        if self._de is None:
            a, b = self.a, self.b
            # conj(a) b: three products, two reductions in a large field
            self._de = complex_product((a[0], -a[1]), (b[0], b[1]))
        return self._de

    def __eq__(self, other) -> bool:
        if self is other:
            return True
        if not isinstance(other, AngleKey):
            return False
        if self._hash != other._hash or self.home is not other.home \
                or self.dot_sign != other.dot_sign:
            return False
        if _angles_differ_mod_p(self.a, self.b, other.a, other.b):
            return False
        (d, e), (d2, e2) = self.dot_cross(), other.dot_cross()
        return cross_is_zero((d, e), (d2, e2))

    def __hash__(self) -> int:
        return self._hash


def _angles_differ_mod_p(a, b, a2, b2) -> bool:
    """True only when the angle from a to b is proved unequal to the one from a2 to b2:
    (d, e) = conj(a) b and (d2, e2) = conj(a2) b2 have d e2 - e d2 != 0 under a ring map
    into F_p (:func:`exactsym.exact.cyclotomic_modular.images` of the eight coordinates;
    zero maps to zero).  False means "not proved".  Equal hash cells of unequal angles
    are then refuted without any exact product (over a sparse base those cross-multiply
    denominators: issue 9)."""
    found = images((*a, *b, *a2, *b2))
    if found is None:
        return False
    p, sides = found
    for ax, ay, bx, by, cx, cy, ex, ey in sides:
        d, e = ax * bx + ay * by, ax * by - ay * bx
        d2, e2 = cx * ex + cy * ey, cx * ey - cy * ex
        if (d * e2 - e * d2) % p:
            return True
    return False


def gap_ratio_key(a, b, c: int, dot_sign: int):
    """The value of :func:`exactsym.paper.keys.ccw_gap_key` for vectors a, b with
    cross-product sign ``c`` (non-zero) and dot-product sign ``dot_sign``, as ``(class,
    key)`` with key an :class:`AngleKey`: equal iff the gap keys are equal.  For equality
    only (small integer ids): every gap of a polygon gets this kind of key.  No exact
    product until two gaps share a hash cell."""
    s = -dot_sign * c

    def parts():
        d = a[0] * b[0] + a[1] * b[1]
        la = a[0] * a[0] + a[1] * a[1]
        lb = b[0] * b[0] + b[1] * b[1]
        return s * d * d, la * lb

    def value_ball(prec):
        ax, ay, bx, by = (ball_at(v, prec) for v in (a[0], a[1], b[0], b[1]))
        dot = ax * bx + ay * by
        return s * dot * dot / ((ax * ax + ay * ay) * (bx * bx + by * by))
    return (0 if c > 0 else 2, AngleKey(a, b, dot_sign, parts, value_ball,
                                        largest_field(a + b)))


__all__ = ["AngleKey", "OrderedKey", "RatioKey", "chord_key", "gap_ratio_key", "ray_ratio_key"]
