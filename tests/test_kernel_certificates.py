"""Certificates for the fields issue 9 found uncertifiable, and tamper tests for them.

A multiquadratic field written by a primitive element (sqrt(2+sqrt(3)) generates
Q(sqrt(2), sqrt(3))) is reducible modulo every prime; its minimal polynomial is proved
irreducible by the checker's "square-roots" method instead (``docs/certificates.md``)."""

from __future__ import annotations

import copy
import json

import pytest

from exactsym import checker
from exactsym.certificate import make_certificate
from exactsym.configuration import load


def _cert(tmp_path, points: list[str]) -> dict:
    path = tmp_path / "c.toml"
    path.write_text("format = 1\npoints = [\n" + ",\n".join(points) + "\n]\n")
    cert = json.loads(json.dumps(make_certificate(load(str(path)))))
    ok, message = checker.verify_certificate(cert)
    assert ok, message
    return cert


def _rejected(cert: dict, fragment: str) -> None:
    cert["configuration_sha256"] = checker.digest(cert["configuration"])
    ok, message = checker.verify_certificate(cert)
    assert not ok and fragment in message, message


@pytest.mark.parametrize("points, group", [
    (['["sqrt(2+sqrt(3))", "0"]'], "O2"),
    (['["sqrt(2+sqrt(3))", "0"]', '["0", "sqrt(2+sqrt(3))"]', '["-sqrt(2+sqrt(3))", "0"]',
      '["0", "-sqrt(2+sqrt(3))"]'], "D4"),
    (['["sqrt(2+sqrt(3))", "1"]', '["1", "sqrt(2)"]', '["0", "0"]'], "C1"),
])
def test_nested_biquadratic_fields_are_certified(tmp_path, points, group):
    cert = _cert(tmp_path, points)
    assert cert["claim"]["group"] == group
    field = cert["configuration"]["field"]
    if field is not None and field["irreducible"]["method"] == "square-roots":
        assert len(field["irreducible"]["radicands"]) == 2


def test_square_root_proofs_are_checked(tmp_path):
    cert = _cert(tmp_path, ['["sqrt(2+sqrt(3))", "0"]'])
    proof = cert["configuration"]["field"]["irreducible"]
    assert proof["method"] == "square-roots"
    bad = copy.deepcopy(cert)
    bad["configuration"]["field"]["irreducible"]["radicands"] = ["2", "8"]
    _rejected(bad, "a product of radicands is a square")
    bad = copy.deepcopy(cert)
    root = bad["configuration"]["field"]["irreducible"]["roots"][0]
    root[0] = str(checker.frac(root[0]) + 1).replace(" ", "")
    _rejected(bad, "does not square to it")
    bad = copy.deepcopy(cert)
    bad["configuration"]["field"]["irreducible"]["radicands"] = ["2"]
    bad["configuration"]["field"]["irreducible"]["roots"] = [proof["roots"][0]]
    _rejected(bad, "degree 2^k")
    bad = copy.deepcopy(cert)       # another polynomial: interval and roots no longer fit
    bad["configuration"]["field"]["minpoly"] = ["1", "0", "-10", "0", "1"]
    ok, _ = checker.verify_certificate(bad)
    assert not ok
