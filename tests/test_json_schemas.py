"""Issue 34, item 5: every JSON output has a schema under docs/schemas/ (draft 2020-12) and
real outputs of the cases satisfy it; each begins with ``format``, ``schema_version``,
``file`` and ``name``; witnesses carry data (robot indices, exact turns) beside their prose.
"""

from __future__ import annotations

import json
import os
from fractions import Fraction
from pathlib import Path

import pytest

from exactsym.cli.main import main
from exactsym.version import SCHEMA_VERSION
from schema_validator import KNOWN, UnknownKeyword, errors

ROOT = Path(__file__).resolve().parent.parent
SCHEMAS = ROOT / "docs" / "schemas"
CASES = ROOT / "cases"
GOLDEN = ROOT / "tests" / "golden"
GATHER = CASES / "gathering" / "last-three-no-leader.toml"
SHORT = [str(GATHER), "--scheduler", "centralised", "--max-events", "5", "--no-expect"]
HEAD = ["format", "schema_version", "file", "name"]


def schema(name: str) -> dict:
    return json.loads((SCHEMAS / f"{name}.schema.json").read_text(encoding="utf-8"))


def valid(name: str, value) -> None:
    found = errors(schema(name), value)
    assert found == [], found[:5]


def run_json(capsys, *argv, code=(0, 1)):
    assert main(list(argv)) in code
    return json.loads(capsys.readouterr().out)


def _schema_nodes(node, path="$"):
    """Every subschema of a schema file (under the keywords that hold schemas)."""
    if not isinstance(node, dict):
        return
    yield path, node
    for key in ("properties", "$defs", "patternProperties"):
        for name, sub in node.get(key, {}).items():
            yield from _schema_nodes(sub, f"{path}.{key}.{name}")
    for key in ("items", "additionalProperties", "not"):
        if isinstance(node.get(key), dict):
            yield from _schema_nodes(node[key], f"{path}.{key}")
    for key in ("prefixItems", "anyOf", "oneOf", "allOf"):
        for k, sub in enumerate(node.get(key, [])):
            yield from _schema_nodes(sub, f"{path}.{key}[{k}]")


@pytest.mark.parametrize("path", sorted(SCHEMAS.glob("*.schema.json")), ids=lambda p: p.name)
def test_each_schema_is_draft_2020_12_with_known_keywords(path):
    data = json.loads(path.read_text(encoding="utf-8"))
    assert data["$schema"] == "https://json-schema.org/draft/2020-12/schema"
    for where, node in _schema_nodes(data):
        assert set(node) <= KNOWN, (where, set(node) - KNOWN)


def test_the_validator_refuses_what_it_cannot_check():
    with pytest.raises(UnknownKeyword):
        errors({"type": "object", "unevaluatedProperties": False}, {})
    assert errors({"type": "integer"}, True) != []          # a boolean is no integer
    assert errors({"enum": [1]}, True) != []


@pytest.mark.parametrize("path", sorted(GOLDEN.rglob("*.json")),
                         ids=lambda p: str(p.relative_to(GOLDEN)))
def test_every_pinned_check_output_satisfies_the_check_schema(path):
    # the golden files are check --json of every case file (tests/test_golden.py)
    valid("check", json.loads(path.read_text(encoding="utf-8")))


def test_check_json_heads_and_mutations_are_caught(capsys):
    case = CASES / "examples" / "chiral-nine-gon.toml"
    out = run_json(capsys, "check", "--json", str(case))
    assert list(out)[:4] == HEAD
    assert out["format"] == "exactsym-check" and out["schema_version"] == SCHEMA_VERSION
    assert out["file"] == str(case) and out["name"] and out["n"] == 9
    valid("check", out)
    for broken in ({**out, "schema_version": SCHEMA_VERSION + 1},
                   {k: v for k, v in out.items() if k != "leader"},
                   {**out, "n": 9.0},
                   {**out, "sec": {**out["sec"], "radius_squared": 16}}):
        assert errors(schema("check"), broken) != []


def test_check_json_from_standard_input_names_its_file(capsys, monkeypatch):
    import io
    text = (CASES / "examples" / "rational-pentagon.txt").read_text(encoding="utf-8")
    monkeypatch.setattr("sys.stdin", io.StringIO(text))
    out = run_json(capsys, "check", "--json", "-")
    valid("check", out)
    assert out["file"] == "<stdin>" or out["file"] == "-"


def _symmetry_witnesses(report: dict) -> list:
    return [d["witness"] for d in report["audit"]["discrepancies"]
            if isinstance(d["witness"], dict) and "maps" in d["witness"]]


@pytest.mark.parametrize("case", ["examples/chiral-nine-gon.toml",
                                  "discrepancies/family-c3-two-triangles.toml",
                                  "discrepancies/c3-nonagon-rotation-only.toml"])
