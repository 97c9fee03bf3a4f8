"""cos and sin of rational turns as numbers of the motion: MQ, a RunTower, or K(alpha).

A start of the gathering simulator written with ``cos(q*pi)``, ``sin(q*pi)`` or polar
turns (``docs/format.md``) needs ``cos 2 pi t`` and ``sin 2 pi t`` for turns ``t = j/d`` in
the one number system its motion runs in (:mod:`.interface`).  All of them lie in the real
cyclotomic field ``Q(zeta_L)^+``, ``L = lcm(4, d_1, d_2, ...)`` (``sin 2 pi t = cos 2 pi
(1/4 - t)``), whose Galois group over Q is ``G = (Z/L)^* / {+-1}``.  Let ``H = G^2`` (the
squares):

* ``|G|`` a power of 2 and ``H = 1`` (``L | 24``): every value is multiquadratic
  (``multiquadratic``): products of ``cos, sin`` of ``2 pi/24`` (``(sqrt 6 +- sqrt 2)/4``);
* ``|G|`` a power of 2 and ``H != 1`` (``L = 2^a 3^b 5^c``, ``b, c <= 1``: turns j/5,
  j/16, j/20, j/40, ...): the field is a tower of quadratic extensions (``nested``): the
  values are numbers of one :class:`~.run_tower.RunTower` -- ``cos, sin`` of ``2 pi/5``
  (``sin = sqrt((5 + sqrt 5)/8)``, one level), halvings ``cos x/2 = sqrt((1 + cos x)/2)``,
  ``sin x/2 = sin x / (2 cos x/2)`` (one level each), and sums of angles by the Chinese
  remainder theorem; at most :data:`MAX_TURN_LEVELS` levels;
* ``|H|`` odd and ``> 1`` (the 2-part of G elementary: turns j/7, j/9, j/36, j/28, j/63,
  ...): ``alpha = 2 cos(2 pi/L)`` has odd degree ``|H|`` over the fixed field ``K`` of H,
  which is multiquadratic (``G/H`` is an elementary 2-group), so alpha's factor over K
  stays irreducible over every multiquadratic field and the numbers of ``K(alpha)``
  (:class:`~.algebraic_numbers.AlgebraicNumber`) are canonical (the soundness argument of
  :mod:`.algebraic_numbers`).  ``f`` = the factor over ``K' = Q(sqrt p : p | L odd prime;
  sqrt 2 when 8 | L)`` (a multiquadratic field holding K: the factor over K' is the one
  over K, odd degree) of alpha's rational minimal polynomial, found by
  :func:`.factor.factor_over_k` and picked by an exact Sturm count on a rational interval
  round alpha; ``cos 2 pi k/L = c_k / 2`` with ``c_0 = 2, c_1 = alpha, c_(k+1) = alpha
  c_k - c_(k-1)`` (Chebyshev), reduced modulo ``f``.  ``deg f <=`` :data:`MAX_ALPHA_DEGREE`
  and ``[K(alpha):Q] <=`` :data:`MAX_FIELD_DEGREE` (the degree the paper layer's kernel
  field holds, ``gathering.algebraic_kernel``);
* anything else (turns j/13, j/17, j/11: the 2-part of G is not elementary and G is not a
  2-group; or two families that need two systems, j/5 with j/36): refused
  (:class:`TurnBoundError`, naming the bound).

No float decides: alpha's interval is proposed by an Arb ball and accepted by an exact Sturm
count; every value is built by exact field arithmetic.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import reduce
from math import gcd

from flint import arb, ctx, fmpq, fmpz_poly

from ..multiquadratic import MQ
from .algebraic_numbers import AlgebraicNumber, AlgebraicRoot
from .factor import factor_over_k, stable
from .polynomials import ONE, ZERO
from .run_tower import RunTower, sqrt_exact
from .sturm import sturm_chain, variations

__all__ = ["TurnBoundError", "TurnField", "turn_field", "MAX_TURN_LEVELS",
           "MAX_ALPHA_DEGREE", "MAX_FIELD_DEGREE", "MAX_TURN_DENOMINATOR"]

#: The most quadratic levels the cos/sin of nested turns may need (j/5: 1, j/16: 2, j/80: 4).
MAX_TURN_LEVELS = 4
#: The largest odd degree of alpha = 2 cos(2 pi/L) over its multiquadratic subfield K.
MAX_ALPHA_DEGREE = 9
#: The largest degree of K(alpha) over Q (the paper layer's kernel field, 64).
MAX_FIELD_DEGREE = 64
#: The largest L = lcm(4, denominators of the turns) looked at.
MAX_TURN_DENOMINATOR = 720


class TurnBoundError(ValueError):
    """The turns need a number system beyond the motion's documented bounds."""


