"""The JSON text of ``exactsym check --json`` (exactsym.report.check.json_text): the layout of
``json.dumps(indent=2)`` for small reports, long lists one item per line, and the same
object either way."""

from __future__ import annotations

import json

from exactsym.geometry.configuration import load
from exactsym.report.check import LONG_LIST, check_report, json_text


def test_small_report_is_written_as_json_dumps_indent_2():
    report = check_report(load("cases/examples/rational-pentagon.txt"))
    assert json_text(report) == json.dumps(report, indent=2)
    assert json_text(report, compact=True) == json.dumps(report)


def test_long_lists_one_item_per_line_and_the_same_object():
    n = LONG_LIST + 5
    report = {"n": n, "levels": [{"radius_squared": f"{k}/3", "points": [k],
                                  "paper": {"tie": k % 2 == 0, "x": None}} for k in range(n)],
              "ordering": list(range(n)), "empty": [], "nested": {"a": [1, {"b": "é"}]}}
    text = json_text(report)
    assert json.loads(text) == report
    lines = text.splitlines()
    assert sum(1 for line in lines if line.startswith('    {"radius_squared"')) == n
    assert '  "ordering": [0, 1, 2,' in text          # numbers: one line
    short = {"levels": report["levels"][:3], "ordering": [1, 2]}
    assert json_text(short) == json.dumps(short, indent=2)


def test_written_by_pieces_the_same_text(monkeypatch):
    """write_json streams the text json_text makes (by pieces of about 4 MB: here forced
    to a few bytes, so every piece is its own write), and a newline."""
    import io
    import exactsym.report.check as report_module
    n = LONG_LIST + 5
    report = {"n": n, "levels": [{"radius_squared": f"{k}/3", "points": [k]}
                                 for k in range(n)], "text": "x" * 5000, "nested": {"a": [1]}}
    whole = io.StringIO()
    report_module.write_json(report, whole)
    assert whole.getvalue() == json_text(report) + "\n"
    writes = []

    class Counting(io.StringIO):
        def write(self, text):
            writes.append(len(text))
            return super().write(text)
    monkeypatch.setattr(report_module._Sink, "append", lambda self, text: (
        self.pieces.append(text), self.flush()))
    small = Counting()
    report_module.write_json(report, small)
    assert small.getvalue() == whole.getvalue() and len(writes) > 10
    compact = io.StringIO()
    report_module.write_json(report, compact, compact=True)
    assert compact.getvalue() == json_text(report, compact=True) + "\n"
