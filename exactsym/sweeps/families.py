"""Families of configurations for a sweep: exact, deterministic enumerators with a size.

A family is written as text on the command line (``docs/sweeps.md``):

* ``roots:M:K[:RINGS]`` -- K robots on the M-th roots of unity (rays at turns j/M) of up
  to RINGS concentric circles; RINGS is a count R (radii 1..R) or a list of radii
  (``1,3/2``); one configuration per class under rotation and reflection, generated as a
  canonical bracelet (:mod:`.canonical`);
* ``grid:N:K`` -- K robots on the N x N integer grid, one per class under its 8 symmetries
  (orderly generation);
* ``random:K:SEED:COUNT`` -- COUNT sets of K rational points (coordinates p/q, |p| <= 8,
  1 <= q <= 4), item i drawn from its own generator seeded with (SEED, i);
* ``perturb:FILE:EPS:COUNT`` -- COUNT exact perturbations of FILE's points, each
  coordinate moved by a multiple of EPS/16 in [-EPS, EPS]; in a polar file each radius
  written as a rational moves and the turns stay (a turn moved by a rational would put the
  points in a cyclotomic field of large degree -- Q(zeta_800) for EPS = 1/50 -- where one
  configuration takes minutes);
* ``algebraic:K:M:SEED:COUNT`` -- COUNT sets of K points in polar form, each on a ray at
  a turn j/M and a radius from :data:`SURD_RADII` (square roots of 2 and 3: with M = 8,
  12 or 24 every coordinate is a number of Q(sqrt 2, sqrt 3); M = 36 puts the turns in
  K(alpha), ``docs/gathering.md``, "Starts"), item i drawn from its own generator seeded
  with (SEED, i), turned so that its first robot is at turn 0;
* ``gather:BUDGET:FAMILY`` -- the configurations of FAMILY as starting configurations of
  the gathering simulator, BUDGET adversary steps per run; ``gather:EVENTS+STATES:FAMILY``
  also lets the searching adversary generate STATES states from each start
  (``--what gather-corrected``: ``docs/sweeps.md``).

K may be an integer, ``<=K`` (1..K) or ``A..B``.  Every item is a :class:`SweepItem`:
its key (the canonical form as text: a sweep's results are keyed by it), its points as
configuration-file text, and what orders counterexamples (:func:`rank`).
"""

from __future__ import annotations

import random
from dataclasses import dataclass
from fractions import Fraction
from math import lcm
from typing import Iterator

from .canonical import (bracelets, burnside_count, dihedral_permutations, gap_bracelets,
                        gaps_to_positions, orderly_subsets, square_permutations)

__all__ = ["Family", "SweepItem", "FamilyError", "parse_family", "family_size",
           "family_items", "can_jump", "rank", "ENUMERATION", "SURD_RADII"]

#: The radii of ``algebraic:`` families, as configuration-file text (``docs/format.md``):
#: rationals and square roots of 2, 3 and 6, between 1 and 3.
SURD_RADII = ("1", "sqrt(2)", "sqrt(3)", "2", "1+sqrt(2)", "sqrt(6)", "1+sqrt(3)",
              "3*sqrt(2)/2", "3", "2*sqrt(2)")

#: Version of the enumerators' order: a results file records it, and ``--resume`` refuses a
#: file of another version (its indices would name other configurations).
ENUMERATION = 1


class FamilyError(ValueError):
    """A family text the user wrote that cannot be read (exit 2)."""


@dataclass(frozen=True)
class SweepItem:
    """One configuration of a family: ``points`` are ``("polar", r, turn)`` or
    ``("xy", x, y)`` with exact numbers as text; ``size`` is M (roots) or N (grid), else 0;
    ``denominator`` the lcm of the denominators of every number written."""
    key: str
    n: int
    denominator: int
    size: int
    points: tuple
    index: int = -1               # position in the family's enumeration (set by the engine)


@dataclass(frozen=True)
class Family:
    text: str
    kind: str
    counts: tuple = ()            # robot counts K, increasing
    m: int = 0                    # roots: M; grid: N
    radii: tuple = ()             # roots: the circles' radii (Fractions), increasing
    seed: str = ""
    count: int = 0                # random / perturb: number of draws
    eps: Fraction = Fraction(0)
    file: str = ""
    base_points: tuple = ()       # perturb: the file's points (SweepItem form)
    budget: int = 0               # gather: adversary steps per run
    states: int = 0               # gather: the searching adversary's states per start
    inner: "Family | None" = None


