"""The cyclotomic field Q(zeta_M): cosines, sines and square roots of rationals.

Why this field (see ``docs/numbers.md``): ``cos(2 pi k/M)`` and ``sin(2 pi k/M)``
(``4 | M``) are ``(z^k + z^-k)/2`` and ``(z^k - z^-k)/(2i)`` with ``i = z^(M/4)``,
and ``sqrt(p)`` is a Gauss sum in Q(zeta_p) or Q(zeta_4p).  So every coordinate
of a polar configuration and every square root of a rational lives in one field
whose minimal polynomial (the cyclotomic polynomial) is known in closed form:
no primitive-element computation, and elements are built in microseconds.
"""

from __future__ import annotations

from math import gcd

from flint import acb, arb, fmpq, fmpq_poly, fmpz_poly

from .factor import factorization
from .field import FieldElement, NumberField

#: Largest field degree phi(M) we build; beyond it arithmetic costs milliseconds.
MAX_DEGREE = 16384


def euler_phi(m: int) -> int:
    result = m
    for p in factorization(m):
        result = result // p * (p - 1)
    return result


def lcm(a: int, b: int) -> int:
    return a // gcd(a, b) * b


def squarefree_decomposition(q: fmpq) -> tuple[fmpq, int]:
    """``(c, s)`` with ``sqrt(q) = c * sqrt(s)``, ``c`` rational, ``s`` a squarefree positive integer."""
    num, den = int(q.p), int(q.q)
    n = num * den
    square, free = 1, 1
    for p, e in factorization(n).items():
        square *= p ** (e // 2)
        if e % 2:
            free *= p
    return fmpq(square, den), free


def sqrt_conductor(s: int) -> int:
    """A conductor M such that Q(zeta_M) holds sqrt(s) as built by :func:`sqrt_element`."""
    m = 1
    for p in factorization(s):
        m = lcm(m, 8 if p == 2 else (p if p % 4 == 1 else 4 * p))
    return m


def turn_conductor(turn: fmpq, func: str) -> int:
    """Conductor needed for ``cos`` or ``sin`` of ``turn`` full turns."""
    den = int(turn.q)
    return lcm(den, 4) if func == "sin" else den


class CyclotomicField(NumberField):
    """Q(zeta_m) with zeta_m = exp(2 pi i / m): a number field that holds the square
    roots of the integers whose conductor divides m (Gauss sums)."""

    def __init__(self, m: int):
        def enclose(prec: int):
            from flint import ctx
            with ctx.workprec(prec + 16):
                angle = fmpq(2, m)
                return acb(arb.cos_pi_fmpq(angle), arb.sin_pi_fmpq(angle))

        super().__init__(fmpq_poly(fmpz_poly.cyclotomic(m)), enclose, f"Q(zeta_{m})",
                         theta_text=None, conductor=m)
        self.cyclotomic_order = m

    def sqrt_of_integer(self, m: int) -> FieldElement:
        if self.conductor % sqrt_conductor(m):
            raise TypeError("elements of two different number fields do not mix")
        return sqrt_element(self, fmpq(m))


def cyclotomic_field(m: int) -> NumberField:
    """Q(zeta_m) with zeta_m = exp(2 pi i / m)."""
    return CyclotomicField(m)


def root_of_unity(field: NumberField, k: int) -> FieldElement:
    """``zeta_M^k`` for the field's order M.

    With r the product of the primes dividing M and s = M / r, Phi_M(x) = Phi_r(x^s) and
    phi(M) = s phi(r): x^k = x^a (x^s)^b (k = b s + a, a < s) is reduced as y^b modulo
    Phi_r(y), whose remainder (degree < phi(r)) becomes, at y = x^s and times x^a, a
    polynomial of degree < phi(M): the canonical element, without dividing x^k by
    Phi_M (a quadratic division: 6 ms per root in Q(zeta_27720))."""
    m = field.cyclotomic_order
    k %= m
    n = field.degree
    if k < n:
        return field.element(fmpq_poly([0] * k + [1]))
    r, phi_r = _radical_cyclotomic(m)
    s = m // r
    a, b = k % s, k // s
    small = fmpz_poly([0] * b + [1]) % phi_r
    coeffs = [0] * n
    for i, c in enumerate(small.coeffs()):
        coeffs[a + i * s] = c
    return field.element(fmpq_poly(coeffs))


_RADICAL: dict = {}         # m -> (r, Phi_r): by value, a few entries per field seen


def _radical_cyclotomic(m: int) -> tuple:
    """``(r, Phi_r)`` for r the product of the primes dividing m."""
    found = _RADICAL.get(m)
    if found is None:
        r = 1
        for p in factorization(m):
            r *= p
        if len(_RADICAL) >= 256:           # a bound on the memory
            _RADICAL.clear()
        found = _RADICAL[m] = (r, fmpz_poly.cyclotomic(r))
    return found


def cos_turn(field: NumberField, turn: fmpq) -> FieldElement:
    """``cos(2 pi turn)``; the turn's denominator must divide the field's order."""
    m = field.cyclotomic_order
    k = turn * m
    if k.q != 1:
        raise ValueError(f"turn {turn} is not in Q(zeta_{m})")
    k = int(k.p)
    return (root_of_unity(field, k) + root_of_unity(field, -k)) / 2


def sin_turn(field: NumberField, turn: fmpq) -> FieldElement:
    """``sin(2 pi turn) = cos(2 pi (1/4 - turn))``."""
    return cos_turn(field, fmpq(1, 4) - turn)


def _legendre(a: int, p: int) -> int:
    r = pow(a, (p - 1) // 2, p)
    return -1 if r == p - 1 else r


def _sqrt_prime(field: NumberField, p: int) -> FieldElement:
    """An element whose square is p (sign not yet fixed)."""
    m = field.cyclotomic_order
    if p == 2:  # zeta_8 + zeta_8^-1 = sqrt(2)
        return root_of_unity(field, m // 8) + root_of_unity(field, -(m // 8))
    step = m // p
    gauss = field(0)
    for a in range(1, p):
        gauss = gauss + _legendre(a, p) * root_of_unity(field, a * step)
    if p % 4 == 1:
        return gauss
    return gauss * root_of_unity(field, -(m // 4))    # g = i sqrt(p)  =>  sqrt(p) = -i g up to sign


def sqrt_element(field: NumberField, q: fmpq) -> FieldElement:
    """The non-negative square root of the rational ``q >= 0``."""
    c, s = squarefree_decomposition(q)
    root = field(1)
    for p in factorization(s):
        root = root * _sqrt_prime(field, p)
    if root * root != s:
        raise ArithmeticError(f"Gauss sum for sqrt({s}) is wrong")  # cannot happen
    if root.sign() < 0:
        root = -root
    return c * root
