"""Refutation certificates: a statement refuted by facts about symmetries alone.

``make_refutation(config, label)`` wraps the group certificate of ``config``
(:func:`exactsym.certificate.make_certificate`) with the label it refutes.  The checker
(:func:`exactsym.checker.verify_refutation`, standard library only) verifies the group and
derives the premise ("P in O_A": no mirror that moves a point, no half-turn, at least two
points; for ``lem-asym-ord`` also one level) and the failed conclusion ("orderable") from
it.  Labels: :data:`exactsym.checker.REFUTABLE` (``Pasym-Pord``, ``lem-asym-ord``); a C3
configuration refutes both.  ``exactsym certify --refutes LABEL FILE -o OUT.json``.
"""

from __future__ import annotations

import json

from . import checker
from .certificate import CertificateError, make_certificate
from .labels import is_label, unknown_label_message

__all__ = ["FORMAT", "make_refutation"]

FORMAT = "exactsym-refutation"


def make_refutation(config, label: str) -> dict:
    """The refutation certificate of ``label`` on ``config``; :class:`CertificateError` when
    the label is unknown or not refutable by symmetry facts, or when ``config`` does not
    refute it (the checker's reason)."""
    if not is_label(label):
        raise CertificateError(unknown_label_message(label))
    if label not in checker.REFUTABLE:
        raise CertificateError(f"{label} is not refuted by symmetry facts alone (refutable: "
                               f"{', '.join(sorted(checker.REFUTABLE))})")
    obj = {"format": FORMAT, "version": 1, "label": label,
           "statement": checker.REFUTABLE[label],
           "premise": ["at least two points", "no mirror moves a point",
                       "no half-turn about the centre"]
           + (["one level (a polygon)"] if label == "lem-asym-ord" else []),
           "conclusion": "orderable",
           "certificate": make_certificate(config)}
    ok, why = checker.verify_refutation(json.loads(json.dumps(obj)))
    if not ok:
        raise CertificateError(f"does not refute {label}: {why}")
    return obj
