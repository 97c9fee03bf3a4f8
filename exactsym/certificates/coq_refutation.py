"""Refutations that Coq re-checks (issue 35; docs/certificates.md, "Coq").

``coq_refutation(refutation)`` turns a refutation certificate of :mod:`.refutation`
(``certify --refutes LABEL``) into one self-contained Coq file: the library
``proofs/coq/Exactsym.v`` (the paper's definitions as decision procedures, each citing its
\\label) inlined, the configuration as exact rationals, and one theorem stating in the
paper's terms that the configuration meets the statement's hypotheses and that its
conclusion is false, proved by ``vm_compute`` (and by the library's theorems
``not_orderable_by_candidates``, ``orderable_of_only_identity``,
``not_electable_by_candidates`` and ``printed_loop_never_ends``).  ``coqc FILE.v``
accepting it is the check; nothing of exactsym is trusted by it.
``coq_refutation_of_points(label, points, source)`` does the same for the statements
about CW/ACW strings and the paper's algorithms (:data:`CASE_STATEMENTS`), which the
Python checker does not certify, from a configuration's points.

Scope: rational polar configurations (every shipped witness used is one).  Which levels
the theorem names is read from the certificate's parts (or, for a family, is the inner
and the outer level); Coq recomputes the levels from P itself, so a wrong part makes the
file fail, not pass.
"""

from __future__ import annotations

import re
from fractions import Fraction
from pathlib import Path

__all__ = ["CoqExportError", "STATEMENTS", "CASE_STATEMENTS", "coq_file_name",
           "coq_refutation", "coq_refutation_of_points", "coqc_accepts", "library_text",
           "read_library", "source_of", "theorem_name"]

#: The library every exported file inlines, in the source tree (issue 35: one copy).
LIBRARY = Path(__file__).resolve().parents[2] / "proofs" / "coq" / "Exactsym.v"

_VM = "vm_compute; reflexivity"
_ORDER = "apply not_orderable_by_candidates; vm_compute; reflexivity"
_LOOP = "intros fuel; apply printed_loop_never_ends; vm_compute; reflexivity"
_PRE = "intros fuel; apply preprocess_printed_never_ends; vm_compute; reflexivity"
_ORDERABLE = "apply orderable_of_only_identity; vm_compute; reflexivity"
_ELECT = "apply not_electable_by_candidates; vm_compute; reflexivity"


class CoqExportError(ValueError):
    """The refutation cannot be written as a Coq file (a label or a configuration
    outside the exporter's scope)."""


def _s(words, names, hypotheses, conclusion, reading=None, note=None, scale=None) -> dict:
    """One statement: the paper's words, the levels it names besides P, its hypotheses
    (Coq booleans, each ``= true``), the negated conclusion (Coq propositions, each with
    its tactic), the reading it is refuted under (refuted-under-reading), a note, and the
    factor (an integer) the source's squared distances are multiplied by (a statement
    about fat robots: the witness scaled until they are separated, ``separated P``)."""
    return {"words": words, "names": names, "hypotheses": hypotheses,
            "conclusion": conclusion, "reading": reading, "note": note, "scale": scale}


_PAIR = ["existsb (Qeq_bool rGi) (radii P)", "existsb (Qeq_bool rGj) (radii P)",
         "negb (Qeq_bool rGi rGj)", "polygon Gi", "polygon Gj", "asymmetric_pair Gi Gj"]

