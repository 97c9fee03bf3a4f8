"""Square roots of rationals over the sparse Q(zeta_N) in the independent checker (standard
library only; shares no code with the solver; docs/certificates.md, "Square roots of rationals
over the sparse Q(zeta_N)").

Field ``{"tower": {"base": {"sparse-cyclotomic": SPEC}, "levels": [{"radicand": r_i,
"kummer": true}, ...], "kummer": [{"prime": p}, ...]}}``: K_0 is the real subfield F of
Q(zeta_N), its numbers the sums of cosines of :class:`checker_sparse.SparseField` (``SPEC``
as there: the factors of N, the hashing prime l and its root of order N); K_i = K_(i-1)(y_i),
y_i the positive square root of the positive rational r_i.  Every level must be a kummer
level, and the levels are proved together (:meth:`SparseKummerTower._prove_kummer`):

* Kummer theory (exponent 2, characteristic 0): if x in a field K is a square in K(sqrt r),
  x = (c + d sqrt r)^2, then 2cd = 0 when sqrt r is not in K, so x = c^2 or x = r d^2.
  Down the levels, a rational q that is a square in K_(i-1) has q prod_(j in S) r_j in F*^2
  for some S in {1, ..., i - 1} (also when a lower level were not proper).
* Each listed p is prime (deterministic Miller-Rabin, below 3.3 * 10^24), p = 1 mod N and p
  divides no numerator or denominator of a radicand.  Then F_p^* (cyclic, N | p - 1) holds
  a primitive N-th root of unity g, a simple root of Phi_N modulo p (X^N - 1 is separable as
  p does not divide N), so zeta_N -> g is a ring map phi: Z_(p)[zeta_N] -> F_p; disc(Phi_N)
  divides a power of N, a p-unit, so Z_(p)[zeta_N] is integrally closed.  An s in F with
  s^2 = q, q a rational p-unit, is integral over Z_(p) (a root of X^2 - q), so it lies in
  Z_(p)[zeta_N], and phi(s)^2 = q mod p != 0: the Legendre symbol (q | p) is 1.
* The vectors ((r_i | p))_p (Euler's criterion) have rank L over F_2 (checked), so no
  non-empty product of the r_i has all its symbols 1: no r_i prod_(j in S) r_j is in F*^2,
  and no r_i is a square in K_(i-1).  Each level is proper, {1, y_i} is a basis of K_i over
  K_(i-1), and the form below is unique.

Elements: a rational or ``{"e": c, ...}`` (a number of the sparse base), or ``[i, A, B]`` =
A + B y_i with A, B of levels below i and B != 0.  Equality is structural down to base
numbers, which are compared by the exact zero test of :mod:`checker_sparse`; the hash is
the base numbers' residues modulo l (equal numbers, equal residues).  Signs: a base number's
by :meth:`checker_sparse.SparseField.sign` (zero test, then enclosures); A + B y_i with
B != 0 is not 0 (y_i is not in K_(i-1)), so integer enclosures of it at doubling precision
(each y_i enclosed from its radicand's) end with 0 excluded.
"""

from __future__ import annotations

from fractions import Fraction

try:
    from .checker_numbers import integer, need
    from .checker_sparse import SNum, SparseField, is_prime
    from .checker_tower import Tower, add_legendre_row
except ImportError:     # run as a lone script: sibling files
    from checker_numbers import integer, need
    from checker_sparse import SNum, SparseField, is_prime
    from checker_tower import Tower, add_legendre_row


class SparseKummerTower(Tower):
    """The field of a ``"tower"`` spec whose base is ``{"sparse-cyclotomic": ...}``: checks
    the base and the proof of the levels, then makes elements (:class:`checker_tower.TNum`)."""

    base_number = SNum          # a base number's sign: the sparse zero test, then balls

    def __init__(self, spec: dict):
        need(isinstance(spec, dict) and isinstance(spec.get("base"), dict)
             and set(spec["base"]) == {"sparse-cyclotomic"}
             and isinstance(spec.get("levels"), list) and spec["levels"],
             "tower: a sparse-cyclotomic base and a non-empty list of levels")
        self.base = SparseField(spec["base"]["sparse-cyclotomic"])
        self.r: list = []
        self._balls: dict = {}
        rationals: list = []
        for i, lev in enumerate(spec["levels"], start=1):
            need(isinstance(lev, dict) and lev.get("kummer") is True,
                 f"tower level {i}: over a sparse base every level is a kummer level")
            r = self._read(lev.get("radicand"), i - 1)
            q = _rational(r)
            need(q is not None and q > 0,
                 f"tower level {i}: a kummer radicand must be a positive rational")
            rationals.append(q)
            self.r.append(r)
        self._prove_kummer(rationals, spec.get("kummer"))

    def base_num(self, value):
        need(isinstance(value, (str, int, dict)) and not isinstance(value, bool),
             f"tower element {value!r:.60}: not a number")
        return self.base.num(value)

    def base_of(self, o):
        return self.base.make({0: Fraction(o)})

    # -- signs ----------------------------------------------------------------
    def _interval(self, x, bits: int):
        """Integers lo <= x 2^bits <= hi."""
        if isinstance(x, SNum):
            lo, hi = self.base.term_bounds(x.t, bits)
            return lo // x.den, -(-hi // x.den)
        return Tower._interval(self, x, bits)

    # -- the proof that no r_i is a square in K_(i-1) ----------------------------
    def _prove_kummer(self, rationals: list, primes) -> None:
        """The Legendre symbols (r_i | p) at the listed primes p = 1 mod N have rank L over
        F_2: no r_i is a square in K_(i-1) (the module's docstring)."""
        need(isinstance(primes, list), "tower: kummer levels need a \"kummer\" list of primes")
        n = self.base.n
        values = [q.numerator * q.denominator for q in rationals]
        rows: dict = {}
        for k, entry in enumerate(primes):
            need(isinstance(entry, dict) and isinstance(entry.get("prime"), (str, int))
                 and not isinstance(entry.get("prime"), bool),
                 f"tower kummer prime {k + 1}: not an object with a prime")
            p = integer(str(entry["prime"]))
            need(p > 2 and p % n == 1 and is_prime(p),
                 f"tower kummer prime {k + 1}: {p} is not an odd prime = 1 mod {n}")
            need(all(v % p for v in values), f"tower kummer prime {p} divides a radicand")
            add_legendre_row(rows, values, p)
        need(len(rows) == len(values), f"tower: the Legendre symbols of the kummer levels "
             f"have rank {len(rows)} over F_2, not {len(values)}")


def _rational(x):
    """The rational value of a base number written as its constant term only, else None."""
    if isinstance(x, tuple) or set(x.t) - {0}:
        return None
    return Fraction(x.t.get(0, 0), x.den)


__all__ = ["SparseKummerTower"]
