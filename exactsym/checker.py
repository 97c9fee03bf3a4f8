"""The independent checker of exactsym certificates: the one module a sceptic must trust.

Standard library only; imports nothing from exactsym.  ``python -m exactsym.checker CERT.json``
exits 0 when the certificate proves its claim, 1 when it does not (the reason on stderr), 2 when
the file is unreadable.  The format is described in ``docs/certificates.md``.

What a valid certificate proves.  P is the embedded point set, G the group of the isometries g
of the plane with g(P) = P; the "level" of a point is the set of points as far as it from c.
 1. c is fixed by every g in G.  Cartesian: c is the centroid (g is affine and permutes P, so it
    fixes the mean of P).  Polar: c is the origin, checked to be the centre of the smallest
    enclosing circle of P, which is unique and so mapped onto itself by every g.
 2. H <= G: each generator (a rotation rho about c; for Dk also a reflection mu through c) maps
    every point i to point perm[i], so it maps P into P and is in G.  A rotation about c fixing
    a point a != c is the identity, so the order k of rho is the length of the cycle of the
    reference point a under its permutation, and H = <rho, mu> is exactly Ck or Dk.
 3. G <= H: every g in G fixes c, so g is determined by its kind (rotation or reflection) and
    by b = g(a), a point of P on the level of a.  For each such b and kind, the candidate is in
    H (b is in the H-orbit of a, computed from the verified permutations) or the witness names
    a point w whose image under the candidate is not in P: then the candidate is not in G.
So G = H: the checker names it, derives "orderable" (no element of G moves a point) and
compares both with the claim.  The cost is linear: O(n) per generator, O(1) per candidate.

Numbers are exact: rationals (ints after scaling by a common denominator, or Fractions), or
elements of one real number field Q(theta) written as coefficient lists in theta.
"""

from __future__ import annotations

import hashlib
import itertools
import json
import sys
from fractions import Fraction
from math import gcd, isqrt, lcm, prod


class Invalid(Exception):
    """The certificate does not prove its claim; the message says why."""


def need(condition, reason: str) -> None:
    if not condition:
        raise Invalid(reason)


def rat(text) -> tuple[int, int]:
    """An exact rational "p/q" or "p" (or a JSON integer) as ``(p, q)``, q > 0."""
    if isinstance(text, int) and not isinstance(text, bool):
        return text, 1
    num, slash, den = text.partition("/") if isinstance(text, str) else ("?", "", "")
    try:
        p, q = integer(num), (integer(den) if slash else 1)
    except ValueError:
        q = 0
    need(q > 0, f"not an exact rational: {text!r}")
    return p, q


def integer(text: str) -> int:
    """``int(text)`` for a decimal integer of any length: Python's ``int`` refuses strings of
    more than 4300 digits, so longer ones are read in chunks (no global limit is changed)."""
    digits = text[1:] if text[:1] in "+-" else text
    if not (digits.isascii() and digits.isdigit()):
        raise ValueError(f"not an integer: {text!r}")
    value = 0
    for start in range(0, len(digits), 4000):
        chunk = digits[start:start + 4000]
        value = value * 10 ** len(chunk) + int(chunk)
    return -value if text[:1] == "-" else value


def frac(text) -> Fraction:
    return Fraction(*rat(text))