#: The statements refuted from a refutation certificate (the checker's labels).
STATEMENTS = {
    "Pasym-Pord": _s(
        "Theorem Pasym-Pord, 'if': P is orderable if P is in O_A.",
        (), ["Nat.leb 2 (length P)", "in_O_A P"], [("~ orderable P", _ORDER)],
        note="Asymmetric (O_A) reads the skewed mirror image as the half-turn about C "
             "(skmirrorimage, m = C; the text before stmirrorimage: L' perpendicular "
             "to L at m): a rotation-only set is asymmetric. The refutation hinges on "
             "that reading."),
    "lem-asym-ord": _s(
        "Lemma lem-asym-ord: an asymmetric polygon is orderable.",
        (), ["polygon P", "asymmetric_polygon P"], [("~ orderable P", _ORDER)],
        note="Asymmetric (O_A) reads the skewed mirror image as the half-turn about C "
             "(skmirrorimage, m = C; the text before stmirrorimage: L' perpendicular "
             "to L at m): a rotation-only set is asymmetric. The refutation hinges on "
             "that reading."),
    "cor-Pasym-Pord": _s(
        "Corollary cor-Pasym-Pord, 'if': P is orderable if calG_P is in O_A.",
        (), ["forallb polygon (polygons P)", "calG_in_O_A (polygons P)"],
        [("~ orderable P", _ORDER)], note="Asymmetric (O_A) reads the skewed mirror image as the half-turn about C "
             "(skmirrorimage, m = C; the text before stmirrorimage: L' perpendicular "
             "to L at m): a rotation-only set is asymmetric. The refutation hinges on "
             "that reading."),
    "lem-one-pair-asym-ord": _s(
        "Lemma lem-one-pair-asym-ord: if calG contains at least one asymmetric polygon "
        "then calG is orderable.",
        ("G",), ["existsb (Qeq_bool rG) (radii P)", "polygon G", "asymmetric_polygon G"],
        [("~ orderable P", _ORDER)]),
    "lem-asym-pair-ord": _s(
        "Lemma lem-asym-pair-ord: an asymmetric pair is orderable.",
        ("Gi", "Gj"), _PAIR, [("~ orderable (Gi ++ Gj)", _ORDER)]),
    "lem-all-pair-asym-ord": _s(
        "Lemma lem-all-pair-asym-ord: if there exists an asymmetric pair in calG, then "
        "calG is orderable.",
        ("Gi", "Gj"), _PAIR, [("~ orderable P", _ORDER)]),
    "obs-merg-asym-pair": _s(
        "Observation obs-merg-asym-pair: if <G_i, G_j> is an asymmetric pair, then the "
        "polygon G_ij is asymmetric.",
        ("Gi", "Gj"), _PAIR[:2] + ["Qlt_bool rGi rGj"] + _PAIR[3:] + ["polygon (merged Gi Gj)"],
        [("asymmetric_polygon (merged Gi Gj) = false", _VM)],
        note="G_i is the inner polygon (i < j); G_ij its vertices projected radially onto "
             "G_j's circle, with G_j."),
    "lemma-sym-regular": _s(
        "Lemma lemma-sym-regular: if a polygon G is convex and has more than one line of "
        "symmetry such that each line of symmetry passes through at least one vertex of G, "
        "then G is regular.",
        (), ["polygon P", "negb (is_symmetry half_turn P)", "Nat.leb 2 (length (mirrors P))",
             "forallb (through_vertex P) (mirrors P)"], [("regular P = false", _VM)],
        note="No half-turn: otherwise every line through C is a line of skew symmetry, and "
             "one misses every vertex; so the lines of symmetry are exactly the mirrors, "
             "under either reading of 'line of symmetry'."),
    "obs-exh-poly": _s(
        "Observation obs-exh-poly: the above characterization (types 0-4) of straight "
        "symmetric polygons is exhaustive.",
        (), ["polygon P", "straight_symmetric P"], [("some_type P = false", _VM)]),
}

