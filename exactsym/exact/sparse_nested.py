"""A square root that is new over a tower of the sparse Q(zeta_N), proved by characters.

MakeAsym moves a robot radially to another circle (L1526): the scale factor is
sqrt(r_to^2 / r_from^2), a number of the configuration's tower over the real subfield K_0 of
the sparse Q(zeta_N) (:mod:`.sparse_tower`), not a rational.  The sparse base has no
square-root test (no canonical basis, degrees near 10^14), so such a root was refused and
the paper's run left "incomplete".  Here a radicand x is proved *not* a square of the top
field K_L, so that y = sqrt(x) is a new level (the tower's canonical form a + b y stays
canonical); when the proof is not found x is refused as before.

Proof.  The levels are y_j = sqrt(r_j).  Let S be the levels x is written with, with the
levels their radicands are written with, and every level whose radicand is not rational;
the others, R, are square roots of rationals k_m.  F = K_0(y_j : j in S) holds x, and
K_L = F(sqrt(k_m) : m in R) with each level new, so by Kummer theory x is a square of K_L
iff x * prod(k_m : m in T) is a square of F for some subset T of R.  A ring map phi from
Z_(l)[zeta_N, y_j : j in S] onto F_l (l = 1 mod N prime, zeta_N -> w a primitive N-th root
of unity mod l, y_j -> a root s_j of phi(r_j)) sends squares to squares; with chi the
Legendre symbol written additively, x * prod_T k_m a square forces
chi(phi(x)) + sum_T chi(k_m) = 0 whenever every factor is a unit at l.  (phi is the
reduction at a prime of F above l of degree 1: l splits in Q(zeta_N), and each level whose
radicand's image is a non-zero square splits it again; so the root of x prod k_m, a unit
there, has an image in F_l itself.)  Each map is one linear equation over F_2 in the
unknown T; when they have no solution (Gaussian elimination reaches 0 = 1) no T exists and
x is not a square.  Several maps per prime l
(w = g^u for units u: conjugate embeddings) vary chi(phi(x)); several primes l vary the
chi(k_m).  The primes are l = 1 mod lcm(N, 4, the primes of the rational radicands in S; 8 for 2),
so that those levels always extend a map (reciprocity).  A non-square is typically proved
at the first prime (two conjugates disagree), a rational non-square times a square after
about |R| primes; a square is never proved, and costs the whole budget (|R| + 40 primes,
at most :data:`_PRIMES`) before it is refused.

Input reaches this through MakeAsym's radial move only (:meth:`.sparse_tower.
SparseKummerTower.extended`, a copy of the configuration's tower): a configuration's own
tower has rational levels only, so its certificate never holds a nested level.  The
sparse nested reading that would put nested levels in it, and the certificate writer of
such a level, are tests/reference/sparse_nested_reading.py (issue 29: code input does not
reach leaves the package); the checker still verifies such a level (a certificate file
is input).

Public names: :func:`new_level_proved`.
"""

from __future__ import annotations

from math import lcm

from flint import fmpz

from .factor import factorization, is_prime
from .modular import sparse_image
from .sparse_context import root_of_unity
from .tower_proof import sqrt_mod

__all__ = ["new_level_proved"]

#: primes l = k M + 1 tried at most (and |R| + 40): :data:`_CONJUGATES` embeddings at the
#: first (they settle a non-square there), two at each later one (they vary the chi(k_m))
_PRIMES = 400
_CONJUGATES = 8


def _levels(v, out: set) -> set:
    if type(v) is tuple:
        out.add(v[0])
        _levels(v[1], out)
        _levels(v[2], out)
    return out


def _closure(radicands, start: set) -> set:
    """``start`` with every level a radicand in it is written with."""
    todo, seen = list(start), set(start)
    while todo:
        j = todo.pop()
        for k in _levels(radicands[j - 1], set()):
            if k not in seen:
                seen.add(k)
                todo.append(k)
    return seen


def _rational(v):
    """The rational value of a raw base value of the tower, or None."""
    if type(v) is tuple or not v.is_rational():
        return None
    return v.to_fmpq()


def _rational_image(q, l: int):
    num, den = int(q.p) % l, int(q.q) % l
    return None if den == 0 else num * pow(den, -1, l) % l


class _Embedding:
    """zeta_N -> w modulo l (:func:`.cyclotomic_modular.sparse_image` on the base)."""

    def __init__(self, n: int, l: int, w: int):
        self.n, self.l, self.w = n, l, w

    def value(self, v, roots: dict):
        """phi(v) for a raw tower value whose levels have images in ``roots``."""
        if type(v) is not tuple:
            return sparse_image(v, self.l, self.w)
        lev, a, b = v
        ia, ib = self.value(a, roots), self.value(b, roots)
        if ia is None or ib is None:
            return None
        return (ia + ib * roots[lev]) % self.l


