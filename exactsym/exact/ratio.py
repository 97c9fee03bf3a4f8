"""Whether a quotient num/den is rational, and which rational, without a division in the
field (issue 9: in a cyclotomic field of degree thousands an inverse costs 0.1 s to seconds,
:mod:`.inverse`; with coefficients of thousands of digits as much at degree 4).

Public names: :func:`rational_ratio`.
"""

from __future__ import annotations

from flint import fmpq, fmpq_poly

from .cyclotomic_modular import quotient_irrational
from .field import FieldElement, PolyElement
from .level_radius import tower_ratio_irrational
from .sparse_cyclotomic import SparseCyclotomic
from .tower import TowerElement, leaf_ratio, raw as tower_raw


def _poly(x) -> fmpq_poly:
    return x.poly if isinstance(x, PolyElement) else fmpq_poly([x])


def rational_ratio(num, den):
    """``num / den`` as an ``fmpq`` when it is rational, else None, without a division
    in the field: num must be a rational multiple q of den, read off one coefficient
    and checked on all (``den`` a non-zero element of a polynomial field, or rational).
    In a sparse Q(zeta_N) (no coefficients to read) the quotient num/den is held
    undivided and its rationality decided exactly, after the same F_p refutation."""
    if isinstance(num, SparseCyclotomic) or isinstance(den, SparseCyclotomic):
        if quotient_irrational(num, den):
            return None
        q = num / den
        return q.to_fmpq() if q.is_rational() else None
    if isinstance(num, TowerElement) or isinstance(den, TowerElement):
        if tower_ratio_irrational(num, den):     # a level's radius, not made: F_p images
            return None
        tower = num.tower if isinstance(num, TowerElement) else den.tower
        q = leaf_ratio(tower_raw(tower, num), tower_raw(tower, den))
        if q is not NotImplemented:
            return q if q is not None and num == den * q else None
        q = num / den                       # a cyclotomic base: divide
        return q.to_fmpq() if q.is_rational() else None
    if not isinstance(num, PolyElement) and not isinstance(den, PolyElement):
        q = num / den                       # multiquadratic numbers (a tower's level 0)
        return (q.to_fmpq() if q.is_rational() else None) if isinstance(q, FieldElement) \
            else fmpq(q)
    if quotient_irrational(num, den):   # two maps into F_p disagree: microseconds, where
        return None                     # a coefficient of 16,000 bits costs 0.1 ms to read
    n, d = _poly(num), _poly(den)       # (and a level's radius may not be computed yet)
    if n.is_zero():
        return fmpq(0)
    top = d.degree()
    if n.degree() != top:   # num = q den with q != 0 has den's degree
        return None
    i = 0                   # the first non-zero coefficient of d, read by index: the
    while d[i] == 0:        # coefficient lists of degree thousands cost milliseconds
        i += 1
    q = n[i] / d[i]
    if n[top] != q * d[top]:    # two coefficients refute it before a product of all
        return None
    return q if n == q * d else None


__all__ = ["rational_ratio"]
