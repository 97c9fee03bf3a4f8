"""The paper layer's exact keys of rays, lines through C and gaps between directions.

One home for the keys both :mod:`exactsym.paper.polygon` and :mod:`exactsym.paper.family`
compare (the ground truth, :mod:`exactsym.truth.symmetry`, keeps its own: the two sides share
no logic).  A direction is a rational turn (polar path) or an exact vector from C
(Cartesian path).  A *line* through C is a direction modulo half a turn: its key is the
turn of the line in [0, 1/2), or the ray of its doubled angle (``lemma-LOS-Passes-CenterSECP``).
"""

from __future__ import annotations

from functools import cmp_to_key
from math import atan2, gcd, lcm, pi

from flint import ctx

from ..exact import exact_key, fmpq, normal_turn, sign
from ..exact.fused import complex_product as fused_complex_product, cross_is_zero
from ..exact.cyclotomic_text import fast_number_text as number_text
from ..exact.text_numbers import DIGITS, HUGE, LONG, huge_quotient, number, quotient_decimal
from ..exact.context import Cache
from .homogeneous import homogeneous_pair, line_direction, slope_text
from .circle_polygon import CirclePolygon
from ..exact.cyclotomic_modular import product_ratio_irrational
from ..exact.number import (all_plain_rational, any_algebraic, huge_field, is_number, is_sparse,
                            kummer_tower, largest_field, slow_quotient)
from .filtered import (ball, compare_directions, cross_sign, dot_sign, gap_classes_on_circle,
                       ball_sign)
from .ratio_keys import RatioKey, ball_at, gap_ratio_key, ray_ratio_key
from .inverses import inverse_length, squared_length


HALF = fmpq(1, 2)


def cross(u, v):
    return u[0] * v[1] - u[1] * v[0]


def dot(u, v):
    return u[0] * v[0] + u[1] * v[1]


def ccw_gap_key(polar: bool, a, b):
    """An exact key, strictly increasing in the counter-clockwise angle from direction a
    to direction b, taken in (0, 1] turns (a full turn when a == b): turns when ``polar``,
    else exact vectors."""
    if polar:
        d = normal_turn(b - a)
        return d if d != 0 else fmpq(1)
    c, d = cross_sign(a, b), dot(a, b)      # the cross product's sign ball-filtered
    if c > 0:       # d^2 / (|a|^2 |b|^2), one cached inverse per length (no inverse per gap)
        return (0, -sign(d) * d * d * inverse_length(squared_length(a))
                * inverse_length(squared_length(b)))
    if c < 0:
        return (2, sign(d) * d * d * inverse_length(squared_length(a))
                * inverse_length(squared_length(b)))
    return (1, 0) if sign(d) < 0 else (3, 0)


def ray_key(polar: bool, d, inverse=None):
    """Exact hashable key of the ray from C with direction d (cheap to hash: numbers go
    through :func:`exactsym.exact.exact_key`): a turn (polar), else the signs of the
    coordinates of the unit vector u = d/|d| and ``u_x^2 = x^2 / (x^2 + y^2)``, which
    determine u, hence the ray.  The only division is by the squared length, a rational
    for points on a circle of rational radius about a rational centre; pass
    ``inverse`` = 1/(x^2 + y^2) when it is known (else
    :func:`exactsym.paper.inverses.inverse_length`: one inverse per distinct length, never
    one per vertex: an inverse in a cyclotomic field of degree hundreds costs a second).
    In a polynomial field of large degree the squared x coordinate is held undivided
    (:func:`exactsym.paper.ratio_keys.ray_ratio_key`: the same equalities, no inverse)."""
    if polar:
        return hashable_key(normal_turn(d))
    x, y = d
    if inverse is None and any_algebraic((x, y)):
        ratio = ray_ratio_key(x, y)          # a polynomial field: no inverse at all
        if ratio is not None:
            return (sign(x), sign(y), ratio)
    xx = x * x
    if inverse is None:
        inverse = inverse_length(xx + y * y)
    return (sign(x), sign(y), exact_key(xx * inverse))


def ray_keys(poly: CirclePolygon) -> tuple:
    return tuple(ray_key(poly.polar, d) for d in poly.directions)


