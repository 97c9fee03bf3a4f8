"""Reading configuration files (format 1, ``docs/format.md``) into an unevaluated description.

The expressions are parsed (:mod:`exactsym.io.expr`) but not evaluated: the number
kernel evaluates them and checks what needs exact numbers (distinct points,
fat robots at distance >= 2, r >= 0, square roots of negative numbers).
Every problem a user can cause raises :class:`~exactsym.errors.InputError`
naming the file, and the line and column where known.
"""

from __future__ import annotations

import re
import sys
import tomllib
import types
from dataclasses import dataclass, field
from fractions import Fraction
from pathlib import Path
from typing import Mapping, Sequence

from flint import fmpq

from ..errors import ExpressionError, InputError
from .expr import MAX_LENGTH, parse_expression, tokenize
from .exprtree import Const, Node
from ..labels import is_label, unknown_label_message


class ExpressionText(str):
    """Marker type for :data:`EXPECT_KEYS`: a string holding an expression (checked to parse)."""


#: Allowed ``[expect]`` keys and the Python type of their values (the keys of
#: :data:`exactsym.report.check.EXPECTATIONS`, which compares them with the report).
EXPECT_KEYS: dict[str, type | tuple] = {
    "orderable": bool,
    "group": str,
    "paper_orderable": bool,
    "n": int,
    "sec_radius_squared": ExpressionText,
    "levels": int,
    # the paper on each level polygon (exactsym.paper.polygon_report): a single value is the
    # outermost level's, an array has one value per level, nearest first ("none" for null)
    "paper_symmetric": (bool, list),
    "paper_straight": (bool, list),
    "paper_skew": (bool, list),
    "paper_degree": (int, str, list),
    "paper_type": (str, list),
    "paper_lines_by_strings": (int, list),
    "paper_theorem1_symmetric": (bool, list),
    "paper_loop_terminates": (bool, str, list),
    "paper_def_straight": (bool, list),
    "paper_def_skew": (bool, list),
    "paper_def_mirrors": (int, list),
    "paper_leader_sym": (int, str, list),
    "paper_leader_sym_by_lines": (int, str, list),
    "paper_leader_asym": (int, str, list),
    "paper_leader_asym_mirrored": (int, str, list),
    # the paper on the whole configuration (exactsym.paper.family)
    "paper_leader": int,            # the robot ElectLeader elects; -1: none
    "audit_agrees": bool,           # exactsym.audit.statements finds no false statement
    "audit_false": list,            # the labels it finds false, exactly (any order)
    # the gathering simulator (exactsym.gathering.cases): the outcome and the run's setting
    "gather_outcome": str, "gather_label": str, "gather_invariant": str,
    "gather_robots": list, "gather_time": str, "gather_scheduler": str, "gather_seed": int,
    "gather_readings": list, "gather_invariants": list, "gather_max_events": int,
    "gather_non_rigid": ExpressionText, "gather_algorithm": str,
    "gather_mid_run": bool,         # the start is a state inside a run (robots may touch)
}

TOP_LEVEL_KEYS = ("format", "name", "notes", "model", "lemmas", "points", "expect")
MODELS = ("points", "fat")


@dataclass(frozen=True)
class PointSpec:
    """One robot position as written: Cartesian (``x``, ``y``) or polar (``r``, ``turn``).

    ``index`` is 0-based in file order; ``line`` and ``column`` (1-based) locate the
    point, ``texts`` are its expression strings and ``columns`` their first columns
    (exact for plain text, best effort for TOML).
    """
    index: int
    line: int
    column: int
    x: Node | None = None
    y: Node | None = None
    r: Node | None = None
    turn: Fraction | None = None
    texts: tuple[str, ...] = ()
    columns: tuple[int, ...] = ()

    @property
    def is_polar(self) -> bool:
        return self.r is not None


