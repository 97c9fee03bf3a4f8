"""Elements of Q(zeta_M) mapped into F_p by two embeddings: exact proofs of irrationality.

For a prime p = 1 (mod M) the cyclotomic polynomial splits modulo p, and each primitive
M-th root of unity w in F_p gives a ring map zeta -> w from the elements whose
coefficients have denominators prime to p onto F_p (the reduction modulo one prime of
Q(zeta_M) above p).  A rational number q (p-integral) has the one image q mod p under
every such map; so two maps that send a number to two different residues prove it is
not rational.  The maps used are zeta -> w and zeta -> w^j with j != +-1 (mod M): complex
conjugation (j = -1) fixes every real number, so it would prove nothing here.

This is exact arithmetic in F_p (no float, no ball): a test of a few microseconds per
element instead of products of degree thousands (issue 9: the paper layer asks whether
x^2 / (x^2 + y^2) is rational for every line it keys).  When the residues agree nothing
is concluded and the caller computes exactly.
"""

from __future__ import annotations

from math import gcd

from flint import fmpq, fmpz, nmod_poly

from .context import Cache
from .factor import factorization, is_prime
from .field import PolyElement
from .modular import sparse_image
from .sparse_cyclotomic import SparseCyclotomic
from .tower import TowerElement, raw as tower_raw

_EMBEDDINGS: dict = {}     # M -> (p, (w1, w2)) or None