def hashable_key(key):
    """A cheap hashable form of an exact key (a number or a tuple of numbers)."""
    if isinstance(key, tuple):
        return tuple(hashable_key(k) for k in key)
    if is_number(key):
        return exact_key(key)
    return key


class LineKey:
    """A line through C.  ``value`` is the exact key of :mod:`.polygon` (the turn of the
    line in [0, 1/2), or the ray (sign x, y/x) of its doubled angle), ``h`` a canonical
    hashable form of it; both are computed on demand only (the Cartesian value divides,
    and an inverse in a cyclotomic field of degree hundreds costs a second).  Equality
    and hashing use ``canon``: the polar value's key, or :func:`ray_key` of the doubled
    angle's vector (the signs of its unit vector and its squared x coordinate): equal iff
    the lines are equal, with no division but by a squared length
    (:func:`line_key`, :func:`bisector_key`)."""

    __slots__ = ("canon", "_value", "_vector_", "_make", "_text")

    def __init__(self, canon, value=None, vector=None, make=None):
        self.canon = canon
        self._value = value
        self._vector_ = vector
        self._make = make          # vector=None, make=f: the vector is f(), made when read
        self._text = None

    @property
    def _vector(self):
        """The doubled direction (exact), made on first read when it was left lazy
        (:func:`bisector_key`, :func:`line_key`: the key itself needs no product)."""
        if self._vector_ is None and self._make is not None:
            self._vector_, self._make = self._make(), None
        return self._vector_

    @classmethod
    def of(cls, value) -> "LineKey":
        """The key of a line given by its :mod:`.polygon` value (a turn, or (sign, slope))."""
        if isinstance(value, tuple):
            s, v = value
            vector = (s, s * v) if s else (0 * v, v)
            return cls(line_canon(vector), value, vector)
        return cls(hashable_key(value), value)

    @property
    def value(self):
        if self._value is None:
            # one division per line, not per key object: equal keys have one value
            slot = self._slot()
            values = _LINE_VALUES.table()
            known = values.get(slot)
            if known is None:
                if len(values) >= _LINE_LIMIT:
                    values.clear()
                known = values[slot] = [ray_value(*self._vector), None]
            self._value = known[0]
        return self._value

    def _slot(self) -> tuple:
        """The key of this line's entry in the value cache: the line and the number
        fields of its vector (objects, compared by identity), so a value is shared only
        by keys of one configuration's numbers, never across inputs checked in one
        process (equal lines of two fields are printed in each field's terms)."""
        return (tuple(_number_home(c) for c in self._vector), self)     # fields first

    def display_key(self):
        """The order in which lines are shown: by the value (a turn; or ``(sign, slope)``,
        the vertical doubled direction as ``(0, 0)``), compared without dividing for a
        Cartesian line (:class:`_Slope`): in a field of degree thousands one slope costs
        seconds to divide.  A line whose doubled direction is not made yet is ordered by
        the balls of its two factors, and if they never separate by the positive multiple
        of it its short text is written from (:meth:`_short_parts`: the same sign and
        slope, numbers of a few bits per coefficient)."""
        if self._vector_ is None:
            key = self._direction_key()
            if key is not None:
                # ordered from the balls of its two factors; only if they never separate,
                # the exact product: of the short forms when known (sorting a G_ij's
                # lines made a product per line where 8 are shown), else a b itself
                def direction():
                    parts = self._short_parts()
                    return key.vector() if parts is None else parts[1:]
                return (key.signs[0], _Slope(None, None, key.factors, direction))
        if self._vector is None:
            return self.value
        x, y = self._vector
        s = sign(x)
        return (s, _Slope(x, y)) if s else (0, 0)

    @property
    def text(self) -> str:
        """The value as :mod:`exactsym.paper.family` prints it (a turn, or ``(sign,
        slope)``), written once per line: in a field of degree thousands the text of a
        slope is a megabyte and the claims print each line several times.  In a field of
        degree >= :data:`~exactsym.exact.number.LARGE_DEGREE` the slope is written as the quotient ``(Y)/(X)``
        of the doubled direction, undivided (exact; it reads back as the same number)."""
        if self._text is None and self._value is None:
            short = self._short_text()
            if short is not None:
                self._text = short
        if self._text is None and self._value is None and self._vector is not None and \
                slow_quotient(*self._vector):
            x, y = self._vector
            s = sign(x)
            self._text = f"(0, {sign(y)})" if not s else f"({s}, 0)" if y == 0 else \
                f"({s}, ({number_text(y)})/({number_text(x)}))"
        if self._text is None:
            value = self.value
            known = _LINE_VALUES.table().get(self._slot()) if self._vector is not None else None
            if known is None or known[0] is not value:     # the text of this very value
                known = [value, None]
            if known[1] is None:
                known[1] = line_value_text(value)
            self._text = known[1]
        return self._text

    def _direction_key(self):
        """The :class:`_DirectionKey` of a line whose doubled direction is the product of
        two factors, or None."""
        key = self.canon[3] if isinstance(self.canon, tuple) and len(self.canon) == 4 \
            else None
        return key if isinstance(key, _DirectionKey) and key.factors is not None else None

    def _short_parts(self):
        """``(sign, X', Y')``: a positive multiple of this line's doubled direction made
        from the homogeneous forms of the two directions it is the product of
        (:mod:`.homogeneous`: the same slope, numbers of a few bits per coefficient where
        the product's have thousands of digits), or None."""
        key = self._direction_key()
        found = None if key is None else line_direction(key.factors)
        return None if found is None else (key.signs[0],) + found

    def _short_text(self):
        """``(sign, slope)`` with the slope written from the homogeneous forms
        (:func:`.homogeneous.slope_text`), or None."""
        key = self._direction_key()
        text = None if key is None else slope_text(key.factors)
        return None if text is None else f"({key.signs[0]}, {text})"

    def screen_text(self) -> str:
        """:attr:`text`, except a slope written as a quotient whose exact text would be
        megabytes: then its decimal and the estimated length
        (:func:`exactsym.exact.text_numbers.huge_quotient`), what the text summary shows,
        without writing the text; and a long slope of a sparse Q(zeta_N), by its decimal
        and length (:func:`exactsym.exact.text_numbers.number`)."""
        shown = self._factor_decimal() if self._value is None else None
        if shown is not None:               # a tower over the sparse Q(zeta_N): no product
            return shown
        parts = self._short_parts() if self._value is None else None
        if parts is not None:
            text = self.text                        # the short exact text
            if len(text) <= LONG:
                return text
            s, x, y = parts
            return f"({s}, ≈ {quotient_decimal(y, x)} (exact: {len(text)} characters, " \
                "in --json))"
        if (self._text is None or len(self._text) > HUGE) and self._value is None and \
                self._vector is not None and slow_quotient(*self._vector):
            x, y = self._vector
            s = sign(x)
            shown = huge_quotient(y, x) if s else None
            if shown is not None:
                return f"({s}, {shown})"
        text = self.text
        if len(text) > LONG and self._value is None and self._vector is not None and \
                any(kummer_tower(c)
                    for c in self._vector) and sign(self._vector[0]):
            # a tower of square roots over a large or sparse cyclotomic field: the undivided
            # quotient's decimal (the division costs seconds there)
            x, y = self._vector
            return f"({sign(x)}, ≈ {quotient_decimal(y, x)} (exact: {len(text)} " \
                "characters, in --json))"
        if len(text) > LONG and isinstance(self.value, tuple) and \
                is_sparse(self.value[1]):
            value = self.value
            # a sum of hundreds of cosines, which the summary would not read back
            return f"({value[0]}, {number(value[1])})"
        return text

    def _factor_decimal(self) -> str | None:
        """The screen text of a line of a tower over a sparse or large cyclotomic field
        whose doubled direction a b is not made: its slope's decimal from the balls of
        the two factors (the product is a tower multiplication of seconds, and its exact
        text, megabytes, would not be shown), or None."""
        key = self._direction_key() if self._vector_ is None else None
        if key is None:
            return None
        (a, b), prec = key.factors, 64
        if not any(kummer_tower(c)
                   for c in a + b):
            return None
        while prec <= 4096:
            with ctx.workprec(prec + 16):
                ax, ay, bx, by = (ball_at(v, prec) for v in (a[0], a[1], b[0], b[1]))
                slope = (ax * by + ay * bx) / (ax * bx - ay * by)
                if slope.is_finite() and slope.rad() < abs(slope.mid()) * 1e-9 + 1e-30:
                    return f"({key.signs[0]}, ≈ {slope.str(DIGITS, radius=False)} " \
                        "(exact: in --json))"
            prec *= 4
        return None

    @property
    def h(self):
        return hashable_key(self.value)

    def __eq__(self, other):
        return isinstance(other, LineKey) and self.canon == other.canon

    def __hash__(self):       # as the frozen dataclass this class was: set orders unchanged
        return hash((self.canon,))

    def __repr__(self) -> str:
        return f"LineKey({self.value!r})"


