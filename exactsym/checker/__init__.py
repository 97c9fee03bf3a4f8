"""The independent checker of exactsym certificates: the modules a sceptic must trust.

Standard library only; imports nothing from exactsym but its own modules:
``checker_numbers`` (exact numbers and number fields), ``checker_groups`` (group
certificates), ``checker_ordering`` (the canonical ordering and the leader) and
``checker_refutations`` (refutation certificates).
``python -m exactsym.checker CERT.json`` exits 0 when the certificate proves its claim, 1 when
it does not (the reason on stderr), 2 when the file is unreadable.  The format is described in
``docs/certificates.md``.

What a valid group certificate proves, and why, is written once, in ``checker_groups``;
the ordering's proof in ``checker_ordering``; refutations in ``checker_refutations``.
"""

from __future__ import annotations

import json
import sys

try:
    from .arithmetic import (Alg, Field, Invalid, frac, integer, irreducible_mod, need,
                                  number_field, one_root, peval, psi, rat, sgn)
except ImportError:     # run as a lone script (python exactsym/checker/__init__.py): a sibling file
    from checker_numbers import (Alg, Field, Invalid, frac, integer, irreducible_mod, need,
                                 number_field, one_root, peval, psi, rat, sgn)
try:
    from .groups import digest, verify_certificate
except ImportError:     # run as a lone script (python exactsym/checker/__init__.py): a sibling file
    from checker_groups import digest, verify_certificate
try:
    from .refutations import REFUTABLE, verify_refutation
except ImportError:     # run as a lone script (python exactsym/checker/__init__.py): a sibling file
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
