"""The checker apart from the producer (issue 29, point 4): the solver side only runs it, never
imports its code; it runs as a copied directory, with or without its extensions; it reads its
JSON strictly; and where both sides compute the same thing, they agree."""

from __future__ import annotations

import ast
import json
import random
import re
import shutil
import subprocess
import sys
from fractions import Fraction
from pathlib import Path

import pytest
from flint import fmpq, fmpq_poly, fmpz_poly
from hypothesis import given, settings, strategies as st

from exactsym import checker
from exactsym.certificates import certificate, refutation
from exactsym.certificates.encoder import one_sign_change
from exactsym.checker.dispatch import FORMATS, IRREDUCIBILITY, NUMBER_SYSTEMS, REFUTATIONS
from exactsym.cli.main import main as cli_main
from exactsym.geometry.configuration import load

ROOT = Path(__file__).resolve().parents[2]
PACKAGE = ROOT / "exactsym"
CHECKER = PACKAGE / "checker"
#: the only modules of exactsym that import the checker: they run it on a certificate
RUNNERS = {"exactsym/cli/certify.py", "exactsym/ledger/evidence.py"}
CORE = ("__init__.py", "__main__.py", "numbers.py", "dispatch.py", "groups.py", "ordering.py",
        "refutations.py")


def _checker_imports(text: str, package: str) -> list[str]:
    """The imports of exactsym.checker (absolute or relative) in one module's text."""
    found = []
    for node in ast.walk(ast.parse(text)):
        if isinstance(node, ast.ImportFrom):
            base = package.split(".")[:len(package.split(".")) - node.level + 1] \
                if node.level else []
            target = ".".join(base + ([node.module] if node.module else []))
            names = [target] + [f"{target}.{a.name}" for a in node.names]
        elif isinstance(node, ast.Import):
            names = [a.name for a in node.names]
        else:
            continue
        found += [n for n in names if n == "exactsym.checker" or
                  n.startswith("exactsym.checker.")]
    return found


def test_only_the_runners_import_the_checker():
    """Nothing of the solver imports the checker but the two modules that run it (the
    certify and verify commands, the ledger's evidence check); relative imports count."""
    importers = {str(p.relative_to(ROOT)) for p in PACKAGE.rglob("*.py")
                 if CHECKER not in p.parents and _checker_imports(
                     p.read_text(), ".".join(p.relative_to(ROOT).parts[:-1]))}
    assert importers == RUNNERS, importers
    probe = "from .. import checker\nfrom ..checker.numbers import psi\nimport json\n"
    assert _checker_imports(probe, "exactsym.certificates") == [
        "exactsym.checker", "exactsym.checker.numbers", "exactsym.checker.numbers.psi"]


def test_dispatch_tables_name_existing_functions():
    """Every entry of the dispatch tables is a function or class of a checker module; the
    tables are written out (literal dicts), not filled at import time."""
    for table in (FORMATS, NUMBER_SYSTEMS, IRREDUCIBILITY, REFUTATIONS):
        for key, (module, name) in table.items():
            assert (CHECKER / f"{module}.py").exists(), key
            assert callable(checker.dispatch.load(table, key)), key
    assert set(REFUTATIONS) == set(checker.REFUTABLE)
    tree = ast.parse((CHECKER / "dispatch.py").read_text())
    assigned = {t.id for node in tree.body if isinstance(node, ast.Assign)
                for t in node.targets if isinstance(t, ast.Name)}
    assert {"FORMATS", "NUMBER_SYSTEMS", "IRREDUCIBILITY", "REFUTATIONS"} <= assigned
    for node in tree.body:
        if isinstance(node, ast.Assign):
            assert isinstance(node.value, ast.Dict)


def _certificate(case: str) -> dict:
    return json.loads(json.dumps(certificate.make_certificate(load(ROOT / case))))


def _write(path: Path, text: str) -> Path:
    path.write_text(text)
    return path


def _run_checker(cwd: Path, module: str, cert: Path):
    return subprocess.run([sys.executable, "-m", module, str(cert)], capture_output=True,
                          text=True, cwd=cwd)


