"""The paper on whole configurations (exactsym.paper.family) and the audit (exactsym.audit.statements).

Exact expected values on small families, agreement of the O(n) line finder with the
definition (exactsym.paper.polygon.definition_mirrors), the branches of MakeAsym,
ElectLeader and Preprocess reached by the case library, the ``exactsym audit`` command.
The case files themselves are run by tests/test_cases.py.
"""

from __future__ import annotations

import json
import subprocess
import sys
from fractions import Fraction
from pathlib import Path

import pytest
from hypothesis import event, given, settings, strategies as st

from exactsym.audit.levels import LEVEL_STATEMENTS
from exactsym.audit.statements import audit, transformed
from exactsym.geometry.configuration import load
from exactsym.exact import fmpq
from exactsym.geometry.levels import levels_of
from exactsym.paper import family as F
from exactsym.paper.keys import hashable_key
from exactsym.paper import polygon as P
from exactsym.paper.circle_polygon import polygon_from_directions

from strategies import polar_configuration

ROOT = Path(__file__).resolve().parents[2]
FAMILY = ROOT / "cases" / "family"
DISCREPANCIES = ROOT / "cases" / "discrepancies"
Q = fmpq


def regular(r, k, rot=Fraction(0)):
    return [(Fraction(r), (Fraction(rot) + Fraction(j, k)) % 1) for j in range(k)]


def ring(r, turns):
    return [(Fraction(r), Fraction(t) % 1) for t in turns]


def family_of(points):
    config = polar_configuration(points)
    return config, levels_of(config), F.concentric_polygons(config)


def keys(lines):
    return {k.h for k in lines}


# ---------------------------------------------------------------- lines of symmetry
def polar_polygon(turns):
    return polygon_from_directions(range(len(turns)), [Q(t.numerator, t.denominator)
                                                        for t in turns], True)


turn_sets = st.lists(st.fractions(0, 1, max_denominator=24).map(lambda t: t % 1),
                     min_size=1, max_size=9, unique=True)


def symmetric_turn_sets():
    """Orbits of a few seeds under C_k or D_k (so that mirrors and half-turns are common)."""
    return st.tuples(st.integers(1, 6), st.booleans(),
                     st.lists(st.fractions(0, 1, max_denominator=24), min_size=1, max_size=3),
                     st.fractions(0, 1, max_denominator=30)).map(
        lambda a: sorted({(s * sign + Fraction(j, a[0]) + a[3]) % 1 for s in a[2]
                          for j in range(a[0]) for sign in ((1, -1) if a[1] else (1,))}))


@settings(max_examples=150, deadline=None)
@given(st.one_of(turn_sets, symmetric_turn_sets()))
def test_mirror_lines_are_the_definitions_mirrors_polar(turns):
    poly = polar_polygon(turns)
    assert keys(F.mirror_lines(poly)) == {hashable_key(k) for k in P.definition_mirrors(poly)}
    assert F.centrally_symmetric(poly) == P.is_skew_symmetric(poly)


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(st.integers(-6, 6), st.integers(-6, 6)).filter(lambda p: p != (0, 0)),
                min_size=1, max_size=6, unique=True), st.sampled_from([None, "C2", "C4", "D1"]))
def test_mirror_lines_are_the_definitions_mirrors_cartesian(seeds, group):
    """Directions of different lengths (only directions matter), rational coordinates."""
    maps = {None: [(1, 0, 0, 1)], "C2": [(1, 0, 0, 1), (-1, 0, 0, -1)],
            "C4": [(1, 0, 0, 1), (0, -1, 1, 0), (-1, 0, 0, -1), (0, 1, -1, 0)],
            "D1": [(1, 0, 0, 1), (1, 0, 0, -1)]}[group]
    dirs = {}
    for x, y in seeds:
        for a, b, c, d in maps:
            v = (Q(a * x + b * y), Q(c * x + d * y))
            ray = (v[0] / (abs(v[0]) + abs(v[1])), v[1] / (abs(v[0]) + abs(v[1])))
            dirs.setdefault(ray, v)
    poly = polygon_from_directions(range(len(dirs)), list(dirs.values()), False)
    assert keys(F.mirror_lines(poly)) == {hashable_key(k) for k in P.definition_mirrors(poly)}
    assert F.centrally_symmetric(poly) == P.is_skew_symmetric(poly)


