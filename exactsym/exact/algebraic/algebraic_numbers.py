"""Numbers of K(alpha): roots of cubic (and other) factors that square roots do not express.

A critical instant of a motion (the gathering simulator's ``instants``) is a real root
``alpha`` of a square-free polynomial ``p`` with multiquadratic coefficients, isolated by
a rational interval (:mod:`.roots`).  Linear and quadratic factors, and the quartics
that square roots solve, are exact already (``MQ`` numbers, tower numbers).  This module
makes the other roots exact: the mover's point at ``tau = alpha`` has coordinates in
``K(alpha)``, and the fresh Look runs on them.

**Factoring first.**  :func:`.factor.factor_over_k` factors ``p`` into irreducible
factors over ``K = Q(sqrt q : q a prime of p's coefficients)`` (Trager's algorithm).
``alpha``'s factor ``f`` is the one that changes
sign on the isolating interval (the interval holds one root of ``p``, a simple one).

**Why reduction modulo f is canonical for every multiquadratic field.**  The gathering code
mixes ``alpha``'s numbers with positions holding square roots that ``K`` lacks (other robots,
layer slots).  So ``f`` must stay irreducible over every multiquadratic extension ``K'`` of
``K``; then ``{1, alpha, ..., alpha^(d-1)}`` is a basis of ``K'(alpha)`` over ``K'``, a number
reduced modulo ``f`` has one representation, ``==`` and ``hash`` are structural, a
non-constant one is never a multiquadratic number, and ``g(alpha) = 0`` iff ``f | g``.

* ``f`` of odd degree ``d``: over ``K' = K(sqrt q)``, ``[K'(alpha):K] = 2 d'`` is a multiple
  of ``d``, so ``d' = d`` (and by induction over any number of square roots).
* ``f`` of degree 4: its Galois group over ``K`` is S4 or A4 iff its resolvent cubic is
  irreducible over ``K`` (tested by the same factoring).  Then ``K(alpha)`` has no field
  strictly between ``K`` and it (the stabiliser of a root, S3 or C3, is maximal), so
  ``sqrt q`` is not in ``K(alpha)`` and ``[K'(alpha):K'] = 4``; the group over ``K'`` is
  again S4 or A4 (index at most 2), so the argument repeats.
* quartics with a reducible resolvent (D4, C4, V4): their roots are nested square roots,
  not numbers of ``K(alpha)`` here; :func:`.roots.algebraic_root` hands the factor to
  :mod:`.quartic` (Ferrari over ``K``: an MQ or a number of a RunTower of at
  most two levels, checked ``f(root) == 0``; None -- ``sided`` -- when it is not built).
* other even degrees: no exact value (``sided``, as before).

**Signs**: an Arb ball of ``alpha`` from its rational interval, refined by bisection (signs
of ``f`` at rationals: an Arb evaluation, exact evaluation when the ball holds 0), and the
element's value at it, precision doubled until the ball excludes 0 (a non-zero element
has a non-zero value, so this ends).  **Square roots** (a radial target of the mover at
the instant): :func:`algebraic_sqrt` finds a root that lies in ``K'(alpha)``, ``K'`` a
multiquadratic field (complete for alpha of odd degree); a root outside (the usual case:
``|p - C|`` of a generic point) is a level of a tower over ``K(alpha)``
(:mod:`.algebraic_tower`, for alpha of odd degree only; for a quartic alpha the caller
gets None, raises ``ValueError`` and the fresh Look at that instant is ``undecided``,
counted as ``skipped``, the Looks just before and after it still running).
"""

from __future__ import annotations

from flint import arb, ctx, fmpq

from ..context import Cache
from ..field import FieldElement
from ..mq_closure import decided_sqrt
from ..multiquadratic import MQ, sum_of_products
from .factor import factor_over_k
from .polynomials import ONE, ZERO, padd, pdivmod, peval, pmul, trim
from .sturm import sturm_chain, variations

__all__ = ["AlgebraicNumber", "AlgebraicRoot", "is_algebraic", "algebraic_sqrt",
           "algebraic_sqrt_decided"]


