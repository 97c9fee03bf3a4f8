"""Square roots in a cyclotomic field Q(zeta_M): an exact and complete test (issue 9).

:func:`field_sqrt` answers, for an element a of Q(zeta_M) (a :class:`~.field.PolyElement` of a
field made by :func:`~.cyclotomic.cyclotomic_field`), either a z of the field with z^2 == a
(checked exactly) or None, and None only when a is not a square there.  It is the base case
of the square-root test of a tower over a cyclotomic field (:mod:`.cyclotomic_tower`).

1. **Refutation modulo primes.**  For a prime p = 1 mod M, Phi_M splits into distinct linear
   factors mod p, and zeta -> w (w a root of Phi_M mod p) is a ring map phi from Z_(p)[zeta]
   (the elements whose coefficients have no p in their denominators) onto F_p.  Since p does
   not divide disc(Phi_M) (a divisor of a power of M), Z_(p)[zeta] is integrally closed; so if
   a (p-integral) were z^2, z would be integral over it, hence in it, and phi(a) = phi(z)^2 a
   square.  A non-residue phi(a) (Euler's criterion) proves that a is not a square.  For a
   non-square, about half of the embeddings refute it (Chebotarev), so a few primes settle
   it; nothing but a refutation is concluded here.
2. **Trager's norm.**  If no embedding refutes a, a = A/d with A integral, b = d^2 a, and
   F(X) = (X - s zeta)^2 - b in K[X] for s = 1, 2, ...  N(X) = Norm_{K/Q} F is the
   characteristic polynomial of multiplication by s zeta + Y on the Q-algebra K[Y]/(Y^2 - b)
   (a 2n x 2n integer matrix, n = phi(M); FLINT's ``charpoly``).  For the first s with N
   squarefree, Trager's theorem says: the factorisation of F over K matches that of N over Q,
   the gcd over K of F and the factor g of N holding a root of F being linear.  So N
   irreducible (FLINT's ``factor``) proves b (and a) is not a square; otherwise for some
   factor g, g mod F = u + v X has v != 0, the root of F is -u/v, z = -u/v - s zeta and the
   answer z/d is checked to square to a exactly (a failure raises: never a wrong answer).

Public names: :func:`field_sqrt`, :func:`split_primes`, :func:`root_of_unity_mod`,
:func:`image_mod`.
"""

from __future__ import annotations

from flint import fmpq_poly, fmpz_mat, fmpz_poly, nmod_poly

from .factor import factorization, is_prime
from .field import NumberField, PolyElement
from .inverse import nth_prime

#: primes p = 1 mod M tried for a refutation, and embeddings tried per prime
REFUTATION_PRIMES = 6
EMBEDDINGS_PER_PRIME = 4


