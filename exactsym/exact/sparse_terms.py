"""Sums of roots of unity and of cosines as dictionaries: the exact zero test and arithmetic
of :mod:`.sparse_cyclotomic` (its docstring gives the reasons).

A sum of roots of unity is ``{e mod n: c}`` = sum c zeta_n^e; a cosine form is ``{e: c}`` =
sum c cos(2 pi e/n) with 0 <= e <= n/2 (the real numbers of Q(zeta_n)).  Coefficients are
rationals (``fmpq``), zeros dropped.

Public names: :func:`is_zero_sum`, :func:`roots_zero`, :func:`cosines_zero`, :func:`to_roots`,
:func:`real_part`, :func:`add_terms`, :func:`mul_cosines`, :func:`mul_roots`,
:func:`scale_terms`, :func:`rational_terms`.
"""

from __future__ import annotations

from functools import lru_cache

from flint import fmpq, fmpq_poly, fmpz

from .factor import factorization


# ---------------------------------------------------------------- the exact zero test
@lru_cache(maxsize=4096)
def _peel_order(n: int) -> tuple:
    """``((p, a), ...)``: the order in which primes are peeled off ``n``: squares first (no
    group subtraction there), then single primes from the largest (fewer residues occur)."""
    f = factorization(n) if n > 1 else {}
    return tuple(sorted(f.items(), key=lambda pa: (pa[1] == 1, -pa[0])))


@lru_cache(maxsize=4096)
def _idempotent(n: int, p: int, a: int) -> int:
    """E with E = 1 mod p^a and E = 0 mod n / p^a."""
    q = p ** a
    m = n // q
    return (m * pow(m, -1, q)) % n if m > 1 else 1 % n


def _split(terms: dict, n: int, p: int, a: int) -> dict:
    """``{i: {f: c}}``: x = sum_i w^i beta_i with beta_i = sum c zeta_(n/p)^f (zeros dropped)."""
    e1 = _idempotent(n, p, a)
    groups: dict = {}
    for e, c in terms.items():
        i = e % p
        f = ((e - i * e1) % n) // p
        g = groups.get(i)
        if g is None:
            groups[i] = {f: c}
        else:
            v = g.get(f)
            if v is None:
                g[f] = c
            else:
                v = v + c
                if v == 0:
                    del g[f]
                else:
                    g[f] = v
    return groups


def is_zero_sum(terms: dict, n: int) -> bool:
    """Whether ``sum c * zeta_n^e`` over ``terms = {e: c}`` (e mod n, c rational) is zero."""
    terms = {e: c for e, c in terms.items() if c != 0}
    return roots_zero(terms, n)


def roots_zero(terms: dict, n: int) -> bool:
    if not terms:
        return True
    if len(terms) == 1:
        return False          # c zeta^e with c != 0
    if n == 1:
        return sum(terms.values()) == 0
    p, a = _peel_order(n)[0]
    groups = _split(terms, n, p, a)
    m = n // p
    if a >= 2 or len(groups) < p:
        return all(roots_zero(g, m) for g in groups.values())
    base = groups[0]
    for i in range(1, p):
        diff = dict(groups[i])
        for f, c in base.items():
            v = diff.get(f, 0) - c
            if v == 0:
                diff.pop(f, None)
            else:
                diff[f] = v
        if not roots_zero(diff, m):
            return False
    return True


def to_roots(terms: dict, n: int) -> dict:
    """The cosine form {e: c} = sum c cos(2 pi e/n) as roots of unity: c/2 (z^e + z^-e)."""
    out: dict = {}
    for e, c in terms.items():
        if e == 0 or 2 * e == n:
            out[e] = out.get(e, 0) + c
        else:
            h = c / 2
            out[e] = out.get(e, 0) + h
            out[n - e] = out.get(n - e, 0) + h
    return {e: c for e, c in out.items() if c != 0}


def real_part(terms: dict, n: int) -> dict:
    """The cosine form of the real part of sum c z^e: the number itself when it is real."""
    out: dict = {}
    for e, c in terms.items():
        e %= n
        k = min(e, n - e)
        out[k] = out.get(k, 0) + c
    return {e: c for e, c in out.items() if c != 0}


def cosines_zero(terms: dict, n: int) -> bool:
    """Whether the cosine form {e: c} is zero."""
    if not terms:
        return True
    if len(terms) == 1:           # c cos(2 pi e/n), 0 <= e <= n/2: zero iff e/n = 1/4
        (e,) = terms
        return 4 * e == n
    return roots_zero(to_roots(terms, n), n)


# ---------------------------------------------------------------- sparse dictionaries
def add_terms(a: dict, b: dict, sign: int = 1) -> dict:
    out = dict(a)
    for e, c in b.items():
        v = out.get(e)
        if v is None:
            out[e] = c if sign > 0 else -c
        else:
            v = v + c if sign > 0 else v - c
            if v == 0:
                del out[e]
            else:
                out[e] = v
    return out


