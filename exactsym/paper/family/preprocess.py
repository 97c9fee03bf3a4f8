"""``Preprocess`` (Section 4.2): merge pairs of odd polygons whose G_ij is of type 4.

:func:`preprocess` is the evident reading with an exact prefilter (G_ij built only when it
can be type 4), :func:`preprocess_literal` the printed loop (it never ends once an odd
polygon is reached: detected exactly), ``_preprocess_unfiltered`` the faithful reference
without prefilter (tested equal).  Preprocess is long because the scan, its trace and the
prefilter's index are one algorithm; it is kept in one module.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Sequence

from .concentric import Ring, is_odd, robot_count
from .limits import DEFAULT_LIMITS, Limits, WorkBudgetExceeded
from .projection import (coincidence_note, could_be_type4, is_type4, radial_projection,
                         radius_less)
from .trace import trace_entry


#: Work steps charged for building one vertex of a G_ij and typing it (the polygon's
#: strings and lines cost about a hundred index steps per vertex).
BUILD_COST = 100


class _Type4Pairs:
    """Preprocess's test "G_ij is a type 4 polygon" on pairs of odd polygons, with an
    *exact* prefilter (``docs/interpretations.md``, "Bounds of the family layer").

    G_ij (the inner one projected onto the outer one's circle) has n_i + n_j - s
    vertices, s the number of rays holding a vertex of both (``radial_projection`` merges
    them): for two odd polygons that count is odd iff s is odd, and a type 4 polygon has
    an odd composite number of vertices.  So G_ij is built only for the pairs that share
    an odd number of rays and leave an odd composite count; every other pair is rejected
    without building it, exactly as the faithful loop would reject it.  Shared rays are
    counted with an index from exact ray keys (the rational turn, or the ray key of the
    vector) to the odd polygons on that ray; a polygon is indexed only when some other
    odd polygon is large enough to make 9 vertices with it (n + max n >= 10), so
    configurations of small polygons cost nothing.  Verdicts of pairs built are kept by
    identity (the polygons are immutable and kept alive here), so later passes and the
    literal loop do not rebuild them.  ``budget``: index steps plus vertices of G_ij built
    (None: unbounded); exceeding it raises :class:`WorkBudgetExceeded`."""

    def __init__(self, budget: int | None):
        self.budget = budget
        self.steps = 0
        self.built = 0
        self.memo: dict = {}
        self.index: dict = {}
        self.indexed: dict = {}
        self.max_n = 0
        self.any_pair = False
        self.ray_sets: dict = {}
        self.by_rays: dict = {}

    def spend(self, k: int) -> None:
        self.steps += k
        if self.budget is not None and self.steps > self.budget:
            raise WorkBudgetExceeded(f"more than {self.budget} steps")

    def reset(self, G) -> None:
        odd = [g for g in G if g.n % 2 == 1 and g.polygon is not None]
        sizes = sorted((g.n for g in odd), reverse=True)[:2]
        self.max_n = sizes[0] if sizes else 0
        self.any_pair = len(sizes) == 2 and sizes[0] + sizes[1] >= 10
        if not self.any_pair:
            return
        for g in odd:
            self.add(g)

    def possible(self, G) -> bool:
        """Whether two odd polygons of G can make a G_ij of 9 or more vertices (only then
        can a scan build anything: n_i + n_j - s >= 9 with s >= 1)."""
        return self.any_pair

    def add(self, ring: Ring) -> None:
        if id(ring) in self.indexed or ring.n + self.max_n < 10:
            return
        self.indexed[id(ring)] = ring
        keys = ring.ray_keys
        self.spend(len(keys))
        for k in keys:
            self.index.setdefault(k, {})[id(ring)] = ring

    def remove(self, ring: Ring) -> None:
        if self.indexed.pop(id(ring), None) is None:
            return
        for k in ring.ray_keys:
            bucket = self.index.get(k)
            if bucket is not None:
                bucket.pop(id(ring), None)
                if not bucket:
                    del self.index[k]

    def replaced(self, old: Sequence[Ring], new: Ring, G) -> None:
        """``old`` left G and ``new`` (odd) entered it."""
        if not self.any_pair:
            raise AssertionError("no merge is possible without a candidate pair")
        for ring in old:
            self.remove(ring)
        if new.n > self.max_n:
            before, self.max_n = self.max_n, new.n
            if before < 9:              # smaller polygons may have become eligible
                self.spend(len(G))
                for g in G:
                    if is_odd(g):
                        self.add(g)
        self.add(new)

    def shared(self, gi: Ring) -> dict:
        """``{id(gj): s}`` for the indexed odd polygons gj != gi sharing s >= 1 rays with gi."""
        counts: dict = {}
        if id(gi) not in self.indexed:
            return counts
        keys = gi.ray_keys
        self.spend(len(keys))
        index = self.index
        for k in keys:
            bucket = index.get(k)
            if bucket is None or len(bucket) == 1:
                continue
            self.spend(len(bucket))
            for rid in bucket:
                counts[rid] = counts.get(rid, 0) + 1
        counts.pop(id(gi), None)
        return counts

    def candidates(self, gi: Ring, counts: dict) -> list:
        """The polygons whose G_ij may be type 4, in the order of G (nearest first)."""
        indexed, n_i = self.indexed, gi.n
        out = [indexed[rid] for rid, s in counts.items()
               if s % 2 == 1 and could_be_type4(n_i + indexed[rid].n - s)]
        out.sort(key=lambda g: g.levels[-1])
        return out

    def _ray_set(self, ring: Ring):
        rid = id(ring)
        got = self.ray_sets.get(rid)
        if got is None:
            self.spend(ring.n)
            got = self.ray_sets[rid] = (ring, frozenset(ring.ray_keys))
        return got[1]

    def verdict(self, gi: Ring, gj: Ring):
        """``(is type 4, projection or None, text)`` for G_ij, built at most once per pair.
        On the polar path G_ij's vertices are the union of the two sets of rational turns
        and its type depends on them only, so a pair of ray sets already found not type 4
        is rejected without building G_ij again (many aligned polygons cost one build)."""
        inner, outer = (gi, gj) if radius_less(gi, gj) else (gj, gi)
        key = (id(inner), id(outer))
        hit = self.memo.get(key)
        if hit is None:
            shape = None
            if outer.polygon.polar and inner.polygon.polar:
                shape = (self._ray_set(inner), self._ray_set(outer))
                known = self.by_rays.get(shape)
                if known is not None and not known[0]:
                    hit = self.memo[key] = (inner, outer, False, None, known[1])
                    return hit[2], hit[3], hit[4]
            self.spend(BUILD_COST * (gi.n + gj.n))
            proj = radial_projection(inner, outer)
            ok, why = is_type4(proj.ring)
            hit = self.memo[key] = (inner, outer, ok, proj, why)
            if shape is not None:
                self.by_rays[shape] = (ok, why)
            self.built += 1
        return hit[2], hit[3], hit[4]


def _built_size(gi: Ring, gj: Ring, proj, counts: dict) -> int:
    return proj.ring.n if proj is not None else gi.n + gj.n - counts.get(id(gj), 0)


def _prefilter_text(gi: Ring, gj: Ring, counts: dict) -> str:
    """Why the pair is rejected without building G_ij."""
    if gi.n + gj.n < 9:
        return f"{gj.name} (at most {gi.n + gj.n} vertices)"
    m = gi.n + gj.n - counts.get(id(gj), 0)
    what = "even" if m % 2 == 0 else ("below 9" if m < 9 else "prime")
    return f"{gj.name} ({m} vertices: {what}, not type 4; G_ij not built)"


#: Preprocess lists the polygons it passes over by name when G has at most this many.
SMALL_FAMILY = 64


def preprocess(G: Sequence[Ring], trace: list | None = None, limits: Limits | None = None,
               stats: dict | None = None, prefilter: bool = True) -> tuple:
    """``Preprocess`` (Section 4.2), evident reading: for each G_i with an odd number of
    vertices, scan j = 1..t for G_j (j != i) with an odd number of vertices whose G_ij
    (the inner one projected onto the outer one's circle) is a type 4 polygon; replace
    *both* G_i and G_j by G_ij (the text before ``lem-los-gij``: "replace both G_i and
    G_j by G_ij"), placed at the outer one's level, and rescan j with the merged polygon
    as G_i; after the scan i++ (also for odd G_i).  Passes are repeated until none
    merges ("We repeat this process of merging polygons until ...").  The robot at C is
    not a polygon with a direction and is skipped.  Returns G'.

    The scan builds G_ij only for the pairs :class:`_Type4Pairs` cannot reject exactly
    (``prefilter=False`` runs the unfiltered loop, which builds every G_ij of two odd
    polygons with n_i + n_j >= 9: the same G').  ``limits``: the work budget
    (``search_steps``) and the number of polygons whose scan gets trace entries of its
    own (the rest are counted in one entry).  ``stats`` (a dict) receives
    ``complete`` (False when the budget stopped the scan: G' then holds the merges made
    so far), ``pairs_built``, ``steps``, ``passes``."""
    if not prefilter:
        return _preprocess_unfiltered(G, trace)
    limits = limits if limits is not None else DEFAULT_LIMITS
    trace = trace if trace is not None else []
    stats = stats if stats is not None else {}
    G = list(G)
    n_robots = robot_count(G)
    pairs = _Type4Pairs(limits.step_budget(n_robots))
    detail_left = [limits.preprocess_entries]
    omitted: dict = {}

    def bulk(line, polygons, detail, branch):
        if detail_left[0] is not None and detail_left[0] <= 0:
            omitted[branch] = omitted.get(branch, 0) + 1
            return
        trace_entry(trace, "Preprocess", line, polygons, "Preprocess", detail, branch=branch)

    def scanned():
        if detail_left[0] is not None:
            detail_left[0] -= 1

    passes, complete = 0, True
    try:
        pairs.reset(G)
        if not pairs.possible(G):
            # no two odd polygons make 9 vertices: every scan rejects every G_j without
            # building G_ij (the loop below would say so polygon by polygon)
            passes = 1
            for gi in G:
                if detail_left[0] is not None and detail_left[0] <= 0:
                    branch = "skip-centre" if gi.at_centre else (
                        "skip-i-even" if not is_odd(gi) else "odd-pair-not-type4")
                    omitted[branch] = omitted.get(branch, 0) + 1
                    continue
                if gi.at_centre:
                    bulk(3, [gi.name], "the robot at C has no direction: not projected, "
                         "skipped", "skip-centre")
                elif not is_odd(gi):
                    bulk(12, [gi.name], f"{gi.name} has {gi.n} (even) vertices: i++",
                         "skip-i-even")
                else:
                    _scan_entries(bulk, G if len(G) <= SMALL_FAMILY else None, gi, None, {},
                                  {})
                scanned()
        merged_any = pairs.possible(G)
        while merged_any:
            merged_any = False
            passes += 1
            i = 0
            while i < len(G):
                gi = G[i]
                pairs.spend(1)
                if gi.at_centre:
                    bulk(3, [gi.name], "the robot at C has no direction: not projected, "
                         "skipped", "skip-centre")
                    scanned()
                    i += 1
                    continue
                if not is_odd(gi):
                    bulk(12, [gi.name], f"{gi.name} has {gi.n} (even) vertices: i++",
                         "skip-i-even")
                    scanned()
                    i += 1
                    continue
                restart = True
                while restart:
                    restart = False
                    counts = pairs.shared(gi)
                    found, built = None, {}
                    for gj in pairs.candidates(gi, counts):
                        ok, proj, why = pairs.verdict(gi, gj)
                        if ok:
                            found = (gj, proj, why)
                            break
                        built[id(gj)] = (proj, why)
                    # the order the scan saw (for the listing of a small family)
                    before = G[:] if len(G) <= SMALL_FAMILY else None
                    if found is not None:
                        gj, proj, why = found
                        new = proj.ring
                        inner, outer = (gi, gj) if radius_less(gi, gj) else (gj, gi)
                        trace_entry(trace, "Preprocess", 9, [gi.name, gj.name, new.name],
                                    "obs-type-4",
                                    f"G_ij = {new.name} ({new.n} vertices) is {why}: replace "
                                    f"{gi.name} and {gj.name} by it (on the circle of {outer.name})"
                                    + coincidence_note(proj), branch="odd-merge-type4")
                        pairs.spend(2 * len(G))
                        G[index_of(G, outer)] = new
                        G.pop(index_of(G, inner))
                        pairs.replaced((gi, gj), new, G)
                        old_gi, gi = gi, new
                        i = index_of(G, new)
                        merged_any = True
                        restart = True
                    else:
                        old_gi = gi
                    if detail_left[0] is None or detail_left[0] > 0:
                        _scan_entries(bulk, before, old_gi, found, built, counts)
                    else:
                        omitted["odd-pair-not-type4"] = omitted.get("odd-pair-not-type4", 0) + 1
                scanned()
                i += 1
    except WorkBudgetExceeded as err:
        complete = False
        trace_entry(trace, "Preprocess", None, [g.name for g in G[:8]], "Preprocess",
                    f"Preprocess stopped: its pair scan exceeded the work budget ({err}); G' "
                    f"below holds the merges made so far, and the procedure is reported as not "
                    f"carried out exactly", branch=None, kind="budget")
    if omitted:
        trace_entry(trace, "Preprocess", None, [], "Preprocess",
                    f"{sum(omitted.values())} further entries of the scan omitted ("
                    + ", ".join(f"{v} {k}" for k, v in sorted(omitted.items())) + ")",
                    omitted=dict(sorted(omitted.items())))
    stats.update(complete=complete, pairs_built=pairs.built, steps=pairs.steps,
                 passes=passes)
    return tuple(G)


def _scan_entries(bulk, G: list | None, gi: Ring, found, built: dict, counts: dict) -> None:
    """The trace entries of one scan of j for G_i: the G_j rejected (lines 8, 10) and the
    G_j passed over (even, or j = i: line 11), up to the partner when one was found;
    listed by name when ``G`` (the family as the scan saw it) is given, else counted."""
    stop = found[0] if found is not None else None
    if G is not None:
        skipped, rejected = [], []
        for gj in G:
            if gj is stop:
                break
            if gj is gi or not is_odd(gj):
                skipped.append(gj.name)
            elif id(gj) in built:
                proj, why = built[id(gj)]
                rejected.append(f"{gj.name} ({_built_size(gi, gj, proj, counts)} vertices, "
                                f"{why}" + (coincidence_note(proj) if proj else "") + ")")
            else:
                rejected.append(_prefilter_text(gi, gj, counts))
        if rejected:
            bulk(10, [gi.name], "G_ij is not type 4 for G_j = " + "; ".join(rejected[:12])
                 + (f"; ... ({len(rejected)} in all)" if len(rejected) > 12 else "")
                 + ": j++", "odd-pair-not-type4")
        if skipped:
            bulk(11, [gi.name], f"j = i or G_j even: j++ past {', '.join(skipped[:12])}"
                 + (f", ... ({len(skipped)} in all)" if len(skipped) > 12 else ""),
                 "skip-j-even-or-same")
        return
    shown = [f"{proj.ring.name} ({proj.ring.n} vertices, {why})" if proj is not None else
             f"a G_ij with the rays of one built before ({why})"
             for proj, why in list(built.values())[:6]]
    bulk(10, [gi.name], "G_ij is not type 4 for the odd G_j "
         + ("before " + stop.name if stop is not None else "scanned")
         + (": built and rejected " + "; ".join(shown) if shown else "")
         + "; every other odd G_j is rejected without building G_ij (n_i + n_j - shared "
         "rays is even, prime or below 9): j++", "odd-pair-not-type4")
    bulk(11, [gi.name], "j = i or G_j even: j++ past them", "skip-j-even-or-same")


def _preprocess_unfiltered(G: Sequence[Ring], trace: list | None = None) -> tuple:
    """The faithful loop without the prefilter: G_ij is built for every pair of odd
    polygons with n_i + n_j >= 9 (the reference the prefiltered :func:`preprocess` is
    tested against; quadratic in t)."""
    trace = trace if trace is not None else []
    G = list(G)
    passes, merged_any = 0, True
    while merged_any:
        merged_any = False
        passes += 1
        i = 0
        while i < len(G):
            gi = G[i]
            if gi.at_centre:
                trace_entry(trace, "Preprocess", 3, [gi.name], "Preprocess",
                            "the robot at C has no direction: not projected, skipped",
                            branch="skip-centre")
                i += 1
                continue
            if not is_odd(gi):
                trace_entry(trace, "Preprocess", 12, [gi.name], "Preprocess",
                            f"{gi.name} has {gi.n} (even) vertices: i++", branch="skip-i-even")
                i += 1
                continue
            restart = True
            while restart:
                restart = False
                skipped, rejected = [], []
                for j, gj in enumerate(G):
                    if j == i or not is_odd(gj):
                        skipped.append(gj.name)
                        continue
                    if gi.n + gj.n < 9:
                        # a type 4 polygon is odd, composite and not regular: n >= 9
                        rejected.append(f"{gj.name} (at most {gi.n + gj.n} vertices)")
                        continue
                    inner, outer = (gi, gj) if radius_less(gi, gj) else (gj, gi)
                    proj = radial_projection(inner, outer)
                    ok, why = is_type4(proj.ring)
                    if ok:
                        new = proj.ring
                        trace_entry(trace, "Preprocess", 9, [gi.name, gj.name, new.name],
                                    "obs-type-4",
                                    f"G_ij = {new.name} ({new.n} vertices) is {why}: replace "
                                    f"{gi.name} and {gj.name} by it (on the circle of {outer.name})"
                                    + coincidence_note(proj), branch="odd-merge-type4")
                        G[index_of(G, outer)] = new
                        G.pop(index_of(G, inner))
                        gi = new
                        i = index_of(G, new)
                        merged_any = True
                        restart = True
                        break
                    rejected.append(f"{gj.name} ({proj.ring.n} vertices, {why}"
                                    + coincidence_note(proj) + ")")
                if rejected:
                    trace_entry(trace, "Preprocess", 10, [gi.name], "Preprocess",
                                "G_ij is not type 4 for G_j = " + "; ".join(rejected[:12])
                                + (f"; ... ({len(rejected)} in all)" if len(rejected) > 12 else "")
                                + ": j++", branch="odd-pair-not-type4")
                if skipped:
                    trace_entry(trace, "Preprocess", 11, [gi.name], "Preprocess",
                                f"j = i or G_j even: j++ past {', '.join(skipped[:12])}"
                                + (f", ... ({len(skipped)} in all)" if len(skipped) > 12 else ""),
                                branch="skip-j-even-or-same")
            i += 1
    return tuple(G)


def index_of(G: list, ring: Ring) -> int:
    return next(k for k, g in enumerate(G) if g is ring)


@dataclass(frozen=True)
class LiteralRun:
    """The printed Preprocess loop run as printed: ``terminated`` False when a state
    (i, j, G) repeated (proof of non-termination) or ``max_steps`` passed."""
    terminated: bool
    steps: int
    reason: str
    result: tuple
    budget_exceeded: bool = False


def preprocess_literal(G: Sequence[Ring], max_steps: int | None = None,
                       limits: Limits | None = None, fast_off: bool = False) -> LiteralRun:
    """``Preprocess`` exactly as printed::

        i = 1; while i <= t: if G_i odd: j = 1; while j <= t:
            if j != i & G_j odd: compute G_ij; if type 4: replace G_i by G_ij else j++
            else j++
        else i++

    After a replacement j is not incremented (and G_j stays), and i is never
    incremented for an odd G_i, so the loop never ends once an odd polygon is reached
    (the state (i, j, G) repeats: detected exactly) -- a finding.

    "G_ij is type 4" uses the exact prefilter of :func:`preprocess` (G_ij is built only
    when it can be type 4).  A state is (i, j, the version of G): G changes only by a
    replacement, and each content of G (the levels, robots and size of each polygon, in
    order) gets one version number, so a repeated state is still detected exactly while
    a state costs O(1) (not O(t)).  When no two odd polygons can make a G_ij of 9
    vertices, the run is counted without stepping through it (``fast_off`` steps through
    it; the same result, tested).  Over the work budget of ``limits`` the run stops
    (``terminated`` False, the reason says so)."""
    limits = limits if limits is not None else DEFAULT_LIMITS
    G = list(G)
    t = len(G)
    max_steps = max_steps if max_steps is not None else 20 * (t + 2) ** 2
    pairs = _Type4Pairs(limits.step_budget(robot_count(G)))
    versions: dict = {}

    def version() -> int:
        pairs.spend(t)
        return versions.setdefault(tuple((g.levels, g.robots, g.n) for g in G), len(versions))

    seen = set()
    i, j, steps = 1, None, 0
    candidates: dict = {}
    try:
        pairs.reset(G)
        if not pairs.possible(G) and not fast_off:
            # no G_ij can be type 4: the loop passes the polygons before the first odd
            # one (one step each), then sweeps j = 1..t (t steps), ends the inner loop
            # (one step) and re-enters it in the state it started from (one step)
            first = next((k for k, g in enumerate(G, 1) if not g.at_centre and is_odd(g)),
                         None)
            if first is None:
                return LiteralRun(True, t, "terminated", tuple(G))
            steps = first - 1 + t + 2
            return LiteralRun(False, steps, f"the state (i={first}, j=1, G) repeats after "
                              f"{steps} steps: the printed loop never ends", tuple(G))
        current = version()
        while i <= t:
            steps += 1
            if steps > max_steps:
                return LiteralRun(False, steps, f"no end within {max_steps} steps", tuple(G))
            gi = G[i - 1]
            if gi.at_centre or not is_odd(gi):
                i += 1
                continue
            if j is None:
                j = 1
            state = (i, j, current)
            if state in seen:
                return LiteralRun(False, steps, f"the state (i={i}, j={j}, G) repeats after "
                                  f"{steps} steps: the printed loop never ends", tuple(G))
            seen.add(state)
            if j > t:
                j = None       # the inner loop ended; the outer loop re-enters with the same i
                continue
            gj = G[j - 1]
            if j != i and is_odd(gj):
                cands = candidates.get(id(gi))
                if cands is None:
                    cands = candidates[id(gi)] = (gi, {id(g) for g in pairs.candidates(
                        gi, pairs.shared(gi))})
                if id(gj) in cands[1]:
                    ok, proj, _ = pairs.verdict(gi, gj)
                    if ok:
                        G[i - 1] = proj.ring    # "Replace G_i by G_ij"; j is not incremented
                        pairs.replaced((gi,), proj.ring, G)
                        current = version()
                        continue
            j += 1
    except WorkBudgetExceeded as err:
        return LiteralRun(False, steps, f"not run to its end: the work budget was exceeded "
                          f"({err})", tuple(G), True)
    return LiteralRun(True, steps, "terminated", tuple(G))
