"""The checker's dispatch tables, written out in one place (nothing registers itself): the
module and function or class that verifies each format, reads each number system, proves each
kind of irreducibility and checks each refuted label, loaded on first use.  An ``ext_*`` module
is an optional extension: a certificate that needs an absent one is rejected, saying which."""

from __future__ import annotations

import json
from importlib import import_module

from .numbers import Field, Invalid, need

#: a certificate's "format" -> the function verifying it: (True, summary) or (False, reason)
FORMATS = {"exactsym-certificate": ("groups", "verify_certificate"),
           "exactsym-refutation": ("refutations", "verify_refutation")}

#: a configuration's number system (:func:`system`) -> the class reading its "field"
NUMBER_SYSTEMS = {
    "minpoly": ("dispatch", "dense_field"),                 # Q(theta), e.g. Q(2cos(2pi/M))
    "radicands": ("numbers", "SquareRoots"),                # Q(sqrt a_1, ..., sqrt a_k)
    "sparse-cyclotomic": ("ext_sparse", "SparseField"),     # Q(zeta_N) as sums of cosines
    "tower": ("ext_tower", "Tower"),                        # nested radicals, square roots below
    "tower over minpoly": ("ext_tower", "CyclotomicTower"),  # nested radicals over Q(theta)
    "tower over sparse-cyclotomic": ("ext_sparse_tower", "SparseKummerTower")}

#: the "method" of a Q(theta)'s "irreducible" proof -> the function checking it
IRREDUCIBILITY = {"real-cyclotomic": ("numbers", "cyclotomic_proof"),
                  "prime": ("ext_primitive", "prime_proof"),
                  "square-roots": ("ext_primitive", "square_roots_proof")}

#: a refutable label -> the function deriving its premise and failed conclusion from G
REFUTATIONS = {"Pasym-Pord": ("refutations", "in_o_a"), "lem-asym-ord": ("refutations", "in_o_a"),
               "cor-Pasym-Pord": ("ext_polygons", "asymmetric_level"),
               "lem-one-pair-asym-ord": ("ext_polygons", "asymmetric_level"),
               "lem-asym-pair-ord": ("ext_polygons", "asymmetric_pair"),
               "lem-all-pair-asym-ord": ("ext_polygons", "asymmetric_pair"),
               "obs-merg-asym-pair": ("ext_polygons", "merged_pair"),
               "lemma-sym-regular": ("ext_polygons", "sym_regular"),
               "obs-exh-poly": ("ext_polygons", "no_type")}

def load(table: dict, key: str):
    module, name = table[key]
    try:
        return getattr(import_module(f".{module}", __package__), name)
    except ModuleNotFoundError as err:
        if err.name != f"{__package__}.{module}":
            raise
        raise Invalid(f"{key!r} needs the checker extension {module}.py, which is not here") \
            from None

def system(spec: dict) -> str:
    """The key in NUMBER_SYSTEMS of a configuration's "field" object."""
    if "tower" in spec:
        tower = spec["tower"] if isinstance(spec["tower"], dict) else {}
        if "base" not in tower:
            return "tower"
        return "tower over " + ("sparse-cyclotomic" if isinstance(tower["base"], dict)
                                and "sparse-cyclotomic" in tower["base"] else "minpoly")
    return "sparse-cyclotomic" if "sparse-cyclotomic" in spec else \
        "radicands" if "radicands" in spec else "minpoly"

def number_field(spec: dict):
    """The checked field of a "field" object (the part under "tower" or "sparse-cyclotomic")."""
    kind = system(spec)
    key = kind.split()[0]
    return load(NUMBER_SYSTEMS, kind)(spec[key] if key in ("tower", "sparse-cyclotomic")
                                      else spec)

def dense_field(spec: dict) -> Field:
    """Q(theta) with its minimal polynomial proved irreducible by the proof named."""
    field, proof = Field(spec), spec["irreducible"]
    need(proof["method"] in IRREDUCIBILITY, f"unknown irreducibility proof {proof['method']!r}")
    load(IRREDUCIBILITY, proof["method"])(field, proof)
    return field

def _no_duplicate(pairs: list) -> dict:
    out = dict(pairs)
    if len(out) < len(pairs):
        seen: set = set()
        twice = next(k for k, _ in pairs if k in seen or seen.add(k))
        raise Invalid(f"the key {twice!r} is given twice in one object")
    return out

def parse(text: str):
    """A certificate's JSON; a key twice in one object is Invalid (json keeps the last: two
    "claim" objects, one read by a person, one checked); ValueError when it is not JSON."""
    return json.loads(text, object_pairs_hook=_no_duplicate)

def verify(cert) -> tuple[bool, str]:
    """``(True, summary)`` when the certificate proves its claim, else ``(False, reason)``."""
    kind = cert.get("format") if isinstance(cert, dict) else None
    return load(FORMATS, kind if isinstance(kind, str) and kind in FORMATS
                else "exactsym-certificate")(cert)