_LINE_VALUES = Cache("line values")     # (LineKey, fields) -> [value, text or None]

class _Slope:
    """The slope y/x (x != 0) of a line's doubled direction, ordered without dividing:
    Arb balls at rising precision (distinct lines have distinct slopes), and if they
    never separate, the exact sign of y x' - y' x over sign(x x')."""

    __slots__ = ("x", "y", "_factors", "_make")

    def __init__(self, x, y, factors=None, make=None):
        """``factors`` (a, b) and ``make``: the direction is the complex product a b, made
        by ``make()`` only if the balls never separate (its balls come from a's and b's)."""
        self.x, self.y, self._factors, self._make = x, y, factors, make

    def _ball(self, prec: int):
        with ctx.workprec(prec):
            if self.x is None:
                (ax, ay), (bx, by) = ([ball_at(c, prec) for c in v] for v in self._factors)
                return (ax * by + ay * bx) / (ax * bx - ay * by)
            return ball_at(self.y, prec) / ball_at(self.x, prec)

    def _exact(self) -> tuple:
        if self.x is None:
            self.x, self.y = self._make()
        return self.x, self.y

    def _cmp(self, other) -> int:
        prec = 64
        for _ in range(4):
            a, b = self._ball(prec), other._ball(prec)
            if a < b:
                return -1
            if a > b:
                return 1
            prec *= 4
        (x, y), (ox, oy) = self._exact(), other._exact()
        return sign(y * ox - oy * x) * sign(x) * sign(ox)

    def __lt__(self, other) -> bool:
        return self._cmp(other) < 0

    def __gt__(self, other) -> bool:
        return self._cmp(other) > 0

    def __eq__(self, other) -> bool:
        return isinstance(other, _Slope) and self._cmp(other) == 0

    __hash__ = None