#: The statements refuted from a configuration's points (no Python certificate).
CASE_STATEMENTS = {
    "obs-asymmetric-polygon": _s(
        "Theorem obs-asymmetric-polygon (Theorem 1): a polygon G is asymmetric if and only "
        "if (1) CW_vi <> ACW_vi, (2) CW_vi <> CW_vj and (3) CW_vi <> ACW_vj for all i <> j.",
        (), ["polygon P", "asymmetric_polygon P"], [("theorem1_conditions P = false", _VM)],
        note="'Only if' fails: P is asymmetric and a condition fails."),
    "obs-asymmetric-polygon-1.1": _s(
        "Theorem 1.1: Theorem 1 with (2) ACW_vi <> ACW_vj and (3) ACW_vi <> CW_vj.",
        (), ["polygon P", "asymmetric_polygon P"], [("theorem1_1_conditions P = false", _VM)],
        note="'Only if' fails: P is asymmetric and a condition fails."),
    "obs-gcd": _s(
        "Observation obs-gcd: if the odd polygons G_i, G_j (n_i, n_j vertices) have one "
        "common line of symmetry, then <G_i, G_j> has gcd(n_i, n_j) common lines of symmetry.",
        ("G1", "G2"), ["polygon G1", "polygon G2", "Nat.odd (length G1)", "Nat.odd (length G2)",
                       "symmetric_pair G1 G2"],
        [("Nat.eqb (length (filter (line_of_symmetry G2) (mirrors G1))) "
          "(Nat.gcd (length G1) (length G2)) = false", _VM)],
        note="Odd polygons have no half-turn, so their common lines are the mirrors of G_1 "
             "that are lines of symmetry of G_2; their number is not gcd(n_1, n_2)."),
    "lem-los-gij": _s(
        "Lemma lem-los-gij: for odd n_i, n_j, n_i not dividing n_j or n_j not dividing n_i, "
        "gcd(n_i, n_j) > 1 and a common line of symmetry, a line of symmetry for G_ij is a "
        "common line of symmetry for <G_i, G_j>.",
        ("G1", "G2"), ["polygon G1", "polygon G2", "Nat.odd (length G1)", "Nat.odd (length G2)",
                       "negb (Nat.eqb (Nat.modulo (length G2) (length G1)) 0) || "
                       "negb (Nat.eqb (Nat.modulo (length G1) (length G2)) 0)",
                       "Nat.ltb 1 (Nat.gcd (length G1) (length G2))", "symmetric_pair G1 G2",
                       "polygon (merged G1 G2)"],
        [("existsb (fun s => negb (line_of_symmetry G1 s && line_of_symmetry G2 s)) "
          "(mirrors (merged G1 G2)) = true", _VM)],
        note="G_12: G_1 projected onto G_2's circle, with G_2 (shared rays once); one of its "
             "mirrors is not a line of symmetry of both."),
    "obs-type-4": _s(
        "Observation obs-type-4: if n_i and n_j are odd, <G_i, G_j> has a common line of "
        "symmetry; additionally, if gcd(n_i, n_j) > 1, then G_ij is a type 4 polygon.",
        ("G1", "G2"), ["polygon G1", "polygon G2", "Nat.odd (length G1)", "Nat.odd (length G2)",
                       "symmetric_pair G1 G2", "Nat.ltb 1 (Nat.gcd (length G1) (length G2))"],
        [("type4 (merged G1 G2) = false", _VM)],
        note="G_12: G_1 projected onto G_2's circle, with G_2 (shared rays once). Here no "
             "ray is shared, so G_12 has 9 + 15 = 24 vertices: it fails type 4 by parity "
             "(type 4 needs n odd) before any symmetry is looked at; with shared rays an "
             "odd G_12 can be type 4 (family-merge-within-hypotheses: 21 vertices, 3 "
             "mirrors)."),
    "lem-type4": _s(
        "Lemma lem-type4: if three polygons G_i, G_j, G_k of calG' with odd n_i, n_j, n_k, "
        "distinct and none a multiple of another, are pairwise symmetric, then n_i, n_j, "
        "n_k are pairwise coprime.",
        ("G1", "G2", "G3"), [
            "Nat.eqb (length (polygons P)) 3",
            "polygon G1", "polygon G2", "polygon G3",
            "Nat.odd (length G1)", "Nat.odd (length G2)", "Nat.odd (length G3)",
            "negb (Nat.eqb (Nat.modulo (length G2) (length G1)) 0)",
            "negb (Nat.eqb (Nat.modulo (length G1) (length G2)) 0)",
            "negb (Nat.eqb (Nat.modulo (length G3) (length G1)) 0)",
            "negb (Nat.eqb (Nat.modulo (length G1) (length G3)) 0)",
            "negb (Nat.eqb (Nat.modulo (length G3) (length G2)) 0)",
            "negb (Nat.eqb (Nat.modulo (length G2) (length G3)) 0)",
            "symmetric_pair G1 G2", "symmetric_pair G1 G3", "symmetric_pair G2 G3",
            "negb (type4 (merged G1 G2))", "negb (type4 (merged G1 G3))",
            "negb (type4 (merged G2 G3))", "type0 G1 && type0 G2 && type0 G3"],
        [("Nat.eqb (Nat.gcd (length G1) (length G2)) 1 = false", _VM)],
        reading="calG' is what Preprocess's merge test (G_ij type 4) and the text's stopping "
                "rule give (no merge); merging every pair that meets the text's conditions "
                "before lem-los-gij would merge G_1, G_2 (the ledger: not a reading, it "
                "contradicts both)",
        note="calG' = calG_P = (G_1, G_2, G_3): Preprocess merges a pair only when G_ij is "
             "type 4 (no pair's is), and the text's stopping rule (every symmetric odd "
             "polygon type 0, 3 or 4) holds from the start (all three are regular: type 0). "
             "Distinct counts follow from 'none a multiple of another'. Odd polygons have "
             "no half-turn, so every reading of 'common line' gives symmetric_pair."),
    "theorem-los-g1n": _s(
        "Theorem theorem-los-g1n: a line of symmetry of G_1..n (the polygon Preprocess "
        "merges from G_1, ..., G_n) is a common line of symmetry of G_1, ..., G_n.",
        ("G1", "G2"), ["polygon G1", "polygon G2", "Nat.odd (length G1)", "Nat.odd (length G2)",
                       "negb (Nat.eqb (Nat.modulo (length G2) (length G1)) 0) || "
                       "negb (Nat.eqb (Nat.modulo (length G1) (length G2)) 0)",
                       "Nat.ltb 1 (Nat.gcd (length G1) (length G2))", "symmetric_pair G1 G2",
                       "polygon (merged G1 G2)", "type4 (merged G1 G2)"],
        [("existsb (fun s => negb (line_of_symmetry G1 s && line_of_symmetry G2 s)) "
          "(mirrors (merged G1 G2)) = true", _VM)],
        note="n = 2: G_1..2 = G_12 (G_1 projected onto G_2's circle, with G_2; shared rays "
             "once), which Preprocess merges (its test: G_12 is type 4) with every hypothesis "
             "of the text before lem-los-gij; one of its mirrors is not a line of both."),
    "Gprime-equiG": _s(
        "Theorem Gprime-equiG: calG' (Preprocess(calG)) is symmetric iff calG is symmetric.",
        ("G1", "G2", "G3"), [
            "Nat.eqb (length (polygons P)) 3", "polygon G1", "polygon G2", "polygon G3",
            "Nat.odd (length G1)", "Nat.odd (length G2)", "Nat.even (length G3)",
            "negb (Nat.eqb (Nat.modulo (length G2) (length G1)) 0) || "
            "negb (Nat.eqb (Nat.modulo (length G1) (length G2)) 0)",
            "Nat.ltb 1 (Nat.gcd (length G1) (length G2))", "symmetric_pair G1 G2",
            "polygon (merged G1 G2)", "type4 (merged G1 G2)"],
        [("calG_in_O_A (polygons P) = true", _VM),
         ("calG_symmetric [merged G1 G2; G3] = true", _VM)],
        reading="calG' = (G_12, G_3): the merge replaces G_1 and G_2 by G_12 (G_12 holds "
                "G_2's vertices; as printed Preprocess never ends here, see its entry)",
        note="G_1, G_2 odd meet every hypothesis of the text's merge and G_12 is type 4 "
             "(Preprocess's test); G_3 is even, so no other pair is merged. calG = calG_P has "
             "no common line (in O_A, under the mixed reading, so under every reading); "
             "calG' has one."),
    "GatheringPattern": _s(
        "Algorithm GatheringPattern(R) (R, the set of separated robots): gathers n >= 5 "
        "fat robots from every asymmetric configuration: 'G' = Preprocess(G); if G' is in "
        "O_S, report that gathering is not possible; else MakeAsym, ElectLeader, "
        "FormGPattern'.",
        ("G1", "G2", "G3"), [
            "Nat.leb 5 (length P)", "separated P", "in_O_A P",
            "Nat.eqb (length (polygons P)) 3", "polygon G1", "polygon G2", "polygon G3",
            "Nat.odd (length G1)", "Nat.odd (length G2)", "Nat.even (length G3)",
            "negb (Nat.eqb (Nat.modulo (length G2) (length G1)) 0) || "
            "negb (Nat.eqb (Nat.modulo (length G1) (length G2)) 0)",
            "Nat.ltb 1 (Nat.gcd (length G1) (length G2))", "symmetric_pair G1 G2",
            "polygon (merged G1 G2)", "type4 (merged G1 G2)"],
        [("orderable P", _ORDERABLE),
         ("calG_symmetric [merged G1 G2; G3] = true", _VM)],
        reading="G' = (G_12, G_3): Preprocess's merge replaces G_1 and G_2 by G_12 (as "
                "printed Preprocess never ends here, see its entry: then GatheringPattern "
                "never gets past its third line)",
        note="P is asymmetric (in O_A) and orderable (every candidate symmetry fixes it "
             "pointwise: group C1), n = 28. G_1, G_2 odd meet every hypothesis of the "
             "text's merge and G_12 is type 4 (Preprocess's test); G_3 is even, so no "
             "other pair is merged. G' = (G_12, G_3) has a common line, so the first "
             "branch runs: 'Report that gathering is not possible' for an asymmetric "
             "configuration. G_12 (21 vertices) and G_3 have no half-turn, so the common "
             "line is a mirror of both: in O_S under every reading of 'common line'.",
        scale=100),
    "MakeAsym": _s(
        "Algorithm MakeAsym(G'): given G' with G_t symmetric, makes G_t asymmetric by "
        "moving one elected robot v_l, reporting 'An orderable G' where G_t is asymmetric', "
        "or reports 'G' is not orderable' (when no asymmetric polygon, no asymmetric pair "
        "and no single-vertex polygon is found).",
        ("G1", "Gt"), [
            "Nat.leb 5 (length P)", "separated P", "Nat.eqb (length (polygons P)) 2",
            "existsb (Qeq_bool rG1) (radii P)", "existsb (Qeq_bool rGt) (radii P)",
            "forallb (fun r => Qle_bool rG1 r) (radii P)",
            "forallb (fun r => Qle_bool r rGt) (radii P)",
            "polygon G1", "polygon Gt", "symmetric_polygon Gt",
            "negb (type4 (merged G1 Gt))",
            "forallb symmetric_polygon (polygons P)", "asymmetric_pair G1 Gt",
            "Nat.eqb (length Gt) 3"],
        [("~ orderable P", _ORDER), ("~ electable P", _ELECT)],
        reading="the branch MakeAsym takes, not which robot it elects: Find_Asymmetry "
                "finds no asymmetric polygon, Find_Asymmetry_Pair finds <G_1, G_t>, so it "
                "elects one robot v_l (|G_t| = 3: ElectLeader(G_1t), whatever its "
                "ordering) and moves it, instead of reporting 'G' is not orderable'; G' = "
                "calG_P (Preprocess merges nothing: G_1t is not type 4; as printed its "
                "loop never ends on an odd polygon, see Preprocess's entry)",
        note="G' is not orderable, and no robot can be elected by an algorithm reading the "
             "configuration (electable, the same whatever the coordinates among the "
             "isometries about C): the rotation by 1/3 turn maps P onto itself and moves "
             "every robot, so the observer it turns elects the image of v_l, another "
             "robot (not_electable). Observers disagree on the robot that moves.",
        scale=100),
    "Preprocess": _s(
        "Algorithm Preprocess(calG): merges odd polygons whose G_ij is type 4, giving calG' "
        "(symmetric iff calG is).",
        ("G1", "G2", "G3"), [
            "Nat.eqb (length (polygons P)) 3", "polygon G1", "polygon G2", "polygon G3",
            "Nat.odd (length G1)", "Nat.odd (length G2)", "Nat.even (length G3)",
            "existsb (fun G => Nat.odd (length G)) (polygons P)",
            "type4 (merged G1 G2)", "Nat.odd (length (merged G1 G2))"],
        [("forall fuel, preprocess_printed fuel (polygons P) (Outer 1) = false", _PRE),
         ("calG_in_O_A (polygons P) = true", _VM),
         ("calG_symmetric [merged G1 G2; G3] = true", _VM)],
        note="Literal reading (the printed loops, preprocess_printed): it never ends, "
             "whatever the order of the polygons (i stops at an odd polygon). Evident "
             "reading (replace G_i and G_j by G_ij, rescan): G_12 is type 4, so G_1, G_2 "
             "merge; then G_12 is the only odd polygon and calG' = (G_12, G_3), which is "
             "symmetric while calG is in O_A: no reading rescues it."),
    "lem-3-pair-sym": _s(
        "Lemma lem-3-pair-sym: three polygons G_i, G_j, G_k of calG' are pairwise "
        "symmetric iff they have a common line of symmetry.",
        ("G1", "G2", "G3"), [
            "Nat.eqb (length (polygons P)) 3", "polygon G1", "polygon G2", "polygon G3",
            "Nat.eqb (length (filter (fun G => Nat.odd (length G)) (polygons P))) 1",
            "symmetric_pair_same_kind G1 G2", "symmetric_pair_same_kind G1 G3",
            "symmetric_pair_same_kind G2 G3"],
        [("common_line_same_kind [G1; G2; G3] = false", _VM)],
        reading="same-kind: a common line is straight for all the polygons or skew for "
                "all (the mixed reading, its proof's own, holds here: the line at turn 0 "
                "is straight for G_1 and G_2 and skew for G_3)",
        note="calG' = calG_P: Preprocess merges only pairs of odd polygons and there is one "
             "(as printed its loop never ends on an odd polygon, Preprocess's entry; read "
             "as a merge it merges nothing). 'Only if' fails: the pairs share straight lines "
             "(G_1, G_2; G_2, G_3) or skew ones (the two rectangles), yet no line is "
             "common to all three."),
    "theorem-sym-pair-symG": _s(
        "Theorem theorem-sym-pair-symG: every pair <G_i, G_j> of calG' is symmetric iff "
        "all the polygons of calG' have a common line of symmetry.",
        (), ["Nat.leb 2 (length (polygons P))", "forallb polygon (polygons P)",
             "Nat.eqb (length (filter (fun G => Nat.odd (length G)) (polygons P))) 1",
             "forallb (fun Gi => forallb (symmetric_pair_same_kind Gi) (polygons P)) "
             "(polygons P)"],
        [("common_line_same_kind (polygons P) = false", _VM)],
        reading="same-kind: a common line is straight for all the polygons or skew for "
                "all; t >= 2 (for t = 1 'every pair' is vacuous)",
        note="calG' = calG_P (one odd polygon: Preprocess merges nothing). Every pair has a "
             "common line of one kind; no line is common to all the polygons."),
    "Psym-Gsym": _s(
        "Theorem Psym-Gsym: P is in O_S iff calG_P is in O_S (all polygons have a common "
        "line of symmetry, def-sym-calG).",
        (), ["forallb polygon (polygons P)", "calG_symmetric (polygons P)"],
        [("in_O_A P = true", _VM)],
        reading="mixed: a common line may be straight for one polygon and skew for another "
                "(the other readings have other witnesses: not exported)",
        note="calG_P is symmetric: one line through C is a mirror of some polygons and a "
             "skew line (the half-turn) of the others; yet P is in O_A."),
    "lemma-straight-sym": _s(
        "Lemma lemma-straight-sym: let G be a straight symmetric polygon; a straight line L "
        "is a line of straight symmetry for G iff CW_m = ACW_m or CW_m' = ACW_m' (m, m' where "
        "L meets G).",
        (), ["polygon P", "straight_symmetric P"],
        [("existsb (fun m => cw_sym P m && negb (is_symmetry (Mirror (2 * turn m)) P)) P "
          "= true", _VM)],
        reading="or: either end suffices (as printed), with m a vertex and L the line "
                "through m and C (the other readings need an end on an edge: not exported). "
                "With L any line through m the literal 'if' fails trivially (CW_m depends on "
                "m only: any non-mirror line through a vertex with CW_m = ACW_m); lines "
                "through C are the ones a line of symmetry can be",
        note="'If' fails: a vertex m has CW_m = ACW_m, yet the line through m and C (the "
             "reflection Mirror (2 turn m)) does not map P onto itself."),
    "Check_Symmetry_Even": _s(
        "Algorithm Check_Symmetry_Even(G): reports whether the even polygon G is straight "
        "or skew symmetric and its degree of symmetry (0 if asymmetric).",
        (), ["polygon P", "Nat.even (length P)", "asymmetric_polygon P"],
        [("even_reports_straight P = true", _VM),
         ("forall fuel, printed_loop fuel P 1 = false", _LOOP)],
        note="Under the evident reading (i++ after every vertex) it reports 'G is straight "
             "symmetric' for an asymmetric polygon; as printed (i++ in the else branch "
             "only) its loop never ends on it, whatever the labelling."),
    "Check_Symmetry_Odd": _s(
        "Algorithm Check_Symmetry_Odd(G): reports the degree of symmetry of the odd polygon "
        "G (0 if asymmetric).",
        (), ["polygon P", "Nat.odd (length P)"],
        [("forall fuel, printed_loop fuel P 1 = false", _LOOP)],
        reading="literal: i++ in the else branch, as printed (with i++ after every vertex "
                "it is correct: proofs/check_symmetry_odd.md)",
        note="As printed its loop never ends on P (no report), whatever the labelling."),
    "Elect_Leader_Asym": _s(
        "Algorithm Elect_Leader_Asym(G): elects a leader vertex v_l of the asymmetric "
        "polygon G such that G \\ v_l is asymmetric.",
        (), ["polygon P", "asymmetric_polygon P"], [("leader_candidates P = []", _VM)],
        note="Every G \\ v is symmetric: 'while G \\ v_i is symmetric: i++' runs past v_n "
             "and elects nobody, whatever the ordering. n = 3: G \\ v is two points, "
             "straight symmetric for every triangle, so every asymmetric triangle refutes "
             "it (the ledger's rotation-only tie failure has no Coq file)."),
    "ElectLeader": _s(
        "Algorithm ElectLeader(calG): given calG with G_t asymmetric, elects a leader v_l of "
        "G_1 such that G_1 \\ v_l is asymmetric.",
        ("G1", "Gt"), ["existsb (Qeq_bool rG1) (radii P)", "existsb (Qeq_bool rGt) (radii P)",
                       "forallb (fun r => Qle_bool rG1 r) (radii P)",
                       "forallb (fun r => Qle_bool r rGt) (radii P)",
                       "polygon Gt", "asymmetric_polygon Gt", "polygon G1",
                       "asymmetric_polygon G1", "Nat.odd (length G1)",
                       "negb (existsb (cw_sym G1) G1)"],
        [("leader_candidates G1 = []", _VM)],
        note="G_1 is the inner polygon, G_t the outer one; G_1 is asymmetric and odd, and "
             "no vertex has CW = ACW, so Check_Symmetry_Odd(G_1)'s loop (as printed, or with "
             "i++ after every vertex) ends with deg_sym = 0: it reports G_1 asymmetric and "
             "ElectLeader calls Elect_Leader_Asym(G_1). Every G_1 \\ v is symmetric (n = 3: "
             "two points): it elects nobody."),
    "Elect_Leader_Sym": _s(
        "Algorithm Elect_Leader_Sym(G): elects a leader of a symmetric convex polygon G "
        "whose degree of symmetry is one, its line through a single vertex or two vertices "
        "(else reports that leader election is not possible).",
        (), ["polygon P", "Nat.even (length P)", "negb (is_symmetry half_turn P)",
             "Nat.eqb (length (mirrors P)) 1",
             "forallb (fun s => Nat.eqb (fixed_vertices P s) 2) (mirrors P)"],
        [("elect_leader_sym_even_refuses P = true", _VM)],
        reading="degree as Check_Symmetry_Even reports it (deg_sym/2, its loop read with "
                "i++ after every vertex); with the degree read as the number of mirrors it "
                "elects (proofs/short_proofs.md)",
        note="One line of symmetry (one mirror, no half-turn: no skew line), through two "
             "vertices; Check_Symmetry_Even reports degree 2, so the algorithm reports "
             "'Leader Election is not possible for G'."),
    "lem-sym-notord": _s(
        "Lemma lem-sym-notord: if <G_i, G_j> is a symmetric pair, then it is not orderable.",
        ("G1", "G2"), ["Nat.eqb (length (polygons P)) 2", "polygon G1", "polygon G2",
                       "symmetric_pair G1 G2"],
        [("orderable (G1 ++ G2)", _ORDERABLE)],
        reading="mixed: a common line may be straight for one polygon and skew for the "
                "other; the pair's orderability is that of its union about C (the other "
                "readings' witnesses have single robots or collinear ones: not exported)",
        note="The line at s/2 turns for a mirror Mirror s of G_1 is a line of skew "
             "symmetry of G_2 (the half-turn maps G_2 onto itself): a common line, so the "
             "pair is symmetric. Yet no candidate isometry about C other than the identity "
             "maps G_1 ++ G_2 onto itself (only_identity, computed), so it is orderable: "
             "orderable_of_only_identity, a theorem of the library, with (T2) proved."),
    "Make_SymToAsym": _s(
        "Algorithm Make_SymToAsym(G): for a convex polygon G with degree of symmetry one, "
        "its line of symmetry through a single vertex or two vertices, moving the leader "
        "v_l epsilon to its right on the circle makes G asymmetric.",
        ("G1",), ["existsb (Qeq_bool rG1) (radii P)",
                  "forallb (fun r => Qle_bool rG1 r) (radii P)",
                  "Nat.eqb (length G1) 1", "symmetric_polygon G1"],
        [("forall eps : Q, symmetric_polygon (map (fun v => Pt (r2 v) (turn v - eps)) G1) "
          "= true", "intros eps; vm_compute; reflexivity")],
        reading="a single robot is a polygon G_1 with degree of symmetry one (its line "
                "through C and it), as Check_Symmetry_Odd reports with i++ after every "
                "vertex (CW = ACW = [], deg_sym = 1); as printed its loop never ends on G_1 "
                "and ElectLeader never reaches Make_SymToAsym",
        note="G_1 is one robot: symmetric, its one line of symmetry through C and its vertex "
             "(the paper's note after def-asymmetric-poly), so ElectLeader calls "
             "Make_SymToAsym on it; moved by any epsilon it is again one point: symmetric."),
}


