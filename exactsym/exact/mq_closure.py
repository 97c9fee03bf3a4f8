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

import random
from functools import lru_cache
from math import gcd, isqrt

from flint import fmpq, fmpz

from .factor import is_prime
from .multiquadratic import MQ, coprime_base, sqrt_rational
from .tower import TowerElement, denominator
from .modular import image, sqrt_mod

__all__ = ["closure_sqrt", "decided_sqrt", "bounded_squarefree_split", "RATIONAL_BITS",
           "SMOOTH_BITS"]

#: A rational that is not a square and has more bits than this is not factored in full
#: (that can take minutes), unless ``big_ok``: its square-free part is then sought by
#: :func:`bounded_squarefree_split`, and a miss when that cannot tell.
RATIONAL_BITS = 160

#: The size of the prime factors that :func:`bounded_squarefree_split` looks for (ECM,
#: ``fmpz.factor_smooth``): a bounded effort, whatever the integer.
SMOOTH_BITS = 48

#: A composite that ECM leaves (no prime factor below :data:`SMOOTH_BITS` bits found) is
#: factored in full when it has at most this many bits: ``fmpz.factor``'s quadratic sieve
#: takes 1.3 s at 178 bits, 2.6 s at 193 and 8 s at 212 (two primes of 90 and 123 bits,
#: the largest the gathering sweep meets); a larger one stays unresolved.
FULL_FACTOR_BITS = 216


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
    b = max(coprime_base(x.radicands()))
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


