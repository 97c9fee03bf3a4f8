"""The Section-3 statements on G and G', evaluated with the paper's own notions.

:func:`family_claims` checks, within the work budgets (:class:`~.limits.Limits`), each
statement by the function named after its label (``obs_pair_asym_ord``, ...) and records
each failure (``holds`` False, with a witness) and one summary per statement that holds.
Claims about orderability need the truth and are the audit's (:mod:`exactsym.audit.statements`).
"""

from __future__ import annotations

from itertools import combinations
from math import gcd
from typing import Iterable, Sequence

from ..circle_polygon import CirclePolygon
from .concentric import (ALL_LINES, SCREEN_ONLY, Ring, common_lines, first_shown, has_lines,
                         intersect_lines, is_odd, is_symmetric_family, is_symmetric_pair,
                         is_symmetric_polygon, line_text, lines_data, lines_text, new_ring,
                         polygon_name, robot_count)
from .find_asymmetry import find_asymmetry_pair
from ..keys import sort_by_angle
from .limits import DEFAULT_LIMITS, END_LEVELS, Limits, WorkBudgetExceeded
from .projection import coincidence_note, is_type4, radial_projection
from .trace import few_names, trace_entry


def _claim(trace, statement: str, holds: bool, polygons, detail: str, witness=None):
    return trace_entry(trace, "Section 3", None, polygons, statement, detail, holds=holds,
                       witness=witness)