def _lcm(a: int, b: int) -> int:
    return a * b // gcd(a, b)


def group_orders(L: int) -> tuple:
    """``(|G|, |H|)`` for ``G = (Z/L)^*/{+-1}``, ``H = G^2`` (brute force, ``L`` small)."""
    units = [u for u in range(1, L) if gcd(u, L) == 1]
    classes = {min(u, L - u) for u in units}
    squares = {min(u * u % L, L - u * u % L) for u in units}
    return len(classes), len(squares)


def _odd_primes(L: int) -> list:
    out, n, p = [], L, 3
    while n % 2 == 0:
        n //= 2
    while p * p <= n:
        if n % p == 0:
            out.append(p)
            while n % p == 0:
                n //= p
        p += 2
    if n > 1:
        out.append(n)
    return out


def _mul(a, b):
    """(cos x, sin x) * (cos y, sin y) = (cos, sin) of x + y."""
    return (a[0] * b[0] - a[1] * b[1], a[0] * b[1] + a[1] * b[0])


def _power(a, k: int):
    out, base = (ONE, ZERO), a
    if k < 0:
        base, k = (a[0], -a[1]), -k
    while k:
        if k & 1:
            out = _mul(out, base)
        base = _mul(base, base)
        k >>= 1
    return out


@dataclass
class TurnField:
    """The number system of a set of turns: ``kind`` is ``"multiquadratic"``,
    ``"nested"`` (numbers of :attr:`tower`) or ``"algebraic"`` (numbers of K(alpha),
    :attr:`root`); :meth:`cos_sin` gives ``(cos 2 pi t, sin 2 pi t)`` exactly."""
    kind: str
    L: int
    unit: tuple                       # (cos, sin) of 2 pi / L
    tower: RunTower | None = None
    root: AlgebraicRoot | None = None

    def cos_sin(self, turn: fmpq) -> tuple:
        k = turn * self.L
        if k.q != 1:
            raise TurnBoundError(f"turn {turn} is outside this system (L = {self.L})")
        return _power(self.unit, int(k.p) % self.L)

    def describe(self) -> str:
        if self.kind == "algebraic":
            return (f"K(alpha), alpha = 2cos(2pi/{self.L}) of degree {self.root.degree} over "
                    "a multiquadratic field")
        return f"{self.kind} (L = {self.L})"


