"""Certificates of configurations in a sparse Q(zeta_N) (certificate.py, checker_sparse.py):
they verify, tampering is caught, and the checker's own zero test and cosine enclosures agree
with the solver's."""

from __future__ import annotations

import copy
import json

import pytest
from flint import arb, ctx, fmpq
from hypothesis import given, settings, strategies as st

from exactsym import checker
from exactsym.certificate import make_certificate
from exactsym.checker_sparse import SparseField, _zero, is_prime
from exactsym.configuration import load
from exactsym.exact import cyclotomic
from exactsym.exact.sparse_cyclotomic import is_zero_sum, sparse_context


def _file(tmp_path, rows, name="c.toml"):
    path = tmp_path / name
    path.write_text("format = 1\npoints = [\n" + ",\n".join(rows) + "\n]\n")
    return str(path)


def _orbit(k, r, offset, shift=("1", "1/3")):
    rows = []
    for j in range(k):
        q = 2 * (fmpq(j, k) + offset)
        rows.append(f'["{shift[0]} + {r}*cos({q.p}/{q.q}*pi)", '
                    f'"{shift[1]} + {r}*sin({q.p}/{q.q}*pi)"]')
    return rows


D = fmpq(1, 999983)
CASES = {
    "C1": ['{ r = "1", turn = "0" }', '{ r = "1", turn = "1/999983" }',
           '{ r = "2", turn = "2/5" }', '{ r = "3", turn = "3/999979" }',
           '{ r = "1", turn = "5/13" }'],
    "D5": _orbit(5, 1, D),
    "C5": _orbit(5, 1, D) + _orbit(5, 2, D + fmpq(1, 13)),
    "D7": _orbit(7, 1, D),
    # square roots of rationals join as Gauss sums
    "C1 with square roots": ['{ r = "sqrt(2)", turn = "0" }', '{ r = "1", turn = "1/999983" }',
                             '{ r = "sqrt(5)", turn = "2/5" }', '{ r = "3", turn = "3/999979" }',
                             '["sqrt(3)/7", "cos(2*pi/999983) - 1/2"]'],
}


def _cert(tmp_path, rows):
    cert = json.loads(json.dumps(make_certificate(load(_file(tmp_path, rows)))))
    ok, message = checker.verify_certificate(cert)
    assert ok, message
    return cert


@pytest.mark.parametrize("group", sorted(CASES))
def test_sparse_certificates_verify(tmp_path, group):
    cert = _cert(tmp_path, CASES[group])
    assert cert["claim"]["group"] == group.split()[0]
    assert "sparse-cyclotomic" in cert["configuration"]["field"]


def _rejected(cert, fragment=""):
    cert["configuration_sha256"] = checker.digest(cert["configuration"])
    ok, message = checker.verify_certificate(cert)
    assert not ok and fragment in message, message


def test_tampered_sparse_certificates_are_rejected(tmp_path):
    good = _cert(tmp_path, CASES["D5"])
    spec = good["configuration"]["field"]["sparse-cyclotomic"]
    # a composite "prime" factor: the zero test would be unsound
    bad = copy.deepcopy(good)
    factors = bad["configuration"]["field"]["sparse-cyclotomic"]["factors"]
    p = int(factors[-1][0])
    n = int(spec["conductor"])
    bad["configuration"]["field"]["sparse-cyclotomic"]["factors"] = \
        factors[:-1] + [[str(p * 3), 1]]
    _rejected(bad)
    # a root of smaller order: the hash would not be a homomorphism of Q(zeta_N)
    bad = copy.deepcopy(good)
    ell = int(spec["prime"])
    bad["configuration"]["field"]["sparse-cyclotomic"]["root"] = str(pow(int(spec["root"]), 2, ell))
    _rejected(bad, "order")
    bad = copy.deepcopy(good)
    bad["configuration"]["field"]["sparse-cyclotomic"]["prime"] = str(ell + n)
    _rejected(bad)
    # a moved point: the claimed group no longer holds
    bad = copy.deepcopy(good)
    x = bad["configuration"]["points"][1][0]
    key = next(k for k in x if k != "0")
    x[key] = "2"
    _rejected(bad)
    # a wrong claim
    bad = copy.deepcopy(good)
    bad["claim"]["group"] = "C5"
    _rejected(bad)
    # a wrong SEC scale
    bad = copy.deepcopy(_cert(tmp_path, CASES["C1"]))
    if "scale" in bad["witness"]["sec"]:
        bad["witness"]["sec"]["scale"] = "3"
        _rejected(bad)


