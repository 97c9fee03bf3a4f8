"""Checker extension: the sparse cyclotomic numbers of ``{"sparse-cyclotomic": ...}`` fields
(standard library only).

The field is Q(zeta_N) for a conductor N too large for a minimal polynomial (turns 1/999983
and 3/999979: N near 2.6 * 10^14).  A number is written ``{"e": c, ...}``, meaning
``sum c cos(2 pi e / N)``: real by construction.  Here it is kept in that form (0 <= e <= N/2,
integer coefficients over one denominator; cos e cos f = (cos(e + f) + cos(e - f))/2), and
read as the roots of unity ``sum c/2 (zeta^e + zeta^-e)`` by the zero test.  The form is not
canonical, so:

* **Equality** is an exact zero test over the prime factorisation of N (checked: the
  product is N and each factor is prime, by :mod:`ext_primes`: deterministic Miller-Rabin
  below 3.3 * 10^24, above it the certificate's ``"primality"`` proofs).  With
  N = p^a m, gcd(p, m) = 1 and E = 1 mod p^a, E = 0 mod m, w = zeta_N^E is a primitive p^a-th
  root of unity and zeta_N^e = w^i zeta_(N/p)^f with i = e mod p, f = (e - i E)/p.  If a >= 2,
  1, w, ..., w^(p-1) are a basis of Q(zeta_N) over Q(zeta_(N/p)) (w^p lies there and the
  degree is p): the number is 0 iff each group i is 0.  If a = 1, w = zeta_p has minimal
  polynomial 1 + X + ... + X^(p-1) over Q(zeta_m), so the number is 0 iff the p groups are
  equal (all 0 when fewer than p occur).  At N = 1 the number is rational.
* **Hash** (sets of points): the residue modulo a prime l = 1 mod N under zeta_N -> g, g of
  order exactly N modulo l (checked), a ring homomorphism Z_(l)[zeta_N] -> F_l; every
  denominator of the certificate's numbers must be prime to l (checked), so products and sums
  of them are too, and equal numbers have equal residues.  The residue of a number read from
  the certificate is computed from its terms, that of a sum or product from its operands'
  (the map is a ring homomorphism: the same value, without a power per term).
* **Sign**: integer interval arithmetic.  pi is enclosed by Machin's formula with each
  truncated term's error counted; cos of an angle in [0, pi] by its Taylor series on the
  interval's ends (every term is increasing in the angle), the alternating tail bounded by
  the next term; precision doubles until the enclosure excludes 0 (a non-zero number, as
  the zero test shows, has a non-zero value: this ends).
"""

from __future__ import annotations

from fractions import Fraction
from math import gcd, lcm

from .ext_boxes import BoxedAngle
from .ext_primes import is_prime, proved_primes
from .numbers import Invalid, RingOps, frac, integer, need


