"""The checker's exact numbers: rationals, square roots of integers, and one real field Q(theta)
whose description (minimal polynomial, isolating interval, irreducibility) is checked first."""

from __future__ import annotations

import itertools
import re
from fractions import Fraction
from functools import lru_cache
from math import gcd, isqrt, lcm, prod

class Invalid(Exception):
    """The certificate does not prove its claim; the message says why."""

def need(condition, reason: str) -> None:
    if not condition:
        raise Invalid(reason)

def is_int(x) -> bool:
    return isinstance(x, int) and not isinstance(x, bool)      # JSON true is no number

_SHORT = re.compile(r"([+-]?[0-9]{1,4000})(?:/([0-9]{1,4000}))?")     # ASCII digits only

def rat(text) -> tuple[int, int]:
    """An exact rational "p/q" or "p" (or a JSON integer) as ``(p, q)``, q > 0."""
    pair = _short_rat(text) if type(text) is str and len(text) < 200 else None
    if pair and pair[1] > 0:                    # the common case: parsed once per text
        return pair
    if is_int(text):
        return text, 1
    num, slash, den = text.partition("/") if isinstance(text, str) else ("?", "", "")
    try:
        p, q = integer(num), (integer(den) if slash else 1)
    except ValueError:
        q = 0
    need(q > 0, f"not an exact rational: {text!r}")
    return p, q

def rats(texts: list) -> list[tuple[int, int]]:
    """``[rat(t) for t in texts]``, the common case (short texts "p/q") in one pass."""
    try:
        pairs = list(map(_short_rat, texts)) if max(map(len, texts), default=0) < 200 else [None]
        if None not in pairs and 0 not in {q for _, q in pairs}:
            return pairs
    except TypeError:                           # not a string
        pass
    return [rat(t) for t in texts]

@lru_cache(maxsize=1 << 18)     # keyed by the text: the group and ordering checks read it twice
def _short_rat(text: str) -> tuple[int, int] | None:
    match = _SHORT.fullmatch(text)
    return match and (int(match[1]), int(match[2]) if match[2] is not None else 1)

def integer(text: str) -> int:
    """``int(text)`` of any length, in chunks (``int`` refuses over 4300 digits)."""
    digits = text[1:] if text[:1] in "+-" else text
    if not (digits.isascii() and digits.isdigit()):
        raise ValueError(f"not an integer: {text!r}")
    value = 0
    for chunk in (digits[i:i + 4000] for i in range(0, len(digits), 4000)):
        value = value * 10 ** len(chunk) + int(chunk)
    return -value if text[:1] == "-" else value

def frac(text) -> Fraction:
    return Fraction(*rat(text))

