"""The audit of the per-level statements (Section 3 and 4.1 on each level polygon).

:func:`level_findings` reads the polygon layer's verdicts of each level (the ``"paper"``
entries of :func:`exactsym.paper.polygon_report.level_reports`, computed once per polygon
shape) and lists, per statement, where the paper's notions contradict its definitions
evaluated exactly.  It never looks at the ground truth: the definitions
(``def-straight-symmetric-poly``, ``def-skew-symmetric-poly``) are exact, and the audit's
truth-based per-level check (``lem-asym-ord``) stays in :mod:`exactsym.audit.statements`.

Statements and what is checked on each level (``docs/interpretations.md``, "The audit of
the per-level statements"):

* ``obs-asymmetric-polygon`` (Theorem 1): its verdict against the definitions
  (asymmetric = neither straight nor skew symmetric);
* ``lemma-straight-sym`` (reading "or"): on a straight symmetric level, the lines the
  CW/ACW strings find (``lines_by_strings``) against the exact mirrors, kind ``reading``
  (the reading "and" with both ends on the circle rescues the lemma); outside the
  premise (not straight symmetric) nothing is recorded;
* ``Check_Symmetry_Odd``: only the printed loop's non-termination, a note of kind
  ``literal-reading`` (the loop with ``i++`` after every vertex is proved correct);
* ``Check_Symmetry_Even``: "straight"/"skew" against the definitions, and the degree
  against the number of mirrors when that number is the degree (a polygon that is not
  skew symmetric: a skew symmetric one has every line through C as a line of symmetry);
  the printed loop's non-termination is a ``literal-reading`` note;
* ``obs-exh-poly``: a straight symmetric level whose type (by the definition) is
  "unclassified";
* ``lemma-sym-regular``: two or more mirrors, all through vertices, not regular (on a
  skew symmetric polygon only under the reading "line of symmetry = line of straight
  symmetry": kind ``reading``);
* ``Elect_Leader_Asym`` on a level asymmetric by the definitions: no leader, or the
  lexicographic minimum tied (both handednesses).
"""

from __future__ import annotations

from ..paper import polygon as P
from ..paper.circle_polygon import level_polygon
from ..paper.polygon_report import LEADER_LIMIT

#: The per-level statements, in the paper's order.
LEVEL_STATEMENTS = ("lemma-straight-sym", "obs-asymmetric-polygon", "lemma-sym-regular",
                    "obs-exh-poly", "Check_Symmetry_Odd", "Check_Symmetry_Even",
                    "Elect_Leader_Asym")


def _entry(statement, says, truth, witness, kind="claim") -> dict:
    return {"statement": statement, "says": says, "truth": truth, "witness": witness,
            "kind": kind}


