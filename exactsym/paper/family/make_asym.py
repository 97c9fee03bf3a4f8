"""``MakeAsym`` (Section 4.2) with exact epsilon moves.

Epsilon moves are exact: a rational turn (polar), or a rational rotation keeping the
robot on its circle (Cartesian).  The configuration after the moves is built with
:meth:`exactsym.geometry.configuration.Configuration.with_positions` (exact numbers; an
impossible move raises :class:`~exactsym.errors.MoveImpossible`).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Iterable, Sequence

from .. import polygon as P
from ...geometry.configuration import Configuration, Polar
from ...errors import MoveImpossible
from ...exact.adjoin_sqrt import adjoin_sqrt
from ...exact import fmpq, normal_turn, number_text, sign
from ...geometry.levels import Levels
from ..circle_polygon import polygon_from_directions
from .concentric import (Ring, has_lines, intersect_lines, is_symmetric_pair,
                         is_symmetric_polygon, lines_text, new_ring)
from .elect_leader import elect_leader_asym_on, first_of_ring_in_ordering
from .find_asymmetry import find_asymmetry, find_asymmetry_pair
from ...geometry.predicates import PseudoAngle
from ..keys import HALF, cross, dot
from .limits import DEFAULT_LIMITS, Limits, MAX_QUADRATIC_N, WorkBudgetExceeded
from .projection import radial_projection, robot_in, scale_to
from .trace import few_names, trace_entry


class _Placement:
    """Mutable robot positions used to apply the paper's moves exactly, and to build the
    configuration after them (polar when the input is polar about C): exact numbers
    only; the configuration after the moves is :meth:`Configuration.with_positions`."""

    def __init__(self, config: Configuration, ring_data: Levels):
        self.config = config
        self.ring_data = ring_data
        self.polar = ring_data.polar and config.polar is not None and config.radii is not None
        self.changed: set = set()
        if self.polar:
            self.radii = list(config.radii)
            self.turns = [t for _, t in config.polar]
            self.r2 = [r2 for r2, _ in config.polar]
        else:
            self.points = list(config.points)
            self.centre = ring_data.sec.centre
            self.system = config.system     # grows when a radial move adjoins a square root

    # -- reading
    def direction(self, i):
        if self.polar:
            return self.turns[i]
        p = self.points[i]
        return (p[0] - self.centre[0], p[1] - self.centre[1])

    # -- moves
    def set_turn(self, i, turn):
        self.turns[i] = normal_turn(turn)
        self.changed.add(i)

    def set_polar(self, i, r, turn):
        self.radii[i], self.r2[i], self.turns[i] = r, r * r, normal_turn(turn)
        self.changed.add(i)

    def set_vector(self, i, v):
        self.points[i] = (self.centre[0] + v[0], self.centre[1] + v[1])
        self.changed.add(i)

    def radius_from(self, i, j):
        """Put robot i on the circle of robot j, same direction (exact or False)."""
        if self.polar:
            self.set_polar(i, self.radii[j], self.turns[i])
            return True
        v = self.direction(i)
        scale = scale_to(self.r2_of(j), self.r2_of(i))
        if scale is None:
            # sqrt of the ratio outside the field: adjoin it (a square root of a rational,
            # or a tower level for a nested radical); None: out of reach
            found = adjoin_sqrt(self.system, [c for p in self.points for c in p]
                                + list(self.centre), self.r2_of(j) / self.r2_of(i))
            if found is None:
                return False
            self._rehome(found[0])
            scale, v = found[1], self.direction(i)      # v rewritten in the new field
        self.set_vector(i, (v[0] * scale, v[1] * scale))
        return True

    def _rehome(self, system):
        """Write every number in ``system`` (a field that contains the old one)."""
        if system is self.system:
            return
        c = system.coerce
        self.points = [(c(x), c(y)) for x, y in self.points]
        self.centre = (c(self.centre[0]), c(self.centre[1]))
        self.system = system

    def r2_of(self, i):
        if self.polar:
            return self.r2[i]
        v = self.direction(i)
        return dot(v, v)

    def configuration(self) -> Configuration:
        """The configuration after the moves (raises :class:`MoveImpossible`)."""
        if self.polar:
            return self.config.with_positions({i: Polar(self.radii[i], self.turns[i])
                                               for i in sorted(self.changed)})
        config = self.config
        if self.system is not config.system:    # a square root was adjoined
            config = Configuration(source=config.source, name=config.name, model=config.model,
                                   points=self.points, system=self.system)
        return config.with_positions({i: self.points[i] for i in sorted(self.changed)})


def _global_gap(place: _Placement, robots: Iterable[int]):
    """Smallest counter-clockwise gap between consecutive distinct rays of ``robots``
    (polar: a turn; Cartesian: a gap key), for the size of epsilon."""
    dirs = [place.direction(i) for i in robots]
    dirs = [d for d in dirs if place.polar or (sign(d[0]) != 0 or sign(d[1]) != 0)]
    if place.polar:
        ts = sorted(set(normal_turn(t) for t in dirs))
        if len(ts) < 2:
            return fmpq(1)
        gaps = [b - a for a, b in zip(ts, ts[1:])] + [ts[0] + 1 - ts[-1]]
        return min(gaps)
    return None


def _rotate_vector(v, tau, times: int = 1):
    c, s = (1 - tau * tau) / (1 + tau * tau), 2 * tau / (1 + tau * tau)
    for _ in range(times):
        v = (v[0] * c - v[1] * s, v[0] * s + v[1] * c)
    return v


def _epsilon_rotation(place: _Placement, robot: int, orientation: int, accept,
                      all_robots: Sequence[int], max_halvings: int = 6, cap=None):
    """Move ``robot`` by epsilon along its circle, clockwise for the observer of this
    handedness (the direction Make_SymToAsym calls "its right side"; MakeAsym names
    none).  Polar: epsilon = a quarter of the smallest angular gap between rays of the
    configuration, halved (at most ``max_halvings`` times) until ``accept(place)`` holds.
    Cartesian: the rational rotation of Pythagorean parameter tau = -orientation/4,
    halved until four such rotations stay inside the gap to the neighbouring ray, then
    until ``accept`` holds.  When no epsilon tried is accepted, the first one is used.
    ``cap`` (polar): a turn epsilon must stay below; the first epsilon is then at most
    half of it (:func:`_stable_turn_cap`).
    Returns ``(amount_text, accepted)``; the placement is left moved."""
    if place.polar:
        start = place.turns[robot]
        first = _global_gap(place, [i for i in all_robots if place.r2[i] != 0]) / 4
        if cap is not None and first >= cap:
            first = cap / 2
        delta = first
        for _ in range(max_halvings + 1):
            place.set_turn(robot, start - orientation * delta)
            if accept(place):
                return f"{number_text(-orientation * delta)} turn", True
            delta /= 2
        place.set_turn(robot, start - orientation * first)
        return f"{number_text(-orientation * first)} turn", False
    u = place.direction(robot)
    others = [place.direction(i) for i in all_robots if i != robot]
    others = [d for d in others if sign(d[0]) != 0 or sign(d[1]) != 0]
    tau = fmpq(-orientation, 4)
    nearest = _nearest_turn(u, others, orientation)
    for _ in range(64):                      # fit inside the gap (always possible)
        if _inside_gap(u, _rotate_vector(u, tau, 4), nearest, orientation):
            break
        tau /= 2
    first = tau
    for _ in range(max_halvings + 1):
        place.set_vector(robot, _rotate_vector(u, tau))
        if accept(place):
            return f"rotation with tau = {number_text(tau)}", True
        tau /= 2
    place.set_vector(robot, _rotate_vector(u, first))
    return f"rotation with tau = {number_text(first)}", False


def _stable_turn_cap(directions, start, sense: int):
    """MakeAsym line 26 (polar): how far, in turns, v may move from turn ``start`` in the
    sense ``sense`` (+1 counter-clockwise) before the ordering of G_it could change.

    G_it is G_t's polygon (turns ``directions``) with v's ray added.  Elect_Leader_Asym
    compares the vertices' strings entry by entry, each entry a gap between consecutive
    rays (or its chord, equal for gaps g and 1 - g).  Only v's two gaps change as v
    moves, so every comparison keeps its outcome until one of v's gaps meets a fixed gap
    g or 1 - g, or v's two gaps meet each other: the first such position bounds epsilon.
    This is the reading of the paper's "epsilon" that ``obs-v-move`` needs (docstring
    of :func:`make_asym`); a quarter of the smallest gap between rays alone can carry v
    across a line of symmetry of G_t (docs/interpretations.md)."""
    ts = sorted(set(normal_turn(t) for t in directions))
    if not ts:
        return None
    # a, b: the rays of G_t around v's path (v on a ray of G_t: the gap it moves into)
    ahead = [normal_turn(sense * (t - start)) for t in ts]
    b_dist = min((d for d in ahead if d != 0), default=fmpq(1))
    a_dist = min((normal_turn(-d) for d in ahead if d != 0), default=fmpq(1))
    if 0 in ahead:
        a_dist = fmpq(0)
    span = a_dist + b_dist
    gaps = [y - x for x, y in zip(ts, ts[1:])] + [ts[0] + 1 - ts[-1]]
    gaps.remove(span if span < 1 else max(gaps))   # v's gap: no longer fixed
    # after moving d: v's gaps are a_dist + d (behind) and b_dist - d (ahead)
    events = [span / 2 - a_dist]
    for g in set(gaps):
        for h in {g, 1 - g}:
            events += [h - a_dist, b_dist - h]
    events.append(b_dist)
    positive = [e for e in events if e > 0]
    return min(positive) if positive else None


_FULL_TURN = (1, 0)


def _turn_key(u, v, orientation):
    """Exact key increasing with the angle from u to v in the moving sense (clockwise for
    orientation +1), in (0, 1] turns as :func:`ccw_gap_key` (v on u's ray: a full turn):
    the pseudo-angle of (u.v, +-u x v), which is v in u's frame, compared by
    cross-multiplying; no squared length is inverted (over the sparse Q(zeta_N) with
    square-root levels, sums of those inverses grew without bound: issue 9)."""
    x, y = dot(u, v), cross(u, v)
    if orientation == 1:
        y = -y
    if sign(y) == 0 and sign(x) > 0:
        return _FULL_TURN
    return (0, PseudoAngle(x, y))


def _nearest_turn(u, others, orientation):
    """The smallest :func:`_turn_key` from u to a direction of ``others`` off u's ray
    (None when there is none): computed once, so that each epsilon tried costs O(1)."""
    # off u's ray: not (cross = 0 and dot > 0) -- the rays compared without a division
    keys = [_turn_key(u, d, orientation) for d in others
            if sign(cross(u, d)) != 0 or sign(dot(u, d)) <= 0]
    return min(keys) if keys else None


def _inside_gap(u, far, nearest, orientation) -> bool:
    """``far`` is reached from u, turning clockwise (orientation +1) or counter-clockwise,
    before any direction of the others (which may share u's ray): before ``nearest``,
    the smallest turn to one of them (:func:`_nearest_turn`)."""
    reach = _turn_key(u, far, orientation)
    if reach == _FULL_TURN:
        return False
    return nearest is None or reach < nearest


@dataclass
class MakeAsymResult:
    """``outcome``: "orderable" or "not-orderable" (or "undecided" when exactsym cannot
    place a robot exactly); ``moves``: the robots moved, in order; ``config``: the
    configuration after the moves; ``branch``: see :data:`BRANCHES`."""
    outcome: str
    branch: str
    moves: list = field(default_factory=list)
    config: Configuration | None = None


def make_asym(config: Configuration, ring_data: Levels, Gp: Sequence[Ring], trace: list,
              orientation: int = 1, reading: str = "literal", rnd: int = 1,
              limits: Limits | None = None) -> MakeAsymResult:
    """``MakeAsym`` (Section 4.2) on G' whose G_t is symmetric, every branch.

    Epsilon moves: :func:`_epsilon_rotation` (exact: a rational turn, or a rational
    rotation keeping the robot on its circle).  "Move v_l to the circumference of the
    enclosing circle of G_t": radially, same direction, exact: polar, or the square root
    of the radii's squared ratio -- adjoined when it is outside the configuration's field
    (:func:`~exactsym.exact.adjoin_sqrt.adjoin_sqrt`: a larger multiquadratic field, or a
    tower of quadratic extensions, over the multiquadratic field or over Q(zeta_M) for a
    cyclotomic configuration; the configuration after the moves is then written in that
    field).  Out of reach, the move is "not exact" (outcome "undecided", the paper
    layer's ``complete: false``): a base Q(zeta_M) beyond the tower's bound (phi(M) <=
    192), or a root sqrt(m) w whose integer m has more than 160 bits
    (``mq_closure.decided_sqrt`` without its bounded split, :mod:`exactsym.exact.adjoin_sqrt`).
    "Move v, epsilon distance" for a single-vertex polygon: along its circle (the robot at
    C moves to a quarter of the smallest radius, towards the first vertex of G_t
    counter-clockwise from the observer's x axis: no invariant direction exists there);
    polar, its epsilon also stays below the first turn at which the ordering of G_it
    could change (:func:`_stable_turn_cap`): the paper's epsilon is "small", and
    ``obs-v-move`` (the leader chosen through G_it is the same while v moves) holds only
    for such an epsilon."""
    alg = "MakeAsym"
    t = len(Gp)
    Gt = Gp[-1]
    place = _Placement(config, ring_data)
    everyone = list(range(config.n))
    moves: list = []

    def accept_asym(ring_index):
        def check(pl: _Placement):
            ring = Gp[ring_index]
            return not is_symmetric_polygon(_moved_ring(ring, pl))
        return check

    def move_eps(robot, line, branch, accept, why):
        amount, ok = _epsilon_rotation(place, robot, orientation, accept, everyone)
        moves.append({"robot": robot, "algorithm": alg, "line": line, "kind": "epsilon",
                      "amount": amount})
        trace_entry(trace, alg, line, [Gt.name], alg,
                    f"move robot {robot} by epsilon along its circle ({amount}, clockwise for "
                    f"this observer)" + ("" if ok else f"; no epsilon tried makes {why}"),
                    robots=[robot], branch=branch, round=rnd, uses="epsilon-move")
        if not ok:
            trace_entry(trace, alg, line, [Gt.name], alg,
                        f"the move is meant to make {why}, but no epsilon tried does",
                        holds=False, round=rnd)

    def move_out(robot, line, branch):
        target = Gt.own[0]
        ok = place.radius_from(robot, target)
        moves.append({"robot": robot, "algorithm": alg, "line": line, "kind": "to-G_t-circle"})
        if not ok:
            trace_entry(trace, alg, line, [Gt.name], alg,
                        f"move robot {robot} to the circle of {Gt.name}: the point is not exact "
                        "here (the square root of the ratio of radii needs a tower over a "
                        "cyclotomic field beyond its bound, or a large rational factored)",
                        robots=[robot], branch=branch, round=rnd)
            return False
        trace_entry(trace, alg, line, [Gp[-2].name if t > 1 else Gt.name, Gt.name], alg,
                    f"move robot {robot} radially to the circle of {Gt.name}", robots=[robot],
                    branch=branch, round=rnd)
        return True

    def elect_on_gt_and_move(projected: Ring, line: int, statement: str, branch: str,
                             family: str) -> MakeAsymResult:
        """Lines 4-6 / 16-18 (|G_t| > 3): Elect_Leader_Asym on the polygon projected onto
        G_t's circle, move the first robot of G_t in its ordering by epsilon, report."""
        robot, _ = elect_leader_asym_on(trace, alg, line, projected, Gt, orientation, reading,
                                        statement, branch, rnd)
        if robot is None:
            return MakeAsymResult("undecided", branch, moves, None)
        move_eps(robot, line + 1, branch, accept_asym(t - 1), f"{Gt.name} asymmetric")
        trace_entry(trace, alg, line + 2, [Gt.name], alg,
                    f"Report: an orderable {family} where G_t is asymmetric", round=rnd)
        return MakeAsymResult("orderable", branch, moves, _safe_config(place, trace, rnd))

    a = find_asymmetry(Gp)
    trace_entry(trace, alg, 1, few_names(Gp), "lem-one-pair-asym-ord",
                f"FindAsymmetry(G'): {'found ' + Gp[a].name if a is not None else 'none'}",
                round=rnd)
    if a is not None:
        Ga = Gp[a]
        if Gt.n > 3:
            return elect_on_gt_and_move(radial_projection(Ga, Gt).ring, 4,
                                        "lem-one-pair-asym-ord", "asym-polygon-large", "G'")
        return _small_gt(config, place, Gp, Ga, None, trace, orientation, reading, rnd, moves,
                         move_out, polygon_branch=True)
    limits = limits if limits is not None else DEFAULT_LIMITS
    try:
        pair = find_asymmetry_pair(Gp, limits.step_budget(config.n))
    except WorkBudgetExceeded as err:
        trace_entry(trace, alg, 13, few_names(Gp), "lem-all-pair-asym-ord",
                    f"Find_Asymmetry_Pair(G') not carried out: {err} (work budget)", round=rnd,
                    kind="budget")
        return MakeAsymResult("undecided", "asym-pair-large", moves, None)
    trace_entry(trace, alg, 13, few_names(Gp), "lem-all-pair-asym-ord",
                "Find_Asymmetry_Pair(G'): " + ("none" if pair is None else
                                               f"<{Gp[pair[0]].name}, {Gp[pair[1]].name}>"),
                round=rnd)
    if pair is not None:
        gi, gj = Gp[pair[0]], Gp[pair[1]]
        if Gt.n > 3:
            gij = radial_projection(gi, gj).ring if not gi.at_centre else gj
            return elect_on_gt_and_move(radial_projection(gij, Gt).ring, 16,
                                        "lem-all-pair-asym-ord", "asym-pair-large", "G")
        return _small_gt(config, place, Gp, gi, gj, trace, orientation, reading, rnd, moves,
                         move_out, polygon_branch=False)
    single = next((k for k, g in enumerate(Gp) if g.n == 1), None)
    if single is not None:
        branch = "single-vertex"
        gi = Gp[single]
        v = gi.robots[0]
        on_line = has_lines(intersect_lines(gi.lines, Gt.lines))
        trace_entry(trace, alg, 25, [gi.name, Gt.name], "obs-v-move",
                    f"{gi.name} is the single robot {v}" + (" (on a line of symmetry of G_t)"
                                                            if on_line else
                                                            " (not on a line of symmetry of G_t)"),
                    robots=[v], branch=branch, round=rnd)
        if gi.at_centre:
            first = Gt.own[0] if Gt.polygon is None else robot_in(Gt.polygon.labels[0], Gt)
            ok = _move_off_centre(place, v, first, Gp)
            moves.append({"robot": v, "algorithm": alg, "line": 26, "kind": "off-centre"})
            trace_entry(trace, alg, 26, [gi.name], "obs-v-move",
                        f"move robot {v} off C by a quarter of the smallest radius, towards robot "
                        f"{first} (the first vertex of {Gt.name} from this observer's x axis)"
                        + ("" if ok else ": not exact here"), robots=[v], branch=branch, round=rnd,
                        labelling_dependent=True)
            if not ok:
                return MakeAsymResult("undecided", branch, moves, None)
            pair_ok = True
        else:
            def accept_pair(pl):
                return not is_symmetric_pair(_moved_ring(gi, pl), Gt)
            cap = (_stable_turn_cap(Gt.polygon.directions, place.turns[v], -orientation)
                   if place.polar and Gt.polygon is not None else None)
            amount, pair_ok = _epsilon_rotation(place, v, orientation, accept_pair, everyone,
                                                cap=cap)
            moves.append({"robot": v, "algorithm": alg, "line": 26, "kind": "epsilon",
                          "amount": amount})
            trace_entry(trace, alg, 26, [gi.name], "obs-v-move",
                        f"move robot {v} by epsilon ({amount})", robots=[v], branch=branch,
                        round=rnd)
        if not pair_ok:
            trace_entry(trace, alg, 26, [gi.name, Gt.name], alg,
                        f"<{gi.name}, {Gt.name}> is meant to become asymmetric, but it stays "
                        f"symmetric for every epsilon tried ({Gt.name} has "
                        f"{lines_text(Gt, Gt.polygon.polar if Gt.polygon else True)})",
                        holds=False, round=rnd)
        try:
            place.configuration()          # raises MoveImpossible when the move is impossible
        except MoveImpossible as err:
            trace_entry(trace, alg, 26, [gi.name], alg, f"the move is impossible: {err}",
                        holds=False, round=rnd)
            return MakeAsymResult("undecided", branch, moves, None)
        new_gi = _moved_ring(gi, place)
        new_gt = _moved_ring(Gt, place)
        if new_gi.at_centre:
            return MakeAsymResult("undecided", branch, moves, None)
        proj = radial_projection(new_gi, new_gt)
        robot, problem = elect_leader_asym_on(trace, alg, 27, proj.ring, new_gt, orientation,
                                              reading, "obs-v-move", branch, rnd)
        if robot is None:
            return MakeAsymResult("undecided", branch, moves, None)
        _check_v_move(trace, place, gi, Gt, v, robot, orientation, reading, rnd)
        move_eps(robot, 28, branch, accept_asym(t - 1), f"{Gt.name} asymmetric")
        return MakeAsymResult("orderable", branch, moves, _safe_config(place, trace, rnd))
    trace_entry(trace, alg, 29, few_names(Gp), "theorem-sym-pair-symG",
                "Report: G' is not orderable (no asymmetric polygon, no asymmetric pair, no "
                "single-vertex polygon)", branch="not-orderable", round=rnd)
    return MakeAsymResult("not-orderable", "not-orderable", moves, None)


def _safe_config(place: _Placement, trace, rnd):
    try:
        return place.configuration()
    except MoveImpossible as err:
        trace_entry(trace, "MakeAsym", None, [], "MakeAsym",
                    f"the moves lead to an invalid configuration: {err}", holds=False, round=rnd)
        return None


def _small_gt(config, place, Gp, first, second, trace, orientation, reading, rnd, moves,
              move_out, polygon_branch: bool) -> MakeAsymResult:
    """MakeAsym lines 7-12 (``polygon_branch``) or 19-24: |G_t| <= 3."""
    alg = "MakeAsym"
    base = 7 if polygon_branch else 19
    kind = "polygon" if polygon_branch else "pair"
    t = len(Gp)
    Gt = Gp[-1]
    if t < 2:
        trace_entry(trace, alg, base, [Gt.name], alg, "there is no G_{t-1}", holds=False,
                    round=rnd)
        return MakeAsymResult("undecided", f"asym-{kind}-small-asym", moves, None)
    prev = Gp[-2]
    if prev.at_centre:
        check_sym, deg = True, "1 (the robot at C)"
    else:
        check = P.check_symmetry(prev.polygon, orientation)
        check_sym, deg = check.symmetric, str(check.degree)
    trace_entry(trace, alg, base, [prev.name], alg,
                f"CheckSymmetry({prev.name}): {'symmetric' if check_sym else 'asymmetric'} "
                f"(degree {deg})", round=rnd)
    if not check_sym:
        branch = f"asym-{kind}-small-asym"
        robot, problem = elect_leader_asym_on(trace, alg, base + 2, prev, prev, orientation,
                                              reading, alg, branch, rnd)
    else:
        branch = f"asym-{kind}-small-sym"
        if polygon_branch:
            src = first
            what = f"G_a(t-1) = {first.name} projected onto {prev.name}"
        else:
            src = radial_projection(first, second).ring if not first.at_centre else second
            what = f"G_ij(t-1) = {src.name} projected onto {prev.name}"
        if src.at_centre or prev.at_centre:
            trace_entry(trace, alg, base + 3, [prev.name], alg,
                        f"{what}: the robot at C cannot be projected", branch=branch, round=rnd)
            return MakeAsymResult("undecided", branch, moves, None)
        proj = radial_projection(src, prev)
        robot, problem = elect_leader_asym_on(trace, alg, base + 3, proj.ring, prev, orientation,
                                              reading, alg, branch, rnd)
    if robot is None:
        return MakeAsymResult("undecided", branch, moves, None)
    if not move_out(robot, base + 4, branch):
        return MakeAsymResult("undecided", branch, moves, None)
    trace_entry(trace, alg, base + 5, [Gt.name], alg,
                "Report: an orderable G' where G_t is asymmetric", round=rnd)
    return MakeAsymResult("orderable", branch, moves, _safe_config(place, trace, rnd))


def _moved_ring(ring: Ring, place: _Placement) -> Ring:
    """``ring`` with its robots' current directions (projected vertices keep theirs)."""
    if ring.polygon is None:
        return ring
    poly = ring.polygon
    dirs = []
    moved_to_centre = False
    own_set = set(ring.own)
    for lab, d in zip(poly.labels, poly.directions):
        own = [r for r in lab if r in own_set]
        r = own[0] if own else lab[0]
        nd = place.direction(r)
        if not place.polar and sign(nd[0]) == 0 and sign(nd[1]) == 0:
            moved_to_centre = True
        dirs.append(nd if (own or len(lab) == 1) else d)
    if moved_to_centre:
        return ring
    moved = polygon_from_directions(poly.labels, dirs, poly.polar)
    return new_ring(ring.name, moved, ring.radius_squared, ring.levels, ring.robots,
                    ring.own)


def _move_off_centre(place: _Placement, v: int, towards: int, Gp) -> bool:
    """The robot at C moves to a quarter of the smallest non-zero radius, on the ray of
    robot ``towards``."""
    if place.polar:
        inner = min((i for i in range(len(place.r2)) if place.r2[i] != 0),
                    key=lambda i: place.r2[i])
        place.set_polar(v, place.radii[inner] / 4, place.turns[towards])
        return True
    q = place.direction(towards)
    r2q = dot(q, q)
    inner = min((dot(place.direction(i), place.direction(i)) for i in range(len(place.points))
                 if i != v), key=lambda x: x)
    f = inner / (4 * r2q)
    place.set_vector(v, (q[0] * f, q[1] * f))
    return True


def _check_v_move(trace, place, gi, Gt, v, robot, orientation, reading, rnd):
    """``obs-v-move``: the leader selected through G_it is the same whether v is in motion
    (half way to its new position) or epsilon apart.  Polar configurations only (half a
    rational turn is exact; half a Cartesian rotation is not rational in general)."""
    if gi.at_centre or not place.polar:
        return
    saved = place.turns[v]
    start = gi.polygon.directions[0]
    place.set_turn(v, start + (normal_turn(saved - start + HALF) - HALF) / 2)
    try:
        half_gi = _moved_ring(gi, place)
        half_gt = _moved_ring(Gt, place)
        proj = radial_projection(half_gi, half_gt).ring
        if proj.polygon.n <= MAX_QUADRATIC_N:
            res = P.elect_leader_asym(proj.polygon, orientation, reading)
            _, other = first_of_ring_in_ordering(proj.polygon, res, half_gt)
            trace_entry(trace, "MakeAsym", 27, [gi.name, Gt.name], "obs-v-move",
                        f"with robot {v} half way, the first vertex of {Gt.name} in the ordering "
                        f"of G_it is robot {other} (robot {robot} with v epsilon apart)",
                        holds=other == robot, round=rnd)
    finally:
        place.set_turn(v, saved)