def rank(item: SweepItem) -> tuple:
    """Smaller is a better counterexample: fewest robots, then smallest denominators, then
    smallest M (or N), then the key (deterministic ties)."""
    return (item.n, item.denominator, item.size, item.key)


def _int(text: str, what: str, family: str, low: int = 1) -> int:
    if not text.strip().isdigit() or int(text) < low:
        raise FamilyError(f"family {family!r}: {what} must be an integer >= {low}, not {text!r}")
    return int(text)


def _counts(text: str, family: str) -> tuple:
    t = text.strip()
    if t.startswith("<="):
        return tuple(range(1, _int(t[2:], "K", family) + 1))
    if ".." in t:
        a, b = t.split("..", 1)
        lo, hi = _int(a, "K", family), _int(b, "K", family)
        if lo > hi:
            raise FamilyError(f"family {family!r}: empty range of K {t!r}")
        return tuple(range(lo, hi + 1))
    return (_int(t, "K", family),)


def _fraction(text: str, what: str, family: str) -> Fraction:
    try:
        value = Fraction(text.strip())          # "3/2", "0.01": exact, never eval
    except (ValueError, ZeroDivisionError):
        raise FamilyError(f"family {family!r}: {what} must be a rational number, "
                          f"not {text!r}") from None
    return value


def parse_family(text: str, load_points=None) -> Family:
    """Read a family text; ``load_points(path) -> tuple of points`` reads perturb's file
    (:func:`exactsym.sweeps.analysis_bridge.file_points`)."""
    parts = text.split(":")
    kind = parts[0]
    if kind == "roots" and len(parts) in (3, 4):
        m = _int(parts[1], "M", text)
        radii = (Fraction(1),)
        if len(parts) == 4:
            ring = parts[3]
            if "," in ring or "/" in ring or "." in ring:
                radii = tuple(sorted({_fraction(r, "a radius", text) for r in ring.split(",")}))
            else:
                radii = tuple(Fraction(r) for r in range(1, _int(ring, "RINGS", text) + 1))
            if radii[0] <= 0:
                raise FamilyError(f"family {text!r}: radii must be positive")
        counts = tuple(k for k in _counts(parts[2], text) if k <= m * len(radii))
        return Family(text, "roots", counts=counts, m=m, radii=radii)
    if kind == "grid" and len(parts) == 3:
        n = _int(parts[1], "N", text)
        counts = tuple(k for k in _counts(parts[2], text) if k <= n * n)
        return Family(text, "grid", counts=counts, m=n)
    if kind == "random" and len(parts) == 4:
        return Family(text, "random", counts=_counts(parts[1], text), seed=parts[2],
                      count=_int(parts[3], "COUNT", text, low=0))
    if kind == "perturb" and len(parts) >= 4:
        path = ":".join(parts[1:-2])
        eps = _fraction(parts[-2], "EPS", text)
        if eps <= 0:
            raise FamilyError(f"family {text!r}: EPS must be positive")
        points = tuple(load_points(path)) if load_points is not None else ()
        return Family(text, "perturb", file=path, eps=eps,
                      count=_int(parts[-1], "COUNT", text, low=0), base_points=points,
                      counts=(len(points),))
    if kind == "algebraic" and len(parts) == 5:
        return Family(text, "algebraic", counts=_counts(parts[1], text),
                      m=_int(parts[2], "M", text), seed=parts[3],
                      count=_int(parts[4], "COUNT", text, low=0))
    if kind == "gather" and len(parts) >= 3:
        inner = parse_family(":".join(parts[2:]), load_points)
        if inner.kind == "gather":
            raise FamilyError(f"family {text!r}: gather of gather")
        events, _, states = parts[1].partition("+")
        return Family(text, "gather", budget=_int(events, "BUDGET", text), inner=inner,
                      counts=inner.counts,
                      states=_int(states, "STATES", text) if states else 0)
    raise FamilyError(f"unknown family {text!r}: expected roots:M:K[:RINGS], grid:N:K, "
                      "random:K:SEED:COUNT, algebraic:K:M:SEED:COUNT, perturb:FILE:EPS:COUNT or "
                      "gather:BUDGET[+STATES]:FAMILY")


