"""Every case under cases/gathering/ gives its expected gathering outcome (the gather_*
keys of its [expect] block, exactsym.gathering.cases)."""

from pathlib import Path

import pytest

from exactsym.gathering.cases import run_case_file

CASES = sorted((Path(__file__).resolve().parent.parent / "cases" / "gathering").glob("*.toml"))


def test_there_are_gathering_cases():
    assert len(CASES) >= 2


@pytest.mark.parametrize("path", CASES, ids=[p.name for p in CASES])
def test_gathering_case(path):
    run = run_case_file(path)
    assert not run.failures, "\n".join(run.failures)
