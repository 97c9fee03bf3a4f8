"""Square roots of rationals over Q(zeta_M): which rationals are squares, by Kummer theory.

A :class:`~.cyclotomic_tower.CyclotomicTower` whose levels are all square roots of positive
rationals r_1, ..., r_L is K_L = F(sqrt r_1, ..., sqrt r_L) over the real subfield F of
Q(zeta_M).  By Kummer theory (F has characteristic 0 and holds -1), a rational q > 0 is a
square in K_L iff q is in F*^2 <r_1, ..., r_L>; a rational in F*^2 is a rational whose square
root lies in Q(zeta_M) (a real root of a real field element's square), and with 4 | M those
are exactly the rationals whose squarefree part is made of odd primes dividing M and of 2
when 8 | M (the conductor of Q(sqrt d) is d or 4d).  So "is q a square in K_L?" is linear
algebra over F_2 on the exponent vectors of the primes: no field arithmetic, no recursion
over the levels (:meth:`.tower.Tower.root_in` costs 2^L tests), and a level is added for a
rational exactly when its class is new (issue 9: square-root radii at turns j/997, where a
square root as a Gauss sum of Q(zeta_N) had hundreds of terms whose products grew without
bound).

Public names: :class:`SquareClasses`.
"""

from __future__ import annotations

from math import isqrt

from flint import fmpq

from .factor import factorization


class SquareClasses:
    """The classes of positive rationals modulo squares, the ones whose root Q(zeta_M) holds,
    and the radicands r_1, ..., r_L added so far (in order, by :meth:`add`)."""

    def __init__(self, conductor: int):
        if conductor % 4:
            raise ValueError("the conductor must be divisible by 4")
        self.base = sorted(p for p in factorization(conductor) if p != 2 or conductor % 8 == 0)
        self.primes: list[int] = []          # primes of the radicands outside the base
        self._rows: dict[int, tuple[int, int]] = {}   # pivot bit -> (vector, levels mask)
        self.levels = 0

    def _vector(self, q: fmpq, grow: bool):
        """The exponent vector of q modulo 2 on the radicands' primes (the base primes
        dropped: Q(zeta_M) holds their roots); None when a prime outside the known ones has
        an odd exponent (and ``grow`` is false)."""
        n = int(q.p) * int(q.q)
        for p in self.base:
            while n % p == 0:
                n //= p
        vector = 0
        for i, p in enumerate(self.primes):
            e = 0
            while n % p == 0:
                n //= p
                e += 1
            if e % 2:
                vector |= 1 << i
        if isqrt(n) ** 2 != n:
            if not grow:
                return None
            for p, e in factorization(n).items():
                if e % 2:
                    self.primes.append(p)
                    vector |= 1 << (len(self.primes) - 1)
        return vector

    def _reduce(self, vector: int, mask: int):
        """The vector reduced by the rows (highest bit first: a row's pivot is its highest
        bit, so a reduction never sets a higher pivot again) and the levels used."""
        while vector:
            row = self._rows.get(vector.bit_length() - 1)
            if row is None:
                break
            vector ^= row[0]
            mask ^= row[1]
        return vector, mask

    def express(self, q: fmpq):
        """The levels i (indices into the radicands) with q / prod(r_i) a rational whose square
        root Q(zeta_M) holds, or None when q > 0 is not a square in F(sqrt r_1, ...,
        sqrt r_L)."""
        found = self._vector(q, grow=False)
        if found is None:
            return None
        vector, mask = self._reduce(found, 0)
        if vector:
            return None
        return [i for i in range(mask.bit_length()) if mask >> i & 1]

    def add(self, r: fmpq) -> None:
        """Record the radicand of the next level (the caller has found it new: express(r) is
        None)."""
        vector, mask = self._reduce(self._vector(r, grow=True), 1 << self.levels)
        if not vector:
            raise ValueError(f"{r} is already a square")
        self._rows[vector.bit_length() - 1] = (vector, mask)
        self.levels += 1


__all__ = ["SquareClasses"]
