"""Checker extension: nested radicals, towers of quadratic extensions (standard library only;
docs/certificates.md, "Towers" and "Towers over Q(zeta_M)").

Field ``{"tower": {"radicands": [q_1, ...], "levels": [level_1, ...]}}``: K_0 = Q(sqrt q_1, ...)
is the square-root field of :class:`numbers.SquareRoots` (pairwise coprime integers
> 1, none a square; the list may be empty: K_0 = Q), and K_i = K_(i-1)(y_i), y_i the positive
square root of ``level_i["radicand"]`` = r_i, an element of K_(i-1) proved > 0 and NOT a square
in K_(i-1) by ``level_i["prime"]`` p, ``"base"`` (a root of each q_j mod p) and ``"roots"``
(a root of the image of each r_j, j < i): see :func:`Tower._prove`.  The first levels may
instead say ``"kummer": true`` (radicands in K_0), proved new together by the spec's
``"kummer"`` list of maps K_0 -> F_p whose Legendre symbols have full rank: see
:meth:`Tower._prove_kummer`.

Elements: a rational ``"p/q"``; ``{"P_S": c, ...}`` in K_0; ``[i, A, B]`` = A + B y_i with A, B
elements of levels < i and B != 0.  Since each r_i is not a square, {1, y_i} is a basis of K_i
over K_(i-1), so this form is unique: == and hash decide equality of real numbers.

With ``"base": FIELD`` instead of radicands, K_0 is a Q(theta) (:class:`CyclotomicTower`).
"""

from __future__ import annotations

from fractions import Fraction
from math import isqrt

from .dispatch import dense_field
from .ext_boxes import BoxedAngle
from .numbers import Invalid, Root, SquareRoots, integer, need

# A value is a base number (a Root of the square-root field, or an Alg of Q(theta) for a
# tower over Q(zeta_M)) or a tuple (i, A, B) = A + B y_i.

def _level(v) -> int:
    return v[0] if isinstance(v, tuple) else 0


def _zero_like(v):
    """The zero of the base of v (Root or Alg: zeros of two types must not meet)."""
    while isinstance(v, tuple):
        v = v[1]
    return v * 0


def _split(v, lev):
    return (v[1], v[2]) if _level(v) == lev else (v, _zero_like(v))


def _is_zero(b) -> bool:
    return not isinstance(b, tuple) and b == 0


def _make(lev, a, b):
    return a if _is_zero(b) else (lev, a, b)


def _add(x, y):
    if not isinstance(x, tuple) and not isinstance(y, tuple):
        return x + y
    lev = max(_level(x), _level(y))
    (xa, xb), (ya, yb) = _split(x, lev), _split(y, lev)
    return _make(lev, _add(xa, ya), _add(xb, yb))


def _neg(x):
    return (x[0], _neg(x[1]), _neg(x[2])) if isinstance(x, tuple) else -x


def _is_prime(p: int) -> bool:
    return p > 1 and all(p % d for d in range(2, isqrt(p) + 1))