def library_text() -> str:
    """The Coq library, ``proofs/coq/Exactsym.v``."""
    return read_library(LIBRARY)


def read_library(path: Path) -> str:
    """The text of a Coq library of ``proofs/coq/`` (inlined into every export)."""
    try:
        return path.read_text(encoding="utf-8")
    except OSError as err:
        raise CoqExportError(f"the Coq library {path.name} is not here (it lives in "
                             "the source tree, proofs/coq/)") from err


def theorem_name(label: str) -> str:
    return "refutes_" + "".join(c if c.isalnum() else "_" for c in label)


def coq_file_name(label: str) -> str:
    """The file name of a label's Coq refutation (a Coq module name: no '-')."""
    return "".join(c if c.isalnum() else "_" for c in label) + ".v"


def _q(value) -> str:
    """A rational as a Coq term of type Q."""
    f = Fraction(str(value))
    return f"(Qmake {f.numerator} {f.denominator})" if f.numerator >= 0 else \
        f"(Qmake ({f.numerator}) {f.denominator})"


def _points(config: dict) -> list[tuple[Fraction, Fraction]]:
    if config.get("coordinates") != "polar" or config.get("field") is not None:
        raise CoqExportError("only rational polar configurations are exported to Coq "
                             "(number fields: not yet)")
    try:
        return [(Fraction(str(r)), Fraction(str(t))) for r, t in config["points"]]
    except (ValueError, TypeError) as err:
        raise CoqExportError(f"a coordinate is not rational: {err}") from None


