"""The paper against the ground truth, and against its own definitions, on one configuration.

:func:`audit` runs the paper's family algorithms (:mod:`exactsym.paper.family`) and the
ground truth (:mod:`exactsym.truth.symmetry`), and lists every statement of the paper whose
claim is false on this configuration, in the paper's order, each as
``{"statement": label, "says": ..., "truth": ..., "witness": ..., "kind": ...}``:

* the per-level statements (:mod:`exactsym.audit.levels`: Theorem 1, ``lemma-straight-sym``,
  the two checks, ``obs-exh-poly``, ``lemma-sym-regular``, Elect_Leader_Asym), from the
  polygon layer's verdicts of each level;
* statements about orderability, checked against the truth: ``lemma-sym-ord``,
  ``lem-asym-ord`` (each level), ``lem-sym-notord`` and ``lem-asym-pair-ord`` (each pair of
  levels: the union of the two levels, symmetries about C), ``lem-all-pair-asym-ord``,
  ``lem-one-pair-asym-ord``, ``Psym-Gsym``, ``Pasym-Pord``, ``cor-Pasym-Pord``;
* statements the paper's own notions contradict (recorded by the family layer with
  ``holds`` False: ``obs-gcd``, ``lem-los-gij``, ``obs-merg-asym-pair``, ... and the
  algorithms' guarantees: MakeAsym's "G_t is asymmetric", an unchanged SEC,
  ``obs-v-move``, ``lem-vl-move``, ties in Elect_Leader_Asym);
* the conclusions: ``paper.orderable`` against the truth's ``orderable`` (GatheringPattern,
  for n >= 5 only); when the truth is orderable the paper's leader must not depend on the
  observer: the procedure is recomputed on exactly transformed inputs (a reflection; a
  rotation, scaling and, for Cartesian inputs, translation), indices mapped back, and two
  frames electing different leaders (or moving different robots) are the witness
  (:func:`_frame_difference` tells the sense of an epsilon move and the reading of
  Elect_Leader_Asym apart); when the truth is not orderable the first robot the paper
  makes act must be fixed by every symmetry.

``kind``: ``claim``, ``algorithm``, ``conclusion``, or ``reading`` (false under the reading
in effect; ``reading`` and ``rescued_by`` name it and the reading that rescues the paper).
``notes`` lists, in the same shape, what is *not* a discrepancy: defects of the literal
reading of a printed loop (``literal-reading``), failures outside a statement's hypotheses
(``outside-hypotheses``: ``lem-los-gij``, ``theorem-los-g1n``), GatheringPattern, MakeAsym
and ``lem-vl-move`` below n = 5 (``out-of-scope``), exactsym's repair of a printed line
that works as printed (``repair``), frames that differ only in the sense of an epsilon move
(``epsilon-sense``).  ``covered``: the labels evaluated on this configuration, in the
paper's order.  ``agrees`` is True iff ``discrepancies`` is empty; ``conclusions_agree``
only looks at the conclusions.  The audit is outside :mod:`exactsym.paper` and may use
both sides.

The statements on levels and pairs of levels are checked within the family layer's
budgets (:class:`exactsym.paper.family.Limits`: the same selection of pairs as
``family_claims``, at most ``claim_levels`` asymmetric levels, a statement failing on
many of them listed a few times and then counted); ``bounded`` in the result says what
was checked (``docs/interpretations.md``, "Bounds of the family layer").
"""

from __future__ import annotations

from .frames import (FRAME_TEXT, frame_levels, frame_rings, reflected_frame, rings_fit, slim,
                     transformed)
from .groups import SubGroups, group_about_centre
from .handedness import MIRROR_RUN, decided_without_tie, frames_agree, other_handedness_findings
from .levels import level_findings
from .result import AuditResult
from ..geometry.configuration import Configuration, no_cycle_collection
from ..exact import fmpq, number_text
from ..labels import ALGORITHMS, STATEMENTS
from ..geometry.levels import Levels, levels_of
from ..paper import family as F
from ..paper.polygon_report import level_section
from ..truth.symmetry import SymmetryGroup, symmetry_group

__all__ = ["audit", "truth_in_O_S", "group_about_centre", "transformed", "FRAMES",
           "STATEMENT_ORDER"]