def test_audit_json_and_witnesses_as_data(case, capsys):
    out = run_json(capsys, "audit", "--json", str(CASES / case))
    assert list(out)[:4] == HEAD and out["format"] == "exactsym-audit"
    valid("audit", out)
    n = sum(len(g["robots"]) for g in out["paper"]["G"])
    witnesses = _symmetry_witnesses(out)
    assert witnesses, "a case with a symmetry witness"
    for w in witnesses:
        m = w["robot_map"]
        assert w["maps"] == f"robot {m['from']} -> robot {m['to']}"   # the prose stays
        assert m["from"] != m["to"] and 0 <= m["from"] < n and 0 <= m["to"] < n
        if w.get("isometry") == "rotation" and "group" in w:
            k = int(w["group"][1:])
            assert Fraction(w["turn"]) == Fraction(1, k)            # reads back, exactly


def test_line_witnesses_as_exact_turns(capsys):
    out = run_json(capsys, "check", "--json", str(CASES / "examples" / "chiral-nine-gon.toml"))
    found = [d["witness"] for d in out["audit"]["discrepancies"]
             if isinstance(d["witness"], dict) and "lines" in d["witness"]]
    assert found
    for w in found:
        values = w["lines"]["values"]
        assert w["G_ij lines"].startswith(f"{len(values)} lines")
        if w["lines"]["unit"] == "turns":
            turns = [Fraction(v) for v in values]
            assert all(0 <= t < Fraction(1, 2) for t in turns)
            assert ", ".join(values) in w["G_ij lines"]


def test_audit_text_does_not_print_the_data_twice(capsys):
    main(["audit", str(CASES / "examples" / "chiral-nine-gon.toml")])
    out = capsys.readouterr().out
    assert "robot_map" not in out and "isometry" not in out and "robot 3 -> robot 4" in out


def test_certificate_and_refutation_outputs(capsys, tmp_path):
    case = CASES / "polygon" / "kite-polar.toml"
    cert = run_json(capsys, "certify", str(case), "-o", "-")
    assert list(cert)[:4] == HEAD and cert["format"] == "exactsym-certificate"
    valid("certificate", cert)
    written = tmp_path / "c.json"
    written.write_text(json.dumps(cert), encoding="utf-8")
    assert main(["verify", str(written)]) == 0       # the checker accepts the new keys
    capsys.readouterr()
    ref = run_json(capsys, "certify", str(CASES / "examples" / "chiral-nine-gon.toml"),
                   "--refutes", "Pasym-Pord", "-o", "-")
    assert ref["format"] == "exactsym-refutation"
    valid("certificate", ref)
    assert errors(schema("certificate"), {**ref, "format": "exactsym-check"}) != []


def test_gather_json_plain_search_and_replay(capsys, tmp_path):
    trace = tmp_path / "t.json"
    out = run_json(capsys, "gather", *SHORT, "--json", "--trace", str(trace))
    assert list(out)[:4] == HEAD and out["format"] == "exactsym-gather"
    assert out["file"] == str(GATHER) and out["name"]
    valid("gather", out)
    out = run_json(capsys, "gather", *SHORT, "--search", "--budget", "20", "--json")
    assert out["search"] is not None
    valid("gather", out)
    again = run_json(capsys, "replay", str(trace), "--json")
    assert again["format"] == "exactsym-replay" and again["file"] == str(trace)
    valid("replay", again)
    assert errors(schema("gather"), {**out, "events": "5"}) != []


def test_gather_readings_all_json(capsys):
    out = run_json(capsys, "gather", *SHORT, "--readings", "all", "--budget", "5",
                   "--time", "5", "--json")
    assert out["format"] == "exactsym-gather-readings"
    valid("gather-readings", out)
    assert errors(schema("gather-readings"), {**out, "matrix": []}) != []


def test_sweep_results_lines_and_summary(capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    results = tmp_path / "r.jsonl"
    out = run_json(capsys, "sweep", "grid:3:<=3", "--what", "audit", "--serial",
                   "--out", str(results), "--json")
    assert list(out)[:4] == HEAD and out["format"] == "exactsym-sweep"
    assert out["name"] == "grid:3:<=3"
    valid("sweep", out)
    lines = [json.loads(line) for line in results.read_text(encoding="utf-8").splitlines()]
    assert lines[0]["format"] == "exactsym-sweep-results"
    assert lines[0]["schema_version"] == SCHEMA_VERSION
    for line in lines:
        valid("sweep-results", line)
    assert any(line.get("points") for line in lines[1:])
    assert errors(schema("sweep-results"), {**lines[1], "status": "fine"}) != []
    # a resumed sweep reads the header's inner format still
    assert main(["sweep", "grid:3:<=3", "--what", "audit", "--serial", "--out",
                 str(results), "--resume"]) in (0, 1)


def test_every_output_schema_is_documented():
    text = (ROOT / "docs" / "json.md").read_text(encoding="utf-8")
    for path in SCHEMAS.glob("*.schema.json"):
        assert f"schemas/{path.name}" in text, path.name
        fmt = schema(path.name.split(".")[0])["properties"]["format"] \
            if "properties" in schema(path.name.split(".")[0]) else \
            schema(path.name.split(".")[0])["$defs"]["header"]["properties"]["format"]
        for name in fmt.get("enum", [fmt.get("const")]):
            assert f"`{name}`" in text, name
