"""Refutation certificates: a statement refuted by facts about symmetries alone.

``make_refutation(config, label)`` wraps the group certificate of ``config``
(:func:`exactsym.certificates.certificate.make_certificate`) with the label it refutes, and, for the
statements about the polygons of G_P, group certificates of the parts the premise names
(a level; a pair of levels; the merged polygon G_ij).  The checker (``verify_refutation``
of ``exactsym/checker/``, standard library only, run by ``certify`` on what is written here)
verifies every group, recomputes the parts from P and derives the premise and the failed
conclusion (docs/certificates.md, "Refutations").  Labels: :data:`STATEMENTS`.
``exactsym certify --refutes LABEL FILE -o OUT.json``.

The producer decides, from its own groups, whether ``config`` refutes the label
(:func:`_why_not`, with the checker's words): it shares no function with the checker, which
judges the result independently.

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

from flint import fmpz

from .certificate import CertificateError, make_certificate
from ..geometry.configuration import Configuration
from ..labels import is_label, unknown_label_message

__all__ = ["FORMAT", "make_refutation", "PREMISES", "STATEMENTS"]

FORMAT = "exactsym-refutation"

#: The statements refutable by symmetry facts alone, in the words the certificate carries
#: (the checker holds its own copy and requires these words).
STATEMENTS = {"Pasym-Pord": "P is orderable if P is in O_A",
              "lem-asym-ord": "an asymmetric polygon is orderable",
              "cor-Pasym-Pord": "P is orderable if G_P is in O_A",
              "lem-one-pair-asym-ord": "if G_P contains an asymmetric polygon, P is orderable",
              "lem-asym-pair-ord": "an asymmetric pair is orderable",
              "lem-all-pair-asym-ord": "if G_P has an asymmetric pair, P is orderable",
              "obs-merg-asym-pair": "if <G_i, G_j> is an asymmetric pair, G_ij is asymmetric",
              "lemma-sym-regular": "a convex polygon with more than one line of symmetry, "
                                   "each through a vertex, is regular",
              "obs-exh-poly": "every straight symmetric polygon is of type 0, 1, 2, 3 or 4"}

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


def _group(cert) -> tuple[str, int]:
    """(name, k): the group a certificate claims and its number of rotations."""
    name = cert["claim"]["group"]
    return name, 1 if name == "O2" else int(name[1:])


def _axes(cert) -> set:
    """The mirror axes of a polar group Dk, as turns mod 1/2 (reflections t -> 2a - t + j/k:
    axes a + j/2k)."""
    name, k = _group(cert)
    if not name.startswith("D"):
        return set()
    a = Fraction(cert["witness"]["mirror"]["turn"])
    return {(a + Fraction(j, 2 * k)) % Fraction(1, 2) for j in range(k)}


def _pair_ok(a, b) -> bool:
    """Two levels form an asymmetric pair under every reading: neither has the half-turn
    (k odd: else every line through c is a skew line) and they share no mirror."""
    return all(_group(c)[1] % 2 == 1 for c in (a, b)) and not _axes(a) & _axes(b)


def _turns(config) -> list[Fraction]:
    """The turn mod 1 of each point of a rational polar configuration (0 at the centre)."""
    return [Fraction(int(t.p), int(t.q)) % 1 if r2 != 0 else Fraction(0)
            for r2, t in config.polar]


def _one_level(config) -> bool:
    """All points at one distance from the centroid (exactly, in the configuration's numbers)."""
    if config.polar is not None:
        return len({r2 for r2, _ in config.polar}) == 1
    pts = config.points
    cx, cy = sum(x for x, _ in pts) / len(pts), sum(y for _, y in pts) / len(pts)
    return len({(x - cx) ** 2 + (y - cy) ** 2 for x, y in pts}) == 1


def _why_not(label: str, config, obj: dict) -> str | None:
    """Why ``obj`` (just built from ``config``) does not refute ``label``, in the checker's
    words, or None: the premise of the label holds for the group of P and the conclusion fails
    (docs/certificates.md, "Refutations")."""
    cert = obj["certificate"]
    (name, k), orderable, n = _group(cert), cert["claim"]["orderable"], config.n
    if label in ("Pasym-Pord", "lem-asym-ord"):
        # a reflection moves a point unless G = D1 fixes every point; the half-turn: k even
        if not (n >= 2 and (name.startswith("C") or name == "D1" and orderable) and k % 2):
            return f"the premise fails: group {name} on {n} point(s) is in O_S"
        if label == "lem-asym-ord" and not _one_level(config):
            return "the premise fails: not one polygon"
    if label == "lem-asym-pair-ord" and sum(
            len(c["configuration"]["points"]) for c in obj["parts"]["pair"]) != n:
        return "the premise fails: P is not the union of the pair"
    if label == "obs-merg-asym-pair":
        return None                             # the parts were chosen so (see _parts)
    if label in ("lemma-sym-regular", "obs-exh-poly"):
        if config.polar is None or config.radii is None:
            return "this refutation is checked on rational polar certificates only"
        if len(_levels(config)) != 1 or n < 3:
            return ("the premise fails: not one polygon with >= 3 vertices" +
                    (" (points on one circle: a convex polygon)"
                     if label == "lemma-sym-regular" else ""))
        turns, axes = _turns(config), _axes(cert)
        through = {x for x in axes if any((t - x) % Fraction(1, 2) == 0 for t in turns)}
        if label == "obs-exh-poly":
            if not name.startswith("D"):
                return f"the premise fails: group {name} has no mirror"
            prime = bool(fmpz(n).is_prime())
            types = {0: k == n, 1: n % 2 == 0 and k == 2 and not through,
                     2: n % 2 == 0 and k == 1, 3: n % 2 == 1 and k == 1,
                     4: n % 2 == 1 and not prime and 1 < k < n}
            fits = [t for t, holds in types.items() if holds]
            return f"the conclusion holds: it is of type {fits[0]}" if fits else None
        if not (name.startswith("D") and k >= 2 and k % 2 == 1):
            return (f"the premise fails: group {name} does not have more than one line of "
                    "symmetry, all mirrors (k odd)")
        if through != axes:
            return "the premise fails: a mirror passes through no vertex"
        return f"the conclusion holds: the rotation of order {k} = n makes it regular" \
            if k >= n else None
    if orderable:
        return f"the conclusion holds: group {name} is orderable"
    return None


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
    if label not in STATEMENTS:
        raise CertificateError(f"{label} is not refuted by symmetry facts alone (refutable: "
                               f"{', '.join(sorted(STATEMENTS))})")
    premise, conclusion = PREMISES[label]
    obj = {"format": FORMAT, "version": 1, "label": label,
           "statement": STATEMENTS[label], "premise": premise,
           "conclusion": conclusion, "certificate": make_certificate(config)}
    parts = _parts(config, label)
    if parts:
        obj["parts"] = parts
    why = _why_not(label, config, json.loads(json.dumps(obj)))
    if why is not None:
        raise CertificateError(f"does not refute {label}: {why}")
    return obj
