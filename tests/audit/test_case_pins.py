"""Issue 32: which statements a discrepancy or gathering case refutes is pinned in the case
itself (``[expect] audit_false``, written from the paper), not only by golden files, so a
change of verdict fails the case's own expectation."""

import tomllib
from pathlib import Path

import pytest

CASES = Path(__file__).resolve().parents[2] / "cases"
PATHS = sorted(p for d in ("discrepancies", "gathering") for p in (CASES / d).glob("*.toml"))


@pytest.mark.parametrize("path", PATHS, ids=lambda p: f"{p.parent.name}/{p.name}")
def test_every_discrepancy_and_gathering_case_pins_its_findings(path):
    expect = tomllib.loads(path.read_text(encoding="utf-8")).get("expect", {})
    assert "audit_false" in expect, f"{path.name}: no [expect] audit_false"
    assert len(set(expect["audit_false"])) == len(expect["audit_false"])
