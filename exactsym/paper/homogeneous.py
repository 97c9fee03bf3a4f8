"""Short exact texts for a cyclotomic field of degree thousands: numbers written as
quotients of numbers with small coefficients.

The SEC centre is C = (X/D, Y/D) with X, Y, D of a few bits per coefficient (products of
the support points' coordinates), but C itself, divided, has coefficients of thousands
of digits: a direction p - C, a level's squared radius |p - C|^2 and a line's doubled
direction (a complex product of two directions) are numbers of megabytes, and the
paper layer prints lines in its G, G', trace and witnesses (six robots at turns j/997
wrote 566 MB of JSON).  The same values have short exact forms:

* p - C = (D p - (X, Y)) / D: the homogeneous direction D p - (X, Y), small, has the same
  direction (D > 0); a line's slope Y'/X' of the doubled direction a b is unchanged
  when a and b are scaled by positive numbers, so it is written from the homogeneous
  directions' product;
* |p - C|^2 = |D p - (X, Y)|^2 / D^2, and C = (X/D, Y/D), written as such quotients.

The configuration syntax reads a quotient back as the same number (it divides exactly),
so these texts are exact; they are only *written* this way, every computation uses the
numbers as they are.  :func:`register` records the homogeneous form of a direction
vector when the paper layer makes it (:func:`homogeneous_of` finds it by the vector
object: an entry keeps the vector alive, so an id is never mistaken for another's).
The vectors are megabytes each, so the record holds one configuration's:
:func:`exactsym.analysis.analyse` calls :func:`forget` first (the report, written after
the analysis, still reads them).
"""

from __future__ import annotations

from ..exact import number_text
from ..exact.field import PolyElement

__all__ = ["SHORT_DEGREE", "forget", "register", "homogeneous_of", "scaled", "quotient_text",
           "centre_texts", "radius_text", "sec_radius_text", "line_direction"]

#: fields from this degree get the short texts
SHORT_DEGREE = 512

# id(vector) -> [vector, homogeneous vector or None, function making it]: made when a text
# first asks (the summary writes few lines: no product per robot on the hot path)
_FORMS: dict = {}
_LIMIT = 1 << 14


def forget() -> None:
    """Drop every recorded form (a new configuration is analysed)."""
    _FORMS.clear()


def _huge(d) -> bool:
    return isinstance(d, PolyElement) and d.field.degree >= SHORT_DEGREE


def register(vector, point, homogeneous) -> None:
    """Record ``D p - (X, Y)`` as the homogeneous form of ``vector == p - C``."""
    x, y, d = homogeneous
    if _huge(d):
        _record(vector, lambda: (d * point[0] - x, d * point[1] - y))


def scaled(vector, source, k) -> None:
    """``vector == k * source`` for a positive rational k: record its homogeneous form."""
    hit = _FORMS.get(id(source))
    if hit is not None and hit[0] is source:
        def make():
            found = homogeneous_of(source)
            return None if found is None else (found[0] * k, found[1] * k)
        _record(vector, make)


def _record(vector, make) -> None:
    if len(_FORMS) >= _LIMIT:
        _FORMS.clear()
    _FORMS[id(vector)] = [vector, None, make]


def homogeneous_of(vector):
    """The homogeneous form of ``vector`` (a positive multiple of it), or None."""
    hit = _FORMS.get(id(vector))
    if hit is None or hit[0] is not vector:
        return None
    if hit[1] is None and hit[2] is not None:
        hit[1], hit[2] = hit[2](), None
    return hit[1]


def quotient_text(num, den) -> str:
    return f"({number_text(num)})/({number_text(den)})"


def centre_texts(circle):
    """``[X/D, Y/D]`` texts of the SEC centre, or None (a small field: the usual texts)."""
    x, y, d = circle.homogeneous
    if not _huge(d):
        return None
    return [quotient_text(x, d), quotient_text(y, d)]


def _squared_quotient(point, homogeneous, scale=1) -> str:
    x, y, d = homogeneous
    u, v = d * point[0] - x, d * point[1] - y
    total = u * u + v * v
    if scale != 1:
        total = total * scale
    return quotient_text(total, d * d)


def radius_text(r2):
    """The text of a level's squared radius (:class:`~exactsym.level_radius.LevelRadius`,
    which keeps its point and the homogeneous centre) as |D p - (X, Y)|^2 scale / D^2, or
    None."""
    from ..level_radius import LevelRadius
    if not isinstance(r2, LevelRadius) or r2.homogeneous is None \
            or not _huge(r2.homogeneous[2]):
        return None
    return _squared_quotient(r2._p, r2.homogeneous, r2.scale)


def line_direction(factors):
    """``(X', Y')``, a positive multiple of the doubled direction a b of ``factors``
    (a, b), from their homogeneous forms (the same slope), or None when one is not
    known."""
    if factors is None:
        return None
    a, b = (homogeneous_of(v) for v in factors)
    if a is None or b is None:
        return None
    return a[0] * b[0] - a[1] * b[1], a[0] * b[1] + a[1] * b[0]


def sec_radius_text(circle, points):
    """The SEC's squared radius as |D t - (X, Y)|^2 / D^2 for a point t on it, or None."""
    if not _huge(circle.homogeneous[2]):
        return None
    t = circle._through if circle._through is not None else points[circle.support[0]]
    return _squared_quotient(t, circle.homogeneous)
