"""An exact canonical key of a world's state, for the adversary search's de-duplication.

Two worlds of the search (deep copies, :mod:`.search`) each own a copy of the run's tower
of nested radicals, and a tower number refuses ``==`` with a number of another tower
(:class:`~exactsym.exact.algebraic.tower_numbers.TowerNumber`): a set of raw positions
crashed there (issue 30).  The key here never compares numbers: a multiquadratic number
is its sorted terms; a tower number is the signature of its tower (the base primes and the
keys of the radicands up to its level) with :func:`exactsym.exact.tower.key` of its raw
value, which is canonical (``a + b y`` with ``y`` not in the level below).  Equal keys
are equal states; a number of any other kind is keyed by identity, so two such states are
never merged (only explored twice).
"""

from __future__ import annotations

from ..exact.algebraic.interface import is_multiquadratic, is_run_tower, nested_tower
from ..exact.number import tower_of
from ..exact.tower import key, level
from . import geometry as g

__all__ = ["number_key", "point_key", "piece_key", "state_key", "shared_by_copies",
           "tower_free"]


class _Identity:
    """A key that equals only itself (a number of a kind without a canonical form)."""

    __slots__ = ("obj",)

    def __init__(self, obj):
        self.obj = obj

    def __eq__(self, other):
        return isinstance(other, _Identity) and other.obj is self.obj

    def __hash__(self):
        return id(self.obj)


def number_key(x):
    """A hashable key equal for two numbers only when they are equal (never ``==`` on
    numbers: plain tuples of integers)."""
    if is_multiquadratic(x):
        return key(x)
    tower = nested_tower(x)              # a nested radical (not a number of K(alpha))
    if tower is not None:
        lev = level(x.v)
        signature = (type(tower).__name__, tuple(tower.primes),
                     tuple(key(r) for r in tower.radicands[:lev]))
        return ("tower", signature, key(x.v))
    return ("object", _Identity(x))


def point_key(p) -> tuple:
    return (number_key(p[0]), number_key(p[1]))


def piece_key(piece) -> tuple:
    if isinstance(piece, g.Segment):
        return ("segment", point_key(piece.start), point_key(piece.end))
    return ("arc", point_key(piece.centre), point_key(piece.start), point_key(piece.end),
            int(piece.sense))


def state_key(world) -> tuple:
    """What decides the rest of a run: every robot's position, pending path, role and
    kind (the invariants name them), and, non-rigid, where its move began (delta)."""
    return tuple((point_key(r.pos), tuple(piece_key(pc) for pc in r.path), r.role, r.kind,
                  None if world.rigid or r.start is None else point_key(r.start))
                 for r in world.robots)


def shared_by_copies(x) -> bool:
    """May ``x`` (a critical instant's exact value, or None) be kept in a cache that the
    copies of a world (:func:`.search.fork`) share?  Yes for a rational or
    multiquadratic number, a number of ``K(alpha)`` and a nested radical of an instant's
    own one-level tower (:func:`~exactsym.exact.algebraic.tower_numbers.tower_of`: one
    object per radicand in a run, never copied with a world); no for a number of a run's
    tower or of a quadratic level over ``K(alpha)`` (each copy of the world owns its own,
    and numbers of two towers are not compared)."""
    if tower_of(x) is None:
        return True
    tower = nested_tower(x)
    return tower is not None and not is_run_tower(tower)


def tower_free(world) -> bool:
    """Do the world's positions and pending paths hold no nested radical?  Only then may
    a cache shared by the copies of a world keep instants of an instant's own tower: a
    copy's tower numbers live in its own copy of that tower (:func:`.search.fork`), and
    numbers of two copies do not mix."""
    for r in world.robots:
        pts = [r.pos] + [p for pc in r.path for p in
                         ((pc.start, pc.end) + ((pc.centre,) if isinstance(pc, g.Arc) else ()))]
        if any(tower_of(x) is not None for p in pts for x in p):
            return False
    return True