def _number_home(x):
    """The object a number's exact key names (its field or tower), or its type."""
    home = getattr(x, "field", None)
    if home is None:
        home = getattr(x, "tower", None)
    return home if home is not None else type(x).__name__
_LINE_LIMIT = 4096


def line_value_text(k) -> str:
    """The text of a line value (a turn, or ``(sign, slope)``)."""
    return number_text(k) if not isinstance(k, tuple) else \
        f"({k[0]}, {number_text(k[1]) if not isinstance(k[1], int) else k[1]})"


def line_canon(doubled) -> tuple:
    """:attr:`LineKey.canon` of the Cartesian line whose doubled angle has direction
    ``doubled`` (a non-zero exact vector)."""
    return ("line",) + ray_key(False, doubled)


def line_key(polar: bool, d) -> LineKey:
    """The :class:`LineKey` of the line through C with direction d (no division)."""
    if polar:
        return LineKey.of(line_value(True, d))
    return _product_line(d, d)


def bisector_key(polar: bool, a, b) -> LineKey:
    """The :class:`LineKey` of :func:`bisector_line` (no division)."""
    if polar:
        return LineKey.of(bisector_line(True, a, b))
    return _product_line(a, b)


_PRODUCT_LINES = Cache("product lines")   # (id(a), id(b)) -> (a, b, key): one per pair


def _product_line(a, b) -> LineKey:
    """The key of the line whose doubled angle has the direction of the complex product
    a b = (a_x b_x - a_y b_y, a_x b_y + a_y b_x) (a == b: the line along a).  In a large
    cyclotomic field the key is made without that product when filters settle it
    (:func:`lazy_line_canon`); the product is then made only if the line's value, text or
    an exact equality asks for it.  One key per pair of vector objects (the entry keeps
    them, so an id is not reused): the line of a lone vertex, its mirror, is the line of
    its direction, and two keys made apart were equal only by exact products, minutes in
    a tower over the sparse base with a centre of thousands of terms."""
    lines = _PRODUCT_LINES.table()
    hit = lines.get((id(a), id(b)))
    if hit is not None and hit[0] is a and hit[1] is b:
        return hit[2]
    key = _made_product_line(a, b)
    if len(lines) >= 1 << 14:
        lines.clear()
    lines[(id(a), id(b))] = (a, b, key)
    return key


