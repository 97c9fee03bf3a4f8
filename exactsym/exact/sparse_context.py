"""The conductor's context of :mod:`.sparse_cyclotomic`: N and its factorisation, the
Arb balls of the cosines met so far, rational traces, and the l-adic embedding that hashes
numbers whatever their (non-canonical) form.

Public names: :class:`SparseContext`, :func:`sparse_context`.
"""

from __future__ import annotations

from math import gcd

from flint import arb, ctx, fmpq

from .factor import factorization, is_prime

_COS_CACHE_LIMIT = 1 << 16


def root_of_unity(n: int, factors, ell: int) -> int:
    """A primitive n-th root of unity modulo the prime ell = 1 mod n (``factors``: the
    primes of n)."""
    h = 2
    while True:
        g = pow(h, (ell - 1) // n, ell)
        if all(pow(g, n // p, ell) != 1 for p in factors):
            return g
        h += 1


# ---------------------------------------------------------------- the conductor's context
class SparseContext:
    """What every element of Q(zeta_N) shares: N, its factorisation, the cosines met so far,
    and the l-adic embedding used for hashing.

    Hashing: l is the least prime 1 mod N above 2^61, and t_K a primitive N-th root of unity
    modulo l^K (the Teichmueller lift of g mod l).  zeta_N -> t_K is a ring homomorphism
    Z_(l)[zeta_N] -> Z/l^K, one embedding Q(zeta_N) -> Q_l read to K digits, so the residue
    of x in Q_l (or "a pole" when x is not l-integral) does not depend on how x is written:
    equal numbers hash alike."""

    def __init__(self, n: int):
        self.n = n
        self.factors = factorization(n) if n > 1 else {}
        self.phi = 1
        for p, a in self.factors.items():
            self.phi *= (p - 1) * p ** (a - 1)
        k = (1 << 61) // n + 1
        while not is_prime(k * n + 1):
            k += 1
        self.ell = ell = k * n + 1
        self.g = g = root_of_unity(n, self.factors, ell)
        self._lifts: dict = {1: g}
        self._cos: dict = {}

    # -- l-adic residue (hashing) --------------------------------------------
    def _lift(self, k: int) -> int:
        t = self._lifts.get(k)
        if t is None:
            mod = self.ell ** k
            t = self._lifts[k] = pow(self.g, self.ell ** (k - 1), mod)
        return t

    def _image(self, terms: dict, k: int) -> tuple[int, int]:
        """``(A(t_k) mod l^k, d)`` with ``terms = A / d`` (cosine form: cos(2 pi e/N) maps to
        (t^e + t^-e)/2, 2 a unit as l is odd), A integral, d a positive integer."""
        d = 1
        for c in terms.values():
            d = d * int(c.q) // gcd(d, int(c.q))
        mod = self.ell ** k
        t = self._lift(k)
        n = self.n
        total = 0
        for e, c in terms.items():
            total += int(c.p) * (d // int(c.q)) * (pow(t, e, mod) + pow(t, n - e, mod))
        return total * pow(2, -1, mod) % mod, d

    def _valuation(self, v: int, k: int) -> int:
        """The l-adic valuation of an integer known modulo l^k, capped at k."""
        if v == 0:
            return k
        out = 0
        while out < k and v % self.ell == 0:
            v //= self.ell
            out += 1
        return out

    def rho(self, terms: dict) -> int:
        """The image of the cosine form modulo l, or -1 when a denominator is divisible by l."""
        ell, g, n = self.ell, self.g, self.n
        total = 0
        for e, c in terms.items():
            q = int(c.q)
            if q % ell == 0:
                return -1
            total += int(c.p) * pow(q, -1, ell) * (pow(g, e, ell) + pow(g, n - e, ell))
        return total * pow(2, -1, ell) % ell

    def residue(self, num: dict, den: dict | None) -> int:
        """The residue in F_l of num/den under the embedding, or -1 when it has a pole."""
        ell = self.ell
        k = 1
        while True:
            mod = ell ** k
            a, da = self._image(num, k)
            b, db = self._image(den, k) if den is not None else (1, 1)
            u, w = a * db % mod, b * da % mod        # x = u / w
            vw = self._valuation(w, k)
            if vw < k:
                vu = self._valuation(u, k)
                if vu > vw:
                    return 0
                if vu < vw:
                    return -1
                scale = ell ** vu
                return (u // scale) * pow(w // scale, -1, ell) % ell
            k *= 2

    # -- numerics -------------------------------------------------------------
    def cos_ball(self, e: int, prec: int) -> arb:
        """A proven ball around cos(2 pi e / N) (working precision ``prec`` set by the caller)."""
        key = (min(e, self.n - e), prec)
        ball = self._cos.get(key)
        if ball is None:
            if len(self._cos) >= _COS_CACHE_LIMIT:
                self._cos.clear()
            ball = self._cos[key] = arb.cos_pi_fmpq(fmpq(2 * key[0], self.n))
        return ball

    def ball(self, terms: dict, prec: int) -> arb:
        """A proven ball around ``sum c cos(2 pi e/N)``."""
        with ctx.workprec(prec + 16):
            total = arb(0)
            for e, c in terms.items():
                total += self.cos_ball(e, prec) * arb(c)
            return total

    # -- traces ---------------------------------------------------------------
    def mean_trace(self, terms: dict) -> fmpq:
        """Tr(x) / phi(N) for x in cosine form (or roots of unity): for a rational x, x
        itself.  Tr zeta_N^e = mu(d) phi(N) / phi(d) with d = N / gcd(e, N) the order of
        zeta_N^e, and Tr cos(2 pi e/N) = Tr zeta_N^e (zeta^-e has the same order)."""
        total = fmpq(0)
        for e, c in terms.items():
            d = self.n // gcd(e, self.n)
            mu, ph = _mu_phi(d, self.factors)
            if mu:
                total += c * fmpq(mu, ph)
        return total

    def __repr__(self):
        return f"SparseContext(N={self.n})"


def _mu_phi(d: int, primes) -> tuple[int, int]:
    """Moebius mu(d) and Euler phi(d) for a divisor d of N, from the primes of N (a divisor
    of N with two primes of 25 digits took 0.3 s to factor again, per trace)."""
    mu, ph = 1, 1
    for p in primes:
        if d % p:
            continue
        a = 0
        while d % p == 0:
            d //= p
            a += 1
        mu = 0 if a > 1 else -mu
        ph *= (p - 1) * p ** (a - 1)
    return mu, ph


_CONTEXTS: dict = {}


def sparse_context(n: int) -> SparseContext:
    """The one context of conductor n (elements of one context mix by identity)."""
    found = _CONTEXTS.get(n)
    if found is None:
        if len(_CONTEXTS) > 64:
            _CONTEXTS.clear()
        found = _CONTEXTS[n] = SparseContext(n)
    return found


__all__ = ["SparseContext", "sparse_context"]
