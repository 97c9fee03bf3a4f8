"""The ledger's claim on the corrected algorithm (issue 31): its gathering sweep summary
is well formed, the grade follows from it, the summary is what the results files say."""

from __future__ import annotations

from pathlib import Path

from exactsym.ledger.evidence import check_evidence
from exactsym.ledger.model import parse_ledger

ROOT = Path(__file__).resolve().parents[2]


def test_the_ledgers_claim_on_the_corrected_algorithm_is_consistent():
    """The committed claim: its gathering sweep summary is well formed, its grade follows
    from it, and the summary is what the committed results files say (the script's
    check, re-run)."""
    ledger = parse_ledger((ROOT / "proofs" / "statements.toml").read_text(encoding="utf-8"))
    claim = next(c for c in ledger.claims if c.id == "corrected-gathers-with-a-leader")
    assert {e.kind for e in claim.evidence} >= {"gather_sweep", "script"}
    only = type(ledger)(ledger.source, (), (), (type(claim)(
        claim.id, claim.about, claim.claim, claim.grade, claim.finding,
        tuple(e for e in claim.evidence if e.kind in ("gather_sweep", "script")),
        claim.checked_by),))
    assert check_evidence(only, ROOT) == []
    # the same claim with a grade the sweep does not back is a mismatch
    other = "holds-on-cases" if claim.grade != "holds-on-cases" else "refuted"
    wrong = type(ledger)(ledger.source, (), (), (type(claim)(
        claim.id, claim.about, claim.claim, other, claim.finding,
        tuple(e for e in claim.evidence if e.kind == "gather_sweep"), claim.checked_by),))
    assert check_evidence(wrong, ROOT) != []
