"""A level's squared radius held lazily in a large cyclotomic field (exactsym.exact.level_radius):
every answer it gives before its polynomial is computed is the exact number's."""

from __future__ import annotations

import random

from flint import ctx, fmpq
from hypothesis import assume, given, settings, strategies as st

from exactsym import load
from exactsym.exact.cyclotomic import MAX_DEGREE
from exactsym.exact.cyclotomic_modular import _element_images, _embeddings
from exactsym.exact.evaluate import dense_degree_limit
from exactsym.exact.field import PolyElement
from exactsym.geometry.configuration import Configuration
from exactsym.exact import sign
from exactsym.exact.evaluate import SparseKummerSystem
from exactsym.exact.level_radius import LevelRadius, TowerLevelRadius, tower_ratio_irrational
from exactsym.geometry.levels import levels_of


def _config(tmp_path, seed: int, n: int = 6):
    """n robots at turns j/331 (Q(zeta_1324), degree 660) and small radii, off centre:
    every robot on a level of its own, most of them."""
    draw = random.Random(seed)
    rows = "".join(f'  {{ r = "{draw.randrange(1, 9)}", turn = "{t}/331" }},\n'
                   for t in draw.sample(range(331), n))
    path = tmp_path / f"c{seed}.toml"
    path.write_text("format = 1\npoints = [\n" + rows + "]\n")
    with dense_degree_limit(MAX_DEGREE):      # the dense field (sparse by default)
        config = load(path)
        config.system                         # chosen when first read
    return config


def _fresh(level: LevelRadius) -> LevelRadius:
    """The same lazy radius, not computed yet (the tests read each one exactly)."""
    return LevelRadius(level.field, level._make, level._p, level._c, level.scale,
                       level.owner, level.index, level.homogeneous) if not level.made else level


@settings(max_examples=8, deadline=None)
@given(st.integers(0, 10 ** 6))
def test_lazy_radii_answer_as_the_exact_ones(tmp_path_factory, seed):
    config = _config(tmp_path_factory.mktemp("r"), seed)
    levels = levels_of(config)
    radii = [r for r in (level.radius_squared for level in levels.levels)
             if isinstance(r, LevelRadius)]
    assume(len(radii) >= 2)             # (the SEC's own level may be known already)
    assert not any(r.made for r in radii)
    lazy = [_fresh(r) for r in radii]
    exact = [PolyElement(r.field, r.poly) for r in radii]           # computes them
    m = exact[0].field.conductor
    p, roots = _embeddings(m)
    for k, (a, ea) in enumerate(zip(lazy, exact)):
        # balls contain the exact value; images in F_p are the exact number's
        with ctx.workprec(80):
            assert a.enclosure(64).contains(ea.enclosure(200))
        assert a.modular_images(m, p, roots, lambda v: _element_images(v, m, p, roots)) \
            == _element_images(ea, m, p, roots)
        assert a.sign() == ea.sign() == 1
        for b, eb in zip(lazy, exact):
            assert (a == b) == (ea == eb) and (a != b) == (ea != eb)
            assert (a < b) == (ea < eb) and (a >= b) == (ea >= eb)
        assert not a.made                  # none of the above computed it
        k2 = fmpq(4, 9)
        scaled = a.scaled(k2, object(), k)
        es = ea * k2
        with ctx.workprec(80):
            assert scaled.enclosure(64).contains(es.enclosure(200))
        assert scaled.modular_images(m, p, roots, lambda v: _element_images(v, m, p, roots)) \
            == _element_images(es, m, p, roots)
        assert scaled.poly == es.poly and a.poly == ea.poly
        # scaled again once made: the value and its balls still agree
        twice = scaled.scaled(fmpq(3), object(), k)
        with ctx.workprec(80):
            assert twice.enclosure(64).contains((es * 3).enclosure(200))
        assert twice.poly == (es * 3).poly


def _sqrt_config(seed: int, n: int = 4):
    """n robots at radii sqrt(k) and turns j/30, off centre, written in the tower of square
    roots over the sparse Q(zeta_60) (evaluate.SparseKummerSystem; chosen for turns j/997,
    where an exact radius takes minutes: small here so that the test can compute them)."""
    draw = random.Random(seed)
    system = SparseKummerSystem(60)
    points = []
    for t in draw.sample(range(1, 30), n):
        r = system.sqrt(fmpq(draw.randrange(2, 40)))
        points.append((r * system.cos_turn(fmpq(t, 30)), r * system.sin_turn(fmpq(t, 30))))
    return Configuration(points=points, system=system)


@settings(max_examples=20, deadline=None)
@given(st.integers(0, 10 ** 6))
def test_tower_radii_answer_as_the_exact_ones(seed):
    levels = levels_of(_sqrt_config(seed))
    lazy = [level.radius_squared for level in levels.levels]
    assume(len(lazy) >= 2 and all(isinstance(r, TowerLevelRadius) for r in lazy))
    assert not any(r.made for r in lazy)
    fresh = [TowerLevelRadius(r.tower, r._make, r._p, r._c, r.owner, r.index) for r in lazy]
    exact = [r.value() for r in lazy]                 # computes them
    for a, ea in zip(fresh, exact):
        with ctx.workprec(80):
            assert a.enclosure(64).contains(ea.enclosure(200))
        assert a.sign() == sign(ea) == 1
        for b, eb in zip(fresh, exact):
            assert (a == b) == (ea == eb) and (a != b) == (ea != eb)
            assert (a < b) == (ea < eb) and (a >= b) == (ea >= eb)
        assert not a.made                  # none of the above computed it
        # read exactly, it is the number
        assert a * 3 == ea * 3 and a - ea == 0 and a.made


@settings(max_examples=12, deadline=None)
@given(st.integers(0, 10 ** 6))
def test_tower_ratio_refuted_only_when_irrational(seed):
    """A ratio of radii that tower_ratio_irrational calls irrational is irrational (exact
    quotient); a radius against itself or a rational multiple of its exact value never is."""
    from exactsym.exact.ratio import rational_ratio
    levels = levels_of(_sqrt_config(seed, 5))
    lazy = [level.radius_squared for level in levels.levels]
    assume(len(lazy) >= 2 and all(isinstance(r, TowerLevelRadius) for r in lazy))
    fresh = [TowerLevelRadius(r.tower, r._make, r._p, r._c, r.owner, r.index) for r in lazy]
    refuted = [[tower_ratio_irrational(a, b) for b in fresh] for a in fresh]
    assert not any(r.made for r in fresh)
    exact = [r.value() for r in lazy]
    for i, a in enumerate(exact):
        assert not refuted[i][i]
        assert not tower_ratio_irrational(fresh[i], a * 3)     # 1/3, made on the right
        for j, b in enumerate(exact):
            if refuted[i][j]:       # the exact numbers (made): the quotient's test
                assert rational_ratio(a, b) is None


def test_tower_ratio_refutes_the_levels_of_one_configuration():
    """Seed 0: three levels whose radii have irrational ratios (checked above against the
    exact quotient); the maps into F_p refute all six without an exact radius."""
    radii = [level.radius_squared for level in levels_of(_sqrt_config(0, 5)).levels]
    assert len(radii) == 3 and all(isinstance(r, TowerLevelRadius) for r in radii)
    assert sum(tower_ratio_irrational(a, b) for a in radii for b in radii if a is not b) == 6
    assert not any(r.made for r in radii)
