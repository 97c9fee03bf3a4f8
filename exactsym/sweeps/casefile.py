"""Configuration files written by a sweep (format 1, ``docs/format.md``): plain text only,
so the same text is what a worker analyses and what a counterexample's case file holds."""

from __future__ import annotations

import json

__all__ = ["case_text"]


def _string(text: str) -> str:
    """A TOML basic string (JSON's escapes are TOML's: quote, backslash, \\n, \\uXXXX)."""
    return json.dumps(text, ensure_ascii=False)


def _point(point: tuple) -> str:
    kind, a, b = point
    if kind == "polar":
        return f"  {{ r = {_string(a)}, turn = {_string(b)} }},"
    return f"  [{_string(a)}, {_string(b)}],"


def _value(value) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    return _string(str(value))


def case_text(points, name: str | None = None, notes: str | None = None,
              lemmas=(), expect: dict | None = None) -> str:
    """The TOML text of a configuration: ``points`` as in
    :class:`exactsym.sweeps.families.SweepItem`, ``expect`` the ``[expect]`` block."""
    lines = ["format = 1"]
    if name:
        lines.append(f"name = {_string(name)}")
    if notes:
        lines.append(f"notes = {_string(notes)}")
    if lemmas:
        lines.append("lemmas = [" + ", ".join(_string(x) for x in lemmas) + "]")
    lines.append("points = [")
    lines.extend(_point(p) for p in points)
    lines.append("]")
    if expect:
        lines.append("")
        lines.append("[expect]")
        lines.extend(f"{k} = {_value(v)}" for k, v in expect.items())
    return "\n".join(lines) + "\n"
