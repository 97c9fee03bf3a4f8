"""A tower of quadratic extensions over Q(theta) in the independent checker (standard library
only; shares no code with the solver; docs/certificates.md, "Towers over Q(zeta_M)").

Field ``{"tower": {"base": FIELD, "levels": [level_1, ...]}}``: K_0 = Q(theta) is the field
of :class:`checker_numbers.Field` (``FIELD`` = minimal polynomial, isolating interval and
irreducibility proof, e.g. the real-cyclotomic Psi_M of theta = 2cos(2pi/M)), whose minimal
polynomial f must be monic with integer coefficients; K_i = K_(i-1)(y_i), y_i the positive
square root of ``level_i["radicand"]`` = r_i, proved > 0 and NOT a square in K_(i-1) by
``level_i["prime"]`` p, ``"theta"`` (the d = deg f roots of f modulo p, the map using the
first) and ``"roots"`` (a root of the image of each r_j, j < i): see
:meth:`CyclotomicTower._prove`.

Elements: a rational ``"p/q"``; ``{"theta": [c_0, c_1, ...]}`` = sum c_k theta^k in K_0;
``[i, A, B]`` = A + B y_i (B != 0).  The form is unique, as in :mod:`checker_tower`.
Signs are exact: sign(A + B y) is sign(A) when A, B agree in sign, else
sign(A) * sign(A^2 - r B^2) (|A| > |B| y iff A^2 > r B^2), down to signs in Q(theta).
"""

from __future__ import annotations

from fractions import Fraction

try:
    from .arithmetic import Field, integer, need
    from .tower import Tower, _add, _is_prime, _level, _neg, _split, add_legendre_row
except ImportError:     # run as a lone script: sibling files
    from checker_numbers import Field, integer, need
    from checker_tower import Tower, _add, _is_prime, _level, _neg, _split, add_legendre_row


