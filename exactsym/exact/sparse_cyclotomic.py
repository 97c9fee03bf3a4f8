"""Sparse elements of Q(zeta_N) for conductors far beyond a dense field (issue 9).

Why: a polar file with turns 1/999983 and 3/999979 needs Q(zeta_N) with N near 2.6 * 10^14,
of degree phi(N) near 10^14: no polynomial of that degree can be built.  But each coordinate
``r cos(2 pi k/N)`` is two roots of unity, and the predicates of the pipeline are short sums
of products of coordinates.  So an element here is a finite sum of roots of unity, and since
every number the pipeline makes is real, it is kept as its real part, a dictionary
``{e: fmpq}`` = ``sum c_e cos(2 pi e/N)`` over representatives 0 <= e <= N/2
(:mod:`.sparse_terms`; ``cos e cos f = (cos(e+f) + cos(e-f))/2``): a product of sums of s and
t cosines costs s t coefficient products, a quarter of the same product written with roots of
unity (each cosine is two).  The zero test reads the cosines back as roots of unity.
Factorisation, balls, traces and hashing live in the conductor's :mod:`.sparse_context`.

This form is *not* canonical (``1 + zeta_p + ... + zeta_p^(p-1) = 0``), and no canonical basis
is sparse: the Zumbroich basis writes ``zeta_p^0`` as minus p - 1 other roots, a million terms
for p = 999983.  So equality is decided by an exact zero test (:func:`is_zero_sum`) over the
prime factorisation of N, and hashing by an l-adic residue that is a ring homomorphism, so
equal numbers hash alike whatever their representation (:meth:`SparseContext.residue`; the
images modulo l are carried along sums and products, :meth:`SparseCyclotomic.rho`).

Zero test (the heart; never a float).  Write N = p^a m, gcd(p, m) = 1, and
E = the idempotent lift of 1 (E = 1 mod p^a, E = 0 mod m), so that w = zeta_N^E is a
primitive p^a-th root of unity.  An exponent e splits as e = i E + p f with i = e mod p:
zeta_N^e = w^i * zeta_(N/p)^f, f = (e - i E)/p mod N/p.  Hence
``x = sum_(i < p) w^i beta_i`` with beta_i in Q(zeta_(N/p)).

* a >= 2: w has minimal polynomial X^p - w^p over Q(zeta_(N/p)) (degree phi(N)/phi(N/p) = p),
  so 1, w, ..., w^(p-1) are independent: x = 0 iff every beta_i = 0.
* a = 1: N/p = m and w = zeta_p has minimal polynomial Phi_p over Q(zeta_m) (gcd(p, m) = 1),
  whose only relation is 1 + w + ... + w^(p-1) = 0: x = 0 iff all p of the beta_i are equal;
  when fewer than p residues i occur, the missing beta_i are 0, so every beta_i must be 0.

The recursion ends at N = 1, a rational.  Cost: each level partitions the terms; only a = 1
with all p residues present (small p) subtracts groups.

Sign of a real element: the value is ``sum c_e cos(2 pi e/N)`` (the real part of a real
number is itself); Arb's ``cos_pi_fmpq`` encloses each cosine of a rational multiple of pi
with a proven radius, so the sum is a proven ball.  Precision doubles until the ball excludes
0; after two balls that contain 0 the exact zero test is run once, and a non-zero element
keeps doubling (its value is not zero, so this ends).

Division: the inverse of a sparse sum is dense in general.  Elements are fractions
``num / den`` of sparse sums with ``den`` real and non-zero, or ``den`` None for 1; a rational
divisor is folded into the numerator.  The pipeline divides rarely on the Cartesian path
(homogeneous SEC centre, pseudo-angles): fractions keep that rare case exact.

Public names: :class:`SparseContext`, :func:`sparse_context`, :class:`SparseCyclotomic`,
:func:`is_zero_sum`, :data:`MAX_GAUSS_TERMS`.
"""


from __future__ import annotations

from fractions import Fraction
from math import gcd

from flint import arb, ctx, fmpq, fmpz

from .factor import factorization
from .field import FieldElement, PolyElement, as_fmpq
from .multiquadratic import MQ
from .sparse_context import SparseContext, sparse_context
from .sparse_terms import (add_terms, cosines_zero, is_zero_sum, mul_cosines, mul_roots,
                           rational_terms, real_part, roots_zero, scale_terms)

