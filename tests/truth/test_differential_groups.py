"""Differential test (issue 9): configurations of known group built from orbits.

For k = 1..12, Ck and Dk are built as orbits of three seeds on rings of radius sqrt(2),
sqrt(3), 2 (turns 1/(8k), 1/(3k), 1/(6k): no 2(t_i - t_j) and no 2 t_i is a multiple of
1/k, so the group is exactly Ck or Dk; the field stays Q(zeta_24k)).  Each is written in polar form and in
Cartesian form (cos/sin of rational multiples of pi), moved by an exact similarity, and
broken by moving one point by 1e-30 (then the group is C1).  The truth must name the group
and give both spellings the same canonical ordering when orderable.
"""

from __future__ import annotations

from fractions import Fraction

import pytest

from exactsym.geometry.configuration import load
from exactsym.truth.symmetry import symmetry_group


def _orbit(k: int, mirror: bool) -> list[tuple[str, Fraction]]:
    points = []
    for radius, seed in (("sqrt(2)", Fraction(1, 8 * k)), ("sqrt(3)", Fraction(1, 3 * k)),
                         ("2", Fraction(1, 6 * k))):
        for j in range(k):
            points.append((radius, seed + Fraction(j, k)))
            if mirror:
                points.append((radius, -seed + Fraction(j, k)))
    return points


def _write(tmp_path, name: str, rows: list[str]) -> str:
    path = tmp_path / f"{name}.toml"
    path.write_text("format = 1\npoints = [\n" + ",\n".join(rows) + "\n]\n")
    return str(path)


def _polar(points) -> list[str]:
    return [f'{{ r = "{r}", turn = "{t}" }}' for r, t in points]


def _cartesian(points, scale="1", shift=("0", "0"), nudge=None) -> list[str]:
    rows = []
    for i, (r, t) in enumerate(points):
        a = 2 * t
        r_text = f"({r} + 1e-30)" if i == nudge else r
        rows.append(f'["{shift[0]} + {scale}*{r_text}*cos({a.numerator}*pi/{a.denominator})", '
                    f'"{shift[1]} + {scale}*{r_text}*sin({a.numerator}*pi/{a.denominator})"]')
    return rows


@pytest.mark.parametrize("k", range(1, 13))
@pytest.mark.parametrize("mirror", [False, True])
def test_orbit_groups(tmp_path, k, mirror):
    expected = f"{'D' if mirror else 'C'}{k}"
    points = _orbit(k, mirror)
    polar = symmetry_group(load(_write(tmp_path, "polar", _polar(points))))
    cartesian = symmetry_group(load(_write(tmp_path, "cart", _cartesian(points))))
    moved = symmetry_group(load(_write(tmp_path, "moved", _cartesian(
        points, scale="3/2", shift=("1/3", "sqrt(3)")))))
    broken = symmetry_group(load(_write(tmp_path, "broken", _cartesian(points, nudge=0))))
    assert polar.name == cartesian.name == moved.name == expected
    assert broken.name == "C1"
    if polar.orderable:
        assert polar.ordering == cartesian.ordering == moved.ordering