# -- the number type ------------------------------------------------------------------------
#: f -> [AlgebraicRoot]: one object per root in a run (its context, :mod:`..context`), so
#: the numbers of an instant share it and the levels over it (at most
#: :data:`.algebraic_tower.MAX_LEVELS`) are the run's own, never an earlier run's
_ROOTS = Cache("algebraic roots", shared_outside=True)


class AlgebraicRoot:
    """``alpha``: the root of the monic ``f`` (irreducible over every multiquadratic
    field, :func:`.factor.stable`) in the rational interval ``(lo, hi)``; one object per root
    and run (:meth:`of`), so numbers of the same instant share it."""

    def __init__(self, f: tuple, lo: fmpq, hi: fmpq):
        self.f, self.lo, self.hi = f, lo, hi
        self.degree = len(f) - 1
        self._balls: dict = {}
        self._canonical = None

    def __deepcopy__(self, memo):
        # one object per root: a copied world (the adversary search's forks) keeps it, so
        # its numbers still compare with every other number of the root (its tables only
        # refine intervals and add levels that were proved, in any fork, sound for all)
        return self

    @classmethod
    def of(cls, f: tuple, lo: fmpq, hi: fmpq) -> "AlgebraicRoot":
        known = _ROOTS.table()
        for r in known.setdefault(f, []):
            # (lo, hi) holds one root of f: r's root is in it iff it is the same root
            while not (lo <= r.lo and r.hi <= hi) and not (r.hi <= lo or hi <= r.lo):
                r._bisect()
            if lo <= r.lo and r.hi <= hi:
                return r
        root = cls(f, lo, hi)
        known[f].append(root)
        if len(known) > 4096:            # a bound on the memory, not on correctness
            known.clear()
            known[f] = [root]
        return root

    def _sign_at(self, x: fmpq) -> int:
        with ctx.workprec(128):
            v = arb(0)
            xa = arb(x)
            for c in reversed(self.f):
                v = v * xa + c.enclosure(128)
        if v > 0:
            return 1
        if v < 0:
            return -1
        return peval(self.f, MQ.rational(x)).sign()

    def _bisect(self) -> None:
        mid = (self.lo + self.hi) / 2
        s = self._sign_at(mid)
        if s == 0:
            raise ArithmeticError("a rational root of an irreducible factor")
        if s == self._sign_at(self.lo):
            self.lo = mid
        else:
            self.hi = mid

    def powers(self) -> tuple:
        """``alpha^k`` for ``k = d, ..., 2d - 2`` in the basis ``1, ..., alpha^(d-1)``
        (tuples of d MQ coefficients): the reduction of a product modulo ``f`` (monic)
        as a few products by these fixed, small coefficients."""
        table = self.__dict__.get("_powers")
        if table is None:
            d = self.degree
            top = [ZERO] * (d - 1) + [ONE]              # alpha^(d-1)
            table = []
            for _ in range(d - 1):
                lead = top[-1]                          # alpha * top, alpha^d = -sum f_i alpha^i
                top = [ZERO] + top[:-1]
                if not lead.is_zero():
                    top = [t - lead * fi for t, fi in zip(top, self.f[:d])]
                table.append(tuple(top))
            table = self.__dict__["_powers"] = tuple(table)
        return table

    def ball(self, prec: int) -> arb:
        """An Arb ball holding ``alpha``, of radius below ``2^-prec``."""
        b = self._balls.get(prec)
        if b is None:
            eps = fmpq(1, 1 << prec)
            while self.hi - self.lo > eps:
                self._bisect()
            with ctx.workprec(prec + 32):
                b = arb(self.lo).union(arb(self.hi))
            self._balls[prec] = b
        return b

    def text(self) -> str:
        lo, hi = self.canonical_interval()
        return f"the root of {_poly_text(self.f, 'x')} in ({lo}, {hi})"

    def canonical_interval(self) -> tuple:
        """The largest dyadic interval ``(k/2^j, (k+1)/2^j)`` inside ``(0, 1)``'s halvings
        that holds alpha and no other root of ``f`` (Sturm counts): the same for the same
        root whatever interval it was isolated by, so texts (witnesses, replays) do not
        depend on the history of refinements."""
        if self._canonical is None:
            chain = sturm_chain(self.f)
            lo, hi = fmpq(min(0, self.lo.floor())), fmpq(max(1, self.hi.ceil()))
            while variations(chain, MQ.rational(lo)) - variations(chain, MQ.rational(hi)) > 1:
                mid = (lo + hi) / 2
                while self.lo < mid < self.hi:
                    self._bisect()
                lo, hi = (mid, hi) if self.lo >= mid else (lo, mid)
            self._canonical = (lo, hi)
        return self._canonical


