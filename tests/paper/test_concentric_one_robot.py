"""The rings of levels of one robot (:func:`exactsym.paper.family.concentric_polygons`)
are slotted objects (issue 33: memory per robot) that read as the dict-based
:class:`~exactsym.paper.family.concentric.Ring` built from the same level would."""

from __future__ import annotations

import copy
import pickle
import random

from exactsym.exact import fmpq
from exactsym.geometry.configuration import Configuration
from exactsym.geometry.levels import levels_of
from exactsym.paper import family as F
from exactsym.paper.circle_polygon import CirclePolygon
from exactsym.paper.family.concentric import Ring, lines_of_symmetry, new_ring


def _random_config(n: int, seed: int) -> Configuration:
    rnd = random.Random(seed)
    return Configuration.from_points(tuple((fmpq(rnd.randint(-999, 999), rnd.randint(1, 50)),
                                fmpq(rnd.randint(-999, 999), rnd.randint(1, 50)))
                               for _ in range(n)))


def _plain(ring) -> Ring:
    """The same ring with the dataclasses' dict-based classes."""
    poly = ring.polygon
    plain = CirclePolygon(tuple(poly.labels), tuple(poly.directions), poly.polar)
    return new_ring(ring.name, plain, ring.radius_squared, ring.levels, ring.robots,
                    ring.own)


def test_one_robot_rings_read_as_plain_rings():
    config = _random_config(40, 5)
    G = F.concentric_polygons(config, levels_of(config))
    singles = [g for g in G if g.polygon is not None and len(g.robots) == 1]
    assert len(singles) >= 35            # random points: (almost) one robot per level
    for g in singles:
        k = g.levels[0]
        assert g.name == f"G{k}" and g.levels == (k,)
        assert g.own == g.robots and g.n == 1 and g.polygon.n == 1
        assert g.polygon.labels == ((g.robots[0],),)
        assert g.polygon.one_circle is True
        x, y = config.points[g.robots[0]]
        cx, cy = levels_of(config).sec.centre
        assert g.polygon.directions == ((x - cx, y - cy),)
        plain = _plain(g)
        for name in ("name", "radius_squared", "levels", "robots", "own", "n"):
            assert getattr(g, name) == getattr(plain, name)
        assert lines_of_symmetry(g) == lines_of_symmetry(plain)
        assert F.is_symmetric_polygon(g) == F.is_symmetric_polygon(plain)
        assert g.ray_keys == plain.ray_keys
        assert not hasattr(g, "__dict__") or not vars(g)       # no dict per ring


def test_one_robot_rings_copy_pickle_and_compare():
    config = _random_config(12, 9)
    G = F.concentric_polygons(config, levels_of(config))
    again = F.concentric_polygons(config, levels_of(config))
    assert G == again and hash(G) == hash(again)
    for g in G:
        back = pickle.loads(pickle.dumps(g))
        assert back == g and back.name == g.name and back.polygon == g.polygon
        assert copy.deepcopy(g) == g
    # another ring of another level differs
    assert G[0] != G[1]
