"""Refutation certificates beyond Pasym-Pord (exactsym.certificates.refutation, checker.verify_refutation):
every shipped certificate verifies, and every tampering -- a point, the claim, the label,
a part -- is rejected with a reason."""

from __future__ import annotations

import copy
import json
from pathlib import Path

import pytest

from exactsym import checker
from exactsym.certificates.certificate import CertificateError
from exactsym.geometry.configuration import load
from exactsym.certificates.refutation import PREMISES, make_refutation

ROOT = Path(__file__).resolve().parents[2]
RING = "cases/discrepancies/family-chiral-c3-ring.toml"
TRIANGLES = "cases/discrepancies/family-c3-two-triangles.toml"
NONAGON = "cases/polygon/d3-nonagon-type4.toml"
WITNESS = {"cor-Pasym-Pord": RING, "lem-one-pair-asym-ord": RING,
           "lem-asym-pair-ord": TRIANGLES, "lem-all-pair-asym-ord": TRIANGLES,
           "obs-merg-asym-pair": TRIANGLES, "lemma-sym-regular": NONAGON,
           "obs-exh-poly": "cases/discrepancies/d3-hexagon.toml"}


@pytest.fixture(scope="module")
def made():
    return {label: json.loads(json.dumps(make_refutation(load(ROOT / case), label)))
            for label, case in WITNESS.items()}


def rejected(obj, *reasons):
    ok, why = checker.verify_refutation(obj)
    assert not ok and any(r in why for r in reasons), why


def _rehash(cert):
    cert["configuration_sha256"] = checker.digest(cert["configuration"])
    return cert


def test_every_refutable_label_has_a_premise_and_a_witness(made):
    assert set(PREMISES) == set(checker.REFUTABLE)
    assert set(WITNESS) | {"Pasym-Pord", "lem-asym-ord"} == set(checker.REFUTABLE)
    for label, obj in made.items():
        ok, why = checker.verify_refutation(obj)
        assert ok and why.startswith(f"{label} refuted"), (label, why)


def test_the_label_and_the_statement_are_checked(made):
    obj = made["lem-asym-pair-ord"]
    rejected({**obj, "label": "lem-sym-notord"}, "no refutation by symmetry facts")
    rejected({**obj, "label": "cor-Pasym-Pord"}, "the statement is not the label's")
    # relabelled with its statement: the parts do not carry the other premise
    rejected({**obj, "label": "cor-Pasym-Pord", "statement": checker.REFUTABLE[
        "cor-Pasym-Pord"]}, "KeyError", "'level'")
    # lem-asym-pair-ord needs P to be the pair; the C3 ring's certificate is not
    ring = made["cor-Pasym-Pord"]
    rejected({**ring, "label": "lem-asym-pair-ord",
              "statement": checker.REFUTABLE["lem-asym-pair-ord"]}, "pair")


def test_a_moved_point_is_rejected(made):
    for label, obj in made.items():
        bad = copy.deepcopy(obj)
        bad["certificate"]["configuration"]["points"][0][1] = "1/7"
        _rehash(bad["certificate"])
        rejected(bad, "the image of point", "neither in the claimed group", "invalid")
    # a part's point moved: its own certificate fails, or its points are not P's
    for label in ("cor-Pasym-Pord", "obs-merg-asym-pair"):
        bad = copy.deepcopy(made[label])
        part = bad["parts"]["level"] if "level" in bad["parts"] else bad["parts"]["merged"]
        part["configuration"]["points"][0][1] = "1/7"
        _rehash(part)
        rejected(bad, "is invalid", "not the ones the checker computes")


def test_a_changed_claim_is_rejected(made):
    for label, obj in made.items():
        bad = copy.deepcopy(obj)
        bad["certificate"]["claim"]["orderable"] = True
        rejected(bad, "the embedded certificate is invalid")


def test_parts_must_prove_the_premise(made):
    # a symmetric level (the two-triangles' D3 triangle) is no asymmetric polygon
    pair = made["lem-asym-pair-ord"]["parts"]["pair"]
    obj = copy.deepcopy(made["lem-asym-pair-ord"])
    obj.update(label="cor-Pasym-Pord", statement=checker.REFUTABLE["cor-Pasym-Pord"],
               parts={"level": pair[0]})
    rejected(obj, "it is symmetric")
    # one level named twice is not a pair
    obj = copy.deepcopy(made["lem-all-pair-asym-ord"])
    obj["parts"]["pair"] = [pair[0], pair[0]]
    rejected(obj, "one level twice")
    # the merged polygon must be the one the checker builds
    obj = copy.deepcopy(made["obs-merg-asym-pair"])
    obj["parts"]["merged"] = pair[1]
    rejected(obj, "not the ones the checker computes")


def test_configurations_that_do_not_refute_are_refused():
    with pytest.raises(CertificateError, match="no level without a mirror"):
        make_refutation(load(ROOT / TRIANGLES), "cor-Pasym-Pord")
    with pytest.raises(CertificateError, match="not one polygon"):
        make_refutation(load(ROOT / TRIANGLES), "lemma-sym-regular")
    with pytest.raises(CertificateError, match="more than one line of symmetry"):
        make_refutation(load(ROOT / RING), "lemma-sym-regular")
    with pytest.raises(CertificateError, match="regular"):
        make_refutation(load(ROOT / "cases/polygon/regular-pentagon-polar.toml"),
                        "lemma-sym-regular")


def test_each_type_of_obs_exh_poly_is_recognised():
    # a polygon of each type makes the checker say which type it is: no refutation
    for case, kind in (("cases/polygon/regular-pentagon-polar.toml", "type 0"),
                       ("cases/polygon/kite-polar.toml", "type 2"),
                       ("cases/discrepancies/isosceles-triangle.toml", "type 3"),
                       (NONAGON, "type 4")):
        with pytest.raises(CertificateError, match=kind):
            make_refutation(load(ROOT / case), "obs-exh-poly")
    for case in ("d4-octagon", "d2-octagon-vertex-lines"):   # the other two witnesses
        obj = make_refutation(load(ROOT / f"cases/discrepancies/{case}.toml"), "obs-exh-poly")
        assert checker.verify_refutation(json.loads(json.dumps(obj)))[0]


def test_shipped_certificates_are_the_ones_certify_writes(made):
    for label, obj in made.items():
        shipped = [p for p in (ROOT / "proofs" / "certificates").glob(f"{label}-*.json")]
        assert shipped, label
        got = json.loads(shipped[0].read_text())
        assert checker.verify_refutation(got)[0] and got["label"] == label
        assert got["certificate"]["configuration"] == obj["certificate"]["configuration"]
        assert set(got.get("parts", {})) == set(obj.get("parts", {})), label
