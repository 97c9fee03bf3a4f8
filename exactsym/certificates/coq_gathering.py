"""Refutations of the gathering statements that Coq re-checks (issue 35;
docs/certificates.md, "Coq: the gathering statements").

The gathering statements (\\label{gathering_algorithm}: FormGPattern, gather-no-obstacle,
lem-vl-move) are about runs of the asynchronous algorithm; their refutations here are
facts of ONE configuration, or of a start and one snapshot of a move, stated for every
choice the run leaves open that the Coq library does not compute (which robot
ElectLeader elects, which robot of G_t MakeAsym moves and in which sense).
``coq_gathering_of_points(label, points, source)`` writes one self-contained Coq file: the
libraries ``proofs/coq/Exactsym.v`` and ``proofs/coq/Gathering.v`` inlined, the rational
polar configuration, and one theorem whose conjuncts are proved by ``vm_compute`` (and by
``Gathering.v``'s ``every_leader_blocked_spec``).  ``coqc FILE.v`` accepting it is the
check.  The simulator (``exactsym gather`` on the source case) confirms the same violation
on a run; nothing of exactsym is trusted by the Coq file.
"""

from __future__ import annotations

from fractions import Fraction
from pathlib import Path

from .coq_refutation import CoqExportError, library_text, read_library, theorem_name

__all__ = ["GATHERING_STATEMENTS", "GATHERING_LIBRARY", "coq_gathering_of_points",
           "gathering_library_text"]

#: The gathering library, inlined after Exactsym.v in every file this module writes.
GATHERING_LIBRARY = Path(__file__).resolve().parents[2] / "proofs" / "coq" / "Gathering.v"

_VM = "vm_compute; reflexivity"
_BLOCKED = ("(forall P', map r2 P' = map r2 P -> sec_centred P' = true ->\n"
            "     forall i, (i < length P')%nat -> blocked_at_C (map r2 P') i = true)",
            "intros P' E _; exact (every_leader_blocked_spec P "
            "ltac:(vm_compute; reflexivity) P' E)")

#: The start of GatheringPattern on P: separated robots, n >= 5, P asymmetric, Preprocess
#: merging nothing, calG' in O_A (so it does not report "gathering is not possible").
_START = ["Nat.leb 5 (length P)", "separated P", "no_merge P", "calG_in_O_A (polygons P)"]

_OBSTACLE_NOTE = (
    "C is not occupied and two robots lie within 2 of C, so whichever robot R ElectLeader "
    "elects, the move of R to C ends with R's disc overlapping another robot's, whatever "
    "the path; the moves made before it in the cycle (Make_SymToAsym's epsilon turn of "
    "the one-robot G_1) are turns about C, which keep every distance from C and the SEC "
    "(P' below: any configuration with P's distances from C and the same SEC centre).")
_OBSTACLE_READING = (
    "A3=all (every move the procedures name is made in the cycle, so the leader's "
    "FormGPattern move is reached; under A3=first the leader never moves: "
    "make-sym-to-asym-livelock), A4=exact or A4=covers (C occupied = a centre at C, or "
    "a disc covering C: no centre is within 1 of C, so C is free under both; only "
    "A4=within2, C occupied by robot 1 at 9/5, rescues it, by a proved cycle), "
    "Preprocess with its counters advancing (calG' = calG when no G_ij is type 4); any path (A5)")


def _spec(words, hypotheses, conclusion, reading, note, definitions=()) -> dict:
    return {"words": words, "hypotheses": hypotheses, "conclusion": conclusion,
            "reading": reading, "note": note, "definitions": list(definitions)}


