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
from math import lcm

from flint import arb, ctx, fmpq, fmpz

from ..io.exprtree import Fold, Node, fold
from .factor import factorization
from .field import FieldElement
from .mq_products import (INTEGER_PRODUCT, arb_sign, canonical_terms, coprime_base, float_sign,
                          integer_product, product_integers, rational_product,
                          sqrt_arb)



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
        self._ints = None       # the integer form of :func:`integer_terms`, once asked for

    def __getstate__(self):     # a pickle or copy carries the terms, not the caches
        return self.terms

    def __setstate__(self, terms):
        self.__init__(terms)

    # -- construction -------------------------------------------------------
    @staticmethod
    def from_rational(q) -> "MQ":
        q = _as_fmpq(q)
        return MQ({1: q} if q != 0 else {})

    #: ``MQ.rational(q)``: the element q (the value of a rational element is read with
    #: :meth:`to_fmpq`, the name of the number interface, :class:`~.number.ExactNumber`)
    rational = from_rational

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
        if la * lb >= INTEGER_PRODUCT:
            return MQ(integer_product(self, other))
        return MQ(rational_product(a, b))     # few terms

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
        s = float_sign(t)
        return s if s is not None else arb_sign(t)

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
                total += arb(c.p) / arb(c.q) * sqrt_arb(m)
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


class _Multiquadratic(Fold):
    """Values in Q(sqrt a_1, ...): ``ValueError`` for anything else."""

    def const(self, node):
        return MQ.rational(node.value)

    def neg(self, node, arg):
        return -arg

    def binop(self, node, a, b):
        if node.op == "+":
            return a + b
        if node.op == "-":
            return a - b
        if node.op == "*":
            return a * b
        if node.op == "/":
            return a / b
        raise ValueError(f"operator {node.op!r} is not supported")

    def power(self, node, base):
        return base ** int(node.exponent)

    def sqrt(self, node, arg):
        if not arg.is_rational():
            raise ValueError("nested radicals are not multiquadratic")
        return sqrt_rational(arg.to_fmpq())

    def trig(self, node):
        raise ValueError(f"{type(node).__name__} is not multiquadratic")

    def unknown(self, node):
        raise ValueError(f"{type(node).__name__} is not multiquadratic")


def from_tree(node: Node) -> MQ:
    """Evaluate an expression tree (:mod:`exactsym.io.exprtree`) built from rationals,
    ``+ - * /``, integer powers and square roots of non-negative rationals.
    Raises ``ValueError`` for anything else (``cos``, ``pi``, nested radicals)."""
    return fold(node, _Multiquadratic())


def sum_of_products(items) -> MQ:
    """``sum s a b`` over ``(s, a, b)`` (``s`` an int, ``a``, ``b`` :class:`MQ`), made
    canonical once: a dot product or a cross product of two points pays one gcd per
    term of the result instead of one per term of each product and of their sum.  The
    same value (integers summed exactly over a common denominator), so the same
    element; small factors go the ordinary way."""
    items = list(items)
    if max((len(a.terms) * len(b.terms) for _, a, b in items), default=0) < INTEGER_PRODUCT:
        return _plain_sum(items)
    parts = []
    for s, a, b in items:
        if not a.terms or not b.terms:
            continue
        r = product_integers(a, b)
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
    return MQ(canonical_terms(out, den))


def _plain_sum(items) -> MQ:
    out = MQ()
    for s, a, b in items:
        t = a * b
        out = out + t if s == 1 else out - t if s == -1 else out + t * s
    return out
