"""Nested radicals in a tower of quadratic extensions, built lazily (issue 9).

K_0 = Q(sqrt p : p in ``primes``) is a multiquadratic field (its elements are
:class:`~.multiquadratic.MQ`), and K_i = K_(i-1)(y_i) with y_i the positive square root of
a positive radicand r_i of K_(i-1) that is **not a square** in K_(i-1).  A level is added
only when a square root is asked for a number that has none in the current top field; when
it has one (``sqrt(3+2*sqrt(2)) = 1 + sqrt(2)``, ``sqrt(2+sqrt(3)) = (sqrt(6)+sqrt(2))/2``
once sqrt(2) and sqrt(3) are in K_0) the root is an element of the field below: the radical
is denested.

Canonical form.  An element of level 0 is an MQ; an element of level i >= 1 is the tuple
``(i, a, b)`` = a + b y_i with a, b of level < i and b != 0.  Since r_i is not a square in
K_(i-1), {1, y_i} is a basis of K_i over K_(i-1), so every number of the tower has exactly one
such form: equality and hash are structural and exact, and an element of level i >= 1 is
never equal to one of a lower level.  Inverses are conjugate multiplications down the tower:
1/(a + b y) = (a - b y) / (a^2 - r b^2).  Signs come from Arb balls at doubling precision (a
non-zero element has a non-zero value, so the loop ends).

The square-root test is exact and complete.  In K_i = K_(i-1)(y), x = a + b y is a square
(c + d y)^2 iff: for b = 0, a or a/r is a square in K_(i-1) (root c or d y); for b != 0, the
norm a^2 - r b^2 = (c^2 - r d^2)^2 has a root n in K_(i-1), one of (a + n)/2, (a - n)/2 is
c^2 with c != 0, and d = b / (2c).  In K_0 = Q(sqrt p_1, ..., sqrt p_k) the same recursion
runs over the primes (K_0 is the tower Q(sqrt p_1)(sqrt p_2)...), ending at rational squares.
All fields are real, so a negative number is never a square.

Public names: :class:`Tower`, :class:`TowerElement`, :func:`height_bits`.
"""

from __future__ import annotations

from copy import deepcopy
from fractions import Fraction
from math import isqrt, lcm, prod

from flint import arb, ctx, fmpq, fmpz

from .field import FieldElement
from .modular import kummer_subset, square_class_rank
from .multiquadratic import MQ
from .sparse_cyclotomic import SparseCyclotomic

_ZERO = MQ()
_UNDECIDED = object()        # a shortcut that could not decide: the complete test runs
_MAX_PREC = 1 << 18

#: Largest number of levels above K_0 (degree up to 2^MAX_LEVELS over K_0).  Decided before
#: a level is added; beyond it, FieldTooLargeError (exit 2).
MAX_LEVELS = 12


def level(v) -> int:
    return v[0] if type(v) is tuple else 0


def split(v, lev: int):
    return (v[1], v[2]) if type(v) is tuple and v[0] == lev else (v, _ZERO)


def _make(lev: int, a, b):
    return a if type(b) is not tuple and not b else (lev, a, b)


def _is_zero(v) -> bool:
    # a base value (MQ, or a PolyElement of a cyclotomic base) is false exactly when zero
    return type(v) is not tuple and not v


def add(x, y):
    # hot: type tests instead of level() calls; adding a lower level touches only the a part
    tx, ty = type(x) is tuple, type(y) is tuple
    if not tx:
        if not ty:
            return x + y
        return (y[0], add(x, y[1]), y[2]) if x else y
    if not ty:
        return (x[0], add(x[1], y), x[2]) if y else x
    lx, ly = x[0], y[0]
    if lx == ly:
        b = add(x[2], y[2])
        return add(x[1], y[1]) if type(b) is not tuple and not b else \
            (lx, add(x[1], y[1]), b)
    if lx > ly:
        return (lx, add(x[1], y), x[2])
    return (ly, add(x, y[1]), y[2])


def neg(x):
    return (x[0], neg(x[1]), neg(x[2])) if type(x) is tuple else -x


def sub(x, y):
    return add(x, neg(y))



def denominator(v) -> int:
    """The least common denominator of the rational coefficients of a raw value."""
    if type(v) is tuple:
        return lcm(denominator(v[1]), denominator(v[2]))
    return lcm(*[int(c.q) for c in v.terms.values()]) if v.terms else 1