def test_lines_exact_values():
    _, _, G = family_of(regular(1, 3) + regular(2, 5, Fraction(1, 20)) + regular(3, 6))
    tri, pent, hexa = G
    assert keys(tri.lines) == {hashable_key(Q(0)), hashable_key(Q(1, 6)), hashable_key(Q(1, 3))}
    assert keys(pent.lines) == {hashable_key(Q(1, 20) + Q(k, 10)) for k in range(5)}
    assert hexa.lines is F.ALL_LINES                       # lem-skew-los
    assert not F.is_symmetric_pair(tri, pent)
    assert F.is_symmetric_pair(tri, hexa) and F.is_symmetric_pair(pent, hexa)
    assert F.find_asymmetry(G) is None
    assert F.find_asymmetry_pair(G) == (0, 1)
    assert not F.is_symmetric_family(G)


def test_single_vertex_and_centre_lines():
    _, _, G = family_of([(Fraction(0), Fraction(0)), (Fraction(1), Fraction(1, 7))]
                        + regular(2, 4))
    centre, single, square = G
    assert centre.at_centre and centre.lines is F.ALL_LINES
    assert keys(single.lines) == {hashable_key(Q(1, 7))}         # the paper's note
    assert F.common_lines(G) == single.lines
    assert F.is_symmetric_family(G)


# ---------------------------------------------------------------- radial projection
def test_radial_projection_merges_rays_and_keeps_robots():
    _, _, (g1, g2) = family_of(regular(1, 9) + regular(2, 15))
    proj = F.radial_projection(g1, g2)
    assert proj.ring.n == 9 + 15 - 3 and len(proj.coincident) == 3
    assert sorted(proj.ring.robots) == list(range(24))
    merged = [lab for lab in proj.ring.polygon.labels if len(lab) == 2]
    assert sorted(merged) == [(0, 9), (3, 14), (6, 19)]
    assert proj.ring.radius_squared == g2.radius_squared
    assert F.is_type4(proj.ring)[0]
    assert len(proj.ring.lines) == 3 and proj.ring.lines == F.intersect_lines(g1.lines, g2.lines)


def test_projection_to_an_even_union_is_not_type4():
    _, _, (g1, g2) = family_of(regular(1, 9) + regular(2, 15, Fraction(1, 2)))
    proj = F.radial_projection(g1, g2)
    assert proj.ring.n == 24 and not proj.coincident
    assert not F.is_type4(proj.ring)[0]


def test_projection_of_the_centre_is_refused():
    _, _, (c, g) = family_of([(Fraction(0), Fraction(0))] + regular(1, 5))
    with pytest.raises(ValueError):
        F.radial_projection(c, g)


# ---------------------------------------------------------------- Preprocess
def test_preprocess_merges_9_and_15_and_literal_loop_never_ends():
    _, _, G = family_of(regular(1, 9) + regular(2, 15) + ring(3, ["1/40", "1/7", "17/40",
                                                                   "5/8", "6/7"]))
    trace = []
    Gp = F.preprocess(G, trace)
    assert [g.name for g in Gp] == ["G(1,2)", "G3"]
    assert [g.n for g in Gp] == [21, 5]
    assert any(e["branch"] == "odd-merge-type4" for e in trace)
    literal = F.preprocess_literal(G)
    assert not literal.terminated and "repeats" in literal.reason


def test_preprocess_keeps_even_polygons_and_literal_terminates_without_odd():
    _, _, G = family_of(regular(1, 4) + regular(2, 6, Fraction(1, 24)))
    trace = []
    assert F.preprocess(G, trace) == G
    assert {e["branch"] for e in trace} == {"skip-i-even"}
    assert F.preprocess_literal(G).terminated


def test_preprocess_merges_15_and_21():
    _, _, G = family_of(regular(1, 15) + regular(2, 21))
    Gp = F.preprocess(G, [])
    assert len(Gp) == 1 and Gp[0].n == 33 and len(Gp[0].lines) == 3


# ---------------------------------------------------------------- the procedure
def run(points, **kw):
    config = polar_configuration(points)
    return config, F.paper_procedure(config, **kw)


