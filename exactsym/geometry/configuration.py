"""A configuration: robot positions as exact numbers, validated; moves and frames on it.

:func:`load` reads a file (:mod:`exactsym.io.fileformat`), evaluates every expression in
one number system (:mod:`exactsym.exact`) and checks validity (distinct points,
``r >= 0``, fat robots at distance >= 2).  A configuration whose points are all
polar keeps them as ``(r^2, turn)`` (and the radii r) too: about the origin, radii and
angles are then rationals and need no trigonometry, which keeps polar polygons with
thousands of vertices cheap (``docs/numbers.md``); Cartesian coordinates are
built on first use.

Moves and changes of frame work on the exact numbers (never on expressions):
:meth:`Configuration.moved` / :meth:`Configuration.with_positions` put robots at new
positions (Cartesian pairs or :class:`Polar`), :meth:`Configuration.transformed` applies
a :class:`Similarity`; an impossible result (robots coinciding or overlapping, a
negative radius) raises :class:`~exactsym.errors.MoveImpossible`, not ``InputError``.
"""

from __future__ import annotations

import dataclasses
import gc
import math
from contextlib import contextmanager
from dataclasses import dataclass
from functools import cached_property
from fractions import Fraction
from typing import Iterable, Mapping, Sequence

import numpy as np

from ..io.fileformat import ConfigFile, PlainPoints, PointSpec, read_config
from ..errors import ExpressionError, InputError, MoveImpossible
from ..exact import (RationalSystem, evaluate, exact_key, fmpq, normal_turn, number_system,
                    sign)
from ..exact.number import dense_field, is_algebraic, is_plain_rational
from ..io.exprtree import BinOp, Const, Node
from .predicates import float_coordinates


@dataclass(frozen=True)
class Polar:
    """A position about the origin: radius ``r`` (an exact number >= 0) and ``turn``
    (a rational, in turns)."""
    r: object
    turn: fmpq


@dataclass(frozen=True)
class Similarity:
    """An exact similarity of the plane: first the reflection (x, y) -> (x, -y) when
    ``reflect``, then the rotation about the origin by the rational ``turn`` or by the
    exact matrix ``rotation = (c, s)`` (c^2 + s^2 = 1), then the scaling by ``scale`` (a
    positive rational) and the translation by ``shift``.  Without ``rotation`` and
    ``shift`` it keeps a polar configuration polar."""
    reflect: bool = False
    turn: fmpq | None = None
    rotation: tuple | None = None
    scale: object = 1
    shift: tuple | None = None

    @property
    def keeps_polar(self) -> bool:
        return self.rotation is None and self.shift is None