def scaled(pairs: list) -> tuple[list, int]:
    """Rationals as ints times a common denominator D (scaling all numbers of one kind by one
    D > 0 keeps equality, order and symmetries); Fractions and D = 1 if D would be huge."""
    d = 1
    for _, q in pairs:
        if d % q:
            d = lcm(d, q)
            if d.bit_length() > 8192:
                return [Fraction(p, q) for p, q in pairs], 1
    return [p * (d // q) for p, q in pairs], d


# ------------------------------------------------------------------ the number field
# theta is the only root of the monic polynomial p in the interval (lo, hi).  If p is
# irreducible, a polynomial of degree < deg p vanishes at theta only if it is zero, so the
# coefficients of an element reduced modulo p are canonical: == and hash on them decide the
# equality of real numbers exactly.  So irreducibility is PROVED, never trusted: with a
# reducible p, equal numbers could have different coefficients and a false witness would pass.

def psi(m: int) -> list[int]:
    """The minimal polynomial of 2cos(2pi/m), m >= 3, with integer coefficients (low first).

    Phi_m = prod over squarefree t | m of (x^(m/t) - 1)^mu(t) (Moebius inversion of
    x^m - 1 = prod_{e | m} Phi_e); dividing after all multiplications keeps divisions exact.
    Phi_m is irreducible (Gauss), palindromic of degree 2h, and z^-h Phi_m(z) = Psi_m(z + 1/z):
    so 2cos(2pi/m) has degree h, and Psi_m, monic of degree h, is its minimal polynomial."""
    primes, r = [], m
    for q in range(2, isqrt(m) + 1):
        if r % q == 0:
            primes.append(q)
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


def irreducible_mod(p: list, ell) -> bool:
    """p (monic, rational) keeps its degree d and is irreducible modulo the prime ell.

    This proves p irreducible over Q: by Gauss's lemma a factorisation over Q gives one of an
    integer multiple of p over Z with the same degrees, which reduced mod ell (not dividing the
    leading coefficient) factors p mod ell.  Over F_ell, x^(ell^i) - x is the product of the
    monic irreducibles of degree dividing i, and a reducible f has a factor of degree <= d/2:
    so f is irreducible iff gcd(x^(ell^i) - x, f) = 1 for i = 1 .. d/2."""
    need(isinstance(ell, int) and 2 <= ell < 1 << 32
         and all(ell % q for q in range(2, isqrt(ell) + 1)), f"{ell!r} is not a prime")
    den = lcm(*(c.denominator for c in p))
    lead = int(p[-1] * den) % ell
    f = [int(c * den) * pow(lead, -1, ell) % ell for c in p] if lead else [0]
    if f[0] == 0:                               # ell divides the leading coefficient, or x | f
        return False

    def rem(a, g):                              # a mod g over F_ell, no trailing zeros
        a, inv = [c % ell for c in a], pow(g[-1], -1, ell)
        while True:
            while a and a[-1] == 0:
                a.pop()
            if len(a) < len(g):
                return a
            t, s = a[-1] * inv % ell, len(a) - len(g)
            for j, c in enumerate(g):
                a[s + j] = (a[s + j] - t * c) % ell

    def mulmod(a, b):
        out = [0] * (len(a) + len(b) - 1)
        for i, x in enumerate(a):
            for j, y in enumerate(b):
                out[i + j] += x * y
        return rem(out, f)

    h = [0, 1]
    for _ in range((len(f) - 1) // 2):
        base, e, h = h, ell, [1]
        while e:                                # h = base^ell mod f: now h = x^(ell^i) mod f
            h = mulmod(h, base) if e & 1 else h
            base, e = mulmod(base, base), e >> 1
        a, b = f, rem([c - (j == 1) for j, c in enumerate(h + [0] * (2 - len(h)))], f)
        while b:                                # gcd(f, x^(ell^i) - x)
            a, b = b, rem(a, b)
        if len(a) > 1:
            return False
    return True


def one_root(p: list, lo: Fraction, hi: Fraction) -> bool:
    """p has exactly one root in (lo, hi): Descartes' rule of signs on
    q(x) = (1 + x)^d p(lo + (hi - lo)/(1 + x)), whose positive roots are the roots of p in
    (lo, hi); the sign changes of q's coefficients exceed the number of positive roots by an
    even number, so one sign change means exactly one (simple) root.  (In integers: with
    lo = l/D, hi = h/D, q is a positive multiple of (1 + x)^d P((l + (h - l)/(1 + x))/D).)"""
    def shift(c, a):                            # the coefficients of c(x + a)
        c = list(c)
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


def peval(p, x):
    value = 0
    for c in reversed(p):
        value = value * x + c
    return value


class Field:
    """Q(theta): checks the field's description, then makes its elements and decides signs."""

    def __init__(self, spec: dict):
        p = [frac(c) for c in spec["minpoly"]]
        while p and p[-1] == 0:
            p.pop()
        need(len(p) >= 3, "the minimal polynomial must have degree >= 2")
        self.p, self.d = [c / p[-1] for c in p], len(p) - 1
        self.lead = lcm(*(c.denominator for c in self.p))      # p = big / lead, big integral
        self.big = [int(c * self.lead) for c in self.p]
        lo, hi = self.interval = tuple(frac(x) for x in spec["interval"])
        need(lo < hi and peval(self.p, lo) * peval(self.p, hi) < 0,
             "the minimal polynomial does not change sign on the interval of theta")
        need(one_root(self.p, lo, hi), "the interval does not isolate one root of the polynomial")
        proof = spec["irreducible"]
        if proof["method"] == "real-cyclotomic":    # p must be Psi_m: irreducible by theorem
            m = proof["conductor"]
            need(isinstance(m, int) and 3 <= m <= 10 ** 6 and psi(m) == self.p,
                 f"the minimal polynomial is not that of 2cos(2pi/{m!r})")
        elif proof["method"] == "square-roots":
            self.square_roots(proof["radicands"], proof["roots"])
        else:
            need(proof["method"] == "prime", f"unknown irreducibility proof {proof['method']!r}")
            need(irreducible_mod(self.p, proof["prime"]),
                 f"the minimal polynomial is not irreducible modulo {proof['prime']!r}")

    def square_roots(self, radicands: list, roots: list) -> None:
        """p is irreducible if it has degree 2^k and Q(theta') holds square roots of k
        positive integers a_1..a_k, no product of a non-empty subset of which is a square,
        for every root theta' of p.  Such a_i generate a field of degree 2^k (the square
        roots of independent elements of Q*/Q*^2 have independent classes: Besicovitch 1940),
        so every root of p has degree >= 2^k = deg p, and p is its minimal polynomial.  The
        roots are polynomials g_i with g_i^2 = a_i modulo p: this holds at every root of p,
        whatever p is, because it is a polynomial identity modulo p."""
        a = [integer(x) for x in radicands]
        k = len(a)
        need(1 <= k <= 16 and self.d == 1 << k and len(roots) == k and all(x > 0 for x in a),
             "square-roots proof: need k positive radicands and degree 2^k")
        for mask in range(1, 1 << k):
            product = prod(x for i, x in enumerate(a) if mask >> i & 1)
            need(isqrt(product) ** 2 != product,
                 f"square-roots proof: a product of radicands is a square ({product})")
        for x, g in zip(a, roots):
            need(isinstance(g, list), "square-roots proof: a root must be a coefficient list")
            root = self.num(g)
            need(root * root == x, f"square-roots proof: the root given for {x} does not "
                 "square to it")

    def make(self, c: list, den: int) -> "Alg":
        """The element (sum c_i theta^i) / den in canonical form: c reduced modulo p (in
        integers: c - (c_i / lead) theta^(i-d) big, first scaling c and den by lead if needed),
        then divided by the gcd of den and all of c, without trailing zeros."""
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
        """The sign of c(theta) by interval Horner on [lo, hi], halving the interval (towards the
        sign change of p) until 0 is excluded.  c(theta) != 0 for canonical c != 0 and the
        enclosure shrinks to c(theta), so this ends; the narrower interval is kept."""
        for _ in range(10000):
            lo, hi = self.interval
            a = b = Fraction(0)
            for coeff in reversed(c):
                ends = (a * lo, a * hi, b * lo, b * hi)
                a, b = min(ends) + coeff, max(ends) + coeff
            if a > 0 or b < 0 or not c:
                return (a > 0) - (b < 0)
            mid = (lo + hi) / 2
            left = (peval(self.p, lo) > 0) != (peval(self.p, mid) > 0)
            self.interval = (lo, mid) if left else (mid, hi)
        raise Invalid("a sign could not be decided")


class Alg:
    """c(theta)/den, canonical (see Field.make): == and hash are exact; mixes with int/Fraction."""
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
        (b, db), a = self._of(o), self.c
        out = [0] * max(len(a) + len(b) - 1, 0)
        for i, x in enumerate(a):
            for j, y in enumerate(b):
                out[i + j] += x * y
        return self.f.make(out, self.den * db)

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


def sgn(v) -> int:
    """The sign of a number (den > 0, so an element has the sign of its numerator)."""
    return v.f.sign(v.c) if isinstance(v, Alg) else (v > 0) - (v < 0)


# ------------------------------------------------------------------ the proof, steps 2 and 3

def permutation(spec: dict, n: int, name: str) -> list:
    perm = spec["permutation"]
    need(isinstance(perm, list) and len(perm) == n and all(
        isinstance(j, int) and 0 <= j < n for j in perm), f"{name}: not a list of {n} indices")
    return perm


def reference(witness: dict, n: int) -> int:
    ref = witness["reference"]
    need(isinstance(ref, int) and 0 <= ref < n, f"bad reference point {ref!r}")
    return ref


def group(n, ref, level, rot, mir, witness, image_in) -> tuple[str, bool]:
    """Order of rho and step 3, given the verified permutations; returns (name, orderable).
    ``image_in(kind, b, w)``: does the isometry of this kind fixing c and taking the reference
    point to point b map point w onto a point of P?"""
    orbit, j = [ref], (rot[ref] if rot else ref)
    while j != ref:                             # rot is a bijection: an injective map of P
        orbit.append(j)
        j = rot[j]
    inside = {"rotation": set(orbit), "reflection": {mir[i] for i in orbit} if mir else set()}
    on_level, refutations = set(level), witness.get("refutations", {})
    for kind in ("rotation", "reflection"):
        refuted = set()
        for b, w in refutations.get(kind, []):
            need(b in on_level, f"{kind} refutation: point {b!r} is not on the level of the "
                 f"reference point {ref}")
            need(isinstance(w, int) and 0 <= w < n, f"{kind} refutation: bad point {w!r}")
            need(not image_in(kind, b, w), f"the {kind} taking point {ref} to point {b} maps "
                 f"point {w} onto a point of the configuration: it refutes nothing")
            refuted.add(b)
        for b in level:
            need(b in inside[kind] or b in refuted, f"the {kind} taking point {ref} to point "
                 f"{b} is neither in the claimed group nor refuted")
    orderable = len(orbit) == 1 and (mir is None or all(mir[i] == i for i in range(n)))
    return f"{'D' if mir else 'C'}{len(orbit)}", orderable


def distinct(keys: list) -> dict:
    index: dict = {}
    for i, k in enumerate(keys):
        need(index.setdefault(k, i) == i, f"points {index[k]} and {i} coincide")
    return index


def cartesian(points: list, field: Field | None, witness: dict) -> tuple[str, bool]:
    n = len(points)
    if field is None:
        flat, scale = scaled([rat(v) for x, y in points for v in (x, y)])
        pts, num = list(zip(flat[0::2], flat[1::2])), frac
    else:
        pts, scale, num = [(field.num(x), field.num(y)) for x, y in points], 1, field.num
    sx, sy = sum(x for x, _ in pts), sum(y for _, y in pts)
    w = [(n * x - sx, n * y - sy) for x, y in pts]     # n * scale * (p - centroid): exact
    distinct(w)
    if n == 1:
        return "O2", True

    def isometry(name, det):                    # step 2 for one generator
        spec = witness.get(name)
        if spec is None:
            return None
        cx, cy = (num(v) for v in spec["centre"])
        need(cx * (n * scale) == sx and cy * (n * scale) == sy,
             f"{name}: the centre is not the centroid of the points")
        (a, b), (c, d) = [[num(v) for v in row] for row in spec["matrix"]]
        need(a * a + c * c == 1 and b * b + d * d == 1 and a * b + c * d == 0,
             f"{name}: the matrix is not orthogonal")
        need(a * d - b * c == det, f"{name}: the matrix does not have determinant {det}")
        m = 1 if field else lcm(a.denominator, b.denominator, c.denominator, d.denominator)
        a, b, c, d = (e * m if field else int(e * m) for e in (a, b, c, d))
        perm = permutation(spec, n, name)
        for i, (x, y) in enumerate(w):          # m g(p_i) = m p_perm[i], in the w frame
            need((m * w[perm[i]][0], m * w[perm[i]][1]) == (a * x + b * y, c * x + d * y),
                 f"{name}: the image of point {i} is not point {perm[i]}")
        return perm

    rot, mir, ref = isometry("rotation", 1), isometry("mirror", -1), reference(witness, n)
    ux, uy = w[ref]
    s = ux * ux + uy * uy
    need(s != 0, "the reference point is the centre")
    level = [i for i, (x, y) in enumerate(w) if x * x + y * y == s]
    scaled_w: set = set()

    def image_in(kind, b, i):
        # The isometry about c with u = w[ref] -> v = w[b] (|u|^2 = |v|^2 = s) is the rotation
        # [[dot, -cross], [cross, dot]] / s or the reflection [[e, f], [f, -e]] / s; s times the
        # image of w[i] is looked up in s * P, so nothing is divided.
        if not scaled_w:
            scaled_w.update((s * x, s * y) for x, y in w)
        (vx, vy), (x, y) = w[b], w[i]
        if kind == "rotation":
            dot, cross = ux * vx + uy * vy, ux * vy - uy * vx
            return (dot * x - cross * y, cross * x + dot * y) in scaled_w
        e, f = ux * vx - uy * vy, ux * vy + uy * vx
        return (e * x + f * y, f * x - e * y) in scaled_w

    return group(n, ref, level, rot, mir, witness, image_in)


def polar(points: list, field: Field | None, witness: dict) -> tuple[str, bool]:
    n = len(points)
    rot, mir = witness.get("rotation"), witness.get("mirror")
    extra = [rat(rot["turn"])] if rot else []
    if mir:
        p, q = rat(mir["turn"])
        extra.append((2 * p, q))                # 2 alpha: the reflection is t -> 2 alpha - t
    turns, T = scaled([rat(t) for _, t in points] + extra)    # whole turns are T
    r2 = scaled([rat(r) for r, _ in points])[0] if field is None else [
        field.num(r) for r, _ in points]
    values = set(r2)
    need(all(sgn(v) >= 0 for v in values), "a squared radius is negative")

    def key(r, t):                              # the point (r2, turn), the turn taken mod 1
        return (r, 0) if r == 0 else (r, t % T)

    keys = [key(r, t) for r, t in zip(r2, turns)]
    index = distinct(keys)
    if n == 1:
        return "O2", True
    # Step 1: the origin is the SEC centre iff no point is farther than R and the points at
    # distance R leave no angular gap above half a turn (else a smaller circle holds them all).
    big = next(iter(values))
    for v in values:
        big = v if sgn(v - big) > 0 else big
    rim = sorted(t for r, t in keys if r == big)
    gaps = [b - a for a, b in zip(rim, rim[1:])] + [rim[0] + T - rim[-1]]
    need(2 * max(gaps) <= T, "the origin is not the centre of the smallest enclosing circle")

    def isometry(name, spec, image):            # step 2 for one generator
        if spec is None:
            return None
        perm = permutation(spec, n, name)
        for i, (r, t) in enumerate(keys):
            need(key(r, image(t)) == keys[perm[i]],
                 f"{name}: the image of point {i} is not point {perm[i]}")
        return perm

    tau, sigma = turns[n] if rot else None, turns[-1] if mir else None
    rot = isometry("rotation", rot, lambda t: t + tau)
    mir = isometry("mirror", mir, lambda t: sigma - t)
    ref = reference(witness, n)
    ra, ta = keys[ref]
    need(ra != 0, "the reference point is the centre")
    level = [i for i, (r, _) in enumerate(keys) if r == ra]

    def image_in(kind, b, i):                   # rotation by tb - ta; reflection t -> ta + tb - t
        (r, t), tb = keys[i], keys[b][1]
        return key(r, t + tb - ta if kind == "rotation" else ta + tb - t) in index

    return group(n, ref, level, rot, mir, witness, image_in)


# ------------------------------------------------------------------ the certificate

def digest(configuration) -> str:
    text = json.dumps(configuration, sort_keys=True, separators=(",", ":"))
    return hashlib.sha256(text.encode()).hexdigest()


def verify_certificate(cert) -> tuple[bool, str]:
    """``(True, summary)`` when the certificate proves its claim, else ``(False, reason)``."""
    try:
        need(isinstance(cert, dict) and cert.get("format") == "exactsym-certificate"
             and cert.get("version") == 1, "not an exactsym certificate of version 1")
        config, claim, witness = cert["configuration"], cert["claim"], cert["witness"]
        # A fingerprint of the configuration: it catches edits; the proof does not rely on it.
        need(cert.get("configuration_sha256") == digest(config),
             "configuration_sha256 does not match the embedded configuration")
        field = Field(config["field"]) if config.get("field") is not None else None
        points, kind = config["points"], config["coordinates"]
        need(isinstance(points, list) and points and all(
            isinstance(p, list) and len(p) == 2 for p in points), "points must be pairs")
        need(kind in ("cartesian", "polar"), f"unknown coordinates {kind!r}")
        name, orderable = (cartesian if kind == "cartesian" else polar)(points, field, witness)
        need(claim["group"] == name, f"the claim says group {claim['group']!r} but the "
             f"witness proves {name}")
        need(claim["orderable"] is orderable, f"the claim says orderable "
             f"{claim['orderable']!r} but group {name} makes it {orderable}")
        return True, f"group {name}, orderable {str(orderable).lower()}"
    except Invalid as err:
        return False, str(err)
    except (KeyError, TypeError, ValueError, IndexError, AttributeError, ZeroDivisionError) as err:
        return False, f"malformed certificate ({type(err).__name__}: {err})"


# ------------------------------------------------------------------ refutations
# A refutation certificate (docs/certificates.md, "Refutations") wraps a group certificate:
# once that proves G (the group of P) and its orderability, the premise "P is in O_A" and
# the conclusion "P is orderable" are facts about G, derived here and nowhere else.
REFUTABLE = {"Pasym-Pord": "P is orderable if P is in O_A",
             "lem-asym-ord": "an asymmetric polygon is orderable",
             "cor-Pasym-Pord": "P is orderable if G_P is in O_A",
             "lem-one-pair-asym-ord": "if G_P contains an asymmetric polygon, P is orderable",
             "lem-asym-pair-ord": "an asymmetric pair is orderable",
             "lem-all-pair-asym-ord": "if G_P has an asymmetric pair, P is orderable",
             "obs-merg-asym-pair": "if <G_i, G_j> is an asymmetric pair, G_ij is asymmetric",
             "lemma-sym-regular": "a convex polygon with more than one line of symmetry, "
                                  "each through a vertex, is regular",
             "obs-exh-poly": "every straight symmetric polygon is of type 0, 1, 2, 3 or 4"}


def _one_level(config) -> bool:
    """All points at one distance from c (rational coordinates only)."""
    pts = config["points"]
    need(all(isinstance(v, (str, int)) for p in pts for v in p),
         "one level: only rational coordinates are supported")
    if config["coordinates"] == "polar":
        return len({frac(p[0]) for p in pts}) == 1
    xs, ys = [frac(p[0]) for p in pts], [frac(p[1]) for p in pts]
    cx, cy = sum(xs) / len(xs), sum(ys) / len(ys)
    return len({(x - cx) ** 2 + (y - cy) ** 2 for x, y in zip(xs, ys)}) == 1


# The other refutations speak of the polygons of G_P: the levels of P about the centre c of
# its SEC.  They are checked on rational polar certificates only, where c is the origin
# (verified by the group certificate) and a level is the set of points with one r2.  A
# part -- a level, a pair of levels, the merged polygon G_ij -- comes with a group
# certificate of its own, whose points must be exactly those the checker computes from P.
# Lines of symmetry of a polygon with >= 3 vertices on a circle about c (none of the
# readings of "common line" differ there: no line holds every vertex, no single vertex):
# its mirrors, and when it has the half-turn about c every line through c (skew lines).

def _keys(config) -> list:
    """(r2, turn mod 1) of each point: a rational polar configuration."""
    need(config["coordinates"] == "polar" and config.get("field") is None,
         "this refutation is checked on rational polar certificates only")
    return [(frac(r), frac(t) % 1 if frac(r) else Fraction(0)) for r, t in config["points"]]


def _levels(keys) -> dict:
    out: dict = {}
    for r2, t in keys:
        if r2:
            out.setdefault(r2, set()).add((r2, t))
    return out


def _part(cert, expected: set, what: str) -> tuple:
    """Verify a part's group certificate and that its points are ``expected``; returns
    (group name, number of rotations k, mirror axes as turns mod 1/2)."""
    ok, why = verify_certificate(cert)
    need(ok, f"{what}: the certificate is invalid: {why}")
    keys = _keys(cert["configuration"])
    need(set(keys) == expected and len(keys) == len(expected),
         f"{what}: its points are not the ones the checker computes from P")
    name = cert["claim"]["group"]
    need(name != "O2", f"{what}: one point")
    k = int(name[1:])
    axes = set()
    if name.startswith("D"):                   # reflections t -> 2a - t + j/k: axes a + j/2k
        a = frac(cert["witness"]["mirror"]["turn"])
        axes = {(a + Fraction(j, 2 * k)) % Fraction(1, 2) for j in range(k)}
    return name, k, axes


def _no_line(name: str, k: int) -> bool:
    """The polygon has no line of symmetry: no mirror and no half-turn (k odd)."""
    return name.startswith("C") and k % 2 == 1


def _level_part(obj, levels, what="level") -> tuple:
    r2 = frac(obj["parts"][what]["configuration"]["points"][0][0])
    need(r2 in levels and len(levels[r2]) >= 3, f"{what}: not a level of P with >= 3 points")
    return levels[r2], _part(obj["parts"][what], levels[r2], what)


def _asymmetric_pair(obj, levels) -> tuple:
    """The two levels of ``parts.pair`` form an asymmetric pair under every reading: no
    half-turn in either (no skew line) and no common mirror.  Returns their point sets."""
    pair = obj["parts"]["pair"]
    need(isinstance(pair, list) and len(pair) == 2, "parts.pair: two certificates")
    sets, axes = [], []
    for i, cert in enumerate(pair):
        level, (name, k, ax) = _level_part({"parts": {"pair": cert}}, levels, "pair")
        need(k % 2 == 1, f"pair {i}: group {name} has the half-turn: every line through c "
             "is a skew line of it")
        sets.append(level)
        axes.append(ax)
    need(sets[0] != sets[1], "the pair names one level twice")
    need(not axes[0] & axes[1], "the pair has a common mirror: it is symmetric")
    return sets[0], sets[1]


def _premise(label, obj, P: set, name: str, k: int, n: int) -> str:
    """Check the premise of ``label`` on P (its group ``name`` is proved); returns it in
    words.  The shared conclusion, except for obs-merg-asym-pair, is "P is orderable"."""
    levels = _levels(P)
    if label in ("cor-Pasym-Pord", "lem-one-pair-asym-ord"):
        _, (lname, lk, _) = _level_part(obj, levels)
        need(_no_line(lname, lk), f"the premise fails: the level has group {lname}, it is "
             "symmetric")
        return (f"a level of P has group {lname} (no mirror, no half-turn): an asymmetric "
                "polygon, so no line is common to every polygon and G_P is in O_A")
    if label in ("lem-asym-pair-ord", "lem-all-pair-asym-ord"):
        a, b = _asymmetric_pair(obj, levels)
        if label == "lem-asym-pair-ord":
            need(a | b == P, "the premise fails: P is not the union of the pair")
        return "two levels of P form an asymmetric pair (no half-turn, no common mirror)"
    if label == "lemma-sym-regular":
        need(len(levels) == 1 and len(P) == n >= 3, "the premise fails: not one polygon "
             "with >= 3 vertices (points on one circle: a convex polygon)")
        axes = _part(obj["certificate"], P, "P")[2]
        need(name.startswith("D") and k >= 2 and k % 2 == 1, f"the premise fails: group "
             f"{name} does not have more than one line of symmetry, all mirrors (k odd)")
        turns = {t for _, t in P}
        need(all(any((t - x) % Fraction(1, 2) == 0 for t in turns) for x in axes),
             "the premise fails: a mirror passes through no vertex")
        return f"one polygon of {n} vertices with group {name}: {k} mirrors, each through a vertex"
    raise Invalid(f"no refutation by symmetry facts for {label!r}")


def _no_type(P: set, name: str, k: int, n: int, axes: set) -> str:
    """obs-exh-poly: P is one straight symmetric polygon (group Dk, k mirrors) that fits
    none of the types, each decided from n, k and the mirrors through vertices: 0 regular
    (k = n); 1 n even, k = 2, no mirror through a vertex; 2 n even, k = 1 (one mirror of an
    even polygon fixes 0 or 2 vertices: it passes through two vertices or two edges); 3 n
    odd, k = 1 (it fixes one vertex: a vertex and an edge); 4 n odd and not prime, 1 < k < n."""
    need(len(_levels(P)) == 1 and n >= 3, "the premise fails: not one polygon with >= 3 "
         "vertices")
    need(name.startswith("D"), f"the premise fails: group {name} has no mirror")
    through = {x for x in axes if any((t - x) % Fraction(1, 2) == 0 for _, t in P)}
    prime = n > 1 and all(n % d for d in range(2, isqrt(n) + 1))
    types = {0: k == n, 1: n % 2 == 0 and k == 2 and not through,
             2: n % 2 == 0 and k == 1, 3: n % 2 == 1 and k == 1,
             4: n % 2 == 1 and not prime and 1 < k < n}
    fits = [t for t, holds in types.items() if holds]
    need(not fits, f"the conclusion holds: it is of type {fits[0] if fits else ''}")
    return (f"one polygon of {n} vertices with group {name}: {k} mirrors "
            f"({len(through)} through a vertex), not regular, fits none of the types 0-4")


def _merged_asymmetric(obj, P: set) -> str:
    """obs-merg-asym-pair: the pair is asymmetric, and G_ij -- G_i projected radially onto
    G_j's circle, with G_j (the checker builds it) -- has a mirror or the half-turn."""
    a, b = _asymmetric_pair(obj, _levels(P))
    rj = next(iter(b))[0]
    merged = {(rj, t) for _, t in a} | b
    need(len(merged) == len(a) + len(b), "G_i projected onto G_j meets a vertex of G_j")
    name, k, _ = _part(obj["parts"]["merged"], merged, "merged")
    need(not _no_line(name, k), f"the conclusion holds: G_ij has group {name}")
    return (f"an asymmetric pair whose merged polygon G_ij has group {name}: it is "
            "symmetric")


def verify_refutation(obj) -> tuple[bool, str]:
    """``(True, summary)`` when the refutation certificate shows a configuration meeting the
    premise of ``obj["label"]`` whose conclusion is false, all derived from the groups its
    embedded certificates prove (docs/certificates.md, "Refutations"): for Pasym-Pord and
    lem-asym-ord P in O_A (at least two points, no mirror that moves a point, no half-turn;
    for lem-asym-ord also one level) and P not orderable; for the others the premise
    about the polygons of G_P in :func:`_premise` and P not orderable, or, for
    obs-merg-asym-pair, an asymmetric pair whose merged polygon is symmetric."""
    try:
        need(isinstance(obj, dict) and obj.get("format") == "exactsym-refutation"
             and obj.get("version") == 1, "not an exactsym refutation of version 1")
        label = obj.get("label")
        need(label in REFUTABLE, f"no refutation by symmetry facts for {label!r}")
        need(obj.get("statement") == REFUTABLE[label], "the statement is not the label's")
        cert = obj["certificate"]
        ok, why = verify_certificate(cert)
        need(ok, f"the embedded certificate is invalid: {why}")
        name, orderable = cert["claim"]["group"], cert["claim"]["orderable"]
        n = len(cert["configuration"]["points"])
        k = 1 if name == "O2" else int(name[1:])
        if label == "obs-merg-asym-pair":
            return True, f"{label} refuted: " + _merged_asymmetric(
                obj, set(_keys(cert["configuration"])))
        if label == "obs-exh-poly":
            P = set(_keys(cert["configuration"]))
            return True, f"{label} refuted: " + _no_type(P, name, k, n,
                                                         _part(cert, P, "P")[2])
        if label in ("Pasym-Pord", "lem-asym-ord"):
            # A reflection in G moves a point unless G = D1 fixes every point (orderable); a
            # half-turn is in G iff k is even.
            no_moving_mirror = name.startswith("C") or (name == "D1" and orderable)
            need(n >= 2 and no_moving_mirror and k % 2 == 1,
                 f"the premise fails: group {name} on {n} point(s) is in O_S")
            if label == "lem-asym-ord":
                need(_one_level(cert["configuration"]), "the premise fails: not one polygon")
            premise = "group {name} has no mirror moving a point and no half-turn".format(
                name=name)
        else:
            premise = _premise(label, obj, set(_keys(cert["configuration"])), name, k, n)
        if label == "lemma-sym-regular":
            need(k < n, f"the conclusion holds: the rotation of order {k} = n makes it "
                 "regular")
            return True, f"{label} refuted: {premise}, yet its rotations have order {k} < {n}"
        need(orderable is False, f"the conclusion holds: group {name} is orderable")
        mover = f"its rotation of order {k}" if k > 1 else "its mirror"
        return True, (f"{label} refuted: {premise}, yet P (group {name}) is not "
                      f"orderable: {mover} moves a point")
    except Invalid as err:
        return False, str(err)
    except (KeyError, TypeError, ValueError, IndexError, AttributeError) as err:
        return False, f"malformed refutation ({type(err).__name__}: {err})"


def main(argv: list | None = None) -> int:
    args = sys.argv[1:] if argv is None else argv
    if len(args) != 1:
        print("usage: python -m exactsym.checker CERT.json", file=sys.stderr)
        return 2
    try:
        with open(args[0], encoding="utf-8") as fh:
            cert = json.load(fh)
    except (OSError, ValueError, RecursionError) as err:
        print(f"{args[0]}: unreadable certificate: {err}", file=sys.stderr)
        return 2
    verify = verify_refutation if isinstance(cert, dict) and \
        cert.get("format") == "exactsym-refutation" else verify_certificate
    ok, message = verify(cert)
    print(f"{args[0]}: {'valid' if ok else 'INVALID'}: {message}",
          file=sys.stdout if ok else sys.stderr)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