def sampled_pairs(t: int, count: int):
    """Pairs among the first and last :data:`END_LEVELS` levels (lexicographic), then
    consecutive pairs (i, i + 1) evenly spaced over the rest, ``count`` in all at most."""
    k = END_LEVELS
    ends = sorted(set(range(min(k, t))) | set(range(max(0, t - k), t)))
    made = 0
    for x, a in enumerate(ends):
        for b in ends[x + 1:]:
            if made >= count:
                return
            made += 1
            yield a, b
    ends_set = set(ends)
    middle = [i for i in (range(k - 1, t - k) if t > 2 * k else ())
              if not (i in ends_set and i + 1 in ends_set)] if t <= 4 * count + 4 * k else None
    if middle is None:       # avoid a list of t indices: the same spacing, computed
        lo, hi = k - 1, t - k            # i in [lo, hi): (i, i + 1) not both at the ends
        span = hi - lo
        left = count - made
        for x in range(min(left, span)):
            yield lo + (x * span) // min(left, span), lo + (x * span) // min(left, span) + 1
        return
    left = count - made
    if len(middle) <= left:
        chosen = middle
    else:
        chosen = [middle[(x * len(middle)) // left] for x in range(left)]
    for i in chosen:
        yield i, i + 1


def select_pairs(G: Sequence[Ring], limits: Limits | None = None) -> tuple[list, int]:
    """``(pairs, total)``: the pairs (i, j), i < j, of ``G`` on which pair statements are
    checked (``family_claims``, the audit), and the number of pairs.  All pairs in
    lexicographic order when there are at most ``limits.claim_pairs``; else the pairs
    among the first and last :data:`END_LEVELS` levels, then evenly spaced consecutive
    pairs; a pair is skipped when its vertices would exceed the vertex budget."""
    limits = limits if limits is not None else DEFAULT_LIMITS
    t = len(G)
    total = t * (t - 1) // 2
    cap = limits.claim_pairs
    budget = limits.vertex_budget(robot_count(G))
    if cap is None or total <= cap:
        order = ((i, j) for i in range(t) for j in range(i + 1, t))
    else:
        order = sampled_pairs(t, cap)
    out, used = [], 0
    for i, j in order:
        if cap is not None and len(out) >= cap:
            break
        cost = G[i].n + G[j].n
        if budget is not None and used + cost > budget:
            continue
        used += cost
        out.append((i, j))
    return out, total


def select_triples(tp: int, limits: Limits | None = None) -> tuple[Iterable, int]:
    """``(triples, total)``: every triple of the tp polygons of G' when there are at most
    ``limits.claim_triples``, else every triple among the first and last m polygons
    (C(m, 3) at most the limit)."""
    limits = limits if limits is not None else DEFAULT_LIMITS
    total = tp * (tp - 1) * (tp - 2) // 6
    cap = limits.claim_triples
    if cap is None or total <= cap:
        return combinations(range(tp), 3), total
    m = 3
    while (m + 1) * m * (m - 1) // 6 <= cap:
        m += 1
    idx = list(range((m + 1) // 2)) + list(range(tp - m // 2, tp))
    return combinations(idx, 3), total


def union_lines(rings: Sequence[Ring]):
    """The lines of the projection of every polygon of ``rings`` onto the outermost
    circle (radial projection one after the other, nearest first): that polygon has one
    vertex on every ray holding a vertex of some polygon, and its lines depend on these
    rays only (:func:`mirror_lines` and :func:`centrally_symmetric` compare directions),
    so it is built once from the distinct rays (O(n log n), not O(t n)); equal to the
    chained projections (tested)."""
    polar = rings[0].polygon.polar
    seen: dict = {}
    for g in rings:
        for d, key in zip(g.polygon.directions, g.ray_keys):
            if key not in seen:
                seen[key] = d
    dirs = list(seen.values())
    if polar:
        dirs.sort()
    else:
        sort_by_angle(dirs)
    poly = CirclePolygon(tuple((k,) for k in range(len(dirs))), tuple(dirs), polar)
    ring = new_ring("G*", poly, rings[-1].radius_squared, (), (), ())
    return ring.lines, poly.n


class _Record:
    """What the statement checks found: the failures listed (at most ``examples`` per
    statement, then a count), the instances checked per statement (in first-checked
    order: the order of the summaries), the statements checked on a part only."""

    def __init__(self, trace: list, examples: int | None, screen: bool = False):
        self.trace, self.examples, self.screen = trace, examples, screen
        self.out: list[dict] = []
        self.failures: dict = {}
        self.within: dict = {}        # statement -> a failure within its hypotheses seen
        self.checked: dict = {}
        self.partial: set = set()

    def check(self, statement: str) -> None:
        self.checked[statement] = self.checked.get(statement, 0) + 1

    def fail(self, statement, polygons, detail, witness=None, within: bool = True) -> None:
        """Record a failure.  ``detail`` and ``witness`` may be functions returning them,
        called only when this failure is listed (the texts of lines of symmetry are
        megabytes in a field of degree thousands, and failures beyond ``examples`` are
        only counted); ``within``: whether it lies within the statement's hypotheses when
        the witness is given as a function (else read from the witness)."""
        self.failures[statement] = self.failures.get(statement, 0) + 1
        if callable(witness):
            inside = within
        else:
            inside = not (isinstance(witness, dict) and
                          witness.get("within_hypotheses") is False)
        self.within[statement] = self.within.get(statement, False) or inside
        if self.examples is None or self.failures[statement] <= self.examples:
            mark = SCREEN_ONLY.set(self.screen)
            try:
                if callable(detail):
                    detail = detail()
                if callable(witness):
                    witness = witness()
            finally:
                SCREEN_ONLY.reset(mark)
            self.out.append(_claim(self.trace, statement, False, polygons, detail, witness))

    def summaries(self) -> None:
        """One entry per statement failing more than ``examples`` times (the count), and
        one per statement that holds on every instance checked."""
        examples = self.examples
        for statement, count in self.failures.items():
            if examples is not None and count > examples:
                checked = self.checked.get(statement, count)
                self.out.append(_claim(self.trace, statement, False, [],
                                       f"fails on {count} of the {checked} instance(s) "
                                       f"checked; the first {examples} are listed",
                                       {"failures": count, "checked": checked,
                                        "listed": examples,
                                        "within_hypotheses": self.within[statement]}))
        for statement, count in self.checked.items():
            if statement not in self.failures:
                note = (" (a bounded part of the instances: see paper.bounded)"
                        if statement in self.partial else "")
                _claim(self.trace, statement, True, [],
                       f"holds on the {count} instance(s) checked" + note)


# ---------------------------------------------------------------- one function per statement
def obs_pair_asym_ord(rec: _Record, a: Ring, b: Ring, common) -> None:
    """``obs-pair-asym-ord``: an asymmetric polygon makes an asymmetric pair."""
    if not is_symmetric_polygon(a) or not is_symmetric_polygon(b):
        rec.check("obs-pair-asym-ord")
        if has_lines(common):
            rec.fail("obs-pair-asym-ord", [a.name, b.name],
                     "an asymmetric polygon in a symmetric pair")


#: named when a witness of obs-merg-asym-pair has a level of one or two robots
SMALL_LEVEL_READING = ("levels of 1 or 2 robots are polygons of G (the paper's G covers every "
                       "robot); if a polygon needs 3 vertices, this pair is outside the statement")


def obs_merg_asym_pair(rec: _Record, a: Ring, b: Ring, common, proj, polar: bool) -> None:
    """``obs-merg-asym-pair`` (as stated: no hypothesis on n_i, n_j): an asymmetric pair
    makes an asymmetric G_ij.  Reading: every level is a polygon of G, one or two robots
    included ("the t convex polygons whose union is the whole set of points"); a witness
    with such a level names that reading, since polygons of 3 or more vertices only would
    rescue the statement there (not everywhere: two triangles refute it, the ledger's
    witness)."""
    gij = proj.ring
    if not has_lines(common):
        rec.check("obs-merg-asym-pair")
        if is_symmetric_polygon(gij):
            small = min(a.n, b.n) < 3
            rec.fail("obs-merg-asym-pair", [a.name, b.name, gij.name],
                     lambda: f"<{a.name}, {b.name}> is an asymmetric pair but G_ij = "
                     f"{gij.name} has {lines_text(gij, polar)}" + coincidence_note(proj)
                     + (f"; reading: {SMALL_LEVEL_READING}" if small else ""),
                     lambda: {"G_ij lines": lines_text(gij, polar),
                              "lines": lines_data(gij, polar),
                              **({"reading": SMALL_LEVEL_READING} if small else {})})


def lem_los_gij(rec: _Record, a: Ring, b: Ring, common, proj, polar: bool) -> None:
    """``lem-los-gij`` (as stated): a line of symmetry of G_ij is a common line of
    <G_i, G_j>."""
    gij = proj.ring
    rec.check("lem-los-gij")
    if _some_line_not_in(gij.lines, common):
        # the text around lem-los-gij assumes n_i, n_j odd, neither dividing the other,
        # gcd > 1, a common line
        context = (is_odd(a) and is_odd(b) and gcd(a.n, b.n) > 1 and has_lines(common)
                   and a.n % b.n != 0 and b.n % a.n != 0)
        rec.fail("lem-los-gij", [a.name, b.name, gij.name],
                 lambda: f"G_ij = {gij.name} has {lines_text(gij, polar)}, but "
                 f"<{a.name}, {b.name}> have {lines_text(common, polar)} in common"
                 + coincidence_note(proj)
                 + ("" if context else " (outside the hypotheses of the surrounding text: "
                    "n_i, n_j odd, neither dividing the other, gcd > 1, a common line)"),
                 lambda: {"line": _lines_not_in(gij.lines, common), "n_i": a.n, "n_j": b.n,
                          "within_hypotheses": context,
                          "coincident_vertices": len(proj.coincident)},
                 within=bool(context))


def obs_gcd(rec: _Record, a: Ring, b: Ring, common) -> None:
    """``obs-gcd``: two odd polygons with a common line have gcd(n_i, n_j) common lines
    (called only on pairs meeting these hypotheses: ``within_hypotheses`` True)."""
    g = gcd(a.n, b.n)
    count = "all" if common is ALL_LINES else len(common)
    rec.check("obs-gcd")
    if count != g:
        rec.fail("obs-gcd", [a.name, b.name], f"n_i = {a.n}, n_j = {b.n} odd with a common "
                 f"line: gcd = {g} but they have {count} common line(s)",
                 {"gcd": g, "common_lines": count, "within_hypotheses": True})


def obs_type_4(rec: _Record, a: Ring, b: Ring, proj) -> None:
    """``obs-type-4``: n_i, n_j odd with a common line and gcd > 1 make G_ij type 4
    (called only on pairs meeting these hypotheses: ``within_hypotheses`` True; whether
    n_i and n_j divide one another is Preprocess's condition, recorded separately)."""
    gij = proj.ring
    g = gcd(a.n, b.n)
    ok, why = is_type4(gij)
    rec.check("obs-type-4")
    if not ok:
        neither = a.n % b.n != 0 and b.n % a.n != 0
        rec.fail("obs-type-4", [a.name, b.name, gij.name],
                 f"n_i = {a.n}, n_j = {b.n} odd, a common line, gcd = {g} > 1, but "
                 f"G_ij ({gij.n} vertices) is {why}" + coincidence_note(proj)
                 + ("" if neither else "; note n_i and n_j divide one another "
                    "(Preprocess's text excludes that case)"),
                 {"G_ij vertices": gij.n, "type": why, "neither_divides": neither,
                  "coincident_vertices": len(proj.coincident), "within_hypotheses": True})


def theorem_los_g1n(rec: _Record, G: Sequence[Ring], Gp: Sequence[Ring], polar: bool,
                    limits: Limits) -> None:
    """``theorem-los-g1n`` on the projection of every polygon onto the outermost circle
    (within ``limits.union_vertices``), and on every merged polygon of G'."""
    with_dir = [g for g in G if not g.at_centre]
    if len(with_dir) >= 2 and limits.union_vertices is not None and \
            sum(g.n for g in with_dir) > limits.union_vertices:
        rec.partial.add("theorem-los-g1n")
    elif len(with_dir) >= 2:
        whole_lines, whole_n = union_lines(with_dir)
        whole_name = polygon_name([k for g in with_dir for k in g.levels])
        common = common_lines(with_dir)
        rec.check("theorem-los-g1n")
        extra = _lines_not_in(whole_lines, common)
        if extra:
            rec.fail("theorem-los-g1n", few_names(with_dir) + [whole_name],
                     f"G_(1..n) = {whole_name} (every polygon projected onto the outermost "
                     f"circle) has {lines_text(whole_lines, polar)}, but the polygons have "
                     f"{lines_text(common, polar)} in common",
                     {"line": extra, "within_hypotheses": False})
    by_level = None         # built for the first merged polygon (none on random input)
    for g in Gp:
        if len(g.levels) > 1:
            if by_level is None:
                by_level = {g.levels[0]: g for g in G}
            parts = [by_level[k] for k in g.levels]
            common = common_lines(parts)
            rec.check("theorem-los-g1n")
            extra = _lines_not_in(g.lines, common)
            if extra:
                rec.fail("theorem-los-g1n", few_names(parts) + [g.name],
                         f"the merged polygon {g.name} of G' has {lines_text(g, polar)}, but "
                         f"its parts have {lines_text(common, polar)} in common",
                         {"line": extra, "within_hypotheses": True})


def lem_3_pair_sym(rec: _Record, trio) -> None:
    """``lem-3-pair-sym`` (one direction): three pairwise symmetric polygons of G' have a
    common line of symmetry (called on pairwise symmetric triples)."""
    rec.check("lem-3-pair-sym")
    if not is_symmetric_family(trio):
        rec.fail("lem-3-pair-sym", [g.name for g in trio],
                 "pairwise symmetric without a common line")


def lem_type4(rec: _Record, trio) -> None:
    """``lem-type4``: three pairwise symmetric odd polygons of G' with distinct counts,
    none a multiple of another, have pairwise coprime counts."""
    counts = [g.n for g in trio]
    if all(is_odd(g) for g in trio) and len(set(counts)) == 3 and not any(
            x % y == 0 for x in counts for y in counts if x != y):
        rec.check("lem-type4")
        if any(gcd(x, y) > 1 for x in counts for y in counts if x != y):
            rec.fail("lem-type4", [g.name for g in trio], f"pairwise symmetric with n = "
                     f"{counts}, not pairwise coprime", {"n": counts})


def theorem_sym_pair_symG(rec: _Record, Gp: Sequence[Ring], symmetric_p: bool,
                          steps: int | None) -> None:
    """``theorem-sym-pair-symG``: every pair of G' is symmetric iff all polygons of G'
    have a common line (within the search budget ``steps``)."""
    try:
        all_pairs_sym = find_asymmetry_pair(Gp, steps) is None
    except WorkBudgetExceeded:
        all_pairs_sym = None
        rec.partial.add("theorem-sym-pair-symG")
    if len(Gp) >= 2 and all_pairs_sym is not None:   # one polygon: "every pair" is vacuous
        rec.checked["theorem-sym-pair-symG"] = 1
        if all_pairs_sym != symmetric_p:
            rec.fail("theorem-sym-pair-symG", few_names(Gp),
                     f"every pair of G' symmetric: {all_pairs_sym}; a common line for all: "
                     f"{symmetric_p}")


def obs1_Gprime_equiG(rec: _Record, G: Sequence[Ring], Gp: Sequence[Ring]) -> None:
    """``obs1-Gprime-equiG``: in a symmetric G (and G') every pair is symmetric."""
    for label, fam in (("G", G), ("G'", Gp)):
        if is_symmetric_family(fam):
            rec.check("obs1-Gprime-equiG")
            bad = find_asymmetry_pair(fam)    # None at once: the common line is shared
            if bad is not None:
                rec.fail("obs1-Gprime-equiG", [fam[bad[0]].name, fam[bad[1]].name],
                         f"{label} is symmetric but this pair is not")


def Gprime_equiG(rec: _Record, Gp: Sequence[Ring], symmetric_g: bool,
                 symmetric_p: bool) -> None:
    """``Gprime-equiG``: G is symmetric iff G' is."""
    rec.checked["Gprime-equiG"] = 1
    if symmetric_p != symmetric_g:
        rec.fail("Gprime-equiG", few_names(Gp), f"G symmetric: {symmetric_g}; G' "
                 f"symmetric: {symmetric_p}")


# ---------------------------------------------------------------- all of them
def family_claims(G: Sequence[Ring], Gp: Sequence[Ring], trace: list | None = None,
                  polar: bool = True, limits: Limits | None = None,
                  stats: dict | None = None) -> list[dict]:
    """Evaluate, with the paper's own notions (exact), the family statements of Section 3
    on G and G' and record each failure (``holds`` False, with a witness) and one
    summary per statement that holds.  Claims about orderability need the truth and are
    the audit's (``lem-sym-notord``, ``lem-asym-pair-ord``, ...).

    Bounded by ``limits`` (:class:`Limits`; :data:`UNBOUNDED` checks everything): pair
    statements on :func:`select_pairs`, triple statements on :func:`select_triples`,
    ``theorem-los-g1n`` on the projection of every polygon within the vertex budget,
    ``theorem-sym-pair-symG`` within the search budget.  A statement failing on more than
    ``limits.claim_examples`` instances records that many and then one entry with the
    count.  ``stats`` (a dict) receives what was checked: ``pairs_checked``, ``pairs``,
    ``triples_checked``, ``triples``, ``partial`` (the statements not checked on every
    instance), ``failures`` (per statement)."""
    limits = limits if limits is not None else DEFAULT_LIMITS
    trace = trace if trace is not None else []
    stats = stats if stats is not None else {}
    rec = _Record(trace, limits.claim_examples, limits.screen_texts)
    n_robots = robot_count(G)
    pairs, total_pairs = select_pairs(G, limits)
    if len(pairs) < total_pairs:
        rec.partial.update(("obs-pair-asym-ord", "obs-merg-asym-pair", "lem-los-gij",
                            "obs-gcd", "obs-type-4"))
    for i, j in pairs:
        a, b = G[i], G[j]
        common = intersect_lines(a.lines, b.lines)
        obs_pair_asym_ord(rec, a, b, common)
        if a.at_centre or b.at_centre:
            continue
        proj = radial_projection(a, b)
        obs_merg_asym_pair(rec, a, b, common, proj, polar)
        lem_los_gij(rec, a, b, common, proj, polar)
        if is_odd(a) and is_odd(b) and has_lines(common):
            obs_gcd(rec, a, b, common)
            if gcd(a.n, b.n) > 1:
                obs_type_4(rec, a, b, proj)
    theorem_los_g1n(rec, G, Gp, polar, limits)
    triples, total_triples = select_triples(len(Gp), limits)
    triples_checked = 0
    for i, j, k in triples:
        triples_checked += 1
        trio = (Gp[i], Gp[j], Gp[k])
        if all(is_symmetric_pair(x, y) for x, y in ((trio[0], trio[1]), (trio[1], trio[2]),
                                                    (trio[0], trio[2]))):
            lem_3_pair_sym(rec, trio)
            lem_type4(rec, trio)
    if triples_checked < total_triples:
        rec.partial.update(("lem-3-pair-sym", "lem-type4"))
    symmetric_p = is_symmetric_family(Gp)
    symmetric_g = is_symmetric_family(G)
    theorem_sym_pair_symG(rec, Gp, symmetric_p, limits.step_budget(n_robots))
    obs1_Gprime_equiG(rec, G, Gp)
    Gprime_equiG(rec, Gp, symmetric_g, symmetric_p)
    rec.summaries()
    stats.update(pairs_checked=len(pairs), pairs=total_pairs,
                 triples_checked=triples_checked, triples=total_triples,
                 partial=sorted(rec.partial), failures=dict(sorted(rec.failures.items())))
    return rec.out


def _some_line_not_in(lines, allowed) -> bool:
    """Whether :func:`_lines_not_in` finds a line (without writing its text)."""
    if allowed is ALL_LINES:
        return False
    return lines is ALL_LINES or any(k not in allowed for k in lines)


def _lines_not_in(lines, allowed):
    """A line of ``lines`` that is not in ``allowed`` (as text), or None."""
    if allowed is ALL_LINES:
        return None
    if lines is ALL_LINES:
        return "every line through C (skew symmetric)"
    extra = [k for k in lines if k not in allowed]
    if not extra:
        return None
    return line_text(first_shown(extra))
