"""A joint step stopped short reuses the verdicts of the whole joint motion's instants
(``stops.covered_points``, ``invariants._VERDICTS``): the same verdicts as checking each
step's own instants anew (``invariants.REUSE_JOINT = False``), stop by stop and over
whole searches; and the premise, a piece's prefix moves along the piece's own
parametrisation."""

from __future__ import annotations

import copy
from fractions import Fraction as F
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from exactsym.exact.multiquadratic import MQ
from exactsym.gathering import geometry as g
from exactsym.gathering import invariants
from exactsym.gathering.adversary import apply_action, children
from exactsym.gathering.cases import settings_of
from exactsym.gathering.invariants import ALL, Checker, Violation
from exactsym.gathering.search import Bounds, search
from exactsym.gathering.world import IDENTITY, World
from exactsym.gathering.paper_bridge import read_case

P = g.point
CASES = Path(__file__).resolve().parents[2] / "cases" / "gathering"
fractions = st.fractions(min_value=F(1, 50), max_value=F(49, 50), max_denominator=60)


@settings(max_examples=40, deadline=None)
@given(fractions, fractions, st.integers(-30, 30), st.integers(-30, 30),
       st.sampled_from([(3, 4), (5, 12), (8, 15), (1, 0)]), st.sampled_from([1, -1]))
def test_a_prefix_moves_along_the_pieces_own_parametrisation(f, s, x, y, rot, sense):
    """``piece.split(f)[0].at(s) == piece.at(f s)`` exactly, segment and arc: the instants
    of a step stopped at ``f`` are the whole motion's before ``f`` (time scaled by f)."""
    a, b = rot
    start = P(x + 5 * a, y + 5 * b)
    end = P(x - 5 * b * sense, y + 5 * a * sense)        # a quarter turn about (x, y)
    pieces = [g.Segment(start, P(-y, x + 1)), g.Arc(P(x, y), start, end, sense)]
    for piece in pieces:
        head = piece.split(MQ.rational(f))[0]
        p, q = head.at(MQ.rational(s)), piece.at(MQ.rational(f * s))
        assert (p[0] - q[0]).sign() == 0 and (p[1] - q[1]).sign() == 0


#: robots 0 and 1 cut across the SEC (C changes part way), robot 4 on Make_SymToAsym's arc
JOINT = [(20, 0), (-20, 0), (12, 16), (-16, 12), (5, 0)]


def _world(enabled, chords: bool):
    w = World(JOINT, checker=Checker(enabled=frozenset(enabled)))
    w.look(4, IDENTITY)
    if chords:
        w.robots[0].path = [g.Segment(P(20, 0), P(0, 20))]
        w.robots[1].path = [g.Segment(P(-20, 0), P(0, -20))]
    else:
        w.robots[0].path = [g.Arc(P(0, 0), P(20, 0), P(16, -12), -1)]
        w.robots[1].path = [g.Arc(P(0, 0), P(-20, 0), P(-16, -12), 1)]
    return w


def _verdict(world, act):
    w = copy.deepcopy(world)
    try:
        ok = apply_action(w, act)
    except Violation as v:
        return (v.invariant, tuple(v.robots), v.label)
    return ("allowed" if ok else "refused", (), "")


@pytest.mark.parametrize("chords", [True, False])
@pytest.mark.parametrize("enabled", [("I3",), ("I6",), ("I9",), ("I3", "I4", "I6", "I9")])
def test_every_stop_of_a_joint_step_has_the_verdict_of_its_own_instants(
        enabled, chords, monkeypatch):
    world = _world(enabled, chords)
    steps = [a for a in children(world) if a["a"] == "step"]
    assert len(steps) >= 4 and any(a["moves"][0][1] is not None for a in steps)
    invariants._VERDICTS.clear()
    monkeypatch.setattr(invariants, "REUSE_JOINT", True)
    shared = [_verdict(world, a) for a in steps]          # the siblings share the cache
    again = [_verdict(world, a) for a in steps]           # every verdict from the cache
    reused = len(invariants._VERDICTS)
    monkeypatch.setattr(invariants, "REUSE_JOINT", False)
    own = [_verdict(world, a) for a in steps]
    assert shared == own == again
    if not chords:                  # every stop allowed: the passed instants were shared
        assert reused > 0 and all(v[0] == "allowed" for v in own)
    if chords and set(enabled) != {"I9"}:         # C moves part way: some stop fails
        assert any(v[0] in enabled for v in own)


def _case_worlds():
    for path in sorted(CASES.glob("*.toml")):
        points, _name, expect, _source = read_case(path)
        if "A3=all" in expect.get("gather_readings", []):
            yield path.stem, points, expect