class Configuration:
    """A finite set of distinct robot positions, exact.  Treat as immutable.

    ``points``: tuple of ``(x, y)`` in ``system`` (a number system of
    :mod:`exactsym.exact`); ``polar``: tuple of ``(r^2, turn in [0, 1))`` about the
    origin when every point was given in polar form, else ``None``.
    """

    def __init__(self, *, source: str = "<memory>", name: str | None = None,
                 notes: str | None = None, model: str = "points", lemmas: Sequence[str] = (),
                 expect: Mapping | None = None, specs: Sequence[PointSpec] = (),
                 points: Sequence | None = None, system=None,
                 polar: Sequence | None = None, polar_system=None,
                 radii: Sequence | None = None):
        self.source = source
        self.name = name
        self.notes = notes
        self.model = model
        self.lemmas = tuple(lemmas)
        self.expect = dict(expect or {})
        self.specs = specs if isinstance(specs, PlainPoints) else tuple(specs)
        self.polar = tuple(polar) if polar is not None else None
        self.polar_system = polar_system
        self.radii = tuple(radii) if radii is not None else None     # r, when polar
        if points is not None:
            self.__dict__["points"] = tuple(map(tuple, points))
            self.__dict__["system"] = system
        self.n = len(points) if points is not None else len(self.polar)

    @classmethod
    def from_points(cls, points: Iterable, system=None, **kw) -> "Configuration":
        """From exact ``(x, y)`` pairs: ``int``, ``Fraction``, ``fmpq``, strings the file
        format reads (``'1/3'``, ``'sqrt(2)/2'``, ``'cos(2*pi/7)'``), sympy numbers (read
        by walking their trees, :mod:`exactsym.io.sympy_trees`), or elements of one number
        field with its ``system``.  Raises :class:`~exactsym.errors.InputError` when two
        points coincide, for a float (not exact) or an unreadable number.

        >>> from fractions import Fraction
        >>> square = Configuration.from_points([(1, 0), (0, 1), (-1, 0), (0, -1)])
        >>> square.n, square.points[1]
        (4, (0, 1))
        >>> Configuration.from_points([(0, 0), (Fraction(1, 2), 0)]).points[1]
        (1/2, 0)
        >>> import sympy
        >>> c = Configuration.from_points([(sympy.sqrt(2), 0), (0, "sqrt(2)"), ("-1/3", 0)])
        >>> c.to_sympy()[:2]
        ((sqrt(2), 0), (0, sqrt(2)))
        >>> Configuration.from_points([(0.5, 0), (1, 0)])
        Traceback (most recent call last):
        ...
        exactsym.errors.InputError: <memory>: point 0, x = 0.5: a float is not exact; write it as a string ('0.5') or a Fraction
        """
        from ..exact import RationalSystem, as_fmpq
        pts = [tuple(p) for p in points]
        if system is None and any(_needs_reading(v) for p in pts for v in p):
            system, pts = _read_values(pts, kw.get("source", "<memory>"))
        elif system is None:
            pts = [(as_fmpq(x), as_fmpq(y)) for x, y in pts]
        config = cls(points=pts, system=system or RationalSystem(), **kw)
        check_distinct(config)
        return config

    def to_sympy(self) -> tuple:
        """The points as pairs of sympy numbers (:func:`to_sympy`)."""
        return tuple((to_sympy(x), to_sympy(y)) for x, y in self.points)

    def __repr__(self) -> str:
        what = f"{self.n} {'fat robots' if self.model == 'fat' else 'points'}"
        name = f" {self.name!r}" if self.name else ""
        shown = ""
        if "points" in self.__dict__ and self.n <= 6:      # never computed for a repr
            texts = [f"({to_text(x)}, {to_text(y)})" for x, y in self.points]
            if sum(map(len, texts)) <= 120:
                shown = ": " + ", ".join(texts)
        return f"<Configuration{name}: {what} from {self.source}{shown}>"

    @cached_property
    def system(self):
        # the points with it: computing them apart would evaluate every expression twice
        # (and choose the field twice, perhaps differently inside dense_degree_limit)
        self.points
        return self.__dict__["system"]

    @cached_property
    def points(self) -> tuple:
        system, pts = self._cartesian()
        self.__dict__["system"] = system
        return tuple(pts)

    @cached_property
    def float_points(self):
        """``geometry.float_coordinates(self.points)`` (the correctly rounded floats of
        rational coordinates, or None), computed once: the check for coincident points
        and the levels' filters both read them."""
        return float_coordinates(self.points)

    def _cartesian(self):
        if self.specs or self.radii is None:
            return _cartesian(self.specs, self.source)
        return _cartesian_of_polar(self.radii, [t for _, t in self.polar])

    # ------------------------------------------------------------ moves and frames
    def _same(self, **kw) -> "Configuration":
        return Configuration(source=self.source, name=self.name, model=self.model, **kw)

    def with_positions(self, positions: Mapping[int, object]) -> "Configuration":
        """The configuration with robot i at ``positions[i]`` (every other robot where it
        is): a :class:`Polar` position keeps a polar configuration polar (its radius in
        :attr:`polar_system`), an exact ``(x, y)`` pair is Cartesian (in :attr:`system`).
        Raises :class:`MoveImpossible` when robots coincide, fat robots overlap or a
        radius is negative."""
        if self.radii is not None and all(isinstance(p, Polar) for p in positions.values()):
            radii, polar = list(self.radii), list(self.polar)
            for i, p in positions.items():
                if sign(p.r) < 0:
                    raise MoveImpossible(f"robot {i}: negative radius")
                radii[i] = p.r
                polar[i] = (p.r * p.r, normal_turn(p.turn) if sign(p.r) != 0 else fmpq(0))
            new = self._same(polar=polar, radii=radii, polar_system=self.polar_system)
        else:
            points = list(self.points)
            for i, p in positions.items():
                points[i] = _cartesian_position(p, self.system)
            new = self._same(points=points, system=self.system)
        _check_move(new)
        return new

    def moved(self, index: int, point) -> "Configuration":
        """The configuration with robot ``index`` at ``point`` (see :meth:`with_positions`)."""
        return self.with_positions({index: point})

    def radius(self, index: int):
        """The radius r of robot ``index`` about the origin (polar configurations)."""
        if self.radii is None:
            raise ValueError("not a polar configuration with known radii")
        return self.radii[index]

    def cartesian(self) -> "Configuration":
        """The same points, as a Cartesian configuration (no polar data)."""
        return self._same(points=self.points, system=self.system)

    def transformed(self, similarity: Similarity, check: bool = True) -> "Configuration":
        """The configuration in another frame, robot indices unchanged: a polar
        configuration stays polar when ``similarity.keeps_polar``.  ``check=False`` skips
        the test that no two robots coincide or overlap on a Cartesian copy (the audit's
        frames, :mod:`exactsym.audit.frames`): a similarity is one-to-one, and one of scale
        at least 1 cannot make fat robots overlap; on a million robots the test cost a
        second per frame."""
        sim = similarity
        if self.radii is not None and sim.keeps_polar:
            turn = sim.turn if sim.turn is not None else fmpq(0)
            scale = fmpq(sim.scale)
            moved = {i: Polar(r * scale, (-t if sim.reflect else t) + turn)
                     for i, (r, (_, t)) in enumerate(zip(self.radii, self.polar))}
            if not (self.specs and all(spec.is_polar for spec in self.specs)):
                return self.with_positions(moved)
            # radii written as expressions (sqrt(1499)): the copy's Cartesian points are
            # evaluated from the same expressions, as the file's are -- the values of
            # irrational radii alone do not name their field
            polar = [(p.r * p.r, normal_turn(p.turn) if sign(p.r) != 0 else fmpq(0))
                     for p in moved.values()]
            new = self._same(polar=polar, radii=[p.r for p in moved.values()],
                             polar_system=self.polar_system,
                             specs=[_polar_spec(spec, scale, sim.reflect, turn)
                                    for spec in self.specs])
            _check_move(new)
            return new
        coerce = self.system.coerce
        if sim.rotation is not None:
            c, s = coerce(sim.rotation[0]), coerce(sim.rotation[1])
        elif sim.turn is not None:
            c, s = self.system.cos_turn(sim.turn), self.system.sin_turn(sim.turn)
        else:
            c, s = coerce(1), coerce(0)
        k = coerce(sim.scale)
        dx, dy = (coerce(v) for v in (sim.shift or (0, 0)))
        new = self._same(points=_similar_points(self.points, sim, c, s, k, dx, dy),
                         system=self.system)
        if check:
            _check_move(new)
        return new


