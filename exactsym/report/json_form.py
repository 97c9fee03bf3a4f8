"""The JSON form of an :class:`~exactsym.analysis.Analysis`: the object ``exactsym check
--json`` writes (keys of ``docs/cli.md``; exact numbers are strings in the configuration
syntax).  Read by both renderings, :mod:`exactsym.report.check` (JSON and the ``[expect]``
check) and :mod:`exactsym.report.summary` (the text), which is why it sits below both.
"""

from __future__ import annotations

from json.encoder import encode_basestring_ascii

from ..analysis import Analysis
from ..geometry.configuration import no_cycle_collection
from ..exact import fmpq
from ..exact.cyclotomic_text import fast_number_text as number_text   # same strings, faster
from ..paper.family_report import paper_json
from ..paper.homogeneous import centre_texts, radius_text, sec_radius_text
from ..truth.report import truth_json
from ..version import json_head

__all__ = ["report_json", "LevelEntries", "JSONText"]


def report_json(analysis: Analysis, brief: bool = False, streamed: bool = False) -> dict:
    """The JSON object of ``exactsym check --json`` (``docs/cli.md``).  ``brief``: without
    ``sec``, ``levels`` and the paper's ``G`` and ``G_prime`` (their exact texts: seconds
    in a cyclotomic field of degree thousands), for summaries that do not print them.
    ``streamed``: ``levels`` is a :class:`LevelEntries`, whose entries are made as the
    writer (:func:`exactsym.report.check.write_json`) reads them, not a list of them all
    (a million levels held a million dicts: issue 33)."""
    # one small dict per level: nothing cyclic; the texts read the analysis's forms
    with no_cycle_collection(), analysis.reading():
        return _report_json(analysis, brief, streamed)


class LevelEntries:
    """The ``levels`` of a report, one entry (the dict :func:`_level_entries` makes) per
    level, made when iterated: as many as the levels (``len``), each equal to the list
    entry; iterating again makes them again.  Read by the JSON writer, which writes it
    as the list it stands for."""

    __slots__ = ("levels", "verdicts", "strings")

    def __init__(self, levels, verdicts, strings):
        self.levels, self.verdicts, self.strings = levels, verdicts, strings

    def __len__(self) -> int:
        return len(self.levels)

    def __iter__(self):
        levels, verdicts, strings = self.levels, self.verdicts, self.strings
        step = 4096
        for start in range(0, len(levels), step):
            stop = start + step
            yield from _level_entries(
                levels[start:stop], None if verdicts is None else verdicts[start:stop],
                None if strings is None else strings[start:stop])

    def as_list(self) -> list:
        return _level_entries(self.levels, self.verdicts, self.strings)

    def json_items(self, sep: str | None = None):
        """The entries as the writer takes them: a level of one robot whose verdict is
        made when read (:class:`~exactsym.paper.polygon_report.SingleVerdicts` with a JSON
        template) as its JSON text (a :class:`JSONText`, the text the writer makes of its
        entry), without making the verdict; every other level as its entry.  ``sep``:
        the text the writer puts between entries; then a run of such levels comes as one
        :class:`JSONText`, their texts joined by ``sep`` (on a million levels, a
        string object per level cost a second)."""
        verdicts = self.verdicts
        parts = getattr(getattr(verdicts, "relabelled", None), "json_parts", None)
        if parts is None or self.strings is not None or len(verdicts) != len(self.levels):
            yield from self
            return
        items, levels = verdicts.items, self.levels
        step = 4096
        for start in range(0, len(levels), step):
            stop = start + step
            run = []
            for level, x in zip(levels[start:stop], items[start:stop]):
                if type(x) is int:
                    r2 = level.radius_squared
                    # flint writes an fmpq as digits, "-" and "/": nothing to escape
                    r2 = f'"{r2}"' if type(r2) is fmpq else \
                        encode_basestring_ascii(_radius_text(r2))
                    x = str(x)
                    text = f'{{"radius_squared": {r2}, "points": [{x}], "paper": ' \
                           f'{x.join(parts)}}}'
                    if sep is None:
                        yield JSONText(text)
                    else:
                        run.append(text)
                else:
                    if run:
                        yield JSONText(sep.join(run))
                        run = []
                    yield _level_entries((level,), (x,), None)[0]
            if run:
                yield JSONText(sep.join(run))


class JSONText(str):
    """The JSON text of one item of a streamed list (:meth:`LevelEntries.json_items`)."""
    __slots__ = ()


def _report_json(analysis: Analysis, brief: bool = False, streamed: bool = False) -> dict:
    config, levels = analysis.config, analysis.levels
    # format, schema_version, file, name first (docs/json.md); the rest as before
    report = json_head("exactsym-check", config.source, config.name)
    report["n"] = config.n
    if not brief:
        # in a field of degree thousands, as quotients of numbers with small
        # coefficients (paper/homogeneous.py): the divided ones are megabytes each
        sec = levels.sec
        centre = centre_texts(sec) or [number_text(c) for c in sec.centre]
        radius = sec_radius_text(sec, config.points) if not levels.polar else None
        report["sec"] = {"center": centre,
                         "radius_squared": radius or number_text(sec.radius_squared)}
    report["number_field"] = getattr(config.polar_system if levels.polar else config.system,
                                     "name", "Q")
    if not brief:
        report["levels"] = (LevelEntries if streamed else _level_entries)(
            levels.levels, analysis.level_verdicts, analysis.level_strings)
    if analysis.truth is not None:
        report.update(truth_json(analysis.truth))
    if analysis.paper is not None:
        report["paper"] = paper_json(analysis.paper, described=not brief)
    if analysis.audit is not None:
        report["audit"] = analysis.audit.as_dict()
    return report


def _radius_text(r2) -> str:
    return radius_text(r2) or number_text(r2)


def _level_entries(levels, verdicts, strings) -> list:
    """One dict per level: ``radius_squared``, ``points`` and, when computed, the polygon
    layer's ``paper`` verdict and its ``strings``."""
    if verdicts is not None and strings is None and len(verdicts) == len(levels):
        # one pass (100,000 levels on random input)
        return [{"radius_squared": str(level.radius_squared)
                 if type(level.radius_squared) is fmpq       # flint writes p/q as we do
                 else _radius_text(level.radius_squared),
                 "points": list(level.points), "paper": verdict}
                for level, verdict in zip(levels, verdicts)]
    out = [{"radius_squared": str(level.radius_squared)
            if type(level.radius_squared) is fmpq else _radius_text(level.radius_squared),
            "points": list(level.points)} for level in levels]
    if verdicts is not None:
        strings = strings or (None,) * len(out)
        for entry, verdict, text in zip(out, verdicts, strings):
            entry["paper"] = verdict
            if text is not None:
                entry["strings"] = text
    return out
