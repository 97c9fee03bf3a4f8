"""MakeAsym's single-vertex epsilon (lines 25-27, ``obs-v-move``): below the cap of
:func:`make_asym._stable_turn_cap`, wherever v is on its way, Elect_Leader_Asym orders
G_it the same."""

from __future__ import annotations

from hypothesis import given, settings, strategies as st

from exactsym.audit.statements import audit
from exactsym.geometry.configuration import load
from exactsym.exact import fmpq, normal_turn
from exactsym.paper import polygon as P
from exactsym.paper.circle_polygon import polygon_from_directions
from exactsym.paper.family.make_asym import _stable_turn_cap

OCTAGON = [fmpq(13, 240) + fmpq(k, 8) for k in range(8)]


def test_cap_exact_values():
    # the octagon's mirror between robots at -17/240 and 13/240 is 1/120 turn clockwise
    assert _stable_turn_cap(OCTAGON, fmpq(0), -1) == fmpq(1, 120)
    # counter-clockwise, v's gap ahead (13/240) meets its gap behind at the same mirror...
    # no: moving counter-clockwise, the gaps 13/240 - d and 17/240 + d never meet; the
    # first event is v reaching robot 2's ray
    assert _stable_turn_cap(OCTAGON, fmpq(0), 1) == fmpq(13, 240)
    hexagon = [fmpq(k, 6) for k in range(6)]
    assert _stable_turn_cap(hexagon, fmpq(1, 20), -1) == fmpq(1, 20)
    # v on a vertex: it splits the gap it moves into; the midpoint comes first
    assert _stable_turn_cap(hexagon, fmpq(0), 1) == fmpq(1, 12)


def _ordered_labels(gt, v_turn, orientation):
    labels = [(i + 1,) for i in range(len(gt))] + [(0,)]
    poly = polygon_from_directions(labels, list(gt) + [normal_turn(v_turn)], True)
    res = P.elect_leader_asym(poly, orientation)
    return [poly.labels[i] for i in res.ordering], res.tie


turns = st.fractions(min_value=0, max_value=1, max_denominator=60).map(
    lambda f: fmpq(f.numerator, f.denominator))


@settings(max_examples=150, deadline=None)
@given(st.lists(turns, min_size=3, max_size=7, unique_by=lambda t: normal_turn(t)),
       turns, st.sampled_from([1, -1]), st.fractions(min_value=0, max_value=1,
                                                      max_denominator=50))
def test_ordering_of_g_it_is_constant_below_the_cap(gt, start, orientation, where):
    gt = sorted(set(normal_turn(t) for t in gt))
    sense = -orientation
    cap = _stable_turn_cap(gt, start, sense)
    assert cap is not None and cap > 0
    early = _ordered_labels(gt, start + sense * cap / 1000, orientation)
    frac = fmpq(where.numerator, where.denominator)
    d = cap * (frac if 0 < frac < 1 else fmpq(1, 2))
    assert _ordered_labels(gt, start + sense * d, orientation) == early


def test_octagon_case_obs_v_move_holds_with_the_small_epsilon(tmp_path):
    f = tmp_path / "octagon.toml"
    f.write_text("format = 1\npoints = [\n  { r = \"1\", turn = \"0\" },\n" + "".join(
        f"  {{ r = \"2\", turn = \"{13 + 30 * k}/240\" }},\n" for k in range(8)) + "]\n")
    found = {d["statement"] for d in audit(load(f))["discrepancies"]}
    assert "obs-v-move" not in found
    assert {"MakeAsym", "lem-sym-notord"} <= found
    # G' is in O_S for the paper (the octagon has every line through C): GatheringPattern
    # never starts MakeAsym, so lem-vl-move (about MakeAsym's run) is not in question
    # (issue 32); Make_SymToAsym on the single-vertex G_1 is, wherever it is called
    assert "lem-vl-move" not in found and "Make_SymToAsym" in found
