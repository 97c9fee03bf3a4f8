"""The independent checker of exactsym certificates: standard library only, sharing no code with
the solver (docs/certificates.md).  ``python -m exactsym.checker CERT.json`` (or, this directory
copied anywhere, ``python -m checker CERT.json``) exits 0 when the certificate proves its claim,
1 when it does not (the reason on stderr), 2 when the file is unreadable.  The core: numbers,
dispatch, groups, ordering, refutations; ``ext_*``: optional extensions, reached by dispatch."""

from __future__ import annotations

import sys

from .dispatch import number_field, parse, verify
from .groups import digest, verify_certificate
from .numbers import Field, Invalid, frac, integer, one_root, psi, rat, sgn
from .refutations import REFUTABLE, verify_refutation

__all__ = ["Field", "Invalid", "REFUTABLE", "digest", "frac", "integer", "main",
           "number_field", "one_root", "parse", "psi", "rat", "sgn", "verify",
           "verify_certificate", "verify_refutation"]

def main(argv: list | None = None) -> int:
    args = sys.argv[1:] if argv is None else argv
    if len(args) != 1:
        print("usage: python -m exactsym.checker CERT.json", file=sys.stderr)
        return 2
    try:
        with open(args[0], encoding="utf-8") as fh:
            cert = parse(fh.read())
    except Invalid as err:                      # JSON, but two keys alike in one object
        ok, message = False, str(err)
    except (OSError, ValueError, RecursionError) as err:
        print(f"{args[0]}: unreadable certificate: {err}", file=sys.stderr)
        return 2
    else:
        ok, message = verify(cert)
    print(f"{args[0]}: {'valid' if ok else 'INVALID'}: {message}",
          file=sys.stdout if ok else sys.stderr)
    return 0 if ok else 1

