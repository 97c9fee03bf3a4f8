"""``certify`` succeeds wherever ``check`` answers (issue 9): every number kind the parser
accepts and their mixes, and tamper tests for the square-roots proof over a cyclotomic field.

The fixed table is ``bench/certify_fields.py``'s (which also times it); the hypothesis test
draws small configurations over random atoms of each kind and of each mix, symmetric (rings of
k points) and asymmetric, and requires certify to succeed and the checker to accept.
"""

from __future__ import annotations

import copy
import importlib
import importlib.util
import json
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings, strategies as st

from exactsym import checker
from exactsym.certificates.certificate import make_certificate
from exactsym.geometry.configuration import load
from certificate_checks import rejected

ROOT = Path(__file__).resolve().parents[2]
_spec = importlib.util.spec_from_file_location("certify_fields", ROOT / "bench" /
                                               "certify_fields.py")
fields = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(fields)

# the table's slow rows (nine square roots, a polar field of degree 576: several seconds
# each) run in the hypothesis draws' place only with EXACTSYM_SLOW=1.  Nested radicals with
# cos/sin (formerly sympy's primitive element, seconds each) take milliseconds in a tower over
# Q(zeta_M) and run by default ("nested + trig/16" denests: no level, a real-cyclotomic field)
SLOW = {"nine sqrt C1", "polar r sqrt(2) turns 2/45,47/90,59/315"}


def certify_text(tmp_path: Path, points: list[str]) -> dict:
    path = tmp_path / "c.toml"
    path.write_text(fields.toml(points))
    cert = json.loads(json.dumps(make_certificate(load(str(path)))))
    ok, message = checker.verify_certificate(cert)
    assert ok, message
    return cert


@pytest.mark.parametrize("name", [n for n in fields.CASES if n not in SLOW])
def test_every_kind_certifies(tmp_path, name):
    kind, points = fields.CASES[name]
    cert = certify_text(tmp_path, points)
    assert cert["claim"]["group"]


@pytest.mark.skipif(not __import__("os").environ.get("EXACTSYM_SLOW"),
                    reason="slow: EXACTSYM_SLOW=1")
@pytest.mark.parametrize("name", sorted(SLOW & set(fields.CASES)))
def test_every_slow_kind_certifies(tmp_path, name):
    certify_text(tmp_path, fields.CASES[name][1])


# ------------------------------------------------------------------ random configurations
def _atom(kind: str, draw) -> str:
    small = st.integers(1, 9)
    if kind == "rational":
        return f"{draw(st.integers(-9, 9))}/{draw(small)}"
    if kind == "sqrt":
        return f"{draw(st.integers(-3, 3))}*sqrt({draw(st.sampled_from([2, 3, 5, 6, 7, 10]))})"
    if kind == "trig":
        q = f"{draw(st.integers(1, 11))}/{draw(st.sampled_from([5, 7, 8, 10, 12]))}"
        return f"{draw(small)}*{draw(st.sampled_from(['cos', 'sin']))}({q}*pi)"
    raise AssertionError(kind)


@st.composite
def configurations(draw):
    """A small configuration over one kind of number or a mix of two (turn denominators
    kept small: an off-centre polar point with turns of denominator in the hundreds needs a
    real cyclotomic field of degree in the hundreds, several seconds per draw)."""
    kinds = draw(st.sampled_from([("rational",), ("sqrt",), ("trig",), ("sqrt", "trig"),
                                  ("rational", "sqrt"), ("polar",), ("polar", "sqrt"),
                                  ("polar", "trig")]))
    if "polar" in kinds:
        k = draw(st.integers(1, 6))
        radii = [draw(st.sampled_from(["1", "2", "sqrt(2)", "sqrt(3)", "3/2"]))
                 for _ in range(draw(st.integers(1, 2)))]
        den = draw(st.sampled_from([5, 7, 8, 10, 12]))
        points = []
        for j, r in enumerate(radii):
            points += fields.ring(r, k, f"{draw(st.integers(0, den - 1))}/{den}" if j else "0")
        if len(kinds) > 1 or draw(st.booleans()):          # off the centre, or a mix
            other = [k for k in kinds if k != "polar"] or ["rational"]
            points.append(f'["{_atom(other[0], draw)}", "{_atom(other[-1], draw)}"]')
        return points
    n = draw(st.integers(1, 4))
    pts = {(_atom(draw(st.sampled_from(kinds)), draw), _atom(draw(st.sampled_from(kinds)), draw))
           for _ in range(n)}
    if draw(st.booleans()):                     # a half-turn symmetric copy
        pts |= {(f"-({x})", f"-({y})") for x, y in pts}
    return [f'["{x}", "{y}"]' for x, y in sorted(pts)]


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow,
                                                                  HealthCheck.function_scoped_fixture])
