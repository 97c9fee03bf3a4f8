"""The report of ``exactsym check``: JSON and text rendered from one :class:`Analysis`,
and the check of a configuration's ``[expect]`` block.

:func:`report_json` (:mod:`exactsym.report.json_form`) returns a JSON-ready dict with the
keys of ``docs/cli.md``; exact numbers are strings in the configuration syntax.
:func:`report_text` is the summary the command prints without ``--json``
(:mod:`exactsym.report.summary`).  Both read the :class:`~exactsym.analysis.Analysis` only
(nothing is recomputed here).  To add a section: add its part to
:func:`exactsym.analysis.analyse`, then one block to :func:`report_json` and one to the
summary, and its ``[expect]`` keys to :data:`EXPECTATIONS` and
:data:`exactsym.io.fileformat.EXPECT_KEYS`.
"""

from __future__ import annotations

import json
from json.encoder import c_make_encoder, encode_basestring_ascii

from ..analysis import Analysis, Options, analyse
from ..geometry.configuration import Configuration, no_cycle_collection
from ..exact import evaluate, number_system
from ..io.expr import parse_expression
from ..paper.polygon_report import LabelledVerdict
from .json_form import JSONText, LevelEntries, report_json
from .summary import summary_text


#: A list longer than this is written one item per line (items on one line each, by
#: the C encoder), not one number per line: the JSON of 100,000 levels stays readable
#: and is written about ten times faster than by ``json.dumps(indent=2)``.
LONG_LIST = 256

_ITEM = json.JSONEncoder(separators=(", ", ": ")).encode     # the C encoder (no indent)
# The same C encoder made once (``JSONEncoder.encode`` builds one per call: on 100,000
# levels that was a third of the JSON time); no circular check (a report is a tree).
_C_ITEM = c_make_encoder(None, json.JSONEncoder().default, encode_basestring_ascii, None, ": ", ", ", False,
                         False, True) if c_make_encoder is not None else None


#: The encoded text of each dict key seen by :func:`_item`, with ``": "`` (a level entry
#: has the same three or four keys: encoded once, not once per level).  Keyed by the key
#: names the report writes (a fixed set): nothing of one configuration is kept.
_KEY_TEXT: dict = {}


_ONE_ROBOT_LEVEL = ("radius_squared", "points", "paper")


def _item(value) -> str:
    """``_ITEM(value)`` for a dict or list of JSON values."""
    if _C_ITEM is None:
        return _ITEM(value)
    if type(value) is dict:
        paper = value.get("paper")
        if type(paper) is LabelledVerdict and paper.json_parts is not None:
            if len(value) == 3 and tuple(value) == _ONE_ROBOT_LEVEL:
                # the level of one robot (every level of a random configuration)
                r2, points = value["radius_squared"], value["points"]
                if type(r2) is str and type(points) is list and len(points) == 1 \
                        and type(points[0]) is int:
                    return (f'{{"radius_squared": {encode_basestring_ascii(r2)}, '
                            f'"points": [{points[0]!r}], "paper": {paper.json_text()}}}')
            # a level entry whose verdict carries its JSON text (one template per shape)
            out = []
            keys = _KEY_TEXT
            for key, item in value.items():
                head = keys.get(key)
                if head is None:
                    head = keys[key] = encode_basestring_ascii(key) + ": "
                kind = type(item)
                if item is paper:
                    text = paper.json_text()
                elif kind is str:
                    text = encode_basestring_ascii(item)
                elif kind is list and len(item) == 1 and type(item[0]) is int:
                    text = f"[{item[0]!r}]"      # one robot: as the C encoder writes it
                else:
                    text = "".join(_C_ITEM(item, 0))
                out.append(head + text)
            return "{" + ", ".join(out) + "}"
    return "".join(_C_ITEM(value, 0))


#: Types of JSON values that are not containers (a long list of only these, the ordering
#: of 100,000 robots, is recognised without a Python-level pass).
_SCALARS = frozenset((int, float, str, bool, type(None)))


def json_text(report: dict, compact: bool = False) -> str:
    """The text of ``exactsym check --json``: ``report`` (a JSON-ready dict) indented by
    two spaces as ``json.dumps(report, indent=2)`` writes it, except that a list of more
    than :data:`LONG_LIST` items (the levels, the ordering) has one item per line, each
    item on one line (a list of numbers: all on one line); ``compact``: one line."""
    if compact:
        return json.dumps(report)
    out: list = []
    with no_cycle_collection():
        _write(report, "", out)
    return "".join(out)