def _roots_of(embedding: _Embedding, radicands, levels) -> dict | None:
    """Images of y_j (j in ``levels``, increasing) under one extension of the embedding,
    or None when a radicand's image is not a non-zero square mod l."""
    roots: dict = {}
    for j in sorted(levels):
        r = embedding.value(radicands[j - 1], roots)
        s = None if not r else sqrt_mod(r, embedding.l)
        if s is None:
            return None
        roots[j] = s
    return roots


def _primes(context, count: int, modulus: int, start: int = 1 << 20):
    """Primes l = k M + 1 (M = ``modulus``, a multiple of N; k from ``start``, by default
    2^20: l far above the small denominators) with g a primitive N-th root of unity mod l."""
    n, k, found = context.n, start, 0
    while found < count:
        l = k * modulus + 1
        k += 1
        if not is_prime(l):
            continue
        found += 1
        yield l, root_of_unity(n, context.factors, l)


def _split_modulus(n: int, rationals) -> int:
    """lcm(N, 4, the odd primes of ``rationals``, 8 if 2 divides one of them an odd number of
    times): modulo a prime l = 1 mod it every one of them is a square (an odd prime q by
    reciprocity as l = 1 mod 4q, 2 as l = 1 mod 8), so the levels of F that are roots of
    rationals always extend a map.  8 only when needed: with l = 1 mod 8 always, sqrt(2)
    has an image at every prime, and sqrt(2 + sqrt(3)) = (sqrt(6) + sqrt(2))/2, not in a
    field without sqrt(2), would have a square image at every map."""
    modulus = lcm(n, 4)
    for q in rationals:
        for part in (int(q.p), int(q.q)):
            factors = factorization(abs(part)) if abs(part) > 1 else {}
            for prime, exponent in factors.items():
                modulus = lcm(modulus, 8 if prime == 2 and exponent % 2 else prime)
    return modulus


def _units(n: int, count: int):
    """The first ``count`` units u mod N up to sign (u and -u give the same cosines)."""
    out, u = [], 1
    while len(out) < count and u <= n // 2:
        if fmpz(u).gcd(n) == 1:
            out.append(u)
        u += 1
    return out


def new_level_proved(tower, x) -> bool:
    """Whether x (a raw value of ``tower``, a :class:`~.sparse_tower.SparseKummerTower`,
    positive, not rational) is proved not a square of the top field (module docstring);
    False when the maps tried prove nothing (x may be a square)."""
    radicands = tower.radicands
    nested = {j for j in range(1, len(radicands) + 1) if _rational(radicands[j - 1]) is None}
    inner = _closure(radicands, _levels(x, set()) | nested)
    outer = [j for j in range(1, len(radicands) + 1) if j not in inner]
    rationals = [_rational(radicands[j - 1]) for j in outer]
    rows: dict = {}         # pivot bit -> (mask over the outer levels, right-hand side)
    units = _units(tower.context.n, _CONJUGATES)
    # |R| + 1 independent rows settle any x; a square never is (a prime l near a
    # 350-bit N costs 40 ms to find): so at most |R| + 40 primes
    budget = min(_PRIMES, len(outer) + 40)
    split = _split_modulus(tower.context.n, [q for q in map(_rational, (
        radicands[j - 1] for j in inner)) if q is not None])
    for index, (l, g) in enumerate(_primes(tower.context, budget, split)):
        chis = []
        for q in rationals:
            image = _rational_image(q, l)
            if not image:
                break
            chis.append(0 if pow(image, (l - 1) // 2, l) == 1 else 1)
        if len(chis) < len(rationals):
            continue
        mask_of_prime = sum(bit << i for i, bit in enumerate(chis))
        for u in units if index == 0 else units[:2]:
            embedding = _Embedding(tower.context.n, l, pow(g, u, l))
            roots = _roots_of(embedding, radicands, inner)
            if roots is None:
                continue
            image = embedding.value(x, roots)
            if not image:
                continue
            rhs = 0 if pow(image, (l - 1) // 2, l) == 1 else 1
            mask = mask_of_prime
            while mask:
                row = rows.get(mask.bit_length() - 1)
                if row is None:
                    break
                mask, rhs = mask ^ row[0], rhs ^ row[1]
            if mask:
                rows[mask.bit_length() - 1] = (mask, rhs)
            elif rhs:
                return True         # 0 = 1: no subset T makes x prod k_m a square of F
    return False