def _level_radii(refutation: dict, names: tuple) -> dict:
    """The squared radius of each level the theorem names, from the certificate's parts."""
    parts = refutation.get("parts") or {}
    if names == ("G",):
        certs = [parts.get("level")]
    elif names == ("Gi", "Gj"):
        certs = list(parts.get("pair") or [])
    else:
        return {}
    if len(certs) != len(names) or any(not isinstance(c, dict) for c in certs):
        raise CoqExportError(f"the certificate names no part for {', '.join(names)}")
    radii = [_points(c["configuration"])[0][0] for c in certs]
    if names == ("Gi", "Gj") and radii[0] > radii[1]:
        radii.reverse()                 # G_i is the inner polygon (obs-merg-asym-pair)
    return dict(zip(names, radii))


def _file(label: str, spec: dict, points: list, levels: dict, source: str | None,
          statement: str | None) -> str:
    """The Coq file: header, library, configuration, theorem."""
    out = [f"(* Refutation of {label}, checked by Coq: `coqc` on this file alone.",
           f"   The paper: {spec['words']}"]
    if statement:
        out.append(f"   The ledger (proofs/statements.toml): {statement}")
    if spec["reading"]:
        out.append(f"   Refuted under the reading: {spec['reading']}.")
    k = spec.get("scale") or 1
    if k != 1:
        out += [f"   P is the source's configuration with every squared distance multiplied by {k}",
                "   (a scaling about C), so that its robots are separated fat robots (unit",
                "   discs); no other conjunct changes under a scaling about C."]
    out += ["   Written by exactsym (exactsym/certificates/coq_refutation.py); the library",
            "   below is proofs/coq/Exactsym.v, inlined: it holds every definition used.",
            f"   source: {source or '-'} *)", ""]
    out.append(library_text().rstrip())
    out += ["", "(* ================================================= the configuration *)", "",
            "(* P: (squared distance from C, turn) of each point. *)",
            "Definition P : list pt := ["]
    points = [(r * k, t % 1 if r else Fraction(0)) for r, t in points]  # scaled, canonical
    levels = {name: r * k for name, r in levels.items()}
    out.append(";\n".join(f"  Pt {_q(r)} {_q(t)}" for r, t in points) + "].")
    for name, r in levels.items():
        out.append(f"Definition r{name} : Q := {_q(r)}.")
        out.append(f"Definition {name} : list pt := level P r{name}.")
    out.append("")
    if spec["note"]:
        out.append(f"(* {spec['note']} *)")
    hypotheses = ["canonical P", "distinct P", "sec_centred P", *spec["hypotheses"]]
    conjuncts = [(f"{h} = true", _VM) for h in hypotheses] + list(spec["conclusion"])
    claim = " /\\\n  ".join(f"({p})" if p.startswith("forall") else p for p, _ in conjuncts)
    out += [f"(* P is a set written canonically about C, the centre of its SEC (T1); the",
            f"   hypotheses of {label} hold and its conclusion is false. *)",
            f"Theorem {theorem_name(label)} :\n  {claim}.", "Proof."]
    out += [f"  split; [{t} |]." for _, t in conjuncts[:-1]] + [f"  {conjuncts[-1][1]}."]
    out += ["Qed.", "", f"Print Assumptions {theorem_name(label)}.", ""]
    return "\n".join(out)


