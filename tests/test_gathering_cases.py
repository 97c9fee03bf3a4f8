"""The cases under cases/gathering/ exist and carry gathering expectations; each one's
expected outcome (the gather_* keys of its [expect] block) is checked with the rest of
the case library in tests/test_cases.py (exactsym.cases_cli.run_case runs the simulator)."""

from pathlib import Path


CASES = sorted((Path(__file__).resolve().parent.parent / "cases" / "gathering").glob("*.toml"))


def test_there_are_gathering_cases():
    assert len(CASES) >= 2


def test_every_gathering_case_states_an_outcome():
    from exactsym.fileformat import read_config
    for path in CASES:
        assert "gather_outcome" in read_config(path).expect, path
