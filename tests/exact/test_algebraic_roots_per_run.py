"""The roots of the motion's K(alpha) instants and the levels of square roots over them
belong to a run (its context, exactsym.exact.context), not to the process (issue 29):
a decision asked after other runs in the same process is the one a fresh process gives.
Before, ``AlgebraicRoot._known`` shared one root, and the at most three levels above it,
with every later run: a fourth square root over it was None (the Look undecided)."""

import subprocess
import sys

from flint import fmpq

from exactsym.exact.algebraic.algebraic_tower import MAX_LEVELS, sqrt_over_k_alpha
from exactsym.exact.algebraic.roots import algebraic_root
from exactsym.exact.context import AnalysisContext, in_own_context
from exactsym.exact.multiquadratic import MQ, sqrt_rational

#: what a fresh process answers: the square root of alpha + 5 over K(alpha), alpha the
#: root in (0, 1) of 8 f^3 - f - sqrt(3)/4 (a cubic of this test only)
DECISION = """
from flint import fmpq
from exactsym.exact.algebraic.algebraic_tower import sqrt_over_k_alpha
from exactsym.exact.algebraic.roots import algebraic_root
from exactsym.exact.multiquadratic import MQ, sqrt_rational
alpha = algebraic_root(tuple(MQ.coerce(c) for c in (-sqrt_rational(3) / 4, -1, 0, 8)),
                       fmpq(0), fmpq(1))
root = sqrt_over_k_alpha(alpha + 5)
print(None if root is None else root.text())
"""


def _alpha():
    return algebraic_root(tuple(MQ.coerce(c) for c in (-sqrt_rational(3) / 4, -1, 0, 8)),
                          fmpq(0), fmpq(1))


@in_own_context
def _other_run(shifts):
    """A run that asks square roots over the same root: each a new level."""
    alpha = _alpha()
    return [sqrt_over_k_alpha(alpha + k) for k in shifts]


@in_own_context
def _decision():
    root = sqrt_over_k_alpha(_alpha() + 5)
    return None if root is None else root.text()


def _fresh_process() -> str:
    out = subprocess.run([sys.executable, "-c", DECISION], capture_output=True, text=True,
                         check=True)
    return out.stdout.strip()


def test_a_decision_after_other_runs_is_a_fresh_process_one():
    fresh = _fresh_process()
    assert fresh != "None"                  # a level over K(alpha): decided
    assert MAX_LEVELS == 3
    levels = _other_run((1, 2, 3))          # three levels over the same root...
    assert all(r is not None for r in levels)
    assert levels[-1].tower.levels == MAX_LEVELS
    assert _decision() == fresh             # ...are that run's only
    _other_run((2, 7, 11))
    assert _decision() == fresh


def test_within_a_run_the_numbers_of_an_instant_share_one_root():
    with AnalysisContext(memo=False).active():
        a, b = _alpha(), _alpha()
        assert a.root is b.root and a == b
        x, y = sqrt_over_k_alpha(a + 1), sqrt_over_k_alpha(b + 1)
        assert x.tower is y.tower and x == y
        # at most MAX_LEVELS levels in one run: the fourth is not built
        assert all(sqrt_over_k_alpha(a + k) is not None for k in (2, 3))
        assert sqrt_over_k_alpha(a + 5) is None
    with AnalysisContext(memo=False).active():
        assert _alpha().root is not a.root


#: what a fresh process answers: a new level over the one-level tower of sqrt(1 + sqrt 2)
TOWER_DECISION = """
from exactsym.exact.algebraic.tower_numbers import mq_sqrt_any, tower_sqrt
from exactsym.exact.multiquadratic import sqrt_rational
y = mq_sqrt_any(1 + sqrt_rational(2))
print(tower_sqrt(y + 100).tower.levels)
"""


@in_own_context
def _tower_run(shifts):
    """A run that adds levels to the one-level tower of sqrt(1 + sqrt 2)."""
    from exactsym.exact.algebraic.tower_numbers import mq_sqrt_any, tower_sqrt
    y = mq_sqrt_any(1 + sqrt_rational(2))
    return [tower_sqrt(y + k) for k in shifts]


@in_own_context
def _tower_decision():
    from exactsym.exact.algebraic.tower_numbers import mq_sqrt_any, tower_sqrt
    y = mq_sqrt_any(1 + sqrt_rational(2))
    return str(tower_sqrt(y + 100).tower.levels)


def test_the_levels_over_an_instants_tower_are_the_runs_own():
    """Before, the instants' one-level towers were a process-wide lru_cache: the levels
    one run added (at most 12) were every later run's, whose next level then failed."""
    fresh = subprocess.run([sys.executable, "-c", TOWER_DECISION], capture_output=True,
                           text=True, check=True).stdout.strip()
    assert fresh == "2"
    for _ in range(2):
        assert [r.v[0] for r in _tower_run(range(1, 12))] == list(range(2, 13))   # new levels
        assert _tower_decision() == fresh