_START_PRECISION = 64
_MAX_PRECISION = 1 << 20
#: largest number of roots of unity in the Gauss sum of one square root of a rational
MAX_GAUSS_TERMS = 2048


# ---------------------------------------------------------------- the element
class SparseCyclotomic(FieldElement):
    """A real number ``num / den`` of Q(zeta_N), num and den sums of cosines
    ``{e: c}`` = sum c cos(2 pi e/N), 0 <= e <= N/2 (den None for 1).

    Immutable by convention; zero test, sign, rationality and hash are computed once."""

    __slots__ = ("ctx", "num", "den", "_zero", "_sign", "_rat", "_hash", "_rho")

    def __init__(self, context: SparseContext, num: dict, den: dict | None = None,
                 rho: tuple | None = None):
        self.ctx = context
        self.num = num
        self.den = den
        self._zero = self._sign = self._rat = self._hash = None
        self._rho = rho

    def rho(self) -> tuple[int, int]:
        """(image of num, image of den) modulo l under zeta_N -> g, -1 where a coefficient's
        denominator is divisible by l.  Carried along sums and products (a ring
        homomorphism), so hashing a product of large sums costs no power per term."""
        r = self._rho
        if r is None:
            context = self.ctx
            r = self._rho = (context.rho(self.num),
                             1 if self.den is None else context.rho(self.den))
        return r

    # -- coercion -------------------------------------------------------------
    def _coerce(self, other):
        """``other`` as an element of this context, or None for a foreign type."""
        if isinstance(other, SparseCyclotomic):
            if other.ctx is not self.ctx:
                if other.ctx.n == self.ctx.n:
                    return SparseCyclotomic(self.ctx, other.num, other.den)
                raise TypeError("elements of two different number fields do not mix")
            return other
        if isinstance(other, (int, fmpz, fmpq, Fraction)):
            return SparseCyclotomic(self.ctx, rational_terms(as_fmpq(other)))
        if isinstance(other, PolyElement):
            return from_poly_element(self.ctx, other)
        if isinstance(other, MQ):
            return from_multiquadratic(self.ctx, other)
        return None

    # -- arithmetic -----------------------------------------------------------
    def _new(self, num, den=None, rho=None):
        return SparseCyclotomic(self.ctx, num, den, rho)

    def __add__(self, other):
        o = self._coerce(other)
        if o is None:
            return NotImplemented
        return self._combine(o, 1)

    __radd__ = __add__

    def __sub__(self, other):
        o = self._coerce(other)
        if o is None:
            return NotImplemented
        return self._combine(o, -1)

    def __rsub__(self, other):
        o = self._coerce(other)
        if o is None:
            return NotImplemented
        return o._combine(self, -1)

    def _combine(self, o, sign):
        (an, ad), (bn, bd) = self.rho(), o.rho()
        ell = self.ctx.ell
        if self.den is o.den or (self.den is not None and o.den is not None and
                                 self.den == o.den):
            # both None, or one denominator (equal dictionaries: a tower's products make
            # the same denominator N M as separate objects; cross-multiplying them squared
            # it at every sum, issue 9)
            rho = (-1 if an < 0 or bn < 0 else (an + sign * bn) % ell, ad)
            return self._new(add_terms(self.num, o.num, sign), self.den, rho)
        rho = (-1 if min(an, ad, bn, bd) < 0 else (an * bd + sign * bn * ad) % ell,
               -1 if ad < 0 or bd < 0 else ad * bd % ell)
        n = self.ctx.n
        a = mul_cosines(self.num, o.den, n) if o.den is not None else self.num
        b = mul_cosines(o.num, self.den, n) if self.den is not None else o.num
        den = (mul_cosines(self.den, o.den, n) if self.den is not None and o.den is not None
               else self.den if self.den is not None else o.den)
        return self._new(add_terms(a, b, sign), den, rho)

    def __neg__(self):
        rn, rd = self.rho()
        return self._new({e: -c for e, c in self.num.items()}, self.den,
                         (-1 if rn < 0 else -rn % self.ctx.ell, rd))

    def __pos__(self):
        return self

    def __mul__(self, other):
        if isinstance(other, (int, fmpq, fmpz)):
            if not other:
                return self._new({})
            q = as_fmpq(other)
            rn, rd = self.rho()
            rq = self.ctx.rho({0: q})
            return self._new(scale_terms(self.num, q), self.den,
                             (-1 if rn < 0 or rq < 0 else rn * rq % self.ctx.ell, rd))
        o = self._coerce(other)
        if o is None:
            return NotImplemented
        n = self.ctx.n
        num = mul_cosines(self.num, o.num, n)
        if not num:
            return self._new({})
        den = (mul_cosines(self.den, o.den, n) if self.den is not None and o.den is not None
               else self.den if self.den is not None else o.den)
        (an, ad), (bn, bd) = self.rho(), o.rho()
        ell = self.ctx.ell
        rho = (-1 if an < 0 or bn < 0 else an * bn % ell,
               -1 if ad < 0 or bd < 0 else ad * bd % ell)
        return self._new(num, den, rho)

    __rmul__ = __mul__

    def inverse(self):
        if self.is_zero():
            raise ZeroDivisionError("division by zero")
        if self.is_rational():
            return self._new(rational_terms(1 / self.to_fmpq()))
        den = self.num
        if len(den) == 1 and 0 in den:                       # a rational numerator
            return self._new(scale_terms(self.den or {0: fmpq(1)}, 1 / den[0]))
        return self._new(dict(self.den) if self.den is not None else {0: fmpq(1)}, den)

    def __truediv__(self, other):
        if isinstance(other, (int, fmpq, fmpz)):
            if other == 0:
                raise ZeroDivisionError("division by zero")
            return self * (1 / as_fmpq(other))
        o = self._coerce(other)
        if o is None:
            return NotImplemented
        if o.is_rational():
            return self / o.to_fmpq()
        if self.den is not None and (self.den is o.den or self.den == o.den):
            # (a/d) / (b/d) = a/b: no product of sums (a line's slope y/x, whose
            # coordinates share the denominator of the SEC centre, multiplied a/d by d/b)
            if o.is_zero():
                raise ZeroDivisionError("division by zero")
            if len(o.num) == 1 and 0 in o.num:              # b rational: a scaled
                return self._new(scale_terms(self.num, 1 / o.num[0]))
            return self._new(self.num, dict(o.num), (self.rho()[0], o.rho()[0]))
        return self * o.inverse()

    def __rtruediv__(self, other):
        o = self._coerce(other)
        return NotImplemented if o is None else o * self.inverse()

    def _one(self):
        return self._new({0: fmpq(1)})

    # -- exact tests ----------------------------------------------------------
    def is_zero(self) -> bool:
        z = self._zero
        if z is None:
            # a non-zero image modulo l (a ring map: zero maps to zero) proves x != 0; the
            # image is carried along sums and products, the exact test walks N's factors
            z = self._zero = False if self.rho()[0] > 0 else cosines_zero(self.num, self.ctx.n)
        return z

    def reduced(self) -> "SparseCyclotomic":
        """This number written as the rational ``{0: q}`` when it is one held as a quotient
        or a sum of cosines (the SEC centre X/D, the centroid of a translated C7 set: every
        later product multiplied those sums), else itself."""
        if (self.den is not None or len(self.num) > 1) and self.is_rational():
            return self._new(rational_terms(self.to_fmpq()))
        return self

    def is_rational(self) -> bool:
        return self._rational_value() is not None

    def _rational_value(self):
        r = self._rat
        if r is None:
            r = self._rat = self._find_rational()
        return r if r is not False else None

    def _find_rational(self):
        """The rational value or False.  For den None, q = Tr(x)/phi(N); for a fraction,
        x = q forces num = q den, and q = Tr(num den)/Tr(den^2) with Tr(den^2) > 0 (den is
        real and Q(zeta_N) a CM field, so every conjugate of den is real and non-zero)."""
        num, den, context = self.num, self.den, self.ctx
        if not num:
            return fmpq(0)
        if den is None:
            if len(num) == 1 and 0 in num:
                return num[0]
            q = context.mean_trace(num)
            return q if cosines_zero(add_terms(num, rational_terms(q), -1), context.n) else False
        if _moved_by_galois(context, num, den):
            return False
        q = context.mean_trace(mul_cosines(num, den, context.n)) / \
            context.mean_trace(mul_cosines(den, den, context.n))
        return q if cosines_zero(add_terms(num, scale_terms(den, q), -1), context.n) else False

    def to_fmpq(self) -> fmpq:
        r = self._rational_value()
        if r is None:
            raise ValueError("not a rational number")
        return r

    def sign(self) -> int:
        s = self._sign
        if s is None:
            if self.den is None:
                s = _sign_of(self.ctx, self.num)
            else:
                s = _sign_of(self.ctx, self.num)
                s = s and s * _sign_of(self.ctx, self.den)
            self._sign = s
        return s

    def _cmp(self, other):
        o = self._coerce(other)
        return None if o is None else (self - o).sign()

    def __eq__(self, other):
        o = self._coerce(other) if not isinstance(other, SparseCyclotomic) or \
            other.ctx is not self.ctx else other
        if o is None:
            return NotImplemented
        # the images modulo l differ: not equal, without the difference (whose
        # denominators cross-multiply sums of hundreds of cosines: issue 9)
        (an, ad), (bn, bd) = self.rho(), o.rho()
        if min(an, ad, bn, bd) >= 0 and (an * bd - bn * ad) % self.ctx.ell:
            return False
        return (self - o).is_zero()

    def __ne__(self, other):
        eq = self.__eq__(other)
        return eq if eq is NotImplemented else not eq

    def __bool__(self):
        return not self.is_zero()

    def __hash__(self):
        h = self._hash
        if h is None:
            q = self._rational_value()
            h = self._hash = hash(q) if q is not None else \
                hash(("sparse-cyclotomic", self.ctx.n, self.residue()))
        return h

    def residue(self) -> int:
        """The l-adic residue of :meth:`SparseContext.residue` (equal numbers, equal
        residue): from the carried images when both are l-integral and the denominator's is
        a unit (then they are the same value), else from the terms."""
        rn, rd = self.rho()
        if rn >= 0 and rd > 0:
            return rn * pow(rd, -1, self.ctx.ell) % self.ctx.ell
        return self.ctx.residue(self.num, self.den)

    def __abs__(self):
        return -self if self.sign() < 0 else self

    def exact_key(self) -> tuple:
        """The key of an irrational element for :func:`.ordering.exact_key`: no sparse form
        is canonical, so the key holds the element behind a wrapper whose equality is the
        exact zero test and whose hash is the l-adic residue (equal numbers, equal hash)."""
        return (_SPARSE_TAG, self.ctx.n, self.residue(), _KeyedElement(self))

    # -- numerics -------------------------------------------------------------
    def enclosure(self, prec: int = 53) -> arb:
        """A proven ball around the value (filters and drawing only)."""
        ball = self.ctx.ball(self.num, prec)
        if self.den is not None:
            with ctx.workprec(prec + 16):
                ball = ball / self.ctx.ball(self.den, prec)
        return ball

    def __float__(self):  # display and float filters only: never decides anything
        return float(self.enclosure(53).mid())

    def text(self) -> str:
        from .sparse_text import sparse_text
        return sparse_text(self)

    def __repr__(self):
        return f"SparseCyclotomic({self.text()} in Q(zeta_{self.ctx.n}))"


