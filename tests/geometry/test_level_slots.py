""":class:`exactsym.geometry.levels.Level` is slotted (issue 33: a million levels) and the
fast constructors of the analysis and of the audit's frames build levels equal to
``Level(r2, points)``."""

from __future__ import annotations

import pickle
import random

from exactsym.analysis import analyse
from exactsym.exact import fmpq
from exactsym.geometry.configuration import Configuration
from exactsym.geometry.levels import Level, levels_of


def test_level_has_no_dict_and_pickles():
    level = Level(fmpq(25, 4), (3, 1))
    assert not hasattr(level, "__dict__")
    assert pickle.loads(pickle.dumps(level)) == level
    assert Level(fmpq(25, 4), (3, 1)) == level and hash(Level(fmpq(25, 4), (3, 1))) == hash(level)
    assert level != Level(fmpq(25, 4), (1, 3))


def test_built_levels_equal_constructed_ones():
    rnd = random.Random(3)
    config = Configuration.from_points(tuple((fmpq(rnd.randint(-99, 99), rnd.randint(1, 9)),
                                              fmpq(rnd.randint(-99, 99), rnd.randint(1, 9)))
                                             for _ in range(300)))
    plain = levels_of(config)
    assert not isinstance(plain.levels, tuple)      # many rational points: built when read
    levels = analyse(config, sections=["family"]).levels        # built_levels' fast path
    assert isinstance(levels.levels, tuple)
    built = tuple(levels.levels)
    assert built == tuple(Level(lv.radius_squared, tuple(lv.points)) for lv in plain.levels)
    for lv in built:
        assert sum(c * c for c in (config.points[lv.points[0]][0] - plain.sec.centre[0],
                                   config.points[lv.points[0]][1] - plain.sec.centre[1])) \
            == lv.radius_squared