def coq_refutation(refutation: dict, statement: str | None = None,
                   source: str | None = None) -> str:
    """The Coq file refuting ``refutation["label"]`` on its configuration.  ``statement``
    (the ledger's claim) is quoted in the header when given; ``source`` names where the
    configuration came from (default: the certificate's source file, if any)."""
    label = refutation.get("label")
    if label not in STATEMENTS:
        raise CoqExportError(f"no Coq statement for {label!r} from a certificate (exported: "
                             f"{', '.join(sorted(STATEMENTS))})")
    spec = STATEMENTS[label]
    cert = refutation["certificate"]
    points = _points(cert["configuration"])
    levels = _level_radii(refutation, spec["names"])
    source = source or (cert.get("source") or {}).get("file")
    return _file(label, spec, points, levels, source, statement)


def coq_refutation_of_points(label: str, points, source: str | None = None,
                             statement: str | None = None) -> str:
    """The Coq file refuting ``label`` (one of :data:`CASE_STATEMENTS`) on the rational
    polar configuration ``points``: ``(r2, turn)`` pairs about the SEC centre."""
    if label not in CASE_STATEMENTS:
        raise CoqExportError(f"no Coq statement for {label!r} from a configuration "
                             f"(exported: {', '.join(sorted(CASE_STATEMENTS))})")
    try:
        points = [(Fraction(str(r)), Fraction(str(t))) for r, t in points]
    except (ValueError, TypeError) as err:
        raise CoqExportError(f"a coordinate is not rational: {err}") from None
    spec = CASE_STATEMENTS[label]
    radii = sorted({r for r, _ in points if r > 0})
    ends = {"G1": radii[0], "Gt": radii[-1]} if radii else {}
    if len(radii) > 1:
        ends["G2"] = radii[1]
    if len(radii) > 2:
        ends["G3"] = radii[2]
    levels = {name: ends[name] for name in spec["names"] if name in ends}
    return _file(label, spec, points, levels, source, statement)


