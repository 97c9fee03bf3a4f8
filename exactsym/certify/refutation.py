"""Refutation certificates: a statement refuted by facts about symmetries alone.

``make_refutation(config, label)`` wraps the group certificate of ``config``
(:func:`exactsym.certify.certificate.make_certificate`) with the label it refutes, and, for the
statements about the polygons of G_P, group certificates of the parts the premise names
(a level; a pair of levels; the merged polygon G_ij).  The checker
(:func:`exactsym.checker.verify_refutation`, standard library only) verifies every group,
recomputes the parts from P and derives the premise and the failed conclusion
(docs/certificates.md, "Refutations").  Labels: :data:`exactsym.checker.refutations.REFUTABLE`.
``exactsym certify --refutes LABEL FILE -o OUT.json``.

Which part is chosen: the first level (in order of increasing radius) with no mirror and
no half-turn (``cor-Pasym-Pord``, ``lem-one-pair-asym-ord``); the first pair of levels
of at least three points each, without the half-turn and without a common mirror
(``lem-asym-pair-ord``, ``lem-all-pair-asym-ord``, ``obs-merg-asym-pair``; for the last,
one whose merged polygon is symmetric).  Nothing the producer computes is trusted.
"""

from __future__ import annotations

import json
from fractions import Fraction
from itertools import combinations

from ..checker import refutations as checker
from .certificate import CertificateError, make_certificate
from ..geometry.configuration import Configuration
from ..labels import is_label, unknown_label_message

__all__ = ["FORMAT", "make_refutation", "PREMISES"]

FORMAT = "exactsym-refutation"

#: The premise and the conclusion of each refutable label, in words (informative: the
#: checker derives both from the groups).
PREMISES = {
    "Pasym-Pord": (["at least two points", "no mirror moves a point",
                    "no half-turn about the centre"], "orderable"),
    "lem-asym-ord": (["at least two points", "no mirror moves a point",
                      "no half-turn about the centre", "one level (a polygon)"], "orderable"),
    "cor-Pasym-Pord": (["a level of P with no mirror and no half-turn (parts.level): "
                        "no line is common to all polygons, G_P is in O_A"], "orderable"),
    "lem-one-pair-asym-ord": (["a level of P with no mirror and no half-turn "
                               "(parts.level): an asymmetric polygon of G_P"], "orderable"),
    "lem-asym-pair-ord": (["P is two levels (parts.pair), neither with the half-turn, "
                           "without a common mirror: an asymmetric pair"], "orderable"),
    "lem-all-pair-asym-ord": (["two levels of P (parts.pair), neither with the half-turn, "
                               "without a common mirror: an asymmetric pair"], "orderable"),
    "obs-merg-asym-pair": (["two levels of P (parts.pair), neither with the half-turn, "
                            "without a common mirror: an asymmetric pair"],
                           "G_ij (parts.merged: G_i projected onto G_j's circle, with "
                           "G_j) has no mirror and no half-turn"),
    "lemma-sym-regular": (["one level (points on a circle: a convex polygon)",
                           "more than one line of symmetry, all mirrors (k odd), each "
                           "through a vertex"], "regular (a rotation of order n)"),
    "obs-exh-poly": (["one level (a convex polygon) with a mirror: straight symmetric"],
                     "of type 0, 1, 2, 3 or 4 (decided from n, the number of mirrors and "
                     "the mirrors through vertices)"),
}


def _levels(config) -> list[list[int]]:
    """Indices of the points of each level about the origin, by increasing r2 (a polar
    configuration with rational squared radii)."""
    by: dict = {}
    for i, (r2, _) in enumerate(config.polar):
        if r2 != 0:
            by.setdefault(Fraction(int(r2.p), int(r2.q)), []).append(i)
    return [by[r] for r in sorted(by)]


def _sub(config, entries) -> Configuration:
    """The polar configuration of ``entries``: (radius, r2, turn) triples."""
    return Configuration(source=config.source, polar=[(r2, t) for _, r2, t in entries],
                         radii=[r for r, _, _ in entries], polar_system=config.polar_system)


def _part(config, indices) -> tuple[dict, object]:
    sub = _sub(config, [(config.radii[i], *config.polar[i]) for i in indices])
    cert = make_certificate(sub)
    return json.loads(json.dumps(cert)), sub


def _asymmetric(cert) -> bool:
    name = cert["claim"]["group"]
    return name.startswith("C") and int(name[1:]) % 2 == 1


def _pair_ok(a, b) -> bool:
    obj = {"parts": {"pair": [a, b]}}
    P = set(checker._keys(a["configuration"])) | set(checker._keys(b["configuration"]))
    try:
        checker._asymmetric_pair(obj, checker._levels(P))
        return True
    except checker.Invalid:
        return False


def _merged(config, a_idx, b_idx) -> dict:
    rb = config.radii[b_idx[0]]
    entries = [(rb, rb * rb, config.polar[i][1]) for i in a_idx] + \
        [(config.radii[i], *config.polar[i]) for i in b_idx]
    return json.loads(json.dumps(make_certificate(_sub(config, entries))))


def _parts(config, label: str) -> dict:
    if label in ("Pasym-Pord", "lem-asym-ord", "lemma-sym-regular", "obs-exh-poly"):
        return {}
    if config.polar is None or config.radii is None:
        raise CertificateError(f"{label}: refutations about the polygons of G_P are "
                               "written for polar configurations only")
    levels = _levels(config)
    if label in ("cor-Pasym-Pord", "lem-one-pair-asym-ord"):
        for idx in levels:
            if len(idx) >= 3:
                cert, _ = _part(config, idx)
                if _asymmetric(cert):
                    return {"level": cert}
        raise CertificateError("no level without a mirror and without the half-turn")
    for a_idx, b_idx in combinations([x for x in levels if len(x) >= 3], 2):
        a, b = _part(config, a_idx)[0], _part(config, b_idx)[0]
        if not _pair_ok(a, b):
            continue
        if label != "obs-merg-asym-pair":
            return {"pair": [a, b]}
        merged = _merged(config, a_idx, b_idx)
        if not _asymmetric(merged):
            return {"pair": [a, b], "merged": merged}
    raise CertificateError("no asymmetric pair of levels" +
                           (" whose merged polygon is symmetric"
                            if label == "obs-merg-asym-pair" else ""))


def make_refutation(config, label: str) -> dict:
    """The refutation certificate of ``label`` on ``config``; :class:`CertificateError` when
    the label is unknown or not refutable by symmetry facts, or when ``config`` does not
    refute it (the checker's reason)."""
    if not is_label(label):
        raise CertificateError(unknown_label_message(label))
    if label not in checker.REFUTABLE:
        raise CertificateError(f"{label} is not refuted by symmetry facts alone (refutable: "
                               f"{', '.join(sorted(checker.REFUTABLE))})")
    premise, conclusion = PREMISES[label]
    obj = {"format": FORMAT, "version": 1, "label": label,
           "statement": checker.REFUTABLE[label], "premise": premise,
           "conclusion": conclusion, "certificate": make_certificate(config)}
    parts = _parts(config, label)
    if parts:
        obj["parts"] = parts
    ok, why = checker.verify_refutation(json.loads(json.dumps(obj)))
    if not ok:
        raise CertificateError(f"does not refute {label}: {why}")
    return obj