def mul_cosines(a: dict, b: dict, n: int) -> dict:
    """The product of two cosine forms: cos e cos f = (cos(e + f) + cos(e - f))/2, with
    0 <= e, f <= n/2, so e + f <= n (its representative min(e + f, n - e - f)) and
    |e - f| <= n/2.  Long forms of a moderate conductor are multiplied as one product of
    dense polynomials (:func:`_mul_cosines_dense`), short ones or those of a huge conductor
    term by term."""
    if len(a) < len(b):
        a, b = b, a
    pairs = len(a) * len(b)
    if pairs >= _DENSE_MIN_PAIRS and n <= _DENSE_MAX_N and pairs * _DENSE_PAIR_COST >= n and \
            _one_denominator(a) and _one_denominator(b):
        return _mul_cosines_dense(a, b, n)
    out: dict = {}
    get = out.get
    half = fmpq(1, 2)
    for f, d in b.items():
        if f == 0:
            for e, c in a.items():
                v = get(e)
                out[e] = c * d if v is None else v + c * d
            continue
        dh = d * half
        for e, c in a.items():
            v = c * dh
            t = e + f
            if t + t > n:
                t = n - t
            w = get(t)
            out[t] = v if w is None else w + v
            t = e - f if e >= f else f - e
            w = get(t)
            out[t] = v if w is None else w + v
    return {e: c for e, c in out.items() if c != 0}


#: the dense product pays from this many coefficient pairs on, and when the pairs times
#: this factor reach the conductor (the palindromes have n + 1 entries; measured at N =
#: 1404, 3988, 27720 with forms of 16 to 256 terms over one denominator: at pairs = n/2
#: the dense product is 1.4 times slower than the loop with 200-bit numerators, at
#: pairs = n about as fast, beyond faster, 40 times at N = 1404 and 256 terms)
_DENSE_MIN_PAIRS = 64
_DENSE_PAIR_COST = 1
#: no dense list beyond this conductor (a sparse Q(zeta_N) with N near 10^14 has cosine
#: forms of a few terms)
_DENSE_MAX_N = 1 << 22


def _one_denominator(form: dict) -> bool:
    """Whether the coefficients' least common denominator is about their largest one (a
    dense fmpq_poly holds its numerators over that common denominator: coefficients of
    distinct 100-bit denominators made the dense product ten times slower than the loop;
    the paper layer's forms share one denominator)."""
    den = top = _ONE
    for c in form.values():
        q = c.q
        if q != 1:
            den = den * q // den.gcd(q)
            if q > top:
                top = q
    return den.bit_length() <= top.bit_length() + _DENOMINATOR_SLACK


_ONE = fmpz(1)
_DENOMINATOR_SLACK = 16


def _mul_cosines_dense(a: dict, b: dict, n: int) -> dict:
    """:func:`mul_cosines` as one product of dense polynomials (flint's compiled
    arithmetic).  With h = floor(n/2), the form sum a_e cos(2 pi e/n) is written as the
    palindrome V_a = sum a_e (x^(h+e) + x^(h-e)), x^h times twice its Laurent polynomial in
    x = zeta_n, so V = V_a V_b = 4 x^(2h) L_a L_b is a palindrome of degree 4h whose
    coefficients V_(2h+t), 0 <= t <= 2h, are 4 r_0 and 2 r_t (t > 0) for the product
    sum r_t cos(2 pi t/n).  A t > n/2 stands for n - t =: t' < n/2; by the palindrome
    V_(2h+t) = V_(2h-t) = V_(t'-(n-2h)), the low end: index t' for n even, t' - 1 for n
    odd.  So the product's coefficients 0..h are
    (V >> 2h)/2 - V_(2h)/4 + (V mod x^h, times x for n odd)/2."""
    h = n // 2
    v = _palindrome(a, h) * _palindrome(b, h)
    fold = v.truncate(h)
    if n % 2:
        fold = fold.left_shift(1)
    total = (v.right_shift(2 * h).truncate(h + 1) + fold) * _HALF - v[2 * h] * _QUARTER
    return {e: c for e, c in enumerate(total.coeffs()) if c}


def _palindrome(a: dict, h: int) -> fmpq_poly:
    """sum a_e (x^(h+e) + x^(h-e)) for the cosine form {e: a_e}, 0 <= e <= h."""
    dense = [0] * (2 * h + 1)
    for e, c in a.items():
        if e:
            dense[h + e] = dense[h - e] = c
        else:
            dense[h] = c + c
    return fmpq_poly(dense)


_HALF = fmpq(1, 2)
_QUARTER = fmpq(1, 4)


def mul_roots(a: dict, b: dict, n: int) -> dict:
    """The product of two sums of roots of unity (exponents mod n)."""
    if len(a) < len(b):
        a, b = b, a
    out: dict = {}
    for e2, c2 in b.items():
        for e1, c1 in a.items():
            e = e1 + e2
            if e >= n:
                e -= n
            v = out.get(e)
            out[e] = c1 * c2 if v is None else v + c1 * c2
    return {e: c for e, c in out.items() if c != 0}


def scale_terms(a: dict, q: fmpq) -> dict:
    return {e: c * q for e, c in a.items()} if q != 0 else {}


def rational_terms(q: fmpq) -> dict:
    return {0: q} if q != 0 else {}


__all__ = ["is_zero_sum", "roots_zero", "cosines_zero", "to_roots", "real_part",
           "add_terms", "mul_cosines", "mul_roots", "scale_terms", "rational_terms"]