def turn_field(turns, tower: RunTower | None = None) -> TurnField:
    """The :class:`TurnField` of the rational ``turns`` (fmpq); ``tower``: the run's tower
    for nested values (a new one when None).  :class:`TurnBoundError` beyond the bounds."""
    L = reduce(_lcm, (int(fmpq(t).q) for t in turns), 4)
    if L > MAX_TURN_DENOMINATOR:
        raise TurnBoundError(f"turns with denominators of lcm {L}: the motion's bound is "
                             f"lcm(4, denominators) <= {MAX_TURN_DENOMINATOR}")
    g, h = group_orders(L)
    if h == 1:
        return TurnField("multiquadratic", L, _power(_unit24(), 24 // L))   # L | 24
    if g & (g - 1) == 0:
        tower = tower if tower is not None else RunTower()
        return TurnField("nested", L, _nested_unit(L, tower), tower=tower)
    if h % 2 == 0:
        raise TurnBoundError(
            f"cos/sin of turns j/{L}: (Z/{L})*/(+-1) has a 2-part that is not elementary, so "
            "the values are neither nested square roots nor numbers of an odd-degree "
            "K(alpha) (the motion's bound: a 2-group, or an odd group of squares)")
    if h > MAX_ALPHA_DEGREE or g > MAX_FIELD_DEGREE:
        raise TurnBoundError(
            f"cos/sin of turns j/{L} need alpha = 2cos(2pi/{L}) of degree {h} over K and "
            f"{g} over Q: the motion's bound is degree <= {MAX_ALPHA_DEGREE} over K and "
            f"<= {MAX_FIELD_DEGREE} over Q")
    root = _alpha_root(L, h)
    alpha = AlgebraicNumber(root, (ZERO, ONE))
    c_prev, c = MQ.rational(2), alpha                # c_k = 2 cos(2 pi k/L), from k = 1
    for _ in range(L // 4 - 2):                       # to c_(L/4 - 1) (L >= 28 here):
        c_prev, c = c, alpha * c - c_prev             # sin 2pi/L = cos 2pi (L/4 - 1)/L
    return TurnField("algebraic", L, (alpha / 2, c / 2), root=root)


def _unit24() -> tuple:
    """(cos, sin) of 2 pi / 24 = 15 degrees: ((sqrt 6 + sqrt 2)/4, (sqrt 6 - sqrt 2)/4)."""
    q = fmpq(1, 4)
    return (MQ({6: q, 2: q}), MQ({6: q, 2: -q}))


def _nested_unit(L: int, tower: RunTower) -> tuple:
    """(cos, sin) of 2 pi / L for ``L = 2^a 3^b 5^c`` (``b, c <= 1``), in ``tower``."""
    parts, n, twos = [], L, 0
    while n % 2 == 0:
        n, twos = n // 2, twos + 1
    for p in (3, 5):
        if n % p == 0:
            parts.append(p)
            n //= p
    if n != 1:
        raise TurnBoundError(f"turns j/{L}: nested values only for 2^a 3^b 5^c, b, c <= 1")
    parts.append(1 << twos)
    start = tower.levels
    values = []
    for m in parts:
        values.append(_prime_power_unit(m, tower))
    if tower.levels - start > MAX_TURN_LEVELS:
        raise TurnBoundError(f"cos/sin of turns j/{L} need {tower.levels - start} nested "
                             f"levels: the motion's bound is {MAX_TURN_LEVELS}")
    # 1/L = sum a_i / m_i (Chinese remainder theorem): the product of the rotations
    out = (ONE, ZERO)
    for m, v in zip(parts, values):
        rest = L // m
        a = pow(rest, -1, m) if m > 1 else 0   # a rest == 1 (mod m): a/m = a rest / L
        out = _mul(out, _power(v, a))
    # out is the rotation by 2 pi (sum a_i/m_i), equal to 2 pi k/L with k = 1 mod L
    return out


def _prime_power_unit(m: int, tower: RunTower) -> tuple:
    if m == 1:
        return (ONE, ZERO)
    if m == 3:
        return (MQ.rational(fmpq(-1, 2)), MQ({3: fmpq(1, 2)}))
    if m == 5:
        c = MQ({5: fmpq(1, 4), 1: fmpq(-1, 4)})
        return (c, sqrt_exact(MQ({1: fmpq(5, 8), 5: fmpq(1, 8)}), tower))
    if m in (2, 4, 8):
        return {2: (MQ.rational(-1), ZERO), 4: (ZERO, ONE),
                8: (MQ({2: fmpq(1, 2)}), MQ({2: fmpq(1, 2)}))}[m]
    c, s = _prime_power_unit(m // 2, tower)           # halve the angle 2 pi/(m/2)
    ch = sqrt_exact((c + 1) / 2, tower)
    return (ch, s / (ch * 2))


def _alpha_root(L: int, degree: int) -> AlgebraicRoot:
    """alpha = 2 cos(2 pi/L) as a root of its factor over K' (module docstring)."""
    rational = fmpz_poly.cos_minpoly(L)
    radicands = _odd_primes(L) + ([2] if L % 8 == 0 else [])
    p = tuple(MQ.rational(fmpq(int(c))) for c in rational.coeffs())
    factors = factor_over_k(p, tuple(radicands))
    if factors is None:
        raise TurnBoundError(f"alpha = 2cos(2pi/{L}): its factor over K is beyond the "
                             "factoring bound (factor.MAX_NORM_DEGREE)")
    lo, hi = _isolating_interval(rational, L)
    held = [f for f in factors if _count(f, lo, hi) == 1]
    if len(held) != 1 or len(held[0]) - 1 != degree or not stable(held[0]):
        raise TurnBoundError(f"alpha = 2cos(2pi/{L}): no factor of odd degree {degree}")
    return AlgebraicRoot.of(held[0], lo, hi)


def _count(f, lo, hi) -> int:
    chain = sturm_chain(f)
    return variations(chain, MQ.rational(lo)) - variations(chain, MQ.rational(hi))


def _isolating_interval(rational: fmpz_poly, L: int) -> tuple:
    """A rational interval holding alpha and no other root of its rational minimal
    polynomial (an Arb ball proposes it; an exact Sturm count accepts it)."""
    chain = sturm_chain(tuple(MQ.rational(fmpq(int(c))) for c in rational.coeffs()))
    for prec in (64, 128, 256, 512, 1024):
        with ctx.workprec(prec + 16):
            ball = 2 * (2 * arb.pi() / L).cos()
            den = 1 << prec
            lo = fmpq(int((ball.lower() * den).floor().unique_fmpz()) - 1, den)
            hi = fmpq(int((ball.upper() * den).ceil().unique_fmpz()) + 1, den)
        if variations(chain, MQ.rational(lo)) - variations(chain, MQ.rational(hi)) == 1:
            return lo, hi
    raise TurnBoundError(f"alpha = 2cos(2pi/{L}) could not be isolated")
