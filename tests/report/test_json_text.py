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


def _old_json_text(report: dict) -> str:
    """The writer as it was before the levels were streamed (issue 33): every long list of
    containers joined into one string; the reference the streamed text must equal."""
    from exactsym.report.check import _item, _SCALARS

    def write(value, pad, out):
        inner = pad + "  "
        if isinstance(value, dict) and value:
            out.append("{")
            sep = "\n"
            for key, item in value.items():
                out.append(sep + inner + json.dumps(str(key)) + ": ")
                write(item, inner, out)
                sep = ",\n"
            out.append("\n" + pad + "}")
        elif isinstance(value, list) and len(value) > LONG_LIST:
            if set(map(type, value)) <= _SCALARS:
                out.append(_item(value))
            else:
                out.append("[\n" + inner + (",\n" + inner).join(map(_item, value))
                           + "\n" + pad + "]")
        elif isinstance(value, list) and value:
            out.append("[")
            sep = "\n"
            for item in value:
                out.append(sep + inner)
                write(item, inner, out)
                sep = ",\n"
            out.append("\n" + pad + "]")
        else:
            out.append(json.dumps(value))
    out: list = []
    write(report, "", out)
    return "".join(out)


def test_streamed_levels_write_the_same_bytes(monkeypatch, tmp_path):
    """``check --json`` makes the levels' entries as it writes them
    (:class:`exactsym.report.json_form.LevelEntries`), joined by pieces of ``_CHUNK``
    items (here 7, so that the pieces' seams fall inside the list): the text is the one
    the former writer made from the whole list, byte for byte, in both layouts; with a
    short list too."""
    import io
    import random
    import exactsym.report.check as report_module
    from exactsym.analysis import analyse
    from exactsym.report.json_form import LevelEntries, report_json
    monkeypatch.setattr(report_module, "_CHUNK", 7)
    rnd = random.Random(3)
    pts = {(rnd.randint(-999, 999), rnd.randint(-999, 999)) for _ in range(LONG_LIST + 40)}
    inner = {(x, y) for x, y in pts if x * x + y * y < 990 ** 2} - {(0, 0)}
    for text in ("".join(f"{x}/7 {y}/3\n" for x, y in sorted(pts)),
                 # a robot at the SEC centre (its level has no verdict) among single robots
                 "0 0\n1000 0\n-1000 0\n" + "".join(f"{x} {y}/3\n" for x, y in sorted(inner)),
                 "0 0\n1 0\n0 1\n-1 -1\n"):
        path = tmp_path / "c.txt"
        path.write_text(text)
        analysis = analyse(load(path))
        whole = report_json(analysis)
        streamed = report_json(analysis, streamed=True)
        assert isinstance(streamed["levels"], LevelEntries)
        assert list(streamed["levels"]) == whole["levels"]
        for compact in (False, True):
            # pieces by count, by size, and runs of entries joined as pieces of their own
            for block in (1 << 16, 700, 10 ** 9):
                monkeypatch.setattr(report_module, "_BLOCK", block)
                out = io.StringIO()
                report_module.write_json(streamed, out, compact=compact)
                want = json.dumps(whole) if compact else _old_json_text(whole)
                assert out.getvalue() == want + "\n"