def add_legendre_row(rows: dict, values: list, p: int) -> None:
    """Row-reduce the vector of Legendre symbols (v | p) of ``values`` (bit i set for -1)
    into ``rows`` (pivot bit -> row) over F_2: their number is the rank so far."""
    vector = 0
    for i, v in enumerate(values):
        if pow(v, (p - 1) // 2, p) == p - 1:
            vector |= 1 << i
    while vector and vector.bit_length() - 1 in rows:
        vector ^= rows[vector.bit_length() - 1]
    if vector:
        rows[vector.bit_length() - 1] = vector


class Tower:
    """The field of a ``"tower"`` spec: checks every level, then makes elements."""

    Angle = BoxedAngle          # the ordering reads angles from enclosures (bounds)

    def __init__(self, spec: dict):
        need(isinstance(spec, dict) and isinstance(spec.get("radicands"), list)
             and isinstance(spec.get("levels"), list) and spec["levels"],
             "tower: radicands and a non-empty list of levels")
        qs = spec["radicands"]
        if qs:
            self.base = SquareRoots({"radicands": qs})
        else:
            self.base = SquareRoots.__new__(SquareRoots)
            self.base.radicands = []
        self.r: list = []
        self._balls: dict = {}
        kummer: list = []               # the radicands of the "kummer" levels (in K_0)
        for i, lev in enumerate(spec["levels"], start=1):
            need(isinstance(lev, dict), f"tower level {i}: not an object")
            r = self._read(lev.get("radicand"), i - 1)
            if lev.get("kummer") is True:
                need(len(kummer) == i - 1, f"tower level {i}: a kummer level above a level "
                     "that is not")
                need(isinstance(r, Root), f"tower level {i}: a kummer radicand must lie in "
                     "K_0")
                kummer.append(r)
            else:
                self._prove(i, r, lev)
            self.r.append(r)
            need(self._sign(r) > 0, f"tower level {i}: the radicand is not positive")
        if kummer:
            self._prove_kummer(kummer, spec.get("kummer"))

    # -- elements -----------------------------------------------------------
    def _read(self, value, top: int):
        if isinstance(value, list):
            need(len(value) == 3 and isinstance(value[0], int) and not isinstance(value[0], bool)
                 and 1 <= value[0] <= top, f"tower element {value!r:.60}: bad level")
            lev = value[0]
            a, b = self._read(value[1], lev - 1), self._read(value[2], lev - 1)
            need(not _is_zero(b), "tower element with a zero y coefficient")
            return (lev, a, b)
        return self.base_num(value)

    def base_num(self, value):
        return self.base.num(value)

    def base_of(self, o):
        """An int or Fraction as a base number."""
        return Root._of(o)

    def num(self, value) -> "TNum":
        return TNum(self, self._read(value, len(self.r)))

    def mul(self, x, y):
        if not isinstance(x, tuple) and not isinstance(y, tuple):
            return x * y
        lev = max(_level(x), _level(y))
        if _level(y) < lev or _level(x) < lev:
            # one factor lies below level lev: (a + b y_lev) c = a c + (b c) y_lev, two
            # products of half the size (the full formula's products by a zero part would
            # walk the other factor's tree twice per level: 2^L visits over L levels)
            (a, b), c = (x[1:], y) if _level(x) == lev else (y[1:], x)
            return _make(lev, self.mul(a, c), self.mul(b, c))
        (xa, xb), (ya, yb) = _split(x, lev), _split(y, lev)
        cross = _add(self.mul(xa, yb), self.mul(xb, ya))
        return _make(lev, _add(self.mul(xa, ya), self.mul(self.r[lev - 1], self.mul(xb, yb))),
                     cross)

    # -- signs: dyadic intervals [lo, hi] / 2^bits, bits doubled until 0 is excluded --------
    def _interval(self, x, bits: int):
        if isinstance(x, Root):
            lo = hi = 0
            for m, c in _items(x):
                s = isqrt(m << 2 * bits)
                a, b = s, s + (s * s != m << 2 * bits)       # sqrt(m) 2^bits in [a, b]
                p, q = c.numerator, c.denominator
                ends = (p * a, p * b)
                lo += min(ends) // q
                hi += -(-max(ends) // q)
            return lo, hi
        lev, a, b = x
        (alo, ahi), (blo, bhi) = self._interval(a, bits), self._interval(b, bits)
        ylo, yhi = self._root_interval(lev, bits)
        ends = (blo * ylo, blo * yhi, bhi * ylo, bhi * yhi)
        return alo + (min(ends) >> bits), ahi - ((-max(ends)) >> bits)

    def bounds(self, x, bits: int):
        """Integers lo <= x 2^bits <= hi (x a raw value): the ordering's filter, which
        then compares angles from boxes and multiplies exactly only on a tie (the ordering
        of 100 points of a tower of nested radicals took 20 s of exact products)."""
        return self._interval(x, bits)

    def _root_interval(self, lev: int, bits: int):
        key = (lev, bits)
        if key not in self._balls:
            lo, hi = self._interval(self.r[lev - 1], bits)
            need(hi >= 0, "a tower radicand is negative")
            self._balls[key] = (isqrt(max(lo, 0) << bits), isqrt(hi << bits) + 1)
        return self._balls[key]

    #: the base's number type: its own sign, exact (a subclass over another base sets it)
    base_number = Root

    def _sign(self, x) -> int:
        if isinstance(x, self.base_number):
            return x.sign()
        bits = 64
        while bits < 1 << 20:
            lo, hi = self._interval(x, bits)
            if lo > 0 or hi < 0:
                return 1 if lo > 0 else -1
            bits *= 2
        raise Invalid("a sign could not be decided")

    # -- the proof that r_i is not a square in K_(i-1) ---------------------------------
    def _prove(self, i: int, r, lev: dict) -> None:
        """Let R be the elements of K_(i-1) whose coefficients have denominators prime to p.
        With p an odd prime dividing no q_j, every r_j (j < i) in R with N(r_j) a p-unit,
        the discriminant of R over Z_(p) (a product of powers of 4 q_j and of N(4 r_j)) is a
        p-unit, so R is integrally closed.  sqrt q_j -> base_j, y_j -> roots_j (checked:
        base_j^2 = q_j, roots_j^2 = phi(r_j) mod p) defines a ring homomorphism phi: R -> F_p.
        If r_i = z^2 in K_(i-1) with r_i in R, z is integral over R, so z is in R and
        phi(r_i) = phi(z)^2 is a square mod p; it is checked to be a non-residue."""
        p, base, roots = lev.get("prime"), lev.get("base"), lev.get("roots")
        need(isinstance(p, int) and not isinstance(p, bool) and 2 < p < 1 << 40
             and _is_prime(p), f"tower level {i}: {p!r} is not an odd prime below 2^40")
        qs = self.base.radicands
        need(isinstance(base, list) and len(base) == len(qs) and isinstance(roots, list)
             and len(roots) == i - 1, f"tower level {i}: one root per base radicand and per "
             "level below")
        base = [integer(b) if isinstance(b, str) else b for b in base]
        roots = [integer(t) if isinstance(t, str) else t for t in roots]
        need(all(isinstance(v, int) and 0 <= v < p for v in base + roots),
             f"tower level {i}: roots must be integers in [0, p)")
        for q, s in zip(qs, base):
            need(q % p != 0 and (s * s - q) % p == 0,
                 f"tower level {i}: {s} is not a root of {q} modulo {p}, or p divides it")
        base_map = dict(zip(qs, base))
        for j, rj in enumerate(self.r):
            need(all(c.denominator % p for c in _coefficients(rj)),
                 f"tower level {i}: p divides a denominator of radicand {j + 1}")
            n = self._norm(rj)
            need(n.numerator % p and n.denominator % p,
                 f"tower level {i}: p divides the norm of radicand {j + 1}")
            need((roots[j] ** 2 - _image(rj, p, base_map, roots)) % p == 0,
                 f"tower level {i}: {roots[j]} is not a root of radicand {j + 1} modulo {p}")
        need(all(c.denominator % p for c in _coefficients(r)),
             f"tower level {i}: p divides a denominator of the radicand")
        value = _image(r, p, base_map, roots)
        need(pow(value, (p - 1) // 2, p) == p - 1,
             f"tower level {i}: the radicand's image {value} is a square modulo {p}")

    def _prove_kummer(self, radicands: list, maps) -> None:
        """The radicands r_1, ..., r_L of the first L levels, all in K_0, are independent
        modulo squares of K_0, so each level is new (Kummer theory: K_0(sqrt r_1, ...,
        sqrt r_L) has degree 2^L).  Each entry of ``maps``, an odd prime p < 2^40 and a
        root mod p of each q_j (none dividing p), defines phi: R -> F_p as in :meth:`_prove`
        (R integrally closed: its discriminant, powers of 4 q_j, is a p-unit); every r_j is
        in R with phi(r_j) != 0.  If a product of some r_j were z^2 with z in K_0, z would
        lie in R and its image be a square: the Legendre symbol of phi of the product is 1
        for every map.  The symbols' rank L over F_2 rules out every non-empty product."""
        need(isinstance(maps, list), "tower: kummer levels need a \"kummer\" list of maps")
        qs = self.base.radicands
        rows: dict = {}
        for k, entry in enumerate(maps, start=1):
            need(isinstance(entry, dict) and isinstance(entry.get("base"), list),
                 f"tower kummer map {k}: not an object with a prime and base roots")
            p, base = entry.get("prime"), entry["base"]
            need(isinstance(p, int) and not isinstance(p, bool) and 2 < p < 1 << 40
                 and _is_prime(p), f"tower kummer map {k}: {p!r} is not an odd prime below "
                 "2^40")
            base = [integer(b) if isinstance(b, str) else b for b in base]
            need(len(base) == len(qs) and all(isinstance(v, int) and 0 <= v < p
                                               for v in base),
                 f"tower kummer map {k}: one root in [0, p) per base radicand")
            for q, s in zip(qs, base):
                need(q % p != 0 and (s * s - q) % p == 0,
                     f"tower kummer map {k}: {s} is not a root of {q} modulo {p}, or p "
                     "divides it")
            need(all(c.denominator % p for r in radicands for c in _coefficients(r)),
                 f"tower kummer map {k}: p divides a denominator of a radicand")
            images = [_image(r, p, dict(zip(qs, base)), []) for r in radicands]
            need(all(images), f"tower kummer map {k}: a radicand's image is 0")
            add_legendre_row(rows, images, p)
        need(len(rows) == len(radicands), f"tower: the Legendre symbols of the kummer levels "
             f"have rank {len(rows)} over F_2, not {len(radicands)}")

    def _norm(self, x) -> Fraction:
        for lev in range(_level(x), 0, -1):
            a, b = _split(x, lev)
            x = _add(self.mul(a, a), _neg(self.mul(self.r[lev - 1], self.mul(b, b))))
        for q in self.base.radicands:
            x = x * Root({m: (-c if m % q == 0 else c) for m, c in x.t.items()}, x.den)
        need(set(x.t) <= {1}, "a norm is not rational (bug)")
        return Fraction(x.t.get(1, 0), x.den)


def _items(x: Root):
    """(radicand product, rational coefficient) of a base element (integers over x.den)."""
    return ((m, Fraction(c, x.den)) for m, c in x.t.items())


def _coefficients(x):
    if isinstance(x, Root):
        yield from (c for _, c in _items(x))
    else:
        yield from _coefficients(x[1])
        yield from _coefficients(x[2])


def _image(x, p: int, base: dict, roots: list) -> int:
    if isinstance(x, Root):
        total = 0
        for m, c in _items(x):
            v = c.numerator * pow(c.denominator, -1, p)
            for q, s in base.items():
                if m % q == 0:
                    v *= s
            total += v
        return total % p
    lev, a, b = x
    return (_image(a, p, base, roots) + _image(b, p, base, roots) * roots[lev - 1]) % p


class TNum:
    """A number of a checked :class:`Tower`, canonical; mixes with ints and Fractions."""
    __slots__ = ("f", "v")

    def __init__(self, f: Tower, v):
        self.f, self.v = f, v

    def _of(self, o):
        if isinstance(o, TNum):
            need(o.f is self.f, "numbers of two towers")
            return o.v
        return self.f.base_of(o)

    def __add__(self, o):
        return TNum(self.f, _add(self.v, self._of(o)))

    def __mul__(self, o):
        return TNum(self.f, self.f.mul(self.v, self._of(o)))

    __radd__, __rmul__ = __add__, __mul__

    def __neg__(self):
        return TNum(self.f, _neg(self.v))

    def __sub__(self, o):
        return TNum(self.f, _add(self.v, _neg(self._of(o))))

    def __rsub__(self, o):
        return TNum(self.f, _add(_neg(self.v), self._of(o)))

    def __eq__(self, o):
        return isinstance(o, (TNum, int, Fraction)) and self.v == self._of(o)

    def __hash__(self):
        return hash(self.v)

    def sign(self) -> int:
        return self.f._sign(self.v)


# ------------------------------------------------------------------ towers over Q(theta)
# Field ``{"tower": {"base": FIELD, "levels": [level_1, ...]}}``: K_0 = Q(theta) is the field
# of :class:`numbers.Field` (``FIELD`` = minimal polynomial, isolating interval and
# irreducibility proof, e.g. the real-cyclotomic Psi_M of theta = 2cos(2pi/M)), whose minimal
# polynomial f must be monic with integer coefficients; K_i = K_(i-1)(y_i), y_i the positive
# square root of ``level_i["radicand"]`` = r_i, proved > 0 and NOT a square in K_(i-1) by
# ``level_i["prime"]`` p, ``"theta"`` (the d = deg f roots of f modulo p, the map using the
# first) and ``"roots"`` (a root of the image of each r_j, j < i): see
# :meth:`CyclotomicTower._prove`.
#
# Elements: a rational ``"p/q"``; ``{"theta": [c_0, c_1, ...]}`` = sum c_k theta^k in K_0;
# ``[i, A, B]`` = A + B y_i (B != 0).  The form is unique, as in towers over square roots.
# Signs are exact: sign(A + B y) is sign(A) when A, B agree in sign, else
# sign(A) * sign(A^2 - r B^2) (|A| > |B| y iff A^2 > r B^2), down to signs in Q(theta).

class CyclotomicTower(Tower):
    """The field of a ``"tower"`` spec with a ``"base"`` field: checks every level."""

    #: no integer enclosures of a base number here (its signs come from Field's isolating
    #: interval): the ordering compares angles exactly
    Angle = bounds = None

    def __init__(self, spec: dict):
        need(isinstance(spec, dict) and isinstance(spec.get("base"), dict)
             and isinstance(spec.get("levels"), list) and spec["levels"],
             "tower: a base field and a non-empty list of levels")
        self.base = dense_field(spec["base"])
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
                q = _theta_rational(r)
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
            need(_theta_integral(rj, p),
                 f"tower level {i}: p divides a denominator of radicand {j + 1}")
            n = self._base_norm(rj)
            norm = 1
            for t in thetas:
                norm = norm * _theta_image(n, p, t, []) % p
            need(norm != 0, f"tower level {i}: p divides the norm of radicand {j + 1}")
            need((roots[j] ** 2 - _theta_image(rj, p, h, roots)) % p == 0,
                 f"tower level {i}: {roots[j]} is not a root of radicand {j + 1} modulo {p}")
        need(_theta_integral(r, p), f"tower level {i}: p divides a denominator of the radicand")
        value = _theta_image(r, p, h, roots)
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


def _theta_rational(x):
    """The rational value of a base element of degree 0, else None."""
    if isinstance(x, tuple) or any(x.c[1:]):
        return None
    return Fraction(x.c[0] if x.c else 0, x.den)


def _eval_mod(c: list, h: int, p: int) -> int:
    value = 0
    for coeff in reversed(c):
        value = (value * h + coeff) % p
    return value


def _theta_integral(x, p: int) -> bool:
    if isinstance(x, tuple):
        return _theta_integral(x[1], p) and _theta_integral(x[2], p)
    return x.den % p != 0


def _theta_image(x, p: int, h: int, roots: list) -> int:
    """phi(x): theta -> h, y_j -> roots[j - 1] (x p-integral)."""
    if isinstance(x, tuple):
        lev, a, b = x
        return (_theta_image(a, p, h, roots) + _theta_image(b, p, h, roots) * roots[lev - 1]) % p
    return _eval_mod(list(x.c), h, p) * pow(x.den, -1, p) % p