def _similar_points(points, sim: Similarity, c, s, k, dx, dy) -> list:
    """The Cartesian ``points`` reflected (y -> -y), turned by (c, s), scaled by k and
    shifted by (dx, dy), as ``sim`` says, in that order."""
    turns = sim.rotation is not None or sim.turn is not None
    if sim.reflect and not turns and sim.scale == 1 and sim.shift is None:
        return [(x, -y) for x, y in points]
    if not sim.reflect and turns and sim.shift is not None:
        # k (c x - s y) + dx = (k c) x - (k s) y + dx: the same exact values with two
        # products fewer per point
        if sim.scale != 1:
            c, s = k * c, k * s
        return [(c * x - s * y + dx, s * x + c * y + dy) for x, y in points]
    out = []
    for x, y in points:
        if sim.reflect:
            y = -y
        if turns:
            x, y = c * x - s * y, s * x + c * y
        if sim.scale != 1:
            x, y = k * x, k * y
        if sim.shift is not None:
            x, y = x + dx, y + dy
        out.append((x, y))
    return out


def _polar_spec(spec: PointSpec, scale, reflect: bool, turn) -> PointSpec:
    """``spec`` (polar) reflected, turned by ``turn`` and scaled by ``scale`` about the
    origin: the radius expression times the scale, the turn moved alike."""
    r = spec.r if scale == 1 else BinOp("*", Const(Fraction(int(scale.p), int(scale.q))),
                                         spec.r)
    t = Fraction(int(turn.p), int(turn.q)) + (-spec.turn if reflect else spec.turn)
    return dataclasses.replace(spec, r=r, turn=t - math.floor(t))


def to_text(x) -> str:
    """The exact text of a number (the file format's syntax: it reads back)."""
    from ..exact import number_text
    return number_text(x)


