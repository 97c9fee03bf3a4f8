"""``exactsym certify FILE -o CERT.json`` and ``exactsym verify CERT.json`` (``docs/cli.md``).

``certify`` computes the symmetry group, writes its certificate and checks it with the
independent checker before reporting success.  ``verify`` uses :mod:`exactsym.checker` only.
These two commands (and the ledger's evidence check) are the only code of exactsym that runs
the checker; none shares a function with it.
Exit codes: 0 valid; 1 the certificate does not prove its claim (reason on stderr); 2 the
input, the certificate file (unreadable or not JSON) or the command line is unusable.
"""

from __future__ import annotations

import json
import sys

from ..errors import EXIT_BUG, EXIT_FALSE, EXIT_OK, InputError
from ..version import json_head


def add_certify_arguments(certify) -> None:
    certify.add_argument("file", help="configuration file ('-' for standard input)")
    certify.add_argument("-o", "--output", default=None, metavar="CERT.json",
                         help="where to write the certificate ('-' for standard output); "
                         "required unless --coq is given")
    certify.add_argument("--refutes", metavar="LABEL", default=None,
                         help="write a refutation certificate of LABEL instead "
                         "(exactsym.certificates.refutation)")
    certify.add_argument("--coq", metavar="OUT.v", default=None,
                         help="with --refutes: also write the refutation as a Coq file "
                         "that coqc checks on its own (exactsym.certificates.coq_refutation)")


def add_verify_arguments(verify) -> None:
    verify.add_argument("certificate", metavar="CERT.json",
                        help="a certificate written by exactsym certify")


#: cos/sin needing a dense Q(zeta_M) of a larger degree are certified in the sparse Q(zeta_N)
#: (``evaluate.dense_degree_limit``): the checker (standard library only) multiplies dense
#: numbers term by term and isolates a root of Phi_M's real factor, which took 155 s at
#: degree 2,880 where the sparse certificate takes 0.4 s (and 1.3 s against 0.4 s at 252)
CERTIFY_DENSE_DEGREE = 64


def _certificate(parsed, refutes):
    """``(config, certificate)`` of a parsed file: cos/sin beyond
    :data:`CERTIFY_DENSE_DEGREE` in the sparse field, and if that field refuses the
    numbers (a square root whose Gauss sum is too long) or cannot write them, in the
    field ``check`` uses."""
    from ..certificates.certificate import CertificateError, make_certificate
    from ..geometry.configuration import from_file
    from ..errors import FieldTooLargeError
    from ..exact.evaluate import dense_degree_limit

    def make():
        config = from_file(parsed)
        if refutes:
            from ..certificates.refutation import make_refutation
            return config, make_refutation(config, refutes)
        return config, make_certificate(config)
    try:
        with dense_degree_limit(CERTIFY_DENSE_DEGREE):
            return make()
    except (FieldTooLargeError, CertificateError):
        pass
    try:
        return make()
    except CertificateError as err:
        raise InputError(f"{parsed.source}: cannot certify: {err}") from None


def checked_certificate(config) -> dict:
    """The certificate of ``config``'s verdict as JSON data, accepted by the standalone
    checker (``exactsym.certify(...)`` of the API); AssertionError if the checker refuses
    it (the solver's verdict failed the independent check: a bug)."""
    from .. import checker
    from ..certificates.certificate import make_certificate
    cert = json.loads(json.dumps(make_certificate(config)))
    ok, message = checker.verify_certificate(cert)
    if not ok:
        raise AssertionError(f"the certificate does not verify: {message} (a bug)")
    return cert