def family_size(family: Family) -> int:
    """The number of items :func:`family_items` yields (exact; for random and perturb the
    number of draws, of which equal sets count once in a sweep)."""
    if family.kind == "roots":
        perms = dihedral_permutations(family.m, len(family.radii))
        return sum(burnside_count(perms, k) for k in family.counts)
    if family.kind == "grid":
        perms = square_permutations(family.m)
        return sum(burnside_count(perms, k) for k in family.counts)
    if family.kind in ("random", "perturb", "algebraic"):
        return family.count
    return family_size(family.inner)


def family_items(family: Family, after: str | None = None) -> Iterator[SweepItem]:
    """Every item of the family, in a fixed order (the same on every run); with ``after``
    (the key of one of its items; roots and grid families only, see :func:`can_jump`)
    the items that follow it, generated from its canonical form without replaying the
    ones before."""
    if after is not None and not can_jump(family):
        raise ValueError(f"family {family.text!r} cannot start after a key")
    if family.kind == "roots":
        yield from _roots(family, after)
    elif family.kind == "grid":
        yield from _grid(family, after)
    elif family.kind == "random":
        yield from _random(family)
    elif family.kind == "perturb":
        yield from _perturb(family)
    elif family.kind == "algebraic":
        yield from _algebraic(family)
    else:
        yield from family_items(family.inner, after)


def can_jump(family: Family) -> bool:
    """Whether :func:`family_items` can start after a key (random draws cannot: an equal
    earlier draw must be seen to be skipped)."""
    return family.kind in ("roots", "grid") or (family.kind == "gather" and
                                                can_jump(family.inner))


def _start(family: Family, after: str | None) -> tuple[int | None, tuple | None]:
    """(robot count, canonical form) of the item keyed ``after``, or (None, None)."""
    if after is None:
        return None, None
    form = after.rsplit(":", 1)[1]
    if family.kind == "roots" and len(family.radii) == 1:
        positions = [int(x) for x in form.split(",")]
        m = family.m
        gaps = tuple(b - a - 1 for a, b in zip(positions, positions[1:])) + \
            (m - positions[-1] - 1 + positions[0],)
        return len(positions), gaps
    if family.kind == "roots":
        beads = tuple(int(x) for x in form.split("."))
        return sum(bin(b).count("1") for b in beads), beads
    cells = tuple(int(x) for x in form.split(","))
    return len(cells), cells


def _text(q: Fraction) -> str:
    return str(q.numerator) if q.denominator == 1 else f"{q.numerator}/{q.denominator}"


def _roots_item(family: Family, cells: list[tuple[int, int]]) -> SweepItem:
    """``cells``: (ring, vertex) pairs; turned so that the first robot is at turn 0."""
    m = family.m
    j0 = cells[0][1]
    points, den = [], 1
    for ring, j in sorted(cells, key=lambda c: ((c[1] - j0) % m, c[0])):
        turn = Fraction((j - j0) % m, m)
        r = family.radii[ring]
        den = lcm(den, turn.denominator, r.denominator)
        points.append(("polar", _text(r), _text(turn)))
    return SweepItem("", len(cells), den, m, tuple(points))


def _roots(family: Family, after: str | None = None) -> Iterator[SweepItem]:
    m, rings = family.m, len(family.radii)
    radii = ",".join(_text(r) for r in family.radii)
    k0, form = _start(family, after)
    for k in family.counts:
        if k0 is not None and k < k0:
            continue
        start = form if k == k0 else None
        if rings == 1:
            for gaps in gap_bracelets(m, k, start_after=start):
                positions = gaps_to_positions(gaps)     # unique per class, like the gaps
                item = _roots_item(family, [(0, j) for j in positions])
                yield _keyed(item, f"roots:{m}:{radii}:" + ",".join(map(str, positions)))
        else:
            for beads in bracelets(m, k, 1 << rings, start_after=start):
                cells = [(r, j) for j, b in enumerate(beads) for r in range(rings) if b >> r & 1]
                item = _roots_item(family, cells)
                yield _keyed(item, f"roots:{m}:{radii}:" + ".".join(map(str, beads)))


