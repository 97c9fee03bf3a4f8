"""Checker extension: irreducibility proofs of a field Q(theta) given by a primitive element
(nested radicals; standard library only), reached through ``dispatch.IRREDUCIBILITY``: a prime
modulo which the minimal polynomial stays irreducible, or, when no prime can (Q(sqrt 2, sqrt 3),
Q(sqrt 2, sqrt 3, cos(2pi/13)), ...), square roots proving its degree by Kummer theory.
"""

from __future__ import annotations

from math import gcd, isqrt, lcm

from .numbers import Field, poly_product, integer, is_int, need, psi


def prime_proof(field: Field, proof: dict) -> None:
    """{"method": "prime", "prime": ell}: p is irreducible modulo ell (:func:`irreducible_mod`)."""
    need(irreducible_mod(field.p, proof["prime"]),
         f"the minimal polynomial is not irreducible modulo {proof['prime']!r}")


def irreducible_mod(p: list, ell) -> bool:
    """p (monic, rational) keeps its degree d and is irreducible modulo the prime ell: then it
    is irreducible over Q (Gauss's lemma: a factorisation over Q gives one over Z with the same
    degrees, which reduced mod ell, not dividing the leading coefficient, factors p mod ell).
    Over F_ell, x^(ell^i) - x is the product of the monic irreducibles of degree dividing i,
    and a reducible f has a factor of degree <= d/2: f is irreducible iff
    gcd(x^(ell^i) - x, f) = 1 for i = 1 .. d/2."""
    need(is_int(ell) and 2 <= ell < 1 << 32 and all(ell % q for q in range(2, isqrt(ell) + 1)),
         f"{ell!r} is not a prime")
    den = lcm(*(c.denominator for c in p))
    lead = int(p[-1] * den) % ell
    f = [int(c * den) * pow(lead, -1, ell) % ell for c in p] if lead else [0]
    if f[0] == 0:                               # ell divides the leading coefficient, or x | f
        return False

    def rem(a, g):                              # a mod g over F_ell, no trailing zeros
        a, inv = [c % ell for c in a], pow(g[-1], -1, ell)
        while True:
            while a and a[-1] == 0:
                a.pop()
            if len(a) < len(g):
                return a
            t, s = a[-1] * inv % ell, len(a) - len(g)
            for j, c in enumerate(g):
                a[s + j] = (a[s + j] - t * c) % ell

    def mulmod(a, b):
        return rem(poly_product(a, b), f)

    h = [0, 1]
    for _ in range((len(f) - 1) // 2):
        base, e, h = h, ell, [1]
        while e:                                # h = base^ell mod f: now h = x^(ell^i) mod f
            h = mulmod(h, base) if e & 1 else h
            base, e = mulmod(base, base), e >> 1
        a, b = f, rem([c - (j == 1) for j, c in enumerate(h + [0] * (2 - len(h)))], f)
        while b:                                # gcd(f, x^(ell^i) - x)
            a, b = b, rem(a, b)
        if len(a) > 1:
            return False
    return True


def square_roots_proof(field: Field, proof: dict) -> None:
    """p is irreducible if it has degree 2^k e and, for every root theta' of p, Q(theta')
    holds a subfield K of degree e and square roots of k positive integers a_1..a_k no
    product of a non-empty subset of which is a square in K.  By Kummer theory (exponent
    2; K holds -1) K(sqrt a_1, ..., sqrt a_k) then has degree 2^k over K, so every root of p
    has degree >= 2^k e = deg p, and p is its minimal polynomial.  The roots are
    polynomials g_i with g_i^2 = a_i modulo p: this holds at every root of p, whatever p
    is, because it is a polynomial identity modulo p.

    K = Q without ``cyclotomic`` (e = 1: a product must not be a rational square).  With
    ``cyclotomic`` = {"conductor": M, "root": h}, Psi_M(h) = 0 modulo p (again an identity
    at every root), so Q(theta') holds K = Q(2cos(2pi/M)), of degree e = deg Psi_M (Gauss).
    A list of such parts with pairwise coprime conductors M_j: K is the compositum of the
    Q(2cos(2pi/M_j)), of degree e = prod e_j (Q(zeta_Mi) and Q(zeta_Mj) meet only in Q, so
    Galois subfields of them are linearly disjoint), inside Q(zeta_M), M = prod M_j.  A
    rational a is a square in K only if sqrt(a) lies in Q(zeta_M), i.e. (a's squarefree
    part s > 1) only if Q(sqrt s) has conductor dividing M: s if s = 1 mod 4, else 4s
    (conductor-discriminant formula).  So every non-empty subset must have a squarefree
    part s > 1 whose conductor does not divide M (e.g. Q(sqrt 2, sqrt 3, cos(2pi/13)):
    2^2 * 6 = 24; Q(sqrt 3, cos(2pi/16)): 2 * 4, where sqrt 2 is in K and may not be a
    radicand)."""
    radicands, roots, cyclo = proof["radicands"], proof["roots"], proof.get("cyclotomic")
    a = [integer(x) for x in radicands]
    k = len(a)
    e, m = 1, 1
    for part in [cyclo] if isinstance(cyclo, dict) else cyclo or []:
        mj = part["conductor"]
        need(is_int(mj) and 3 <= mj <= 10 ** 4 and gcd(m, mj) == 1,
             "square-roots proof: bad conductor (conductors must be pairwise coprime)")
        psi_m, h = psi(mj), field.num(part["root"])
        value = 0
        for c in reversed(psi_m):
            value = value * h + c
        need(value == 0, f"square-roots proof: the root given is not a root of Psi_{mj}")
        e, m = e * (len(psi_m) - 1), m * mj
    need(0 <= k <= 16 and field.d == (1 << k) * e > 1 and len(roots) == k
         and all(x > 0 for x in a), "square-roots proof: need k positive radicands and "
         "degree 2^k e")
    need(all(x < 1 << 48 for x in a), "square-roots proof: radicands below 2^48")
    parts = [_squarefree_part(x) for x in a]
    for mask in range(1, 1 << k):
        s = 1                                   # squarefree s, t: st = g^2 (s/g)(t/g)
        for i, t in enumerate(parts):
            if mask >> i & 1:
                g = gcd(s, t)
                s = (s // g) * (t // g)
        need(s > 1, f"square-roots proof: a product of radicands is a square ({s})")
        need(m % (s if s % 4 == 1 else 4 * s) != 0, f"square-roots proof: sqrt({s}) lies "
             f"in Q(zeta_{m}), so a product of radicands is a square there")
    for x, g in zip(a, roots):
        need(isinstance(g, list), "square-roots proof: a root must be a coefficient list")
        root = field.num(g)
        need(root * root == x, f"square-roots proof: the root given for {x} does not "
             "square to it")


def _squarefree_part(n: int) -> int:
    """n divided by its largest square factor (trial division: radicands below 2^48)."""
    out, q = 1, 2
    while q * q <= n:
        while n % (q * q) == 0:
            n //= q * q
        if n % q == 0:
            out, n = out * q, n // q
        q += 1
    return out * n