def _made_product_line(a, b) -> LineKey:
    def make():
        return complex_product(a, b)
    canon = lazy_line_canon(a, b, make)
    if canon is not None:
        return LineKey(canon, None, None, make)
    forms = homogeneous_pair(a, b)
    if forms is not None:       # the same line from positive multiples of a and b
        return LineKey(line_canon(complex_product(*forms)), None, None, make)
    prod = make()
    return LineKey(line_canon(prod), None, prod)


def complex_product(a, b) -> tuple:
    """(a_x b_x - a_y b_y, a_x b_y + a_y b_x), exact, with three products (Gauss; two
    for a square: (x - y)(x + y), 2 x y): in a field of degree thousands a product costs
    milliseconds, a sum microseconds."""
    if a is b:
        x, y = a
        return ((x - y) * (x + y), 2 * (x * y))
    return fused_complex_product(a, b)      # the shared product reduced in both sums


def lazy_line_canon(a, b, make):
    """:func:`line_canon` of the product ``make() == a b`` (complex product of two exact
    vectors) without making it, or None.  Applies when a coordinate lies in a cyclotomic
    field of degree >= :data:`~exactsym.exact.number.LARGE_DEGREE`: the signs of the product's coordinates come
    from Arb balls built from the balls of a and b (they decide only when they exclude
    zero), and x^2 / (x^2 + y^2) must be proved irrational by two embeddings into F_p
    (:func:`exactsym.exact.cyclotomic_modular.product_ratio_irrational`); then the key is
    the :class:`RatioKey` :func:`ray_key` would make (same value, same hash cell), whose
    exact parts are made from ``make()`` only when an equality needs them."""
    numbers = (a[0], a[1], b[0], b[1])
    if not huge_field(*numbers):
        return None
    ax, ay, bx, by = (ball(v) for v in numbers)
    sx = ball_sign(ax * bx - ay * by)
    sy = ball_sign(ax * by + ay * bx)
    if not sx or not sy or not product_ratio_irrational(a, b):
        return None
    made = []

    def vector():
        if not made:
            made.append(make())
        return made[0]

    def parts():
        x, y = vector()
        xx = x * x
        return xx, xx + y * y

    def value_ball(prec):
        ax, ay, bx, by = (ball_at(v, prec) for v in numbers)
        x, y = ax * bx - ay * by, ax * by + ay * bx
        sq = x * x
        return sq / (sq + y * y)
    return ("line", sx, sy, _DirectionKey(sx, sy, vector, parts, value_ball,
                                          largest_field(numbers), (a, b)))


class _DirectionKey(RatioKey):
    """The :class:`RatioKey` of x^2 / (x^2 + y^2) for a vector (x, y) = ``vector()`` whose
    coordinate signs ``sx``, ``sy`` (non-zero) are known: two such keys with equal signs
    are equal iff the vectors have one direction, i.e. iff x y' - y x' == 0 (two products
    of the vectors' coordinates, not two of their squares).  Against any other
    RatioKey, the RatioKey comparison (which reads ``parts``).  ``factors``: the two
    vectors (a, b) whose complex product ``vector()`` is: keys of the same factors (the
    same objects, in either order) are equal without a product (a 1-gon's mirror and
    the line through its vertex are both made from its direction)."""

    __slots__ = ("signs", "vector", "factors")

    def __init__(self, sx: int, sy: int, vector, parts, value_ball, home, factors=None):
        self.signs, self.vector, self.factors = (sx, sy), vector, factors
        super().__init__(parts, value_ball, home)

    def __eq__(self, other) -> bool:
        if self is other:
            return True
        if not isinstance(other, _DirectionKey):
            return super().__eq__(other)
        if self._hash != other._hash or self.home is not other.home \
                or self.signs != other.signs:
            return False
        if _same_factors(self.factors, other.factors):
            return True
        (x, y), (x2, y2) = self.vector(), other.vector()
        # equal signs: x^2/|v|^2 == x2^2/|v2|^2 iff the unit vectors are equal
        return cross_is_zero((x, y), (x2, y2))

    def __ne__(self, other) -> bool:
        return not self.__eq__(other)

    def __hash__(self) -> int:
        return self._hash


