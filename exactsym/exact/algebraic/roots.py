"""Exact real roots in (0, 1) of small polynomials with multiquadratic coefficients.

The gathering simulator's "any instant" checks (:mod:`exactsym.gathering.instants`) reduce
each event of a motion (two distances become equal, the SEC's support changes, a symmetry
appears) to a root of a polynomial of degree at most 4 in the piece's parameter ``f`` (a
segment is linear in ``f``; an arc is rational in ``f`` with the denominator
``1 + T^2 f^2``, cleared).  Its coefficients are
:class:`~exactsym.exact.multiquadratic.MQ` elements.

A root is a :class:`Root`: a rational isolating interval ``(lo, hi)`` holding exactly
one root of its polynomial (Sturm sequences over the coefficient field, exact signs),
and, when the kernel can hold it, its exact value (``exact``: a root of a linear
factor, or a quadratic's root whose discriminant is a square in the multiquadratic
field, found by :func:`mq_sqrt`), or -- when it needs a nested radical -- a number of a
tower of quadratic extensions over that field (:mod:`.tower_numbers`): a quadratic
whose discriminant is a square in no multiquadratic field, or a biquadratic quartic
``a f^4 + b f^2 + c`` (:func:`exact_root_hook`); or -- a root of a factor of degree 3
or more -- a number of ``K(alpha)`` (:mod:`.algebraic_numbers`: the polynomial factored
over its coefficients' field K, numbers reduced modulo alpha's factor); or -- a root of
a quartic factor of group D4, C4 or V4 -- a nested radical again, an MQ or a number of a
RunTower (:mod:`.quartic`, Ferrari over K).  The roots those modules leave
without a value (factors of other even degrees, a root whose square roots cannot be
decided) stay isolated by rationals only (``sided`` instants).

:func:`separate` refines a list of roots until their intervals are pairwise disjoint,
merging roots that are equal (same exact value, or a common root of the two polynomials:
their gcd vanishes inside the overlap).  No float decides anything.

Polynomials are tuples of coefficients, lowest degree first.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from flint import fmpq

from ...errors import FieldTooLargeError

from ..mq_closure import closure_sqrt, decided_sqrt
from ..multiquadratic import MQ
from .algebraic_numbers import AlgebraicNumber, AlgebraicRoot, is_algebraic
from .algebraic_tower import is_algebraic_tower, own_sqrt_over_k_alpha, sqrt_over_k_alpha
from .factor import changes_sign, factor_over_k, stable
from .polynomials import ONE, ZERO, pdivmod, peval, pgcd, trim
from .quartic import quartic_root
from .sturm import costly, squarefree, sturm_chain, surely_no_root_in_unit, variations
from .tower_numbers import biquadratic_root, is_tower, quadratic_root, tower_sqrt

__all__ = ["Root", "roots_in_unit", "roots_of", "separate", "separate_inside", "bracket",
           "same_root", "exact_root_hook", "algebraic_root", "mq_sqrt"]


# -- square roots in the multiquadratic field ------------------------------------------
def mq_sqrt(x, _depth: int = 0, big_ok: bool = False):
    """The non-negative square root of ``x >= 0`` when it lies in a multiquadratic field,
    else None (:func:`exactsym.exact.mq_closure.closure_sqrt`: a recursive denesting
    verified by squaring; a rational that is not a square and has more than
    :data:`RATIONAL_BITS` bits is a miss, except ``x`` itself with ``big_ok``).  For a
    tower number ``x`` (:mod:`.tower_numbers`) the answer is its root in the tower, a new
    level when it has none there (None only when that cannot be decided); for a number
    of ``K(alpha)`` (:mod:`.algebraic_numbers`) its root there or one level over it
    (:mod:`.algebraic_tower`)."""
    if is_algebraic(x) or is_algebraic_tower(x):   # K(alpha), or one level over it
        return sqrt_over_k_alpha(x)
    if is_tower(x):                     # a tower number: its root in the tower
        return tower_sqrt(x) if x.sign() > 0 else None
    return closure_sqrt(x, _depth, big_ok)


def _disc_root(disc):
    """A discriminant's root in the multiquadratic closure, or None: the complete test
    (:func:`~exactsym.exact.mq_closure.decided_sqrt`, a finite search), not
    :func:`mq_sqrt`'s, whose recursion can branch thousands of times before it gives up.
    A discriminant of a run whose positions are not multiquadratic (a start in a RunTower
    or in ``K(alpha)``, ``gathering.start_numbers``): its root in its own field or one
    level over it (:func:`mq_sqrt`), None when that is not built (the instant is then
    ``sided``)."""
    if isinstance(disc, MQ):
        return decided_sqrt(disc)[0]
    return _field_sqrt(disc)


def _field_sqrt(x):
    """The non-negative root of a tower number or a number of K(alpha), or None when it
    is negative or its square root cannot be built or decided."""
    try:
        if x.sign() < 0:
            return None
        # a discriminant of K(alpha): a one-level tower of its own, as an MQ radicand's
        return own_sqrt_over_k_alpha(x) if is_algebraic(x) else mq_sqrt(x)
    except (ValueError, ArithmeticError, FieldTooLargeError):
        return None


def _field_quartic_root(poly, lo, hi):
    """A cubic or quartic with coefficients of a tower or of K(alpha): a biquadratic
    ``a f^4 + b f^2 + c`` (``f = sqrt u``, ``u`` a root of ``a u^2 + b u + c``), or one
    with a factor ``h(f^2)`` of its even and odd parts (an arc's denominator), each factor
    of degree at most 2 solved; None otherwise."""
    if len(poly) == 5 and poly[1].is_zero() and poly[3].is_zero() and lo >= 0:
        c, _, b, _, a = poly
        inv = 1 / a
        bm, cm = b * inv, c * inv
        y = _field_sqrt(bm * bm - cm * 4)
        for u in (() if y is None else ((-bm - y) / 2, (-bm + y) / 2)):
            f = _field_sqrt(u) if u.sign() > 0 else None
            if f is not None and (f - lo).sign() > 0 and (f - hi).sign() < 0:
                return f
        return None
    even = trim(c if k % 2 == 0 else ZERO for k, c in enumerate(poly))
    odd = trim(poly[k + 1] if k % 2 == 0 and k + 1 < len(poly) else ZERO
               for k in range(len(poly) - 1))
    h = pgcd(even, odd) if odd else ()
    if 1 < len(h) < len(poly):
        for factor in (h, pdivmod(poly, h)[0]):
            if len(factor) <= 3 and changes_sign(factor, lo, hi):
                r = exact_root_hook(factor, lo, hi)
                if r is not None:
                    return r
    return None


def _field_quadratic_root(c, b, a, lo, hi):
    """The root in ``(lo, hi)`` of ``a f^2 + b f + c`` with coefficients of a tower or of
    K(alpha) (:func:`_field_sqrt` of the discriminant), or None."""
    inv = 1 / a
    bm, cm = b * inv, c * inv
    y = _field_sqrt(bm * bm - cm * 4)
    if y is None:
        return None
    for r in ((-bm - y) / 2, (-bm + y) / 2):
        if (r - lo).sign() > 0 and (r - hi).sign() < 0:
            return r
    return None


def exact_root_hook(poly, lo, hi):
    """The exact value of the root of ``poly`` (square-free) in ``(lo, hi)`` when it
    needs a nested radical, as a tower number (:mod:`.tower_numbers`): a quadratic (its
    discriminant a square in no multiquadratic field), a biquadratic quartic
    ``a f^4 + b f^2 + c``, or a cubic or quartic with a factor ``h(f^2)`` (the common
    factor of its even and odd parts: an arc's denominator ``1 + T^2 f^2`` times a
    relation, for example), whose two factors are solved in turn.  Any other polynomial
    of degree 3 or more is factored over its coefficients' field
    (:func:`algebraic_root`): a root of a factor of degree 3, 5, ...
    or of a quartic factor of group S4 or A4 is a number of ``K(alpha)``, one of a
    quartic factor of group D4, C4 or V4 a nested radical (:mod:`.quartic`);
    None for the rest, whose instants are only seen on both sides (``sided``).
    Coefficients of a tower or of K(alpha) (a start beyond the multiquadratic field): the
    linear root, a quadratic's root (:func:`_field_quadratic_root`), else None."""
    if not all(isinstance(c, MQ) for c in poly):
        if len(poly) == 2:
            r = _linear_root(poly)
            return r if (r - lo).sign() > 0 and (r - hi).sign() < 0 else None
        if len(poly) == 3:
            return _field_quadratic_root(poly[0], poly[1], poly[2], lo, hi)
        if len(poly) in (4, 5):
            return _field_quartic_root(poly, lo, hi)
        return None
    if len(poly) == 2:
        r = _linear_root(poly)
        return r if (r - lo).sign() > 0 and (r - hi).sign() < 0 else None
    if len(poly) == 3:
        c, b, a = poly
        return quadratic_root(c, b, a, lo, hi)
    if len(poly) == 5 and poly[1].is_zero() and poly[3].is_zero() and lo >= 0:
        return biquadratic_root(poly, lo, hi)
    if len(poly) in (4, 5):
        even = trim(c if k % 2 == 0 else ZERO for k, c in enumerate(poly))
        odd = trim(poly[k + 1] if k % 2 == 0 and k + 1 < len(poly) else ZERO
                   for k in range(len(poly) - 1))
        h = pgcd(even, odd) if odd else ()
        if 1 < len(h) < len(poly):
            for factor in (h, pdivmod(poly, h)[0]):
                r = exact_root_hook(factor, lo, hi)
                if r is not None:
                    return r
    if len(poly) >= 4:      # factored over K: a root of K(alpha) (algebraic_numbers)
        return algebraic_root(poly, lo, hi)
    return None


def algebraic_root(p, lo, hi):
    """The root of the square-free ``p`` in ``(lo, hi)`` (rationals, one root of ``p``
    inside, none at the ends), exact: an MQ (a linear factor over K), the factor's
    quadratic root (tower numbers, :func:`.tower_numbers.quadratic_root`), or an
    :class:`AlgebraicNumber` (a factor of odd degree, or a quartic with an S4 or A4 group),
    or for a quartic of group D4, C4 or V4 a nested radical (an MQ or a tower number,
    :func:`.quartic.quartic_root`); None otherwise (other even degrees, such a
    quartic whose root :mod:`.quartic` does not build, a norm too big,
    coefficients that are not multiquadratic: a run's tower numbers)."""
    if not all(isinstance(c, MQ) for c in p):
        return None
    factors = factor_over_k(trim(p))
    if factors is None:
        return None
    held = [f for f in factors if changes_sign(f, lo, hi)]
    if len(held) != 1:
        return None
    f = held[0]
    if len(f) == 2:
        return -f[0]
    if len(f) == 3:
        return quadratic_root(f[0], f[1], f[2], lo, hi)
    if not stable(f):
        if len(f) == 5:              # D4, C4 or V4: nested square roots (Ferrari over K)
            return quartic_root(f, lo, hi)
        return None
    root = AlgebraicRoot.of(f, fmpq(lo), fmpq(hi))
    return AlgebraicNumber(root, (ZERO, ONE))


# -- roots ---------------------------------------------------------------------------
@dataclass
class Root:
    """One real root in ``(lo, hi)`` (rationals, ``lo < hi``), of ``poly`` (square-free);
    ``exact``: its value when the kernel holds it; ``tags``: what the root means (one
    per polynomial merged into it)."""
    poly: tuple
    lo: fmpq
    hi: fmpq
    exact: object = None            # MQ, a tower number, a number of K(alpha), or None
    tags: list = field(default_factory=list)

    def _sign_at(self, x) -> int:
        if self.exact is not None:
            return (self.exact - x).sign()      # > 0: the root is right of x
        return peval(self.poly, x).sign()

    def refine(self) -> None:
        """Halve the interval (exactly)."""
        mid = (self.lo + self.hi) / 2
        if self.exact is not None:
            s = (self.exact - mid).sign()
            if s == 0:                                    # the root is rational: pin it
                w = (self.hi - self.lo) / 4
                self.lo, self.hi = mid - w, mid + w
            elif s > 0:
                self.lo = mid
            else:
                self.hi = mid
            return
        s_lo, s_mid = peval(self.poly, self.lo).sign(), peval(self.poly, mid).sign()
        if s_mid == 0:                       # a rational root (of a cubic or quartic)
            self.exact = MQ.rational(mid)
            w = (self.hi - self.lo) / 4
            self.lo, self.hi = mid - w, mid + w
            return
        if s_lo * s_mid < 0:
            self.hi = mid
        else:
            self.lo = mid


def _linear_root(p):
    return -p[0] / p[1]


def roots_in_unit(poly, tag=None) -> list:
    """The distinct real roots of ``poly`` strictly inside (0, 1), as :class:`Root`\\ s.
    A polynomial that is identically zero has no isolated roots (the relation holds
    along the whole piece): ``[]``."""
    p = trim(poly)
    if len(p) <= 1 or (costly(p) and surely_no_root_in_unit(p)):
        return []
    out: list = []
    if len(p) > 3:
        p = squarefree(p)           # (a quadratic's double root: its discriminant is 0)
    # exact roots first: linear polynomials, quadratics with a square discriminant
    if len(p) == 2:
        r = _linear_root(p)
        if r.sign() > 0 and (r - 1).sign() < 0:
            out.append(bracket(p, r, tag))
        return out
    if len(p) == 3:
        c, b, a = p
        disc = b * b - a * c * 4
        if disc.sign() < 0 or _none_inside(p):
            return []
        root = _disc_root(disc)
        if root is not None:
            for r in {(-b - root) / (a * 2), (-b + root) / (a * 2)}:
                if r.sign() > 0 and (r - 1).sign() < 0:
                    out.append(bracket(p, r, tag))
            return out
    # otherwise: Sturm isolation; a rational root met on the way is divided out
    return _isolate(p, fmpq(0), fmpq(1), tag)


def _none_inside(p) -> bool:
    """Does the quadratic ``p`` have no root in (0, 1)?
    Decided from signs alone, exactly, with no division: an inverse of a coefficient
    with k primes in its radicands is k products of numbers of up to 2^k terms (it went
    through a Sturm chain before), and the check spares the square root of the discriminant (a
    bounded factorisation beyond 160 bits) for the many relations whose roots lie
    outside the piece.  With ``p = a t^2 + b t + c``: ends of opposite signs hold one
    root between them; ends of the sign opposite to ``a`` lie between the two roots;
    ends of ``a``'s sign hold both roots or none, both exactly when the vertex
    ``-b / 2a`` lies inside and the discriminant is not negative (a double root there
    counts as inside)."""
    c, b, a = p
    s0, s1 = c.sign(), (a + b + c).sign()
    if s0 == 0 or s1 == 0 or s0 != s1:
        return False
    sa = a.sign()
    if s0 != sa:
        return True
    if (-b).sign() == sa and (a * 2 + b).sign() == sa:
        return (b * b - a * c * 4).sign() < 0
    return True


def bracket(p, r: MQ, tag) -> Root:
    """A rational interval around the exact root ``r`` of ``p`` in (0, 1)."""
    lo, hi = fmpq(0), fmpq(1)
    root = Root(p, lo, hi, r, [tag] if tag is not None else [])
    # a float guess, then exact checks (the float only proposes)
    try:
        x = float(r)
        k = 1 << 20
        guess_lo, guess_hi = fmpq(int(x * k) - 1, k), fmpq(int(x * k) + 2, k)
        if (r - guess_lo).sign() > 0 and (r - guess_hi).sign() < 0:
            root.lo, root.hi = max(guess_lo, lo), min(guess_hi, hi)
    except (OverflowError, ValueError):
        pass
    return root


def _isolate(p, lo, hi, tag) -> list:
    """Roots of square-free ``p`` in the open interval (lo, hi), endpoints not roots
    (a rational root found at an endpoint or a midpoint is divided out and kept exact)."""
    out = []
    for end in (lo, hi):
        if peval(p, end).is_zero():
            p = pdivmod(p, (MQ.rational(-end), MQ.rational(1)))[0]
    chain = sturm_chain(p)
    stack = [(lo, hi)]
    while stack:
        a, b = stack.pop()
        n = variations(chain, a) - variations(chain, b)
        if n == 0:
            continue
        if n == 1:
            out.append(Root(p, a, b, _exact_in(p, a, b), [tag] if tag is not None else []))
            continue
        mid = (a + b) / 2
        if peval(p, mid).is_zero():
            out.append(bracket(p, MQ.rational(mid), tag))
            out[-1].lo, out[-1].hi = (a + mid) / 2, (mid + b) / 2
            p = pdivmod(p, (MQ.rational(-mid), MQ.rational(1)))[0]
            chain = sturm_chain(p)
            stack.append((a, b))                 # the rest of this interval, again
            # (mid is no longer a root of p; the recount sees the others)
            continue
        stack += [(a, mid), (mid, b)]
    return out


def _exact_in(p, a, b):
    """The exact value of the one root of ``p`` in (a, b) when a linear or
    square-discriminant quadratic factor holds it (a factor found by the gcd with
    ``p``'s derivative cannot help: ``p`` is square-free), else the hook's answer."""
    if len(p) == 2:
        return _linear_root(p)
    if len(p) == 3:
        c, bb, aa = p
        root = _disc_root(bb * bb - aa * c * 4)
        if root is not None:
            for r in ((-bb - root) / (aa * 2), (-bb + root) / (aa * 2)):
                if (r - a).sign() > 0 and (r - b).sign() < 0:
                    return r
    return exact_root_hook(p, a, b)


def same_root(r: Root, s: Root) -> bool:
    """Do two roots with overlapping intervals coincide?  Exactly: equal exact values; an
    exact value that is a root of the other's polynomial inside its interval (which
    holds one root only); or the gcd of the two polynomials has a root in the overlap."""
    if r.exact is not None and s.exact is not None and _comparable(r.exact, s.exact):
        return r.exact == s.exact
    if r.exact is not None or s.exact is not None:
        e, o = (r, s) if r.exact is not None else (s, r)
        return ((e.exact - o.lo).sign() > 0 and (e.exact - o.hi).sign() < 0
                and peval(o.poly, e.exact).is_zero())
    g = pgcd(r.poly, s.poly)
    if len(g) <= 1:
        return False
    lo, hi = max(r.lo, s.lo), min(r.hi, s.hi)
    if lo >= hi:
        return False
    if peval(g, lo).is_zero() or peval(g, hi).is_zero():
        # the overlap's end is a rational root of both: then it is the one root of each
        return True
    chain = sturm_chain(squarefree(g))
    return variations(chain, lo) - variations(chain, hi) > 0


def _comparable(x, y) -> bool:
    """Can ``==`` decide: not two numbers of different towers (their canonical forms
    differ even for equal values; :func:`_same_root` then uses a polynomial), nor of two
    different roots' fields (:mod:`.algebraic_numbers`)."""
    if is_tower(x) and is_tower(y):
        return x.tower is y.tower
    if is_algebraic(x) and is_algebraic(y):        # two instants' fields: not mixed
        return x.root is y.root
    return True


def separate(roots: list, max_rounds: int | None = None) -> list:
    """Merge equal roots and refine the others until the closed intervals are pairwise
    disjoint; sorted by position.  The budget grows with the number of roots: each pair of
    equal roots takes about 24 refinements before it is merged (a sweep run had 27 roots,
    17 of them repeats from several families, and a fixed 400 rounds ran out)."""
    roots = list(roots)
    if max_rounds is None:
        max_rounds = 400 + 64 * len(roots)
    for _ in range(max_rounds):
        roots.sort(key=lambda r: (r.lo, r.hi))
        clash = None
        for a, b in zip(roots, roots[1:]):
            if b.lo <= a.hi:
                clash = (a, b)
                break
        if clash is None:
            return roots
        a, b = clash
        if (a.hi - a.lo) < fmpq(1, 1 << 24) and (b.hi - b.lo) < fmpq(1, 1 << 24) \
                and same_root(a, b):
            keep = a if a.exact is not None or b.exact is None else b
            other = b if keep is a else a
            keep.tags += other.tags
            keep.lo, keep.hi = max(a.lo, b.lo), min(a.hi, b.hi)
            if keep.lo >= keep.hi:      # touching at one rational end: that is the root
                keep.lo, keep.hi = keep.lo - (a.hi - a.lo), keep.hi + (b.hi - b.lo)
            roots.remove(other)
            continue
        a.refine()
        b.refine()
    raise ArithmeticError("root separation did not finish")


def separate_inside(roots: list) -> list:
    """:func:`separate`, then each interval kept strictly inside (0, 1), so that the points
    just before and just after a root lie inside the piece."""
    roots = separate(roots)
    for r in roots:
        while r.lo == 0 or r.hi == 1:
            r.refine()
    return separate(roots)


def roots_of(polys, extra=()) -> list:
    """The roots in (0, 1) of every ``(poly, tag)``, with ``extra`` roots, separated and
    kept strictly inside (:func:`separate_inside`): the critical instants of a motion."""
    roots = [r for poly, tag in polys for r in roots_in_unit(poly, tag)]
    return separate_inside(roots + list(extra))