@dataclass(frozen=True)
class ConfigFile:
    """A configuration file as read: points unevaluated, ``expect`` validated (read-only)."""
    source: str
    points: tuple[PointSpec, ...]
    name: str | None = None
    notes: str | None = None
    model: str = "points"
    lemmas: tuple[str, ...] = ()
    expect: Mapping[str, object] = field(default_factory=dict)


# ---------------------------------------------------------------- reading files

_TOML_SNIFF = re.compile(r"\A(?:[ \t]*(?:#[^\n]*)?\r?\n)*[ \t]*format[ \t]*=")


def read_config(path: str | Path) -> ConfigFile:
    """Read a configuration file; ``"-"`` reads standard input.

    A ``.toml`` file is TOML; anything else (``.txt``, other names, standard
    input) is plain text, unless its first line that is not blank or a comment
    starts with ``format =``, when it is TOML.  Returns the
    :class:`ConfigFile`; raises :class:`InputError` naming the file if it does
    not exist, is a directory, cannot be read, is not UTF-8 or is malformed.
    """
    if str(path) == "-":
        source = "<stdin>"
        stream = getattr(sys.stdin, "buffer", None)
        data = stream.read() if stream is not None else sys.stdin.read().encode("utf-8")
    else:
        source = str(path)
        try:
            data = Path(path).read_bytes()
        except FileNotFoundError:
            raise InputError("no such file", source) from None
        except IsADirectoryError:
            raise InputError("is a directory, not a configuration file", source) from None
        except OSError as err:
            raise InputError(f"cannot read: {err.strerror or err}", source) from None
    try:
        text = data.decode("utf-8-sig")
    except UnicodeDecodeError as err:
        line = data.count(b"\n", 0, err.start) + 1
        column = err.start - (data.rfind(b"\n", 0, err.start) + 1) + 1
        raise InputError("not UTF-8 text", source, line, column) from None
    is_toml = source.lower().endswith(".toml") or _TOML_SNIFF.match(text) is not None
    return parse_config_text(text, source, "toml" if is_toml else "txt")


def parse_config_text(text: str, source: str, kind: str) -> ConfigFile:
    """Parse the text of a configuration; ``kind`` is ``"toml"`` or ``"txt"``.

    Returns the :class:`ConfigFile`; raises :class:`InputError` (an
    :class:`ExpressionError` for a bad expression) located in ``source``.
    """
    if kind == "toml":
        return _parse_toml(text, source)
    if kind == "txt":
        return _parse_txt(text, source)
    raise ValueError(f"unknown configuration kind {kind!r}")


def _rational_turn(node: Node, source: str, line: int | None, column: int | None) -> Fraction:
    """Return the value of a polar ``turn``; raise InputError unless it folded to a rational."""
    if not isinstance(node, Const):
        raise InputError("turn must be a rational number (a fraction of a full turn, "
                         "such as 1/3)", source, line, column)
    return node.value


# ---------------------------------------------------------------- plain text

_SPACE = " \t\r\n\f\v"
MAX_LINE = 2 * MAX_LENGTH + 100   # characters of one plain-text point (comment excluded)