def to_sympy(value):
    """An exact number, a point or a :class:`Configuration` as sympy numbers, built from
    the number's exact text (:func:`exactsym.io.sympy_trees.sympy_of_tree`).

    >>> from exactsym import load, to_sympy
    >>> to_sympy(load("cases/examples/chiral-nine-gon.toml").points[1])
    (-2, 2*sqrt(3))
    """
    from ..io.expr import parse_expression
    from ..io.sympy_trees import sympy_of_tree
    if isinstance(value, Configuration):
        return value.to_sympy()
    if isinstance(value, tuple):
        return tuple(to_sympy(v) for v in value)
    return sympy_of_tree(parse_expression(to_text(value), written=True))


def _needs_reading(value) -> bool:
    from ..io.sympy_trees import is_sympy
    return isinstance(value, (str, float)) or is_sympy(value)


def _tree(value, index: int, axis: str, source: str) -> Node:
    """The expression tree of one number handed to :meth:`Configuration.from_points`."""
    from fractions import Fraction
    from ..exact import as_fmpq
    from ..io.expr import parse_expression
    from ..io.sympy_trees import is_sympy, tree_of_sympy
    where = f"point {index}, {axis}"
    if isinstance(value, float):
        raise InputError(f"{where} = {value!r}: a float is not exact; write it as a string "
                         f"('{value!r}') or a Fraction", source)
    try:
        if isinstance(value, str):
            return parse_expression(value)
        if is_sympy(value):
            return tree_of_sympy(value)
    except ExpressionError as err:
        at = f" (at character {err.offset + 1})" if isinstance(value, str) else ""
        raise InputError(f"{where} = {value!r}: {err.message}{at}", source) from None
    try:
        q = as_fmpq(value)                  # int, Fraction, fmpz, fmpq
    except TypeError:
        raise TypeError(f"{where}: not an exact number: {value!r}") from None
    return Const(Fraction(int(q.p), int(q.q)))


def _read_values(pts: list, source: str):
    """``(system, points)``: numbers handed to the API evaluated in one number system, as
    a file's expressions are."""
    exprs = []
    for i, p in enumerate(pts):
        if len(p) != 2:
            raise InputError(f"point {i}: not an (x, y) pair", source)
        exprs += [_tree(v, i, axis, source) for v, axis in zip(p, "xy")]
    try:
        system = number_system(exprs, ())
        values = [evaluate(e, system) for e in exprs]
    except ExpressionError as err:
        index = getattr(err, "index", None)
        where = f"point {index // 2}, {'xy'[index % 2]}: " if index is not None else ""
        raise InputError(where + err.message, source) from None
    return system, list(zip(values[::2], values[1::2]))


def _locate(err: ExpressionError, spec: PointSpec, which: int, source: str) -> InputError:
    column = spec.columns[which] + err.offset if which < len(spec.columns) else spec.column
    return err.located(source, spec.line, column)


def _expressions(specs: Sequence[PointSpec], polar_only: bool):
    """``(exprs, owners)``: the expressions to evaluate and ``(spec, slot)`` for each."""
    exprs, owners = [], []
    for spec in specs:
        if spec.is_polar:
            exprs.append(spec.r)
            owners.append((spec, 0))
        elif not polar_only:
            exprs.extend((spec.x, spec.y))
            owners.extend(((spec, 0), (spec, 1)))
    return exprs, owners


def _system_and_values(exprs: list[Node], owners, turns, source: str):
    if not turns and all(type(e) is Const for e in exprs):   # plain rationals: Q, no scan
        return RationalSystem(), [fmpq(e.value.numerator, e.value.denominator) for e in exprs]
    try:
        system = number_system(exprs, turns)
    except ExpressionError as err:
        index = getattr(err, "index", None)
        if index is not None:
            spec, slot = owners[index]
            raise _locate(err, spec, slot, source) from None
        raise err.located(source) from None
    except InputError as err:     # the numbers together need too large a field: the
        # refusal is of the whole list, located at its first point (docs/format.md
        # promises file:line:col for every input error)
        spec = owners[0][0] if owners else None
        raise err.located(source, getattr(spec, "line", None),
                          getattr(spec, "column", None)) from None
    if isinstance(system, RationalSystem) and all(type(e) is Const for e in exprs):
        return system, [fmpq(e.value.numerator, e.value.denominator) for e in exprs]
    values = []
    for expr, (spec, slot) in zip(exprs, owners):
        try:
            values.append(evaluate(expr, system))
        except ExpressionError as err:
            raise _locate(err, spec, slot, source) from None
    return system, values