def split_primes(m: int, start: int = 0):
    """The primes p = 1 mod m (m >= 1), odd, above ``start``, increasing."""
    k = max(1, start // m)
    while True:
        p = k * m + 1
        if p > start and p > 2 and is_prime(p):
            yield p
        k += 1


def root_of_unity_mod(m: int, p: int) -> int:
    """A primitive m-th root of unity modulo the prime p = 1 mod m (a root of Phi_m mod p)."""
    primes = list(factorization(m)) if m > 1 else []
    for g in range(2, p):
        w = pow(g, (p - 1) // m, p)
        if all(pow(w, m // q, p) != 1 for q in primes):
            return w
    raise ValueError(f"no primitive {m}-th root of unity modulo {p}")


def image_mod(poly: fmpq_poly, w: int, p: int) -> int | None:
    """poly(w) mod p, or None when p divides a denominator of poly."""
    den = int(poly.denom())
    if den % p == 0:
        return None
    value = int(nmod_poly([int(c) % p for c in poly.numer().coeffs()], p)(w))
    return value * pow(den, -1, p) % p


def _units_mod(m: int):
    from math import gcd
    return [k for k in range(1, m) if gcd(k, m) == 1] if m > 1 else [1]


def refuted(field: NumberField, a: PolyElement) -> bool:
    """True when some embedding Z_(p)[zeta] -> F_p (p = 1 mod M) maps a to a non-residue:
    a proof that a is not a square in Q(zeta_M) (module docstring, step 1)."""
    m = field.conductor
    units = _units_mod(m)
    primes = split_primes(m, start=1000)
    for _ in range(REFUTATION_PRIMES):
        p = next(primes)
        w = root_of_unity_mod(m, p)
        for k in units[:EMBEDDINGS_PER_PRIME]:
            value = image_mod(a.poly, pow(w, k, p), p)
            if value is None or value == 0:
                break
            if pow(value, (p - 1) // 2, p) == p - 1:
                return True
    return False


def field_sqrt(field: NumberField, a: PolyElement) -> PolyElement | None:
    """A z in Q(zeta_M) with z * z == a, or None when a is not a square (module docstring)."""
    if a.poly.is_zero():
        return a
    if refuted(field, a):
        return None
    return _trager_sqrt(field, a)


def _trager_sqrt(field: NumberField, a: PolyElement) -> PolyElement | None:
    n = field.degree
    phi = fmpz_poly(field.minpoly.numer())          # Phi_M, monic with integer coefficients
    d = int(a.poly.denom())
    b_int = fmpz_poly(a.poly.numer()) * d          # b = d^2 a, integral; sqrt(a) = sqrt(b)/d
    x = fmpz_poly([0, 1])
    powers = [fmpz_poly([1])]                       # zeta^j mod Phi, j = 0 .. n
    for _ in range(n):
        powers.append((powers[-1] * x) % phi)
    b_times = [b_int % phi]                         # zeta^j b mod Phi, j < n
    for _ in range(1, n):
        b_times.append((b_times[-1] * x) % phi)

    def coeffs(poly):
        c = [int(v) for v in poly.coeffs()]
        return c + [0] * (n - len(c))

    shifted = [coeffs(powers[j + 1]) for j in range(n)]
    b_cols = [coeffs(v) for v in b_times]
    for s in range(1, 64):
        # rows are the images of the basis zeta^j (j < n), zeta^j Y: multiplication by
        # s zeta + Y maps zeta^j -> s zeta^(j+1) + zeta^j Y, zeta^j Y -> zeta^j b + s zeta^(j+1) Y
        rows = []
        for j in range(n):
            rows.append([s * c for c in shifted[j]] + [int(i == j) for i in range(n)])
        for j in range(n):
            rows.append(b_cols[j] + [s * c for c in shifted[j]])
        norm = fmpz_mat(rows).charpoly()
        if norm.gcd(norm.derivative()).degree() > 0:
            continue                                # not squarefree: another shift
        _, factors = norm.factor()
        if len(factors) == 1 and factors[0][1] == 1:
            return None                             # N irreducible: F irreducible over K
        zeta = fmpz_poly([0, 1])
        c1 = 2 * s * zeta                           # X^2 = c1 X + c0 modulo F (integral)
        c0 = (b_int - s * s * zeta * zeta) % phi
        for g, _ in factors:
            u, v = fmpz_poly([0]), fmpz_poly([0])
            for coeff in reversed(g.coeffs()):
                u, v = (v * c0 + coeff) % phi, (u + v * c1) % phi
            if not v.is_zero():
                # u + v (s zeta + r) = 0 with r = sqrt(b) in Z[zeta] (the ring of integers):
                # r = -(u + s zeta v) / v, an exact quotient with small integer coefficients,
                # found modulo primes (an inverse of v over Q would have huge coefficients)
                r = _integral_quotient(-(u + s * zeta * v) % phi, v, phi, b_int % phi)
                z = field.element(fmpq_poly(r)) / d
                if z * z == a:
                    return z
                raise ArithmeticError("Trager square root does not square back (bug)")
        raise ArithmeticError("reducible norm without a linear factor of F (bug)")
    raise ArithmeticError("no squarefree norm for 63 shifts (bug)")


def _integral_quotient(num: fmpz_poly, den: fmpz_poly, phi: fmpz_poly,
                       square: fmpz_poly) -> fmpz_poly:
    """The r in Z[zeta] with r * den == num modulo phi, known to satisfy r^2 == square: r
    modulo 62-bit primes (``nmod_poly.xgcd``), combined by the Chinese remainder theorem
    into symmetric residues, the number of primes growing until r^2 == square modulo phi
    exactly (the test decides; the residues only propose)."""
    n = phi.degree()
    residues: list[int] = [0] * n
    modulus, i = 1, 0
    while True:
        p = nth_prime(i)
        i += 1
        phi_p = nmod_poly([int(c) % p for c in phi.coeffs()], p)
        den_p = nmod_poly([int(c) % p for c in den.coeffs()], p)
        g, inv, _ = den_p.xgcd(phi_p)
        if g.degree() != 0:
            continue                                # p divides the resultant: skip it
        q = (nmod_poly([int(c) % p for c in num.coeffs()], p) * inv) % phi_p
        q = q * pow(int(g.coeffs()[0]), -1, p)
        coeffs = [int(c) for c in q.coeffs()] + [0] * (n - len(q.coeffs()))
        m_inv = pow(modulus, -1, p)
        for j in range(n):
            residues[j] += modulus * ((coeffs[j] - residues[j]) * m_inv % p)
        modulus *= p
        half = modulus >> 1
        r = fmpz_poly([c - modulus if c > half else c for c in residues])
        if (r * r) % phi == square:
            return r
        if i > 4096:
            raise ArithmeticError("no integral quotient (bug)")


__all__ = ["field_sqrt", "refuted", "split_primes", "root_of_unity_mod", "image_mod"]
