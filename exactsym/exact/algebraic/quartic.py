"""Critical instants at roots of quartic factors of group D4, C4 or V4: nested radicals.

A critical instant is a real root of a square-free polynomial with multiquadratic
coefficients (:mod:`.roots`); :func:`.roots.algebraic_root` factors it
over ``K``, its coefficients' multiquadratic field.  A quartic factor ``f`` whose
resolvent cubic has a root in ``K`` (Galois group D4, C4 or V4 over ``K``) has roots
that are nested square roots; this module builds the one in the isolating interval as
a number of a :class:`~.run_tower.RunTower` (Ferrari's method over ``K``).

**Ferrari.**  ``x = y - a_3/4`` depresses ``f`` to ``y^4 + p y^2 + q y + r``.  For any
``z``, ``(y^2 + z/2)^2 = (z - p) y^2 - q y + (z^2/4 - r)``; the right side is a square
in ``y`` iff ``q^2 = (z - p)(z^2 - 4 r)``, i.e. ``z`` is a root of the resolvent
``z^3 - p z^2 - 4 r z + 4 p r - q^2`` (its roots are ``y_1 y_2 + y_3 y_4`` and the
other two pairings).  Take ``z`` in ``K`` (a linear factor of the resolvent over ``K``,
:func:`.factor.factor_over_k`) and ``t = z - p``; then
``t = (y_1 + y_2)^2`` for the pairing of ``z``, and with ``s = sqrt t > 0`` the right
side is ``t (y - q/(2t))^2``, so ``f = g_+ g_-`` with

    ``g_+(y) = y^2 - s y + (z/2 + q/(2s))``,  ``g_-(y) = y^2 + s y + (z/2 - q/(2s))``,

whose roots are ``(s +- sqrt(D_+))/2`` and ``(-s +- sqrt(D_-))/2``,
``D_+- = -p - z -+ 2q/s``.  With ``q = 0`` (``z = p``, ``t = 0``) the quartic is
biquadratic in ``y``: ``y^2 = u``, ``u`` a root of ``u^2 + p u + r``.

**Exactness.**  ``s = sqrt t`` and then ``sqrt D`` are built by
:func:`.run_tower.sqrt_exact` (an MQ when the radicand is a square in the multiquadratic
closure, else a new level of one RunTower per factor, whose square-root test is
complete at every level): at most two levels.  A real root needs ``t > 0`` (with
``q != 0``, a real ``z`` with ``t <= 0`` pairs complex roots: another ``K``-root of the
resolvent is tried).  Which of ``g_+``, ``g_-`` holds the root is decided by exact
signs at the interval's ends (``f`` has one root inside, so exactly one factor changes
sign there), so only that factor's ``sqrt D`` is built; the candidate inside
``(lo, hi)`` is taken, and returned only after ``f(root) == 0`` is checked exactly in
the tower.  Anything else (no ``K``-root with ``t > 0``, a square root the closure test
cannot decide, a check that fails) gives None: the instant stays ``sided``, never a
wrong value.  The same factor gives the same tower (cached), so two Looks at one instant
build equal numbers.
"""

from __future__ import annotations

from functools import lru_cache

from ..multiquadratic import MQ
from .factor import factor_over_k
from .polynomials import peval, shift, trim
from .run_tower import RunTower, sqrt_exact
from .tower_numbers import is_tower, mq_sqrt_any

__all__ = ["quartic_root", "depressed", "resolvent"]

ZERO = MQ()
ONE = MQ.rational(1)


def depressed(f) -> tuple:
    """``(p, q, r)``: ``f(y - a_3/4) = y^4 + p y^2 + q y + r`` for the monic quartic
    ``f`` (coefficients lowest degree first)."""
    g = shift(f, -f[3] / 4)
    g = tuple(g) + (ZERO,) * (5 - len(g))
    return g[2], g[1], g[0]


def resolvent(p, q, r) -> tuple:
    """The resolvent cubic ``z^3 - p z^2 - 4 r z + 4 p r - q^2`` (lowest degree first)."""
    return (p * r * 4 - q * q, -r * 4, -p, ONE)