def _parse_txt(text: str, source: str) -> ConfigFile:
    """Plain text: one point per line (``x y``, ``x, y`` or ``polar r turn``), ``#`` comments."""
    points: list = []
    simple_line = _SIMPLE_PAIR.fullmatch
    plain = True        # every point so far a "p/q p/q" line (kept as PlainPoints)
    numbers, lines = [], []
    for number, raw in enumerate(text.split("\n"), start=1):
        simple = simple_line(raw)
        if simple:     # fast path: "p/q p/q" with nothing else on the line (most large inputs)
            _, x_num, x_den, _, y_num, y_den = simple.groups()
            if plain:
                points.append((fmpq(int(x_num), int(x_den)) if x_den else fmpq(int(x_num)),
                               fmpq(int(y_num), int(y_den)) if y_den else fmpq(int(y_num))))
                numbers.append(number)
                lines.append(raw)
            else:
                points.append(_plain_spec(len(points), number, simple))
            continue
        line = raw.split("#", 1)[0]
        start = len(line) - len(line.lstrip(_SPACE))
        if start == len(line):
            continue
        if plain:
            points = [_plain_spec(k, numbers[k], simple_line(lines[k]))
                      for k in range(len(lines))]
            plain = False
        polar = re.match(r"polar(?![A-Za-z0-9_])", line[start:]) is not None
        (t1, c1, e1), (t2, c2, e2) = _txt_pair(line, start + 5 if polar else start,
                                               source, number)
        if polar:
            point = PointSpec(len(points), number, start + 1, r=e1,
                              turn=_rational_turn(e2, source, number, c2),
                              texts=(t1, t2), columns=(c1, c2))
        else:
            point = PointSpec(len(points), number, start + 1, x=e1, y=e2,
                              texts=(t1, t2), columns=(c1, c2))
        points.append(point)
    if not points:
        raise InputError("no points: write one point per line, as 'x y', 'x, y' or "
                         "'polar r turn'", source)
    if plain:
        return ConfigFile(source=source, points=PlainPoints(numbers, lines, points))
    return ConfigFile(source=source, points=tuple(points))


def _plain_spec(index: int, number: int, simple: re.Match) -> PointSpec:
    x_text, x_num, x_den, y_text, y_num, y_den = simple.groups()
    x_col, y_col = simple.start(1) + 1, simple.start(4) + 1
    return PointSpec(index, number, x_col,
                     x=Const(Fraction(int(x_num), int(x_den)) if x_den else Fraction(int(x_num))),
                     y=Const(Fraction(int(y_num), int(y_den)) if y_den else Fraction(int(y_num))),
                     texts=(x_text, y_text), columns=(x_col, y_col))


class PlainPoints(Sequence):
    """The points of a plain-text file whose every point is a ``p/q p/q`` line: the lines
    and their numbers, and the values as ``fmpq`` pairs (:attr:`rationals`, the numbers as
    written, reduced).  :class:`PointSpec` objects (expression trees, for messages) are
    built on access: on 100,000 points they cost more than the whole float baseline
    (issue 9).  Equal to the tuple of its specs."""

    __slots__ = ("numbers", "lines", "rationals")

    def __init__(self, numbers: list[int], lines: list[str], rationals: list[tuple]):
        self.numbers, self.lines, self.rationals = numbers, lines, rationals

    def __len__(self) -> int:
        return len(self.lines)

    def __getitem__(self, index):
        if isinstance(index, slice):
            return tuple(self)[index]
        n = len(self.lines)
        if not -n <= index < n:
            raise IndexError(index)
        index %= n
        return _plain_spec(index, self.numbers[index], _SIMPLE_PAIR.fullmatch(self.lines[index]))

    def __eq__(self, other):
        return isinstance(other, Sequence) and tuple(self) == tuple(other)

    __hash__ = None


# Digit runs are capped below Python's int-from-string limit (4300 digits): longer numbers
# take the general path, which enforces the documented 5,000-digit bound (expr.MAX_DIGITS).
_SIMPLE_PAIR = re.compile(r"[ \t]*(([+-]?[0-9]{1,4000})(?:/([0-9]{0,3999}[1-9][0-9]{0,3999}))?)"
                          r"(?:[ \t]+|[ \t]*,[ \t]*)"
                          r"(([+-]?[0-9]{1,4000})(?:/([0-9]{0,3999}[1-9][0-9]{0,3999}))?)[ \t\r]*")


