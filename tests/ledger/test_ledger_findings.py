"""Issue 32: findings without a label of their own are ledger items with evidence."""

from pathlib import Path

import pytest

from exactsym.ledger.audit_doc import render
from exactsym.ledger.evidence import check_evidence
from exactsym.ledger.graph import dependency_graph, support
from exactsym.ledger.model import LedgerError, parse_ledger

ROOT = Path(__file__).resolve().parents[2]
TEXT = (ROOT / "proofs" / "statements.toml").read_text(encoding="utf-8")

FINDING = '''
[[finding]]
id = "{id}"
about = {about}
lines = [243, 250]
claim = "a claim"
finding = "what is found"
evidence = [{evidence}]
checked_by = "x"
'''
SCRIPT = '{script = "proofs/pattern_lone_layer.py", args = [40]}'


def _with(**kw):
    fields = {"id": "new-finding", "about": '["gathering_pattern"]', "evidence": SCRIPT}
    fields.update(kw)
    return TEXT + FINDING.format(**fields)


def test_the_two_findings_are_in_the_ledger_and_in_the_audit_page():
    ledger = parse_ledger(TEXT)
    assert [f.id for f in ledger.findings] == ["def1-no-pattern-for-some-n",
                                                "chord-strings-arc-complement"]
    page = render(ledger, support(ledger, dependency_graph(ledger)))
    assert "## Findings without a label of their own" in page
    assert "| `def1-no-pattern-for-some-n` | `gathering_pattern`, `GatheringPattern` |" in page


@pytest.mark.parametrize("bad, why", [
    ({"id": "GatheringPattern"}, "not a label of the paper"),
    ({"id": "two words"}, "letters, digits"),
    ({"id": "def1-no-pattern-for-some-n"}, "unique"),
    ({"about": '["no-such-label"]'}, "no-such-label"),
    ({"about": "[]"}, "non-empty list of labels"),
    ({"evidence": '{sweep = "proofs/sweeps/grid_5_le5.json"}'}, "cases (verdict expect)"),
    ({"evidence": '{case = "cases/gathering/corrected-last-three.toml", verdict = "audit-false"}'},
     "cases (verdict expect)"),
])
def test_a_malformed_finding_is_refused(bad, why):
    with pytest.raises(LedgerError, match=why.replace("(", r"\(").replace(")", r"\)")):
        parse_ledger(_with(**bad))


def test_a_findings_evidence_is_re_run(tmp_path):
    ledger = parse_ledger(_with(evidence='{case = "cases/no/such.toml", verdict = "expect"}'))
    only = type(ledger)(ledger.source, (), ledger.findings[-1:])
    [m] = check_evidence(only, ROOT)
    assert m.label == "new-finding" and m.message == "file not found"
    good = type(ledger)(ledger.source, (), parse_ledger(_with()).findings[-1:])
    assert check_evidence(good, ROOT) == []