def _conjugate_ball(context: SparseContext, terms: dict, k: int, prec: int) -> arb:
    """A ball around sigma_k(x) for x = sum c cos(2 pi e/N): sum c cos(2 pi k e / N)."""
    n = context.n
    return context.ball({k * e % n: c for e, c in terms.items()}, prec)


def _moved_by_galois(context: SparseContext, num: dict, den: dict) -> bool:
    """True when some automorphism zeta -> zeta^k provably moves num/den (disjoint balls),
    so the number is not rational; False decides nothing.  A rational is fixed by every
    automorphism, and an irrational x of degree d is fixed by a subgroup of index d >= 2,
    so a few k usually find one (the exact test decides otherwise)."""
    n, tried, k = context.n, 0, 3
    x = None
    while tried < 3 and k < 200:
        if gcd(k, n) == 1 and k % n not in (1, n - 1):
            tried += 1
            if x is None:
                with ctx.workprec(80):
                    x = context.ball(num, 64) / context.ball(den, 64)
            with ctx.workprec(80):
                y = _conjugate_ball(context, num, k, 64) / _conjugate_ball(context, den, k, 64)
                if not x.overlaps(y):
                    return True
        k += 2
    return False


_SPARSE_TAG = "sparse-cyclotomic"     # no other key of ordering.exact_key starts with it