def _cartesian(specs: Sequence[PointSpec], source: str = "<memory>"):
    exprs, owners = _expressions(specs, polar_only=False)
    turns = [spec.turn for spec in specs if spec.is_polar]
    system, values = _system_and_values(exprs, owners, [fmpq(t.numerator, t.denominator)
                                                        for t in turns], source)
    points, k = [], 0
    for spec in specs:
        if spec.is_polar:
            r = values[k]
            k += 1
            if r < 0:
                raise InputError("polar radius must be >= 0", source, spec.line, spec.column)
            t = fmpq(spec.turn.numerator, spec.turn.denominator)
            points.append((r * system.cos_turn(t), r * system.sin_turn(t)))
        else:
            points.append((values[k], values[k + 1]))
            k += 2
    return system, points


def _cartesian_of_polar(radii, turns):
    """Cartesian points of polar positions given by exact values (a configuration made
    by moves): rational radii only (the field of irrational radii and of the turns'
    cosines is not built from values)."""
    rational = []
    for r in radii:
        if is_algebraic(r):
            if not r.is_rational():
                raise NotImplementedError("Cartesian coordinates of moved robots at "
                                          "irrational radii are not built")
            r = r.to_fmpq()
        rational.append(r)
    system = number_system((), turns)
    return system, [(system.coerce(r) * system.cos_turn(t),
                     system.coerce(r) * system.sin_turn(t)) for r, t in zip(rational, turns)]


def _cartesian_position(p, system):
    if isinstance(p, Polar):
        r = system.coerce(p.r)
        return r * system.cos_turn(p.turn), r * system.sin_turn(p.turn)
    return p


def _check_move(config: Configuration) -> None:
    pair = _coincident(config)
    if pair is not None:
        raise MoveImpossible(f"robots {pair[0]} and {pair[1]} would coincide")
    if config.model == "fat":
        pair = _overlapping(config)
        if pair is not None:
            raise MoveImpossible(f"fat robots {pair[0]} and {pair[1]} would overlap")


def from_file(config_file: ConfigFile) -> Configuration:
    """Evaluate and validate a parsed configuration file (raises :class:`InputError`)."""
    specs = config_file.points
    common = dict(source=config_file.source, name=config_file.name, notes=config_file.notes,
                  model=config_file.model, lemmas=config_file.lemmas,
                  expect=config_file.expect, specs=specs)
    if isinstance(specs, PlainPoints):        # "p/q p/q" lines only: exact values directly
        config = Configuration(points=specs.rationals, system=RationalSystem(), **common)
    elif all(spec.is_polar for spec in specs):
        exprs, owners = _expressions(specs, polar_only=True)
        system, radii = _system_and_values(exprs, owners, (), config_file.source)
        polar = []
        for spec, r in zip(specs, radii):
            if r < 0:
                raise InputError("polar radius must be >= 0", config_file.source, spec.line,
                                 spec.column)
            turn = normal_turn(fmpq(spec.turn.numerator, spec.turn.denominator)) \
                if r != 0 else fmpq(0)
            polar.append((r * r, turn))
        config = Configuration(polar=polar, polar_system=system, radii=radii, **common)
    else:
        system, points = _cartesian(specs, config_file.source)
        config = Configuration(points=points, system=system, **common)
    check_distinct(config)
    if config.model == "fat":
        check_fat(config)
    return config


@contextmanager
def no_cycle_collection():
    """Pause the cyclic garbage collector: reading and analysing build millions of small
    acyclic objects, and the collector's passes over them doubled the running time."""
    was_enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if was_enabled:
            gc.enable()


def load(path) -> Configuration:
    """Read, evaluate and validate a configuration file (``"-"`` is standard input;
    the format: ``docs/format.md``).  Returns a :class:`Configuration` whose points are
    exact; raises :class:`~exactsym.errors.InputError` (``file:line:col: ...``) on
    unusable input.

    >>> from exactsym import load
    >>> config = load("cases/examples/chiral-nine-gon.toml")
    >>> config.n, config.model, config.name
    (9, 'points', 'Nine robots with threefold rotational symmetry and no mirror')
    >>> x, y = config.points[1]           # r = 4 at 1/3 turn: (-2, 2*sqrt(3)), exact
    >>> x == -2, y * y == 12, y > 0
    (True, True, True)
    >>> load("no/such/file.toml")
    Traceback (most recent call last):
    ...
    exactsym.errors.InputError: no/such/file.toml: no such file
    """
    with no_cycle_collection():
        return from_file(read_config(path))