@pytest.mark.parametrize("name,points,expect", list(_case_worlds())[:4])
def test_a_search_finds_the_same_with_and_without_the_reuse(name, points, expect,
                                                             monkeypatch):
    """Gathering cases read under A3 = all (joint steps), a search of 150 states: the
    same schedule, states and verdict whether sibling stops reuse verdicts or not."""
    settings_ = settings_of({**expect, "gather_invariants": sorted(set(ALL) - {"I2"})})
    out = []
    for reuse in (True, False):
        monkeypatch.setattr(invariants, "REUSE_JOINT", reuse)
        invariants._VERDICTS.clear()
        rep = search(points, settings_, Bounds(budget=150, seconds=None, shrink=False))
        d = rep.as_dict()
        d.pop("seconds")
        out.append(d)
    assert out[0] == out[1]


@pytest.mark.parametrize("enabled", [("I3", "I6"), ("I3", "I4", "I6", "I9")])
def test_the_stops_of_one_joint_motion_compute_its_instants_once(enabled, monkeypatch):
    """Every stop the adversary offers for a joint motion (rational, or an exact instant
    of K(alpha) or of an instant's own tower, numbers that do not mix with each other) is
    resolved and checked from one computation of the motion's critical instants: the
    roots are cached per state and motion (:func:`.stops.motion_roots`), the whole
    motion's look points are built from those very roots, and an exact stop is found
    among them by identity or by disjoint Arb balls, never recomputed per stop.  The
    verdicts are those of each step's own instants (``REUSE_JOINT = False``)."""
    from exactsym.exact.multiquadratic import sqrt_rational
    from exactsym.gathering import joint_instants, stops
    s2 = sqrt_rational(2)
    # robot 2 at (9 sqrt 2, 9 sqrt 2 + 4): the chords' instants need nested radicals
    # (each an instant's own tower) beside numbers of K(alpha)
    world = World([(20, 0), (-20, 0), (s2 * 9, s2 * 9 + 4), (-16, 12), (5, 0)],
                  checker=Checker(enabled=frozenset(enabled)))
    world.look(4, IDENTITY)
    world.robots[0].path = [g.Segment(P(20, 0), P(0, 20))]
    world.robots[1].path = [g.Segment(P(-20, 0), P(0, -20))]
    steps = [a for a in children(world) if a["a"] == "step"]
    exact = [a for a in steps if isinstance(a["moves"][0][1], dict)]
    assert len(exact) >= 4
    calls = []
    real = joint_instants.joint_critical_roots

    def counted(pieces, w, sec_r=False):
        calls.append(tuple(sorted(pieces)))
        return real(pieces, w, sec_r)
    for mod in (joint_instants, stops):
        monkeypatch.setattr(mod, "joint_critical_roots", counted)
    invariants._VERDICTS.clear()
    monkeypatch.setattr(invariants, "REUSE_JOINT", True)
    shared = [_verdict(world, a) for a in exact]
    # the children above filled the cache: no stop computes its motion's instants again
    assert calls == []
    monkeypatch.setattr(invariants, "REUSE_JOINT", False)
    own = [_verdict(world, a) for a in exact]
    assert shared == own


def test_the_point_just_after_an_instant_names_its_isolating_interval():
    """``JointPoint.root_from`` (how a stop is placed before an instant without an exact
    value): the point just after an instant carries the low end of the instant's
    isolating interval; where the instant is held, it lies strictly between that end
    and the point, and so does no other look point."""
    from exactsym.exact.multiquadratic import sqrt_rational
    from exactsym.gathering.joint_instants import joint_look_points
    s2 = sqrt_rational(2)
    world = World([(20, 0), (-20, 0), (s2 * 9, s2 * 9 + 4), (-16, 12), (5, 0)],
                  checker=Checker(enabled=frozenset(("I3",))))
    world.look(4, IDENTITY)
    world.robots[0].path = [g.Segment(P(20, 0), P(0, 20))]
    pieces = {0: world.robots[0].path[0], 4: world.robots[4].path[0]}
    points, _sided = joint_look_points(pieces, world)
    afters = [k for k, jp in enumerate(points) if jp.where.startswith("just after")]
    assert len(afters) >= 3
    for k in afters:
        jp = points[k]
        lo = MQ.rational(jp.root_from)
        assert (jp.tau - lo).sign() > 0
        held = points[k - 1]
        if held.exact:
            assert (held.tau - lo).sign() > 0 and (jp.tau - held.tau).sign() > 0
            others = points[:k - 1]
        else:
            others = points[:k]
        # every earlier point is at or before lo (the interval holds the instant alone)
        assert all((p.tau - lo).sign() <= 0 for p in others if not p.exact)
    assert all(jp.root_from is None for jp in points
               if not jp.where.startswith("just after"))
