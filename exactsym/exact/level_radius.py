"""The squared radius of a level in a cyclotomic field of degree thousands, exact on demand.

A level's squared radius |p - C|^2 about the SEC centre C = (X/D, Y/D) is a number of
megabytes there (C's coefficients have thousands of digits): |p|^2 - 2 p.C + |C|^2 costs
about 20 ms per level, and 100 robots on levels of their own spent 1.9 s of a 4.5 s check
on them (issue 9).  Most readers only compare radii, or ask whether their ratio is
rational.  :class:`LevelRadius` is that exact number, a :class:`PolyElement` whose
polynomial is computed when first read; before that it answers

* balls (:meth:`enclosure`) from the balls of p and C: ``(p_x - c_x)^2 + (p_y - c_y)^2``,
  a sum of squares, so no cancellation;
* its images in F_p (:meth:`modular_images`, for
  :mod:`.cyclotomic_modular`'s proofs of irrationality) from the images of
  p and C: the maps are ring homomorphisms;
* ``==`` with the squared radius of another level of the same levels: distinct levels
  have distinct radii (the levels group the points by exactly equal distance), so two
  level indices decide it; ``<`` and ``sign`` from balls, exact only when balls touch;
* a product by a rational (the audit's scaled frame) stays lazy.

Anything else (arithmetic, hashing, text, ``==`` with another number) reads the exact
polynomial, which is then computed once, so a reader never sees anything but the exact
number.
"""

from __future__ import annotations

from flint import arb, ctx, fmpq

from .field import FieldElement, PolyElement, sign
from .number import LARGE_DEGREE, enclosure as enclosure_of
from .sparse_tower import SparseKummerTower
from .tower import TowerElement, raw as tower_raw
from .tower_proof import tower_images

__all__ = ["LevelRadius", "TowerLevelRadius", "lazy_level_radius", "level_form",
           "scaled_radius", "tower_ratio_irrational"]


class _LevelIdentity:
    """What a lazy squared radius answers from its level alone: ``==`` with the radius of
    another level of the same levels (``owner``) by their indices (the levels group the
    points by exactly equal distance: distinct levels, distinct radii), ``== 0`` and
    ``sign`` from balls (``enclosure``) while not made.  ``_number`` is the exact class
    whose methods answer everything else."""

    __slots__ = ()

    def _same_levels(self, other) -> bool:
        return isinstance(other, type(self)) and other.owner is self.owner

    def _ball_sign(self):
        """1 when a ball proves the radius positive, else None (not decided)."""
        prec = 64
        while prec <= 1024:
            if self.enclosure(prec) > 0:
                return 1
            prec *= 4
        return None

    def __eq__(self, other):
        if self is other:
            return True
        if self._same_levels(other):
            return self.index == other.index        # distinct levels, distinct radii
        if isinstance(other, (int, fmpq)) and other == 0:
            return self.sign() == 0
        return self._number.__eq__(self, other)

    def __ne__(self, other):
        result = self.__eq__(other)
        return result if result is NotImplemented else not result

    def is_zero(self) -> bool:
        return self.sign() == 0          # a ball proves most radii positive