def _coincident(config: Configuration) -> tuple[int, int] | None:
    """The first two indices of coincident points, or None."""
    if config.polar is None and config.n >= 64 and is_plain_rational(config.points[0][0]):
        candidates = _equal_float_groups(config.points, config.float_points)
        if candidates is not None:
            return _first_coincident(config.points, candidates)
    if config.polar is None and config.n >= 3 and any(
            dense_field(c) is not None for p in config.points for c in p):
        return _coincident_irrational(config)      # polynomials: hashing them is slow
    seen: dict = {}
    keys = config.polar if config.polar is not None else config.points
    for i, (a, b) in enumerate(keys):
        if config.polar is not None and a == 0:
            b = fmpq(0)                      # every angle names the origin
        j = seen.setdefault((exact_key(a), exact_key(b)), i)
        if j != i:
            return j, i
    return None


def _coincident_irrational(config: Configuration) -> tuple[int, int] | None:
    """:func:`_coincident` for points with irrational coordinates: Arb balls of the
    coordinates (kept for the levels, ``algebraic_filtered.coordinate_balls``) separate
    the points whose balls are disjoint; only points whose balls overlap in both
    coordinates are compared exactly (hashing a polynomial of degree 960 per coordinate
    cost more than the rest of the truth, issue 9; a multiquadratic or tower element
    hashes faster than it is enclosed, so those keep the dictionary scan)."""
    from .algebraic_filtered import coordinate_balls, overlapping_pairs
    points = config.points
    xs, ys = coordinate_balls(points, specs=config.specs or None)
    best = None
    for j, i in overlapping_pairs(xs, ys):         # j < i
        if points[i][0] == points[j][0] and points[i][1] == points[j][1]:
            if best is None or i < best[1] or (i == best[1] and j < best[0]):
                best = (j, i)
    return best


def _equal_float_groups(points, floats=None):
    """Groups (lists of indices, at least two) of rational points whose correctly rounded
    float pairs are equal: equal points have equal floats, so coincident points are only
    to be looked for inside these groups.  None if a float is not finite.  ``floats``:
    ``float_coordinates(points)``, if known."""
    floats = floats if floats is not None else float_coordinates(points)
    if floats is None:
        return None
    fx, fy = floats
    order = np.lexsort((fy, fx))
    same = (np.diff(fx[order]) == 0) & (np.diff(fy[order]) == 0)
    if not same.any():
        return []
    groups, current = [], None
    for a in np.flatnonzero(same).tolist():
        if current is not None and current[-1] == order[a]:
            current.append(int(order[a + 1]))
        else:
            current = [int(order[a]), int(order[a + 1])]
            groups.append(current)
    return groups


def _first_coincident(points, groups) -> tuple[int, int] | None:
    """As the dictionary scan of :func:`_coincident`: the least i with an equal earlier
    point, and the first such point j; compared exactly inside each float group."""
    best = None
    for group in groups:
        seen: dict = {}
        for i in sorted(group):
            x, y = points[i]
            j = seen.setdefault((exact_key(x), exact_key(y)), i)
            if j != i:
                if best is None or i < best[1]:
                    best = (j, i)
                break
    return best


def _overlapping(config: Configuration) -> tuple[int, int] | None:
    """Two fat robots (unit discs) that overlap (centres closer than 2), or None."""
    pts = config.points
    order = sorted(range(config.n), key=lambda i: pts[i][0])
    for a, i in enumerate(order):
        for j in order[a + 1:]:
            dx = pts[j][0] - pts[i][0]
            if dx >= 2:
                break
            dy = pts[j][1] - pts[i][1]
            if dx * dx + dy * dy < 4:
                lo, hi = sorted((i, j))
                return lo, hi
    return None


def check_distinct(config: Configuration) -> None:
    """Raise :class:`InputError` naming the first two indices of coincident points."""
    pair = _coincident(config)
    if pair is not None:
        raise InputError(f"points {pair[0]} and {pair[1]} coincide", config.source,
                         _line(config, pair[1]))


def check_fat(config: Configuration) -> None:
    """Unit discs must not overlap: centres at distance >= 2 (touching is allowed)."""
    pair = _overlapping(config)
    if pair is not None:
        raise InputError(f"fat robots {pair[0]} and {pair[1]} overlap (centres closer "
                         "than 2)", config.source, _line(config, pair[1]))


def _line(config: Configuration, i: int) -> int | None:
    return config.specs[i].line if i < len(config.specs) else None