def _txt_pair(line: str, body: int, source: str, number: int) -> list[tuple[str, int, Node]]:
    """Split ``line[body:]`` into two expressions and parse them.

    Returns ``[(text, column, tree), (text, column, tree)]`` (1-based columns);
    raises ExpressionError located at the offending character of the line.
    """
    simple = _SIMPLE_PAIR.fullmatch(line, body)
    if simple:       # fast path for "p/q p/q" lines (non-zero q): the general splitter agrees
        x_text, x_num, x_den, y_text, y_num, y_den = simple.groups()
        return [(x_text, simple.start(1) + 1,
                 Const(Fraction(int(x_num), int(x_den)) if x_den else Fraction(int(x_num)))),
                (y_text, simple.start(4) + 1,
                 Const(Fraction(int(y_num), int(y_den)) if y_den else Fraction(int(y_num))))]
    try:
        spans = _split_pair(line[body:])
    except ExpressionError as err:
        raise err.located(source, number, body + err.offset + 1) from None
    result = []
    for a, b in spans:
        a, b = body + a, body + b
        while a < b and line[a] in _SPACE:
            a += 1
        while b > a and line[b - 1] in _SPACE:
            b -= 1
        try:
            result.append((line[a:b], a + 1, parse_expression(line[a:b])))
        except ExpressionError as err:
            raise err.located(source, number, a + err.offset + 1) from None
    return result


def _split_pair(text: str) -> list[tuple[int, int]]:
    """Return the spans ``[(a1, b1), (a2, b2)]`` of the two expressions written in ``text``.

    Rule (``docs/format.md``): a comma outside parentheses separates them.
    Otherwise they are separated at a *gap*: whitespace outside parentheses
    after the end of an operand (a number, a name other than sqrt/cos/sin, or
    ``)``) and before the start of another (a number, a name, ``(``: a *hard*
    gap) or before a sign ``+``/``-`` (a *soft* gap, as in ``1 -2``).  A hard
    gap can never lie inside one expression, so a line with one hard gap is
    split there, and with two or more it has too many expressions; without a
    hard gap, a single soft gap is the split, and several soft gaps
    (``1 - 2 -3``) would each give a reading: that is an error asking for a
    comma.  So a line is accepted exactly when it has one reading as two
    expressions.  Raises ExpressionError (offset in ``text``) otherwise.
    """
    if len(text.rstrip(_SPACE)) > MAX_LINE:
        raise ExpressionError(f"line is too long (at most {MAX_LINE} characters)",
                              offset=MAX_LINE)
    tokens = tokenize(text)
    depth = 0
    for token in tokens:
        if token.kind == "bad" and token.text == "," and depth == 0:
            return [(0, token.offset), (token.end, len(text))]
        if token.kind == "op" and token.text in "()":
            depth += 1 if token.text == "(" else -1
    hard, soft = [], []
    depth = 0
    for index, (prev, token) in enumerate(zip(tokens, tokens[1:]), start=1):
        if prev.kind == "op" and prev.text in "()":
            depth += 1 if prev.text == "(" else -1
        operand_end = (prev.kind == "number" or (prev.kind == "op" and prev.text == ")")
                       or (prev.kind == "name" and prev.text not in ("sqrt", "cos", "sin")))
        if depth != 0 or not operand_end or prev.end == token.offset:
            continue
        if token.kind in ("number", "name") or (token.kind == "op" and token.text == "("):
            hard.append(index)
        elif token.kind == "op" and token.text in "+-":
            soft.append(index)
    gaps = hard or soft
    if len(hard) > 1:
        raise ExpressionError("more than two expressions on the line (write 'x y' or 'x, y')",
                              offset=tokens[hard[1]].offset)
    if not gaps:
        parse_expression(text)   # raises the error, if there is one
        raise ExpressionError("expected two expressions, x and y (write 'x y' or 'x, y')",
                              offset=len(text.rstrip(_SPACE)))
    spans = [(0, tokens[gaps[0] - 1].end), (tokens[gaps[0]].offset, len(text))]
    if len(gaps) > 1:
        for a, b in spans:
            try:
                parse_expression(text[a:b])
            except ExpressionError as err:
                raise ExpressionError(err.message, offset=a + err.offset) from None
        raise ExpressionError("ambiguous: the line reads as two expressions in several ways "
                              "(a sign after a space can start y); separate x and y with a comma",
                              offset=tokens[gaps[1]].offset)
    return spans


# ---------------------------------------------------------------- TOML

