"""Integer factorisation, merged: ``{prime: exponent}``, and the one primality test of the
solver (python-flint's, which proves; the checker and the certifier have their own).

python-flint's ``fmpz.factor()`` (0.9.0) can list one prime twice, each time with
exponent 1: ``fmpz(3513839015486888 * 110994919281).factor()`` gives ``(111053, 1)`` twice.
Reading that list as a factorisation made ``sqrt_rational`` return a radicand with a square
factor, an element that is not canonical (equal numbers with different terms); every
caller goes through :func:`factorization` instead.
"""

from __future__ import annotations

from flint import fmpz


def factorization(n: int) -> dict[int, int]:
    """``{p: e}`` with ``n == prod(p ** e)`` for an integer ``n >= 1``."""
    out: dict[int, int] = {}
    for p, e in fmpz(n).factor():
        p = int(p)
        out[p] = out.get(p, 0) + int(e)
    return out


def is_prime(n: int) -> bool:
    """Whether the integer ``n`` is a prime (python-flint's ``fmpz.is_prime``: a proof,
    not a probable-prime test)."""
    return n >= 2 and bool(fmpz(n).is_prime())