def write_json(report: dict, stream, compact: bool = False) -> None:
    """:func:`json_text` of ``report`` and a newline, written to ``stream`` as it is made:
    in a cyclotomic field of degree thousands the text is gigabytes, and joining it, then
    encoding it for printing, held two more copies of it."""
    if compact:
        stream.write(json.dumps(report, default=_as_list) + "\n")
        return
    sink = _Sink(stream)
    with no_cycle_collection():
        _write(report, "", sink)
    sink.append("\n")
    sink.flush()


def _as_list(value) -> list:
    """The list a streamed part of a report stands for (``json.dumps``'s ``default``)."""
    if isinstance(value, LevelEntries):
        return value.as_list()
    raise TypeError(f"Object of type {type(value).__name__} is not JSON serializable")


class _Sink:
    """A list-like ``append`` that writes to a stream by pieces of about 4 MB (few writes
    for many small pieces; no copy of the whole text for huge ones)."""

    def __init__(self, stream):
        self.stream, self.pieces, self.size = stream, [], 0

    def append(self, text: str) -> None:
        self.pieces.append(text)
        self.size += len(text)
        if self.size > 1 << 22:
            self.flush()

    def flush(self) -> None:
        if self.pieces:
            self.stream.write("".join(self.pieces))
        self.pieces, self.size = [], 0


def _write(value, pad: str, out: list) -> None:
    """``value`` indented as by ``json.dumps(indent=2)`` at the indentation ``pad``
    (the long lists of :func:`json_text` excepted)."""
    inner = pad + "  "
    if isinstance(value, dict) and value:
        out.append("{")
        sep = "\n"
        for key, item in value.items():
            out.append(sep + inner + json.dumps(str(key)) + ": ")
            _write(item, inner, out)
            sep = ",\n"
        out.append("\n" + pad + "}")
    elif isinstance(value, LevelEntries):
        if len(value) > LONG_LIST:
            _write_items(value, pad, out)
        else:
            _write(value.as_list(), pad, out)
    elif isinstance(value, list) and len(value) > LONG_LIST:
        if set(map(type, value)) <= _SCALARS or all(not isinstance(x, (dict, list))
                                                     for x in value):
            out.append(_item(value))
        else:
            _write_items(value, pad, out)
    elif isinstance(value, list) and value:
        out.append("[")
        sep = "\n"
        for item in value:
            out.append(sep + inner)
            _write(item, inner, out)
            sep = ",\n"
        out.append("\n" + pad + "]")
    else:
        out.append(json.dumps(value))


#: Items of a long list joined into one piece of text (then handed to the stream).
_CHUNK = 2048
#: Characters of a piece: a :class:`~exactsym.report.json_form.JSONText` longer than this
#: (a run of entries joined) is a piece of its own, and a piece of items is handed on
#: once this long.
_BLOCK = 1 << 16


def _write_items(items, pad: str, out) -> None:
    """A long list (or :class:`~exactsym.report.json_form.LevelEntries`) of containers,
    one item per line: joined by pieces of at most :data:`_CHUNK` items or about
    :data:`_BLOCK` characters (a :class:`~exactsym.report.json_form.JSONText` may hold
    several, joined by the same separator: a long one is a piece of its own), so that
    the text of a million levels is never one string (issue 33)."""
    inner = pad + "  "
    sep = ",\n" + inner
    out.append("[\n" + inner)
    chunk = []
    first = True
    size = 0
    for item in (items.json_items(sep) if isinstance(items, LevelEntries) else items):
        if type(item) is JSONText and len(item) > _BLOCK:
            # a run of entries already joined (LevelEntries.json_items): a piece of its own
            if chunk:
                out.append(("" if first else sep) + sep.join(chunk))
                first, chunk, size = False, [], 0
            if not first:
                out.append(sep)
            out.append(item)
            first = False
            continue
        text = item if type(item) is JSONText else _item(item)
        chunk.append(text)
        size += len(text)
        if len(chunk) == _CHUNK or size > _BLOCK:
            out.append(("" if first else sep) + sep.join(chunk))
            first, chunk, size = False, [], 0
    if chunk:
        out.append(("" if first else sep) + sep.join(chunk))
    out.append("\n" + pad + "]")


def report_text(analysis: Analysis, verbose: bool = False) -> str:
    """The text ``exactsym check`` prints without ``--json``: a summary for people, with
    ``verbose`` the per-level detail (:func:`exactsym.report.summary.summary_text`)."""
    return summary_text(analysis, verbose=verbose)


def check_report(config: Configuration, *, strings: bool = False) -> dict:
    """:func:`report_json` of the whole analysis (every part) of ``config``."""
    with no_cycle_collection():         # one pause for both (see exactsym.cli.main)
        return report_json(analyse(config, options=Options(strings=strings)))