def _poly_text(cs, var: str) -> str:
    """``(c_n)*var^n + ... + (c_0)``, the zero terms left out."""
    terms = []
    for k, c in enumerate(cs):
        if not c.is_zero():
            x = "" if k == 0 else var if k == 1 else f"{var}^{k}"
            terms.append(f"({c.text()})*{x}" if x else f"({c.text()})")
    return " + ".join(reversed(terms))


def _coerce(other):
    if isinstance(other, MQ):
        return other
    if isinstance(other, FieldElement):
        return None
    try:
        return MQ.rational(other)
    except TypeError:
        return None


class AlgebraicNumber(FieldElement):
    """A number of ``K(alpha)``: ``sum c_k alpha^k``, ``k < deg f``, MQ coefficients,
    reduced modulo ``f`` (canonical, module docstring); never an MQ (a constant result of
    arithmetic is returned as its MQ).  Offers the MQ methods the gathering code calls."""

    __slots__ = ("root", "c", "_hash")

    def __init__(self, root: AlgebraicRoot, c: tuple):
        self.root, self.c, self._hash = root, c, None

    def __deepcopy__(self, memo):
        return self                       # immutable, and its root is shared (above)

    def _new(self, c):
        c = trim(c)
        d = self.root.degree
        if len(c) > d:
            if len(c) < 2 * d:      # a product of two reduced numbers: the power table
                low = list(c[:d])
                for ck, row in zip(c[d:], self.root.powers()):
                    if not ck.is_zero():
                        low = [x if r.is_zero() else x + ck * r for x, r in zip(low, row)]
                c = trim(low)
            else:
                c = pdivmod(c, self.root.f)[1]
        if len(c) <= 1:
            return c[0] if c else ZERO
        return AlgebraicNumber(self.root, c)

    def _other(self, other):
        if isinstance(other, AlgebraicNumber):
            if other.root is not self.root:
                raise ValueError("numbers of two different algebraic instants are not mixed")
            return other.c
        o = _coerce(other)
        return None if o is None else ((o,) if not o.is_zero() else ())

    def __add__(self, other):
        o = self._other(other)
        return NotImplemented if o is None else self._new(padd(self.c, o))

    __radd__ = __add__

    def __neg__(self):
        return AlgebraicNumber(self.root, tuple(-x for x in self.c))

    def __pos__(self):
        return self

    def __sub__(self, other):
        o = self._other(other)
        return NotImplemented if o is None else self._new(padd(self.c, tuple(-x for x in o)))

    def __rsub__(self, other):
        return (-self).__add__(other)

    def __mul__(self, other):
        o = self._other(other)
        return NotImplemented if o is None else self._new(pmul(self.c, o))

    __rmul__ = __mul__

    def inverse(self):
        """By the extended Euclidean algorithm with ``f`` (coprime: ``f`` is irreducible
        and this number is not zero)."""
        r0, r1 = self.root.f, self.c
        s0, s1 = (), (ONE,)
        while len(r1) > 1:
            q, r = pdivmod(r0, r1)
            r0, r1 = r1, r
            s0, s1 = s1, padd(s0, tuple(-x for x in pmul(q, s1)))
        inv = 1 / r1[0]
        return self._new(tuple(x * inv for x in s1))

    def __truediv__(self, other):
        if isinstance(other, AlgebraicNumber):
            return self * other.inverse()
        o = _coerce(other)
        if o is None:
            return NotImplemented
        if o.is_zero():
            raise ZeroDivisionError("division by zero")
        inv = 1 / o
        return self._new(tuple(x * inv for x in self.c))

    def __rtruediv__(self, other):
        o = _coerce(other)
        return NotImplemented if o is None else self.inverse() * o

    def _one(self):
        return ONE

    # -- exact comparison ------------------------------------------------------------------
    def __eq__(self, other):
        if isinstance(other, AlgebraicNumber):
            if other.root is not self.root:
                raise ValueError("numbers of two different algebraic instants are not "
                                 "compared here")
            return self.c == other.c
        o = _coerce(other)
        return NotImplemented if o is None else False     # never a multiquadratic number

    def __ne__(self, other):
        eq = self.__eq__(other)
        return eq if eq is NotImplemented else not eq

    def __hash__(self):
        if self._hash is None:
            self._hash = hash((id(self.root), self.c))
        return self._hash

    def _cmp(self, other):
        d = self - other
        return None if d is NotImplemented else d.sign()

    def sign(self) -> int:
        prec = 64
        while prec <= 1 << 16:
            v = self.enclosure(prec)
            if v > 0:
                return 1
            if v < 0:
                return -1
            prec *= 2
        raise ArithmeticError("sign undecided at maximal precision (a non-zero number)")

    def enclosure(self, prec: int = 53) -> arb:
        """An Arb ball around the value (filters and drawing only)."""
        a = self.root.ball(prec + 16)
        with ctx.workprec(prec + 32):
            v = arb(0)
            for x in reversed(self.c):
                v = v * a + x.enclosure(prec + 32)
        return v

    def __float__(self):
        return float(self.enclosure(53).mid())

    def __bool__(self):
        return True

    def __abs__(self):
        return -self if self.sign() < 0 else self

    # -- the MQ methods the gathering code calls ----------------------------------------------
    def is_zero(self) -> bool:
        return False

    def is_rational(self) -> bool:
        return False

    def to_fmpq(self):
        raise ValueError(f"{self.text()} is not rational")


    def text(self) -> str:
        return f"[{_poly_text(self.c, 'a')}, a = {self.root.text()}]"

    def __repr__(self):
        return f"AlgebraicNumber({self.text()!r})"


