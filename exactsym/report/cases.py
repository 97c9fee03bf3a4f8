"""``exactsym cases [--lemma LABEL] [DIR]``: run the case library.

Every ``.toml`` / ``.txt`` file under DIR (default ``cases``, all subfolders) is loaded,
analysed (:func:`exactsym.analysis.analyse`) and its ``[expect]`` block compared with the report
(``failed_expectations``).  One line per case: ``PASS`` or ``FAIL``, the path and the
case's ``lemmas``; failures are explained on the following lines.  Exit 1 if any case
fails, 0 otherwise; with ``--lemma`` only the cases tagged with that label run.

The library function :func:`run_cases` does the same from Python (``tests/test_cases.py``).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from ..analysis import analyse
from ..geometry.configuration import load
from ..errors import InputError
from ..io.fileformat import read_config
from ..labels import ALGORITHMS, STATEMENTS, is_label, unknown_label_message
from ..gathering.cases import run_case_file
from .check import GATHER_PREFIX, failed_expectations, report_json

CASE_SUFFIXES = (".toml", ".txt")


@dataclass(frozen=True)
class CaseResult:
    path: str
    lemmas: tuple
    failures: tuple

    @property
    def passed(self) -> bool:
        return not self.failures


def case_files(directory) -> list[Path]:
    """The case files under ``directory`` (recursively), sorted."""
    root = Path(directory)
    if not root.is_dir():
        raise InputError("no such directory of cases", str(directory))
    return sorted(p for p in root.rglob("*") if p.suffix in CASE_SUFFIXES and p.is_file())


def run_case(path) -> CaseResult:
    """Load, check and compare one case (an unreadable case is a failure, not an exception)."""
    try:
        config = load(path)
    except InputError as err:
        return CaseResult(str(path), (), (f"cannot be read: {err}",))
    failures = failed_expectations(config, report_json(analyse(config)))
    if any(key.startswith(GATHER_PREFIX) for key in config.expect):
        failures += run_case_file(path).failures     # the gathering run the case describes
    return CaseResult(str(path), tuple(config.lemmas), tuple(failures))


def run_cases(directory="cases", lemma: str | None = None) -> list[CaseResult]:
    """Every case under ``directory`` (only those tagged ``lemma`` when given; an unknown
    label is an :class:`InputError` naming the nearest known one)."""
    if lemma is not None and not is_label(lemma):
        raise InputError(f"--lemma: {unknown_label_message(lemma)}")
    results = []
    for path in case_files(directory):
        result = run_case(path)
        if lemma is None or lemma in result.lemmas:
            results.append(result)
    return results


def label_counts(directory="cases") -> dict:
    """Every known label (exactsym.labels) -> the number of case files under ``directory``
    tagged with it (0 included), in the paper's order."""
    counts = {label: 0 for label in STATEMENTS + ALGORITHMS}
    for path in case_files(directory):
        try:
            lemmas = read_config(path).lemmas
        except InputError:
            continue
        for label in set(lemmas):
            counts[label] += 1
    return counts