def level_findings(config, levels, verdicts, types=None) -> tuple[list, list, set]:
    """``(discrepancies, notes, covered)`` of the per-level statements.

    ``verdicts``: per level, the polygon layer's ``"paper"`` entry (None for the robot at
    C).  A level whose definitions were not evaluated (above the polygon layer's
    ``DEFINITION_LIMIT``) is skipped, and so are levels of one or two robots: the
    statements are about convex polygons (a 2-gon's strings also find the line through
    both vertices, a line of symmetry only under the reading that allows lines containing
    every vertex; ``def-straight-symmetric-conf`` excludes it).  ``covered``: the
    statements evaluated on at least one level meeting their hypotheses.  Levels of one
    shape give one entry each (the audit merges equal claims and counts them).  ``types``:
    per level, the polygon layer's type facts (``(name, every mirror through a vertex)``,
    :class:`exactsym.paper.polygon_report.LevelSection`); recomputed from the definition
    when not given."""
    found, notes, covered = [], [], set()
    for index, v in enumerate(verdicts):
        n = len(levels.levels[index].points)
        if v is None or v.get("definition") is None or n < 3:
            continue
        name = f"G{index + 1}"
        d = v["definition"]
        straight, skew, mirrors = d["straight"], d["skew"], d["mirrors"]
        symmetric_def = straight or skew
        where = {"level": name, "robots": list(levels.levels[index].points)}

        covered.add("obs-asymmetric-polygon")
        if v["theorem1_symmetric"] != symmetric_def:
            found.append(_entry(
                "obs-asymmetric-polygon",
                f"Theorem 1 calls {name} "
                f"{'symmetric' if v['theorem1_symmetric'] else 'asymmetric'}",
                f"{name} is {'symmetric' if symmetric_def else 'asymmetric'} by the definitions "
                f"({mirrors} mirror(s), {'' if skew else 'not '}skew symmetric)", where))
        if straight:
            covered.add("lemma-straight-sym")
            if v["lines_by_strings"] != mirrors:
                entry = _entry(
                    "lemma-straight-sym",
                    f"the CW/ACW strings find {v['lines_by_strings']} lines of straight "
                    f"symmetry of {name}", f"{name} has {mirrors} mirror(s)", where,
                    kind="reading")
                entry["reading"] = "or: a line through C is one of straight symmetry when " \
                                   "either end m has CW_m = ACW_m (as printed)"
                entry["rescued_by"] = "and, circle points: both ends of the line on the " \
                                      "circle have CW = ACW (proofs/straight_sym_readings.md)"
                found.append(entry)
        algorithm = v["check"]
        if n % 2:
            covered.add("Check_Symmetry_Odd")
        else:
            covered.add("Check_Symmetry_Even")
            flags = []
            def yes(flag) -> str:       # words, never Python's True/False, in prose
                return "yes" if flag else "no"
            if v["straight"] != straight:
                flags.append(f"'straight symmetric': {yes(v['straight'])}, by the "
                             f"definition {yes(straight)}")
            if v["skew"] != skew:
                flags.append(f"'skew symmetric': {yes(v['skew'])}, by the definition "
                             f"{yes(skew)}")
            if straight and not skew and str(v["degree"]) != str(mirrors):
                flags.append(f"degree {v['degree']}, but {mirrors} line(s) of symmetry")
            if flags:
                found.append(_entry(algorithm, f"{algorithm}({name}) reports "
                                    + "; ".join(flags), f"{name}: {mirrors} mirror(s), "
                                    f"{'' if skew else 'not '}skew symmetric", where,
                                    kind="algorithm"))
        if _has_axis_vertex(v, n):
            notes.append(_entry(algorithm, f"{algorithm} as printed",
                                "the loop never ends: i++ sits in the else branch and a "
                                "vertex has CW = ACW (with i++ after every vertex it "
                                "terminates)", where, kind="literal-reading"))
        if straight:
            covered.add("obs-exh-poly")
            if v["type"] == "unclassified":
                found.append(_entry("obs-exh-poly", f"{name}, straight symmetric, is skew "
                                    "symmetric or of type 0-4",
                                    f"{name} fits no type: {v['type_reason']}", where))
        if straight and mirrors >= 2:
            if types is not None:
                facts = types[index]
            else:
                kind = P.polygon_type(level_polygon(config, levels, index, cleared=True))
                facts = None if kind is None else (str(kind), all(t > 0 for t in kind.through))
            if facts is not None and facts[1]:
                covered.add("lemma-sym-regular")
                if facts[0] != "type-0":
                    entry = _entry("lemma-sym-regular", f"{name} has {mirrors} lines of "
                                   "symmetry, all through vertices, hence it is regular",
                                   f"{name} is not regular", where,
                                   kind="reading" if skew else "claim")
                    if skew:
                        entry["reading"] = "line of symmetry = line of straight symmetry"
                        entry["rescued_by"] = ("lines of skew symmetry count too: the "
                                               "polygon is centrally symmetric, so most "
                                               "lines through C are skew lines through no "
                                               "vertex")
                    found.append(entry)
        if not symmetric_def and n <= LEADER_LIMIT:
            covered.add("Elect_Leader_Asym")
            found.extend(_elect_leader_asym(config, levels, index, v, name, where))
    return found, notes, covered


def _has_axis_vertex(v: dict, n: int) -> bool:
    """A vertex with CW = ACW (the printed loop of either check then never ends)."""
    if n % 2:
        return v.get("loop_terminates") is False
    return bool(v["straight"])      # st_sym is set exactly by a vertex with CW = ACW


def _elect_leader_asym(config, levels, index, v, name, where) -> list:
    """Elect_Leader_Asym on a level asymmetric by the definitions (its hypothesis): the
    verdicts already hold it when the check also says asymmetric; else it is run here."""
    leaders = v.get("leader_asym")
    if leaders is None:
        poly = level_polygon(config, levels, index, cleared=True)
        plus, minus = P.elect_leader_asym(poly, 1), P.elect_leader_asym(poly, -1)
        leaders = {"+1": plus.label, "-1": minus.label, "tie": plus.tie or minus.tie}
    out = []
    if leaders["tie"]:
        out.append(_entry("Elect_Leader_Asym", f"{name} is asymmetric: the lexicographic "
                          "minimum of the (CW, ACW) tuples gives the ordering",
                          "the minimum is attained at more than one vertex", where,
                          kind="algorithm"))
    if leaders["+1"] is None or leaders["-1"] is None:
        out.append(_entry("Elect_Leader_Asym", f"{name} is asymmetric: a leader v_l with "
                          f"{name} minus v_l asymmetric is elected",
                          "no vertex v_i of the ordering leaves an asymmetric polygon "
                          "(Theorem 1): no leader", where, kind="algorithm"))
    return out


__all__ = ["level_findings", "LEVEL_STATEMENTS"]
