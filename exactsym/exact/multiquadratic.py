"""Sparse elements of multiquadratic fields Q(sqrt(a1), sqrt(a2), ...).

An element is ``sum c_m * sqrt(m)`` over squarefree positive integers ``m``
(``m = 1`` is the rational part) with non-zero ``fmpq`` coefficients.  The square
roots of distinct squarefree integers are linearly independent over Q, so this
sparse form is canonical: equality and zero are exact dictionary comparisons, and
no minimal polynomial or primitive element is ever built.  Products use
``sqrt(a) sqrt(b) = g sqrt(ab / g^2)`` with ``g = gcd(a, b)``; inverses multiply
by conjugates; the sign is decided by a float filter with a proven error bound,
then Arb balls at rising precision, never from a ball that contains zero (a
non-zero element has a non-zero value, so the loop ends).

Used by the gathering simulator (``docs/gathering.md``): a robot placed at radius
``2L`` along a rational direction lies in ``Q(sqrt(r))``, a slot of layer ``L`` in
``Q(sqrt(r), sqrt(4L^2 - 1))``, and predicates between robots in the compositum,
a field of small degree whose elements have few terms.

Public names: :class:`MQ`, :func:`mq`, :func:`sqrt_rational`, :func:`squarefree_split`.
"""

from __future__ import annotations

from functools import lru_cache
from math import gcd, lcm

from flint import arb, ctx, fmpq, fmpz, fmpz_poly

from ..io.exprtree import BinOp, Const, Neg, Node, Pow, Sqrt
from .factor import factorization
from .field import FieldElement

_ULP = 2.0 ** -52
_MAX_PREC = 1 << 16


