"""Real roots counted and excluded: Sturm chains, square-free parts, ball filters.

:func:`sturm_chain` and :func:`variations` count the real roots of a square-free
polynomial in an interval exactly (signs of exact numbers at rationals).
:func:`surely_no_root_in_unit` and :func:`balls_clear_unit` are filters: Arb balls that
prove a polynomial has no root in (0, 1) (True is a proof, False says nothing), so the
exact isolation of :mod:`.roots` runs only where a root may be.
"""

from __future__ import annotations

from flint import arb, arb_mat, ctx, fmpq

from ..multiquadratic import MQ
from .polynomials import pderiv, pdivmod, peval, pgcd, trim

__all__ = ["squarefree", "surely_squarefree", "costly", "surely_no_root_in_unit",
           "balls_clear_unit", "sturm_chain", "variations"]


def squarefree(p) -> tuple:
    """``p`` divided by ``gcd(p, p')``: the same roots, each simple.  Filtered: when an
    Arb enclosure of the discriminant (the Sylvester determinant of ``p`` and ``p'``)
    excludes 0, ``p`` is square-free already and no gcd is computed."""
    if surely_squarefree(p):
        return p
    g = pgcd(p, pderiv(p))
    return p if len(g) <= 1 else pdivmod(p, g)[0]


def surely_squarefree(p, prec: int = 128) -> bool:
    """Does a rigorous enclosure of resultant(p, p') exclude 0?  (Balls of the
    coefficients, :meth:`to_arb`, and ``arb_mat.det``: a proof when True; False says
    nothing.)"""
    n = len(p) - 1
    if n < 2:
        return True
    old = ctx.prec
    ctx.prec = prec
    try:
        top = [c.to_arb(prec) for c in reversed(p)]           # highest degree first
        dtop = [top[k] * (n - k) for k in range(n)]
        size = 2 * n - 1
        rows = [[arb(0)] * k + top + [arb(0)] * (size - k - n - 1) for k in range(n - 1)]
        rows += [[arb(0)] * k + dtop + [arb(0)] * (size - k - n) for k in range(n)]
        return not arb_mat(rows).det().contains(0)
    except (AttributeError, TypeError, ValueError):   # coefficients without balls
        return False
    finally:
        ctx.prec = old


def costly(p) -> bool:
    """Is the exact isolation of ``p`` worth a ball test first: coefficients of several
    terms (a linear or quadratic polynomial with rational coefficients costs less than
    the test), or numbers of a tower or of K(alpha)?"""
    return len(p) > 3 or any(type(c) is not MQ or len(c.terms) > 1 for c in p)


def surely_no_root_in_unit(p, prec: int = 128, depth: int = 6) -> bool:
    """Does a rigorous Arb enclosure prove that ``p`` has no root in the open (0, 1)?
    A filter (True is a proof, False says nothing).  An exact root at 0 or 1 (``p_0``
    zero, or the coefficients' sum zero: additions only) is divided out first (by
    ``f``, by ``f - 1`` synthetically), which keeps the roots inside.  Then each
    coefficient's ball
    (``enclosure``, rigorous for every kernel number), then on each of up to 2^depth
    dyadic pieces X = [a, b] of [0, 1] the ball of p(X) by Horner's rule and by the
    mean value form p(m) + p'(X)(X - m); a piece is cleared when either excludes 0.
    Interval arithmetic encloses every value p(x), x in X, so no piece holds a root.
    The exact isolation (squarefree part, Sturm chain, inverses of coefficients of up
    to 256 terms) is then not needed: most relations of a motion have no root inside
    its piece."""
    p = list(trim(p))
    while len(p) > 1 and p[0].is_zero():
        p.pop(0)
    while len(p) > 1 and sum(p[1:], p[0]).is_zero():
        q = [p[-1]]                         # p = (f - 1) q: q_k = p_(k+1) + q_(k+1)
        for c in reversed(p[1:-1]):
            q.append(c + q[-1])
        p = q[::-1]
    if len(p) < 2:
        return bool(p)
    old = ctx.prec
    ctx.prec = prec
    try:
        return balls_clear_unit([c.enclosure(prec) for c in p], prec, depth)
    except (AttributeError, TypeError, ValueError):   # coefficients without balls
        return False
    finally:
        ctx.prec = old


def balls_clear_unit(cs, prec: int = 128, depth: int = 6) -> bool:
    """Do the balls ``cs`` (coefficients, lowest degree first) prove that every
    polynomial with coefficients in them has no root in the closed [0, 1]?  (The test
    of :func:`surely_no_root_in_unit`, on balls: a caller may build them without the
    exact polynomial.)"""
    if len(cs) < 2:
        return bool(cs) and not cs[0].contains(0)
    if not all(c.is_finite() for c in cs):
        return False
    old = ctx.prec
    ctx.prec = prec
    try:
        ds = [cs[k] * k for k in range(1, len(cs))]

        def horner(coeffs, x):
            v = arb(0)
            for c in reversed(coeffs):
                v = v * x + c
            return v
        at0, at1 = cs[0], horner(cs, arb(1))
        if (at0 > 0 and at1 < 0) or (at0 < 0 and at1 > 0):
            return False                    # a sign change: a root inside, surely
        stack = [(fmpq(0), fmpq(1), 0)]
        while stack:
            a, b, d = stack.pop()
            m = (a + b) / 2
            x = arb(a).union(arb(b))
            if not horner(cs, x).contains(0):
                continue
            if not (horner(cs, arb(m)) + horner(ds, x) * (x - arb(m))).contains(0):
                continue
            if d >= depth:
                return False
            stack += [(a, m, d + 1), (m, b, d + 1)]
        return True
    finally:
        ctx.prec = old


def sturm_chain(p) -> list:
    chain = [trim(p), pderiv(p)]
    while len(chain[-1]) > 1:
        r = pdivmod(chain[-2], chain[-1])[1]
        if not r:
            break
        chain.append(tuple(-c for c in r))
    return [c for c in chain if c]


def variations(chain, x) -> int:
    signs = [s for s in (peval(c, x).sign() for c in chain) if s != 0]
    return sum(1 for a, b in zip(signs, signs[1:]) if a != b)