class CyclotomicTower(Tower):
    """The field of a ``"tower"`` spec with a ``"base"`` field: checks every level."""

    #: no integer enclosures of a base number here (its signs come from Field's isolating
    #: interval): checker_ordering compares angles exactly
    bounds = None

    def __init__(self, spec: dict):
        need(isinstance(spec, dict) and isinstance(spec.get("base"), dict)
             and isinstance(spec.get("levels"), list) and spec["levels"],
             "tower: a base field and a non-empty list of levels")
        self.base = Field(spec["base"])
        need(all(c.denominator == 1 for c in self.base.p),
             "tower base: the minimal polynomial of theta must have integer coefficients")
        self.f = [int(c) for c in self.base.p]           # monic: checked by Field
        self.r: list = []
        rationals: list = []            # the radicands of the "kummer" levels
        for i, lev in enumerate(spec["levels"], start=1):
            need(isinstance(lev, dict), f"tower level {i}: not an object")
            r = self._read(lev.get("radicand"), i - 1)
            if lev.get("kummer") is True:
                need(len(rationals) == i - 1, f"tower level {i}: a kummer level above "
                     "a level that is not")
                q = _rational(r)
                need(q is not None and q > 0, f"tower level {i}: a kummer radicand must be "
                     "a positive rational")
                rationals.append(q)
            else:
                self._prove(i, r, lev)
            self.r.append(r)
            need(self._sign(r) > 0, f"tower level {i}: the radicand is not positive")
        if rationals:
            self._prove_kummer(rationals, spec.get("kummer"))

    def base_num(self, value):
        if isinstance(value, dict):
            need(set(value) == {"theta"} and isinstance(value["theta"], list),
                 "a base number of the tower is a rational or {\"theta\": [c_0, ...]}")
            return self.base.num(value["theta"])
        need(isinstance(value, (str, int)) and not isinstance(value, bool),
             f"tower element {value!r:.60}: not a number")
        return self.base.num(value)

    def base_of(self, o):
        q = Fraction(o)
        return self.base.make([q.numerator] if q else [], q.denominator)

    def _sign(self, x) -> int:
        if not isinstance(x, tuple):
            return self.base.sign(x.c)                  # den > 0
        lev, a, b = x
        sa, sb = self._sign(a), self._sign(b)
        if sa == 0 or sa == sb:
            return sb if sa == 0 else sa
        n = _add(self.mul(a, a), _neg(self.mul(self.r[lev - 1], self.mul(b, b))))
        return sa * self._sign(n)

    # -- the proof that r_i is not a square in K_(i-1) ---------------------------------
    def _prove(self, i: int, r, lev: dict) -> None:
        """f is monic integral with d distinct roots h_1..h_d modulo the odd prime p
        (:meth:`_split_roots`): theta -> h_1 is a ring map R_0 -> F_p.  N_(K_0/Q)(n) =
        Res(f, n) is, modulo p, prod n(h_k).  With every r_j (j < i) p-integral and N(r_j)
        a p-unit (the norm taken down the tower, a^2 - r b^2 per level, then over K_0),
        R = R_0[y_1..y_(i-1)] has a discriminant over Z_(p) that is a p-unit, so it is
        integrally closed, and y_j -> roots_j (roots_j^2 = phi(r_j) mod p, checked)
        extends the map to R.  If r_i = z^2 in K_(i-1) with r_i in R, z is integral over
        R, so z is in R and phi(r_i) = phi(z)^2 would be a square mod p; it is checked to
        be a non-residue."""
        p, roots = lev.get("prime"), lev.get("roots")
        thetas = self._split_roots(f"tower level {i}", p, lev.get("theta"))
        need(isinstance(roots, list) and len(roots) == i - 1,
             f"tower level {i}: one root per level below")
        roots = [integer(t) if isinstance(t, str) else t for t in roots]
        need(all(isinstance(v, int) and not isinstance(v, bool) and 0 <= v < p
                 for v in roots), f"tower level {i}: roots must be integers in [0, p)")
        h = thetas[0]
        for j, rj in enumerate(self.r):
            need(_integral(rj, p), f"tower level {i}: p divides a denominator of radicand {j + 1}")
            n = self._base_norm(rj)
            norm = 1
            for t in thetas:
                norm = norm * _image(n, p, t, []) % p
            need(norm != 0, f"tower level {i}: p divides the norm of radicand {j + 1}")
            need((roots[j] ** 2 - _image(rj, p, h, roots)) % p == 0,
                 f"tower level {i}: {roots[j]} is not a root of radicand {j + 1} modulo {p}")
        need(_integral(r, p), f"tower level {i}: p divides a denominator of the radicand")
        value = _image(r, p, h, roots)
        need(pow(value, (p - 1) // 2, p) == p - 1,
             f"tower level {i}: the radicand's image {value} is a square modulo {p}")

    def _split_roots(self, where: str, p, thetas) -> list:
        """The d = deg f distinct roots of f modulo the odd prime p (checked): then
        f = prod (X - h_k) mod p, disc(f) is a p-unit, R_0 = Z_(p)[theta] is integrally
        closed and theta -> h_1 is a ring map R_0 -> F_p."""
        need(isinstance(p, int) and not isinstance(p, bool) and 2 < p < 1 << 40
             and _is_prime(p), f"{where}: {p!r} is not an odd prime below 2^40")
        d = self.base.d
        need(isinstance(thetas, list) and len(thetas) == d,
             f"{where}: {d} roots of the minimal polynomial modulo p")
        thetas = [integer(h) if isinstance(h, str) else h for h in thetas]
        need(all(isinstance(v, int) and not isinstance(v, bool) and 0 <= v < p
                 for v in thetas), f"{where}: roots must be integers in [0, p)")
        need(len(set(thetas)) == d, f"{where}: the roots modulo {p} are not distinct")
        for h in thetas:
            need(_eval_mod(self.f, h, p) == 0,
                 f"{where}: {h} is not a root of the minimal polynomial modulo {p}")
        return thetas

    def _prove_kummer(self, rationals: list, primes) -> None:
        """Levels 1..L are the square roots of positive rationals r_1..r_L.  By Kummer theory
        (K_0 has characteristic 0 and holds -1), r_i is a square in
        K_(i-1) = K_0(sqrt r_1, ..., sqrt r_(i-1)) iff r_i prod_(j<i) r_j^(e_j) = s^2 for
        some s in K_0 and e_j in {0, 1}.  For each listed prime p (f splits into distinct
        factors modulo p: see _split_roots), chi_p(x) = (phi(x) | p) is a character on the
        elements of K_0 that are p-units, and on a rational p-unit it is the Legendre
        symbol.  Such an s has s^2 a rational p-unit, so s is integral over Z_(p), hence in
        R_0, with phi(s) != 0, and chi_p(r_i prod r_j^(e_j)) = 1 for every p.  The matrix
        of the symbols (r_i | p) has rank L over F_2 (checked), so no non-trivial product
        of the r_i has all symbols 1: no r_i is a square in K_(i-1)."""
        need(isinstance(primes, list), "tower: kummer levels need a \"kummer\" list of primes")
        values = [q.numerator * q.denominator for q in rationals]
        rows: dict = {}
        for k, entry in enumerate(primes):
            need(isinstance(entry, dict), f"tower kummer prime {k + 1}: not an object")
            p = entry.get("prime")
            self._split_roots(f"tower kummer prime {k + 1}", p, entry.get("theta"))
            need(all(v % p for v in values), f"tower kummer prime {p} divides a radicand")
            add_legendre_row(rows, values, p)
        need(len(rows) == len(values), f"tower: the Legendre symbols of the kummer levels "
             f"have rank {len(rows)} over F_2, not {len(values)}")

    def _base_norm(self, x):
        """N_(K_L/K_0)(x): an element of Q(theta)."""
        for lev in range(_level(x), 0, -1):
            a, b = _split(x, lev)
            x = _add(self.mul(a, a), _neg(self.mul(self.r[lev - 1], self.mul(b, b))))
        return x


def _rational(x):
    """The rational value of a base element of degree 0, else None."""
    if isinstance(x, tuple) or any(x.c[1:]):
        return None
    return Fraction(x.c[0] if x.c else 0, x.den)


def _eval_mod(c: list, h: int, p: int) -> int:
    value = 0
    for coeff in reversed(c):
        value = (value * h + coeff) % p
    return value


def _integral(x, p: int) -> bool:
    if isinstance(x, tuple):
        return _integral(x[1], p) and _integral(x[2], p)
    return x.den % p != 0


def _image(x, p: int, h: int, roots: list) -> int:
    """phi(x): theta -> h, y_j -> roots[j - 1] (x p-integral)."""
    if isinstance(x, tuple):
        lev, a, b = x
        return (_image(a, p, h, roots) + _image(b, p, h, roots) * roots[lev - 1]) % p
    return _eval_mod(list(x.c), h, p) * pow(x.den, -1, p) % p


__all__ = ["CyclotomicTower"]