def test_c3_configuration_is_called_orderable():
    """The paper cannot see a rotation of order 3 (two triangles turned by 1/10)."""
    config, res = run(regular(1, 3) + regular(2, 3, Fraction(1, 10)))
    assert res.orderable and res.gathering_possible
    report = audit(config)
    assert report["truth"]["group"] == "C3" and not report["truth"]["orderable"]
    failing = [d["statement"] for d in report["discrepancies"]]
    assert "lem-asym-pair-ord" in failing and "cor-Pasym-Pord" in failing
    assert failing.index("obs-merg-asym-pair") < failing.index("lem-asym-pair-ord")
    assert report["discrepancies"][-2]["statement"] == "GatheringPattern"


def test_merge_witnesses_name_their_reading_on_levels_of_one_or_two_robots():
    """obs-merg-asym-pair: two lone robots at turns 0 and 1/7 form an asymmetric pair whose
    G_ij (a 2-gon) has a mirror, a witness only if a level of one robot is a polygon: the
    witness names that reading.  The two triangles (a witness under every reading) name
    none."""
    from exactsym.paper.family.claims import SMALL_LEVEL_READING
    cases = ((ring(1, ["0"]) + ring(2, ["1/7"]) + ring(3, ["3/10", "3/5", "9/10"]), True),
             (regular(1, 3) + regular(2, 3, Fraction(1, 10)), False))
    for points, small in cases:
        _, _, G = family_of(points)
        sizes = {g.name: g.n for g in G}
        failures = [c for c in F.family_claims(G, F.preprocess(G, []))
                    if c["statement"] == "obs-merg-asym-pair" and c["holds"] is False]
        assert failures
        for claim in failures:
            pair_small = min(sizes[claim["polygons"][0]], sizes[claim["polygons"][1]]) < 3
            assert pair_small == ("reading" in claim["witness"]) == \
                (SMALL_LEVEL_READING in claim["detail"])
        assert any("reading" in c["witness"] for c in failures) == small


def test_mirror_inside_half_turn_is_called_not_orderable():
    config, res = run(ring(1, ["1/4", "1/20", "9/20"])
                      + ring(2, ["0", "1/10", "1/4", "1/2", "3/5", "3/4"]))
    assert not res.orderable and not res.gathering_possible and res.make_asym == "not-orderable"
    report = audit(config)
    assert report["truth"]["orderable"] and report["truth"]["group"] == "C1"
    family_level = [d["statement"] for d in report["discrepancies"]
                    if d["statement"] not in LEVEL_STATEMENTS]
    assert family_level[0] == "lem-sym-notord"


def test_d3_configuration_agrees_on_the_conclusion():
    config, res = run(regular(1, 9) + regular(2, 15))
    assert not res.orderable and res.leader is None
    report = audit(config)
    assert report["agrees"] and report["truth"]["group"] == "D3"


def test_trace_entries_have_the_required_keys():
    _, res = run(ring(1, ["1/40", "1/7", "2/5", "5/8"]) + regular(2, 6))
    for e in res.trace:
        assert {"algorithm", "line", "polygons", "statement", "detail"} <= set(e)
        assert isinstance(e["polygons"], list)
    branches = {(e["algorithm"], e.get("branch")) for e in res.trace if e.get("branch")}
    assert ("MakeAsym", "asym-polygon-large") in branches
    assert ("ElectLeader", "asymmetric") in branches
    assert [m["robot"] for m in res.moves] and res.leader is not None


def test_rotation_and_scale_do_not_change_the_paper():
    """Everything the paper does is invariant under orientation-preserving similarities."""
    config, res = run(regular(1, 3) + regular(2, 5, Fraction(1, 20)) + regular(3, 6))
    other = transformed(config, levels_of(config), "similarity")
    res2 = F.paper_procedure(other)
    assert (res2.orderable, res2.leader, [m["robot"] for m in res2.moves]) == \
        (res.orderable, res.leader, [m["robot"] for m in res.moves])


def test_reflection_is_the_other_handedness():
    """The reflected input seen by an observer of the other handedness is the same view."""
    config, res = run(ring(1, ["1/40", "1/7", "2/5", "5/8"]) + regular(2, 6))
    mirrored = transformed(config, levels_of(config), "reflection")
    res2 = F.paper_procedure(mirrored, orientation=-1)
    assert (res2.leader, [m["robot"] for m in res2.moves]) == \
        (res.leader, [m["robot"] for m in res.moves])


