"""A configuration: robot positions as exact numbers, validated.

:func:`load` reads a file (:mod:`exactsym.fileformat`), evaluates every expression in
one number system (:mod:`exactsym.exact`) and checks validity (distinct points,
``r >= 0``, fat robots at distance >= 2).  A configuration whose points are all
polar keeps them as ``(r^2, turn)`` too: about the origin, radii and angles are
then rationals and need no trigonometry, which keeps polar polygons with
thousands of vertices cheap (``docs/numbers.md``); Cartesian coordinates are
built on first use.
"""

from __future__ import annotations

import gc
from contextlib import contextmanager
from functools import cached_property
from typing import Iterable, Mapping, Sequence

from .fileformat import ConfigFile, PointSpec, read_config
from .errors import ExpressionError, InputError
from .exact import RationalSystem, evaluate, exact_key, fmpq, normal_turn, number_system
from .exprtree import Const, Node


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
                 polar: Sequence | None = None, polar_system=None):
        self.source = source
        self.name = name
        self.notes = notes
        self.model = model
        self.lemmas = tuple(lemmas)
        self.expect = dict(expect or {})
        self.specs = tuple(specs)
        self.polar = tuple(polar) if polar is not None else None
        self.polar_system = polar_system
        if points is not None:
            self.__dict__["points"] = tuple(tuple(p) for p in points)
            self.__dict__["system"] = system
        self.n = len(points) if points is not None else len(self.polar)

    @classmethod
    def from_points(cls, points: Iterable, system=None, **kw) -> "Configuration":
        """From exact ``(x, y)`` pairs (``fmpq``, ``int``, ``Fraction`` or field elements)."""
        from .exact import RationalSystem, as_fmpq
        pts = []
        for x, y in points:
            if system is None:
                x, y = as_fmpq(x), as_fmpq(y)
            pts.append((x, y))
        config = cls(points=pts, system=system or RationalSystem(), **kw)
        check_distinct(config)
        return config

    @cached_property
    def system(self):
        return _cartesian(self.specs, self.source)[0]

    @cached_property
    def points(self) -> tuple:
        system, pts = _cartesian(self.specs, self.source)
        self.__dict__["system"] = system
        return tuple(pts)


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
    try:
        system = number_system(exprs, turns)
    except ExpressionError as err:
        index = getattr(err, "index", None)
        if index is not None:
            spec, slot = owners[index]
            raise _locate(err, spec, slot, source) from None
        raise err.located(source) from None
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


def from_file(config_file: ConfigFile) -> Configuration:
    """Evaluate and validate a parsed configuration file (raises :class:`InputError`)."""
    specs = config_file.points
    common = dict(source=config_file.source, name=config_file.name, notes=config_file.notes,
                  model=config_file.model, lemmas=config_file.lemmas,
                  expect=config_file.expect, specs=specs)
    if all(spec.is_polar for spec in specs):
        exprs, owners = _expressions(specs, polar_only=True)
        system, radii = _system_and_values(exprs, owners, (), config_file.source)
        polar = []
        for spec, r in zip(specs, radii):
            if r < 0:
                raise InputError("polar radius must be >= 0", config_file.source, spec.line,
                                 spec.column)
            turn = normal_turn(fmpq(spec.turn.numerator, spec.turn.denominator)) if r != 0 else fmpq(0)
            polar.append((r * r, turn))
        config = Configuration(polar=polar, polar_system=system, **common)
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
    """Read, evaluate and validate a configuration file (``"-"`` is standard input)."""
    with no_cycle_collection():
        return from_file(read_config(path))


def check_distinct(config: Configuration) -> None:
    """Raise :class:`InputError` naming the first two indices of coincident points."""
    seen: dict = {}
    keys = config.polar if config.polar is not None else config.points
    for i, (a, b) in enumerate(keys):
        if config.polar is not None and a == 0:
            b = fmpq(0)                      # every angle names the origin
        j = seen.setdefault((exact_key(a), exact_key(b)), i)
        if j != i:
            raise InputError(f"points {j} and {i} coincide", config.source, _line(config, i))


def check_fat(config: Configuration) -> None:
    """Unit discs must not overlap: centres at distance >= 2 (touching is allowed)."""
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
                raise InputError(f"fat robots {lo} and {hi} overlap (centres closer than 2)",
                                 config.source, _line(config, hi))


def _line(config: Configuration, i: int) -> int | None:
    return config.specs[i].line if i < len(config.specs) else None