def decided_sqrt(x, bounded: bool = True):
    """``(root, decided)``: the non-negative square root of ``x >= 0`` in the
    multiquadratic closure, or None; ``decided`` is False only when ``x`` has a root,
    ``sqrt(m) w``, and the integer m (more than :data:`RATIONAL_BITS` bits) has a
    square-free part that :func:`bounded_squarefree_split` cannot tell (then None proves
    nothing).  Only a None with ``decided`` may start a tower level on ``x``.
    ``bounded=False`` leaves out the bounded split (a root with such an m is then
    undecided): the paper layer's MakeAsym move (:mod:`.adjoin_sqrt`), where a root
    found there makes the check analyse a moved copy of the whole configuration in a
    larger field (100,000 random points: 14 s instead of 2 s), as before the split.

    Kummer theory makes the search finite: with K = Q(sqrt p : p in P), P the primes of
    ``x``'s radicands, every root of ``x`` in a larger multiquadratic field is
    ``sqrt(m) z`` with ``z`` in K and m a square-free integer.  Down the tower
    K = K_(k-1)(sqrt p_k), ``x = a + b sqrt(p_k)``: for b != 0, ``a^2 - p_k b^2`` must be a
    square ``n^2`` *in* K_(k-1) (m drops out of the norm) and ``(a +- n)/2`` must be
    ``m c^2``; for b = 0, ``a`` or ``a / p_k`` must be.  At Q, ``m c^2`` is any positive
    rational; a true square is a rational square.  The search carries m unfactored
    (:func:`_kummer_root`), so deciding that ``x`` has no root factors nothing; only a
    root found is written with m's square-free part (:func:`sqrt_rational` up to
    :data:`RATIONAL_BITS` bits, :func:`bounded_squarefree_split` beyond).  Every answer
    is verified by squaring.

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
    return _decided_sqrt_mq(x, bounded)


@lru_cache(maxsize=1 << 14)
def _radicand_primes(m: int) -> tuple:
    """The primes of the square-free radicand ``m`` (a full factorisation, remembered:
    the search meets the same few radicands in number after number, and factoring
    them again took a quarter of a joint-step search's time at n = 8)."""
    return tuple(int(p) for p, _ in fmpz(m).factor())


@lru_cache(maxsize=256)       # keys of up to 256 terms of thousands of bits
def _decided_sqrt_mq(x: MQ, bounded: bool):
    """:func:`decided_sqrt` of an MQ, remembered: a function of the value alone (the
    search and its modular filter are deterministic, and the answer is the non-negative
    root or None), and a critical instant's discriminant is tested two or three times
    (the quadratic's, again in the isolation, then the monic one's)."""
    if x.is_zero():
        return MQ(), True
    if x.sign() < 0:
        return None, True
    primes = sorted({p for m in x.radicands() for p in _radicand_primes(m)})
    found = _kummer_root(x, primes, True)
    if found is None:
        return None, True
    m, w = found
    if m == 1:
        root = w
    else:
        s = _sqrt_rational(fmpq(m), False, x if bounded else None, bounded)
        if s is None:                           # sqrt(m): m's square-free part unknown
            return None, False
        root = s * w
    root = root if root.sign() >= 0 else -root
    if root * root != x:                        # never: every step is verified
        return None, False
    return root, True


def _kummer_root(y: MQ, primes, free: bool):
    """A root of ``y`` in K(primes), or None; with ``free``, a root in K(primes)(sqrt m)
    for some integer m, as ``(m, w)``: the root is ``sqrt(m) w`` with ``w`` in K(primes).
    ``m`` is kept as an integer, unfactored (only its square class matters, and it is a
    common factor of every candidate above it): the search decides whether a root exists
    without factoring anything; :func:`decided_sqrt` needs m's square-free part only to
    write a root it has found."""
    if y.is_zero():
        return (1, MQ()) if free else MQ()
    if y.is_rational():
        q = y.to_fmpq()
        root = _rational_square_root(q)
        if not free:
            return root
        if root is not None:
            return 1, root
        if q < 0:
            return None
        num, den = int(q.p), int(q.q)
        return num * den, MQ.rational(fmpq(1, den))      # sqrt(num/den) = sqrt(num den)/den
    if not primes:
        return None
    if len(y.terms) > 2 and _refuted_modulo(y, primes, free):
        return None
    p, below = primes[-1], primes[:-1]
    a = MQ({m: c for m, c in y.terms.items() if m % p})
    b = MQ({m // p: c for m, c in y.terms.items() if m % p == 0})
    sp = MQ({p: fmpq(1)})
    if b.is_zero():
        for t, mult in ((a, None), (a / p, sp)):
            c = _kummer_root(t, below, free)
            if c is not None:
                if mult is None:
                    return c
                return (c[0], c[1] * mult) if free else c * mult
        return None
    n = _kummer_root(a * a - b * b * p, below, False)
    if n is None:
        return None
    for t in ((a + n) / 2, (a - n) / 2):
        if t.sign() <= 0:
            continue
        c = _kummer_root(t, below, free)
        if c is None:
            continue
        m, w = c if free else (1, c)
        if w.is_zero():
            continue
        # (sqrt(m) w + b / (2 sqrt(m) w) sqrt(p)) = sqrt(m) (w + b / (2 m w) sqrt(p))
        cand = w + (b / (w * (2 * m))) * sp
        if cand * cand * m == y:
            return (m, cand) if free else cand
    return None


#: How many embeddings of K into F_q the modular test tries (each refutes a number
#: without the root sought with probability about 1/2).
EMBEDDINGS = 8


def _refuted_modulo(y: MQ, primes, free: bool) -> bool:
    """True only when ``y`` provably has no root of the kind :func:`_kummer_root` seeks
    in K = Q(sqrt p : p in ``primes``): a root in K, or with ``free`` a root
    ``sqrt(m) w`` (m a square-free integer, w in K).  A filter, exact and
    deterministic: the search it spares multiplies numbers of up to 2^k terms along
    2^k branches (the corrected simulator's n = 30 run spent 200 s there).

    Why it is sound: q is an odd prime at which every p is a non-zero square, so q is
    unramified and splits completely in K, and each choice of signs of the roots r_p of p
    mod q gives a ring map phi from the q-integral elements of K onto F_q; that ring
    (generated by the sqrt p over Z localised at q: its discriminant is a product of 2s
    and ps, a unit at q) is integrally closed.  Let y be q-integral with phi(y) != 0.
    If y = m w^2, then m is prime to q (every prime of K over q has valuation 0 in y and
    1 in q, and m is square-free), so w^2 = y/m is q-integral, so w is (integrally
    closed), and phi(y) = m phi(w)^2: the Legendre symbol of phi(y) is that of m,
    the same for every phi (1 for a root in K itself, m = 1).  Two maps with different
    symbols, or one symbol -1 without ``free``, refute."""
    common = denominator(y)
    choices = _sign_choices(len(primes))
    for q, roots in _split_primes(tuple(primes)):
        if common % q == 0:
            continue
        seen = set()
        for signs in choices:
            base = {p: (r if s else q - r) for p, r, s in zip(primes, roots, signs)}
            value = image(y, q, base, [])
            if value == 0:
                continue
            seen.add(pow(value, (q - 1) // 2, q))
            if len(seen) > 1 or (not free and (q - 1) in seen):
                return True
    return False


@lru_cache(maxsize=256)
def _split_primes(primes: tuple) -> tuple:
    """Three primes q > 2^31 at which every one of ``primes`` is a non-zero square, with
    a square root of each mod q (:func:`.tower_proof.sqrt_mod`).  A prime splits
    with probability 2^-k, so this tries a few thousand candidates for k = 12."""
    out = []
    q = (1 << 31) + 1
    while len(out) < 3:
        q += 2
        if is_prime(q) and all(pow(p, (q - 1) // 2, q) == 1 for p in primes):
            out.append((q, tuple(sqrt_mod(p, q) for p in primes)))
    return tuple(out)


def _sign_choices(k: int) -> list:
    """At most :data:`EMBEDDINGS` distinct choices of the roots' signs: all positive,
    then each root flipped alone (the maps differ most there: ``a + b sqrt p`` against
    ``a - b sqrt p``), then fixed pseudo-random ones (the filter stays deterministic)."""
    masks = [0] + [1 << j for j in range(k)]
    draw = random.Random(k)
    while len(masks) < min(EMBEDDINGS, 1 << k) + 1:
        masks.append(draw.getrandbits(k))
    out = list(dict.fromkeys(masks))[:EMBEDDINGS]
    return [tuple(not (mask >> j & 1) for j in range(k)) for mask in out]


def _rational_square_root(q: fmpq):
    """The rational root of ``q``, or None (no factoring)."""
    if q < 0:
        return None
    num, den = int(q.p), int(q.q)
    r = isqrt(num * den)
    return MQ.rational(fmpq(r, den)) if r * r == num * den else None


def _sqrt_rational(q: fmpq, big_ok: bool, source: MQ | None = None, split: bool = True):
    """The root of the rational ``q >= 0`` in the multiquadratic closure, or None when
    its square-free part is out of reach (more than :data:`RATIONAL_BITS` bits, not
    ``big_ok``, and the bounded split, cut by the integers of ``source``, cannot tell)."""
    if q < 0:
        return None
    root = _rational_square_root(q)
    if root is not None:
        return root
    num, den = int(q.p), int(q.q)
    if not big_ok and (num * den).bit_length() > RATIONAL_BITS:
        if not split:
            return None
        hints = () if source is None else tuple(sorted(
            {abs(int(v)) for c in source.terms.values() for v in (c.p, c.q)} - {0, 1}))
        found = bounded_squarefree_split(num * den, hints)
        if found is None:
            return None
        s, m = found
        return MQ({m: fmpq(s, den)})
    return sqrt_rational(q)


@lru_cache(maxsize=4096)
def bounded_squarefree_split(n: int, hints: tuple = ()):
    """``(s, m)`` with ``n == s^2 m`` and ``m`` square-free, found with a bounded effort, or
    None (a pure function of its arguments).  ``n`` is first cut by gcds with the
    integers ``hints`` (the numerators and denominators of the number whose root is
    sought: the integers the search builds share their primes), then each piece is split
    by ``fmpz.factor_smooth`` (ECM for primes of up to 24 bits, then only what is left
    unresolved again for 32, 40 and :data:`SMOOTH_BITS` bits: the larger searches cost
    up to a second on 900-bit integers); a part of odd exponent is resolved when it is a
    proved prime (``fmpz.is_prime`` proves) or a perfect square; a composite part left of
    at most :data:`FULL_FACTOR_BITS` bits is factored in full.  Any part left
    unresolved (a larger composite whose square-free part would need its factors) makes
    the answer None.  The split is checked (the parts multiply back to ``n`` and are pairwise
    coprime), so ``m`` is the product of the prime parts of odd exponent.  The gathering
    simulator meets such integers (160 to 1,900 bits, most of them a smooth part times
    one large prime) when it writes the root of a critical instant's discriminant."""
    if n < 1:
        return None
    parts: dict = {}                      # part -> [exponent, proved prime?]
    open_ = _cut(n, hints)
    for bits in (24, 32, 40, SMOOTH_BITS):
        left = []
        for b, e in open_:
            for f, k in fmpz(b).factor_smooth(bits):
                f, k = int(f), int(k) * e
                if f in parts:
                    parts[f][0] += k
                    continue
                if k % 2 == 0:
                    # primality is read only if a merge makes the exponent odd (below):
                    # a proof for a large prime squared costs up to a second
                    parts[f] = [k, None]
                    continue
                prime = is_prime(f)
                if prime or isqrt(f) ** 2 == f:
                    parts[f] = [k, prime]
                else:
                    left.append((f, k))
        open_ = left
        if not open_:
            break
    left = []
    for b, e in open_:
        if b.bit_length() > FULL_FACTOR_BITS:
            left.append((b, e))
            continue
        for f, k in fmpz(b).factor():
            f, k = int(f), int(k) * e
            if f in parts:
                parts[f][0] += k
            else:
                parts[f] = [k, None]        # primality proved below where it matters
    if left:
        return None
    check = 1
    for b, (e, _) in parts.items():
        check *= b ** e
    keys = list(parts)
    if check != n or any(gcd(a, b) != 1 for k, a in enumerate(keys) for b in keys[k + 1:]):
        return None
    s, m = 1, 1
    for b, (e, prime) in parts.items():
        if e % 2 == 0:
            s *= b ** (e // 2)
        elif prime or (prime is None and is_prime(b)):
            s, m = s * b ** (e // 2), m * b
        elif isqrt(b) ** 2 == b:
            s *= isqrt(b) ** e
        else:                   # a composite whose exponent became odd by merging
            return None
    return s, m


def _cut(n: int, hints) -> list:
    """``[(piece, exponent)]`` with product ``n``: ``n`` cut by its gcds with ``hints``."""
    pieces = [n]
    for h in hints:
        out = []
        for a in pieces:
            g = gcd(a, h)
            while 1 < g < a:
                out.append(g)
                a //= g
                g = gcd(a, g)
            out.append(a)
        pieces = out
    counts: dict = {}
    for a in pieces:
        if a > 1:
            counts[a] = counts.get(a, 0) + 1
    return list(counts.items())
