"""The corrected variant's choices that need no handedness
(``docs/gathering-corrected.md``): the ground truth's test that a move keeps a leader,
the distance profiles that break ties between movers, the ground truth's canonical
order as the last tie-break on a configuration that has a leader, and the counts n for
which Definition 1 read literally has no pattern.

**Never into a symmetric configuration.**  :func:`keeps_a_leader` asks the ground truth
(:func:`exactsym.truth.symmetry.symmetry_group`, never the paper layer) whether the
configuration after a completed move is *orderable* (no symmetry moves a robot: the
paper's ``def-orderable-set``: a leader can be elected).  A move whose completion is
symmetric while robots are left to move is not made (issue 31's n = 9 dead end: two
diametrically opposite robots fix the SEC, and the last slot of the hexagon made the
whole configuration point-symmetric about C).  The answer depends only on the target
and the robots that stand still, so it is the same at every point of the mover's way
(a fresh Look agrees, I3).
"""

from __future__ import annotations

from ..errors import InputError
from ..truth.symmetry import symmetry_group
from . import geometry as g
from .paper_bridge import configuration_of
from .pattern import capacity


def keeps_a_leader(pts, mover, target) -> bool | None:
    """Is the configuration with ``mover`` at ``target`` (the others where they are)
    orderable by the ground truth?  None when the kernel cannot hold its numbers."""
    after = list(pts)
    after[mover] = target
    try:
        return symmetry_group(configuration_of(after)).orderable
    except (InputError, ArithmeticError, NotImplementedError, ValueError):
        return None


def no_leader(pts) -> str | None:
    """The ground truth's group name (``"D2"``, ``"C3"``, ...) when the configuration
    ``pts`` is not orderable (no leader can be elected without chirality), else None
    (also when the kernel cannot hold the numbers)."""
    try:
        group = symmetry_group(configuration_of(list(pts)))
    except (InputError, ArithmeticError, NotImplementedError, ValueError):
        return None
    return None if group.orderable else group.name


def ground_ranks(pts) -> dict | None:
    """The rank of every robot in the ground truth's canonical ordering of the
    configuration (``def-orderable-set``: the same labelling in every frame, with or
    without a reflection), or None when the configuration is not orderable or the kernel
    cannot hold its numbers.  The last tie-break between movers: used only where the
    variant's own keys (distances, profiles) tie on a configuration that has a
    leader."""
    try:
        group = symmetry_group(configuration_of(list(pts)))
    except (InputError, ArithmeticError, NotImplementedError, ValueError):
        return None
    if not group.orderable or group.ordering is None:
        return None
    return {robot: rank for rank, robot in enumerate(group.ordering)}


class SortKey:
    """Sort key of exact numbers."""
    __slots__ = ("x",)

    def __init__(self, x):
        self.x = x

    def __lt__(self, other):
        return (self.x - other.x).sign() < 0


def profile(pts, i):
    """The squared distances from robot i to the others, sorted: a tie-break that needs
    no handedness (equal profiles: no choice without asymmetry)."""
    return sorted((g.dist2(pts[i], q) for j, q in enumerate(pts) if j != i), key=SortKey)


def profile_compare(a, b) -> int:
    """-1, 0 or 1: the lexicographic order of two profiles."""
    for x, y in zip(a, b):
        c = (x - y).sign()
        if c:
            return c
    return 0


def distinct_after(pts, option, R) -> bool:
    """After ``option`` = (robot, path) is made, do the other robots of R have pairwise
    different distance profiles?"""
    i, path = option
    after = list(pts)
    after[i] = path[-1].final
    rest = [profile(after, j) for j in R if j != i]
    return all(profile_compare(a, b) != 0 for k, a in enumerate(rest) for b in rest[k + 1:])


def literal_pattern_exists(n: int) -> bool:
    """Does Definition 1 (``gathering_pattern``), read literally (``lone=reject``: every
    robot of a layer touches one of its layer), have a pattern of n robots?  Not when n
    is one more than a robot at C and full layers (8, 20, 38, ...)."""
    total, layer = 1, 1
    while total < n:
        total += capacity(layer)
        layer += 1
        if total + 1 == n:
            return False
    return True


def mirror_leader(pts) -> int | None:
    """The ground truth's leader when the configuration's symmetry group is D1 (one
    mirror, no rotation, not orderable): the robot on the mirror chosen canonically
    (:func:`exactsym.truth.symmetry.symmetry_group`, ``leader``), the same robot in
    every frame.  None otherwise, or when the kernel cannot hold the numbers."""
    try:
        group = symmetry_group(configuration_of(list(pts)))
    except (InputError, ArithmeticError, NotImplementedError, ValueError):
        return None
    if group.orderable or group.rotations != 1 or group.mirrors != 1:
        return None
    return group.leader