def _in(x, lo, hi) -> bool:
    return (x - lo).sign() > 0 and (x - hi).sign() < 0


@lru_cache(maxsize=512)
def _split(f: tuple):
    """``(shift, z, t, q)``: ``f(y - shift)`` depressed, ``z`` a root in ``K`` of its
    resolvent with ``t = z - p > 0``; None when there is none (or the factoring gave
    up)."""
    p, q, r = depressed(f)
    factors = factor_over_k(trim(resolvent(p, q, r)))
    for h in factors or ():
        if len(h) == 2 and (-h[0] - p).sign() > 0:
            return f[3] / 4, -h[0], -h[0] - p, q
    return None


@lru_cache(maxsize=1024)
def _factor(f: tuple, sign: int):
    """``(s, c)``: the quadratic factor ``y^2 - sign s y + c`` of ``f(y - shift)``
    (module docstring), ``s = sqrt t`` an MQ or the first level of a RunTower of its own
    (one per factor: the other factor's roots need not enlarge it); None when ``s``
    cannot be decided."""
    _, z, t, q = _split(f)
    try:
        s = sqrt_exact(t)
    except ValueError:
        return None
    return s, z / 2 + sign * q / (s * 2)


@lru_cache(maxsize=1024)
def _quadratic_roots(f: tuple, sign: int):
    """The two roots ``y`` of :func:`_factor`'s ``y^2 - sign s y + c``, exact, in the
    tower of ``s`` (a new RunTower when ``s`` is an MQ); None when its discriminant is
    negative or its root cannot be decided."""
    s, c = _factor(f, sign)
    b = -s * sign
    disc = b * b - c * 4
    if disc.sign() < 0:
        return None
    try:
        w = sqrt_exact(disc, s.tower if is_tower(s) else RunTower())
    except ValueError:
        return None
    return ((-b - w) / 2, (-b + w) / 2)


def _biquadratic_candidates(f, lo, hi):
    """``q = 0``: the roots ``y = +-sqrt(u)``, ``u^2 + p u + r = 0``, as ``x``."""
    p, _, r = depressed(f)
    shift = f[3] / 4
    disc = p * p - r * 4
    if disc.sign() < 0:
        return
    d = mq_sqrt_any(disc)
    if d is None:
        return
    for u in ((-p - d) / 2, (-p + d) / 2):
        if u.sign() <= 0:
            continue
        y = mq_sqrt_any(u)
        if y is None:
            continue
        yield y - shift
        yield -y - shift


def quartic_root(f, lo, hi):
    """The root of the monic irreducible quartic ``f`` (MQ coefficients, lowest degree
    first, a resolvent with a root in ``K``) in ``(lo, hi)`` (rationals; one root of
    ``f`` inside, none at the ends), exact: an MQ or a tower number (module docstring),
    checked ``f(root) == 0``; None when it is not built."""
    if len(f) != 5 or not all(isinstance(c, MQ) for c in f) or not f[4] == ONE:
        return None
    lo_q, hi_q = MQ.rational(lo), MQ.rational(hi)
    _, q, _ = depressed(f)
    if q.is_zero():
        candidates = list(_biquadratic_candidates(f, lo_q, hi_q))
    else:
        split = _split(tuple(f))
        if split is None:
            return None
        shift = split[0]
        candidates = []
        for sign in (1, -1):
            factor = _factor(tuple(f), sign)
            if factor is None:
                return None
            s, c = factor
            # the factor y^2 - sign s y + c that changes sign on the interval holds the root
            ends = [(y * y - s * sign * y + c).sign() for y in (lo_q + shift, hi_q + shift)]
            if ends[0] * ends[1] < 0:
                ys = _quadratic_roots(tuple(f), sign)
                candidates = [y - shift for y in ys or ()]
                break
    for x in candidates:
        if _in(x, lo_q, hi_q) and peval(f, x).is_zero():
            return x
    return None
