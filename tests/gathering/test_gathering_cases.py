"""The cases under cases/gathering/ exist and carry gathering expectations; each one's
expected outcome (the gather_* keys of its [expect] block) is checked with the rest of
the case library in tests/test_cases.py (exactsym.report.cases.run_case runs the simulator)."""

from pathlib import Path


CASES = sorted((Path(__file__).resolve().parents[2] / "cases" / "gathering").glob("*.toml"))


def test_there_are_gathering_cases():
    assert len(CASES) >= 2


def test_every_gathering_case_states_an_outcome():
    from exactsym.io.fileformat import read_config
    for path in CASES:
        assert "gather_outcome" in read_config(path).expect, path


def test_the_ledger_reruns_a_gathering_case(tmp_path):
    """The ledger's evidence check runs the simulator on a case's gather_* claims: a
    false gather_outcome is a mismatch."""
    from exactsym.ledger.analysis_bridge import analyse_case
    src = Path(__file__).resolve().parents[2] / "cases/gathering/obstacle-beside-path.toml"
    assert analyse_case(src).expect_failures == ()
    bad = tmp_path / "bad.toml"
    bad.write_text(src.read_text().replace('gather_outcome = "violated"',
                                           'gather_outcome = "gathered"'))
    failures = analyse_case(bad).expect_failures
    assert len(failures) == 1 and "gather_outcome" in failures[0]