class LevelRadius(_LevelIdentity, PolyElement):
    """``scale * |p - C|^2`` (``p``, ``centre`` exact points of one cyclotomic field,
    ``make()`` the exact |p - C|^2) for level ``index`` of the levels ``owner``."""

    __slots__ = ("_make", "_exact", "_p", "_c", "scale", "owner", "index", "homogeneous")

    def __init__(self, field, make, p, centre, scale, owner, index: int, homogeneous=None):
        # PolyElement's state, without its polynomial (read through ``poly``)
        self.field = field
        self._hash = self._sign = self._prep = self._ball = None
        self._make, self._exact = make, None
        self._p, self._c, self.scale = p, centre, fmpq(scale)
        self.owner, self.index = owner, index
        self.homogeneous = homogeneous      # (X, Y, D) of the centre: its short text

    @property
    def poly(self):
        if self._exact is None:
            value = self._make()
            self._exact = value.poly if self.scale == 1 else (value * self.scale).poly
            self._make = None
        return self._exact

    @property
    def made(self) -> bool:
        """Whether the exact polynomial has been computed."""
        return self._exact is not None

    def scaled(self, k, owner, index: int) -> "LevelRadius":
        """``k`` times this squared radius (``k`` rational), as level ``index`` of
        ``owner``, lazily."""
        make = self._make
        if make is None:                  # made: |p - C|^2 is the value over the scale
            exact, field, scale = self._exact, self.field, self.scale

            def make():
                return PolyElement(field, exact) * (1 / scale)
        return LevelRadius(self.field, make, self._p, self._c, self.scale * fmpq(k),
                           owner, index, self.homogeneous)

    # -- what is read without the polynomial -------------------------------------
    def enclosure(self, prec: int = 53):
        if self._exact is not None:
            return PolyElement.enclosure(self, prec)
        with ctx.workprec(prec + 16):
            (x, y), (cx, cy) = self._p, self._c
            dx = enclosure_of(x, prec) - enclosure_of(cx, prec)
            dy = enclosure_of(y, prec) - enclosure_of(cy, prec)
            return (dx * dx + dy * dy) * arb(self.scale)

    def modular_images(self, m: int, p: int, roots, images_of):
        """The two images in F_p (``images_of(x)`` the pair of a coordinate's images,
        None when one has a pole), or None."""
        (x, y), (cx, cy) = self._p, self._c
        parts = [images_of(v) for v in (x, y, cx, cy)]
        if any(part is None for part in parts):
            return None
        q = int(self.scale.p) * pow(int(self.scale.q), -1, p) % p \
            if int(self.scale.q) % p else None
        if q is None:
            return None
        return tuple((((ix - icx) ** 2 + (iy - icy) ** 2) * q) % p
                     for ix, iy, icx, icy in zip(*parts))

    _number = PolyElement

    def sign(self) -> int:
        return (self._exact is None and self._ball_sign()) or PolyElement.sign(self)

    __hash__ = PolyElement.__hash__

    def _cmp(self, other):
        if self is other:
            return 0
        if self._same_levels(other) and self.index == other.index:
            return 0
        if isinstance(other, (PolyElement, int, fmpq)):
            prec = 64
            while prec <= 1024:
                a = self.enclosure(prec)
                b = other.enclosure(prec) if isinstance(other, PolyElement) else \
                    arb(fmpq(other))
                if a < b:
                    return -1
                if a > b:
                    return 1
                prec *= 4
        return PolyElement._cmp(self, other)

    def __repr__(self):
        state = "made" if self._exact is not None else "not made"
        return f"LevelRadius(level {self.index}, {state})"



class TowerLevelRadius(_LevelIdentity, TowerElement):
    """The squared radius |p - C|^2 of level ``index`` of the levels ``owner`` in a tower of
    square roots over the sparse Q(zeta_N), computed (``make()``) when first read exactly.

    There the product p.C alone cost seconds: C = (X/D, Y/D) has the tower's inverse of D
    in it (three robots at radii sqrt(k) and turns j/997 ran past 90 s, most of it on the
    radii of the paper's moved configurations).  Before it is made it answers, as
    :class:`LevelRadius` does: balls from those of p and of C's homogeneous form; ``==``
    and ``<`` with another level of the same levels by their indices (the levels are
    sorted by radius, nearest first, and distinct levels have distinct radii); ``sign``
    from balls.  Anything else
    reads the exact number (``v``), then computed once."""

    __slots__ = ("_make", "_value", "_exact", "_p", "_c", "owner", "index")

    def __init__(self, tower, make, p, homogeneous, owner, index: int):
        self.tower, self._hash = tower, None
        self._make, self._value, self._exact = make, None, None
        self._p, self._c = p, homogeneous       # the centre (X/D, Y/D): not divided
        self.owner, self.index = owner, index

    def value(self):
        """The exact number (a :class:`TowerElement`, or a rational / base number when
        the radius happens to lie below the levels), computed once."""
        if self._make is not None:
            self._value, self._make = self._make(), None
        return self._value

    @property
    def v(self):
        if self._exact is None:
            self._exact = tower_raw(self.tower, self.value())
        return self._exact

    @property
    def made(self) -> bool:
        return self._make is None

    def is_rational(self) -> bool:
        value = self.value()
        return value.is_rational() if isinstance(value, FieldElement) else True

    def to_fmpq(self):
        value = self.value()
        return value.to_fmpq() if isinstance(value, FieldElement) else fmpq(value)

    def enclosure(self, prec: int = 53):
        if self.made:
            return enclosure_of(self.value(), prec)
        with ctx.workprec(prec + 16):
            (x, y), (cx, cy, d) = self._p, self._c
            d = enclosure_of(d, prec)
            dx = enclosure_of(x, prec) - enclosure_of(cx, prec) / d
            dy = enclosure_of(y, prec) - enclosure_of(cy, prec) / d
            return dx * dx + dy * dy

    _number = TowerElement

    def __neg__(self):          # the exact number's negative (not a level's radius)
        return -TowerElement(self.tower, self.v)

    def sign(self) -> int:
        return (not self.made and self._ball_sign()) or sign(self.value())

    __hash__ = TowerElement.__hash__

    def _cmp(self, other):
        if self._same_levels(other):                # nearest first
            return (self.index > other.index) - (self.index < other.index)
        return TowerElement._cmp(self, other)

    def __repr__(self):
        state = "made" if self.made else "not made"
        return f"TowerLevelRadius(level {self.index}, {state})"