#: The order in which statements are listed (the paper's order, then the algorithms).
STATEMENT_ORDER = [
    "lemma-straight-sym", "obs-asymmetric-polygon", "lemma-sym-regular", "obs-exh-poly",
    "lemma-sym-ord", "lem-asym-ord", "obs-pair-asym-ord", "lem-sym-notord",
    "obs-merg-asym-pair", "lem-asym-pair-ord", "lem-all-pair-asym-ord",
    "lem-one-pair-asym-ord", "obs-gcd", "lem-los-gij", "theorem-los-g1n", "obs-type-4",
    "lem-type4", "lem-3-pair-sym", "theorem-sym-pair-symG", "obs1-Gprime-equiG",
    "Gprime-equiG", "Psym-Gsym", "Pasym-Pord", "cor-Pasym-Pord", "Check_Symmetry_Odd",
    "Check_Symmetry_Even", "Elect_Leader_Asym",
]

#: The statements whose instances the family layer marks ``within_hypotheses``: an
#: instance outside them is a note of kind ``outside-hypotheses``, not a discrepancy.
HYPOTHESIS_MARKED = ("lem-los-gij", "theorem-los-g1n", "obs-gcd", "obs-type-4")

#: The paper's gathering algorithm is for n >= 5 robots (GatheringPattern's hypothesis).
GATHERING_MIN_N = 5

#: MakeAsym and the lemma about its run belong to the gathering algorithm: n >= 5 too.
GATHERING_SCOPED = ("MakeAsym", "lem-vl-move")

#: Kinds of entry: a discrepancy (``agrees`` False) or a note (``notes``: not one).
DISCREPANCY_KINDS = ("claim", "algorithm", "conclusion", "reading")
NOTE_KINDS = ("literal-reading", "outside-hypotheses", "out-of-scope", "epsilon-sense",
              "repair")

FRAMES = ("identity", "reflection", "similarity")

#: What each statement (or algorithm step) claims, in a line.
CLAIMS = {
    "lemma-sym-ord": "a non-singleton set in O_S is not orderable",
    "lem-asym-ord": "an asymmetric polygon is orderable",
    "obs-pair-asym-ord": "if a polygon of a pair is asymmetric, the pair is asymmetric",
    "lem-sym-notord": "a symmetric pair is not orderable",
    "obs-merg-asym-pair": "if <G_i, G_j> is an asymmetric pair, G_ij is asymmetric",
    "lem-asym-pair-ord": "an asymmetric pair is orderable",
    "lem-all-pair-asym-ord": "if G has an asymmetric pair, G is orderable",
    "lem-one-pair-asym-ord": "if G has an asymmetric polygon, G is orderable",
    "obs-gcd": "two odd polygons with one common line have gcd(n_i, n_j) common lines",
    "lem-los-gij": "a line of symmetry of G_ij is a common line of symmetry of <G_i, G_j>",
    "theorem-los-g1n": "a line of symmetry of G_1..n is a common line of G_1, ..., G_n",
    "obs-type-4": "n_i, n_j odd with a common line and gcd(n_i, n_j) > 1: G_ij is type 4",
    "lem-type4": "three pairwise symmetric odd polygons of G' (distinct counts, none a "
                 "multiple of another) have pairwise coprime counts",
    "lem-3-pair-sym": "three polygons of G' are pairwise symmetric iff they have a common "
                      "line of symmetry",
    "theorem-sym-pair-symG": "every pair of G' is symmetric iff all polygons of G' have a "
                             "common line of symmetry",
    "obs1-Gprime-equiG": "if G is symmetric, every pair in G is symmetric",
    "Gprime-equiG": "G' is symmetric iff G is symmetric",
    "Psym-Gsym": "P is in O_S iff G_P is in O_S",
    "Pasym-Pord": "P is orderable iff P is in O_A",
    "cor-Pasym-Pord": "P is orderable iff G_P is in O_A",
    "MakeAsym": "MakeAsym makes G_t asymmetric, keeps the SEC, and the polygons it orders "
                "are asymmetric",
    "Make_SymToAsym": "moving the leader of a polygon with one line of symmetry makes it "
                      "asymmetric",
    "ElectLeader": "elects a leader v_l from G_1 (G_1t is orderable when G_t is asymmetric)",
    "obs-v-move": "the leader selected through G_it is the same whether v is moving or "
                  "epsilon apart",
    "lem-vl-move": "while v_l moves, no other robot is selected as leader",
    "Elect_Leader_Sym": "with degree of symmetry one and the line through two vertices, "
                        "Elect_Leader_Sym elects the same leader for every observer",
}


