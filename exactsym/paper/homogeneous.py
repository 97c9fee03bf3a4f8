"""Short exact texts for a cyclotomic field of degree thousands, and for a tower of
square roots over one or over the sparse Q(zeta_N): numbers written as quotients of
numbers with small coefficients.

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

In a tower over the sparse Q(zeta_N) even the product of two homogeneous directions, or
a square, costs a tenth of a second or more: there the texts write the products out,
``((a0)*(b1) + (a1)*(b0))/((a0)*(b0) - (a1)*(b1))`` and ``((u)^2 + (v)^2)/((D)^2)``
(:func:`_expanded`).  A rational centre is written as itself (:func:`is_short`).

The configuration syntax reads a quotient back as the same number (it divides exactly),
so these texts are exact; they are only *written* this way, every computation uses the
numbers as they are.  :func:`register` records the homogeneous form of a direction
vector when the paper layer makes it (:func:`homogeneous_of` finds it by the vector
object: an entry keeps the vector alive, so an id is never mistaken for another's).
The record is a table of the analysis's context
(:class:`~exactsym.exact.context.AnalysisContext`): the vectors are
megabytes each, and it holds one configuration's, which the report of that analysis
still reads.  Outside an analysis nothing is recorded: the texts are the usual ones.
"""

from __future__ import annotations

from ..exact import number_text
from ..exact.level_radius import level_form
from ..exact.number import cheap_products, short_texts
from ..exact.ratio import rational_ratio
from ..exact.context import Cache

__all__ = ["register", "homogeneous_of", "scaled", "quotient_text",
           "centre_texts", "is_short", "is_short_field", "radius_text", "sec_radius_text",
           "line_direction", "slope_text", "homogeneous_pair"]

# id(vector) -> [vector, homogeneous vector or None, function making it]: made when a text
# first asks (the summary writes few lines: no product per robot on the hot path)
_FORMS = Cache("homogeneous forms")
_LIMIT = 1 << 14
# id(homogeneous centre) -> [centre, whether its texts are short] (:func:`is_short`)
_SHORT = Cache("short centres")


def is_short_field(d) -> bool:
    """Whether ``d``'s field gets the short texts (:func:`exactsym.exact.number.short_texts`):
    a dense field of degree >= ``LARGE_DEGREE``, or a tower of square roots over such a field or over the sparse
    Q(zeta_N) (there a divided coordinate is a quotient of sparse sums per tower
    coefficient: the SEC centre of 31 robots at radii sqrt(k) and turns j/997 wrote 5,000
    characters, its homogeneous X, Y, D a few hundred).  In the sparse Q(zeta_N) itself a
    number is held as such a quotient anyway: the usual texts."""
    return short_texts(d)


def is_short(homogeneous) -> bool:
    """Whether the texts about the centre C = (X/D, Y/D) of ``homogeneous`` = (X, Y, D)
    are written from it: D of a short field (:func:`is_short_field`) and C not rational
    (a rational C is short divided: a centre (1, 1/3) stays "1", "1/3"; decided without
    dividing, :func:`~exactsym.paper.ratio_keys.rational_ratio`).  Decided once per
    centre."""
    known = _SHORT.table()
    hit = known.get(id(homogeneous))
    if hit is not None and hit[0] is homogeneous:
        return hit[1]
    x, y, d = homogeneous
    short = is_short_field(d) and (rational_ratio(x, d) is None or
                                   rational_ratio(y, d) is None)
    if len(known) >= _LIMIT:
        known.clear()
    known[id(homogeneous)] = [homogeneous, short]
    return short


def register(vector, point, homogeneous) -> None:
    """Record ``D p - (X, Y)`` as the homogeneous form of ``vector == p - C``."""
    if is_short(homogeneous):
        x, y, d = homogeneous
        _record(vector, lambda: (d * point[0] - x, d * point[1] - y))


def scaled(vector, source, k) -> None:
    """``vector == k * source`` for a positive rational k: record its homogeneous form."""
    hit = _FORMS.table().get(id(source))
    if hit is not None and hit[0] is source:
        def make():
            found = homogeneous_of(source)
            return None if found is None else (found[0] * k, found[1] * k)
        _record(vector, make)


