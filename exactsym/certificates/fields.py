"""Irreducibility proofs that ``certify`` writes for a field given by a primitive element.

The checker's "square-roots" proof (``Field.square_roots`` of the checker's numbers,
``docs/certificates.md``) names, in Q(theta), a root h of Psi_M (so the real cyclotomic field
K = Q(2cos(2pi/M)) of degree e lies in Q(theta)) and square roots g_i of k positive integers
a_i, no non-empty subset product of which is a square in K (the checker tests this with the
conductor of each Q(sqrt s)); then deg p = 2^k e proves p irreducible.  This covers the fields
the kernel builds for nested radicals mixed with square roots and trigonometry whose Galois
group has no element of order d (so no prime works): Q(sqrt 2, sqrt 3), Q(sqrt 2, sqrt 3,
cos(2pi/13)) (24 = 4 * 6), Q(sqrt 3, cos(2pi/16)) (8 = 2 * 4, sqrt 2 already in K).

Nothing found here is trusted: LLL on Arb values proposes each h and g_i and an exact identity
modulo p keeps it.  Prime filters keep the LLL calls few: a square root sqrt(a) or 2cos(2pi/M)
in Q(theta) ramifies only at primes of disc(p), and at a prime ell where p has a root modulo
ell (a place of degree 1), a is a square and Psi_M has a root modulo ell.
"""

from __future__ import annotations

import math

from flint import arb, ctx, fmpq, fmpq_poly, fmpz, fmpz_mat, fmpz_poly, nmod_poly


MAX_CONDUCTOR = 400          # 2cos(2pi/M) is looked for up to this conductor
_PLACES = 48                 # degree-1 primes used as filters


