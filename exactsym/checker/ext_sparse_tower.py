"""Checker extension: square roots of rationals, and nested radicals, over the sparse Q(zeta_N)
(standard library only; docs/certificates.md, "Square roots of rationals over the sparse
Q(zeta_N)").

Field ``{"tower": {"base": {"sparse-cyclotomic": SPEC}, "levels": [{"radicand": r_i,
"kummer": true}, ..., {"radicand": r_k, "prime": l, "zeta": w, "roots": [s_1, ...]}, ...],
"kummer": [{"prime": p}, ...]}}``: K_0 is the real subfield F of Q(zeta_N), its numbers the
sums of cosines of :class:`ext_sparse.SparseField` (``SPEC`` as there: the factors of N,
the hashing prime l and its root of order N); K_i = K_(i-1)(y_i), y_i the positive square
root of r_i > 0.  The first levels are kummer levels (r_i rational), proved together
(:meth:`SparseKummerTower._prove_kummer`); each level above them (a nested radical) is
proved by a ring map onto F_l (:meth:`SparseKummerTower._prove_nested`).  The kummer proof:

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
numbers, which are compared by the exact zero test of :mod:`ext_sparse`; the hash is
the base numbers' residues modulo l (equal numbers, equal residues).  Signs: a base number's
by :meth:`ext_sparse.SparseField.sign` (zero test, then enclosures); A + B y_i with
B != 0 is not 0 (y_i is not in K_(i-1)), so integer enclosures of it at doubling precision
(each y_i enclosed from its radicand's) end with 0 excluded.
"""

from __future__ import annotations

from fractions import Fraction

from .ext_primes import is_prime
from .ext_sparse import SNum, SparseField
from .ext_tower import Tower, add_legendre_row
from .numbers import integer, need


class SparseKummerTower(Tower):
    """The field of a ``"tower"`` spec whose base is ``{"sparse-cyclotomic": ...}``: checks
    the base and the proof of the levels, then makes elements (:class:`ext_tower.TNum`)."""

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
            need(isinstance(lev, dict), f"tower level {i}: not an object")
            r = self._read(lev.get("radicand"), i - 1)
            if lev.get("kummer") is True:
                need(len(rationals) == i - 1, f"tower level {i}: a kummer level above a "
                     "nested one")
                q = _rational(r)
                need(q is not None and q > 0,
                     f"tower level {i}: a kummer radicand must be a positive rational")
                rationals.append(q)
            else:
                need(self._sign(r) > 0, f"tower level {i}: the radicand is not positive")
                self._prove_nested(i, r, lev)
            self.r.append(r)
        if rationals:
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


    # -- the proof that a nested radicand r_i is not a square in K_(i-1) ------------------
    def _prove_nested(self, i: int, r, lev: dict) -> None:
        """A prime l = 1 mod N (Miller-Rabin below 3.3 * 10^24), w of order N modulo l and
        roots s_j with s_j^2 = phi(r_j) != 0 mod l for j < i, every denominator prime to l,
        and phi(r_i) a non-residue (Euler's criterion).  Then w is a simple root of Phi_N mod
        l (l does not divide N), so zeta_N -> w is a ring map phi from A = Z_(l)[zeta_N],
        a regular ring (l is unramified), onto F_l, and cos(2 pi e/N) -> (w^e + w^-e)/2.
        B = A[Y_1, ..., Y_(i-1)] / (Y_j^2 - r_j) extends it by Y_j -> s_j; B is a domain
        (its levels are proper: proved below it), its fraction field is K_(i-1), and at
        q = ker phi its Jacobian prod 2 s_j is a unit, so B_q is etale over A, regular of
        dimension 1: a discrete valuation ring, integrally closed.  If r_i = z^2, z in
        K_(i-1), z is integral over B_q (a root of X^2 - r_i), so z in B_q and
        phi(r_i) = phi(z)^2 would be a square mod l."""
        where = f"tower level {i}"
        p, w, roots = lev.get("prime"), lev.get("zeta"), lev.get("roots")
        need(all(isinstance(v, (str, int)) and not isinstance(v, bool) for v in (p, w)),
             f"{where}: a nested level needs a prime and zeta")
        p, w, n = integer(str(p)), integer(str(w)), self.base.n
        need(p > 2 and p % n == 1 and is_prime(p),
             f"{where}: {p} is not an odd prime = 1 mod {n} below the Miller-Rabin bound")
        need(0 < w < p and pow(w, n, p) == 1
             and all(pow(w, n // q, p) != 1 for q, _ in self.base.factors),
             f"{where}: zeta does not have order N modulo {p}")
        need(isinstance(roots, list) and len(roots) == i - 1, f"{where}: one root per level "
             "below")
        roots = [integer(str(t)) % p for t in roots]
        for j, rj in enumerate(self.r):
            image = _image(rj, p, w, roots)
            need(image is not None and image != 0,
                 f"{where}: radicand {j + 1} is not a unit modulo {p}")
            need((roots[j] * roots[j] - image) % p == 0,
                 f"{where}: {roots[j]} is not a root of radicand {j + 1} modulo {p}")
        image = _image(r, p, w, roots)
        need(image is not None and pow(image, (p - 1) // 2, p) == p - 1,
             f"{where}: the radicand's image is not a non-residue modulo {p}")


def _image(x, p: int, w: int, roots: list):
    """phi(x): zeta_N -> w, y_j -> roots[j - 1]; None when a denominator is divisible by p."""
    if isinstance(x, tuple):
        lev, a, b = x
        ia, ib = _image(a, p, w, roots), _image(b, p, w, roots)
        return None if ia is None or ib is None else (ia + ib * roots[lev - 1]) % p
    return None if x.den % p == 0 else x.f.image(x.t, x.den, p, w)


def _rational(x):
    """The rational value of a base number written as its constant term only, else None."""
    if isinstance(x, tuple) or set(x.t) - {0}:
        return None
    return Fraction(x.t.get(0, 0), x.den)

