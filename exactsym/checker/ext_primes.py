"""Checker extension: proofs that large integers are prime (standard library only), for the
sparse Q(zeta_N): deterministic Miller-Rabin below 3.3 * 10^24, and above it the certificate's
Pocklington (Brillhart-Lehmer-Selfridge) and elliptic-curve (Goldwasser-Kilian, Atkin-Morain)
proofs.
"""

from __future__ import annotations

from math import gcd, isqrt

from .numbers import integer, need

_MR_BASES = (2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41)
MR_LIMIT = 3317044064679887385961981      # the bases above decide primality below this


def is_prime(n: int, proved: frozenset = frozenset()) -> bool:
    """Deterministic Miller-Rabin below MR_LIMIT; a larger n must be among the primes
    ``proved`` by the certificate's primality proofs (:func:`proved_primes`)."""
    if n >= MR_LIMIT:
        need(n in proved, f"cannot prove {n} prime (above the deterministic test's range, "
             "and the certificate has no primality proof of it)")
        return True
    if n < 2:
        return False
    for p in _MR_BASES:
        if n % p == 0:
            return n == p
    d, s = n - 1, 0
    while d % 2 == 0:
        d, s = d // 2, s + 1
    for a in _MR_BASES:
        x = pow(a, d, n)
        if x in (1, n - 1):
            continue
        for _ in range(s - 1):
            x = x * x % n
            if x == n - 1:
                break
        else:
            return False
    return True


def proved_primes(proofs) -> frozenset:
    """The primes proved by ``[{"prime": p, "witness": a, "factors": [[q, e], ...]}, ...]``
    (:func:`_pocklington`) or ``{"prime": p, "curve": [a, b], "point": [x, y], "order": q}``
    (:func:`_elliptic`), taken in increasing order: a factor q of p - 1, or the order q of
    the point, is below p, so a q at or above MR_LIMIT has been proved before it is used."""
    need(isinstance(proofs, list), "sparse-cyclotomic: primality is a list of proofs")
    entries = []
    for item in proofs:
        need(isinstance(item, dict) and "prime" in item, "sparse-cyclotomic: a primality "
             "proof is {prime, witness, factors} or {prime, curve, point, order}")
        p = integer(str(item["prime"]))
        if "curve" in item:
            need(all(isinstance(item.get(k), list) and len(item[k]) == 2
                     for k in ("curve", "point")) and "order" in item,
                 "sparse-cyclotomic: an elliptic primality proof is {prime, curve: [a, b], "
                 "point: [x, y], order}")
            entries.append((p, "curve", ([integer(str(v)) for v in item["curve"]],
                                         [integer(str(v)) for v in item["point"]],
                                         integer(str(item["order"])))))
            continue
        need(isinstance(item.get("factors"), list) and
             all(isinstance(f, list) and len(f) == 2 for f in item["factors"]),
             "sparse-cyclotomic: a primality proof is {prime, witness, factors: [[q, e], ...]}")
        entries.append((p, "factors", (integer(str(item["witness"])),
                                       [(integer(str(q)), integer(str(e)))
                                        for q, e in item["factors"]])))
    proved: set = set()
    for p, kind, data in sorted(entries, key=lambda entry: entry[0]):
        if kind == "curve":
            _elliptic(p, *data, proved)
        else:
            _pocklington(p, *data, proved)
        proved.add(p)
    return frozenset(proved)