def is_algebraic(x) -> bool:
    return isinstance(x, AlgebraicNumber)


def _coefficients(x, root):
    """``x``'s coefficients in K(alpha) of ``root`` (an MQ: one), or None (another kind,
    or another root)."""
    if type(x) is AlgebraicNumber:
        return x.c if x.root is root else None
    if type(x) is MQ:
        return (x,) if x.terms else ()
    return None


def algebraic_two_products(a, b, c, d, sign: int):
    """``a b + sign c d`` for numbers of one K(alpha) (or MQ), reduced once: each
    coefficient of the two products summed before one reduction modulo f (the same
    element as the two products reduced apart); None when the four are not all of one
    K(alpha) or MQ."""
    root = a.root if type(a) is AlgebraicNumber else c.root
    cs = [_coefficients(x, root) for x in (a, b, c, d)]
    if any(x is None for x in cs):
        return None
    pa, pb, pc, pd = cs
    size = max(len(pa) + len(pb), len(pc) + len(pd)) - 1
    if size <= 0:
        return ZERO
    out = []
    for k in range(size):
        items = [(1, pa[i], pb[k - i]) for i in range(len(pa)) if 0 <= k - i < len(pb)]
        items += [(sign, pc[i], pd[k - i]) for i in range(len(pc)) if 0 <= k - i < len(pd)]
        out.append(sum_of_products(items) if items else ZERO)
    return AlgebraicNumber(root, ())._new(out)