def test_chirality_changes_the_leader_and_the_audit_says_so():
    config = load(DISCREPANCIES / "family-leader-chirality.toml")
    report = audit(config)
    # the handedness dependence disappears with the unordered reading of {CW, ACW}:
    # Elect_Leader_Asym refuted under the literal reading, not a failure of lem-asym-ord
    assert [(d["statement"], d["kind"]) for d in report["discrepancies"]] == \
        [("Elect_Leader_Asym", "reading")]
    leader = report["discrepancies"][0]
    assert leader["witness"]["frames"] == ["identity", "reflection"]
    assert leader["witness"]["leaders"] == [1, 0]
    assert leader["reading"].startswith("literal") and "unordered" in leader["rescued_by"]
    assert not report["agrees"] and not report["conclusions_agree"]


def test_cartesian_rational_configuration():
    """The Cartesian path (exact rationals, SEC centre not at a nice place)."""
    from exactsym.geometry.configuration import Configuration
    pts = [(Q(3), Q(4)), (Q(-5), Q(0)), (Q(0), Q(-5)), (Q(4), Q(-3)),   # radius 5
           (Q(1), Q(0)), (Q(0), Q(2))]
    config = Configuration.from_points(pts)
    res = F.paper_procedure(config)
    report = audit(config, paper=res)
    assert report["truth"]["orderable"] == (report["truth"]["group"] == "C1")
    assert isinstance(res.orderable, bool)


# ---------------------------------------------------------------- the case library
def _all_cases():
    return sorted(FAMILY.glob("*.toml")) + sorted(DISCREPANCIES.glob("family-*.toml"))


#: Branches no configuration can reach (docs/interpretations.md, "The family layer"):
#: FindAsymmetry uses the definitions, and a polygon symmetric by the definitions is
#: always reported symmetric by Check_Symmetry_Odd/Even, so after "no asymmetric polygon"
#: CheckSymmetry(G_{t-1}) never reports "asymmetric".
UNREACHABLE = {("MakeAsym", "asym-pair-small-asym")}


@pytest.fixture(scope="module")
def case_traces():
    out = {}
    for path in _all_cases():
        config = load(path)
        out[path.name] = F.paper_procedure(config).trace
    return out


def test_every_branch_is_reached_by_a_case(case_traces):
    reached = {(e["algorithm"], e["branch"]) for trace in case_traces.values()
               for e in trace if e.get("branch")}
    wanted = {(alg, b) for alg, branches in F.BRANCHES.items() for b in branches}
    assert wanted - UNREACHABLE <= reached, sorted(wanted - UNREACHABLE - reached)
    assert not reached & UNREACHABLE


FAMILY_STATEMENTS = [
    "obs-pair-asym-ord", "lem-sym-notord", "obs-merg-asym-pair", "lem-asym-pair-ord",
    "lem-all-pair-asym-ord", "lem-one-pair-asym-ord", "obs-gcd", "lem-los-gij",
    "theorem-los-g1n", "obs-type-4", "lem-type4", "lem-3-pair-sym", "theorem-sym-pair-symG",
    "obs1-Gprime-equiG", "Gprime-equiG", "Psym-Gsym", "Pasym-Pord", "cor-Pasym-Pord",
    "obs-v-move", "lem-vl-move"]


@pytest.mark.parametrize("label", FAMILY_STATEMENTS)
def test_every_family_statement_has_a_case_with_expectations(label):
    from exactsym.io.fileformat import read_config
    tagged = []
    for path in _all_cases():
        cfg = read_config(path)
        if label in cfg.lemmas:
            assert {"orderable", "group", "paper_orderable", "paper_leader",
                    "audit_agrees"} <= set(cfg.expect), path
            tagged.append(path)
    assert tagged, f"no case tagged {label}"


def test_discrepancy_cases_have_notes():
    from exactsym.io.fileformat import read_config
    for path in sorted(DISCREPANCIES.glob("family-*.toml")):
        cfg = read_config(path)
        assert cfg.notes and cfg.expect.get("audit_agrees") is False, path


# ---------------------------------------------------------------- the command
def _exactsym(*args):
    return subprocess.run([sys.executable, "-m", "exactsym", *args], capture_output=True,
                          text=True, cwd=ROOT)