def _same_factors(f, g) -> bool:
    """Whether the factor pairs (a, b), (a', b') of two complex products hold the same
    vectors, in either order (a product commutes): vectors are the same when they are one
    object or their coordinates are (numbers are immutable)."""
    if f is None or g is None:
        return False
    (a, b), (c, d) = f, g
    return (_same_vector(a, c) and _same_vector(b, d)) or \
        (_same_vector(a, d) and _same_vector(b, c))


def _same_vector(u, v) -> bool:
    return u is v or (u[0] is v[0] and u[1] is v[1])


def line_value(polar: bool, d):
    """The key of the line through C with direction d (as :mod:`.polygon` keys lines)."""
    if polar:
        t = normal_turn(d)
        return t - HALF if t >= HALF else t
    x, y = d
    return ray_value(x * x - y * y, 2 * x * y)


def ray_value(x, y):
    """:mod:`.polygon`'s key of the ray of direction (x, y): (sign x, y/x) or (0, sign y)."""
    if sign(x) != 0:
        return (sign(x), y / x)
    return (0, sign(y))


def bisector_line(polar: bool, a, b):
    """Key of the line through C bisecting directions a and b (the mirror a <-> b)."""
    if polar:
        return line_value(True, (a + b) / 2)
    prod = (a[0] * b[0] - a[1] * b[1], a[0] * b[1] + a[1] * b[0])   # doubled angle
    return ray_value(*prod)