def test_a_key_given_twice_is_invalid(tmp_path, capsys):
    """Two "claim" objects: json keeps the last, so a file could show one claim and prove
    another; the checker rejects it (exit 1), also through ``exactsym verify``."""
    cert = _certificate("cases/examples/chiral-nine-gon.toml")
    good = json.dumps(cert)
    false_claim = json.dumps({**cert["claim"], "group": "D9"})
    twice = good.replace('"claim": ', f'"claim": {false_claim}, "claim": ', 1)
    assert json.loads(twice) == cert                # what json.load alone makes of it
    path = _write(tmp_path / "twice.json", twice)
    out = _run_checker(ROOT, "exactsym.checker", path)
    assert out.returncode == 1 and "INVALID" in out.stderr and "'claim'" in out.stderr, out
    assert cli_main(["verify", str(path)]) == 1
    assert "given twice" in capsys.readouterr().err
    nested = good.replace('"group": ', '"group": "D9", "group": ', 1)    # deeper down
    out = _run_checker(ROOT, "exactsym.checker", _write(tmp_path / "nested.json", nested))
    assert out.returncode == 1 and "'group' is given twice" in out.stderr, out
    out = _run_checker(ROOT, "exactsym.checker", _write(tmp_path / "good.json", good))
    assert out.returncode == 0, out
    out = _run_checker(ROOT, "exactsym.checker", _write(tmp_path / "bad.json", good[:-3]))
    assert out.returncode == 2 and "unreadable" in out.stderr     # not JSON: still exit 2
    assert cli_main(["verify", str(tmp_path / "bad.json")]) == 2


def test_a_boolean_is_no_number(tmp_path):
    """true == 1 in Python: "version": true, or true for an index, is rejected."""
    cert = _certificate("cases/examples/chiral-nine-gon.toml")
    assert checker.verify(json.loads(json.dumps(cert)))[0]
    bad = {**cert, "version": True}
    assert checker.verify(bad) == (False, "not an exactsym certificate of version 1")
    out = _run_checker(ROOT, "exactsym.checker",
                       _write(tmp_path / "v.json", json.dumps(bad)))
    assert out.returncode == 1 and "version 1" in out.stderr
    assert cert["witness"]["reference"] == 0
    bad = json.loads(json.dumps(cert))
    bad["witness"]["reference"] = False                         # == 0
    assert checker.verify(bad) == (False, "bad reference point False")
    bad = json.loads(json.dumps(cert))
    perm = bad["witness"]["rotation"]["permutation"]
    perm[perm.index(1)] = True                                  # == 1
    assert checker.verify(bad) == (False, "rotation: not a list of 9 indices")
    obj = refutation.make_refutation(
        load(ROOT / "cases/discrepancies/family-chiral-c3-ring.toml"), "Pasym-Pord")
    assert checker.verify(json.loads(json.dumps(obj)))[0]
    assert not checker.verify({**json.loads(json.dumps(obj)), "version": True})[0]


def test_the_checker_runs_copied_as_a_directory(tmp_path):
    """``python -m checker`` in a copy of the directory; without the extensions, a
    certificate needing one is rejected naming it, and core certificates still verify."""
    full, core = tmp_path / "full" / "checker", tmp_path / "core" / "checker"
    shutil.copytree(CHECKER, full, ignore=shutil.ignore_patterns("__pycache__"))
    core.mkdir(parents=True)
    for name in CORE:
        shutil.copy(CHECKER / name, core / name)
    cases = {"rational": "cases/examples/chiral-nine-gon.toml",
             "radicands": "cases/polygon/regular-hexagon-sqrt3.toml",
             "tower": "cases/examples/nested-radical-pentagon.toml",
             "sparse": "cases/examples/big-turns-asymmetric.toml"}
    paths = {k: _write(tmp_path / f"{k}.json", json.dumps(_certificate(v)))
             for k, v in cases.items()}
    trig = _write(tmp_path / "trig.txt", "".join(   # a hexagon by cos and sin: Q(2cos(2pi/12))
        f"{sx}cos(pi/3) {sy}sin(pi/3)\n" for sx, sy in (("", ""), ("-", ""), ("-", "-"),
                                                         ("", "-"))) + "1 0\n-1 0\n")
    cert = json.loads(json.dumps(certificate.make_certificate(load(trig))))
    assert cert["configuration"]["field"]["irreducible"]["method"] == "real-cyclotomic"
    paths["minpoly"] = _write(tmp_path / "minpoly.json", json.dumps(cert))
    for kind, path in paths.items():
        assert _run_checker(full.parent, "checker", path).returncode == 0, kind
    for kind in ("rational", "radicands", "minpoly"):
        assert _run_checker(core.parent, "checker", paths[kind]).returncode == 0, kind
    for kind, ext in (("tower", "ext_tower.py"), ("sparse", "ext_sparse.py")):
        out = _run_checker(core.parent, "checker", paths[kind])
        assert out.returncode == 1 and f"needs the checker extension {ext}" in out.stderr, out