def test_audit_command_exit_codes_and_json():
    bad = _exactsym("audit", str(DISCREPANCIES / "family-c3-two-triangles.toml"), "--json")
    assert bad.returncode == 1, bad.stderr
    data = json.loads(bad.stdout)
    assert data["audit"]["agrees"] is False and data["paper"]["orderable"] is True
    assert data["audit"]["truth"]["group"] == "C3"
    good = _exactsym("audit", str(FAMILY / "gcd-9-15-merge.toml"))
    assert good.returncode == 0, good.stderr
    assert "audit: the paper agrees: no statement is false here; " in good.stdout
    assert "GatheringPattern" in good.stdout.splitlines()[2]          # the covered labels
    missing = _exactsym("audit", str(FAMILY / "no-such-file.toml"))
    assert missing.returncode == 2 and "Traceback" not in missing.stderr


def test_check_report_has_paper_and_audit():
    out = _exactsym("check", "--json", str(FAMILY / "single-vertex-on-mirror.toml"))
    assert out.returncode == 0, out.stderr
    data = json.loads(out.stdout)
    assert data["paper"]["orderable"] is False and data["paper"]["leader"] == 0
    assert data["paper"]["trace"] and data["audit"]["truth"]["leader"] == 0
    assert data["paper"]["first_actor"] == 0           # the robot on the mirror acts first


# ---------------------------------------------------------------- bounds (scaling)
@st.composite
def aligned_families(draw, max_rings=6):
    """Rings whose vertices often share rays (turns on a grid of 1/105 = 1/(3 5 7)):
    odd orbits of C_k with k | 105 or not, rotated by grid steps, sometimes a robot at C
    -- so that shared rays, odd G_ij, type 4 merges and chains of merges are common."""
    m = draw(st.integers(1, max_rings))
    points = []
    for r in range(1, m + 1):
        k = draw(st.sampled_from([1, 2, 3, 5, 7, 9, 15, 21, 35] if r < m else [3, 5, 9, 15, 21]))
        rotate = Fraction(draw(st.integers(0, 104)), 105)
        extra = draw(st.lists(st.integers(0, 104).map(lambda a: Fraction(a, 105)),
                              max_size=2, unique=True)) if draw(st.booleans()) else []
        turns = {(rotate + Fraction(j, k)) % 1 for j in range(k)} | set(extra)
        points += [(Fraction(r), t) for t in turns]
    if draw(st.integers(0, 5)) == 0:
        points.append((Fraction(0), Fraction(0)))
    return points


def _shape(Gp):
    return [(g.levels, g.robots, g.n, g.polygon.labels if g.polygon else None,
             g.polygon.directions if g.polygon else None) for g in Gp]


@settings(max_examples=250, deadline=None)
@given(aligned_families())
def test_prefiltered_preprocess_is_the_unfiltered_one(points):
    """The prefilter (shared rays counted from exact ray keys; G_ij built only when its
    vertex count can be odd and composite) gives exactly the G' of the faithful loop that
    builds every G_ij -- in the listing mode for small families and in the counting mode
    used above SMALL_FAMILY polygons."""
    _, _, G = family_of(points)
    ref_trace = []
    reference = F.preprocess(G, ref_trace, prefilter=False)
    trace, stats = [], {}
    assert _shape(F.preprocess(G, trace, stats=stats)) == _shape(reference)
    assert stats["complete"]
    merges = [e["polygons"] for e in trace if e.get("branch") == "odd-merge-type4"]
    assert merges == [e["polygons"] for e in ref_trace if e.get("branch") == "odd-merge-type4"]
    event(f"{len(merges)} merge(s)")
    old = F.SMALL_FAMILY
    try:
        F.SMALL_FAMILY = 0
        assert _shape(F.preprocess(G, [])) == _shape(reference)
    finally:
        F.SMALL_FAMILY = old


def _literal_reference(G, max_steps=None):
    """Preprocess as printed, states holding all of G (the implementation before the
    bounds): the reference for :func:`F.preprocess_literal`."""
    G = list(G)
    t = len(G)
    max_steps = max_steps if max_steps is not None else 20 * (t + 2) ** 2
    seen, cache = set(), {}
    i, j, steps = 1, None, 0
    while i <= t:
        steps += 1
        if steps > max_steps:
            return False, steps
        gi = G[i - 1]
        if gi.at_centre or gi.n % 2 == 0:
            i += 1
            continue
        if j is None:
            j = 1
        state = (i, j, tuple((g.levels, g.robots, g.n) for g in G))
        if state in seen:
            return False, steps
        seen.add(state)
        if j > t:
            j = None
            continue
        gj = G[j - 1]
        if j != i and not gj.at_centre and gj.n % 2 == 1:
            inner, outer = (gi, gj) if gi.radius_squared < gj.radius_squared else (gj, gi)
            key = (id(inner), id(outer))
            if key not in cache:
                proj = F.radial_projection(inner, outer)
                cache[key] = (F.is_type4(proj.ring)[0], proj.ring, inner, outer)
            if cache[key][0]:
                G[i - 1] = cache[key][1]
                continue
        j += 1
    return True, steps


