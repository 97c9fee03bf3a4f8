"""Certificates of the ground-truth symmetry verdict, for the independent checker.

:func:`make_certificate` turns a :class:`~exactsym.truth.symmetry.SymmetryGroup` into the JSON
object of ``docs/certificates.md``: the configuration written exactly (:mod:`.encoder`), the
claim (group, orderable, ordering, leader) and a witness (:mod:`.witness`).  The witness is
found here, with the project's exact numbers; the checker recomputes everything it needs from
the certificate alone and shares no code with this side (``exactsym/checker/`` is run, never
imported, by the solver).
"""

from __future__ import annotations

import hashlib
import json

from ..geometry.configuration import Configuration
from .encoder import CertificateError, Encoder, rational_text
from .witness import canonical_frame, cartesian_witness, polar_witness

__all__ = ["FORMAT", "VERSION", "CertificateError", "digest", "make_certificate"]

FORMAT = "exactsym-certificate"
VERSION = 1


def digest(configuration) -> str:
    """The SHA-256 of the configuration's canonical JSON (sorted keys, no spaces): a
    fingerprint the checker compares, catching edits (the proof does not rest on it)."""
    text = json.dumps(configuration, sort_keys=True, separators=(",", ":"))
    return hashlib.sha256(text.encode()).hexdigest()


def make_certificate(config: Configuration, group=None, rings=None) -> dict:
    """The certificate of ``config``'s symmetry group, canonical ordering and leader
    (``group`` from :func:`exactsym.truth.symmetry.symmetry_group` and ``rings`` from
    :func:`exactsym.geometry.levels.levels_of`, computed when not given)."""
    from ..geometry.levels import levels_of
    rings = levels_of(config) if rings is None and (group is None or config.polar is None) \
        else rings
    if group is None:
        from ..truth.symmetry import symmetry_group
        group = symmetry_group(config, rings)
    # one point: no SEC to check, so a polar file stays polar (no trigonometry needed)
    polar = config.polar is not None and (bool(group.polar) or config.n == 1)
    if polar:
        values = [r2 for r2, _ in config.polar]
        system = config.polar_system
    else:
        values = [v for p in config.points for v in p] + list(group.centre)
        for iso in (group.rotation_generator, group.mirror):
            if iso is not None:
                values += [e for row in iso.matrix for e in row]
        system = config.system
    enc = Encoder(system, values)
    if polar:
        points = [[enc.text(r2), rational_text(t if r2 != 0 else 0)] for r2, t in config.polar]
    else:
        points = [[enc.text(x), enc.text(y)] for x, y in config.points]
    configuration = {"coordinates": "polar" if polar else "cartesian", "field": enc.spec,
                     "points": points}
    if config.n == 1:
        witness = {}
    elif polar:
        witness = polar_witness(config, group)
    else:
        witness = cartesian_witness(config, group, enc)
        if enc.sparse is not None:           # the centre as (X, Y) / k: no sparse quotient
            centre, scale = enc.sparse_homogeneous(list(group.centre))
            witness["sec"] = {"centre": centre, "scale": scale,
                              "support": list(rings.sec.support)}
        else:
            witness["sec"] = {"centre": [enc.text(v) for v in group.centre],
                              "support": list(rings.sec.support)}
    canonical = canonical_frame(config, group, polar) if config.n > 1 else None
    if canonical is not None:
        witness["canonical"] = canonical
    return {"format": FORMAT, "version": VERSION,
            "source": {"file": config.source, "name": config.name},
            "claim": {"group": group.name, "orderable": bool(group.orderable),
                      "ordering": list(group.ordering) if group.ordering else None,
                      "leader": group.leader},
            "configuration_sha256": digest(configuration),
            "configuration": configuration,
            "witness": witness}