def _scaled(v, q):
    """q * v for a rational q != 0, coefficient by coefficient (same structure and order)."""
    if type(v) is tuple:
        return (v[0], _scaled(v[1], q), _scaled(v[2], q))
    return MQ({m: c * q for m, c in v.terms.items()})


def _mq_split(x: MQ, p: int):
    """x = A + B sqrt(p) with A, B free of the prime p."""
    a, b = {}, {}
    for m, c in x.terms.items():
        if m % p:
            a[m] = c
        else:
            b[m // p] = c
    return MQ(a), MQ(b)


def height_bits(v) -> int:
    """Bits of the largest numerator or denominator among the rational coefficients."""
    if isinstance(v, MQ):
        return max((int(c.p).bit_length() + int(c.q).bit_length() for c in v.terms.values()),
                   default=1)
    if type(v) is not tuple and hasattr(v, "poly"):     # a PolyElement of a cyclotomic base
        return max(int(v.poly.numer().height_bits()), 1) + int(v.poly.denom()).bit_length()
    if type(v) is not tuple:                # a SparseCyclotomic base: num / den, cosines
        return max((int(c.p).bit_length() + int(c.q).bit_length()
                    for c in list(v.num.values()) + list((v.den or {}).values())), default=1)
    return max(height_bits(v[1]), height_bits(v[2]))


class Tower:
    """One tower K_0 < K_1 < ... for one configuration (grows as square roots are asked)."""

    zero = _ZERO
    one = MQ.rational(1)

    def __init__(self, primes):
        self.primes = tuple(sorted(set(int(p) for p in primes)))
        self.radicands: list = []          # r_i (level < i), index i - 1
        self._roots: dict = {}             # radicand -> its non-negative root in the tower
        self._balls: dict = {}             # (i, prec) -> ball around y_i

    def __deepcopy__(self, memo):
        """A tower that grows on its own (the gathering search forks worlds): its
        radicands and roots copied deeply, its balls shared (an ``arb`` is immutable and
        cannot be deep-copied)."""
        new = object.__new__(type(self))
        memo[id(self)] = new
        for name, value in self.__dict__.items():
            setattr(new, name, dict(value) if name == "_balls" else deepcopy(value, memo))
        return new

    @property
    def levels(self) -> int:
        return len(self.radicands)

    @property
    def degree(self) -> int:
        return 1 << (len(self.primes) + self.levels)

    @property
    def name(self) -> str:
        base = ", ".join(f"sqrt({p})" for p in self.primes[:6]) + \
            (", ..." if len(self.primes) > 6 else "")
        tops = "".join(f"(sqrt({text(self, r)}))" for r in self.radicands)
        head = f"Q({base})" if self.primes else "Q"
        name = head + tops
        return name if len(name) <= 200 else f"{head} with {self.levels} quadratic levels"

    # -- the base field K_0 (overridden by a cyclotomic base, exact/cyclotomic_tower.py) ----
    def const(self, q):
        return MQ.rational(q)

    def coerce_base(self, other):
        """A kernel number of K_0 (or a rational) as a raw base value, or None."""
        if isinstance(other, MQ):
            return other
        if isinstance(other, (int, fmpz, fmpq, Fraction)):
            return MQ.rational(other)
        return None

    def wrap(self, v):
        return v if isinstance(v, MQ) else TowerElement(self, v)

    def base_root(self, x):
        """A root in K_0 of the base value x > 0, or None (complete)."""
        return self._mq_root(x, len(self.primes))

    def base_text(self, v) -> str:
        return v.text()

    # -- arithmetic on raw values --------------------------------------------
    def mul(self, x, y):
        """x * y.  Nested values carry big fractions (an inverse's coefficients share one
        big denominator), and every fmpq product or sum of them pays gcds: so both factors
        are scaled to integer coefficients, multiplied, and the product divided by the two
        scales at the end (exact, and the same canonical value and term order)."""
        if type(x) is not tuple or type(y) is not tuple:
            return self._mul(x, y)
        dx, dy = denominator(x), denominator(y)
        if dx == 1 and dy == 1:
            return self._mul(x, y)
        return _scaled(self._mul(_scaled(x, dx), _scaled(y, dy)), fmpq(1, dx * dy))

    def _mul(self, x, y):
        tx, ty = type(x) is tuple, type(y) is tuple
        if not tx:
            if not ty:
                return x * y
            if not x:
                return self.zero
            return (y[0], self._mul(x, y[1]), self._mul(x, y[2]))   # a scalar of a lower level
        if not ty:
            if not y:
                return self.zero
            return (x[0], self._mul(x[1], y), self._mul(x[2], y))
        lx, ly = x[0], y[0]
        if lx > ly:
            return (lx, self._mul(x[1], y), self._mul(x[2], y))
        if ly > lx:
            return (ly, self._mul(x, y[1]), self._mul(x, y[2]))
        lev = lx
        xa, xb, ya, yb = x[1], x[2], y[1], y[2]
        r = self.radicands[lev - 1]
        low, high = self._mul(xa, ya), self._mul(xb, yb)
        # Karatsuba: three products of the level below instead of four
        mixed = sub(sub(self._mul(add(xa, xb), add(ya, yb)), low), high)
        return _make(lev, add(low, self._mul(r, high)), mixed)

    def inverse(self, x):
        if type(x) is not tuple:
            return x.inverse()
        lev, a, b = x
        norm = sub(self.mul(a, a), self.mul(self.radicands[lev - 1], self.mul(b, b)))
        n_inv = self.inverse(norm)
        return _make(lev, self.mul(a, n_inv), neg(self.mul(b, n_inv)))

    def divide(self, x, y):
        """x / y (y != 0) as x conj(y) / N(y), the norm N(y) = a^2 - r b^2 one level down,
        recursively: the big denominator appears once, at the end, instead of in every
        coefficient of 1/y (which then multiplies x)."""
        return self._divide(x, y, {})

    def _divide(self, x, y, cache):
        if type(y) is not tuple:
            if y.is_rational():
                return self.mul(x, self.const(1 / y.to_fmpq()))
            inv = cache.get(y)
            if inv is None:
                inv = cache[y] = y.inverse()
            return self.mul(x, inv)
        lev = y[0]
        top = level(x)
        if top > lev:       # (xa + xb y_top) / y = xa / y + (xb / y) y_top
            return _make(top, self._divide(x[1], y, cache), self._divide(x[2], y, cache))
        entry = cache.get(y)
        if entry is None:
            a, b = y[1], y[2]
            norm = sub(self.mul(a, a), self.mul(self.radicands[lev - 1], self.mul(b, b)))
            entry = cache[y] = ((lev, a, neg(b)), norm)
        conj, norm = entry
        return self._divide(self.mul(x, conj), norm, cache)

    def ball(self, x, prec: int) -> arb:
        if type(x) is not tuple:
            return x.enclosure(prec)
        lev, a, b = x
        with ctx.workprec(prec):
            return self.ball(a, prec) + self.ball(b, prec) * self._root_ball(lev, prec)

    def _root_ball(self, lev: int, prec: int) -> arb:
        ball = self._balls.get((lev, prec))
        if ball is None:
            r = self.ball(self.radicands[lev - 1], prec)
            with ctx.workprec(prec):
                ball = self._balls[(lev, prec)] = r.sqrt()
        return ball

    def sign(self, x) -> int:
        if type(x) is not tuple:
            return x.sign()
        prec = 64
        while prec <= _MAX_PREC:
            value = self.ball(x, prec + 8 * x[0])
            if value > 0:
                return 1
            if value < 0:
                return -1
            prec *= 2
        raise ArithmeticError("sign undecided at maximal precision (non-zero tower element)")

    # -- square roots ----------------------------------------------------------
    def root_in(self, x, lev: int):
        """A y of level <= ``lev`` with y^2 == x, or None (x of level <= lev)."""
        if self.sign(x) < 0:
            return None
        if lev == 0:
            return self.base_root(x)
        if type(x) is MQ and lev >= 2 and x.terms:
            root = self._kummer_root(x, lev)
            if root is not _UNDECIDED:
                return root
        a, b = split(x, lev)
        r = self.radicands[lev - 1]
        if _is_zero(b):
            c = self.root_in(a, lev - 1)
            if c is not None:
                return c
            d = self.root_in(self.mul(a, self.inverse(r)), lev - 1)
            return None if d is None else (lev, self.zero, d)
        n = self.root_in(sub(self.mul(a, a), self.mul(r, self.mul(b, b))), lev - 1)
        if n is None:
            return None
        half = self.const(fmpq(1, 2))
        for t in (self.mul(add(a, n), half), self.mul(sub(a, n), half)):
            c = self.root_in(t, lev - 1)
            if c is not None and not _is_zero(c):
                d = self.mul(b, self.inverse(add(c, c)))
                y = _make(lev, c, d)
                if self.mul(y, y) == x:
                    return y
        return None

    def _kummer_root(self, x: MQ, lev: int):
        """root_in for an x of K_0 when the levels up to ``lev`` are square roots of K_0:
        the recursion below branches twice per level (x or x / r_i a square one level down)
        and took 14 s over nine such levels (twelve nested radicals, MakeAsym's radial
        move), while by Kummer theory only x * prod(r_j : j in S) for the one S that
        Legendre characters allow can be a square of K_0 (:func:`.modular.kummer_subset`);
        then x = (w / prod r_j)^2 prod r_j and the root is w prod y_j / prod r_j.
        _UNDECIDED when the characters settle nothing or the levels are not of that kind."""
        radicands = self.radicands[:lev]
        if not all(type(r) is MQ for r in radicands) or not self._in_base([x] + radicands):
            return _UNDECIDED
        subset = kummer_subset(self.primes, radicands, x)
        if subset is None:
            return _UNDECIDED
        if subset is False:
            return None
        product = x
        for j in subset:
            product = product * radicands[j]
        root = self._mq_root(product, len(self.primes))
        if root is None:
            return None
        for j in subset:
            root = root / radicands[j]
        for j in subset:
            root = self.mul(root, (j + 1, self.zero, self.one))
        return root

    def _mq_root(self, x: MQ, k: int):
        """A root of x in Q(sqrt p_1, ..., sqrt p_k) (first k primes of K_0), or None."""
        if x.is_rational():
            return _rational_root(x.to_fmpq(), self.primes[:k])
        if x.sign() < 0 or k == 0:
            return None
        if k >= 3 and len(x.terms) > 1 and self._in_base([x], k):
            # a Legendre character of a ring map K_0 -> F_p that is -1 on x proves x no
            # square (the image of a square is a square): the search below branches three
            # ways per prime, and its "no" took 30 s over ten primes (nested radicals of
            # ten square roots, MakeAsym's radial move)
            if square_class_rank(self.primes[:k], [x], tries=2, signs=4):
                return None
        p = self.primes[k - 1]
        a, b = _mq_split(x, p)
        sp = MQ({p: fmpq(1)})
        if not b.terms:
            c = self._mq_root(a, k - 1)
            if c is not None:
                return c
            d = self._mq_root(a / p, k - 1)
            return None if d is None else d * sp
        n = self._mq_root(a * a - b * b * p, k - 1)
        if n is None:
            return None
        for t in ((a + n) / 2, (a - n) / 2):
            c = self._mq_root(t, k - 1)
            if c is not None and c.terms:
                y = c + (b / (2 * c)) * sp
                if y * y == x:
                    return y
        return None

    def sqrt(self, x):
        """The non-negative square root of x >= 0 (raw value): an element of the top field,
        or the generator of a new level when x is not a square there."""
        key = x
        root = self._roots.get(key)
        if root is not None:
            return root
        root = self._rational_sqrt(x)
        if root is None:        # x of K_0 over levels of K_0: Kummer theory (_kummer_root)
            root = self.root_in(x, self.levels)
        if root is None:
            self._check_new_level()
            self.radicands.append(x)
            root = (self.levels, self.zero, self.one)
        elif self.sign(root) < 0:
            root = neg(root)
        self._roots[key] = root
        return root

    def _in_base(self, values, k: int | None = None) -> bool:
        """Whether the MQ ``values`` lie in Q(sqrt p : p among the first ``k`` primes,
        all by default): every squarefree radicand of their terms divides the product of
        those primes (the gathering simulator's towers take square roots of any rational
        over an empty list; Legendre characters of K_0 say nothing there)."""
        product = prod(self.primes[:k])
        return all(product % int(m) == 0 for v in values for m in v.terms)

    def adjoin(self, x):
        """The generator of a new level for ``x > 0`` (raw value) that the caller has
        proved a square in no field this tower can reach
        (:func:`~.mq_closure.decided_sqrt`, over the whole multiquadratic closure): the
        test of :meth:`sqrt` is not repeated (over many primes it branches 3^k times)."""
        root = self._roots.get(x)
        if root is not None:
            return root
        self._check_new_level()
        self.radicands.append(x)
        root = self._roots[x] = (self.levels, self.zero, self.one)
        return root

    def _rational_sqrt(self, x):
        """The root of a rational x in K_0 without the general test, or None."""
        if isinstance(x, MQ) and x.is_rational():
            return _rational_root(x.to_fmpq(), self.primes)
        return None

    def _check_new_level(self) -> None:
        """Raise FieldTooLargeError before a level beyond the documented bound is built."""
        if self.levels >= MAX_LEVELS:
            from ..errors import FieldTooLargeError
            raise FieldTooLargeError(f"these nested radicals need more than {MAX_LEVELS} "
                                     "quadratic extensions above the square roots")


def _rational_root(q: fmpq, primes):
    """The non-negative root of the rational q in Q(sqrt p : p in primes), or None."""
    if q <= 0:
        return _ZERO if q == 0 else None
    # no factoring (a norm down the tower can be a huge integer): m is the product of the
    # primes of K_0 that divide n to an odd power, and n / m must be a perfect square
    n, m = int(q.p) * int(q.q), 1
    for p in primes:
        e = 0
        while n % p == 0:
            n //= p
            e += 1
        if e % 2:
            m *= p
        n *= p ** (e - 1) if e % 2 else p ** e
    s = isqrt(n)                  # now n = num * den / m
    return MQ({m: fmpq(s, int(q.q))}) if s * s == n else None


def text(tower: Tower, v) -> str:
    """The configuration-syntax text of a raw value: a + b*sqrt(radicand), nested."""
    if type(v) is not tuple:
        return tower.base_text(v)
    lev, a, b = v
    root = f"sqrt({text(tower, tower.radicands[lev - 1])})"
    if type(b) is not tuple and b.is_rational():
        c = b.to_fmpq()
        mag = -c if c < 0 else c
        body = root if mag == 1 else f"{mag.p}*{root}" if mag.q == 1 else \
            f"{root}/{mag.q}" if mag.p == 1 else f"{mag.p}*{root}/{mag.q}"
        negative = c < 0
    else:
        body, negative = f"({text(tower, b)})*{root}", False
    if _is_zero(a):
        return ("-" if negative else "") + body
    return text(tower, a) + (" - " if negative else " + ") + body


# ------------------------------------------------------------------ the kernel's number type
def leaf_ratio(num, den):
    """The rational q that ``num == q den`` would need (raw values of one tower), read off
    one coordinate of the canonical form (a + b y at each level, an MQ below): the first
    non-zero one of ``den`` along a + b y, its first term (or first coefficient over a
    cyclotomic base, or the quotient of the two over a sparse one); None when ``num`` is
    above that level or that quotient is irrational (then num/den is not rational);
    NotImplemented for other coordinates (the caller divides).  The caller checks
    num == q den exactly: no inverse is made."""
    while type(den) is tuple:
        lev, a, b = den
        na, nb = split(num, lev)
        den, num = (a, na) if not _is_zero(a) else (b, nb)
    if type(num) is tuple:
        return None
    if isinstance(den, MQ) and isinstance(num, MQ) and den:
        m, c = next(iter(den.terms.items()))
        return num.terms.get(m, fmpq(0)) / c
    dp, np_ = getattr(den, "poly", None), getattr(num, "poly", None)
    if dp is None or np_ is None or not den:
        if isinstance(den, SparseCyclotomic) and den and \
                isinstance(num, (SparseCyclotomic, MQ)):
            q = num / den          # a sparse base: a quotient, no inverse; exact test
            return q.to_fmpq() if q.is_rational() else None
        return NotImplemented
    i = 0                      # a cyclotomic base: den's first non-zero coefficient
    while dp[i] == 0:
        i += 1
    return np_[i] / dp[i]


def raw(tower: Tower, other):
    """``other`` as a raw value of ``tower`` (None for a foreign type)."""
    if isinstance(other, TowerElement):
        if other.tower is not tower:
            raise TypeError("elements of two different number fields do not mix")
        return other.v
    return tower.coerce_base(other)


def wrap(tower: Tower, v):
    """A raw value as a kernel number: an MQ at level 0 (any rational), a
    :class:`TowerElement` above (or an irrational of a cyclotomic base)."""
    return tower.wrap(v)


class TowerElement(FieldElement):
    """A number of a :class:`Tower` at level >= 1, or an irrational number of a cyclotomic
    base (exact/cyclotomic_tower.py): never rational (rationals are MQ), never an MQ."""

    __slots__ = ("tower", "v", "_hash")

    #: a number of the analysis kernel: the paper layer's keys read it from balls and F_p
    #: images in large fields (False: the gathering simulator's subclass, whose decisions
    #: keep their exact keys)
    kernel = True

    def __init__(self, tower: Tower, v):
        self.tower, self.v, self._hash = tower, v, None

    def _new(self, v):
        """A raw value of this tower as a number (a subclass keeps its own type)."""
        return wrap(self.tower, v)

    def _bin(self, other, op):
        o = raw(self.tower, other)
        return NotImplemented if o is None else self._new(op(self.v, o))

    def __add__(self, other):
        return self._bin(other, add)

    __radd__ = __add__

    def __sub__(self, other):
        return self._bin(other, sub)

    def __rsub__(self, other):
        return self._bin(other, lambda x, y: sub(y, x))

    def __neg__(self):
        return type(self)(self.tower, neg(self.v))

    def __pos__(self):
        return self

    def __mul__(self, other):
        return self._bin(other, self.tower.mul)

    __rmul__ = __mul__

    def inverse(self):
        return self._new(self.tower.inverse(self.v))

    def __truediv__(self, other):
        o = raw(self.tower, other)
        if o is None:
            return NotImplemented
        if _is_zero(o):
            raise ZeroDivisionError("division by zero")
        return self._new(self.tower.divide(self.v, o))

    def __rtruediv__(self, other):
        o = raw(self.tower, other)
        return NotImplemented if o is None else self._new(self.tower.divide(o, self.v))

    def __pow__(self, k: int):
        if not isinstance(k, int):
            return NotImplemented
        base = self.v if k >= 0 else self.tower.inverse(self.v)
        out, k = self.tower.one, abs(k)
        while k:
            if k & 1:
                out = self.tower.mul(out, base)
            base = self.tower.mul(base, base)
            k >>= 1
        return self._new(out)

    # -- exact comparison -------------------------------------------------------
    def is_zero(self) -> bool:
        return False                     # a number of level >= 1 (b != 0) is never zero

    def is_rational(self) -> bool:
        return False

    def to_fmpq(self) -> fmpq:
        raise ValueError("not a rational number")

    def sign(self) -> int:
        return self.tower.sign(self.v)

    def __eq__(self, other):
        o = raw(self.tower, other)
        return NotImplemented if o is None else self.v == o

    def __ne__(self, other):
        o = raw(self.tower, other)
        return NotImplemented if o is None else self.v != o

    def _cmp(self, other):
        o = raw(self.tower, other)
        if o is None:
            return None
        # disjoint balls decide: the exact difference of two numbers whose sparse base
        # quotients have other denominators cross-multiplies them (issue 9)
        a, b = self.tower.ball(self.v, 64), self.tower.ball(o, 64)
        if a < b:
            return -1
        if a > b:
            return 1
        return self.tower.sign(sub(self.v, o))

    def __hash__(self):
        if self._hash is None:
            self._hash = hash(self.v)
        return self._hash

    def __bool__(self):
        return True

    def __abs__(self):
        return -self if self.sign() < 0 else self

    def enclosure(self, prec: int = 53) -> arb:
        """An ``arb`` ball around the value (filters and drawing only)."""
        return self.tower.ball(self.v, prec + 8 * level(self.v))

    def __float__(self):
        return float(self.enclosure(53).mid())

    def text(self) -> str:
        return text(self.tower, self.v)

    def __repr__(self):
        return f"TowerElement({self.text()!r})"


def key(v):
    """An injective hashable key of a raw value (tags keep levels and MQ parts apart)."""
    if isinstance(v, MQ):
        return ("sqrt",) + tuple(sorted((m, int(c.p), int(c.q)) for m, c in v.terms.items()))
    if type(v) is not tuple:
        poly = getattr(v, "poly", None)     # a PolyElement of a cyclotomic base: canonical
        if poly is None:                    # a sparse base: equality by the zero test
            return ("sparse",) + v.exact_key()
        return ("cyclotomic",) + tuple((int(c.p), int(c.q)) for c in poly.coeffs())
    return ("level", v[0], key(v[1]), key(v[2]))