def source_of(text: str) -> str | None:
    """The ``source:`` a Coq refutation names in its header (None for '-')."""
    found = re.search(r"^   source: (\S+) \*\)$", text, re.M)
    return found.group(1) if found and found.group(1) != "-" else None


def coqc_accepts(text: str, name: str = "Refutation.v",
                 coqc: str | None = None) -> tuple[bool, str, float]:
    """``(accepted, coqc's messages, seconds)``: run ``coqc`` on ``text`` alone in a
    fresh temporary directory (nothing else on its load path); accepted means coqc exits
    0 and prints nothing but ``Print Assumptions``'s "Closed under the global context" (no
    axiom, no other output).
    Raises :class:`CoqExportError` when no ``coqc`` is installed."""
    import shutil
    import subprocess
    import tempfile
    import time
    coqc = coqc or shutil.which("coqc")
    if not coqc:
        raise CoqExportError("coqc is not installed (Debian: apt-get install coq)")
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / name
        path.write_text(text, encoding="utf-8")
        start = time.perf_counter()
        run = subprocess.run([coqc, "-q", path.name], cwd=tmp, capture_output=True,
                             text=True, timeout=600)
        seconds = time.perf_counter() - start
    messages = (run.stdout + run.stderr).strip()
    accepted = run.returncode == 0 and messages == "Closed under the global context"
    return accepted, messages, seconds