def _minpoly(u: AlgebraicNumber) -> tuple:
    """The monic minimal polynomial over K of ``u`` (not in K, so of degree d: alpha's
    factor stays irreducible and K(alpha) has no field strictly between, for d prime or
    a quartic of group S4 or A4; otherwise the linear system below is singular and
    ValueError is raised): ``u^d`` in the basis ``1, u, ..., u^(d-1)`` by Gaussian
    elimination over K."""
    d = u.root.degree
    powers, x = [], ONE
    for _ in range(d + 1):
        c = x.c if is_algebraic(x) else (x,)
        powers.append([c[i] if i < len(c) else ZERO for i in range(d)])
        x = u * x
    # rows: coordinates i; unknowns: the coefficients of 1, u, ..., u^(d-1)
    rows = [[powers[k][i] for k in range(d)] + [powers[d][i]] for i in range(d)]
    for col in range(d):
        piv = next((r for r in range(col, d) if not rows[r][col].is_zero()), None)
        if piv is None:
            raise ValueError("u does not generate K(alpha)")
        rows[col], rows[piv] = rows[piv], rows[col]
        inv = 1 / rows[col][col]
        rows[col] = [v * inv for v in rows[col]]
        for r in range(d):
            if r != col and not rows[r][col].is_zero():
                k = rows[r][col]
                rows[r] = [a - k * b for a, b in zip(rows[r], rows[col])]
    return tuple(-rows[i][d] for i in range(d)) + (ONE,)


def _sqrt_in_k_alpha(u: AlgebraicNumber) -> tuple:
    """``(s, decided)``: a square root ``s`` of ``u`` in ``K(alpha)``, or None; one lies
    there iff the minimal polynomial P of ``u`` has ``P(y^2) = +- h(y) h(-y)`` over K, and
    then ``h`` and ``y^2 - u`` share the root ``s``: ``h(y) = A + B y`` modulo ``y^2 - u``,
    ``s = -A/B`` (checked: ``s^2 == u``).  ``decided`` is False when the factoring gave
    up (a norm or a gcd too large)."""
    try:
        P = _minpoly(u)
    except ValueError:
        return None, False
    even = []
    for c in P:
        even += [c, ZERO]
    factors = factor_over_k(trim(even))
    if factors is None:
        return None, False
    for h in factors:
        if len(h) - 1 != u.root.degree:
            continue
        A, B, power = ZERO, ZERO, ONE           # power = u^(k // 2)
        for k, c in enumerate(h):
            if k % 2:
                B = B + c * power
                power = power * u
            else:
                A = A + c * power
        if not (is_algebraic(B) or not B.is_zero()):
            continue
        s = -A / B
        if s * s == u:
            return s, True
    return None, True


def algebraic_sqrt_decided(x) -> tuple:
    """``(root, decided)``: the non-negative square root of ``x > 0`` in ``K'(alpha)``,
    ``K'`` a multiquadratic field (then the representation of :class:`AlgebraicNumber`
    holds it), or None; ``decided``: the search was complete -- for alpha of odd degree
    d: ``x = q t^2`` with ``t`` in K(alpha) and ``sqrt q`` in ``K'`` (the quadratic
    subextensions of ``K'(alpha)/K(alpha)`` come from ``K'/K``), and the norm gives ``q =
    N(x)`` modulo squares of K: so ``sqrt N(x)`` in the multiquadratic closure
    (:func:`~exactsym.exact.mq_closure.decided_sqrt`) times a root of ``x / N(x)`` in
    K(alpha).  For a quartic alpha only roots in K(alpha) itself are searched (never
    ``decided`` when none is found).  Each root is checked by squaring."""
    if x.sign() <= 0:
        return None, True
    s, decided = _sqrt_in_k_alpha(x)
    odd = x.root.degree % 2 == 1
    if s is None and decided and odd:
        norm = -_minpoly(x)[0]                     # N(x) = (-1)^d P(0), d odd
        rn, decided = decided_sqrt(norm) if norm.sign() > 0 else (None, True)
        if rn is not None:
            t, decided = _sqrt_in_k_alpha(x / norm)
            if t is not None:
                s = rn * t
    if s is None:
        return None, decided and odd
    s = s if s.sign() > 0 else -s
    return (s, True) if s * s == x else (None, False)


def algebraic_sqrt(x):
    """:func:`algebraic_sqrt_decided`'s root (None: none in any ``K'(alpha)``, or not
    decided)."""
    return algebraic_sqrt_decided(x)[0]
