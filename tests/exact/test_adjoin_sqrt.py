"""adjoin_sqrt over a tower whose levels are square roots of K_0 (exactsym.exact.adjoin_sqrt):
a radicand that Legendre characters of the subfield it lives in prove no square of the top
field (Kummer theory) gets its level at once; the complete test of the tower agrees."""

from __future__ import annotations

from flint import fmpq
from hypothesis import given, settings, strategies as st

from exactsym.exact.adjoin_sqrt import _kummer_nonsquare, adjoin_sqrt
from exactsym.exact.evaluate import TowerSystem
from exactsym.exact.multiquadratic import MQ
from exactsym.exact.tower import Tower, TowerElement, add, wrap

_BASE = (2, 3, 5, 7)
_mq = st.dictionaries(st.sampled_from([1, 2, 3, 5, 6, 7, 10, 14, 15, 21, 35, 210]),
                      st.integers(-4, 4).filter(bool).map(fmpq), min_size=1, max_size=4
                      ).map(MQ)


def _tower(levels=4) -> Tower:
    """Levels y_j = sqrt(1 + sqrt p) over Q(sqrt 2, sqrt 3, sqrt 5, sqrt 7)."""
    tower = Tower(_BASE)
    for p in _BASE[:levels]:
        tower.sqrt(1 + MQ.sqrt(p))
    assert tower.levels == levels
    return tower


def _element(tower, used, coefficients):
    """sum over the subsets T of ``used`` of c_T prod(y_t : t in T), c_T from the list."""
    total = tower.zero
    subsets = [()]
    for lev in used:
        subsets += [s + (lev,) for s in subsets]
    for subset, c in zip(subsets, coefficients):
        term = c
        for lev in subset:
            term = tower.mul(term, (lev, tower.zero, tower.one))
        total = add(total, term)
    return total


@settings(max_examples=40, deadline=None)
@given(st.sets(st.integers(1, 4), min_size=1, max_size=2), st.lists(_mq, min_size=4, max_size=4),
       st.sets(st.integers(1, 4)), _mq)
def test_a_proved_non_square_has_no_root_and_a_square_is_never_proved(used, coefficients,
                                                                        others, z):
    """x = w^2 prod(r_t : t in U) is a square of the top field: never proved a non-square;
    x = w^2 z: when proved a non-square, the tower's complete test finds no root either."""
    tower = _tower()
    w = _element(tower, sorted(used), coefficients)
    if type(w) is not tuple:
        return
    square = tower.mul(w, w)
    for t in others:
        square = tower.mul(square, tower.radicands[t - 1])
    assert not _kummer_nonsquare(tower, square)
    assert tower.root_in(square, tower.levels) is not None
    if z.sign() > 0:
        x = tower.mul(tower.mul(w, w), z)
        if _kummer_nonsquare(tower, x):
            assert tower.root_in(x, tower.levels) is None


def test_new_levels_are_proved_and_adjoined_as_by_the_complete_test():
    """1 + y_1 and 2 + y_1 y_3 are no squares of K_0(y_1..y_4) (the complete test says so):
    the characters prove it, and adjoin_sqrt adds the same level as the tower's sqrt."""
    for used, coefficients in (([1], [MQ.rational(1), MQ.rational(1)]),
                               ([1, 3], [MQ.rational(2), MQ(), MQ(), MQ.rational(1)])):
        tower = _tower()
        x = _element(tower, used, coefficients)
        assert tower.root_in(x, tower.levels) is None
        assert _kummer_nonsquare(tower, x)
        system = TowerSystem(_BASE)
        for p in _BASE:
            system.tower.sqrt(1 + MQ.sqrt(p))
        found, root = adjoin_sqrt(system, [], wrap(system.tower, x))
        assert found is system and system.tower.levels == 5 and root * root == \
            wrap(system.tower, x)
        assert isinstance(root, TowerElement) and root.v == (5, tower.zero, tower.one)
        reference = _tower()
        assert reference.sqrt(x) == (5, tower.zero, tower.one)
        assert reference.radicands == system.tower.radicands


def test_outside_its_conditions_it_decides_nothing():
    """A radicand that is not in K_0 (a level over a level) or a tower without levels."""
    tower = Tower(_BASE)
    assert not _kummer_nonsquare(tower, (1, tower.zero, tower.one))
    y1 = tower.sqrt(1 + MQ.sqrt(2))
    tower.sqrt(add(MQ.rational(3), y1))                     # sqrt(3 + sqrt(1 + sqrt 2))
    assert not _kummer_nonsquare(tower, add(MQ.rational(1), y1))