class _KeyedElement:
    """An element inside a key: equal iff the numbers are equal (exact zero test)."""

    __slots__ = ("x",)

    def __init__(self, x: SparseCyclotomic):
        self.x = x

    def __eq__(self, other):
        return isinstance(other, _KeyedElement) and self.x.ctx.n == other.x.ctx.n and \
            (self.x - other.x).is_zero()

    def __hash__(self):
        return self.x.residue()

    def __repr__(self):
        return f"<{self.x.text()}>"


def _sign_of(context: SparseContext, terms: dict) -> int:
    """Certified sign of the real number sum c zeta^e (see the module docstring)."""
    if not terms:
        return 0
    if len(terms) == 1 and 0 in terms:
        c = terms[0]
        return (c > 0) - (c < 0)
    prec, straddles = _START_PRECISION, 0
    while prec <= _MAX_PRECISION:
        ball = context.ball(terms, prec)
        if ball > 0:
            return 1
        if ball < 0:
            return -1
        straddles += 1
        if straddles == 2 and cosines_zero(terms, context.n):
            return 0
        prec *= 2
    raise ArithmeticError("sign undecided at the precision limit: a non-zero sparse sum "
                          "evaluated as zero (bug in the enclosure)")


# ---------------------------------------------------------------- construction
def cos_turn(context: SparseContext, turn: fmpq) -> SparseCyclotomic:
    """cos(2 pi turn) = cos(2 pi k/N), k = turn N (the turn's denominator divides N)."""
    k = turn * context.n
    if k.q != 1:
        raise ValueError(f"turn {turn} is not in Q(zeta_{context.n})")
    return SparseCyclotomic(context, real_part({int(k.p): fmpq(1)}, context.n))