def tower_ratio_irrational(num, den) -> bool:
    """Whether ``num / den`` is proved irrational, when one of them is a
    :class:`TowerLevelRadius` not made yet (else False: the caller decides), by two ring
    maps of its tower into F_p (:func:`~exactsym.exact.tower_proof.tower_images`) under
    which the quotient has two images: a rational has one.  A radius' image is read from
    those of its point and of the centre's homogeneous form, |D p - (X, Y)|^2 / D^2, so
    no exact radius is made (a radial projection asks whether two levels' radii have a
    rational ratio; in a tower over the sparse Q(zeta_3988) an exact radius costs
    seconds).  Images with a zero denominator prove nothing: False."""
    lazy = [z for z in (num, den) if isinstance(z, TowerLevelRadius) and not z.made]
    if not lazy:
        return False
    tower = lazy[0].tower
    raws, parts = [], []
    try:
        for z in (num, den):
            parts.append(len(raws))
            if isinstance(z, TowerLevelRadius) and not z.made:
                (x, y), (cx, cy, d) = z._p, z._c
                raws += [tower_raw(tower, v) for v in (x, y, cx, cy, d)]
                parts[-1] = (parts[-1], True)
            else:
                raws.append(tower_raw(tower, z))
                parts[-1] = (parts[-1], False)
    except TypeError:                   # two towers: nothing to compare here
        return False
    found = tower_images(tower, raws)
    if found is None:
        return False
    p, maps = found

    def value(images, part):
        """(numerator, denominator) of the image of one number."""
        start, is_radius = part
        if not is_radius:
            return images[start] % p, 1
        x, y, cx, cy, d = images[start:start + 5]
        return ((d * x - cx) ** 2 + (d * y - cy) ** 2) % p, d * d % p
    quotients = []
    for images in maps:
        (a, b), (c, e) = value(images, parts[0]), value(images, parts[1])
        if b * c * e % p == 0:
            return False
        quotients.append(a * e * pow(b * c, -1, p) % p)
    return quotients[0] != quotients[1]


def lazy_level_radius(d, make, point, circle, owner, index: int):
    """The squared radius |point - C|^2 of level ``index`` of ``owner`` (C the centre of
    ``circle``, = (X/D, Y/D) for its ``homogeneous`` (X, Y, D)), held lazily where its exact value
    is costly: a :class:`LevelRadius` in a dense field of degree >= LARGE_DEGREE, a
    :class:`TowerLevelRadius` in a tower over the sparse Q(zeta_N); else None (the caller
    computes it, ``make()``)."""
    if isinstance(d, PolyElement) and d.field.degree >= LARGE_DEGREE:
        return LevelRadius(d.field, make, point, circle.centre, 1, owner, index,
                           circle.homogeneous)
    if isinstance(d, TowerElement) and isinstance(d.tower, SparseKummerTower):
        return TowerLevelRadius(d.tower, make, point, circle.homogeneous, owner, index)
    return None


def scaled_radius(r2, k, owner, index: int):
    """``k`` (a rational) times the squared radius ``r2``, as level ``index`` of
    ``owner``: a lazy :class:`LevelRadius` stays lazy."""
    if isinstance(r2, LevelRadius):
        return r2.scaled(k, owner, index)
    return r2 * k


def level_form(r2):
    """``(p, (X, Y, D), scale)`` when ``r2`` is a lazy level radius that keeps its point
    and the centre's homogeneous form, |D p - (X, Y)|^2 scale / D^2; else None."""
    if isinstance(r2, TowerLevelRadius):
        return r2._p, r2._c, 1
    if isinstance(r2, LevelRadius) and r2.homogeneous is not None:
        return r2._p, r2.homogeneous, r2.scale
    return None
