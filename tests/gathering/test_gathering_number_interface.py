"""The numbers of the motion meet one declared interface (exactsym.exact.algebraic.interface):
an MQ, a nested radical of an instant's own tower and of a run's tower, a number of
K(alpha) and one of a quadratic level over it all answer ``sign``, ``is_zero``,
``is_rational``, ``to_fmpq``, ``enclosure`` and ``text``; the questions the simulator asks
about their kind (``nested_tower``, ``is_run_tower``, ``is_multiquadratic``,
``motion_number``) have the answers the re-homing relies on; the simulator's SEC is the
main one's (exactsym.geometry.sec)."""

from fractions import Fraction as F

import numpy as np
import pytest
from flint import fmpq

from exactsym.exact.algebraic.algebraic_tower import sqrt_over_k_alpha
from exactsym.exact.algebraic.interface import (ExactNumber, compare, is_multiquadratic,
                                                is_run_tower, motion_number, nested_tower)
from exactsym.exact.algebraic.roots import algebraic_root
from exactsym.exact.algebraic.run_tower import RunTower, sqrt_exact
from exactsym.exact.algebraic.tower_numbers import mq_sqrt_any
from exactsym.exact.multiquadratic import MQ, sqrt_rational
from exactsym.gathering import geometry as g
from exactsym.geometry import sec

Q = MQ.rational
S2, S3 = sqrt_rational(2), sqrt_rational(3)


def _numbers():
    """One number of each kind, with its value to 1e-9 (an independent float)."""
    mq = S2 + 1
    instant = mq_sqrt_any(1 + S2)                          # sqrt(1 + sqrt 2): own tower
    run = sqrt_exact(1 + S2, RunTower())                   # the same value, a run's tower
    # the root of 8 f^3 - f - sqrt(3)/4 in (0, 1): a number of K(alpha) (a cubic no other
    # test uses: the levels over K(alpha), at most three, are shared by all its numbers)
    alpha = algebraic_root(tuple(MQ.coerce(c) for c in (-S3 / 4, -1, 0, 8)), fmpq(0), fmpq(1))
    level = sqrt_over_k_alpha(alpha + 3)                   # sqrt(alpha + 3): a level over it
    a = next(r.real for r in np.roots([8, 0, -1, -3 ** 0.5 / 4])
             if abs(r.imag) < 1e-12 and 0 < r.real < 1)   # 8 a^3 - a - sqrt(3)/4 = 0
    return [(mq, 2 ** 0.5 + 1), (instant, (1 + 2 ** 0.5) ** 0.5),
            (run, (1 + 2 ** 0.5) ** 0.5), (alpha, a), (level, (a + 3) ** 0.5)]


def test_every_kind_meets_the_interface():
    for x, value in _numbers():
        assert isinstance(x, ExactNumber), type(x)
        assert x.sign() == 1 and (-x).sign() == -1 and not x.is_zero()
        assert not x.is_rational()
        with pytest.raises(ValueError):
            x.to_fmpq()
        ball = x.enclosure(64)
        assert abs(float(ball.mid()) - value) < 1e-9
        assert isinstance(x.text(), str) and x.text()
        assert compare(x, x) == 0 and compare(x, x + 1) == -1 and compare(x + 1, x) == 1
    assert Q(F(3, 4)).is_rational() and Q(F(3, 4)).to_fmpq() == fmpq(3, 4)


def test_the_kinds_the_rehoming_asks_about():
    mq, instant, run, alpha, level = (x for x, _ in _numbers())
    assert is_multiquadratic(mq) and not any(is_multiquadratic(x)
                                             for x in (instant, run, alpha, level))
    assert nested_tower(mq) is None and nested_tower(alpha) is None
    assert nested_tower(level) is None              # a level over K(alpha): not re-homed
    assert nested_tower(instant) is instant.tower and nested_tower(run) is run.tower
    assert is_run_tower(run.tower) and not is_run_tower(instant.tower)
    assert motion_number(fmpq(1, 3)) == Q(F(1, 3)) and is_multiquadratic(motion_number(2))
    assert motion_number(instant) is instant and motion_number(mq) is mq


def test_the_simulator_sec_is_the_main_one():
    pts = [g.point(0, 0), g.point(4, 0), g.point(1, 3), g.point(2, -1)]
    centre, r2 = g.smallest_enclosing_circle(pts)
    circle = sec.smallest_enclosing_circle(pts)
    assert centre == tuple(circle.centre) and r2 == circle.radius_squared
    assert all(is_multiquadratic(c) for c in centre + (r2,))
    # an irrational centre: three points with square roots
    pts = [g.point(0, 0), (S2 * 3, Q(0)), (Q(1), S2 + 2)]
    centre, r2 = g.smallest_enclosing_circle(pts)
    assert all((g.dist2(centre, p) - r2).sign() == 0 for p in pts)
    assert g.circumcircle(*pts) == (centre, r2)
