"""Elliptic-curve primality certificates (exactsym/certificates/elliptic_primes.py) and their check
(checker/ext_primes._elliptic): a turn 1/p with p a 100-digit prime whose p - 1 resists now
certifies; every proof verifies; tampering is caught."""

from __future__ import annotations

import copy
import random

import pytest
from flint import fmpz

from exactsym import checker
from exactsym.checker.ext_primes import _elliptic, proved_primes
from exactsym.cli.main import main
from exactsym.certificates.elliptic_primes import MR_LIMIT, elliptic_proofs

P100 = 10 ** 99 + 289           # p - 1 has 37 bits factored of 329, p + 1 53


def _next_prime(n: int) -> int:
    while not fmpz(n).is_prime():
        n += 1
    return n


@pytest.fixture(scope="module")
def chain():
    return elliptic_proofs(P100)


def test_a_100_digit_prime_is_proved(chain):
    assert int(chain[-1]["prime"]) == P100
    assert [int(e["prime"]) for e in chain] == sorted(int(e["prime"]) for e in chain)
    assert int(chain[0]["order"]) < MR_LIMIT
    assert P100 in proved_primes(chain) == proved_primes(chain[::-1])


def test_random_primes_are_proved():
    rng = random.Random(5)
    for digits in (26, 40, 60, 80):
        p = _next_prime(rng.randrange(10 ** (digits - 1), 10 ** digits))
        assert p in proved_primes(elliptic_proofs(p))


def test_the_chain_descends():
    """This prime once looped: an order m = n + 1 + u, itself prime and above n, was taken as
    q (smooth part 1), and n came back as the next step's order.  Now every q is below its
    prime."""
    p = 35197046905603822917654843470020805689036285004223581763295198594326725443260797
    chain = elliptic_proofs(p)
    assert p in proved_primes(chain)
    assert all(int(e["order"]) < int(e["prime"]) for e in chain)


def test_primes_above_the_digit_limit_are_refused_before_searching(monkeypatch):
    from exactsym.certificates import elliptic_primes

    def searched(n):
        raise AssertionError("searched")
    monkeypatch.setattr(elliptic_primes, "_step", searched)
    big = 10 ** elliptic_primes.DIGIT_LIMIT + 1       # not even tested for primality
    with pytest.raises(elliptic_primes.EllipticError, match="stop at 200 digits"):
        elliptic_proofs(big)


def _rejects(entries, reason):
    with pytest.raises(checker.Invalid, match=reason):
        proved_primes(entries)


def test_tampered_elliptic_proofs_are_rejected(chain):
    top = chain[-1]
    p, q = P100, int(top["order"])
    a, b = (int(v) for v in top["curve"])
    x, y = (int(v) for v in top["point"])
    bad = copy.deepcopy(chain)
    bad[-1]["point"] = [str(x), str(y + 1)]
    _rejects(bad, "not on the curve")
    bad = copy.deepcopy(chain)
    bad[-1]["order"] = str(q + 2)                   # not among the proved primes
    _rejects(bad, "cannot prove|not a proved prime")
    _rejects(chain[1:], "cannot prove|not a proved prime")   # the order's proof left out
    with pytest.raises(checker.Invalid, match="not above"):
        _elliptic(p, [a, b], [x, y], 101, set())     # a small order proves nothing
    # another point of the same curve: its order is not q
    rng = random.Random(1)
    while True:
        x2 = rng.randrange(p)
        rhs = (x2 ** 3 + a * x2 + b) % p
        if pow(rhs, (p - 1) // 2, p) == 1:
            break
    from exactsym.exact.tower_proof import sqrt_mod
    y2 = sqrt_mod(rhs, p)
    with pytest.raises(checker.Invalid, match="is not -P|infinity|not a unit"):
        _elliptic(p, [a, b], [x2, y2], q, proved_primes(chain[:-1]))
    with pytest.raises(checker.Invalid, match="singular"):
        _elliptic(p, [0, 0], [0, 0], q, proved_primes(chain[:-1]))


def test_composites_are_not_proved():
    """A composite n = r s (r, s primes): the proof of the prime r, replayed for n with the
    same curve and point (lifted by CRT, on the curve modulo n), is refused."""
    r = _next_prime(10 ** 30)
    entry = elliptic_proofs(r)[-1]
    assert int(entry["prime"]) == r
    s = _next_prime(r + 1000)
    n = r * s
    a, b = (int(v) for v in entry["curve"])
    x, y = (int(v) for v in entry["point"])
    # the point modulo s: any point of the curve there; CRT to a point modulo n
    from exactsym.exact.tower_proof import sqrt_mod
    xs = 0
    while True:
        ys = sqrt_mod((xs ** 3 + a * xs + b) % s, s)
        if ys:
            break
        xs += 1
    crt = lambda u, v: (u * s * pow(s, -1, r) + v * r * pow(r, -1, s)) % n  # noqa: E731
    with pytest.raises(checker.Invalid):
        _elliptic(n, [a, b], [crt(x, xs), crt(y, ys)], int(entry["order"]),
                  proved_primes(elliptic_proofs(int(entry["order"]))))


def test_a_turn_of_a_100_digit_prime_certifies(tmp_path, capsys):
    """check answered this and certify refused it (p - 1 resists); now the certificate proves
    p by an elliptic curve and verifies."""
    path = tmp_path / "big.toml"
    path.write_text('format = 1\npoints = [\n  { r = "1", turn = "0" },\n'
                    f'  {{ r = "1", turn = "1/{P100}" }},\n  {{ r = "2", turn = "1/3" }},\n]\n')
    out = tmp_path / "big.json"
    assert main(["certify", str(path), "-o", str(out)]) == 0
    assert main(["verify", str(out)]) == 0
    assert "curve" in out.read_text()