@given(points=configurations())
def test_random_configurations_certify(tmp_path, points):
    path = tmp_path / "c.toml"
    path.write_text(fields.toml(points))
    try:
        config = load(str(path))
    except Exception as err:                    # coincident points: not a configuration
        if "coincide" in str(err):
            return
        raise
    cert = json.loads(json.dumps(make_certificate(config)))
    ok, message = checker.verify_certificate(cert)
    assert ok, message


# ------------------------------------------------------------------ tampering
@pytest.fixture
def primitive_element_path(monkeypatch):
    """Nested radicals mixed with cos/sin through sympy's primitive element (the kernel now
    writes them in a tower over Q(zeta_M), exact/cyclotomic_tower.py): the square-roots
    irreducibility proofs below are made for such fields."""
    from reference.general import general_system
    monkeypatch.setattr(importlib.import_module("exactsym.exact.evaluate"), "_mixed_system",
                        general_system)


def test_even_degree_cyclotomic_part_is_checked(tmp_path, primitive_element_path):
    """Q(sqrt 3, cos(2pi/16)) (written with a nested radical): degree 8 = 2 * 4, Galois group
    C4 x C2, so no prime works; the proof names sqrt(3) and a root of Psi_16.  sqrt(2) also
    squares to 2 in the field, but lies in K = Q(cos(2pi/16)): the checker refuses it."""
    cert = certify_text(tmp_path, fields.cart(("sqrt(2+sqrt(3))", "0"), ("cos(2*pi/16)", "1"),
                                              ("0", "0")))
    proof = cert["configuration"]["field"]["irreducible"]
    assert proof["method"] == "square-roots"
    assert [p["conductor"] for p in proof["cyclotomic"]] == [16]
    field = checker.Field(cert["configuration"]["field"])
    h = field.num(proof["cyclotomic"][0]["root"])
    two = h * h - 2                              # (2cos(pi/8))^2 - 2 = sqrt(2)
    assert two * two == 2
    bad = copy.deepcopy(cert)
    p = bad["configuration"]["field"]["irreducible"]
    i = p["radicands"].index("3") if "3" in p["radicands"] else 0
    p["radicands"][i] = "2"
    p["roots"][i] = [f"{c}/{two.den}" for c in two.c]
    rejected(bad, "lies in Q(zeta_16)")
    bad = copy.deepcopy(cert)                    # a changed radicand: the root no longer fits
    bad["configuration"]["field"]["irreducible"]["radicands"][i] = "5"
    rejected(bad, "does not square to it")
    bad = copy.deepcopy(cert)                    # a changed conductor: h is not a root of it
    bad["configuration"]["field"]["irreducible"]["cyclotomic"][0]["conductor"] = 20
    rejected(bad, "is not a root of Psi_20")
    bad = copy.deepcopy(cert)                    # the cyclotomic part dropped: 2 != 8
    del bad["configuration"]["field"]["irreducible"]["cyclotomic"]
    rejected(bad, "degree 2^k e")


def test_cyclotomic_parts_must_have_coprime_conductors(tmp_path, primitive_element_path):
    cert = certify_text(tmp_path, fields.cart(("sqrt(2+sqrt(3))", "0"), ("cos(2*pi/13)", "1"),
                                              ("0", "0")))
    proof = cert["configuration"]["field"]["irreducible"]
    assert len(proof["radicands"]) == 2 and proof["cyclotomic"][0]["conductor"] == 13
    bad = copy.deepcopy(cert)                    # the same part twice: degree 36 claimed
    parts = bad["configuration"]["field"]["irreducible"]["cyclotomic"]
    parts.append(copy.deepcopy(parts[0]))
    rejected(bad, "pairwise coprime")
    bad = copy.deepcopy(cert)                    # a witness (root of sqrt 2) changed
    root = bad["configuration"]["field"]["irreducible"]["roots"][0]
    root[0] = str(checker.frac(root[0]) + 1).replace(" ", "")
    rejected(bad, "does not square to it")