def _embeddings(m: int):
    """``(p, (w, w^j))``: a prime p = 1 (mod m) near 2^62 and two primitive m-th roots of
    unity modulo p that are not conjugate (j != +-1 mod m); None when every unit modulo
    m is +-1 (m in 1, 2, 3, 4, 6: Q(zeta_m) has degree <= 2 over Q and its real
    elements are rational)."""
    if m in _EMBEDDINGS:
        return _EMBEDDINGS[m]
    j = next((j for j in range(2, m - 1) if gcd(j, m) == 1), None)
    found = None
    if j is not None:
        k = ((1 << 62) // m) + 1
        while not is_prime(k * m + 1):
            k += 1
        p = k * m + 1
        primes = list(factorization(m))
        g = 2
        while True:
            w = pow(g, (p - 1) // m, p)
            if all(pow(w, m // q, p) != 1 for q in primes):
                break
            g += 1
        found = (p, (w, pow(w, j, p)))
    if len(_EMBEDDINGS) > 16:
        _EMBEDDINGS.clear()
    _EMBEDDINGS[m] = found
    return found


def _conductor(x) -> int | None:
    """1 for a rational, the conductor of a cyclotomic element (dense or sparse), else
    None."""
    if isinstance(x, (int, fmpq, fmpz)):
        return 1
    if isinstance(x, PolyElement):
        return x.field.conductor
    if isinstance(x, SparseCyclotomic):
        return x.ctx.n
    return None


def images(numbers) -> tuple | None:
    """``(p, [images under the first map, images under the second])`` of ``numbers``
    (rationals and elements of cyclotomic fields, embedded in Q(zeta_M) for M the lcm
    of their conductors), or None when that does not apply (another kind of number; M
    without two non-conjugate roots; a denominator divisible by p)."""
    towers = {id(x.tower): x.tower for x in numbers if isinstance(x, TowerElement) and x.kernel}
    if towers:
        # a tower of nested radicals over a multiquadratic base: its own pair of maps
        if len(towers) > 1 or any(isinstance(x, (PolyElement, SparseCyclotomic))
                                  for x in numbers):
            return None
        tower = next(iter(towers.values()))
        from .tower_proof import tower_images
        try:
            raws = [tower_raw(tower, x) for x in numbers]
        except TypeError:
            return None
        return tower_images(tower, raws)
    m = 1
    for x in numbers:
        c = _conductor(x)
        if c is None:
            return None
        m = m // gcd(m, c) * c
    emb = _embeddings(m)
    if emb is None:
        return None
    p, roots = emb
    out = ([], [])
    for x in numbers:
        if isinstance(x, (PolyElement, SparseCyclotomic)):
            pair = _element_images(x, m, p, roots)
            if pair is None:
                return None
            out[0].append(pair[0])
            out[1].append(pair[1])
        else:
            q = fmpq(x) if not isinstance(x, fmpq) else x
            if int(q.q) % p == 0:
                return None
            value = int(q.p) * pow(int(q.q), -1, p) % p
            out[0].append(value)
            out[1].append(value)
    return p, out


#: (id(x), M) -> (x, images): a coordinate enters many tests; a table of the analysis
#: (:mod:`.context`), so an id names its object only while the analysis keeps both
_IMAGES = Cache("cyclotomic images mod p")
_IMAGES_LIMIT = 256


def _element_images(x: PolyElement, m: int, p: int, roots) -> tuple | None:
    """The two images of the cyclotomic element ``x`` (embedded in Q(zeta_m)), or None
    when p divides its denominator; remembered by identity (the entry keeps ``x``
    alive, so its id is not reused while cached)."""
    images = _IMAGES.table()
    key = (id(x), m)
    found = images.get(key)
    if found is not None and found[0] is x:
        return found[1]
    if isinstance(x, SparseCyclotomic):
        pair = _sparse_images(x, m, p, roots)
    elif getattr(x, "made", True) is False:
        # a level's squared radius not computed yet (exactsym.exact.level_radius): its images
        # from those of its point and centre
        pair = x.modular_images(m, p, roots, lambda v: _value_images(v, m, p, roots))
    elif int(x.poly.denom()) % p == 0:
        pair = None
    else:
        inv = pow(int(x.poly.denom()), -1, p)
        poly = nmod_poly(x.poly.numer(), p)
        step = m // x.field.conductor        # zeta_c = zeta_M^(M/c)
        pair = tuple(int(poly(pow(w, step, p))) * inv % p for w in roots)
    if len(images) >= _IMAGES_LIMIT:
        images.clear()
    images[key] = (x, pair)
    return pair


def _value_images(x, m: int, p: int, roots) -> tuple | None:
    """The two images of a rational or a cyclotomic element, or None (a pole)."""
    if isinstance(x, (PolyElement, SparseCyclotomic)):
        return _element_images(x, m, p, roots)
    q = fmpq(x)
    if int(q.q) % p == 0:
        return None
    value = int(q.p) * pow(int(q.q), -1, p) % p
    return value, value


def _sparse_images(x: SparseCyclotomic, m: int, p: int, roots) -> tuple | None:
    """The two images of ``num / den``, each a sum ``sum c cos(2 pi e/N)`` (cosine form,
    :mod:`.sparse_cyclotomic`): cos(2 pi e/N) maps to (u^e + u^-e)/2 with u = w^(M/N);
    None when p divides a coefficient's denominator or the denominator maps to 0."""
    step = m // x.ctx.n
    pair = []
    for w in roots:
        value = sparse_image(x, p, pow(w, step, p))
        if value is None:
            return None
        pair.append(value)
    return tuple(pair)


def ratio_irrational(x, y) -> bool:
    """True only when ``x^2 / (x^2 + y^2)`` is proved irrational (module docstring):
    its images under the two maps differ (both denominators non-zero modulo p).  False
    means "not proved" (the caller decides exactly)."""
    found = images((x, y))
    if found is None:
        return False
    p, sides = found
    return _differ(p, sides)


def quotient_irrational(x, y) -> bool:
    """True only when ``x / y`` is proved irrational: the images of the quotient under the
    two maps differ (y's images non-zero).  False means "not proved"."""
    found = images((x, y))
    if found is None:
        return False
    p, sides = found
    (x1, y1), (x2, y2) = sides
    if y1 == 0 or y2 == 0:
        return False
    return x1 * y2 % p != x2 * y1 % p


def product_ratio_irrational(a, b) -> bool:
    """:func:`ratio_irrational` of (x, y) = a b, the complex product of the vectors a and b
    (x = a_x b_x - a_y b_y, y = a_x b_y + a_y b_x), computed in F_p only: the maps are
    ring maps, so the image of the product is the product of the images."""
    found = images((a[0], a[1], b[0], b[1]))
    if found is None:
        return False
    p, sides = found
    return _differ(p, [((ax * bx - ay * by) % p, (ax * by + ay * bx) % p)
                       for ax, ay, bx, by in sides])


def _differ(p: int, sides) -> bool:
    values = []
    for xj, yj in sides:
        length = (xj * xj + yj * yj) % p
        if length == 0:
            return False
        values.append(xj * xj * pow(length, -1, p) % p)
    return values[0] != values[1]


__all__ = ["images", "product_ratio_irrational", "quotient_irrational", "ratio_irrational"]