#: label -> what the Coq theorem says: the paper's words, the hypotheses (Coq booleans,
#: each ``= true``), the negated conclusion (Coq propositions with their tactics), the
#: reading, a note, and the definitions the theorem names besides P.
GATHERING_STATEMENTS = {
    "gather-no-obstacle": _spec(
        "Lemma (\\label{gathering_algorithm}, after GatheringPattern; the ledger's "
        "gather-no-obstacle): 'No obstacle appears in the path of a mobile robot to its "
        "destination.'",
        [*_START, "in_O_A P", "asymmetric_polygon (G_t P)", "negb (occupied_C P)",
         "negb (covered_C P)"],
        [_BLOCKED], _OBSTACLE_READING, _OBSTACLE_NOTE),
    "FormGPattern": _spec(
        "Algorithm FormGPattern(R) (\\label{gathering_algorithm}): 'if C is not occupied "
        "by other robot: Move R to C' -- moves the leader to C (or to the last layer of "
        "the gathering pattern) without a collision.",
        [*_START, "in_O_A P", "asymmetric_polygon (G_t P)", "negb (occupied_C P)",
         "negb (covered_C P)"],
        [_BLOCKED], _OBSTACLE_READING, _OBSTACLE_NOTE),
    "lem-vl-move": _spec(
        "Lemma lem-vl-move: 'When v_l is moving no other robot will be selected as "
        "leader.'",
        [*_START, "forallb symmetric_polygon (polygons P)",
         "asymmetric_pair (G_1 P) (G_t P)", "symmetric_polygon (G_t P)",
         "Nat.ltb 3 (length (G_t P))"],
        [("forallb (fun v => forallb (fun e => fresh_look_elects_other P v lam e) "
          "[eps; - eps]) (G_t P) = true", _VM)],
        "'selected as leader' by any step of the procedure, GatheringPattern's ElectLeader "
        "included (the paper's own use, L1562: 'when the leader is moving, no other "
        "robots will move'); Preprocess with its counters advancing (calG' = calG when no "
        "G_ij is type 4); MakeAsym's 'Move v_l, epsilon distance away' a turn of eps = "
        "1/100 about C (as its FindAsymmetry branch says, 'on the same circle'), in either "
        "sense, the fresh Look half way (lam = 1/2); ElectLeader's branch decided by G_1's "
        "symmetry itself (Check_Symmetry_Odd as printed never ends on G_1; read with i++ "
        "after every vertex it reports the same). No reading of a one-robot G_1 and no "
        "ordering: the leader is a vertex of G_1 whichever Elect_Leader_Asym picks",
        "MakeAsym's branch: no polygon of calG' is asymmetric (FindAsymmetry finds none), "
        "<G_1, G_t> is an asymmetric pair (Find_Asymmetry_Pair finds it) and |G_t| > 3, so "
        "v_l, a vertex of G_t (which one: any), moves epsilon about C.  Half way, for "
        "every such v_l and either sense, a fresh Look's ElectLeader takes its first branch "
        "(G_1, an isosceles triangle, has degree of symmetry one and its line passes through "
        "a single vertex): it calls Make_SymToAsym(G_1) and elects a vertex of G_1, not "
        "v_l.",
        ["Definition eps : Q := (Qmake 1 100).", "Definition lam : Q := (Qmake 1 2)."]),
}


def gathering_library_text() -> str:
    """The gathering library, ``proofs/coq/Gathering.v``."""
    return read_library(GATHERING_LIBRARY)


def _q(value: Fraction) -> str:
    return f"(Qmake {value.numerator} {value.denominator})" if value >= 0 else \
        f"(Qmake ({value.numerator}) {value.denominator})"


def coq_gathering_of_points(label: str, points, source: str | None = None,
                            statement: str | None = None) -> str:
    """The Coq file refuting the gathering statement ``label`` on the rational polar
    configuration ``points`` (``(r2, turn)`` pairs about the SEC centre)."""
    if label not in GATHERING_STATEMENTS:
        raise CoqExportError(f"no Coq statement for {label!r} among the gathering "
                             f"statements ({', '.join(sorted(GATHERING_STATEMENTS))})")
    try:
        points = [(Fraction(str(r)), Fraction(str(t))) for r, t in points]
    except (ValueError, TypeError) as err:
        raise CoqExportError(f"a coordinate is not rational: {err}") from None
    spec = GATHERING_STATEMENTS[label]
    out = [f"(* Refutation of {label}, checked by Coq: `coqc` on this file alone.",
           f"   The paper: {spec['words']}"]
    if statement:
        out.append(f"   The ledger (proofs/statements.toml): {statement}")
    out += [f"   Refuted under the reading: {spec['reading']}.",
            "   Written by exactsym (exactsym/certificates/coq_gathering.py); the libraries",
            "   below are proofs/coq/Exactsym.v and proofs/coq/Gathering.v, inlined: they",
            "   hold every definition used.",
            f"   source: {source or '-'} *)", "",
            library_text().rstrip(), "", gathering_library_text().rstrip(), "",
            "(* ================================================= the configuration *)", "",
            "(* P: (squared distance from C, turn) of each robot. *)",
            "Definition P : list pt := ["]
    points = [(r, t % 1 if r else Fraction(0)) for r, t in points]     # canonical
    out.append(";\n".join(f"  Pt {_q(r)} {_q(t)}" for r, t in points) + "].")
    out += spec["definitions"]
    out += ["", f"(* {spec['note']} *)"]
    hypotheses = ["canonical P", "distinct P", "sec_centred P", *spec["hypotheses"]]
    conjuncts = [(f"{h} = true", _VM) for h in hypotheses] + list(spec["conclusion"])
    # a conjunct that begins with a binder is parenthesised (coq_refutation's convention)
    claim = " /\\\n  ".join(f"({p})" if p.startswith("forall") else p for p, _ in conjuncts)
    name = theorem_name(label)
    out += ["(* P is a set of separated robots written canonically about C, the centre of",
            f"   its SEC (T1, T4); the hypotheses of {label} hold and its conclusion is",
            "   false. *)",
            f"Theorem {name} :\n  {claim}.", "Proof."]
    out += [f"  split; [{t} |]." for _, t in conjuncts[:-1]] + [f"  {conjuncts[-1][1]}."]
    out += ["Qed.", "", f"Print Assumptions {name}.", ""]
    return "\n".join(out)