def _keyed(item: SweepItem, key: str) -> SweepItem:
    return SweepItem(key, item.n, item.denominator, item.size, item.points)


def _grid(family: Family, after: str | None = None) -> Iterator[SweepItem]:
    n = family.m
    perms = square_permutations(n)
    k0, form = _start(family, after)
    for k in family.counts:
        if k0 is not None and k < k0:
            continue
        start = form if k == k0 else None
        for cells in orderly_subsets(n * n, k, perms, start_after=start):
            points = tuple(("xy", str(c // n), str(c % n)) for c in cells)
            yield SweepItem(f"grid:{n}:" + ",".join(map(str, cells)), k, 1, n, points)


def _point_set_item(prefix: str, coords: list[tuple[Fraction, Fraction]]) -> SweepItem:
    coords = sorted(set(coords))
    den = 1
    for x, y in coords:
        den = lcm(den, x.denominator, y.denominator)
    points = tuple(("xy", _text(x), _text(y)) for x, y in coords)
    key = prefix + ";".join(f"{x} {y}" for _, x, y in points)
    return SweepItem(key, len(points), den, 0, points)


def _random(family: Family) -> Iterator[SweepItem]:
    for i in range(family.count):
        k = family.counts[i % len(family.counts)]
        rng = random.Random(f"{family.seed}:{i}")
        coords: set = set()
        while len(coords) < k:
            coords.add((Fraction(rng.randint(-8, 8), rng.randint(1, 4)),
                        Fraction(rng.randint(-8, 8), rng.randint(1, 4))))
        yield _point_set_item("random:", list(coords))


def _algebraic(family: Family) -> Iterator[SweepItem]:
    m = family.m
    for i in range(family.count):
        k = family.counts[i % len(family.counts)]
        rng = random.Random(f"{family.seed}:{i}")
        cells: set = set()
        while len(cells) < k:
            cells.add((rng.randrange(m), rng.randrange(len(SURD_RADII))))
        ordered = sorted(cells)
        j0 = ordered[0][0]
        pts, den = [], 1
        for j, r in sorted(((j - j0) % m, r) for j, r in ordered):
            turn = Fraction(j, m)
            den = lcm(den, turn.denominator, _denominator(SURD_RADII[r]))
            pts.append(("polar", SURD_RADII[r], _text(turn)))
        key = f"algebraic:{m}:" + ";".join(f"{r}@{t}" for _, r, t in pts)
        yield SweepItem(key, len(pts), den, m, tuple(pts))


def _denominator(text: str) -> int:
    try:
        return Fraction(text).denominator
    except (ValueError, ZeroDivisionError):
        return 1                                    # an irrational radius as written


def _perturb(family: Family) -> Iterator[SweepItem]:
    eps = family.eps
    base = family.base_points
    polar = bool(base) and base[0][0] == "polar"
    for i in range(family.count):
        rng = random.Random(f"perturb:{eps}:{i}")
        while True:                                  # redraw until the points are distinct
            item = _perturbed_polar(base, eps, rng) if polar else _perturbed_xy(base, eps, rng)
            if item is not None:
                yield item
                break


def _moved(text: str, eps: Fraction, rng: random.Random) -> Fraction:
    return Fraction(text) + eps * Fraction(rng.randint(-16, 16), 16)


def _perturbed_xy(base, eps, rng) -> SweepItem | None:
    coords = [(_moved(x, eps, rng), _moved(y, eps, rng)) for _, x, y in base]
    return _point_set_item("perturb:", coords) if len(set(coords)) == len(coords) else None


def _perturbed_polar(base, eps, rng) -> SweepItem | None:
    pts = []
    for _, r, turn in base:
        try:
            r_new = _text(_moved(r, eps, rng))
        except (ValueError, ZeroDivisionError):
            r_new = r                                # an irrational radius stays as written
        pts.append(("polar", r_new, turn))
    if len(set(pts)) != len(pts) or any(p[1].startswith("-") for p in pts):
        return None
    pts.sort(key=lambda p: (Fraction(p[2]), p[1]))
    den = 1
    for _, r, t in pts:
        den = lcm(den, Fraction(t).denominator, _denominator(r))
    key = "perturb:" + ";".join(f"{r}@{t}" for _, r, t in pts)
    return SweepItem(key, len(pts), den, 0, tuple(pts))
