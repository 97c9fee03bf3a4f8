"""Square roots in the multiquadratic closure: is ``x`` a square in *some* field
Q(sqrt p_1, ..., sqrt p_k), whatever the primes?

:class:`~.tower.Tower` tests squares in a field with a fixed set of base primes; a level
added for a radicand that is a square once another prime joins the base would break the
tower's canonical form.  :func:`decided_sqrt` answers the question over every
multiquadratic field at once (Kummer theory: a root in a larger field is sqrt(m) times
an element of the field of ``x``'s own radicands), so a radicand it rejects can start a
tower level that no later square root of a rational denests.  :func:`closure_sqrt` is
the older search (sound when it answers, no proof when it does not).
Used by the gathering simulator (critical instants, :mod:`exactsym.gathering.polyroots`)
and by MakeAsym's radial move (:mod:`exactsym.paper.family.make_asym`).
"""

from __future__ import annotations

from math import isqrt

from flint import fmpq, fmpz

from .multiquadratic import MQ, _coprime_base, sqrt_rational
from .tower import TowerElement

__all__ = ["closure_sqrt", "decided_sqrt", "RATIONAL_BITS"]

#: A rational that is not a square and has more bits than this is a miss (its square-free
#: part needs a factorisation that can take minutes), unless ``big_ok``.
RATIONAL_BITS = 160


def closure_sqrt(x, _depth: int = 0, big_ok: bool = False):
    """The non-negative square root of ``x >= 0`` when this search finds it in a
    multiquadratic field, else None (the gathering simulator's ``mq_sqrt``).  With ``b``
    an element of a coprime base of ``x``'s radicands (every radicand is a product of
    distinct base elements), ``x = A + B sqrt(b)`` with ``A``, ``B`` free of ``b``; a root
    ``P + Q sqrt(b)`` has ``P^2 - b Q^2 = +-sqrt(A^2 - b B^2)`` and ``P^2 = (A + that) / 2``:
    square roots one level down, recursively, down to rationals.  Every answer is
    verified by squaring, so a miss is a None, never a wrong root; but a None is no
    proof (the recursion is cut at depth 8, and a rational that is not a square and has
    more than :data:`RATIONAL_BITS` bits is a miss, except ``x`` itself with ``big_ok``):
    :func:`decided_sqrt` is the complete test."""
    if not isinstance(x, MQ):
        x = MQ.rational(x)
    if x.is_zero():
        return MQ()
    if x.sign() < 0 or _depth > 8:
        return None
    if x.is_rational():
        return _sqrt_rational(x.to_fmpq(), big_ok)
    b = max(_coprime_base(x.radicands()))
    A = MQ({m: c for m, c in x.terms.items() if m % b})
    B = MQ({m // b: c for m, c in x.terms.items() if m % b == 0})
    n = closure_sqrt(A * A - B * B * b, _depth + 1)
    if n is None:
        return None
    for half in ((A + n) / 2, (A - n) / 2):
        P = closure_sqrt(half, _depth + 1) if half.sign() >= 0 else None
        if P is None or P.is_zero():
            continue
        y = P + (B / (P * 2)) * MQ({b: fmpq(1)})        # b is square-free
        if y * y == x:
            return y if y.sign() >= 0 else -y
    return None


def decided_sqrt(x):
    """``(root, decided)``: the non-negative square root of ``x >= 0`` in the
    multiquadratic closure, or None; ``decided`` is False only when a rational of more
    than :data:`RATIONAL_BITS` bits would have to be factored (then None proves nothing).
    Only a None with ``decided`` may start a tower level on ``x``.

    Kummer theory makes the search finite: with K = Q(sqrt p : p in P), P the primes of
    ``x``'s radicands, every root of ``x`` in a larger multiquadratic field is
    ``sqrt(m) z`` with ``z`` in K and m a square-free integer.  Down the tower
    K = K_(k-1)(sqrt p_k), ``x = a + b sqrt(p_k)``: for b != 0, ``a^2 - p_k b^2`` must be a
    square ``n^2`` *in* K_(k-1) (m drops out of the norm) and ``(a +- n)/2`` must be
    ``m c^2``; for b = 0, ``a`` or ``a / p_k`` must be.  At Q, ``m c^2`` is any positive
    rational (its root is :func:`sqrt_rational`); a true square is a rational square.
    Every answer is verified by squaring.

    A number of a tower of nested radicals (:class:`~.tower.TowerElement`, level >= 1:
    a critical instant or a position of the gathering simulator) gets its root in its
    own tower (the tower's test, :meth:`~.tower.Tower.root_in`, over all its levels),
    or None: then ``x`` has no root below a new level (complete for a tower whose base
    test is this function, :mod:`exactsym.gathering.run_tower`)."""
    if isinstance(x, TowerElement):
        if x.sign() < 0:
            return None, True
        raw = x.tower.root_in(x.v, x.tower.levels)
        if raw is None:
            return None, True
        root = x._new(raw)
        return (-root if root.sign() < 0 else root), True
    if not isinstance(x, MQ):
        x = MQ.rational(x)
    if x.is_zero():
        return MQ(), True
    if x.sign() < 0:
        return None, True
    primes = sorted({int(p) for m in x.radicands() for p, _ in fmpz(m).factor()})
    unsure: list = []
    root = _kummer_root(x, primes, True, unsure)
    if root is not None:
        root = root if root.sign() >= 0 else -root
        if root * root != x:                    # never: every step is verified
            root = None
    return root, root is not None or not unsure


def _kummer_root(y: MQ, primes, free: bool, unsure: list):
    """A root of ``y`` in K(primes) (``free``: in K(primes)(sqrt m) for some square-free
    m, i.e. ``sqrt(m) z``), or None."""
    if y.is_zero():
        return MQ()
    if y.is_rational():
        q = y.to_fmpq()
        root = _rational_square_root(q)
        if root is not None or q < 0 or not free:
            return root
        root = _sqrt_rational(q, False)
        if root is None:
            unsure.append(y)                 # a large rational, left unfactored
        return root
    if not primes:
        return None
    p, below = primes[-1], primes[:-1]
    a = MQ({m: c for m, c in y.terms.items() if m % p})
    b = MQ({m // p: c for m, c in y.terms.items() if m % p == 0})
    sp = MQ({p: fmpq(1)})
    if b.is_zero():
        for t, mult in ((a, None), (a / p, sp)):
            c = _kummer_root(t, below, free, unsure)
            if c is not None:
                return c if mult is None else c * mult
        return None
    n = _kummer_root(a * a - b * b * p, below, False, unsure)
    if n is None:
        return None
    for t in ((a + n) / 2, (a - n) / 2):
        if t.sign() <= 0:
            continue
        c = _kummer_root(t, below, free, unsure)
        if c is not None and not c.is_zero():
            cand = c + (b / (c * 2)) * sp
            if cand * cand == y:
                return cand
    return None


def _rational_square_root(q: fmpq):
    """The rational root of ``q``, or None (no factoring)."""
    if q < 0:
        return None
    num, den = int(q.p), int(q.q)
    r = isqrt(num * den)
    return MQ.rational(fmpq(r, den)) if r * r == num * den else None


def _sqrt_rational(q: fmpq, big_ok: bool):
    if q < 0:
        return None
    root = _rational_square_root(q)
    if root is not None:
        return root
    num, den = int(q.p), int(q.q)
    if not big_ok and (num * den).bit_length() > RATIONAL_BITS:
        return None
    return sqrt_rational(q)