# ---------------------------------------------------------------- the truth, as needed
def truth_in_O_S(group: SymmetryGroup, n: int) -> bool:
    """``def-symmetric-conf`` decided from the true group: a singleton, or a mirror that
    moves some point (straight symmetry), or the half-turn (skew symmetry: reflecting in
    L and then in the perpendicular L' is the point reflection about their meeting
    point, which must be the centre)."""
    if n == 1:
        return True
    if group.mirrors > 0 and not group.orderable:
        return True
    return group.rotations % 2 == 0


def _symmetry_witness(group: SymmetryGroup, robots) -> dict | None:
    """A symmetry that moves a robot, named with configuration indices."""
    g = group.rotation_generator or (group.mirror if not group.orderable else None)
    if g is None:
        return None
    perm = g.permutation
    moved = next((k for k, j in enumerate(perm) if j != k), None)
    if g.kind == "rotation":
        what = (f"rotation by {number_text(fmpq(1, group.rotations))} turn about C"
                if g.turn is None else f"rotation by {number_text(g.turn)} turn about C")
    else:
        what = ("mirror through C" if g.turn is None else
                f"mirror in the line at {number_text(g.turn)} turn through C")
    turn = g.turn if g.turn is not None else \
        (fmpq(1, group.rotations) if g.kind == "rotation" else None)
    # the data beside the words: the kind, its turn as an exact text, the robots
    out = {"symmetry": what, "group": group.name, "isometry": g.kind,
           "turn": None if turn is None else number_text(turn)}
    if moved is not None:
        out["maps"] = f"robot {robots[moved]} -> robot {robots[perm[moved]]}"
        out["robot_map"] = {"from": robots[moved], "to": robots[perm[moved]]}   # "maps" as data
    return out


def _actions(res: F.PaperResult) -> tuple:
    return (tuple(m["robot"] for m in res.moves), res.leader)


def _steps(res: F.PaperResult) -> list:
    return [(e["algorithm"], e.get("line"), tuple(e.get("robots") or ()), e.get("uses"),
             e["statement"]) for e in res.trace if e.get("robots") and e.get("uses")]


# ---------------------------------------------------------------- the audit
def _d(statement, says, truth, witness=None, kind="claim") -> dict:
    return {"statement": statement, "says": says, "truth": truth, "witness": witness,
            "kind": kind}


def audit(config: Configuration, ring_data: Levels | None = None,
          paper: F.PaperResult | None = None, options: dict | None = None,
          group: SymmetryGroup | None = None, level_verdicts: tuple | None = None,
          level_types: tuple | None = None) -> AuditResult:
    """See :func:`_audit` (run with the cyclic garbage collector paused)."""
    with no_cycle_collection():
        return AuditResult.from_dict(_audit(config, ring_data, paper, options, group,
                                            level_verdicts, level_types))