def scaled(pairs: list) -> tuple[list, int]:
    """Rationals as ints times a common denominator D > 0 (which keeps equality, order and
    symmetries), or Fractions and D = 1 if D would be huge."""
    d = 1
    for q in {q for _, q in pairs}:
        if d % q:
            d = lcm(d, q)
            if d.bit_length() > 8192:
                return [Fraction(p, q) for p, q in pairs], 1
    return [p * (d // q) for p, q in pairs] if d > 1 else [p for p, _ in pairs], d

def peval(p, x):
    value = 0
    for c in reversed(p):
        value = value * x + c
    return value

# ------------------------------------------------------------------ the number field Q(theta)
# theta is the only root of the monic p in (lo, hi).  If p is irreducible, a polynomial of
# degree < deg p vanishes at theta only if it is zero, so elements reduced modulo p have
# canonical coefficients: == and hash decide equality.  So irreducibility is PROVED
# (dispatch.IRREDUCIBILITY): with a reducible p a false witness could pass.

def psi(m: int) -> list[int]:
    """Psi_m, the minimal polynomial of 2cos(2pi/m), m >= 3 (integers, low first).  Phi_m =
    prod over squarefree t | m of (x^(m/t) - 1)^mu(t) (Moebius), divisions last, exact.  Phi_m
    is irreducible (Gauss), palindromic of degree 2h, and z^-h Phi_m(z) = Psi_m(z + 1/z)."""
    primes, r = [], m
    for q in range(2, isqrt(m) + 1):
        primes += [q] if r % q == 0 else []
        while r % q == 0:
            r //= q
    primes += [r] if r > 1 else []
    phi, divide = [1], []
    for chosen in itertools.product((0, 1), repeat=len(primes)):
        e = m // prod(q for q, c in zip(primes, chosen) if c)
        if sum(chosen) % 2:
            divide.append(e)
        else:                                   # phi * (x^e - 1)
            phi = [(phi[i - e] if i >= e else 0) - (phi[i] if i < len(phi) else 0)
                   for i in range(len(phi) + e)]
    for e in divide:                            # phi / (x^e - 1): phi[j] = q[j - e] - q[j]
        quotient = [0] * (len(phi) - e)
        for j in range(len(phi) - 1, e - 1, -1):
            quotient[j - e] = phi[j] + (quotient[j] if j < len(quotient) else 0)
        phi = quotient
    h = (len(phi) - 1) // 2     # z^-h Phi = a_h + sum_k a_(h+k) V_k(z + 1/z), V_k = z^k + z^-k
    out, v_prev, v = [phi[h]] + [0] * h, [2], [0, 1]
    for k in range(1, h + 1):
        for i, c in enumerate(v):
            out[i] += phi[h + k] * c
        v_prev, v = v, [(v[i - 1] if i else 0) - (v_prev[i] if i < len(v_prev) else 0)
                        for i in range(len(v) + 1)]
    return out

def poly_product(a, b) -> list:
    out = [0] * max(len(a) + len(b) - 1, 0)
    for i, x in enumerate(a):
        for j, y in enumerate(b):
            out[i + j] += x * y
    return out

def one_root(p: list, lo: Fraction, hi: Fraction) -> bool:
    """p has exactly one root in (lo, hi): one sign change (Descartes) in the coefficients of
    (1 + x)^d p(lo + (hi - lo)/(1 + x)), whose positive roots are those of p in (lo, hi); in
    integers, lo = l/D, hi = h/D."""
    def shift(c, a):                            # the coefficients of c(x + a)
        for i in range(len(c) - 1):
            for j in range(len(c) - 2, i - 1, -1):
                c[j] += a * c[j + 1]
        return c
    den, d = lcm(lo.denominator, hi.denominator), len(p) - 1
    l, h, scale = int(lo * den), int(hi * den), lcm(*(c.denominator for c in p))
    c = shift([int(cj * scale) * den ** (d - j) for j, cj in enumerate(p)], l)
    c = shift([cj * (h - l) ** j for j, cj in enumerate(c)][::-1], 1)
    signs = [x > 0 for x in c if x]
    return sum(a != b for a, b in zip(signs, signs[1:])) == 1

class Field:
    """Q(theta): checks p and the interval of theta, then makes elements and decides signs.
    Irreducibility is proved by the caller (dispatch.dense_field)."""

    def __init__(self, spec: dict):
        p = [frac(c) for c in spec["minpoly"]]
        while p and p[-1] == 0:
            p.pop()
        need(len(p) >= 3, "the minimal polynomial must have degree >= 2")
        self.p, self.d = [c / p[-1] for c in p], len(p) - 1
        self.lead = lcm(*(c.denominator for c in self.p))      # p = big / lead, big integral
        self.big = [int(c * self.lead) for c in self.p]
        lo, hi = self.interval = tuple(map(frac, spec["interval"]))
        need(lo < hi and peval(self.p, lo) * peval(self.p, hi) < 0,
             "the minimal polynomial does not change sign on the interval of theta")
        need(one_root(self.p, lo, hi), "the interval does not isolate one root of the polynomial")

    def make(self, c: list, den: int) -> "Alg":
        """(sum c_i theta^i) / den, canonical: c reduced mod p in integers (c -= (c_i / lead)
        theta^(i-d) big, c and den scaled by lead first if needed), over gcd, no trailing 0."""
        big, lead, d = self.big, self.lead, self.d
        for i in range(len(c) - 1, d - 1, -1):
            t = c[i]
            if t % lead:
                c, den = [x * lead for x in c], den * lead
            else:
                t //= lead
            for j in range(d + 1):
                c[i - d + j] -= t * big[j]
        del c[d:]
        while c and not c[-1]:
            c.pop()
        g = gcd(den, *c)
        return Alg(self, tuple(x // g for x in c), den // g)

    def num(self, value) -> "Alg":
        """A number of the certificate: a rational, or a list of coefficients of theta^0, ..."""
        q = [frac(x) for x in value] if isinstance(value, list) else [frac(value)]
        den = lcm(*(x.denominator for x in q))
        return self.make([int(x * den) for x in q], den)

    def sign(self, c: tuple) -> int:
        """The sign of c(theta): interval Horner on [lo, hi] in fixed point, the interval
        bisected until 0 is excluded (c(theta) != 0 for canonical c != 0: this ends)."""
        for _ in range(4000 if c else 0):
            (lo, hi), bits = self.interval, self._bits()
            a, b = _horner(c, _floor(lo, bits), _ceil(hi, bits), bits)
            if a > 0 or b < 0:
                return 1 if a > 0 else -1
            for _ in range(16):
                self._bisect(self._bits())
        need(not c, "a sign could not be decided")
        return 0

    def _bits(self) -> int:
        """Fixed-point bits: the interval's width, d per doubling of |theta| (step i's rounding
        error is multiplied by |theta|^(d - i)), and 64."""
        (lo, hi), width = self.interval, self.interval[1] - self.interval[0]
        return (64 + width.denominator.bit_length() - width.numerator.bit_length()
                + self.d * (int(max(abs(lo), abs(hi), 1)).bit_length() + 1))

    def _bisect(self, bits: int) -> None:
        lo, hi = self.interval
        mid = Fraction(_floor((lo + hi) / 2, bits), 1 << bits)
        mid = mid if lo < mid < hi else (lo + hi) / 2
        at_mid = self._p_sign(mid, bits)
        need(at_mid != 0, "the minimal polynomial has a rational root")
        self.interval = (lo, mid) if self._p_sign(lo, bits) != at_mid else (mid, hi)

    def _p_sign(self, x: Fraction, bits: int) -> int:
        if x.denominator & (x.denominator - 1) == 0:    # dyadic: fixed point first, then exact
            for extra in (0, 64, 256):
                a, b = _horner(self.big, _floor(x, bits + extra), _ceil(x, bits + extra),
                               bits + extra)
                if a > 0 or b < 0:
                    return 1 if a > 0 else -1
        v = peval(self.big, x)
        return (v > 0) - (v < 0)

def _floor(x: Fraction, bits: int) -> int:
    return (x.numerator << bits) // x.denominator

def _ceil(x: Fraction, bits: int) -> int:
    return -((-x.numerator << bits) // x.denominator)

def _horner(c, lo: int, hi: int, bits: int) -> tuple[int, int]:
    """[a, b] / 2^bits holding sum c_i t^i for every t in [lo, hi] / 2^bits: interval Horner
    in integers, products rounded outwards (about ``bits`` bits whatever the degree)."""
    a = b = 0
    for coeff in reversed(c):
        ends = (a * lo, a * hi, b * lo, b * hi)
        a, b = (min(ends) >> bits) + (coeff << bits), -(-max(ends) >> bits) + (coeff << bits)
    return a, b

def cyclotomic_proof(field: Field, proof: dict) -> None:
    """{"method": "real-cyclotomic", "conductor": m}: p is Psi_m, irreducible by theorem."""
    m = proof["conductor"]
    need(is_int(m) and 3 <= m <= 10 ** 6 and psi(m) == field.p,
         f"the minimal polynomial is not that of 2cos(2pi/{m!r})")

class RingOps:
    """-, reflected + and * from +, *, unary - and ``_of`` (an int or Fraction as a number)."""
    __slots__ = ()

    def __sub__(self, o):
        return self + (-self._of(o))

    def __rsub__(self, o):
        return -self + o

    def __radd__(self, o):
        return self + o

    def __rmul__(self, o):
        return self * o

class Alg:
    """c(theta)/den, canonical (Field.make): == and hash are exact; mixes with int/Fraction."""
    __slots__ = ("f", "c", "den")

    def __init__(self, f: Field, c: tuple, den: int):
        self.f, self.c, self.den = f, c, den

    def _of(self, o) -> tuple:
        if isinstance(o, Alg):
            return o.c, o.den
        o = Fraction(o)
        return ((o.numerator,) if o else ()), o.denominator

    def __add__(self, o):
        (b, db), a, da = self._of(o), self.c, self.den
        return self.f.make([x * db + y * da for x, y in itertools.zip_longest(a, b, fillvalue=0)],
                           da * db)

    def __mul__(self, o):
        b, db = self._of(o)
        return self.f.make(poly_product(self.c, b), self.den * db)

    def __neg__(self):
        return Alg(self.f, tuple(-x for x in self.c), self.den)

    def __sub__(self, o):
        return self + (-o)

    def __rsub__(self, o):
        return -self + o

    __radd__, __rmul__ = __add__, __mul__

    def __eq__(self, o):
        return isinstance(o, (Alg, int, Fraction)) and (self.c, self.den) == self._of(o)

    def __hash__(self):
        return hash((self.c, self.den))

    def sign(self) -> int:
        return self.f.sign(self.c)              # den > 0

def sgn(v) -> int:
    """The sign of a number: a rational's, or the number's own exact ``sign()``."""
    return v.sign() if hasattr(v, "sign") else (v > 0) - (v < 0)

# ------------------------------------------------------------------ square roots, natively
# Q(sqrt a_1, ..., sqrt a_k), integers a_i > 1 pairwise coprime, none a square: no product of
# a non-empty subset is a square, so the square roots of the 2^k subset products P_S are
# linearly independent over Q (Besicovitch 1940) and sum c_S sqrt(P_S), kept as {P_S: c_S}
# without zeros, is canonical.  sqrt(P_S) sqrt(P_T) = g sqrt(P_S P_T / g^2), g = gcd(P_S, P_T).

class SquareRoots:
    """The field ``{"radicands": [a_1, ...]}``: checks them, then makes elements."""

    def __init__(self, spec: dict):
        a = [integer(x) if isinstance(x, str) else x for x in spec["radicands"]]
        need(a and all(is_int(x) and x > 1 for x in a), "radicands: integers above 1")
        need(all(isqrt(x) ** 2 != x for x in a), "radicands: one of them is a square")
        need(all(gcd(x, y) == 1 for i, x in enumerate(a) for y in a[i + 1:]),
             "radicands: not pairwise coprime")
        self.radicands = a

    def key(self, text) -> int:                 # a product of distinct radicands
        m = rest = integer(text)
        for x in self.radicands:
            rest //= x if rest % x == 0 else 1
        need(m >= 1 and rest == 1, f"{text!r} is not a product of distinct radicands")
        return m

    def num(self, value) -> "Root":
        """A rational, or {"P_S": coefficient, ...}."""
        if isinstance(value, dict):
            terms: dict = {}
            for m, c in value.items():
                q, m = frac(c), self.key(m)
                need(m not in terms, f"radicand product {m} given twice")
                if q:
                    terms[m] = q
            return Root.of(terms)
        need(not isinstance(value, list), "a square-root field's numbers are rationals or "
             "{product: coefficient} maps")
        q = frac(value)
        return Root.of({1: q} if q else {})

class Root(RingOps):
    """(sum c_m sqrt(m)) / den, integers c_m != 0, den > 0, gcd 1: canonical, == and hash exact.
    One denominator: a product of t terms by t terms is t^2 integer products, no gcds."""
    __slots__ = ("t", "den")

    def __init__(self, terms: dict, den: int = 1):
        g = gcd(den, *terms.values())
        if g != 1:
            terms, den = {m: c // g for m, c in terms.items()}, den // g
        self.t, self.den = terms, den

    @staticmethod
    def of(terms: dict) -> "Root":
        """From rational coefficients."""
        den = lcm(*(Fraction(c).denominator for c in terms.values())) if terms else 1
        return Root({m: int(c * den) for m, c in terms.items()}, den)

    @staticmethod
    def _of(o) -> "Root":
        if isinstance(o, Root):
            return o
        o = Fraction(o)
        return Root({1: o.numerator} if o else {}, o.denominator)

    def __add__(self, o):
        o = self._of(o)
        a, b = o.den, self.den
        out = {m: c * a for m, c in self.t.items()}
        for m, c in o.t.items():
            v = out.get(m, 0) + c * b
            if v:
                out[m] = v
            else:
                out.pop(m, None)
        return Root(out, a * b)

    def __mul__(self, o):
        o = self._of(o)
        out: dict = {}
        get = out.get
        for m, c in self.t.items():
            for k, d in o.t.items():
                g = gcd(m, k)
                key = (m // g) * (k // g)
                out[key] = get(key, 0) + c * d * g
        return Root({m: c for m, c in out.items() if c}, self.den * o.den)

    def __neg__(self):
        return Root({m: -c for m, c in self.t.items()}, self.den)

    def __eq__(self, o):
        if not isinstance(o, (Root, int, Fraction)):
            return False
        o = self._of(o)
        return self.den == o.den and self.t == o.t

    def __hash__(self):
        return hash((frozenset(self.t.items()), self.den))

    def sign(self) -> int:
        """By enclosures sqrt(m) in [isqrt(m 4^b), isqrt(m 4^b) + 1] / 2^b, b doubling until 0 is
        excluded (a non-zero element is a non-zero real: this ends)."""
        bits = 32 if self.t else 1 << 20
        while bits < 1 << 20:
            lo = hi = 0
            for m, c in self.t.items():
                r = isqrt(m << 2 * bits)
                r1 = r + (r * r != m << 2 * bits)
                lo, hi = (lo + c * r, hi + c * r1) if c > 0 else (lo + c * r1, hi + c * r)
            if lo > 0 or hi < 0:
                return 1 if lo > 0 else -1
            bits *= 2
        need(not self.t, "a sign could not be decided")
        return 0
