"""Checker extension: angles read from integer enclosures (standard library only), for the
ordering check in fields whose numbers have them (``bounds``): the towers over square roots,
the sparse Q(zeta_N) and the tower over it.  Such a field's ``Angle`` is :class:`BoxedAngle`.
"""

from __future__ import annotations

from fractions import Fraction
from math import ceil, floor

from .numbers import sgn


def _box(plane, i: int, bits: int):
    """Enclosures of the direction of point i of an ordering plane: two boxes (lo, hi, bits)."""
    key = (i, bits)
    if key not in plane.boxes:
        plane.boxes[key] = tuple((*_bounds(v, bits), bits) for v in plane.dirs[i])
    return plane.boxes[key]


def _bounds(v, bits: int) -> tuple[int, int]:
    """Integers lo <= v 2^bits <= hi: a rational exactly, a number of a field with
    ``bounds`` (the sparse Q(zeta_N) and the tower over it) from its terms' enclosures."""
    if isinstance(v, (int, Fraction)):
        v = Fraction(v) * (1 << bits)
        return floor(v), ceil(v)
    return v.f.bounds(getattr(v, "v", v), bits)     # a tower's TNum: its raw value


# Boxes (lo, hi, e): integers with lo <= x 2^e <= hi.  Products and sums are exact integer
# operations on the ends (no rounding), so a box holds its number whenever its operands' do.

def _box_mul(a, b):
    ends = (a[0] * b[0], a[0] * b[1], a[1] * b[0], a[1] * b[1])
    return min(ends), max(ends), a[2] + b[2]


def _box_add(a, b):
    if a[2] < b[2]:
        a, b = b, a
    shift = a[2] - b[2]
    return a[0] + (b[0] << shift), a[1] + (b[1] << shift), a[2]


def _box_neg(a):
    return -a[1], -a[0], a[2]


def _box_sign(a):
    return 1 if a[0] > 0 else -1 if a[1] < 0 else None


class BoxedAngle:
    """The angle from the direction u of point i to the direction v of point j, the vector
    (u . v, u x v), in a boxed plane.  Its signs and its comparisons are read from boxes
    of u and v at 64, then 192 bits; the exact vector (products of sums of hundreds of
    cosines on every level: seconds each) is made only when both hold 0 (ties: two points
    on one ray, equal gaps)."""
    __slots__ = ("plane", "i", "j", "_exact")
    BITS = (64, 192)

    def __init__(self, plane, i: int, j: int):
        self.plane, self.i, self.j, self._exact = plane, i, j, None

    def boxes(self, bits: int):
        (ux, uy), (vx, vy) = _box(self.plane, self.i, bits), _box(self.plane, self.j, bits)
        return (_box_add(_box_mul(ux, vx), _box_mul(uy, vy)),
                _box_add(_box_mul(ux, vy), _box_mul(_box_neg(uy), vx)))

    def exact(self):
        if self._exact is None:
            (ux, uy), (vx, vy) = self.plane.dirs[self.i], self.plane.dirs[self.j]
            self._exact = (ux * vx + uy * vy, ux * vy - uy * vx)
        return self._exact

    def sign(self, k: int) -> int:
        """The sign of u . v (k = 0) or u x v (k = 1)."""
        if self.i == self.j:                # u . u > 0 (u != 0), u x u = 0
            return 1 - k
        for bits in self.BITS:
            s = _box_sign(self.boxes(bits)[k])
            if s is not None:
                return s
        return sgn(self.exact()[k])

    def half(self) -> int:
        """0 in the upper half [0, pi), 1 in the lower half [pi, 2pi)."""
        y = self.sign(1)
        return 0 if y > 0 or (y == 0 and self.sign(0) > 0) else 1

    def cmp(a, b: "BoxedAngle") -> int:
        ha, hb = a.half(), b.half()
        if ha != hb:
            return -1 if ha < hb else 1
        for bits in a.BITS:            # in one half, the sign of a x b
            (ax, ay), (bx, by) = a.boxes(bits), b.boxes(bits)
            s = _box_sign(_box_add(_box_mul(ax, by), _box_neg(_box_mul(ay, bx))))
            if s is not None:
                return -s
        (ax, ay), (bx, by) = a.exact(), b.exact()
        return -sgn(ax * by - ay * bx)
