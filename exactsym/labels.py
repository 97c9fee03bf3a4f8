"""The labels of the paper's statements, definitions and algorithms, in the paper's order.

The numbering of ``docs/paper.md``: the source's ``\\label``s (``obs-type 4``
written ``obs-type-4``, ``obs1-G'equiG`` ``obs1-Gprime-equiG``, ``G'equiG``
``Gprime-equiG``), the unlabelled statements under the project's names (``type-0`` ..
``type-4``, ``hull-symmetric``, ``obs-asymmetric-polygon-1.1``, ``gather-min-distance``,
``gather-no-obstacle``) and the algorithms by name.  Case files (``lemmas``), ``exactsym
cases --lemma`` and the ledger (``proofs/statements.toml``) accept these and nothing else;
:func:`nearest_label` names the closest one in an error.
"""

from __future__ import annotations

import difflib

__all__ = ["STATEMENTS", "ALGORITHMS", "LABELS", "is_label", "nearest_label",
           "unknown_label_message"]

#: Definitions and statements, in the paper's order.
STATEMENTS: tuple[str, ...] = (
    "gathering_pattern", "stmirrorimage", "skmirrorimage", "def-straight-symmetric-conf",
    "def-skewed-symmetric-conf", "def-symmetric-conf", "def-asymmetric-conf",
    "def-orderable-set", "lemma-sym-ord", "lemma-LOS-Passes-CenterSECP",
    "hull-vertex-symmetry", "hull-symmetric", "LemmmaStraightSymHull",
    "LoSkS-intersect-1-vertex-edge", "LoSkS-intersect-2-vertex-edge", "lem-rectangle",
    "obs-parallel-edge-equal", "LoSkS-vertex", "LoSkS-edge", "def-straight-symmetric-poly",
    "def-skew-symmetric-poly", "def-symmetric-poly", "def-asymmetric-poly", "obs-asym-poly",
    "lem-skew-los", "lemma-straight-sym", "lemma-skewed-sym", "obs-asymmetric-polygon",
    "obs-asymmetric-polygon-1.1", "lem-asym-ord", "def-sym-pair", "obs-pair-asym-ord",
    "lem-sym-notord", "obs-merg-asym-pair", "lem-asym-pair-ord", "def-sym-calG",
    "lem-all-pair-asym-ord", "lem-one-pair-asym-ord", "lemma-sym-regular",
    "type-0", "type-1", "type-2", "type-3", "type-4", "obs-exh-poly", "obs-sym-type-0",
    "obs-sym-type-01", "lem-sym-type-01", "obs-gcd", "lem-los-gij", "theorem-los-g1n",
    "obs-type-4", "lem-type4", "lem-3-pair-sym", "theorem-sym-pair-symG",
    "obs1-Gprime-equiG", "Gprime-equiG", "Psym-Gsym", "Pasym-Pord", "cor-Pasym-Pord",
    "1sym_le", "obs-v-move", "lem-vl-move", "gather-min-distance", "gather-no-obstacle",
)

#: Algorithms by name (``FindAsymmetry`` and ``Find_Asymmetry_Pair`` are named, not given).
ALGORITHMS: tuple[str, ...] = (
    "Check_Symmetry_Odd", "Check_Symmetry_Even", "Elect_Leader_Sym", "Make_SymToAsym",
    "Elect_Leader_Asym", "ElectLeader", "Preprocess", "FindAsymmetry", "Find_Asymmetry_Pair",
    "MakeAsym", "FormGPattern", "GatheringPattern",
)

LABELS: frozenset[str] = frozenset(STATEMENTS + ALGORITHMS)


def is_label(text: str) -> bool:
    return text in LABELS


def nearest_label(text: str) -> str:
    """The known label closest to ``text`` (difflib's ratio; case-insensitive first)."""
    lower = {label.lower(): label for label in LABELS}
    if text.lower() in lower:
        return lower[text.lower()]
    match = difflib.get_close_matches(text, sorted(LABELS), n=1, cutoff=0.0)
    return match[0] if match else sorted(LABELS)[0]


def unknown_label_message(text: str) -> str:
    return f"unknown label {text!r} (nearest known label: {nearest_label(text)!r})"