class _TomlFloat:
    """What ``tomllib`` gives for a TOML float here: the text, never a rounded float."""

    def __init__(self, text: str):
        self.text = text


_TYPE_NAMES = {bool: "true or false", int: "an integer", str: "a string",
               ExpressionText: "an expression string", list: "an array", dict: "a table",
               _TomlFloat: "a float"}


def _describe(value: object) -> str:
    for kind in (bool, _TomlFloat, int, str, list, dict):
        if isinstance(value, kind):
            return _TYPE_NAMES[kind]
    return f"a {type(value).__name__}"


def _has_type(value: object, expected: type | tuple) -> bool:
    """``isinstance`` for TOML values: a boolean is not an integer, an ExpressionText is a str."""
    for kind in expected if isinstance(expected, tuple) else (expected,):
        kind = str if kind is ExpressionText else kind
        if isinstance(value, kind) and not (isinstance(value, bool) and kind is not bool):
            return True
    return False


def _contains_float(value: object) -> bool:
    if isinstance(value, list):
        return any(_contains_float(item) for item in value)
    if isinstance(value, dict):
        return any(_contains_float(item) for item in value.values())
    return isinstance(value, _TomlFloat)


def _show(item: object) -> str:
    if isinstance(item, list):
        return f"an array of length {len(item)}"
    if isinstance(item, dict):
        return "a table with keys " + ", ".join(map(repr, item))
    return _describe(item)


class _Locator:
    """Best-effort positions in TOML text (tomllib reports none for valid files).

    Searches look at most ``WINDOW`` characters past their start, so that
    locating every point of a large file stays linear.
    """
    WINDOW = 10_000

    def __init__(self, text: str):
        self.text = text
        self.line_starts = [0] + [m.end() for m in re.finditer("\n", text)]

    def position(self, index: int) -> tuple[int, int]:
        """1-based (line, column) of the character at ``index``."""
        lo, hi = 0, len(self.line_starts)
        while hi - lo > 1:
            mid = (lo + hi) // 2
            lo, hi = (mid, hi) if self.line_starts[mid] <= index else (lo, mid)
        return lo + 1, index - self.line_starts[lo] + 1

    def key(self, key: str, start: int = 0) -> int | None:
        """Index of the first ``key =`` (or ``[key]`` header) at or after ``start`` (None if
        not found within the window)."""
        name = re.escape(key)
        pattern = (rf"(?:^|[{{,])[ \t]*[\"']?({name})[\"']?[ \t]*[=.]"
                   rf"|^[ \t]*\[\[?[ \t]*({name})[ \t]*\]")
        match = re.compile(pattern, re.M).search(self.text, start, start + self.WINDOW)
        return None if match is None else match.start(1 if match.group(1) else 2)

    def value(self, value: object, start: int) -> int | None:
        """Index of the first character of ``value`` as written (inside its quotes)."""
        if isinstance(value, str):
            end = start + len(value) + 2 + self.WINDOW
            found = [i for i in (self.text.find(q + value + q, start, end) for q in "\"'")
                     if i >= 0]
            return min(found) + 1 if found else None
        written = value.text if isinstance(value, _TomlFloat) else str(value)
        match = re.compile(rf"(?<![\w.+-]){re.escape(written)}(?![\w.])").search(
            self.text, start, start + len(written) + self.WINDOW)
        return None if match is None else match.start()

    @staticmethod
    def width(value: object) -> int:
        """Characters from the start of ``value`` as found by :meth:`value` to past its end."""
        if isinstance(value, _TomlFloat):
            return len(value.text)
        return len(value) + 1 if isinstance(value, str) else len(str(value))

    def key_value(self, key: str, value: object, start: int) -> int | None:
        """Index of the value of ``key = value`` at or after ``start``."""
        index = self.key(key, start)
        return None if index is None else self.value(value, index)


