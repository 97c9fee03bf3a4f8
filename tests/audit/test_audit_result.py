"""Issue 34, item 6: ``Analysis.audit`` is a dataclass, as ``truth`` and ``paper`` are; its
``as_dict()`` is the JSON ``check --json`` writes, key for key."""

from __future__ import annotations

import dataclasses
import json
from pathlib import Path

from exactsym.analysis import analyse
from exactsym.audit.result import AuditResult, AuditTruth
from exactsym.cli.main import main
from exactsym.geometry.configuration import load

CASES = Path(__file__).resolve().parents[2] / "cases"
NINE = CASES / "examples" / "chiral-nine-gon.toml"


def test_the_audit_is_a_dataclass_with_the_truths_data():
    a = analyse(load(NINE))
    assert dataclasses.is_dataclass(a.audit) and isinstance(a.audit, AuditResult)
    assert isinstance(a.audit.truth, AuditTruth)
    assert a.audit.truth.group == a.truth.name == "C3"
    assert a.audit.truth.orderable is a.truth.orderable is False
    assert a.audit.truth.leader is None and a.audit.agrees is False
    assert a.audit.covered and all(isinstance(d, dict) for d in a.audit.discrepancies)


def test_as_dict_is_the_json_of_check(capsys):
    a = analyse(load(NINE))
    assert main(["check", "--json", str(NINE)]) == 0
    written = json.loads(capsys.readouterr().out)["audit"]
    assert json.loads(json.dumps(a.audit.as_dict())) == written
    assert list(a.audit.as_dict()) == list(written)          # the same order of keys
    assert AuditResult.from_dict(a.audit.as_dict()) == a.audit


def test_the_dicts_reading_still_works():
    a = analyse(load(NINE))
    assert a.audit["agrees"] is a.audit.agrees
    assert a.audit["truth"] == a.audit.truth.as_dict()
    assert a.audit.get("notes") is a.audit.notes and a.audit.get("nothing", 7) == 7
    assert "covered" in a.audit and "nothing" not in a.audit