def integer_directions(dirs):
    """Rational direction vectors of one length, times one positive integer: int pairs
    of one length (rays, lines and angles unchanged; cheap exact arithmetic without
    division), or None when a coordinate is not an fmpq or the lengths differ.  The
    integer is the least common multiple of the coordinates' denominators."""
    parts = []
    for x, y in dirs:
        if type(x) is not fmpq or type(y) is not fmpq:
            if not all_plain_rational((x, y)):      # (an fmpq subclass is one too)
                return None
        parts.append((int(x.p), int(x.q), int(y.p), int(y.q)))
    den = lcm(*[q for _, qx, _, qy in parts for q in (qx, qy)])
    out = [(px * (den // qx), py * (den // qy)) for px, qx, py, qy in parts]
    x0, y0 = out[0]
    r2 = x0 * x0 + y0 * y0
    for x, y in out:
        if x * x + y * y != r2:
            return None
    return out


def polygon_integer_directions(poly: CirclePolygon):
    """:func:`integer_directions` of ``poly``'s directions, computed once per polygon
    (kept in its ``__dict__``; the family layer's polygon of a level takes it from the
    polygon layer's, which has the same directions: issue 9, no repeated work)."""
    cached = poly.__dict__.get("integer_vectors", False)
    if cached is False:
        cached = poly.__dict__["integer_vectors"] = integer_directions(poly.directions)
    return cached


def integer_gap_key(a, b) -> tuple:
    """For int vectors a, b of one length: a key equal for equal counter-clockwise
    angles from a to b and increasing with it, (class, value) with class 0 below half a
    turn, 1 half a turn, 2 above, 3 a full turn (a == b)."""
    c = a[0] * b[1] - a[1] * b[0]
    d = a[0] * b[0] + a[1] * b[1]
    if c > 0:
        return (0, -d * abs(d))
    if c < 0:
        return (2, d * abs(d))
    return (1, 0) if d < 0 else (3, 0)


def gap_ids(poly: CirclePolygon) -> list:
    """Small integers, equal iff the counter-clockwise gaps between consecutive vertices
    are equal (exact), numbered in order of first occurrence.  Of integer directions
    (:func:`polygon_integer_directions`) computed once per polygon and kept in its
    ``__dict__`` (``"gap_ids"``; the polygon layer's combinatorial key stores the same
    list, and the family layer's polygon of a level takes it: issue 33, one gap key per
    edge); the list is shared: do not modify it."""
    n, dirs = poly.n, poly.directions
    ids: dict = {}
    if not poly.polar and n > 1:
        cached = poly.__dict__.get("gap_ids")
        if cached is not None:
            return cached
        u = polygon_integer_directions(poly)
        if u is not None:
            out = poly.__dict__["gap_ids"] = [
                ids.setdefault(integer_gap_key(u[i], u[(i + 1) % n]), len(ids))
                for i in range(n)]
            return out
        if poly.one_circle:
            # one circle: the gaps are told apart by the sign of the cross product and
            # the dot product, filtered by balls (exact products only for near ties)
            return [ids.setdefault(t, len(ids)) for t in gap_classes_on_circle(dirs)]
    if not poly.polar and any_algebraic(c for d in dirs for c in d):
        # algebraic: the gap keys held undivided (equal iff equal), told apart by balls;
        # exact products only for gaps in one hash cell (a field inverse costs up to a
        # second at degree thousands, tower products a millisecond each)
        return [ids.setdefault(gap_equality_key(dirs[i], dirs[(i + 1) % n]), len(ids))
                for i in range(n)]
    return [ids.setdefault(hashable_key(ccw_gap_key(poly.polar, dirs[i], dirs[(i + 1) % n])),
                           len(ids)) for i in range(n)]


def gap_equality_key(a, b):
    """A hashable key of :func:`ccw_gap_key` (Cartesian), equal iff those keys are equal,
    with no inverse (:func:`exactsym.paper.ratio_keys.gap_ratio_key`)."""
    c, s = cross_sign(a, b), dot_sign(a, b)        # both ball-filtered
    if c == 0:
        return (1, 0) if s < 0 else (3, 0)
    forms = homogeneous_pair(a, b)          # the same angle, from short numbers
    return gap_ratio_key(*(forms or (a, b)), c, s)


def circle_line_keys(poly: CirclePolygon):
    """``(vertex_keys, edge_keys)``: hashable keys of the lines through C of the vertices
    and of the edge points (the edge's midpoint direction, or the perpendicular of a
    diameter edge), equal iff the lines are equal, without a division: for a Cartesian
    polygon on one circle of radius r, the line of v is the ray of v^2 (complex square:
    its doubled angle) and the line of the edge point of (a, b) the ray of a b (the
    doubled angle of the arc's bisector; (a + b)^2 = a b (2 + 2 Re(a conj b) / r^2) is a
    positive multiple of it, and for a diameter a b = -a^2 is the perpendicular's
    square); all have length r^2, so equal rays are equal vectors.  None for polar
    polygons or directions of different lengths (use :func:`line_value`)."""
    if poly.polar or not poly.one_circle:
        return None
    dirs, n = poly.directions, poly.n
    vertex = [(exact_key(x * x - y * y), exact_key(2 * x * y)) for x, y in dirs]
    edge = []
    for i in range(n):
        (ax, ay), (bx, by) = dirs[i], dirs[(i + 1) % n]
        edge.append((exact_key(ax * bx - ay * by), exact_key(ax * by + ay * bx)))
    return vertex, edge


def sort_by_angle(dirs: list) -> None:
    """Sort non-zero exact vectors in place by their angle in [0, 2 pi) from the +x ray
    (as :func:`angle_order_key`, which it equals on distinct rays), without a division:
    rationals by :func:`angle_order_key` (a rational division is cheap); algebraic
    vectors by a float proposal whose adjacent pairs are then checked exactly
    (:func:`exactsym.paper.filtered.compare_directions`, a cross product), falling back to an
    exact comparison sort when a check fails: the float only proposes."""
    if all_plain_rational(c for d in dirs for c in d):
        dirs.sort(key=angle_order_key)
        return
    try:
        proposal = sorted(dirs, key=_float_angle)
    except (OverflowError, ValueError, ZeroDivisionError):
        proposal = None
    if proposal is not None and all(compare_directions(a, b) < 0
                                    for a, b in zip(proposal, proposal[1:])):
        dirs[:] = proposal
        return
    dirs.sort(key=cmp_to_key(compare_directions))


def _float_angle(d) -> float:
    a = atan2(float(d[1]), float(d[0]))
    return a if a >= 0 else a + 2 * pi


def angle_order_key(d):
    """An exact key increasing with the angle of the vector d in [0, 2 pi) from the +x
    ray (the order of :func:`.circle_polygon.polygon_from_directions`)."""
    x, y = d
    sy = sign(y)
    if sy > 0:
        return (1, -x / y)
    if sy < 0:
        return (3, -x / y)
    return (0, 0) if sign(x) > 0 else (2, 0)
