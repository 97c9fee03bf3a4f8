"""The independent checker of exactsym certificates: the modules a sceptic must trust.

Standard library only; imports nothing from exactsym but its own modules:
``checker_numbers`` (exact numbers and number fields), ``checker_groups`` (group
certificates), ``checker_ordering`` (the canonical ordering and the leader) and
``checker_refutations`` (refutation certificates).
``python -m exactsym.checker CERT.json`` exits 0 when the certificate proves its claim, 1 when
it does not (the reason on stderr), 2 when the file is unreadable.  The format is described in
``docs/certificates.md``.

What a valid certificate proves.  P is the embedded point set, G the group of the isometries g
of the plane with g(P) = P; the "level" of a point is the set of points as far as it from c.
 1. c is fixed by every g in G.  Cartesian: c is the centroid (g is affine and permutes P, so it
    fixes the mean of P).  Polar: c is the origin, checked to be the centre of the smallest
    enclosing circle of P, which is unique and so mapped onto itself by every g.
 2. H <= G: each generator (a rotation rho about c; for Dk also a reflection mu through c) maps
    every point i to point perm[i], so it maps P into P and is in G.  A rotation about c fixing
    a point a != c is the identity, so the order k of rho is the length of the cycle of the
    reference point a under its permutation, and H = <rho, mu> is exactly Ck or Dk.
 3. G <= H: every g in G fixes c, so g is determined by its kind (rotation or reflection) and
    by b = g(a), a point of P on the level of a.  For each such b and kind, the candidate is in
    H (b is in the H-orbit of a, computed from the verified permutations) or the witness names
    a point w whose image under the candidate is not in P: then the candidate is not in G.
So G = H: the checker names it, derives "orderable" (no element of G moves a point) and
compares both with the claim.  The cost is linear: O(n) per generator, O(1) per candidate.

Numbers are exact: rationals (ints after scaling by a common denominator, or Fractions), or
elements of one real number field Q(theta) written as coefficient lists in theta.
"""

from __future__ import annotations

import json
import sys

try:
    from .checker_numbers import (Alg, Field, Invalid, frac, integer, irreducible_mod, need,
                                  number_field, one_root, peval, psi, rat, sgn)
except ImportError:     # run as a lone script (python exactsym/checker.py): a sibling file
    from checker_numbers import (Alg, Field, Invalid, frac, integer, irreducible_mod, need,
                                 number_field, one_root, peval, psi, rat, sgn)
try:
    from .checker_groups import digest, verify_certificate
except ImportError:     # run as a lone script (python exactsym/checker.py): a sibling file
    from checker_groups import digest, verify_certificate
try:
    from .checker_refutations import REFUTABLE, verify_refutation
except ImportError:     # run as a lone script (python exactsym/checker.py): a sibling file
    from checker_refutations import REFUTABLE, verify_refutation

__all__ = ["Alg", "Field", "Invalid", "REFUTABLE", "digest", "frac", "integer",
           "irreducible_mod", "need", "number_field", "one_root", "peval", "psi", "rat", "sgn",
           "verify_certificate", "verify_refutation", "main"]


def main(argv: list | None = None) -> int:
    args = sys.argv[1:] if argv is None else argv
    if len(args) != 1:
        print("usage: python -m exactsym.checker CERT.json", file=sys.stderr)
        return 2
    try:
        with open(args[0], encoding="utf-8") as fh:
            cert = json.load(fh)
    except (OSError, ValueError, RecursionError) as err:
        print(f"{args[0]}: unreadable certificate: {err}", file=sys.stderr)
        return 2
    verify = verify_refutation if isinstance(cert, dict) and \
        cert.get("format") == "exactsym-refutation" else verify_certificate
    ok, message = verify(cert)
    print(f"{args[0]}: {'valid' if ok else 'INVALID'}: {message}",
          file=sys.stdout if ok else sys.stderr)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
