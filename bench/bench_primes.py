"""Benchmark: primality certificates of large primes (turn denominators of certify).

For each size, ``--count`` primes (the least prime above a random integer of that many
digits, seeded by the size) are proved by ``prime_certificates.primality_proofs`` (the
bounded p - 1 effort, then an elliptic curve when p - 1 resists) and the proofs re-checked by
``checker/ext_primes.proved_primes``.  Prints per size how many were proved, in how many of
those an elliptic curve was used, and the median and largest CPU seconds per prime.  There
is no float yardstick for primality; the target is that ``certify`` never refuses what
``check`` answered, within a bounded time.  Run: ``python bench/bench_primes.py [--digits 60 80 100] [--count 12]``.
"""

from __future__ import annotations

import argparse
import random
import statistics
import time

from flint import fmpz

from exactsym.checker.ext_primes import proved_primes
from exactsym.certificates.primes import PrimalityError, primality_proofs


def _next_prime(n: int) -> int:
    while not fmpz(n).is_prime():
        n += 1
    return n


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--digits", type=int, nargs="+", default=[60, 80, 100, 150, 200])
    parser.add_argument("--count", type=int, default=12)
    args = parser.parse_args()
    print(f"{'digits':>6} {'proved':>7} {'curve':>6} {'median s':>9} {'max s':>7}")
    for digits in args.digits:
        rng = random.Random(digits)
        times, proved, curves = [], 0, 0
        for _ in range(args.count):
            p = _next_prime(rng.randrange(10 ** (digits - 1), 10 ** digits))
            start = time.process_time()
            try:
                proofs = primality_proofs([p])
            except PrimalityError:
                proofs = None
            times.append(time.process_time() - start)
            if proofs is not None:
                assert p in proved_primes(proofs), p
                proved += 1
                curves += any("curve" in entry for entry in proofs)
        print(f"{digits:>6} {proved:>4}/{args.count:<2} {curves:>6} "
              f"{statistics.median(times):>9.2f} {max(times):>7.2f}", flush=True)


if __name__ == "__main__":
    main()