def square_root_proof(field, atoms: dict | None = None) -> dict | None:
    """The checker's "square-roots" proof for ``field`` (a NumberField with a real generator),
    or None when no such proof is found.  ``atoms`` (the number system's atoms: ("cos", t)
    and ("sqrt", q) -> field element) offer exact roots of Psi_M and square roots first: in
    a primitive-element basis they can have coefficients of hundreds of digits, beyond LLL."""
    d = field.degree
    if d < 2:
        return None
    ints = _integral(field.minpoly)
    disc = abs(int(fmpz_poly(ints).discriminant()))
    primes = [int(q) for q, _ in fmpz(disc).factor_smooth(20) if int(q) < 1 << 40]
    places = _degree_one_primes(ints, disc)
    roots = _atom_square_roots(field, atoms or {})
    options = [_atom_cyclotomic(field, atoms or {})] + [
        [(m, e, None)] for m, e in _conductors(d, primes, places)] + [[]]
    plain_tried = False
    for parts in options:
        e = math.prod(p[1] for p in parts)
        if d % e or (d // e) & (d // e - 1) or (not parts and plain_tried):
            continue
        plain_tried |= not parts
        if any(h is None for _, _, h in parts):
            m = parts[0][0]
            h = _relation(field, lambda: 2 * arb.cos_pi_fmpq(fmpq(2, m)),
                          lambda h: _psi_value(m, h, field.minpoly) == 0)
            if h is None:
                continue
            parts = [(m, parts[0][1], h)]
        k = (d // e).bit_length() - 1
        chosen = _radicands(field, k, math.prod(p[0] for p in parts), primes, places, roots)
        if chosen is None:
            continue
        proof = {"method": "square-roots", "radicands": [str(a) for a, _ in chosen],
                 "roots": [[checker_text(c) for c in g.coeffs()] for _, g in chosen]}
        if parts:
            proof["cyclotomic"] = [{"conductor": m, "root": [checker_text(c)
                                                             for c in h.coeffs()]}
                                   for m, _, h in parts]
        return proof
    return None


def _atom_cyclotomic(field, atoms: dict) -> list:
    """(M, e, h): h = 2cos(2pi a/M), a root of Psi_M, for the cosines among the atoms, of
    pairwise coprime conductors, largest degree first."""
    found = []
    for key, value in atoms.items():
        if key[0] == "cos" and fmpq(key[1]).q >= 3:
            m = int(fmpq(key[1]).q)
            h = 2 * value.poly
            if _psi_value(m, h, field.minpoly) == 0:
                found.append((m, _psi(m).degree(), h))
    found.sort(key=lambda x: (-x[1], x[0]))
    parts: list = []
    for m, e, h in found:
        if e >= 2 and all(math.gcd(m, m2) == 1 for m2, _, _ in parts):
            parts.append((m, e, h))
    return parts


def _atom_square_roots(field, atoms: dict) -> dict:
    """a -> g with g(theta)^2 = a for the square roots sqrt(p/q) among the atoms (a = pq)."""
    out = {}
    for key, value in atoms.items():
        if key[0] == "sqrt":
            q = fmpq(key[1])
            a, g = int(q.p * q.q), value.poly * int(q.q)
            if 1 < a < 1 << 40 and (g * g) % field.minpoly == a:
                out[a] = g
    return out


def checker_text(q) -> str:
    q = fmpq(q)
    return str(q.p) if q.q == 1 else f"{q.p}/{q.q}"


def _integral(minpoly: fmpq_poly) -> list[int]:
    coeffs = minpoly.coeffs()
    den = math.lcm(*(int(c.q) for c in coeffs))
    return [int(c.p) * (den // int(c.q)) for c in coeffs]


def _degree_one_primes(ints: list[int], disc: int) -> list[int]:
    """Primes ell not dividing disc(p) or its leading coefficient at which p has a root."""
    out, ell = [], 3
    while len(out) < _PLACES and ell < 200_000:
        if disc % ell and ints[-1] % ell and _is_prime(ell):
            if nmod_poly([c % ell for c in ints], ell).roots():
                out.append(ell)
        ell += 2
    return out


def _is_prime(n: int) -> bool:
    return n > 1 and bool(fmpz(n).is_prime())


def _psi(m: int) -> fmpz_poly:
    """Psi_m, the minimal polynomial of 2cos(2pi/m) (flint's; the checker derives its own
    from the cyclotomic polynomial and compares)."""
    return fmpz_poly.cos_minpoly(m)


def _conductors(d: int, primes: list[int], places: list[int]):
    """(M, e) with e = deg Psi_M, d / e a power of 2, the primes of M among ``primes`` and
    Psi_M split off a root at every place; largest e first; (None, 1) last when d = 2^k."""
    found = []
    for m in range(3, MAX_CONDUCTOR + 1):
        if m % 4 == 2:
            continue                            # Q(zeta_2n) = Q(zeta_n) for odd n
        psi = [int(c) for c in _psi(m).coeffs()]
        e = len(psi) - 1
        if e < 2 or d % e or (d // e) & (d // e - 1):
            continue
        if any(m % q == 0 and q not in primes for q in _prime_factors(m)):
            continue
        if all(nmod_poly([c % ell for c in psi], ell).roots() for ell in places):
            found.append((m, e))
    found.sort(key=lambda me: (-me[1], me[0]))
    if d & (d - 1) == 0:
        found.append((None, 1))
    return found


def _prime_factors(m: int) -> list[int]:
    return [q for q in range(2, m + 1) if m % q == 0 and _is_prime(q)]


def _psi_value(m: int, h: fmpq_poly, minpoly: fmpq_poly):
    value = fmpq_poly([0])
    for c in reversed(_psi(m).coeffs()):
        value = (value * h + c) % minpoly
    return value


def _conductor(s: int) -> int:
    return s if s % 4 == 1 else 4 * s


def _radicands(field, k: int, m: int, primes: list[int], places: list[int], known: dict):
    """k pairs (a, g), g(theta)^2 = a, whose subset products are not squares in Q(zeta_m)
    (the checker's test), or None.  Candidates a are square-free products of ``primes``
    that are squares modulo every place: the F_2 null space of the Legendre symbols."""
    if k == 0:
        return []
    rows = [sum(1 << i for i, q in enumerate(primes) if pow(q, (ell - 1) // 2, ell) != 1)
            for ell in places]
    basis = _null_space(rows, len(primes))
    if len(basis) > 14:
        return None
    span = sorted({_xor_combination(basis, mask) for mask in range(1, 1 << len(basis))},
                  key=lambda v: (bin(v).count("1"), v))
    index = {q: i for i, q in enumerate(primes)}
    atoms = []                                  # the atoms' square roots first (exact)
    for a0 in known:
        a, v = _squarefree(a0, index)
        if v is not None and a > 1:
            atoms.append((v, a0))
    chosen: list = []                           # (a, g, vector)
    for v, a0 in atoms + [(v, None) for v in span]:
        a = a0 if a0 is not None else math.prod(q for i, q in enumerate(primes) if v >> i & 1)
        combos = [v]
        for _, _, w in chosen:
            combos += [c ^ w for c in combos]
        if any(c == 0 or m % _conductor(math.prod(q for i, q in enumerate(primes)
                                                   if c >> i & 1)) == 0 for c in combos):
            continue
        g = known[a0] if a0 is not None else _relation(
            field, lambda: arb(a).sqrt(), lambda g: (g * g) % field.minpoly == a)
        if g is not None:
            chosen.append((a, g, v))
            if len(chosen) == k:
                return [(a, g) for a, g, _ in chosen]
    return None


def _squarefree(a: int, index: dict):
    """(a, bit vector of the primes of its squarefree part), or (a, None) if a has a prime
    outside ``index`` (then sqrt(a) would ramify outside disc(p): not in the field)."""
    v, rest = 0, a
    for q, i in index.items():
        while rest % q == 0:
            rest //= q
            v ^= 1 << i
    return a, (v if rest == 1 else None)


def _null_space(rows: list[int], n: int) -> list[int]:
    """A basis of {v in F_2^n : popcount(v & r) even for every r} (bit masks)."""
    pivots: dict = {}                           # pivot column -> reduced row
    for r in rows:
        for col, pr in pivots.items():
            if r >> col & 1:
                r ^= pr
        if r:
            col = r.bit_length() - 1
            for c2 in list(pivots):
                if pivots[c2] >> col & 1:
                    pivots[c2] ^= r
            pivots[col] = r
    basis = []
    for free in range(n):
        if free in pivots:
            continue
        v = 1 << free
        for col, pr in pivots.items():
            if pr >> free & 1:
                v |= 1 << col
        basis.append(v)
    return basis


def _xor_combination(basis: list[int], mask: int) -> int:
    v = 0
    for i, b in enumerate(basis):
        if mask >> i & 1:
            v ^= b
    return v


def _relation(field, value, exact):
    """A polynomial g of degree < d with g(theta) = value() (an arb at the working precision),
    proposed by LLL on 1, theta, ..., theta^(d-1), value and kept if exact(g); else None."""
    d = field.degree
    for bits in (64 * d + 256, 256 * d + 1024):
        with ctx.workprec(bits + 64):
            theta = field.enclosure(bits + 64)
            values = [arb(1)]
            for _ in range(d - 1):
                values.append(values[-1] * theta)
            values.append(value())
            scale = arb(2) ** bits
            column = [int((v * scale).mid().floor().unique_fmpz()) for v in values]
        rows = [[int(i == j) for j in range(d + 1)] + [column[i]] for i in range(d + 1)]
        lll = fmpz_mat(rows).lll()
        relation = [int(lll[0, j]) for j in range(d + 2)]
        if relation[d] == 0:
            continue
        g = fmpq_poly([fmpq(-relation[i], relation[d]) for i in range(d)])
        if exact(g):
            return g
    return None