@lru_cache(maxsize=65536)
def squarefree_split(n: int) -> tuple[int, int]:
    """``(s, m)`` with ``n == s*s*m``, ``m`` squarefree, for an integer ``n >= 1``."""
    if n < 1:
        raise ValueError("squarefree_split needs a positive integer")
    s, m = 1, 1
    for p, e in factorization(n).items():
        s *= p ** (e // 2)
        if e % 2:
            m *= p
    return s, m


def _as_fmpq(x) -> fmpq:
    if isinstance(x, fmpq):
        return x
    if isinstance(x, (int, fmpz)):
        return fmpq(x)
    num, den = getattr(x, "numerator", None), getattr(x, "denominator", None)
    if num is not None and den is not None:
        return fmpq(int(num), int(den))
    raise TypeError(f"not a rational: {type(x).__name__}")


class _Rational:
    """``MQ.rational(q)`` builds the element q; ``x.rational()`` is the kernel's name
    (:class:`~.field.FieldElement`) for the value of a rational element ``x``."""

    def __get__(self, obj, cls):
        return cls.from_rational if obj is None else obj.to_fmpq


def _coerced(other):
    """``other`` as an :class:`MQ` (a rational is coerced), or None for a foreign type."""
    if isinstance(other, MQ):
        return other
    try:
        return MQ.rational(other)
    except TypeError:
        return None


class MQ(FieldElement):
    """An element of a multiquadratic field: ``{squarefree radicand: fmpq}``.

    Immutable by convention (the dictionary is never changed after construction).
    Arithmetic with ``int``, ``fmpq`` and ``Fraction`` operands is accepted.
    """

    __slots__ = ("terms", "_hash", "_ints")

    def __init__(self, terms: dict | None = None):
        # ``terms`` must already be canonical: squarefree keys, non-zero fmpq values.
        self.terms = terms if terms is not None else {}
        self._hash = None
        self._ints = None       # the integer form of :func:`_integers`, once asked for

    def __getstate__(self):     # a pickle or copy carries the terms, not the caches
        return self.terms

    def __setstate__(self, terms):
        self.__init__(terms)

    # -- construction -------------------------------------------------------
    @staticmethod
    def from_rational(q) -> "MQ":
        q = _as_fmpq(q)
        return MQ({1: q} if q != 0 else {})

    rational = _Rational()

    @staticmethod
    def sqrt(q) -> "MQ":
        """The non-negative square root of a non-negative rational ``q``."""
        return sqrt_rational(q)

    @staticmethod
    def coerce(x) -> "MQ":
        return x if isinstance(x, MQ) else MQ.rational(x)

    # -- inspection ---------------------------------------------------------
    def is_zero(self) -> bool:
        return not self.terms

    def is_rational(self) -> bool:
        return not self.terms or (len(self.terms) == 1 and 1 in self.terms)

    def to_fmpq(self) -> fmpq:
        """The rational value; ``ValueError`` if the element is irrational."""
        if not self.is_rational():
            raise ValueError(f"{self} is not rational")
        return self.terms.get(1, fmpq(0))

    def radicands(self) -> tuple[int, ...]:
        return tuple(sorted(m for m in self.terms if m != 1))

    def coefficient(self, m: int) -> fmpq:
        return self.terms.get(m, fmpq(0))

    # -- arithmetic ---------------------------------------------------------
    def __add__(self, other):
        if type(other) is not MQ:
            other = _coerced(other)
            if other is None:
                return NotImplemented
        if not other.terms:
            return self
        if not self.terms:
            return other
        out = dict(self.terms)
        for m, c in other.terms.items():
            v = out.get(m)
            if v is None:
                out[m] = c
            else:
                v = v + c
                if v == 0:
                    del out[m]
                else:
                    out[m] = v
        return MQ(out)

    __radd__ = __add__

    def __neg__(self):
        return MQ({m: -c for m, c in self.terms.items()})

    def __pos__(self):
        return self

    def __sub__(self, other):
        other = _coerced(other)
        if other is None:
            return NotImplemented
        return self + (-other)

    def __rsub__(self, other):
        return (-self) + other

    def __mul__(self, other):
        if type(other) is not MQ:
            if not isinstance(other, MQ):
                try:
                    q = _as_fmpq(other)
                except TypeError:
                    return NotImplemented
                if q == 0:
                    return MQ()
                return MQ({m: c * q for m, c in self.terms.items()})
        a, b = self.terms, other.terms
        if not a or not b:
            return MQ()
        la, lb = len(a), len(b)
        if lb == 1 and 1 in b:
            q = b[1]
            return MQ({m: c * q for m, c in a.items()})
        if la == 1 and 1 in a:
            q = a[1]
            return MQ({m: c * q for m, c in b.items()})
        if la * lb >= _INTEGER_PRODUCT:
            return MQ(_integer_product(self, other))
        return MQ(_rational_product(a, b))     # few terms

    __rmul__ = __mul__

    def conjugate(self, base: int) -> "MQ":
        """Image under the automorphism ``sqrt(m) -> -sqrt(m)`` when ``base | m`` an odd
        number of times in a coprime factorisation (``base`` from :func:`coprime_base`)."""
        return MQ({m: (-c if m % base == 0 else c) for m, c in self.terms.items()})

    def inverse(self) -> "MQ":
        """``1 / self`` by conjugation: each step multiplies by the conjugate that flips one
        element of a coprime base of the radicands, which removes that element.  An
        element of many terms has its inverse remembered by value (k products of up to
        2^k terms; a leading coefficient is inverted again at each division by it)."""
        if not self.terms:
            raise ZeroDivisionError("inverse of zero")
        if len(self.terms) >= _REMEMBERED_INVERSE:
            return _inverse_of(self)
        return self._inverse()

    def _inverse(self) -> "MQ":
        num = MQ.rational(1)
        x = self
        while not x.is_rational():
            base = coprime_base(x.radicands())
            b = next(p for p in base if any(m % p == 0 for m in x.terms if m != 1))
            conj = x.conjugate(b)
            num = num * conj
            x = x * conj
        return num * (1 / x.terms[1])

    def __truediv__(self, other):
        if not isinstance(other, MQ):
            try:
                q = _as_fmpq(other)
            except TypeError:
                return NotImplemented
            if q == 0:
                raise ZeroDivisionError("division by zero")
            return MQ({m: c / q for m, c in self.terms.items()})
        if other.is_rational():
            return self / other.to_fmpq()
        return self * other.inverse()

    def __rtruediv__(self, other):
        return MQ.coerce(other) * self.inverse()

    def _one(self):
        return MQ.rational(1)

    # -- equality, hash, sign ----------------------------------------------
    def __eq__(self, other):
        other = _coerced(other)
        if other is None:
            return NotImplemented
        return self.terms == other.terms

    def __hash__(self):
        if self._hash is None:
            if self.is_rational():
                self._hash = hash(self.to_fmpq())   # equal to the rational it equals
            else:
                self._hash = hash(frozenset(self.terms.items()))
        return self._hash

    def sign(self) -> int:
        """-1, 0 or 1, exactly."""
        t = self.terms
        if not t:
            return 0
        if len(t) == 1:
            (c,) = t.values()
            return 1 if c > 0 else -1
        signs = {c > 0 for c in t.values()}
        if len(signs) == 1:
            return 1 if signs.pop() else -1
        s = _float_sign(t)
        return s if s is not None else _arb_sign(t)

    def __lt__(self, other):
        return (self - other).sign() < 0

    def __le__(self, other):
        return (self - other).sign() <= 0

    def __gt__(self, other):
        return (self - other).sign() > 0

    def __ge__(self, other):
        return (self - other).sign() >= 0

    def __bool__(self):
        return bool(self.terms)

    def __abs__(self):
        return -self if self.sign() < 0 else self

    # -- conversions --------------------------------------------------------
    def to_arb(self, prec: int = 53) -> arb:
        old = ctx.prec
        ctx.prec = prec
        try:
            total = arb(0)
            for m, c in self.terms.items():
                total += arb(c.p) / arb(c.q) * _sqrt_arb(m)
            return total
        finally:
            ctx.prec = old

    def enclosure(self, prec: int = 53) -> arb:
        """An ``arb`` ball around the value (the kernel's name, for filters and drawing)."""
        return self.to_arb(prec)

    def __float__(self):
        """An approximation for drawing and float baselines; decides nothing."""
        return float(sum(float(c) * (m ** 0.5) for m, c in self.terms.items()))

    def text(self) -> str:
        """The value in the configuration expression syntax (``3/4*sqrt(6) - 1/2``):
        parsing it with :func:`exactsym.io.expr.parse_expression` and :func:`from_tree`
        gives back this element."""
        if not self.terms:
            return "0"
        parts = []
        for m in sorted(self.terms):
            c = self.terms[m]
            neg = c < 0
            mag = -c if neg else c
            if m == 1:
                body = str(mag.p) if mag.q == 1 else f"{mag.p}/{mag.q}"
            else:
                root = f"sqrt({m})"
                if mag == 1:
                    body = root
                elif mag.q == 1:
                    body = f"{mag.p}*{root}"
                elif mag.p == 1:
                    body = f"{root}/{mag.q}"
                else:
                    body = f"{mag.p}/{mag.q}*{root}"
            if not parts:
                parts.append(f"-{body}" if neg else body)
            else:
                parts.append(f" - {body}" if neg else f" + {body}")
        return "".join(parts)

    __str__ = text

    def __repr__(self):
        return f"MQ({self.text()!r})"


#: terms from which an inverse is remembered (:func:`_inverse_of`)
_REMEMBERED_INVERSE = 8


@lru_cache(maxsize=256)
def _inverse_of(x: MQ) -> MQ:
    """``x.inverse()`` by value: the inverse is a function of the (canonical) value."""
    return x._inverse()


def mq(x) -> MQ:
    """Coerce an ``int``, ``fmpq``, ``Fraction`` or :class:`MQ` to :class:`MQ`."""
    return MQ.coerce(x)


def sqrt_rational(q) -> MQ:
    """``sqrt(q)`` for a rational ``q >= 0``: ``sqrt(p/r) = s/r * sqrt(m)`` with
    ``p*r = s^2 m`` and ``m`` squarefree."""
    q = _as_fmpq(q)
    if q < 0:
        raise ValueError("square root of a negative rational")
    if q == 0:
        return MQ()
    p, r = int(q.p), int(q.q)
    s, m = squarefree_split(p * r)
    return MQ({m: fmpq(s, r)})


def from_tree(node: Node) -> MQ:
    """Evaluate an expression tree (:mod:`exactsym.io.exprtree`) built from rationals,
    ``+ - * /``, integer powers and square roots of non-negative rationals.
    Raises ``ValueError`` for anything else (``cos``, ``pi``, nested radicals)."""
    if isinstance(node, Const):
        return MQ.rational(node.value)
    if isinstance(node, Neg):
        return -from_tree(node.arg)
    if isinstance(node, BinOp):
        a, b = from_tree(node.left), from_tree(node.right)
        if node.op == "+":
            return a + b
        if node.op == "-":
            return a - b
        if node.op == "*":
            return a * b
        if node.op == "/":
            return a / b
        raise ValueError(f"operator {node.op!r} is not supported")
    if isinstance(node, Pow):
        return from_tree(node.base) ** int(node.exponent)
    if isinstance(node, Sqrt):
        arg = from_tree(node.arg)
        if not arg.is_rational():
            raise ValueError("nested radicals are not multiquadratic")
        return sqrt_rational(arg.to_fmpq())
    raise ValueError(f"{type(node).__name__} is not multiquadratic")


#: term pairs above which a product may go through the dense Kronecker product (3^k steps)
_DENSE_PRODUCT = 64

#: (m1, m2) -> (m, g) with sqrt(m1) sqrt(m2) = g sqrt(m), for squarefree m1, m2
_PAIRS: dict = {}
_PAIRS_MAX = 1 << 20


#: ... when the pairs are at least this many times 3^k (the Kronecker product's slots):
#: its conversions and reduction cost more per slot than a pair of the integer product
_DENSE_RATIO = 4

#: term pairs from which the product runs over integers (:func:`_product_integers`)
_INTEGER_PRODUCT = 16


def _rational_product(a: dict, b: dict) -> dict:
    """The product term by term: in ``fmpq`` each product and sum is made canonical (two
    gcds), cheap for small rationals only (the reference the other products are tested
    against); in ``fmpz`` (:func:`_product_integers`) the sums stay integers."""
    out: dict = {}
    pairs = _PAIRS
    for m1, c1 in a.items():
        for m2, c2 in b.items():
            # sqrt(m1) sqrt(m2) = g sqrt(m), cached: the same radicands meet again and again
            mg = pairs.get((m1, m2))
            if mg is None:
                mg = _radicand_product(m1, m2)
            m, g = mg
            c = c1 * c2 if g == 1 else c1 * c2 * g
            v = out.get(m)
            out[m] = c if v is None else v + c
    return {m: c for m, c in out.items() if c != 0}


def _integers(terms: dict, force: bool = False) -> tuple:
    """``({m: fmpz numerator}, den)``: the terms over their least common denominator;
    ``(None, den)`` when that denominator is much longer than the longest one (unrelated
    denominators: the numerators would grow by all of them), unless ``force``."""
    den, top = 1, 1
    for c in terms.values():
        q = int(c.q)
        if q != 1:
            den = lcm(den, q)
            top = max(top, q)
    if not force and den.bit_length() > 2 * top.bit_length() + 64:
        return None, den
    return {m: fmpz(c.p) * (den // int(c.q)) if c.q != 1 else fmpz(c.p) * den
            for m, c in terms.items()}, den


def _integers_of(x: "MQ") -> tuple:
    """:func:`_integers` of an element, kept on it (an element is never changed, and the
    same coordinate meets many products: a robot's distances to all the others)."""
    if x._ints is None:
        x._ints = _integers(x.terms)
    return x._ints


def _product_integers(x: "MQ", y: "MQ"):
    """``({m: fmpz}, den)`` with ``x y = sum v / den sqrt(m)`` (zero sums may be kept), or
    None when a factor's denominators are unrelated (:func:`_integers`).  Each factor is
    scaled to integers over its common denominator, and the term products are summed as
    integers: no gcd until the caller makes each sum canonical once
    (:func:`_canonical`), where the term-by-term product pays two gcds per pair -- on
    the coefficients of thousands of bits of the critical instants, 5 to 10 times less.
    A square (``y is x``) takes each unordered pair once; many pairs over few primes go
    through the Kronecker product (:func:`_dense_integers`).  The same value, radicand
    by radicand, as :func:`_rational_product`."""
    A, da = _integers_of(x)
    if A is None:
        return None
    square = y is x or y.terms is x.terms
    if square:
        B, db = A, da
    else:
        B, db = _integers_of(y)
        if B is None:
            return None
    la, lb = len(A), len(B)
    if la * lb > _DENSE_PRODUCT:
        base = _coprime_base_of(frozenset(A) | frozenset(B))
        if 3 ** len(base) * _DENSE_RATIO <= la * lb:
            return _dense_integers(A, B, base), da * db
    out: dict = {}
    pairs = _PAIRS
    if square:                  # c_i c_j sqrt(m_i m_j) twice for i < j, once for i = j
        items = list(A.items())
        for i, (m1, c1) in enumerate(items):
            c = c1 * c1 * m1 if m1 != 1 else c1 * c1
            v = out.get(1)
            out[1] = c if v is None else v + c
            c1 = c1 * 2
            for m2, c2 in items[i + 1:]:
                mg = pairs.get((m1, m2))
                if mg is None:
                    mg = _radicand_product(m1, m2)
                m, g = mg
                c = c1 * c2 if g == 1 else c1 * c2 * g
                v = out.get(m)
                out[m] = c if v is None else v + c
        return out, da * da
    return _rational_product(A, B), da * db


def _canonical(out: dict, den: int) -> dict:
    """``{m: v / den}`` for the non-zero sums ``v`` (each reduced once: one gcd)."""
    if den == 1:
        return {m: fmpq(v) for m, v in out.items() if v}
    den = fmpz(den)
    return {m: fmpq(v, den) for m, v in out.items() if v}


def _integer_product(x: "MQ", y: "MQ") -> dict:
    """``x y`` over integers (:func:`_product_integers`), term by term when it declines."""
    r = _product_integers(x, y)
    return _rational_product(x.terms, y.terms) if r is None else _canonical(*r)


def sum_of_products(items) -> MQ:
    """``sum s a b`` over ``(s, a, b)`` (``s`` an int, ``a``, ``b`` :class:`MQ`), made
    canonical once: a dot product or a cross product of two points pays one gcd per
    term of the result instead of one per term of each product and of their sum.  The
    same value (integers summed exactly over a common denominator), so the same
    element; small factors go the ordinary way."""
    items = list(items)
    if max((len(a.terms) * len(b.terms) for _, a, b in items), default=0) < _INTEGER_PRODUCT:
        return _plain_sum(items)
    parts = []
    for s, a, b in items:
        if not a.terms or not b.terms:
            continue
        r = _product_integers(a, b)
        if r is None:
            return _plain_sum(items)
        parts.append((s, r[0], r[1]))
    if not parts:
        return MQ()
    den = lcm(*[d for _, _, d in parts])
    out: dict = {}
    for s, part, d in parts:
        k = den // d * s
        for m, v in part.items():
            w = out.get(m)
            out[m] = v * k if w is None else w + v * k
    return MQ(_canonical(out, den))


def _plain_sum(items) -> MQ:
    out = MQ()
    for s, a, b in items:
        t = a * b
        out = out + t if s == 1 else out - t if s == -1 else out + t * s
    return out


def _radicand_product(m1: int, m2: int) -> tuple[int, int]:
    if m1 == m2:
        mg = (1, m1)
    else:
        g = gcd(m1, m2)
        mg = ((m1 // g) * (m2 // g), g)
    if len(_PAIRS) >= _PAIRS_MAX:
        _PAIRS.clear()
    _PAIRS[(m1, m2)] = mg
    return mg


@lru_cache(maxsize=1024)
def _coprime_base_of(radicands: frozenset) -> tuple[int, ...]:
    return tuple(sorted(coprime_base([m for m in radicands if m != 1])))


@lru_cache(maxsize=1024)
def _mask_radicands(base: tuple) -> tuple:
    """The radicand of each mask over ``base`` (bit i: ``base[i]`` divides it)."""
    out = []
    for mask in range(2 ** len(base)):
        m = 1
        for i, p in enumerate(base):
            if mask >> i & 1:
                m *= p
        out.append(m)
    return tuple(out)


def _dense_product(a: dict, b: dict, base) -> dict:
    """The product by Kronecker substitution (:func:`_dense_integers`), canonical."""
    A, da = _integers(a, force=True)
    B, db = _integers(b, force=True)
    return _canonical(_dense_integers(A, B, base), da * db)


def _dense_integers(A: dict, B: dict, base) -> dict:
    """The product of two elements with many terms, integer coefficients ``A``, ``B``, by
    Kronecker substitution.  Over a coprime base b_1..b_k of their radicands the field is
    Z[x_1..x_k]/(x_i^2 - b_i) (tensored with Q): substitute x_i = X^(3^(i-1)) (every
    exponent of the product is at most 2, so base-3 digits do not carry), multiply the
    two integer polynomials in FLINT, then reduce x_i^2 = b_i digit by digit.  The terms
    come out in the order of the radicands' masks over the base."""
    k = len(base)
    masks: dict = {}

    def poly(terms):
        coeffs = [0] * ((3 ** k + 1) // 2)
        for m, c in terms.items():
            index = masks.get(m)
            if index is None:
                index = 0
                for i, p in enumerate(base):
                    if m % p == 0:
                        index += 3 ** i
                masks[m] = index
            coeffs[index] = c
        return fmpz_poly(coeffs)

    pa = poly(A)
    c = (pa * pa if B is A else pa * poly(B)).coeffs()
    c += [0] * (3 ** k - len(c))
    s = 1
    for p in base:      # digit i in {0, 1, 2} -> {0, 1}: x_i^2 = b_i
        out: list = []
        for j in range(0, len(c), 3 * s):
            out += [x + p * z if z else x for x, z in zip(c[j:j + s], c[j + 2 * s:j + 3 * s])]
            out += c[j + s:j + 2 * s]
        c = out
        s *= 2
    radicands = _mask_radicands(tuple(base))
    return {radicands[mask]: v for mask, v in enumerate(c) if v}


def coprime_base(radicands) -> list[int]:
    """Pairwise coprime integers > 1 whose products give every radicand (gcd refinement)."""
    base: list[int] = []
    for m in radicands:
        pending = [m]
        while pending:
            x = pending.pop()
            if x == 1:
                continue
            for i, b in enumerate(base):
                g = gcd(x, b)
                if g > 1:
                    del base[i]
                    pending.extend(y for y in (g, b // g, x // g) if y > 1)
                    break
            else:
                base.append(x)
    return base


_coprime_base = coprime_base     # the name gathering/geometry.py still imports


@lru_cache(maxsize=4096)
def _sqrt_arb_at(m: int, prec: int) -> arb:
    old = ctx.prec
    ctx.prec = prec
    try:
        return arb(m).sqrt()
    finally:
        ctx.prec = old


def _sqrt_arb(m: int) -> arb:
    return _sqrt_arb_at(m, ctx.prec)


def _float_sign(terms: dict):
    """The sign from doubles when the sum is provably away from zero, else ``None``.
    Each term ``c*sqrt(m)`` is within 5 units of rounding (conversions, root, product)
    and the sum adds one per term, so the error is below ``(k + 6) * 2^-52 * S`` with
    ``S`` the sum of magnitudes, provided nothing overflowed or went subnormal."""
    try:
        vals = [float(c) * (float(m) ** 0.5) for m, c in terms.items()]
    except OverflowError:
        return None
    s_abs = sum(abs(v) for v in vals)
    if not (1e-280 < s_abs < 1e280):
        return None
    total = sum(vals)
    bound = (len(vals) + 6) * _ULP * s_abs
    if total > bound:
        return 1
    if total < -bound:
        return -1
    return None


def _arb_sign(terms: dict) -> int:
    prec = 64
    while prec <= _MAX_PREC:
        old = ctx.prec
        ctx.prec = prec
        try:
            total = arb(0)
            for m, c in terms.items():
                total += arb(c.p) / arb(c.q) * _sqrt_arb_at(m, prec)
            if total > 0:
                return 1
            if total < 0:
                return -1
        finally:
            ctx.prec = old
        prec *= 2
    raise ArithmeticError("sign undecided at maximal precision (non-zero element)")