def _elliptic(p: int, curve: list, point: list, q: int, proved: set) -> None:
    """Raises Invalid unless p is prime.  E: y^2 = x^3 + a x + b with 4 a^3 + 27 b^2 prime
    to p, gcd(p, 6) = 1, P = (x, y) on E, q a proved prime above (p^(1/4) + 1)^2, and
    (q - 1) P = -P computed with affine formulas whose every denominator is a unit mod p.
    Then for every prime r | p (r >= 5) E mod r is an elliptic curve, each step of the
    computation is its group law mod r (a unit denominator stays one), so q P = O and
    P != O mod r: P has order q, and by Hasse q <= #E(F_r) <= (sqrt(r) + 1)^2.  A
    composite p has such an r <= sqrt(p), whence q <= (p^(1/4) + 1)^2: so p is prime
    (Goldwasser and Kilian 1986; the certificates of Atkin and Morain 1993)."""
    why = f"sparse-cyclotomic: the elliptic primality proof of {p}"
    a, b = curve[0] % p, curve[1] % p
    x, y = point[0] % p, point[1] % p
    need(p > 3 and gcd(p, 6) == 1, f"{why}: p must be prime to 6")
    need(gcd(4 * a ** 3 + 27 * b ** 2, p) == 1, f"{why}: the curve is singular modulo a "
         "factor of p")
    need((y * y - x ** 3 - a * x - b) % p == 0, f"{why}: the point is not on the curve")
    need(is_prime(q, proved), f"{why}: the order {q} is not a proved prime")
    r = isqrt(isqrt(p))                         # r^4 <= p < (r + 1)^4
    need(q > (r + 2) ** 2, f"{why}: the order {q} is not above (p^(1/4) + 1)^2")
    k, total = q - 1, (x, y)
    for bit in bin(k)[3:]:
        total = _ec_add(total, total, a, p, why)
        if bit == "1":
            total = _ec_add(total, (x, y), a, p, why)
    need(total == (x, (-y) % p), f"{why}: (q - 1) P is not -P")


def _ec_add(u: tuple, v: tuple, a: int, p: int, why: str) -> tuple:
    """u + v on y^2 = x^3 + a x + b modulo p, affine; Invalid unless the denominator is a
    unit (and u, v are neither opposite nor equal with y = 0 modulo a factor of p)."""
    (x1, y1), (x2, y2) = u, v
    if x1 == x2:
        need(y1 == y2, f"{why}: a sum reached the point at infinity")
        num, den = 3 * x1 * x1 + a, 2 * y1
    else:
        num, den = y2 - y1, x2 - x1
    need(gcd(den % p, p) == 1, f"{why}: a denominator is not a unit")
    slope = num * pow(den, -1, p) % p
    x3 = (slope * slope - x1 - x2) % p
    return x3, (slope * (x1 - x3) - y1) % p


def _pocklington(p: int, a: int, factors: list, proved: set) -> None:
    """Raises Invalid unless p is prime.  F = prod q^e divides p - 1, a^(p-1) = 1 and
    gcd(a^((p-1)/q) - 1, p) = 1 for each q: then for every prime r | p the order of a mod r
    divides p - 1 but no (p - 1)/q, so F | r - 1 (Pocklington).  Hence p is prime when
    F > sqrt(p) (Pratt when F = p - 1), or when F^3 >= p and, with p = c2 F^2 + c1 F + 1
    (0 <= c1 < F), c1^2 - 4 c2 is not a square: a composite p would be (uF + 1)(vF + 1)
    (three factors exceed F^3), c1 = u + v, c2 = uv, c1^2 - 4 c2 = (u - v)^2
    (Brillhart, Lehmer, Selfridge 1975; Crandall-Pomerance, Theorem 4.1.5)."""
    why = f"sparse-cyclotomic: the primality proof of {p}"
    need(p > 2, f"{why}: p must exceed 2")
    f = 1
    for q, e in factors:
        need(e >= 1 and is_prime(q, proved), f"{why}: the factor {q} of p - 1 is not a "
             "proved prime")
        f *= q ** e
    need((p - 1) % f == 0, f"{why}: the listed factors do not divide p - 1")
    need(pow(a, p - 1, p) == 1, f"{why}: the witness {a} has a^(p-1) != 1 mod p")
    for q, _ in factors:
        need(gcd(pow(a, (p - 1) // q, p) - 1, p) == 1,
             f"{why}: the witness {a} fails for the factor {q} (a^((p-1)/q) - 1 not prime to p)")
    if f > isqrt(p):                            # f >= isqrt(p) + 1 > sqrt(p)
        return
    need(f ** 3 >= p, f"{why}: the factored part of p - 1 is below p^(1/3)")
    c2, c1 = divmod((p - 1) // f, f)
    d = c1 * c1 - 4 * c2
    need(d < 0 or isqrt(d) ** 2 != d, f"{why}: c1^2 - 4 c2 is a square (p may be composite)")
