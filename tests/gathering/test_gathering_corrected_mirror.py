"""Starts with a mirror and a leader on it (D1; issue 31; ``corrected_mirror``,
``proofs/gathering-corrected.md`` Lemma 8), and the static reach test of chain ends
(``corrected_paths.spokes``, ``walled_off``; Lemma 5 case 1).

Before this change every D1 start with a leader was answered ``not-possible``: the
gathering tests below failed.  The starts are grid:4:5 starts (cells scaled by 3),
checked plain, mirrored, turned by a Pythagorean angle, scaled and translated."""

from __future__ import annotations

from fractions import Fraction as F

import pytest
from flint import fmpq

from exactsym.exact.multiquadratic import MQ
from exactsym.gathering import geometry as g
from exactsym.gathering.cases import run_settings, settings_of
from exactsym.gathering.corrected import decide_corrected
from exactsym.gathering.corrected_choice import mirror_leader
from exactsym.gathering.corrected_paths import spokes, walled_off
from exactsym.gathering.robot import Readings
from exactsym.gathering.world import Frame

#: grid:4:5 starts whose symmetry group is D1 with a robot on the mirror (the truth's
#: leader): the leader is the only nearest robot to C at the start (0,1,2,4,6), or
#: after the first step (0,1,2,8,10)
D1_STARTS = ((0, 1, 2, 4, 6), (0, 1, 2, 8, 10))


def cells(combo):
    return [(F(3 * (i // 4)), F(3 * (i % 4))) for i in combo]


def moved(points, how):
    if how == "mirrored":
        return [(-x, y) for x, y in points]
    if how == "turned":          # the Pythagorean rotation (3/5, 4/5), scaled by 2, shifted
        return [(2 * (F(3, 5) * x - F(4, 5) * y) + 7, 2 * (F(4, 5) * x + F(3, 5) * y) - 1)
                for x, y in points]
    return points


def mq(points):
    return [(MQ.coerce(x), MQ.coerce(y)) for x, y in points]


@pytest.mark.parametrize("combo", D1_STARTS)
@pytest.mark.parametrize("how", ["plain", "mirrored", "turned"])
def test_a_mirror_start_with_a_leader_gathers(combo, how):
    points = moved(cells(combo), how)
    assert mirror_leader(mq(points)) is not None        # D1, a leader on the mirror
    for seed, rigid in ((0, True), (1, False)):
        s = settings_of({"gather_algorithm": "corrected", "gather_max_events": 1500})
        s.update(seed=seed)
        if not rigid:
            s.update(rigid=False, delta="1/4")
        res = run_settings(points, s)
        assert res.outcome == "gathered", (seed, rigid, res.detail)


FRAMES = (Frame(F(3, 5), F(4, 5), False, F(7), F(-3)),
          Frame(F(6, 5), F(8, 5), True, F(-1, 2), F(5)),
          Frame(F(1), F(0), True, F(0), F(0)))


@pytest.mark.parametrize("combo", D1_STARTS)
def test_every_frame_names_the_leader_and_a_mirror_image_target(combo):
    pts = mq(cells(combo))
    lead = mirror_leader(pts)
    plain = decide_corrected(tuple(pts))
    assert [(m.robot, m.role) for m in plain.moves] == [(lead, "asym")]
    target = plain.moves[0].path[-1].final
    c, on = plain.centre, pts[lead]
    v, w = g.sub(on, c), g.sub(target, c)
    image = g.sub(g.add(c, g.scale(v, 2 * g.dot(w, v) / g.dot(v, v))), w)
    senses = set()
    for frame in FRAMES:
        u = frame.unit
        d = decide_corrected(tuple(frame.to_local(p) for p in pts), Readings(),
                             fmpq(u.numerator, u.denominator))
        assert [(m.robot, m.role) for m in d.moves] == [(lead, "asym")]
        back = frame.to_world(d.moves[0].path[-1].final)
        assert back in (target, image)
        senses.add((back == target) != frame.reflect)
    # a frame without a reflection turns as the world's; one with a reflection, opposite
    assert senses == {True}


def P(x, y):
    x, y = F(x), F(y)
    return (MQ.rational(fmpq(x.numerator, x.denominator)),
            MQ.rational(fmpq(y.numerator, y.denominator)))


def test_spokes_wall_off_a_chain_end_on_both_ways_round():
    # C at the origin (a robot), R's next robot at distance 7/2 on both sides of the
    # mover's way: each is within 4 of C and its disc reaches past L = 7/2
    pts = [P(0, 0), P(3, 0), P(0, F(7, 2)), P(0, F(-7, 2)), P(F(9, 2), F(9, 2))]
    c, mover = pts[0], 1
    limit2 = g.dist2(pts[2], c)
    walls = spokes(c, pts, mover, fmpq(1), limit2)
    assert len(walls) == 2                        # the robot at (9/2, 9/2) is too far
    assert walled_off(pts[1], c, P(-2, 0), walls)
    assert not walled_off(pts[1], c, P(F(6, 5), F(8, 5)), walls)
    assert not walled_off(pts[1], c, P(F(6, 5), F(-8, 5)), walls)
    # the same answers in a mirrored frame, and without an L (the last robot) none
    flip = [(x, -y) for x, y in pts]
    walls_m = spokes(flip[0], flip, mover, fmpq(1), limit2)
    assert walled_off(flip[1], flip[0], P(-2, 0), walls_m)
    assert not walled_off(flip[1], flip[0], P(F(6, 5), F(-8, 5)), walls_m)
    assert spokes(c, pts, mover, fmpq(1), None) == []
    # a robot farther than 4 from C is no spoke, nor one whose disc stops short of L
    assert spokes(c, [P(0, 0), P(3, 0), P(0, F(9, 2))], 1, fmpq(1), fmpq(49, 4)) == []
    assert spokes(c, [P(0, 0), P(3, 0), P(0, 2)], 1, fmpq(1), fmpq(20)) == []
