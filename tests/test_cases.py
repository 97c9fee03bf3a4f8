"""Every case file under ``cases/`` (all subfolders) passes: it loads, is checked, and its
``[expect]`` block holds.  Each case is one test, marked ``lemma(label=...)`` once per label
in its ``lemmas`` list, so that (pytest >= 8)::

    pytest tests/test_cases.py -m "lemma(label='obs-exh-poly')"

runs the regression suite of one statement (``docs/cases.md``).
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from exactsym.report.cases import case_files, run_case, run_cases
from exactsym.io.fileformat import read_config


CASES = Path(__file__).resolve().parent.parent / "cases"


def _labels(path: Path) -> tuple:
    try:
        return tuple(read_config(path).lemmas)
    except Exception:      # an unreadable case still gets collected, and fails below
        return ()


def _params():
    for path in case_files(CASES):
        marks = [pytest.mark.lemma(label=label) for label in _labels(path)]
        yield pytest.param(path, id=str(path.relative_to(CASES)), marks=marks)


@pytest.mark.parametrize("path", list(_params()))
def test_case(path):
    result = run_case(path)
    assert not result.failures, "\n".join(result.failures)


def test_every_case_has_labels_and_expectations():
    for path in case_files(CASES / "polygon") + case_files(CASES / "discrepancies"):
        config = read_config(path)
        assert config.lemmas, f"{path}: no lemmas"
        assert config.expect, f"{path}: no [expect] block"
        assert config.notes, f"{path}: no notes"


SECTION_3_STATEMENTS = [
    "lemma-sym-ord", "lem-rectangle", "obs-parallel-edge-equal", "LoSkS-vertex", "LoSkS-edge",
    "lem-skew-los", "lemma-straight-sym", "lemma-skewed-sym", "obs-asymmetric-polygon",
    "lem-asym-ord", "lemma-sym-regular", "obs-exh-poly", "obs-sym-type-0", "obs-sym-type-01",
    "lem-sym-type-01", "1sym_le", "type-0", "type-1", "type-2", "type-3", "type-4"]


@pytest.mark.parametrize("label", SECTION_3_STATEMENTS)
def test_every_polygon_statement_has_a_case(label):
    assert run_cases(CASES / "polygon", label), f"no case under cases/polygon for {label}"


def test_lemma_marker_selects_by_label(tmp_path):
    """``-m "lemma(label='...')"`` selects exactly the tests marked with that label (run in a
    separate pytest process on a throw-away test file)."""
    (tmp_path / "test_sel.py").write_text(
        "import pytest\n"
        "@pytest.mark.parametrize('x', [\n"
        "    pytest.param(1, marks=[pytest.mark.lemma(label='a'), pytest.mark.lemma(label='b')]),\n"
        "    pytest.param(2, marks=[pytest.mark.lemma(label='b')]),\n"
        "    pytest.param(3)])\n"
        "def test_x(x):\n"
        "    pass\n")
    (tmp_path / "pytest.ini").write_text("[pytest]\nmarkers =\n    lemma(label): a label\n")

    def selected(label):
        out = subprocess.run([sys.executable, "-m", "pytest", "-q", "--collect-only", "-m",
                              f"lemma(label='{label}')", str(tmp_path)], cwd=tmp_path,
                             capture_output=True, text=True)
        return sorted(line for line in out.stdout.splitlines() if "test_x[" in line)
    assert selected("a") == ["test_sel.py::test_x[1]"]
    assert selected("b") == ["test_sel.py::test_x[1]", "test_sel.py::test_x[2]"]
