"""The gathering pattern (``gathering_pattern``, Def. 1; spec section 2): generator and
recogniser, exact.

Layer ``L >= 1`` holds centres on the circle ``|x - C| = 2L`` (a robot of layer L
"touches cir(C, 2L - 1)"); neighbours in a layer touch, so consecutive centres are the
angle theta_L apart with ``cos theta_L = 1 - 1/(2L^2)`` and
``sin theta_L = sqrt(D_L)/(2L^2)``, ``D_L = 4L^2 - 1``.  Rotating by theta_L is
multiplication by ``w_L = cos + i sin``; its powers ``w_L^k = a_k + i b_k sqrt(D_L)``
have rational ``a_k, b_k`` (the recurrence of spec section 5), so capacities and slots are
exact without arcsin: the capacity of layer L is the largest ``k`` with
``k theta_L <= 2 pi``, read off the signs of ``b_k`` (6, 12, 18, 25, 31, ...).

Readings (switches of spec section 2):

* ``lone`` -- a lone robot in a new outer layer touches no robot of its layer, so the
  definition's "at least 1" fails; ``"accept"`` (default) accepts it when the inner
  layers are full, ``"reject"`` reads the definition literally.
* connectivity is never required: with two or more layers the pattern is generically not
  connected (the contact graph is reported by :func:`contact_graph`).

Recognising (``recognise``): the robot exactly at C, then layers 1, 2, ... while they are
full (capacity robots, consecutive ones touching except for at most one gap); in the
first layer that is not full, the longest chain of mutually touching consecutive robots
(the "contiguous vacant places"); when two chains tie for longest, neither is taken (the
largest valid partial pattern is then not unique, and a frame-independent choice
does not exist).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

from flint import fmpq

from ..exact.multiquadratic import MQ, sqrt_rational
from .geometry import add, angle_key, angle_less, cross, dist2, dot, rotate, scale, sub


@lru_cache(maxsize=256)
def layer_rotation(L: int) -> tuple[MQ, MQ]:
    """``(cos theta_L, sin theta_L)`` exactly."""
    c = MQ.rational(1 - fmpq(1, 2 * L * L))
    s = sqrt_rational(4 * L * L - 1) * fmpq(1, 2 * L * L)
    return c, s


def rotation_power_coefficients(L: int, k: int) -> tuple[fmpq, fmpq]:
    """``(a_k, b_k)`` with ``w_L^k = a_k + i b_k sqrt(D_L)`` by the recurrence
    ``a_{k+1} = (a_k (2L^2-1) - b_k D_L)/(2L^2)``, ``b_{k+1} = (a_k + b_k (2L^2-1))/(2L^2)``."""
    D, h = 4 * L * L - 1, 2 * L * L
    a, b = fmpq(1), fmpq(0)
    for _ in range(k):
        a, b = (a * (h - 1) - b * D) / h, (a + b * (h - 1)) / h
    return a, b


@lru_cache(maxsize=256)
def capacity(L: int) -> int:
    """Largest k with ``k theta_L <= 2 pi`` (layer 0 holds one robot)."""
    if L == 0:
        return 1
    D, h = 4 * L * L - 1, 2 * L * L
    a, b = fmpq(1), fmpq(0)
    k, passed_half = 0, False
    while True:
        a, b = (a * (h - 1) - b * D) / h, (a + b * (h - 1)) / h
        k += 1
        if b < 0:
            passed_half = True
        elif passed_half:
            # back in the upper half plane: k theta_L >= 2 pi, equality iff b == 0
            return k if b == 0 else k - 1


def slot(centre, start, L: int, k: int):
    """The k-th slot of layer L counter-clockwise from the point ``start`` of that layer
    (negative k: clockwise)."""
    a, b = rotation_power_coefficients(L, abs(k))
    s = sqrt_rational(4 * L * L - 1) * b
    if k < 0:
        s = -s
    return add(centre, rotate(sub(start, centre), MQ.rational(a), s))


def generate(n: int, centre=(0, 0), first=None) -> list:
    """A complete pattern of ``n`` robots about ``centre``: full inner layers, the last
    layer one chain counter-clockwise from the ray through ``first`` (default +x)."""
    c = (MQ.rational(centre[0]), MQ.rational(centre[1]))
    pts = [c]
    L = 1
    while len(pts) < n:
        if first is None:
            start = (c[0] + 2 * L, c[1])
        else:
            v = sub((MQ.rational(first[0]), MQ.rational(first[1])), c)
            r2 = dot(v, v).to_fmpq()
            start = add(c, scale(v, sqrt_rational(1 / r2) * (2 * L)))
        for k in range(min(capacity(L), n - len(pts))):
            pts.append(slot(c, start, L, k))
        L += 1
    return pts


@dataclass(frozen=True)
class Pattern:
    """A recognised partial pattern: ``centre_robot`` (index or None), ``layers[L-1]`` the
    robot indices of layer L in counter-clockwise chain order, ``valid``: Def. 1 holds
    under the reading used; ``defects``: why not."""
    centre: tuple
    centre_robot: int | None
    layers: tuple
    valid: bool
    defects: tuple = ()

    @property
    def robots(self) -> frozenset:
        out = set(r for layer in self.layers for r in layer)
        if self.centre_robot is not None:
            out.add(self.centre_robot)
        return frozenset(out)

    @property
    def last_layer(self) -> int:
        return len(self.layers)

    def last_full(self) -> bool:
        return not self.layers or len(self.layers[-1]) == capacity(len(self.layers))


def _touch(p, q, unit=1) -> bool:
    return dist2(p, q) == 4 * unit * unit


def _chains(points, members, centre, unit=1):
    """Split ``members`` (all at one radius) into maximal chains of touching consecutive
    robots, each in counter-clockwise order."""
    if not members:
        return []
    ref = sub(points[members[0]], centre)
    order = sorted(members, key=lambda i: _SortKey(angle_key(ref, sub(points[i], centre))))
    m = len(order)
    touching = [_touch(points[order[j]], points[order[(j + 1) % m]], unit) for j in range(m)]
    if m == 1:
        return [order]
    if m == 2:
        # one pair: touching[0] and touching[1] are the same contact, not a ring
        if not touching[0]:
            return [[order[0]], [order[1]]]
        a, b = (sub(points[i], centre) for i in order)
        return [order if cross(a, b).sign() > 0 else order[::-1]]
    if all(touching):
        return [order]                      # a closed ring
    # start after a gap
    start = next(j for j in range(m) if not touching[(j - 1) % m])
    chains, cur = [], []
    for s in range(m):
        j = (start + s) % m
        cur.append(order[j])
        if not touching[j]:
            chains.append(cur)
            cur = []
    if cur:
        chains.append(cur)
    return chains


class _SortKey:
    __slots__ = ("k",)

    def __init__(self, k):
        self.k = k

    def __lt__(self, other):
        return angle_less(self.k, other.k)


def recognise(points, centre, lone: str = "accept", unit=1) -> Pattern:
    """The largest valid partial pattern about ``centre`` (see the module docstring);
    ``unit``: the robot radius in the points' frame (a rational)."""
    u = fmpq(unit)
    unit2 = u * u
    at_centre = [i for i, p in enumerate(points) if p[0] == centre[0] and p[1] == centre[1]]
    if not at_centre:
        return Pattern(centre, None, (), True)
    by_radius: dict = {}
    for i, p in enumerate(points):
        r2 = dist2(p, centre)
        if r2.is_rational():
            q = r2.to_fmpq() / unit2
            if q.q == 1 and int(q.p) % 4 == 0:
                L2 = int(q.p) // 4
                L = int(round(L2 ** 0.5))
                for cand in (L - 1, L, L + 1):      # exact check of the square
                    if cand >= 1 and cand * cand == L2:
                        by_radius.setdefault(cand, []).append(i)
    layers, defects = [], []
    L = 1
    while L in by_radius:
        members = by_radius[L]
        chains = _chains(points, members, centre, unit)
        if len(members) == capacity(L) and len(chains) == 1:
            layers.append(tuple(chains[0]))
            L += 1
            continue
        longest = max(len(c) for c in chains)
        best = [c for c in chains if len(c) == longest]
        if len(best) > 1:
            defects.append(f"layer {L}: {len(best)} chains of {longest} robots tie")
            break
        chain = best[0]
        if len(chain) == 1 and lone == "reject":
            defects.append(f"layer {L}: a lone robot touches no robot of its layer")
            break
        layers.append(tuple(chain))
        break
    return Pattern(centre, at_centre[0], tuple(layers), True, tuple(defects))