# ---------------------------------------------------------------- both sides agree
def test_psi_solver_and_checker_agree():
    from exactsym.certificates.fields import _psi
    for m in list(range(3, 300)) + [1155, 4620]:
        assert [int(c) for c in _psi(m).coeffs()] == checker.psi(m), m
        assert [int(c) for c in fmpz_poly.cos_minpoly(m).coeffs()] == checker.psi(m), m


@settings(max_examples=300, deadline=None)
@given(st.lists(st.integers(-30, 30), min_size=3, max_size=8).filter(lambda c: c[-1] != 0),
       st.fractions(-20, 20, max_denominator=16), st.fractions("1/16", 20, max_denominator=16))
def test_one_root_solver_and_checker_agree(coeffs, lo, width):
    """The producer's Descartes count (flint) decides as the checker's (integers)."""
    p = [Fraction(c) for c in coeffs]
    poly = fmpq_poly([fmpq(c) for c in coeffs])
    assert one_sign_change(poly, lo, lo + width) == checker.one_root(p, lo, lo + width)


def test_digest_and_statements_agree():
    rnd = random.Random(5)
    for _ in range(20):
        config = {"coordinates": rnd.choice(["polar", "cartesian"]), "field": None,
                  "points": [[str(rnd.randint(-9, 9)), f"{rnd.randint(1, 9)}/7"]
                             for _ in range(rnd.randint(1, 6))]}
        assert certificate.digest(config) == checker.digest(config)
    assert refutation.STATEMENTS == checker.REFUTABLE


@pytest.mark.parametrize("label, case", [
    ("Pasym-Pord", "cases/family/regular-d3-not-orderable.toml"),
    ("lem-asym-ord", "cases/discrepancies/family-c3-two-triangles.toml"),
    ("lemma-sym-regular", "cases/polygon/regular-pentagon-polar.toml"),
    ("obs-exh-poly", "cases/polygon/kite-polar.toml")])
def test_refusals_solver_and_checker_agree(label, case):
    """Where the producer refuses to write a refutation, the checker rejects the same object
    with the same reason."""
    config = load(ROOT / case)
    with pytest.raises(certificate.CertificateError) as refused:
        refutation.make_refutation(config, label)
    obj = {"format": refutation.FORMAT, "version": 1, "label": label,
           "statement": refutation.STATEMENTS[label],
           "certificate": certificate.make_certificate(config)}
    ok, why = checker.verify(json.loads(json.dumps(obj)))
    assert not ok and str(refused.value) == f"does not refute {label}: {why}"


def test_the_core_is_small_and_docs_count_it():
    """The core is at most 1,200 lines (wc -l) and docs/certificates.md gives each file's
    count; every other module of the checker is an extension."""
    counts = {p.name: len(p.read_text().splitlines()) for p in CHECKER.glob("*.py")}
    assert sum(counts[name] for name in CORE) <= 1200
    assert all(name.startswith("ext_") for name in set(counts) - set(CORE))
    docs = (ROOT / "docs" / "certificates.md").read_text()
    assert f"The **core**, {sum(counts[n] for n in CORE):,} lines" in docs
    for name, lines in counts.items():
        assert re.search(rf"`(exactsym/checker/)?{re.escape(name)}` \| {lines} \|", docs), name