def _record(vector, make) -> None:
    forms = _FORMS.table()
    if len(forms) >= _LIMIT:
        forms.clear()
    forms[id(vector)] = [vector, None, make]


def homogeneous_of(vector):
    """The homogeneous form of ``vector`` (a positive multiple of it), or None."""
    hit = _FORMS.table().get(id(vector))
    if hit is None or hit[0] is not vector:
        return None
    if hit[1] is None and hit[2] is not None:
        hit[1], hit[2] = hit[2](), None
    return hit[1]


def quotient_text(num, den) -> str:
    return f"({number_text(num)})/({number_text(den)})"


def centre_texts(circle):
    """``[X/D, Y/D]`` texts of the SEC centre, or None (a small field: the usual texts)."""
    if not is_short(circle.homogeneous):
        return None
    x, y, d = circle.homogeneous
    return [quotient_text(x, d), quotient_text(y, d)]


def _expanded(*numbers) -> bool:
    """Whether a product of short forms is written expanded: in a dense field (a product
    there is fast), not over the sparse Q(zeta_N), where the product of two short forms
    in a tower of square roots costs a tenth of a second to seconds (100 robots at radii
    sqrt(k) and turns j/997 spent 50 s writing lines and radii) and its expanded text is
    longer than the product written out."""
    return cheap_products(numbers)


def _squared_quotient(point, homogeneous, scale=1) -> str:
    x, y, d = homogeneous
    u, v = d * point[0] - x, d * point[1] - y
    if not _expanded(u, v, d):
        total = f"({number_text(u)})^2 + ({number_text(v)})^2"
        if scale != 1:
            total = f"({number_text(scale)})*({total})"
        return f"({total})/(({number_text(d)})^2)"
    total = u * u + v * v
    if scale != 1:
        total = total * scale
    return quotient_text(total, d * d)


def radius_text(r2):
    """The text of a level's squared radius (:class:`~exactsym.exact.level_radius.LevelRadius`,
    which keeps its point and the homogeneous centre) as |D p - (X, Y)|^2 scale / D^2, or
    None."""
    form = level_form(r2)
    if form is None or not is_short(form[1]):
        return None
    return _squared_quotient(*form)


def _forms(factors):
    """The homogeneous forms of a line's two factors (a, b), or None when one is not
    known."""
    if factors is None:
        return None
    a, b = (homogeneous_of(v) for v in factors)
    return None if a is None or b is None else (a, b)


def homogeneous_pair(a, b):
    """The homogeneous forms of the vectors a and b (positive multiples of them: the same
    angles and lines, numbers without the centre's quotients), or None when one is not
    known.  A key of a scale-invariant property (an angle between them, the line of
    their product) made from these equals the key made from a and b: over the sparse
    Q(zeta_N) the family layer's gap and line keys cost minutes for 8 robots at radii
    sqrt(k) made from p - C."""
    return _forms((a, b))


def line_direction(factors):
    """``(X', Y')``, a positive multiple of the doubled direction a b of ``factors``
    (a, b), from their homogeneous forms (the same slope), or None when one is not
    known."""
    forms = _forms(factors)
    if forms is None:
        return None
    a, b = forms
    return a[0] * b[0] - a[1] * b[1], a[0] * b[1] + a[1] * b[0]


def slope_text(factors) -> str | None:
    """The text ``(Y')/(X')`` of the slope of the doubled direction a b of ``factors``
    from their homogeneous forms (:func:`line_direction`), or None when one is not known;
    over the sparse Q(zeta_N) with the products written out, not expanded
    (:func:`_expanded`)."""
    forms = _forms(factors)
    if forms is None:
        return None
    (a0, a1), (b0, b1) = forms
    if _expanded(a0, a1, b0, b1):
        x, y = line_direction(factors)
        return quotient_text(y, x)
    t0, t1, u0, u1 = (f"({number_text(c)})" for c in (a0, a1, b0, b1))
    return f"({t0}*{u1} + {t1}*{u0})/({t0}*{u0} - {t1}*{u1})"


def sec_radius_text(circle, points):
    """The SEC's squared radius as |D t - (X, Y)|^2 / D^2 for a point t on it, or None."""
    if not is_short(circle.homogeneous):
        return None
    t = circle._through if circle._through is not None else points[circle.support[0]]
    return _squared_quotient(t, circle.homogeneous)