def definition_defects(points, pat: Pattern, lone: str = "accept", unit=1) -> list:
    """Def. 1 checked on a recognised pattern's robots (used by invariant I8): unique robot
    at C, every robot of layer L at distance 2L, inner layers full, no two robots closer
    than 2, each robot touching at least one (unless the lone reading) and at most two of
    its layer, the last layer one chain."""
    out = []
    robots = sorted(pat.robots)
    for i, a in enumerate(robots):
        for b in robots[i + 1:]:
            if (dist2(points[a], points[b]) - 4 * unit * unit).sign() < 0:
                out.append(f"robots {a} and {b} overlap")
    for L, layer in enumerate(pat.layers, start=1):
        for r in layer:
            if dist2(points[r], pat.centre) != 4 * L * L * unit * unit:
                out.append(f"robot {r} is not on layer {L}")
            k = sum(1 for s in layer if s != r and _touch(points[r], points[s], unit))
            if k > 2:
                out.append(f"robot {r} touches {k} robots of layer {L}")
            if k == 0 and not (lone == "accept" and L == len(pat.layers) and len(layer) == 1):
                out.append(f"robot {r} touches no robot of layer {L}")
        if L < len(pat.layers) and len(layer) != capacity(L):
            out.append(f"inner layer {L} is not full")
    return out


def contact_graph(points, robots) -> list:
    """Pairs of touching robots among ``robots``."""
    rs = sorted(robots)
    return [(a, b) for i, a in enumerate(rs) for b in rs[i + 1:] if _touch(points[a], points[b])]
