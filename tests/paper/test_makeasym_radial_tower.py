"""MakeAsym's radial move to G_t's circle (lines 11 / 23) when the scale factor's square
root is outside the configuration's field: the root is adjoined (a larger multiquadratic
field, or a tower level for a nested radical: exactsym.exact.adjoin_sqrt), the moved
robot lands exactly on G_t's circle on its own ray, and the paper layer goes on."""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import given, settings, strategies as st

from exactsym.geometry.configuration import Configuration, load
from exactsym.exact import fmpq, sign
from exactsym.exact.adjoin_sqrt import adjoin_sqrt
from exactsym.exact.evaluate import (FieldSystem, MultiquadraticSystem, RationalSystem,
                                     TowerSystem)
from exactsym.exact.multiquadratic import MQ, sqrt_rational
from exactsym.geometry.levels import levels_of
from exactsym.paper import family as F

FAMILY = Path(__file__).resolve().parents[2] / "cases" / "family"
S2 = sqrt_rational(2)


def _make_asym(config):
    rings = levels_of(config)
    Gp = F.preprocess(F.concentric_polygons(config, rings), [])
    return rings, F.make_asym(config, rings, Gp, [])


def _radial_move(config):
    rings, res = _make_asym(config)
    assert res.outcome == "orderable" and res.config is not None
    (move,) = [m for m in res.moves if m["kind"] == "to-G_t-circle"]
    return rings, res, move["robot"]


@pytest.mark.parametrize("name, system", [("makeasym-radial-move-adjoins-sqrt",
                                           MultiquadraticSystem),
                                          ("makeasym-radial-move-nested-radical",
                                           TowerSystem)])
def test_radial_move_lands_on_the_circle_exactly(name, system):
    config = load(FAMILY / f"{name}.toml")
    rings, res, robot = _radial_move(config)
    after = res.config
    assert isinstance(after.system, system)
    c = rings.sec.centre
    p0, p1 = config.points[robot], after.points[robot]
    v0 = (p0[0] - c[0], p0[1] - c[1])
    v1 = (p1[0] - c[0], p1[1] - c[1])
    # the G_t robot's squared radius (the largest ring: the SEC's)
    assert v1[0] * v1[0] + v1[1] * v1[1] == rings.sec.radius_squared
    assert sign(v0[0] * v1[1] - v0[1] * v1[0]) == 0                 # the same ray ...
    assert sign(v0[0] * v1[0] + v0[1] * v1[1]) > 0                  # ... outwards
    for k in range(config.n):                                       # nobody else moved
        if k != robot:
            assert after.points[k] == config.points[k]


def test_nested_radical_coordinates_are_tower_numbers():
    config = load(FAMILY / "makeasym-radial-move-nested-radical.toml")
    _, res, robot = _radial_move(config)
    x, y = res.config.points[robot]
    from exactsym.exact.tower import TowerElement
    assert isinstance(x, TowerElement) or isinstance(y, TowerElement)


@settings(max_examples=4, deadline=None)
@given(st.sampled_from([(3, 4, 5), (5, 12, 13), (8, 15, 17)]), st.booleans(),
       st.integers(-4, 4), st.integers(-4, 4))
def test_exact_similarity_changes_no_verdict(rot, reflect, tx, ty):
    a, b, n = rot                                    # a Pythagorean rotation
    pts = [(0, 0), (0, 1), (2, 0), (3, 2)]

    def sim(p):
        x, y = fmpq(p[0]), fmpq(-p[1] if reflect else p[1])
        return (fmpq(a, n) * x - fmpq(b, n) * y + tx, fmpq(b, n) * x + fmpq(a, n) * y + ty)

    base = _radial_move(Configuration.from_points(pts))
    moved = _radial_move(Configuration.from_points([sim(p) for p in pts]))
    assert moved[2] == base[2]                       # the same robot moves out
    res, res2 = base[1], moved[1]
    # squared distances between robots after the move are the same exactly
    def d2(cfg, i, j):
        p, q = cfg.points[i], cfg.points[j]
        return (p[0] - q[0]) ** 2 + (p[1] - q[1]) ** 2
    for i in range(4):
        for j in range(i):
            assert d2(res2.config, i, j) == d2(res.config, i, j)


def test_adjoin_sqrt_choices_and_limits():
    # a rational square root: a multiquadratic field holding it and the numbers
    system, root = adjoin_sqrt(RationalSystem(), [fmpq(1, 2)], fmpq(5, 4))
    assert isinstance(system, MultiquadraticSystem) and root == sqrt_rational(5) / 2
    # already there: the same system
    mq = MultiquadraticSystem([2])
    assert adjoin_sqrt(mq, [S2], MQ.rational(8))[0] is mq
    # a nested radical: a tower level
    system, root = adjoin_sqrt(mq, [S2], 1 + S2)
    assert isinstance(system, TowerSystem) and root * root == 1 + S2
    # a denestable one stays multiquadratic
    system, root = adjoin_sqrt(mq, [S2], 3 + 2 * S2)
    assert root == 1 + S2
    # a cyclotomic configuration: a tower over Q(zeta_M), a level only for a non-square
    from exactsym.exact import cyclotomic
    from exactsym.exact.evaluate import CyclotomicTowerSystem
    field = cyclotomic.cyclotomic_field(12)
    system, root = adjoin_sqrt(FieldSystem(field), [field(1)], field(2))
    assert isinstance(system, CyclotomicTowerSystem) and root * root == system.coerce(field(2))
    # degrees over Q: the real subfield Q(sqrt(3)) of Q(zeta_12) is 2; sqrt(2) is a level
    assert system.tower.degree == 4
    system, root = adjoin_sqrt(FieldSystem(field), [field(1)], field(3))
    assert root * root == 3 and system.tower.degree == 2      # sqrt(3) is in the base
    # beyond the tower's a-priori bound (phi(1009) = 1008 > 192): out of reach, at once
    big = cyclotomic.cyclotomic_field(1009)
    assert adjoin_sqrt(FieldSystem(big), [big(1)], big(2)) is None


def test_each_round_is_checked_against_the_sec_it_started_from():
    """Round 1's epsilon moves change the SEC (a finding); round 2 moves a robot radially
    onto G_t's circle (a square root adjoined in a tower over Q(zeta_12)) and keeps the SEC
    of round 1: one finding, not two, and the round-2 configuration is exact."""
    from pathlib import Path
    from exactsym.geometry.configuration import load
    from exactsym.geometry.levels import levels_of
    from exactsym.paper import family as F
    config = load(Path(__file__).resolve().parents[2] /
                  "cases/sweeps/roots_12_le6/sweep-MakeAsym.toml")
    res = F.paper_procedure(config, levels_of(config))
    changed = [e["round"] for e in res.trace if "the SEC changed" in e.get("detail", "")]
    assert changed == [1]
    assert [m["kind"] for m in res.moves][:3] == ["epsilon", "epsilon", "to-G_t-circle"]
    (_, one), (_, two) = res.round_configs[:2]
    a, b = levels_of(one).sec, levels_of(two).sec
    to = two.system.coerce
    assert (to(a.centre[0]), to(a.centre[1]), to(a.radius_squared)) == \
        (b.centre[0], b.centre[1], b.radius_squared)
    assert res.leader == 2 and res.complete