def _audit(config: Configuration, ring_data: Levels | None = None,
           paper: F.PaperResult | None = None, options: dict | None = None,
           group: SymmetryGroup | None = None, level_verdicts: tuple | None = None,
           level_types: tuple | None = None) -> dict:
    """The audit of ``config`` (see the module docstring); ``paper`` is recomputed when
    not given, and so is the true ``group``.  Options: ``reading``, ``degree`` (passed to
    the paper), ``invariance`` (default True: recompute the paper in the other frames),
    ``limits`` (:class:`exactsym.paper.family.Limits`, default the family layer's: the
    statements on levels and pairs of levels are checked within its budgets, and the
    frames are recomputed with it; ``bounded`` in the result says what was checked).
    ``level_verdicts``, ``level_types``: the polygon layer's verdicts and type facts per
    level (:class:`exactsym.paper.polygon_report.LevelSection`; computed when not given)."""
    options = options or {}
    limits = options.get("limits") or F.DEFAULT_LIMITS
    ring_data = ring_data if ring_data is not None else levels_of(config)
    kw = {"reading": options.get("reading", "literal"), "degree": options.get("degree", "paper"),
          "limits": limits}
    if paper is None:
        paper = F.paper_procedure(config, ring_data, **kw)
    if group is None:
        group = symmetry_group(config, ring_data)
    n = config.n
    in_os = truth_in_O_S(group, n)
    G = paper.G_rings or F.concentric_polygons(config, ring_data)
    polar = F.is_polar(G)
    found: dict[str, list] = {}
    failures: dict[str, int] = {}
    examples = limits.claim_examples
    bounded: dict = {}
    notes: list = []
    covered: set = set()

    def add(d):
        found.setdefault(d["statement"], []).append(d)

    # the per-level statements (Section 3 and 4.1 on each level polygon)
    if level_verdicts is None:
        section = level_section(config, ring_data)
        level_verdicts, level_types = section.verdicts, section.types
    level_found, level_notes, level_covered = level_findings(config, ring_data,
                                                             level_verdicts, level_types)
    for d in level_found:
        add(d)
    notes.extend(level_notes)
    covered |= level_covered

    def add_counted(statement, make):
        """A statement checked on many levels or pairs: its first failures (``make()``
        builds the entry: only those listed need the sub-configuration's group), then a
        count."""
        failures[statement] = failures.get(statement, 0) + 1
        if examples is None or failures[statement] <= examples:
            add(make())

    whole_witness = _symmetry_witness(group, list(range(n)))
    # lemma-sym-ord (n > 1): in O_S => not orderable
    if n > 1 and in_os:
        covered.add("lemma-sym-ord")
    if n > 1 and in_os and group.orderable:
        add(_d("lemma-sym-ord", "P is in O_S, hence not orderable", "P is orderable",
               whole_witness))
    # lem-asym-ord on each level: asymmetric polygon => orderable
    asym_levels = [g for g in G if not F.is_symmetric_polygon(g)]
    cap = limits.claim_levels
    if cap is not None and len(asym_levels) > cap:
        asym_checked = asym_levels[:cap // 2] + asym_levels[len(asym_levels) - cap // 2:]
    else:
        asym_checked = asym_levels
    if asym_checked:
        covered.add("lem-asym-ord")
    subs = SubGroups(config, ring_data, group)      # orderability without recomputing
    for g in asym_checked:
        if not subs.orderable(g.robots, g.levels):
            def entry(g=g):
                sub, robots = subs.group(g.robots, g.levels)
                return _d("lem-asym-ord", f"{g.name} is an asymmetric polygon, hence orderable",
                          f"{g.name} is not orderable (group {sub.name})",
                          _symmetry_witness(sub, robots))
            add_counted("lem-asym-ord", entry)
    bounded["lem_asym_ord_levels_checked"] = len(asym_checked)
    bounded["asymmetric_levels"] = len(asym_levels)
    # pairs of levels
    pairs, total_pairs = F.select_pairs(G, limits)
    bounded["pairs_checked"] = len(pairs)
    bounded["of"] = total_pairs
    for i, j in pairs:
        a, b = G[i], G[j]
        sym = F.is_symmetric_pair(a, b)
        orderable = subs.orderable(a.robots + b.robots, a.levels + b.levels)
        covered.add("lem-sym-notord" if sym else "lem-asym-pair-ord")
        if sym and orderable:
            def entry(a=a, b=b):
                sub = subs.group(a.robots + b.robots, a.levels + b.levels)[0]
                common = F.intersect_lines(a.lines, b.lines)
                return _d("lem-sym-notord",
                          f"<{a.name}, {b.name}> is a symmetric pair "
                          f"({F.lines_text(common, polar)} in common: {a.name} has "
                          f"{F.lines_text(a, polar)}, {b.name} has "
                          f"{F.lines_text(b, polar)}), hence not orderable",
                          f"the union of {a.name} and {b.name} is orderable (group "
                          f"{sub.name} about C)", {"pair": [a.name, b.name]})
            add_counted("lem-sym-notord", entry)
        if not sym and not orderable:
            def entry(a=a, b=b):
                sub, robots = subs.group(a.robots + b.robots, a.levels + b.levels)
                return _d("lem-asym-pair-ord", f"<{a.name}, {b.name}> is an asymmetric pair, "
                          "hence orderable", f"the union of {a.name} and {b.name} is not "
                          f"orderable (group {sub.name} about C)",
                          _symmetry_witness(sub, robots))
            add_counted("lem-asym-pair-ord", entry)
    for statement, count in failures.items():
        if examples is not None and count > examples:
            what = "levels" if statement == "lem-asym-ord" else "pairs of levels"
            add(_d(statement, CLAIMS.get(statement, statement),
                   f"false on {count} of the {what} checked; the first {examples} are listed",
                   {"failures": count, "listed": examples}))
    bounded["failures"] = dict(sorted(failures.items()))
    # lem-all-pair-asym-ord / lem-one-pair-asym-ord (on G)
    try:
        asym_pair = F.find_asymmetry_pair(G, limits.step_budget(n))
    except F.WorkBudgetExceeded:
        asym_pair = None
        bounded["lem_all_pair_asym_ord"] = "not checked: Find_Asymmetry_Pair over budget"
    if asym_pair is not None:
        covered.add("lem-all-pair-asym-ord")
    if asym_pair is not None and not group.orderable:
        a, b = G[asym_pair[0]], G[asym_pair[1]]
        add(_d("lem-all-pair-asym-ord", f"<{a.name}, {b.name}> is an asymmetric pair, hence "
               "G is orderable", f"P is not orderable (group {group.name})", whole_witness))
    asym_poly = F.find_asymmetry(G)
    if asym_poly is not None:
        covered.add("lem-one-pair-asym-ord")
    if asym_poly is not None and not group.orderable:
        add(_d("lem-one-pair-asym-ord", f"{G[asym_poly].name} is an asymmetric polygon, "
               "hence G is orderable", f"P is not orderable (group {group.name})",
               whole_witness))
    # paper-internal claims recorded by the family layer
    for e in paper.trace:
        holds = e.get("holds")
        if holds is None:
            continue
        witness = e.get("witness")
        outside = (e["statement"] in HYPOTHESIS_MARKED and isinstance(witness, dict)
                   and witness.get("within_hypotheses") is False)
        if holds is True or not outside:
            covered.add(e["statement"])
        if holds is not False:
            continue
        entry = _d(e["statement"], CLAIMS.get(e["statement"], e["statement"]),
                   f"false here: {e['detail']}", witness,
                   kind="claim" if e["algorithm"] == "Section 3" else "algorithm")
        if e.get("reading"):
            entry.update(kind="reading", reading=e["reading"], rescued_by=e.get("rescued_by"))
        if e["statement"] in GATHERING_SCOPED and n < GATHERING_MIN_N:
            notes.append(_out_of_scope(entry, n))
        elif e.get("kind") in ("literal-reading", "repair"):
            notes.append(dict(entry, kind=e["kind"]))
        elif outside:
            notes.append(dict(entry, kind="outside-hypotheses"))
        else:
            add(entry)
    # the same algorithms run by an observer of the other handedness (the mirror image)
    mirror = _mirror_run(config, ring_data, paper, kw) if options.get("invariance", True) \
        else None
    if mirror is not None:
        for d in other_handedness_findings(paper.trace, mirror.trace, CLAIMS):
            if d["statement"] in GATHERING_SCOPED and n < GATHERING_MIN_N:
                notes.append(_out_of_scope(d, n))
                continue
            covered.add(d["statement"])
            add(d)
    # theorems
    covered.update(("Psym-Gsym", "Pasym-Pord", "cor-Pasym-Pord"))
    g_sym = F.is_symmetric_family(G)
    if g_sym != in_os:
        add(_d("Psym-Gsym", f"P is in O_S iff G_P is; G_P is {'in O_S' if g_sym else 'in O_A'}"
               f" (common lines: {F.lines_text(F.common_lines(G), polar)})",
               f"P is {'in O_S' if in_os else 'in O_A'} (group {group.name})",
               whole_witness if in_os else None))
    if group.orderable == in_os:
        add(_d("Pasym-Pord", "P is orderable iff P is in O_A",
               f"P is {'in O_S' if in_os else 'in O_A'} and "
               f"{'orderable' if group.orderable else 'not orderable'} (group {group.name})",
               whole_witness))
    if group.orderable == g_sym:
        add(_d("cor-Pasym-Pord", "P is orderable iff G_P is in O_A",
               f"G_P is {'in O_S' if g_sym else 'in O_A'} but P is "
               f"{'orderable' if group.orderable else 'not orderable'} (group {group.name})",
               whole_witness))
    # conclusions
    conclusions = []
    if paper.orderable != group.orderable:
        entry = _d("GatheringPattern",
                   f"{'orderable' if paper.orderable else 'not orderable'}"
                   f" (gathering {'possible' if paper.gathering_possible else 'not possible'}"
                   f", MakeAsym: {paper.make_asym})",
                   f"{'orderable' if group.orderable else 'not orderable'} "
                   f"(group {group.name})", whole_witness, kind="conclusion")
        if n >= GATHERING_MIN_N:
            conclusions.append(entry)
        else:
            notes.append(_out_of_scope(entry, n))
    if n >= GATHERING_MIN_N:
        covered.add("GatheringPattern")
    leader_info, leader_notes = _leader_check(config, ring_data, paper, group, kw, options,
                                              mirror)
    conclusions.extend(leader_info)
    notes.extend(leader_notes)
    if paper.complete:
        covered.add("ElectLeader")
    ordered = []
    for label in STATEMENT_ORDER:
        ordered.extend(found.pop(label, []))
    for rest in found.values():
        ordered.extend(rest)
    ordered = _dedupe(ordered)
    ordered.extend(conclusions)
    covered.update(d["statement"] for d in ordered)       # found false: evaluated here
    return {"agrees": not ordered, "conclusions_agree": not conclusions,
            "discrepancies": ordered,
            "notes": _dedupe(notes),
            "covered": _paper_order(covered),
            "truth": {"group": group.name, "orderable": group.orderable,
                      "leader": group.leader, "in_O_S": in_os},
            "bounded": bounded}


def _out_of_scope(entry: dict, n: int) -> dict:
    return dict(entry, kind="out-of-scope", truth=entry["truth"] + f"; out of scope: the "
                f"paper's gathering algorithm is for n >= {GATHERING_MIN_N} robots (n = {n})")


_ORDER = {label: k for k, label in enumerate(STATEMENTS + ALGORITHMS)}


def _paper_order(labels) -> list:
    """``labels`` in the paper's order (``exactsym.labels``)."""
    return sorted(labels, key=lambda label: (_ORDER.get(label, len(_ORDER)), label))


def _dedupe(items: list) -> list:
    """One entry per (statement, kind, claim text); ``count`` says how many were merged
    (a claim failing on several pairs, or again in a later round)."""
    out, index = [], {}
    for d in items:
        key = (d["statement"], d["kind"], d["says"], d["truth"])
        if key in index:
            index[key]["count"] += 1
            continue
        d = dict(d, count=1)
        index[key] = d
        out.append(d)
    return out


def _mirror_run(config, ring_data, paper, kw) -> F.PaperResult | None:
    """The paper's procedure on the reflected configuration (lem-vl-move checked, the
    Section-3 claims not: they do not depend on handedness), or None when it cannot be
    run exactly."""
    moved = transformed(config, ring_data, "reflection")
    G = paper.G_rings
    several = rings_fit(G, ring_data)
    try:
        levels, polygons = reflected_frame(config, ring_data, moved, G, several)
        rings = frame_rings(G, levels, moved, "reflection", polygons) \
            if several and levels is not None else None
        return slim(F.paper_procedure(moved, levels, **kw, level_polygons=polygons,
                                      claims=False, describe_polygons=False, rings=rings))
    except (ArithmeticError, NotImplementedError, ValueError):
        return None


def _leader_check(config, ring_data, paper, group, kw, options,
                  mirror=None) -> tuple[list, list]:
    """``(discrepancies, notes)`` of the conclusions about the leader (see the module
    docstring; :func:`_frame_difference` for two frames that disagree; ``mirror``: the
    run in the reflected frame, when already made).  A run that stops early is compared
    on the moves both runs make."""
    out, notes = [], []
    if group.orderable:
        if paper.complete and paper.orderable and paper.leader is None:
            out.append(_d("ElectLeader", "G is orderable but no leader is elected",
                          f"orderable (group {group.name}); a leader exists "
                          f"(e.g. robot {group.leader})", None, kind="conclusion"))
        if not options.get("invariance", True):
            return out, notes
        for frame in FRAMES[1:]:
            if frame == "reflection" and mirror is not None:
                res = mirror
            else:
                moved = transformed(config, ring_data, frame)
                G = paper.G_rings
                several = rings_fit(G, ring_data)
                levels = frame_levels(config, ring_data, moved, frame, G, several)
                rings = frame_rings(G, levels, moved, frame) \
                    if several and levels is not None else None
                res = slim(F.paper_procedure(moved, levels, **kw, claims=False,
                                             check_vl=False, describe_polygons=False,
                                             rings=rings))
            if frames_agree(paper, res):
                continue
            entry, note = _frame_difference(config, paper, res, frame, kw)
            if note is not None:
                notes.append(note)
            if entry is not None:
                out.append(entry)
                if entry["kind"] == "conclusion":
                    break
        return out, notes
    # not orderable: the first robot made to act must be fixed by every symmetry, for
    # either handedness (the reflected run's robots are the same robots)
    for run in (paper, mirror):
        actor = None if run is None else run.first_actor
        if actor is None:
            continue
        label = "MakeAsym" if run.moves else "ElectLeader"
        g = next((g for g in group.symmetries() if g.permutation[actor] != actor), None)
        if g is None or any(d["statement"] == label for d in out):
            continue
        out.append(_d(label, f"robot {actor} acts first ({'moves' if run.moves else 'is elected'})"
                      + ("" if run is paper else f" for {MIRROR_RUN}"),
                      f"not orderable (group {group.name}); a symmetry maps robot {actor} "
                      f"to robot {g.permutation[actor]}, so observers disagree on it",
                      {"symmetry": g.kind, "maps": f"robot {actor} -> robot "
                       f"{g.permutation[actor]}",
                       "robot_map": {"from": actor, "to": g.permutation[actor]}},
                      kind="conclusion"))
    return out, notes


def _procedure(config: Configuration, frame: str, kw: dict, **changes) -> F.PaperResult:
    """The paper's procedure on ``config`` seen in ``frame`` (claims and lem-vl-move off)."""
    return F.paper_procedure(transformed(config, levels_of(config), frame),
                             **dict(kw, **changes), claims=False, check_vl=False,
                             describe_polygons=False)


def _frame_difference(config: Configuration, paper: F.PaperResult, res: F.PaperResult,
                      frame: str, kw: dict) -> tuple[dict | None, dict | None]:
    """``(discrepancy or None, note or None)`` for the identity frame ``paper`` and the
    frame ``frame`` (result ``res``) acting differently.

    (b) A reflected frame turns "clockwise for this observer" into the other sense: when
    both frames move the same robots and one move is an epsilon move, the two only differ
    in the sense the mover chose (only that robot moves, and it picks one sense).  The
    comparison then continues on the configuration after the moves in either sense
    (``final_config`` of both results; robots are oblivious and recompute): on each, both
    frames must act alike; if they do, that is a note (``epsilon-sense``), not a
    discrepancy; else the first configuration where they do not is compared below.
    (c) A reflected frame is an observer of the other handedness: when the difference
    disappears with Elect_Leader_Asym's unordered reading ({CW, ACW} as a set), it is
    ``Elect_Leader_Asym`` refuted under the literal reading (kind ``reading``), not a
    failure of ``lem-asym-ord``."""
    first, second, continued, where = paper, res, False, config
    sensed = _after_epsilon(paper, res) if frame == "reflection" else None
    if sensed is not None:
        # both senses: the configuration after the identity frame's moves, and the one
        # after the reflected frame's (the mover may take either sense)
        after, moved = sensed
        runs = []
        for c in after:
            try:
                q0, qf = _procedure(c, "identity", kw), _procedure(c, frame, kw)
            except (ArithmeticError, NotImplementedError, ValueError):
                break
            if not (q0.complete and qf.complete):
                break
            runs.append((c, q0, qf))
        if len(runs) == len(after):
            eps = [m for m in moved if m.get("kind") == "epsilon"]
            movers = [m["robot"] for m in eps]
            bad = [(c, q0, qf) for c, q0, qf in runs if _actions(q0) != _actions(qf)]
            if not bad:
                elected = [q0.leader for _, q0, _ in runs]
                return None, _d(
                    eps[-1]["algorithm"],
                    "the leader does not depend on the choice of origin and coordinate system",
                    f"the frames differ only in the sense of the epsilon move of robot(s) "
                    f"{movers} (clockwise for each observer; only the mover chooses): after "
                    f"the move every frame elects one robot: "
                    + ", ".join(f"robot {x} ({sense})" for x, sense in
                                zip(elected, ("this observer's sense", "the other sense"))),
                    {"frames": ["identity", frame], "epsilon_movers": movers,
                     "leader_after_move": elected[0], "leaders_after_move": elected},
                    kind="epsilon-sense")
            where, first, second = bad[0]
            continued = True
    if frame == "reflection" and kw.get("reading", "literal") == "literal":
        try:
            u0 = _procedure(where, "identity", kw, reading="unordered")
            uf = _procedure(where, frame, kw, reading="unordered")
        except (ArithmeticError, NotImplementedError, ValueError):
            u0 = uf = None
        if u0 and decided_without_tie(u0) and decided_without_tie(uf) and _actions(u0) == _actions(uf):
            d = _difference_entry("Elect_Leader_Asym", first, second, frame, continued,
                                  kind="reading")
            d["reading"] = "literal: the ordered pair (CW, ACW) of Elect_Leader_Asym"
            d["rescued_by"] = ("unordered: the pair CW, ACW read as a set (the paper writes "
                               "it in braces); then both frames elect "
                               f"{_leader_text(u0.leader)} "
                               f"({_moves_text(_actions(u0)[0])})")
            return d, None
    step = _first_difference(first, second)
    statement = "lem-asym-ord"
    if step is not None and step[3] != "Elect_Leader_Asym":
        statement = step[0]
    return _difference_entry(statement, first, second, frame, continued), None


def _after_epsilon(paper: F.PaperResult, res: F.PaperResult):
    """``(configurations, moves)``: where to continue comparing two frames that may
    differ only in the sense of an epsilon move (the mover chooses it: "clockwise for
    this observer"), or None.  Either both frames move the same robots with an epsilon
    move among them (continue after all the moves), or their first round of MakeAsym
    moves the same robots and ends with an epsilon move in both (continue after that
    round: what follows is computed on a configuration the mover's sense made, so the
    frames may part there without disagreeing on any one configuration)."""
    if _actions(paper)[0] == _actions(res)[0] and paper.final_config is not None and \
            any(m.get("kind") == "epsilon" for m in paper.moves):
        return [c for c in (paper.final_config, res.final_config) if c is not None], \
            paper.moves
    if paper.round_configs and res.round_configs:
        (k, a), (k2, b) = paper.round_configs[0], res.round_configs[0]
        robots = [m["robot"] for m in paper.moves[:k]]
        if k and k == k2 and robots == [m["robot"] for m in res.moves[:k]] and \
                paper.moves[k - 1].get("kind") == "epsilon" == res.moves[k - 1].get("kind"):
            return [a, b], paper.moves[:k]
    return None


def _leader_text(leader) -> str:
    return "no leader" if leader is None else f"leader {leader}"


def _moves_text(robots) -> str:
    """The robots a run moves, in words: ``no moves`` or ``moves robots 3, 4``."""
    robots = list(robots)
    if not robots:
        return "no moves"
    return f"moves robot{'s' if len(robots) > 1 else ''} " + ", ".join(map(str, robots))


def _difference_entry(statement, a: F.PaperResult, b: F.PaperResult, frame: str,
                      continued: bool, kind: str = "conclusion") -> dict:
    base, other = _actions(a), _actions(b)
    step = _first_difference(a, b)
    where = " on the configuration after the moves" if continued else ""
    witness = {"frames": ["identity", frame], "leaders": [a.leader, b.leader],
               "moves": [list(base[0]), list(other[0])],
               "first_different_step": None if step is None else
               f"{step[0]} line {step[1]} ({step[3] or step[4]}): robots {list(step[2])}"}
    if continued:
        witness["after_moves"] = True
    return _d(statement,
              "the leader does not depend on the choice of origin and coordinate system",
              f"{_leader_text(a.leader)} ({_moves_text(base[0])}) in "
              f"{FRAME_TEXT['identity']}, {_leader_text(b.leader)} ({_moves_text(other[0])}) "
              f"when {FRAME_TEXT[frame]}{where}",
              witness, kind=kind)


def _first_difference(a: F.PaperResult, b: F.PaperResult):
    sa, sb = _steps(a), _steps(b)
    for x, y in zip(sa, sb):
        if x[:3] != y[:3]:
            return x
    return None