@settings(max_examples=80, deadline=None)
@given(st.data(), st.sampled_from([12, 20, 36, 45, 60, 63, 84, 90, 105, 180, 210, 420]))
def test_checker_zero_test_agrees(data, m):
    """The checker's zero test (its own code) against the solver's and the dense field."""
    factors = sorted(cyclotomic.factorization(m).items(), key=lambda pa: (pa[1] == 1, -pa[0]))
    exps = data.draw(st.lists(st.integers(0, m - 1), min_size=1, max_size=6))
    terms = {e: data.draw(st.integers(-3, 3)) for e in exps}
    if data.draw(st.booleans()):                 # add a vanishing sum
        p = data.draw(st.sampled_from([p for p, _ in factors]))
        s = data.draw(st.integers(0, m - 1))
        for k in range(p):
            e = (s + k * (m // p)) % m
            terms[e] = terms.get(e, 0) + 2
    terms = {e: c for e, c in terms.items() if c}
    field = cyclotomic.cyclotomic_field(m)
    dense = sum((c * cyclotomic.root_of_unity(field, e) for e, c in terms.items()), field(0))
    expected = dense == 0
    assert _zero(terms, m, factors) == expected
    assert is_zero_sum({e: fmpq(c) for e, c in terms.items()}, m) == expected


def test_checker_cosines_enclose_the_value():
    context = sparse_context(4 * 5 * 13 * 999983 * 999979)
    field = SparseField({"conductor": str(context.n),
                         "factors": [[str(p), a] for p, a in context.factors.items()],
                         "prime": str(context.ell), "root": str(context.g)})
    for e in [0, 1, 259994540, context.n // 4, context.n // 3, context.n // 2 - 1, 12345678901]:
        for bits in (64, 256):
            lo, hi = field.cos_bounds(e, bits)
            with ctx.workprec(bits + 64):
                value = arb.cos_pi_fmpq(fmpq(2 * e, context.n)) * arb(2) ** bits
                assert lo <= value.lower() and value.upper() <= hi
            assert hi - lo < 1 << 16


def test_miller_rabin():
    assert [n for n in range(100) if is_prime(n)] == [
        2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53, 59, 61, 67, 71, 73, 79, 83,
        89, 97]
    assert is_prime(999983) and is_prime(999979) and not is_prime(999983 * 999979)
    assert not is_prime(3215031751)             # a strong pseudoprime to bases 2, 3, 5, 7


@settings(max_examples=40, deadline=None)
@given(st.data(), st.sampled_from([20, 36, 60, 84, 180, 420]))
def test_checker_numbers_agree_with_the_solver(data, m):
    """The checker's cosine-form sums and products (its own code) against the solver's:
    equal numbers, equal residues (hash), the same sign."""
    from exactsym.certificate import Encoder
    from exactsym.exact.evaluate import SparseCyclotomicSystem
    system = SparseCyclotomicSystem(m)
    field = SparseField({"conductor": str(m),
                         "factors": [[str(p), a] for p, a in system.context.factors.items()],
                         "prime": str(system.context.ell), "root": str(system.context.g)})
    turns = [fmpq(data.draw(st.integers(0, m - 1)), m) for _ in range(3)]
    xs = [system.cos_turn(t) * data.draw(st.integers(-3, 3)) + fmpq(1, 3) for t in turns]
    value = xs[0] * xs[1] - xs[2] * xs[2] * 2
    enc = Encoder(system, xs + [value])
    a, b, c = (field.num(enc.text(x)) for x in xs)
    mine = a * b - c * c * 2
    theirs = field.num(enc.text(value))
    assert mine == theirs and hash(mine) == hash(theirs)
    assert mine.sign() == value.sign()
    assert (mine - 1 == theirs) is False


def test_conductors_beyond_the_checker_are_refused_in_one_line(tmp_path):
    """A turn whose denominator has a prime factor above the checker's Miller-Rabin range:
    check answers, certify refuses with exit 2 and one line."""
    from exactsym.cli import main
    p = 10 ** 25 + 13                     # a prime above 3.3 * 10^24
    assert checker_is_prime_range(p)
    path = _file(tmp_path, ['{ r = "1", turn = "0" }', f'{{ r = "2", turn = "1/{p}" }}',
                            '{ r = "3", turn = "1/3" }'])
    assert main(["check", path]) == 0
    assert main(["certify", path, "-o", str(tmp_path / "c.json")]) == 2


def checker_is_prime_range(p: int) -> bool:
    from flint import fmpz
    return bool(fmpz(p).is_prime()) and p > 3317044064679887385961981


def _moderate(tmp_path, den=127):
    """Six robots off the origin at turns j/den: a dense Q(zeta_4 den) of degree
    2 (den - 1) for check."""
    rows = [f'{{ r = "{r}", turn = "{t}/{den}" }}' for r, t in
            [(5, 0), (6, den // 3), (7, 2 * den // 3), (1, 1), (2, 2), (3, den // 2)]]
    return _file(tmp_path, rows)


def test_certify_writes_moderate_cyclotomic_fields_sparse(tmp_path, capsys):
    """exactsym certify reads cos/sin beyond a dense degree of 64 in the sparse field (the
    checker multiplies dense numbers term by term): the certificate's field is sparse, it
    verifies, and it claims the group check reports; degree 24 stays dense."""
    from exactsym.analysis import analyse
    from exactsym.cli import main
    for den, kind in ((127, "sparse-cyclotomic"), (13, None)):
        path = _moderate(tmp_path, den)
        out = tmp_path / f"c{den}.json"
        assert main(["certify", path, "-o", str(out)]) == 0
        cert = json.loads(out.read_text())
        ok, message = checker.verify_certificate(cert)
        assert ok, message
        field = cert["configuration"]["field"]
        assert (kind in field) if kind else "sparse-cyclotomic" not in json.dumps(field)
        truth = analyse(load(path), sections=["truth"]).truth
        assert cert["claim"]["group"] == truth.name
        assert cert["claim"]["ordering"] == list(truth.ordering)


def test_certify_falls_back_to_the_dense_field(tmp_path, monkeypatch):
    """When the sparse field cannot write a certificate, certify writes it in the dense
    field check uses (one that verifies)."""
    import exactsym.certificate as certificate
    from exactsym.certificate import CertificateError
    from exactsym.certify_cli import _certificate
    from exactsym.exact.evaluate import SparseCyclotomicSystem
    from exactsym.fileformat import read_config
    made = certificate.make_certificate
    seen = []

    def dense_only(config):
        sparse = isinstance(config.system, SparseCyclotomicSystem)
        seen.append(sparse)
        if sparse:
            raise CertificateError("refused for the test")
        return made(config)
    monkeypatch.setattr(certificate, "make_certificate", dense_only)
    config, cert = _certificate(read_config(_moderate(tmp_path)), None)
    assert seen == [True, False]
    assert "sparse-cyclotomic" not in json.dumps(cert["configuration"]["field"])
    ok, message = checker.verify_certificate(json.loads(json.dumps(cert)))
    assert ok, message