# ---------------------------------------------------------------- [expect]
def _same_number(text_a: str, text_b: str) -> bool:
    """Exact equality of two numbers written in the configuration syntax (as exactsym
    writes them: no limit on their length, :func:`~exactsym.io.expr.parse_expression`)."""
    a, b = parse_expression(text_a, written=True), parse_expression(text_b, written=True)
    system = number_system([a, b])
    return evaluate(a, system) == evaluate(b, system)


def _equal(want, got) -> bool:
    return want == got


def _paper_leader(report: dict):
    """The family layer's leader; -1 stands for "no leader"."""
    paper = report.get("paper")
    if not isinstance(paper, dict) or "leader" not in paper:
        return None
    return -1 if paper["leader"] is None else paper["leader"]


def _paper_level_values(*path):
    """Getter: the value at ``path`` in each level's ``"paper"`` entry ("none" for null),
    nearest first; None when that part was not computed."""
    def get(report):
        out = []
        for level in report["levels"]:
            if "paper" not in level:
                return None
            value = level["paper"]
            for key in path:
                value = None if value is None else value.get(key)
            out.append("none" if value is None else value)
        return out
    return get


def _paper_level_check(want, got) -> bool:
    """An array ``want`` has one value per level; a single value is the outermost level's."""
    def same(a, b):
        return isinstance(a, bool) == isinstance(b, bool) and str(a) == str(b)
    if isinstance(want, list):
        return len(want) == len(got) and all(same(a, b) for a, b in zip(want, got))
    return bool(got) and same(want, got[-1])


def _level(*path):
    return _paper_level_values(*path), _paper_level_check


#: How each ``[expect]`` key is compared with the JSON report: key -> (getter, comparison).
#: The keys a file may use are :data:`exactsym.io.fileformat.EXPECT_KEYS` (the same set).
EXPECTATIONS = {
    "n": (lambda r: r["n"], _equal),
    "levels": (lambda r: len(r["levels"]), _equal),
    "sec_radius_squared": (lambda r: r["sec"]["radius_squared"], _same_number),
    "orderable": (lambda r: r.get("orderable"), _equal),
    "group": (lambda r: r.get("group"), _equal),
    "paper_orderable": (lambda r: (r.get("paper") or {}).get("orderable"), _equal),
    "paper_leader": (_paper_leader, _equal),
    "audit_agrees": (lambda r: (r.get("audit") or {}).get("agrees"), _equal),
    # the set of statements the audit finds false (order and repeats ignored)
    "audit_false": (lambda r: sorted({d["statement"] for d in
                                      (r.get("audit") or {}).get("discrepancies", [])}),
                    lambda want, got: sorted(set(want)) == got),
    # the paper on each level polygon
    "paper_symmetric": _level("symmetric"),
    "paper_straight": _level("straight"),
    "paper_skew": _level("skew"),
    "paper_degree": _level("degree"),
    "paper_type": _level("type"),
    "paper_lines_by_strings": _level("lines_by_strings"),
    "paper_theorem1_symmetric": _level("theorem1_symmetric"),
    "paper_loop_terminates": _level("loop_terminates"),
    "paper_def_straight": _level("definition", "straight"),
    "paper_def_skew": _level("definition", "skew"),
    "paper_def_mirrors": _level("definition", "mirrors"),
    "paper_leader_sym": _level("leader_sym"),
    "paper_leader_sym_by_lines": _level("leader_sym_by_lines"),
    "paper_leader_asym": _level("leader_asym", "+1"),
    "paper_leader_asym_mirrored": _level("leader_asym", "-1"),
}


#: ``[expect]`` keys with this prefix describe a gathering run: they are checked by
#: :mod:`exactsym.gathering.cases` (``exactsym gather``, ``exactsym cases``), not here.
GATHER_PREFIX = "gather_"


def failed_expectations(config: Configuration, report: dict) -> list[str]:
    """One message per ``[expect]`` claim that the report contradicts (or cannot check)."""
    failures = []
    for key, want in config.expect.items():
        if key.startswith(GATHER_PREFIX):      # the simulator's: exactsym gather / cases
            continue
        check = EXPECTATIONS.get(key)
        if check is None:
            failures.append(f"[expect] {key}: no check is implemented for this key")
            continue
        got = check[0](report)
        if got is None:
            failures.append(f"[expect] {key} = {want!r}: this version does not compute it")
        elif not check[1](want, got):
            failures.append(f"[expect] {key} = {want!r} is false: exactsym finds {got!r}")
    return failures


__all__ = ["report_json", "report_text", "json_text", "write_json", "check_report",
           "failed_expectations", "EXPECTATIONS", "GATHER_PREFIX"]