@settings(max_examples=150, deadline=None)
@given(aligned_families(max_rings=5))
def test_literal_preprocess_with_versions_and_prefilter_is_the_printed_loop(points):
    _, _, G = family_of(points)
    want = _literal_reference(G)
    for fast_off in (False, True):
        run = F.preprocess_literal(G, fast_off=fast_off)
        assert (run.terminated, run.steps) == want


@settings(max_examples=200, deadline=None)
@given(aligned_families().map(lambda pts: pts + [(Fraction(9), Fraction(0)),
                                                  (Fraction(9), Fraction(1, 2))]))
def test_find_asymmetry_pair_is_the_first_pair_in_lexicographic_order(points):
    _, _, G = family_of(points)
    for fam in (G, F.preprocess(G)):
        brute = next(((i, j) for i in range(len(fam)) for j in range(i + 1, len(fam))
                      if not F.is_symmetric_pair(fam[i], fam[j])), None)
        assert F.find_asymmetry_pair(fam) == brute


def test_find_asymmetry_pair_beyond_the_quick_window():
    """Many rings sharing a line with G1, the first partner far away (the index path)."""
    pts = [(Fraction(r), Fraction(r % 2, 2)) for r in range(1, 30)]   # all on the line at 0
    pts += ring(40, ["1/3"])                                    # no line shared with G1
    pts += ring(50, ["0", "1/3", "2/3"])
    _, _, G = family_of(pts)
    brute = next(((i, j) for i in range(len(G)) for j in range(i + 1, len(G))
                  if not F.is_symmetric_pair(G[i], G[j])), None)
    assert brute == (0, 29)
    assert F.find_asymmetry_pair(G) == brute
    with pytest.raises(F.WorkBudgetExceeded):
        F.find_asymmetry_pair(G, budget=5)


@settings(max_examples=80, deadline=None)
@given(aligned_families())
def test_union_lines_are_the_chained_projections_lines(points):
    _, _, G = family_of(points)
    with_dir = [g for g in G if not g.at_centre]
    if len(with_dir) < 2:
        return
    whole = with_dir[0]
    for g in with_dir[1:]:
        whole = F.radial_projection(whole, g).ring
    lines, n = F.union_lines(with_dir)
    assert n == whole.n
    assert (lines is F.ALL_LINES) == (whole.lines is F.ALL_LINES)
    if lines is not F.ALL_LINES:
        assert keys(lines) == keys(whole.lines)


@settings(max_examples=40, deadline=None)
@given(st.lists(st.tuples(st.integers(-5, 5), st.integers(-5, 5)).filter(lambda p: p != (0, 0)),
                min_size=3, max_size=12, unique=True))
def test_union_lines_cartesian(points):
    from exactsym.geometry.configuration import Configuration
    pts = dict.fromkeys([(x, y) for x, y in points] + [(x * 2, y * 2) for x, y in points[:2]])
    config = Configuration.from_points([(Q(x), Q(y)) for x, y in pts])
    G = F.concentric_polygons(config)
    with_dir = [g for g in G if not g.at_centre]
    if len(with_dir) < 2:
        return
    whole = with_dir[0]
    for g in with_dir[1:]:
        whole = F.radial_projection(whole, g).ring
    lines, n = F.union_lines(with_dir)
    assert n == whole.n
    assert (lines is F.ALL_LINES) == (whole.lines is F.ALL_LINES)
    if lines is not F.ALL_LINES:
        assert keys(lines) == keys(whole.lines)


def singles(count, den):
    """``count`` single robots on distinct circles and rays, inside a triangle (t = count + 1)."""
    return [(Fraction(r), Fraction(r % den, den)) for r in range(1, count + 1)] + \
        regular(10 * count, 3)