def run_certify(args) -> int:
    from .. import checker
    from ..geometry.configuration import no_cycle_collection
    from ..io.fileformat import read_config
    if args.output is None and not args.coq:
        raise InputError("certify needs -o CERT.json (or --coq OUT.v with --refutes)")
    if args.coq and not args.refutes:
        raise InputError("--coq needs --refutes LABEL: only refutations are written for Coq")
    with no_cycle_collection():
        parsed = read_config(args.file)
    from ..certificates.coq_gathering import GATHERING_STATEMENTS
    from ..certificates.coq_refutation import CASE_STATEMENTS
    if args.coq and (args.refutes in CASE_STATEMENTS or args.refutes in GATHERING_STATEMENTS):
        return _coq_only(parsed, args)
    config, cert = _certificate(parsed, args.refutes)
    verify = checker.verify_refutation if args.refutes else checker.verify_certificate
    ok, message = verify(json.loads(json.dumps(cert)))
    if not ok:   # the tool's own verdict failed the independent check: a bug, say so
        print(f"exactsym: internal error: the certificate does not verify ({message}); "
              "please report it with the input file", file=sys.stderr)
        return EXIT_BUG
    # the keys every JSON output begins with (docs/json.md); the checker reads none of them
    if args.coq:
        _write_coq(json.loads(json.dumps(cert)), args.coq)
    cert = {**json_head(cert["format"], config.source, config.name), **cert}
    text = json.dumps(cert, separators=(",", ":")) + "\n"
    if args.output is None:
        return EXIT_OK
    if args.output == "-":
        sys.stdout.write(text)
    else:
        try:
            with open(args.output, "w", encoding="utf-8") as fh:
                fh.write(text)
        except OSError as err:
            raise InputError(f"{args.output}: cannot write the certificate: {err.strerror}") \
                from None
        print(f"{args.output}: certificate of {config.source}: {message}")
    return EXIT_OK


def _write_coq(refutation: dict, path: str) -> None:
    """The refutation as a Coq file (docs/certificates.md, "Coq")."""
    from ..certificates.coq_refutation import CoqExportError, coq_refutation
    try:
        text = coq_refutation(refutation)
    except CoqExportError as err:
        raise InputError(f"cannot write the refutation for Coq: {err}") from None
    _write_text(path, text)
    print(f"{path}: Coq refutation of {refutation['label']} (check it with coqc)")


def _coq_only(parsed, args) -> int:
    """A statement about CW/ACW strings or an algorithm: no certificate for the Python
    checker, the Coq file only (coqc is its check)."""
    from ..certificates.coq_gathering import GATHERING_STATEMENTS, coq_gathering_of_points
    from ..certificates.coq_refutation import CoqExportError, coq_refutation_of_points
    from ..geometry.configuration import from_file
    if args.output is not None:
        raise InputError(f"{args.refutes} has no certificate for the Python checker: give "
                         "--coq OUT.v without -o")
    config = from_file(parsed)
    if config.polar is None:
        raise InputError(f"{config.source}: cannot write the refutation for Coq: only "
                         "rational polar configurations are exported")
    try:
        export = coq_gathering_of_points if args.refutes in GATHERING_STATEMENTS \
            else coq_refutation_of_points
        text = export(args.refutes, config.polar, config.source)
    except CoqExportError as err:
        raise InputError(f"cannot write the refutation for Coq: {err}") from None
    _write_text(args.coq, text)
    print(f"{args.coq}: Coq refutation of {args.refutes} (not checked here: run coqc on it)")
    return EXIT_OK


def _write_text(path: str, text: str) -> None:
    try:
        with open(path, "w", encoding="utf-8") as fh:
            fh.write(text)
    except OSError as err:
        raise InputError(f"{path}: cannot write the Coq file: {err.strerror}") from None


def run_verify(args) -> int:
    from .. import checker
    path = args.certificate
    try:
        if path == "-":
            text = sys.stdin.read()
        else:
            with open(path, encoding="utf-8") as fh:
                text = fh.read()
        cert = checker.parse(text)          # strict: a key given twice is no certificate
    except OSError as err:
        raise InputError(f"{path}: cannot read the certificate: {err.strerror}") from None
    except json.JSONDecodeError as err:
        raise InputError(f"{path}:{err.lineno}:{err.colno}: not JSON: {err.msg}") from None
    except (ValueError, RecursionError) as err:
        raise InputError(f"{path}: not JSON: {err}") from None
    except checker.Invalid as err:          # JSON, but a key given twice in one object
        print(f"{path}: invalid certificate: {err}", file=sys.stderr)
        return EXIT_FALSE
    ok, message = checker.verify(cert)
    if ok:
        print(f"{path}: valid: {message}")
        return EXIT_OK
    print(f"{path}: invalid certificate: {message}", file=sys.stderr)
    return EXIT_FALSE

