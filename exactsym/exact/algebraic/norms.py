"""Where a polynomial is negative on [0, 1], exactly: rational norms and certified roots.

Two discs moving at once overlap when a polynomial in the common time (their squared
distance minus 4, denominators cleared) is negative somewhere in [0, 1]; its
coefficients are multiquadratic numbers, or numbers of a run's tower of nested
radicals.  :func:`negative_instant` finds the earliest rational sample where it is:
the real roots of the polynomial lie among those of its rational norm (the product of
its conjugates: :func:`tower_norm` over the tower's levels, then over a coprime base of
the radicands), isolated by python-flint's certified ``complex_roots``; between two
consecutive roots the sign is constant, so one rational sample per gap, evaluated
exactly, decides.
"""

from __future__ import annotations

from fractions import Fraction

from flint import fmpq, fmpq_poly

from ..multiquadratic import MQ, coprime_base
from ..tower import neg as tuple_neg
from .polynomials import peval, pmul, trim

__all__ = ["negative_instant", "tower_norm", "rational_norm"]


def tower_norm(f):
    """For coefficients in a tower of nested radicals (a run's positions after a
    nested-radical radial move, :mod:`.run_tower`): the product of ``f``'s conjugates
    over the tower's levels, top level first (``y_L -> -y_L`` is an automorphism of K_L
    over K_(L-1), and the product ``f * conj(f)`` has its coefficients in K_(L-1)): MQ
    coefficients, every real root of ``f`` among its roots.  ``f`` unchanged when its
    coefficients are MQ."""
    towers = {id(a.tower): a.tower for a in f if hasattr(a, "tower")}
    if not towers:
        return f
    if len(towers) > 1:
        raise ValueError("a polynomial over two towers of nested radicals")
    (tower,) = towers.values()
    for lev in range(tower.levels, 0, -1):
        f = trim(pmul(f, [_conjugate_level(a, lev) for a in f]))
    return f


def _conjugate_level(a, lev: int):
    """``a`` (of level <= ``lev``) with the generator of level ``lev`` negated."""
    v = getattr(a, "v", None)
    if type(v) is not tuple or v[0] != lev:
        return a
    return a._new((lev, v[1], tuple_neg(v[2])))


def rational_norm(f):
    """The product of the Galois conjugates of ``f``: rational coefficients, and every
    real root of ``f`` is one of its roots (over a tower: :func:`tower_norm` first)."""
    f = tower_norm(f)
    rads = sorted({m for a in f for m in a.radicands()})
    for b in coprime_base(rads):
        f = trim(pmul(f, [a.conjugate(b) for a in f]))
    return [a.to_fmpq() for a in f]


def _dyadic(x):
    man, exp = x.man_exp()
    return fmpq(man) * fmpq(2) ** int(exp) if exp >= 0 else fmpq(man, 2 ** int(-exp))


def _simplest_between(lo, hi):
    """The rational with the smallest denominator strictly between ``lo < hi``
    (continued fractions): short witnesses."""
    def inner(a, b):
        fl = a.numerator // a.denominator
        if fl + 1 < b:
            return Fraction(fl + 1)
        if a == fl:
            return fl + Fraction(1, int(1 / (b - fl)) + 1)
        return fl + 1 / inner(1 / (b - fl), 1 / (a - fl))
    x = inner(Fraction(int(lo.p), int(lo.q)), Fraction(int(hi.p), int(hi.q)))
    return fmpq(x.numerator, x.denominator)


def negative_instant(f):
    """A rational ``tau`` in [0, 1] (a ``Fraction``, the earliest sample) with
    ``f(tau) < 0``, or None when ``f >= 0`` on
    all of [0, 1].  Exact: the real roots of ``f`` lie among those of its rational norm,
    isolated by certified balls (python-flint's ``complex_roots``: real roots come with
    an exactly zero imaginary part); between two consecutive roots ``f`` keeps its sign,
    so one rational sample per gap, evaluated exactly, decides."""
    f = trim(f)
    if not f:
        return None                                   # f = 0: touching all along
    samples = [fmpq(0), fmpq(1)]
    if len(f) > 1:
        norm = fmpq_poly(rational_norm(f))
        bounds = [(fmpq(0), fmpq(0))]
        for root, _mult in norm.numer().complex_roots():
            if not (root.imag.is_exact() and root.imag == 0):
                continue
            lo, hi = _dyadic(root.real.lower()), _dyadic(root.real.upper())
            if hi > 0 and lo < 1:
                bounds.append((lo, hi))
        bounds.append((fmpq(1), fmpq(1)))
        bounds.sort()
        for (_, left), (right, _) in zip(bounds, bounds[1:]):
            if left < right:
                samples.append(_simplest_between(left, right))
    for t in sorted(samples):
        if 0 <= t <= 1 and peval(f, MQ.rational(t)).sign() < 0:
            return Fraction(int(t.p), int(t.q))
    return None