class SparseField:
    """The field ``{"sparse-cyclotomic": {"conductor": N, "factors": [[p, a], ...],
    "prime": l, "root": g}}``: checks the data, then makes numbers."""

    Angle = BoxedAngle          # the ordering reads angles from enclosures (bounds)

    def __init__(self, spec: dict):
        need(isinstance(spec, dict), "sparse-cyclotomic: an object")
        self.n = n = integer(str(spec["conductor"]))
        need(n >= 1, "sparse-cyclotomic: the conductor must be positive")
        proved = proved_primes(spec.get("primality", []))
        factors = []
        product = 1
        for item in spec["factors"]:
            need(isinstance(item, list) and len(item) == 2, "sparse-cyclotomic: factors are "
                 "[prime, exponent] pairs")
            p, a = integer(str(item[0])), integer(str(item[1]))
            need(a >= 1 and is_prime(p, proved), f"sparse-cyclotomic: {p} is not a prime")
            factors.append((p, a))
            product *= p ** a
        need(product == n and len({p for p, _ in factors}) == len(factors),
             "sparse-cyclotomic: the factors do not multiply to the conductor")
        # squares first, then single primes from the largest (the solver's order is irrelevant
        # to correctness: any order peels a valid factorisation)
        self.factors = sorted(factors, key=lambda pa: (pa[1] == 1, -pa[0]))
        self.ell = ell = integer(str(spec["prime"]))
        self.g = g = integer(str(spec["root"])) % ell
        need(is_prime(ell, proved) and ell % n == 1, "sparse-cyclotomic: the prime is not 1 mod N")
        need(pow(g, n, ell) == 1 and all(pow(g, n // p, ell) != 1 for p, _ in factors),
             "sparse-cyclotomic: the root does not have order N modulo the prime")
        self._cos: dict = {}
        self._pi: dict = {}

    def num(self, value) -> "SNum":
        """A rational, or {"e": c, ...} = sum c cos(2 pi e / N)."""
        if isinstance(value, dict):
            terms: dict = {}
            for e, c in value.items():
                e = integer(e) % self.n
                e = min(e, self.n - e)          # cos(2 pi e/N) = cos(2 pi (N - e)/N)
                terms[e] = terms.get(e, 0) + frac(c)
            return self.make(terms)
        need(not isinstance(value, list), "a sparse-cyclotomic number is a rational or a map")
        q = frac(value)
        return self.make({0: q})

    def make(self, terms: dict) -> "SNum":
        """From the cosine form with rational coefficients (0 <= e <= N/2)."""
        den = lcm(*(Fraction(c).denominator for c in terms.values())) if terms else 1
        need(den % self.ell != 0, "sparse-cyclotomic: a denominator is divisible by the prime")
        ints = {e: int(c * den) for e, c in terms.items() if c}
        return SNum(self, ints, den, self.residue(ints, den))

    def residue(self, terms: dict, den: int) -> int:
        """(sum c (g^e + g^-e)/2) / den modulo l."""
        return self.image(terms, den, self.ell, self.g)

    def image(self, terms: dict, den: int, p: int, w: int) -> int:
        """(sum c (w^e + w^-e)/2) / den modulo the odd prime p (zeta_N -> w, w of order N;
        den prime to p)."""
        n, total = self.n, 0
        for e, c in terms.items():
            total += c * (pow(w, e, p) + pow(w, n - e, p))
        return total * pow(2 * den, -1, p) % p

    # -- the zero test -----------------------------------------------------------
    def is_zero(self, terms: dict) -> bool:
        """Whether sum c cos(2 pi e/N) is 0: as roots of unity, 2 times it is
        sum c (zeta^e + zeta^-e)."""
        n, roots = self.n, {}
        for e, c in terms.items():
            if c:
                roots[e] = roots.get(e, 0) + c
                roots[-e % n] = roots.get(-e % n, 0) + c
        return _zero({e: c for e, c in roots.items() if c}, n, self.factors)

    # -- signs --------------------------------------------------------------------
    def _pi_bounds(self, bits: int) -> tuple[int, int]:
        """Integers lo <= pi 2^bits <= hi (Machin: pi = 16 atan(1/5) - 4 atan(1/239))."""
        found = self._pi.get(bits)
        if found is None:
            a5, e5 = _atan_inv(5, bits)
            a239, e239 = _atan_inv(239, bits)
            mid, err = 16 * a5 - 4 * a239, 16 * e5 + 4 * e239
            found = self._pi[bits] = (mid - err, mid + err)
        return found

    def cos_bounds(self, e: int, bits: int) -> tuple[int, int]:
        """Integers lo <= cos(2 pi e / N) 2^bits <= hi."""
        e %= self.n
        e = min(e, self.n - e)                  # the angle 2 pi e / N in [0, pi]
        key = (e, bits)
        found = self._cos.get(key)
        if found is None:
            plo, phi = self._pi_bounds(bits)
            tlo, thi = 2 * plo * e // self.n, -(-2 * phi * e // self.n)   # theta 2^bits
            found = self._cos[key] = _cos_bounds(max(tlo, 0), thi, bits)
        return found

    def term_bounds(self, terms: dict, bits: int) -> tuple[int, int]:
        """Integers lo <= (sum c cos(2 pi e/N)) 2^bits <= hi."""
        lo = hi = 0
        for e, c in terms.items():
            clo, chi = (1 << bits, 1 << bits) if e == 0 else self.cos_bounds(e, bits)
            lo, hi = (lo + c * clo, hi + c * chi) if c > 0 else (lo + c * chi, hi + c * clo)
        return lo, hi

    def bounds(self, x: "SNum", bits: int) -> tuple[int, int]:
        """Integers lo <= x 2^bits <= hi (the ordering's filter)."""
        lo, hi = self.term_bounds(x.t, bits)
        return lo // x.den, -(-hi // x.den)

    def sign(self, x: "SNum") -> int:
        if self.is_zero(x.t):
            return 0
        bits = 64
        while bits < 1 << 20:
            lo, hi = self.term_bounds(x.t, bits)
            if lo > 0 or hi < 0:
                return 1 if lo > 0 else -1
            bits *= 2
        raise Invalid("a sign could not be decided")


def _atan_inv(x: int, bits: int) -> tuple[int, int]:
    """(A, err): |A - atan(1/x) 2^bits| <= err.  Each term floor(2^bits / ((2k+1) x^(2k+1)))
    is within 1 of its value; the alternating tail after the last non-zero term is below 1."""
    total, k, err = 0, 0, 1
    power = (1 << bits) // x                    # floor(2^bits / x^(2k+1)), within 1
    while power:
        term = power // (2 * k + 1)
        total += -term if k % 2 else term
        err += 2
        power //= x * x
        k += 1
    return total, err


def _cos_bounds(tlo: int, thi: int, bits: int) -> tuple[int, int]:
    """Integers lo <= cos(theta) 2^bits <= hi for tlo <= theta 2^bits <= thi, theta in
    [0, ~pi]: the terms theta^(2k)/(2k)! grow with theta (lower ends floored, upper ends
    ceiled), and for 2k + 1 > pi they decrease, so the alternating tail is below the next
    term's upper end."""
    one = 1 << bits
    sq_lo, sq_hi = tlo * tlo, thi * thi           # theta^2 2^(2 bits)
    lo_term, hi_term = one, one
    lo = hi = one
    k = 1
    while True:
        d = (2 * k - 1) * (2 * k) << (2 * bits)
        lo_term = lo_term * sq_lo // d
        hi_term = -(-hi_term * sq_hi // d)
        if k % 2:                               # subtracted
            lo -= hi_term
            hi -= lo_term
        else:
            lo += lo_term
            hi += hi_term
        if k >= 2 and hi_term <= 1:
            return lo - 2, hi + 2               # the tail is at most the next term (<= 1)
        k += 1


def _idempotent(n: int, p: int, a: int) -> int:
    q = p ** a
    m = n // q
    return (m * pow(m, -1, q)) % n if m > 1 else 1 % n


def _zero(terms: dict, n: int, factors: list) -> bool:
    if not terms:
        return True
    if len(terms) == 1:
        return False
    if n == 1:
        return sum(terms.values()) == 0
    (p, a), rest = factors[0], factors[1:]
    lower = ([(p, a - 1)] + rest) if a > 1 else rest
    e1 = _idempotent(n, p, a)
    groups: dict = {}
    for e, c in terms.items():
        i = e % p
        f = ((e - i * e1) % n) // p
        g = groups.setdefault(i, {})
        g[f] = g.get(f, 0) + c
    groups = {i: {f: c for f, c in g.items() if c} for i, g in groups.items()}
    m = n // p
    if a >= 2 or len(groups) < p:
        return all(_zero(g, m, lower) for g in groups.values())
    base = groups[0]
    for i in range(1, p):
        diff = dict(groups[i])
        for f, c in base.items():
            diff[f] = diff.get(f, 0) - c
        if not _zero({f: c for f, c in diff.items() if c}, m, lower):
            return False
    return True


class SNum(RingOps):
    """(sum c_e cos(2 pi e/N)) / den: integer c_e, 0 <= e <= N/2, den > 0 prime to the field's
    l.  ``==`` is the exact zero test, ``hash`` the residue modulo l (equal numbers, equal
    residues), carried along sums and products."""
    __slots__ = ("f", "t", "den", "h")

    def __init__(self, f: SparseField, terms: dict, den: int, h: int):
        g = gcd(den, *terms.values())
        if g != 1:
            terms, den = {e: c // g for e, c in terms.items()}, den // g
        self.f, self.t, self.den, self.h = f, terms, den, h

    def _of(self, o) -> "SNum":
        if isinstance(o, SNum):
            need(o.f is self.f, "numbers of two fields mix")
            return o
        o = Fraction(o)
        ell = self.f.ell
        need(o.denominator % ell != 0, "sparse-cyclotomic: a denominator is divisible by "
             "the prime")
        return SNum(self.f, {0: o.numerator} if o else {}, o.denominator,
                    o.numerator * pow(o.denominator, -1, ell) % ell)

    def __add__(self, o):
        o = self._of(o)
        a, b = o.den, self.den
        out = {e: c * a for e, c in self.t.items()}
        for e, c in o.t.items():
            v = out.get(e, 0) + c * b
            if v:
                out[e] = v
            else:
                out.pop(e, None)
        return SNum(self.f, out, a * b, (self.h + o.h) % self.f.ell)

    def __mul__(self, o):
        """cos e cos f = (cos(e + f) + cos(e - f))/2: twice the product has integer terms."""
        o = self._of(o)
        n = self.f.n
        out: dict = {}
        get = out.get
        for e, c in self.t.items():
            for k, d in o.t.items():
                v = c * d
                t = e + k
                if t + t > n:
                    t = n - t
                out[t] = get(t, 0) + v
                t = e - k if e >= k else k - e
                out[t] = get(t, 0) + v
        return SNum(self.f, {e: c for e, c in out.items() if c}, 2 * self.den * o.den,
                    self.h * o.h % self.f.ell)

    def __neg__(self):
        return SNum(self.f, {e: -c for e, c in self.t.items()}, self.den, -self.h % self.f.ell)

    def __eq__(self, o):
        if not isinstance(o, (SNum, int, Fraction)):
            return False
        o = self._of(o)
        if o.h != self.h:                       # different residues: different numbers
            return False
        return self.f.is_zero((self - o).t)

    def __hash__(self):
        return self.h

    def sign(self) -> int:
        return self.f.sign(self)
