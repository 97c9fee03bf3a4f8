"""Sums of products with one reduction: in a number field of large degree (Q(zeta_M) of
degree thousands, issue 9) reducing a product modulo the minimal polynomial costs more
than the product itself, and reduction is linear, so ``a b + c d`` reduced once is the
same canonical element as ``a b`` and ``c d`` reduced apart and added.  Elsewhere (small
fields, rationals, multiquadratic numbers) the plain operators are used."""

from __future__ import annotations

from math import gcd

from .field import PolyElement

#: from this degree the products are added before one reduction
FUSE_DEGREE = 64


def _fusable(numbers) -> object | None:
    """The common field of ``numbers`` if they are all elements of one field of degree
    >= FUSE_DEGREE, else None."""
    field = None
    for x in numbers:
        if not isinstance(x, PolyElement):
            return None
        if field is None:
            field = x.field
            if field.degree < FUSE_DEGREE:
                return None
        elif x.field is not field:
            return None
    return field


def product_sum(pairs):
    """``sum(a * b for a, b in pairs)``, exactly (one reduction when fusable)."""
    field = _fusable([v for pair in pairs for v in pair])
    if field is None:
        total = pairs[0][0] * pairs[0][1]
        for a, b in pairs[1:]:
            total = total + a * b
        return total
    return PolyElement(field, field.product_sum(pairs))


def complex_product(a, b) -> tuple:
    """``(a_x b_x - a_y b_y, a_x b_y + a_y b_x)``: three products (Gauss) and, when
    fusable, two reductions (the shared product is reduced inside both sums)."""
    (ax, ay), (bx, by) = a, b
    field = _fusable((ax, ay, bx, by))
    if field is None:
        k = bx * (ax + ay)
        return (k - ay * (bx + by), k + ax * (by - bx))
    arithmetic = field.arithmetic()
    if arithmetic is not None and gcd(arithmetic.s, *(v._prepared(arithmetic)[1]
                                                      for v in (ax, ay, bx, by))) > 1:
        # subfield elements: four products of deflated polynomials cost less than
        # Gauss's three of full degree
        return (PolyElement(field, field.product_sum([(ax, bx), (ay, by, -1)])),
                PolyElement(field, field.product_sum([(ax, by), (ay, bx)])))
    k = bx.poly * (ax.poly + ay.poly)
    x = k - ay.poly * (bx.poly + by.poly)
    y = k + ax.poly * (by.poly - bx.poly)
    return PolyElement(field, field.reduce(x)), PolyElement(field, field.reduce(y))


def cross_is_zero(u, v) -> bool:
    """``u_x v_y - u_y v_x == 0`` (u and v parallel), exactly."""
    return not product_sum([(u[0], v[1]), (-u[1], v[0])])