class _TomlReader:
    """Validation of the table ``tomllib`` returned, with best-effort locations."""

    def __init__(self, text: str, source: str):
        self.source = source
        self.where = _Locator(text)

    def error(self, message: str, index: int | None) -> InputError:
        line, column = self.where.position(index) if index is not None else (None, None)
        return InputError(message, self.source, line, column)

    def check(self, data: dict, key: str, expected: type | tuple, what: str) -> None:
        if key in data and not _has_type(data[key], expected):
            raise self.error(f"{what} must be {_TYPE_NAMES[expected]}, not "
                             f"{_describe(data[key])}", self.where.key(key))

    def read(self, data: dict) -> ConfigFile:
        if "format" not in data:
            raise self.error("missing 'format = 1' (the configuration format version)", None)
        if not _has_type(data["format"], int) or data["format"] != 1:
            raise self.error("format must be 1 (this exactsym reads configuration format 1)",
                             self.where.key("format"))
        for key in data:
            if key not in TOP_LEVEL_KEYS:
                raise self.error(f"unknown key {key!r} (the keys are "
                                 f"{', '.join(TOP_LEVEL_KEYS)})", self.where.key(key))
        self.check(data, "name", str, "name")
        self.check(data, "notes", str, "notes")
        self.check(data, "model", str, "model")
        if data.get("model", "points") not in MODELS:
            raise self.error(f"model must be \"points\" or \"fat\", not {data['model']!r}",
                             self.where.key("model"))
        self.check(data, "lemmas", list, "lemmas")
        for lemma in data.get("lemmas", []):
            if not isinstance(lemma, str):
                raise self.error(f"lemmas must be strings, not {_describe(lemma)}",
                                 self.where.key("lemmas"))
        for lemma in data.get("lemmas", []):
            if not is_label(lemma):     # a typo never passes silently (exactsym.labels)
                raise self.error(f"lemmas: {unknown_label_message(lemma)}",
                                 self.where.value(lemma, self.where.key("lemmas") or 0))
        return ConfigFile(source=self.source, points=self.points(data),
                          name=data.get("name"), notes=data.get("notes"),
                          model=data.get("model", "points"),
                          lemmas=tuple(data.get("lemmas", ())),
                          expect=types.MappingProxyType(self.expect(data)))

    def points(self, data: dict) -> tuple[PointSpec, ...]:
        at = self.where.key("points")
        items = data.get("points")
        if items is None:
            raise self.error("missing 'points' (a non-empty array of points)", None)
        if not isinstance(items, list) or not items:
            raise self.error("points must be a non-empty array of points, such as "
                             "[[\"1/2\", \"sqrt(3)/2\"], { r = \"2\", turn = \"1/3\" }]", at)
        cursor = at or 0
        points = []
        for index, item in enumerate(items):
            if isinstance(item, list) and len(item) == 2:
                keys, values, starts = ("x", "y"), item, []
                for value in values:
                    start = self.where.value(value, cursor) \
                        if _has_type(value, (str, int, _TomlFloat)) else None
                    starts.append(start)
                    cursor = cursor if start is None else start + self.where.width(value)
            elif isinstance(item, dict) and set(item) == {"r", "turn"}:
                keys, values = ("r", "turn"), [item["r"], item["turn"]]
                starts = [self.where.key_value(k, v, cursor) for k, v in zip(keys, values)]
                last = max((s for s in starts if s is not None), default=None)
                if last is not None:
                    closing = self.where.text.find("}", last, last + _Locator.WINDOW)
                    cursor = closing + 1 if closing >= 0 else last + 1
            else:
                raise self.error(f"point {index} must be [x, y] or {{ r = ..., turn = ... }}, "
                                 f"not {_show(item)}", at)
            first = self.point_start(starts, at)
            line, column = self.where.position(first)
            texts, columns, trees = zip(*(self.expression(index, k, v, s, first)
                                          for k, v, s in zip(keys, values, starts)))
            if keys == ("x", "y"):
                points.append(PointSpec(index, line, column, x=trees[0], y=trees[1],
                                        texts=texts, columns=columns))
            else:
                turn_at = self.where.position(first if starts[1] is None else starts[1])
                points.append(PointSpec(index, line, column, r=trees[0],
                                        turn=_rational_turn(trees[1], self.source, *turn_at),
                                        texts=texts, columns=columns))
        return tuple(points)

    def point_start(self, starts: list[int | None], fallback: int | None) -> int:
        """Index of the '[' or '{' opening a point (best effort), else of its first value."""
        known = [start for start in starts if start is not None]
        if not known:
            return fallback or 0
        first = min(known)
        text = self.where.text
        line_start = text.rfind("\n", 0, first) + 1
        bracket = max(text.rfind("[", line_start, first), text.rfind("{", line_start, first))
        return bracket if bracket >= 0 else first

    def expression(self, index: int, key: str, value: object, start: int | None,
                   fallback: int) -> tuple[str, int, Node]:
        """Parse one coordinate of point ``index``; return (text, column, tree).

        ``start`` is where the text was found in the file (None: not found, use
        ``fallback``).  Raises InputError / ExpressionError located in the file.
        """
        where = fallback if start is None else start
        if isinstance(value, _TomlFloat):
            raise self.error(f"point {index}: {key} = {value.text} is a TOML float, which is "
                             f"already rounded: quote it, \"{value.text}\", to keep it exact",
                             where)
        if not _has_type(value, (str, int)):
            raise self.error(f"point {index}: {key} must be an expression string or an "
                             f"integer, not {_describe(value)}", where)
        text = value if isinstance(value, str) else str(value)
        try:
            node = parse_expression(text)
        except ExpressionError as err:
            at = where if start is None else start + err.offset
            raise err.located(self.source, *self.where.position(at)) from None
        return text, self.where.position(where)[1], node

    def expect(self, data: dict) -> dict:
        """Return the ``[expect]`` table checked against :data:`EXPECT_KEYS`."""
        expect = data.get("expect", {})
        at = self.where.key("expect")
        if not isinstance(expect, dict):
            raise self.error(f"expect must be a table, not {_describe(expect)}", at)
        for key, value in expect.items():
            where = self.where.key(key, at or 0)
            if key not in EXPECT_KEYS:
                raise self.error(f"unknown [expect] key {key!r} (the keys are "
                                 f"{', '.join(EXPECT_KEYS)})", where)
            kinds = EXPECT_KEYS[key] if isinstance(EXPECT_KEYS[key], tuple) else (EXPECT_KEYS[key],)
            if not _has_type(value, kinds) or _contains_float(value):
                names = " or ".join(_TYPE_NAMES.get(kind, kind.__name__) for kind in kinds)
                raise self.error(f"[expect] {key} must be {names}, not {_describe(value)}", where)
            if ExpressionText in kinds and isinstance(value, str):
                start = None if where is None else self.where.value(value, where)
                try:
                    parse_expression(value, written=True)    # a number as exactsym wrote it
                except ExpressionError as err:
                    at_error = where if start is None else start + err.offset
                    raise err.located(self.source, *(self.where.position(at_error)
                                                     if at_error is not None else ())) from None
        return dict(expect)


_TOML_WHERE = re.compile(r"\s*\((?:at line (\d+), column (\d+)|at end of document)\)$")


def _parse_toml(text: str, source: str) -> ConfigFile:
    """TOML form: returns the ConfigFile, raises InputError."""
    try:
        data = tomllib.loads(text, parse_float=_TomlFloat)
    except RecursionError:
        raise InputError("malformed TOML: nested too deeply", source) from None
    except ValueError as err:   # TOMLDecodeError, and int() past Python's digit limit
        message = str(err)
        match = _TOML_WHERE.search(message)
        line = column = None
        if match:
            message = message[:match.start()]
            if match.group(1):
                line, column = int(match.group(1)), int(match.group(2))
            else:
                line = text.count("\n") + 1
        raise InputError(f"malformed TOML: {message}", source, line, column) from None
    return _TomlReader(text, source).read(data)
