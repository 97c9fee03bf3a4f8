"""The questions the motion asks about the kind of its numbers.

Every number the gathering simulator computes with is one of: a multiquadratic
:class:`~exactsym.exact.multiquadratic.MQ`; a :class:`~.tower_numbers.TowerNumber` (a
nested radical: a critical instant's one-level tower, or a run's
:class:`~.run_tower.RunTower`); an :class:`~.algebraic_numbers.AlgebraicNumber` (a number
of ``K(alpha)``, alpha a root of a factor that square roots do not express); or an
:class:`~.algebraic_tower.AlgebraicTowerNumber` (a quadratic level over ``K(alpha)``).
Each meets the number layer's one interface, :class:`~exactsym.exact.number.ExactNumber`
(field arithmetic, ``sign`` (exact), ``enclosure`` (a rigorous Arb ball: filters and
drawing only), ``is_zero``, ``is_rational``, ``to_fmpq``, ``text``).  Code above ``exact/``
calls those and the functions below; it asks no ``isinstance`` of a concrete class
(sympy's ``Domain``, CGAL's kernel concept).
"""

from __future__ import annotations

from fractions import Fraction

from flint import fmpq

from ..multiquadratic import MQ, sum_of_products
from ..number import ExactNumber
from ..tower import TowerElement
from .algebraic_numbers import AlgebraicNumber, algebraic_two_products
from .algebraic_tower import AlgebraicTower
from .run_tower import RunTower

__all__ = ["ExactNumber", "compare", "is_multiquadratic", "algebraic_root_of", "is_field_number", "motion_number", "nested_tower",
           "is_run_tower", "products_are_large", "two_products", "float_and_error"]

#: products of MQ numbers with at least this many pairs of terms are summed over integers
FUSED_TERMS = 16


def compare(x, y) -> int:
    """-1, 0 or 1 as ``x < y``, ``x == y``, ``x > y``: the exact sign of the difference."""
    return (x - y).sign()


def is_multiquadratic(x) -> bool:
    """Is ``x`` a multiquadratic number (no tower, no ``K(alpha)``)?"""
    return isinstance(x, MQ)


def is_field_number(x) -> bool:
    """Is ``x`` a number of K(alpha) (polynomial coefficients reduced modulo alpha's
    factor: costlier products than an MQ's, worth remembering)?"""
    return type(x) is AlgebraicNumber


def algebraic_root_of(x):
    """The root alpha whose field ``K(alpha)`` holds ``x`` (a number of K(alpha), or of a
    quadratic level over it), or None (an MQ, a tower number of nested radicals)."""
    if isinstance(x, AlgebraicNumber):
        return x.root
    if isinstance(x, TowerElement) and isinstance(x.tower, AlgebraicTower):
        return x.tower.root
    return None


def motion_number(x):
    """``x`` as a number of the motion: a rational (``fmpq``, ``int``: what the checker's
    geometry returns for a rational centre) as an MQ, any other number as it is."""
    return MQ.coerce(x) if isinstance(x, (int, fmpq, Fraction)) else x


def nested_tower(x):
    """The tower of nested radicals ``x`` lives in (a critical instant's own tower or a
    run's), or None: an MQ, or a number over ``K(alpha)`` (those come only from fresh
    Looks at an instant, are compared there and never moved along: not re-homed)."""
    if isinstance(x, TowerElement) and not isinstance(x.tower, AlgebraicTower):
        return x.tower
    return None


def is_run_tower(tower) -> bool:
    """Is ``tower`` a run's :class:`~.run_tower.RunTower` (not an instant's own tower)?"""
    return isinstance(tower, RunTower)


def products_are_large(a, b, c, d) -> bool:
    """Are ``a b`` and ``c d`` MQ products big enough to sum over integers first
    (:func:`~exactsym.exact.multiquadratic.sum_of_products`: the same element, one gcd
    per term of the sum instead of one per term of each product and of the sum)?"""
    ta = getattr(a, "terms", None)         # MQ's dictionary (a tower number has none)
    if ta is None or len(ta) < 2 and len(c.terms if type(c) is MQ else ()) < 2:
        return False
    return (type(a) is MQ and type(b) is MQ and type(c) is MQ and type(d) is MQ
            and len(ta) * len(b.terms) + len(c.terms) * len(d.terms) >= FUSED_TERMS)


def two_products(a, b, c, d, sign: int):
    """``a b + c d`` (``sign`` 1) or ``a b - c d`` (``sign`` -1), exactly: large MQ
    products summed at once (:func:`products_are_large`)."""
    if products_are_large(a, b, c, d):
        return sum_of_products(((1, a, b), (sign, c, d)))
    if type(a) is AlgebraicNumber or type(c) is AlgebraicNumber:
        fused = algebraic_two_products(a, b, c, d, sign)
        if fused is not None:
            return fused
    return a * b + c * d if sign > 0 else a * b - c * d


def float_and_error(x) -> tuple:
    """``(v, e)``: a double ``v`` and a proven bound ``e`` on ``|v - x|`` (a filter's
    input: it never decides alone).  An MQ ``c_1 sqrt(m_1) + ... + c_k sqrt(m_k)``
    evaluated in doubles is within ``(k + 6) 2^-52 S`` of its value, ``S`` the sum of the
    terms' magnitudes (the bound of ``multiquadratic._float_sign``), doubled; any other
    number: its Arb ball's centre, within the ball's radius plus the centre's rounding."""
    terms = getattr(x, "terms", None)
    if terms is None:
        ball = x.enclosure(64)
        mid = float(ball.mid())
        return mid, 2 * (float(ball.rad()) + 2.0 ** -52 * abs(mid)) + 1e-300
    vals = [float(c) * float(m) ** 0.5 for m, c in terms.items()]
    s = sum(abs(v) for v in vals)
    return sum(vals), 2 * (len(vals) + 6) * 2.0 ** -52 * s