def test_select_pairs_and_triples():
    _, _, G = family_of(singles(29, 101))
    pairs, total = F.select_pairs(G)
    assert total == 435 and pairs == [(i, j) for i in range(30) for j in range(i + 1, 30)]
    _, _, G = family_of(singles(999, 1009))
    pairs, total = F.select_pairs(G)
    assert total == 1000 * 999 // 2 and len(pairs) == F.MAX_PAIRS
    assert len(set(pairs)) == len(pairs) and all(i < j for i, j in pairs)
    assert (0, 999) in pairs and (998, 999) in pairs and (11, 12) in pairs
    middle = sorted(i for i, j in pairs if j == i + 1 and 12 <= i < 987)
    assert len(middle) > 300 and middle[-1] > 980 and max(b - a for a, b in
                                                       zip(middle, middle[1:])) <= 4
    for t, count in ((100, 300), (5000, 600), (10 ** 6, 600)):
        got = list(F.sampled_pairs(t, count))
        assert len(got) == len(set(got)) == min(count, 276 + t - 23)
        assert all(0 <= i < j < t for i, j in got) and (0, t - 1) in got
    tight = F.Limits(claim_vertices=10, claim_vertices_per_robot=0)
    assert len(F.select_pairs(G, tight)[0]) == 5          # 2 vertices a pair (at the ends)
    assert len(F.select_pairs(G, F.UNBOUNDED)[0]) == total
    triples, total = F.select_triples(1000)
    triples = list(triples)
    assert total == 1000 * 999 * 998 // 6 and len(triples) <= F.MAX_TRIPLES
    assert (0, 1, 999) in triples


def test_trace_is_compacted_but_keeps_findings():
    trace = [{"algorithm": "Preprocess", "line": 12, "polygons": [], "statement": "x",
              "detail": "", "branch": "skip-i-even"} for _ in range(500)]
    trace.insert(300, {"algorithm": "MakeAsym", "line": 5, "polygons": [],
                       "statement": "MakeAsym", "detail": "", "holds": False})
    out, omitted = F.compact_trace(trace, 50)
    assert len(out) == 50 and omitted == 452               # 48 kept, the finding, the count
    assert out[-1]["omitted"] == 452 and any(e.get("holds") is False for e in out)
    assert F.compact_trace(trace[:40], 50) == (trace[:40], 0)


def test_large_family_has_bounded_trace_and_report():
    """250 levels: 249 single robots on distinct rays, and a triangle."""
    config = polar_configuration(singles(249, 251))
    res = F.paper_procedure(config)
    assert len(res.trace) <= 200
    # every pair among the first and last 12 levels, then every consecutive pair
    assert res.bounded["of"] == 250 * 249 // 2
    assert res.bounded["family_claims_pairs_checked"] == 276 + 227
    assert "obs-merg-asym-pair" in res.bounded["family_claims_partial"]
    assert len(res.G) == 201 and res.G[100] == {"omitted": 50}
    failures = [e for e in res.trace if e["statement"] == "obs-merg-asym-pair"
                and e.get("holds") is False]
    assert len(failures) == 9 and failures[-1]["witness"]["failures"] > 8   # 8, then a count
    report = audit(config, paper=res)
    assert report["bounded"]["pairs_checked"] == 276 + 227


_NORM5 = [(5, 0), (4, 3), (3, 4), (0, 5), (-3, 4), (-4, 3), (-5, 0), (-4, -3), (-3, -4),
          (0, -5), (3, -4), (4, -3)]


@settings(max_examples=60, deadline=None)
@given(st.lists(st.lists(st.sampled_from(range(12)), min_size=1, max_size=9, unique=True),
                min_size=1, max_size=5))
def test_prefiltered_preprocess_cartesian(subsets):
    """Cartesian rings on the 12 rational rays of norm 5 (shared rays across circles),
    inside a ring of all 12: the prefilter's exact Cartesian ray keys."""
    from exactsym.geometry.configuration import Configuration
    pts = []
    for k, subset in enumerate(subsets, 1):
        pts += [(Q(k * _NORM5[d][0]), Q(k * _NORM5[d][1])) for d in subset]
    pts += [(Q(50 * x), Q(50 * y)) for x, y in _NORM5]
    config = Configuration.from_points(pts)
    G = F.concentric_polygons(config)
    assert _shape(F.preprocess(G, [])) == _shape(F.preprocess(G, [], prefilter=False))
    run = F.preprocess_literal(G)
    assert (run.terminated, run.steps) == _literal_reference(G)
