"""GatheringPattern and FormGPattern as a per-robot function (spec section 3).

The paper writes a global sequential procedure with sets R and P; oblivious robots need
``compute(snapshot, me) -> stay | path``, a pure function of what one robot sees in its
own frame.  :func:`decide` computes, from a snapshot, every robot's answer at once (all
robots run the same function on the same snapshot; only "me" differs), and
:func:`compute` reads off one robot's.  The steps, each with its reading switch:

1. ``C`` -- A1: ``sec-all`` (default, the SEC of every robot seen) or ``sec-r`` (the
   literal "SEC by the robots in set R": the SEC of the robots outside the pattern
   recognised about the SEC of all).
2. ``P`` -- A2: the largest valid partial pattern about C (:func:`.pattern.recognise`,
   with the ``lone`` switch of Def. 1).
3. ``R`` = the others; empty: stay (terminated).
4. Preprocess / MakeAsym / ElectLeader on R by the paper layer (:mod:`.paper_bridge`,
   handedness +1: the robot's own frame); G' in O_S or not orderable: stay
   ("gathering not possible").
5. A3: ``first`` (default) -- when MakeAsym or Make_SymToAsym moves a robot, only the
   first move named is made this cycle; ``all`` -- every move named, and the leader
   (elected after them) runs FormGPattern in the same cycle.
6. FormGPattern for the leader (A4-A7 below).

FormGPattern (reference reading, the paper's proof L1660-1661):
A4 "C is not occupied": ``exact`` (no centre at C, default), ``covers`` (no disc covers
C), ``within2`` (no centre within 2 of C); not occupied: the segment to C.  Otherwise,
with l the last layer of P (A7: the largest occupied layer; full = capacity reached):
full -- the radial segment to radius 2(l+1); not full -- A5: ``radial-arc`` (default:
radially to radius 2l, then the arc of that circle to the free slot next to the nearer
end of the layer's chain), ``straight`` (the segment to that slot), ``arc-radial`` (the
arc on the mover's own circle to the slot's ray, then radially in).  A6: the nearer
end; on a tie the counter-clockwise way of the mover's own frame.
Epsilon moves (A8): the paper layer's rational rotations about the SEC centre of R.
EL: the paper layer's reading of Elect_Leader_Asym's tuples {CW, ACW}: ``literal``
(ordered pairs in the observer's handedness, default) or ``unordered`` (sorted pairs,
the same for both handednesses).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

from ..exact.multiquadratic import MQ
from flint import fmpq
from . import geometry as g
from .paper_bridge import paper_decision
from .pattern import Pattern, recognise, slot
from ..exact.algebraic.run_tower import sqrt_exact
from .run_home import snapshot_key

READINGS = {
    "A1": ("sec-all", "sec-r"),
    "A3": ("first", "all"),
    "A4": ("exact", "covers", "within2"),
    "A5": ("radial-arc", "straight", "arc-radial"),
    "A6": ("nearer",),
    "A7": ("largest",),
    "A8": ("rational-rotation",),
    "lone": ("accept", "reject"),
    "EL": ("literal", "unordered"),
}


@dataclass(frozen=True)
class Readings:
    A1: str = "sec-all"
    A3: str = "first"
    A4: str = "exact"
    A5: str = "radial-arc"
    A6: str = "nearer"
    A7: str = "largest"
    A8: str = "rational-rotation"
    lone: str = "accept"
    EL: str = "literal"

    def as_dict(self) -> dict:
        return {k: getattr(self, k) for k in READINGS}

    @staticmethod
    def parse(items) -> "Readings":
        """From ``["A1=sec-r", ...]``; raises ``ValueError`` naming the bad item."""
        kw = {}
        for item in items or ():
            key, sep, value = item.partition("=")
            if not sep or key not in READINGS or value not in READINGS[key]:
                choices = "; ".join(f"{k}={'|'.join(v)}" for k, v in READINGS.items())
                raise ValueError(f"bad reading {item!r} (choices: {choices})")
            kw[key] = value
        return Readings(**kw)


class NoRule(ValueError):
    """The printed FormGPattern has no instruction for this snapshot (a reading made C
    "occupied" without a robot at C): the leader stays."""


@dataclass(frozen=True)
class Move:
    robot: int
    path: tuple          # geometry.Segment / geometry.Arc pieces, in the snapshot's frame
    role: str            # "leader", "leader+epsilon" (A3=all), "MakeAsym", "Make_SymToAsym"
    kind: str = ""       # the paper layer's kind of the robot's first move: "epsilon",
    #                      "to-G_t-circle" (MakeAsym, L1526: lem-vl-move's second case); ""
    #                      for FormGPattern's path


@dataclass(frozen=True)
class Decision:
    """``status``: "move", "stay" (R is not empty but the paper moves nobody),
    "terminated", "not-possible" or "undecided" (the kernel cannot hold the numbers);
    ``moves``: who
    moves and how; ``centre``; ``pattern`` (recognised P); ``leader``; ``detail``."""
    status: str
    moves: tuple
    centre: tuple
    pattern: Pattern
    leader: int | None
    detail: str = ""

    def move_of(self, robot: int):
        return next((m for m in self.moves if m.robot == robot), None)


def compute(snapshot, me: int, readings: Readings = Readings(), unit=1):
    """``None`` (stay) or the path of robot ``me`` for this snapshot (its own frame, in
    which a robot's radius is ``unit``: robots see the discs)."""
    m = decide(tuple(snapshot), readings, fmpq(unit)).move_of(me)
    return None if m is None else m.path


def decide(snapshot: tuple, readings: Readings = Readings(), unit=fmpq(1)) -> Decision:
    """Every robot's answer on ``snapshot`` (see the module docstring).  A snapshot
    whose coordinates come from several towers of nested radicals is first re-homed
    into one (:func:`.run_home.common_tower`); a nested-radical target is built in
    that tower.  Cached per snapshot and per tower: numbers of two towers are never
    compared, not even as cache keys."""
    return _decide(snapshot_key(snapshot), readings, unit)


@lru_cache(maxsize=4096)
def _decide(key: tuple, readings: Readings, unit) -> Decision:
    # key: run_home.snapshot_key (towers and epochs first)
    towers, _epochs, snapshot = key
    tower = towers[0] if towers else None
    pts = list(snapshot)
    centre, _ = g.smallest_enclosing_circle(pts)
    pat = recognise(pts, centre, readings.lone, unit)
    if readings.A1 == "sec-r":
        rest = [p for i, p in enumerate(pts) if i not in pat.robots]
        if rest:
            centre, _ = g.smallest_enclosing_circle(rest)
            pat = recognise(pts, centre, readings.lone, unit)
    R = [i for i in range(len(pts)) if i not in pat.robots]
    if not R:
        return Decision("terminated", (), centre, pat, None, "R is empty")
    rpts = [pts[i] for i in R]
    moves: dict = {}          # robot -> pieces, in the snapshot's frame
    order: list = []
    roles: dict = {}
    kinds: dict = {}          # robot -> kind of its first paper move
    current = list(pts)       # positions after the moves named so far (A3 = all)
    leader = None
    detail = ""
    # A3 = all: MakeAsym's moves, then (every robot recomputing on the moved positions,
    # as the paper layer's rounds do) ElectLeader's, then the leader's FormGPattern
    for _round in range(3 if readings.A3 == "all" else 1):
        rpts = [current[i] for i in R]
        d = paper_decision(rpts, 1, readings.EL)
        detail = d.detail
        if not d.complete:
            return Decision("undecided", (), centre, pat, None, d.detail)
        if not d.possible or not d.orderable:
            if _round == 0:
                return Decision("not-possible", (), centre, pat, None, d.detail)
            return Decision("undecided", (), centre, pat, None,
                            f"after MakeAsym's moves: {d.detail}")
        centre_r = g.smallest_enclosing_circle(rpts)[0] if d.moves else None
        try:
            for pm in (d.moves if readings.A3 == "all" else d.moves[:1]):
                robot = R[pm.robot]
                piece = _paper_move(pm, current[robot], centre_r, current, R, tower)
                if piece is None:
                    return Decision("undecided", (), centre, pat, None,
                                    f"{pm.algorithm} move of kind {pm.kind} is not simulated")
                if robot not in moves:
                    order.append(robot)
                moves[robot] = moves.get(robot, []) + piece
                roles[robot] = pm.algorithm
                kinds.setdefault(robot, pm.kind)
                current[robot] = piece[-1].final
        except ValueError as err:
            return Decision("undecided", (), centre, pat, None, str(err))
        made_asym = bool(d.moves) and all(pm.algorithm == "MakeAsym" for pm in d.moves)
        if not made_asym or readings.A3 == "first":
            leader = R[d.leader] if d.leader is not None else None
            break
    else:
        return Decision("undecided", (), centre, pat, None, "MakeAsym moves for 3 rounds")
    if leader is not None and (readings.A3 == "all" or not moves):
        try:
            path = form_pattern_path(current[leader], current, pat, centre, readings, unit,
                                     tower)
        except NoRule as err:
            # the algorithm's own gap, not the kernel's: the leader has no instruction and
            # stays (a proved stall when no frame moves anybody), never "undecided"; the
            # moves MakeAsym or Make_SymToAsym planned this cycle are still made
            if not moves:
                return Decision("stay", (), centre, pat, None, str(err))
            path, detail = [], f"{detail}; the leader stays: {err}"
        except ValueError as err:
            return Decision("undecided", (), centre, pat, None, str(err))
        if path:
            if leader not in moves:
                order.append(leader)
            moves[leader] = moves.get(leader, []) + path
            # A3 = all: the leader's path may start with its own epsilon move
            roles[leader] = "leader+epsilon" if leader in roles else "leader"
    if not moves:
        return Decision("stay", (), centre, pat, None,
                        f"the paper elects no leader among the {len(R)} robots of R ({detail})")
    out = tuple(Move(r, tuple(moves[r]), roles[r], kinds.get(r, "")) for r in order)
    return Decision("move", out, centre, pat, leader, detail)


def _paper_move(pm, start, centre_r, pts, R, tower=None):
    """The path of one of the paper layer's moves: in the multiquadratic field, or in
    ``tower`` (a new tower when None) when the radial scale factor is a nested
    radical."""
    if pm.kind == "epsilon" and pm.tau is not None:
        t = MQ.rational(pm.tau)
        den = 1 + t * t
        end = g.add(centre_r, g.rotate(g.sub(start, centre_r), (1 - t * t) / den, 2 * t / den))
        return [g.Arc(centre_r, start, end, 1 if pm.tau > 0 else -1)]
    if pm.kind == "to-G_t-circle" and pm.target_ring_robot is not None:
        target = pts[R[pm.target_ring_robot]]
        r2t, r2p = g.dist2(target, centre_r), g.dist2(start, centre_r)
        k = sqrt_exact(r2t / r2p, tower)
        return [g.Segment(start, g.add(centre_r, g.scale(g.sub(start, centre_r), k)))]
    return None


def occupied(pts, pat: Pattern, centre, reading: str, unit=1, me=None) -> bool:
    """A4: is C occupied "by other robot" (L1605)?  ``me``: the mover's point, never
    counted -- a leader half way to C does not occupy C against itself."""
    if reading == "exact":
        return pat.centre_robot is not None
    bound = unit * unit if reading == "covers" else 4 * unit * unit
    return any((g.dist2(p, centre) - bound).sign() < 0 or
               (reading == "covers" and g.dist2(p, centre) == bound)
               for p in pts if p is not me)


def form_pattern_path(p, pts, pat: Pattern, centre, readings: Readings, unit=1,
                      tower=None) -> list:
    """FormGPattern for a leader at ``p`` (see the module docstring); ``unit``: the robot
    radius in this frame; ``tower``: the snapshot's tower of nested radicals, where a
    nested-radical target is built (None: a new one, :func:`radial_point`)."""
    if not occupied(pts, pat, centre, readings.A4, unit, me=p):
        return [g.Segment(p, centre)]
    if pat.centre_robot is None:
        raise NoRule("C is occupied (A4) but no robot is centred on it: FormGPattern has "
                     "no layer to extend, so the printed algorithm gives the leader no move")
    l = pat.last_layer
    if pat.last_full():
        return [g.Segment(p, radial_point(centre, p, 2 * (l + 1) * unit, tower))]
    chain = pat.layers[-1]
    q = radial_point(centre, p, 2 * l * unit, tower)
    s_ccw = slot(centre, pts[chain[-1]], l, 1)      # past the counter-clockwise end
    s_cw = slot(centre, pts[chain[0]], l, -1)       # past the clockwise end
    vq, v1, v2 = g.sub(q, centre), g.sub(s_ccw, centre), g.sub(s_cw, centre)
    # the free arc runs counter-clockwise from s_ccw to s_cw; all three vectors have the
    # length 2l, so angle keys compare angles
    if not g.angle_less(g.angle_key(v1, v2), g.angle_key(v1, vq)):
        # q on the free arc: back (clockwise) to s_ccw, or on (counter-clockwise) to s_cw;
        # the nearer, a tie by the own counter-clockwise sense
        back, on = g.angle_key(v1, vq), g.angle_key(vq, v2)
        target, sense = (s_ccw, -1) if g.angle_less(back, on) else (s_cw, 1)
    else:
        # q inside the chain's own arc (its radial arrival overlaps the chain: I5 reports
        # it): the shorter turn, counter-clockwise to s_ccw or clockwise to s_cw
        on, back = g.angle_key(vq, v1), g.angle_key(v2, vq)
        target, sense = (s_cw, -1) if g.angle_less(back, on) else (s_ccw, 1)
    if readings.A5 == "straight":
        return [g.Segment(p, target)]
    if readings.A5 == "arc-radial":
        vp = g.sub(p, centre)
        k = sqrt_exact(g.dot(vp, vp), tower) / (2 * l * unit)
        above = g.add(centre, g.scale(g.sub(target, centre), k))
        pieces = g.arc_path(centre, p, above, sense)
        return pieces + [g.Segment(above, target)]
    pieces = [g.Segment(p, q)] if q != p else []
    return pieces + g.arc_path(centre, q, target, sense)


def radial_point(centre, p, radius, tower=None):
    """The point at distance ``radius`` from ``centre`` towards ``p``, exactly.
    ``|p - C|^2`` is rational for a robot that has not slid along an arc (then one square
    root of a rational); after a slide, with C moved, or for a point caught at a
    nested-radical instant it is an irrational multiquadratic or a tower number: its root
    is an MQ when it lies in the multiquadratic closure, else a number of the snapshot's
    ``tower`` of nested radicals (a new level when it has none there; a new tower when
    ``tower`` is None: :func:`~exactsym.exact.algebraic.run_tower.sqrt_exact`).
    ValueError (the decision is then ``undecided``) when the closure test cannot write a
    root (an integer of more than 160 bits it cannot split), the tower would exceed its
    levels, or ``p = C``."""
    v = g.sub(p, centre)
    r2 = g.dot(v, v)
    if r2.is_zero():
        # a robot of R standing on C (runs with I1 off can put it there): no ray
        raise ValueError("radial_point: the robot stands on C, no direction towards it")
    if r2.is_rational():
        return g.radial_point(centre, p, radius)
    return g.add(centre, g.scale(v, MQ.coerce(radius) / sqrt_exact(r2, tower)))


def path_end(path):
    return path[-1].final if path else None


__all__ = ["Readings", "READINGS", "Decision", "Move", "NoRule", "compute", "decide",
           "form_pattern_path", "radial_point"]

decide.cache_clear = _decide.cache_clear      # the benchmarks time cold Looks