def _legendre(a: int, p: int) -> int:
    r = pow(a, (p - 1) // 2, p)
    return -1 if r == p - 1 else r


def gauss_terms(s: int) -> int:
    """How many roots of unity the Gauss sum of sqrt(s) has (s squarefree)."""
    out = 1
    for p in factorization(s) if s > 1 else ():
        out *= 2 if p == 2 else p - 1
    return out


def sqrt_rational(context: SparseContext, q: fmpq) -> SparseCyclotomic:
    """The non-negative square root of the rational q >= 0 as a product of Gauss sums
    (:func:`.cyclotomic.sqrt_element`, written sparsely); its square is checked exactly."""
    from .cyclotomic import sqrt_conductor, squarefree_decomposition
    c, s = squarefree_decomposition(q)
    if c == 0:
        return SparseCyclotomic(context, {})
    n = context.n
    if n % sqrt_conductor(s):
        raise ValueError(f"sqrt({s}) is not in Q(zeta_{n})")
    root = {0: fmpq(1)}
    for p in (factorization(s) if s > 1 else ()):
        if p == 2:
            factor = {n // 8: fmpq(1), (-(n // 8)) % n: fmpq(1)}
        else:
            step = n // p
            factor = {a * step % n: fmpq(_legendre(a, p)) for a in range(1, p)}
            if p % 4 == 3:
                factor = mul_roots(factor, {(-(n // 4)) % n: fmpq(1)}, n)
        root = mul_roots(root, factor, n)
    if not roots_zero(add_terms(mul_roots(root, root, n), {0: fmpq(s)}, -1), n):
        raise ArithmeticError(f"Gauss sum for sqrt({s}) is wrong")   # cannot happen
    x = SparseCyclotomic(context, real_part(root, n))     # real: its real part
    if x.sign() < 0:
        x = -x
    return x * c


def from_poly_element(context: SparseContext, x: PolyElement) -> SparseCyclotomic:
    """An element of a dense Q(zeta_M), M | N, written sparsely (zeta_M = zeta_N^(N/M))."""
    m = x.field.conductor
    if m is None or context.n % m:
        raise TypeError("elements of two different number fields do not mix")
    step = context.n // m
    return SparseCyclotomic(context, real_part({k * step: c for k, c in
                                                 enumerate(x.poly.coeffs()) if c != 0},
                                                context.n))


def from_multiquadratic(context: SparseContext, x) -> SparseCyclotomic:
    """A multiquadratic element (``MQ``) whose square roots Q(zeta_N) holds."""
    total = SparseCyclotomic(context, {})
    for m, c in x.terms.items():
        total = total + (sqrt_rational(context, fmpq(m)) * c if m != 1 else
                         SparseCyclotomic(context, {0: c}))
    return total


__all__ = ["SparseContext", "sparse_context", "SparseCyclotomic", "is_zero_sum",
           "cos_turn", "sqrt_rational", "gauss_terms", "from_poly_element",
           "from_multiquadratic", "MAX_GAUSS_TERMS"]
