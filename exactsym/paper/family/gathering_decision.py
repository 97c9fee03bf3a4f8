"""The decision of ``GatheringPattern`` (lines 1-5) and the whole leader election of
Section 4.2 on a configuration: Preprocess, MakeAsym while G_t is symmetric (robots are
oblivious: each round recomputes from scratch), ElectLeader; ``cor-Pasym-Pord``,
``lem-vl-move``.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import partial

from ...geometry.configuration import Configuration, Polar, no_cycle_collection
from ...errors import InputError, MoveImpossible
from ...exact import normal_turn
from ...geometry.levels import Levels, levels_of, polar_sec
from .claims import family_claims
from .concentric import (common_lines, concentric_polygons, is_polar, is_symmetric_family,
                         is_symmetric_polygon, lines_text)
from .elect_leader import elect_leader
from ..keys import HALF
from .limits import DEFAULT_LIMITS, Limits
from .make_asym import MakeAsymResult, make_asym
from .preprocess import preprocess, preprocess_literal
from .trace import compact_trace, describe, family_text, few_names, trace_entry


@dataclass
class PaperResult:
    """What the paper's algorithms conclude on a configuration.

    ``orderable``: False when GatheringPattern reports "gathering is not possible" (G' in
    O_S) or MakeAsym reports "G' is not orderable"; ``gathering_possible``: the former
    decision alone; ``leader``: the robot ElectLeader elects after MakeAsym's moves
    (None when none is elected or it cannot be computed); ``moves``: robots moved, in
    order (MakeAsym, Make_SymToAsym); ``first_actor``: the first robot the procedure
    moves, else the leader; ``complete``: False when exactsym could not carry out a step
    exactly (then the leader is None); ``G``/``Gprime``: names and sizes;
    ``final_config``: the configuration after every move (MakeAsym's and
    Make_SymToAsym's), on which ``leader`` is elected (None when nothing moved or when
    it cannot be built exactly): the audit continues a comparison of frames there;
    ``round_configs``: ``(number of moves so far, configuration)`` after each round of
    MakeAsym's moves, in order (the audit continues there when two frames part after an
    epsilon move)."""
    orderable: bool
    gathering_possible: bool
    leader: int | None
    moves: list
    first_actor: int | None
    complete: bool
    trace: list
    described: "Described" = field(repr=False, compare=False)   # () -> (G, G') dicts
    make_asym: str | None
    elect_leader: str | None
    bounded: dict = field(default_factory=dict)
    G_rings: tuple = field(default=(), repr=False, compare=False)   # G, as Rings (family.Ring)
    final_config: Configuration | None = field(default=None, repr=False, compare=False)
    round_configs: tuple = field(default=(), repr=False, compare=False)

    # G and G' described (names, robots, levels and the exact texts of their lines of
    # symmetry) only when a report reads them: the texts of lines in Q(zeta_M) of degree
    # thousands cost tens of ms each, and the audit's runs in other frames never read them
    @property
    def G(self) -> list:
        return self.described()[0]

    @property
    def Gprime(self) -> list:
        return self.described()[1]


class Described:
    """``() -> (G, G')`` described by :func:`.trace.describe`, computed on the first call
    and kept (a plain object: a result can be pickled, as Dask does)."""

    __slots__ = ("G", "Gp", "polar", "limit", "shown", "value")

    def __init__(self, G: tuple, Gp: tuple, polar: bool, limit, shown: bool = True):
        self.G, self.Gp, self.polar, self.limit, self.shown = G, Gp, polar, limit, shown
        self.value = None

    def __call__(self) -> tuple:
        if self.value is None:
            self.value = ((describe(self.G, self.polar, self.limit),
                           describe(self.Gp, self.polar, self.limit))
                          if self.shown else ([], []))
        return self.value


def paper_procedure(config: Configuration, ring_data: Levels | None = None,
                    orientation: int = 1, reading: str = "literal", degree: str = "paper",
                    max_rounds: int = 3, claims: bool = True,
                    check_vl: bool = True, limits: Limits | None = None,
                    level_polygons=None, describe_polygons: bool = True,
                    rings=None) -> PaperResult:
    """See :func:`_paper_procedure` (run with the cyclic garbage collector paused: the
    family layer builds many small acyclic objects, one polygon per level).
    ``level_polygons``: the polygon layer's polygons of ``ring_data``'s levels, when
    built (:class:`exactsym.paper.polygon_report.LevelSection`): their directions are
    reused.  ``describe_polygons=False``: ``G`` and ``Gprime`` are left empty (the audit's
    runs in other frames only compare actions and traces; listing every polygon's lines
    writes exact slopes, megabytes in a field of degree thousands).  ``rings``: G itself,
    equal to :func:`concentric_polygons` of ``config`` and ``ring_data``, when the caller
    has it (the audit's frames map the first frame's G: :mod:`exactsym.audit.frame_rings`)."""
    with no_cycle_collection():
        return _paper_procedure(config, ring_data, orientation, reading, degree, max_rounds,
                                claims, check_vl, limits, level_polygons, describe_polygons,
                                rings)


def _paper_procedure(config: Configuration, ring_data: Levels | None = None,
                     orientation: int = 1, reading: str = "literal", degree: str = "paper",
                     max_rounds: int = 3, claims: bool = True,
                     check_vl: bool = True, limits: Limits | None = None,
                     level_polygons=None, describe_polygons: bool = True,
                     rings=None) -> PaperResult:
    """Run the paper on ``config``: GatheringPattern's decision (lines 1-5) and the leader
    election of Section 4.2 (Preprocess, MakeAsym when G_t is symmetric, ElectLeader).

    The leader election is run even when GatheringPattern stops at line 5 (the paper
    presents it on its own, and MakeAsym has branches -- a single-vertex polygon, "not
    orderable" -- that only a symmetric G' reaches).  After MakeAsym moves robots, every
    robot recomputes from scratch on the new configuration (they are oblivious): the
    next round runs Preprocess again, MakeAsym again if G_t is still symmetric (at most
    ``max_rounds`` rounds; each extra round is a finding), then ElectLeader.
    ``orientation``: the observer's handedness (+1: that of the file's axes).
    ``limits``: the work budgets (:class:`Limits`, default :data:`DEFAULT_LIMITS`;
    :data:`UNBOUNDED` for the exhaustive procedure); ``PaperResult.bounded`` says what
    was bounded."""
    limits = limits if limits is not None else DEFAULT_LIMITS
    ring_data = ring_data if ring_data is not None else levels_of(config)
    finish = _finish if describe_polygons else partial(_finish, describe_polygons=False)
    trace: list = []
    bounded: dict = {}
    G = rings if rings is not None else concentric_polygons(config, ring_data, level_polygons)
    polar = is_polar(G)
    trace_entry(trace, "GatheringPattern", 2, few_names(G), "def-sym-calG",
                f"G = ({family_text(G)}) about the SEC centre", round=1)
    pre_stats: dict = {}
    Gp = preprocess(G, trace, limits, pre_stats)
    literal = preprocess_literal(G, limits=limits)
    if literal.budget_exceeded:
        trace_entry(trace, "Preprocess", 12, few_names(G), "Preprocess",
                    f"as printed: {literal.reason}", kind="budget", round=1)
    elif not literal.terminated:
        trace_entry(trace, "Preprocess", 12, few_names(G), "Preprocess",
                    f"as printed: {literal.reason}", branch="literal-nontermination",
                    holds=False, kind="literal-reading", round=1)
    trace_entry(trace, "GatheringPattern", 3, few_names(Gp), "Gprime-equiG",
                f"G' = ({family_text(Gp)})", round=1)
    bounded["preprocess_complete"] = pre_stats.get("complete", True)
    bounded["preprocess_pairs_built"] = pre_stats.get("pairs_built", 0)
    if claims:
        claim_stats: dict = {}
        family_claims(G, Gp, trace, polar, limits, claim_stats)
        bounded.update(family_claims_pairs_checked=claim_stats["pairs_checked"],
                       of=claim_stats["pairs"],
                       family_claims_triples_checked=claim_stats["triples_checked"],
                       family_claims_triples=claim_stats["triples"],
                       family_claims_partial=claim_stats["partial"],
                       family_claims_failures=claim_stats["failures"])
    symmetric = is_symmetric_family(Gp)
    gathering = not symmetric
    trace_entry(trace, "GatheringPattern", 4, few_names(Gp), "def-sym-calG",
                f"common lines of all polygons of G': {lines_text(common_lines(Gp), polar)}",
                round=1)
    if symmetric:
        trace_entry(trace, "GatheringPattern", 5, few_names(Gp), "cor-Pasym-Pord",
                    "G' is in O_S: gathering is not possible", branch="not-possible", round=1)
    else:
        trace_entry(trace, "GatheringPattern", 6, few_names(Gp), "cor-Pasym-Pord",
                    "G' is in O_A: call MakeAsym(G_t), then ElectLeader(G')", branch="possible",
                    round=1)
    moves: list = []
    complete = True
    ma_outcome = None
    current, cur_rings, cur_Gp = config, ring_data, Gp
    orderable = gathering
    if config.n == 1:
        # a single robot: nothing to make asymmetric (MakeAsym's branches need a G_t
        # with a circle); ElectLeader elects it (it is at C)
        el = elect_leader(Gp, trace, orientation, reading, degree, 1)
        return finish(limits, bounded, config,
                       orderable, gathering, el.leader, [], True, trace, G, Gp,
                       None, el.branch, polar)
    rnd = 1
    rounds: list = []          # the configuration after each round of MakeAsym's moves
    while True:
        gt = cur_Gp[-1]
        if not is_symmetric_polygon(gt):
            break
        if rnd > max_rounds:
            trace_entry(trace, "MakeAsym", None, [gt.name], "MakeAsym",
                        f"G_t is still symmetric after {max_rounds} rounds", holds=False,
                        round=rnd)
            complete = False
            break
        if rnd > 1:
            trace_entry(trace, "MakeAsym", 6, [gt.name], "MakeAsym",
                        f"after MakeAsym's moves G_t = {gt.name} is still symmetric "
                        f"({lines_text(gt, polar)})", holds=False, round=rnd)
        result = make_asym(current, cur_rings, cur_Gp, trace, orientation, reading, rnd,
                           limits)
        ma_outcome = result.outcome if ma_outcome is None else ma_outcome
        moves.extend(result.moves)
        if result.outcome == "not-orderable":
            if rnd == 1:
                orderable = False
            el = None
            return finish(limits, bounded, config,
                           orderable, gathering, None, moves, complete, trace, G, Gp,
                           ma_outcome, el, polar)
        if result.outcome == "undecided" or result.config is None:
            complete = False
            return finish(limits, bounded, config,
                           orderable, gathering, None, moves, complete, trace, G, Gp,
                           ma_outcome, None, polar)
        new = result.config
        if ring_data.polar and new.polar is not None and polar_sec(new.polar) is None:
            # the moves changed the SEC (its centre left C): the paper says this cannot
            # happen; analysing the new configuration would need the Cartesian path in a
            # cyclotomic field of the moved turns' denominators -- we stop here
            trace_entry(trace, "MakeAsym", None, [gt.name], "MakeAsym",
                        "the SEC changed during the move (the paper: |G_t| > 3 ensures it does "
                        "not)" + _sense_note(current, new, result, ring_data)
                        + "; the configuration after the moves is not analysed", holds=False,
                        round=rnd)
            return finish(limits, bounded, config,
                           orderable, gathering, None, moves, False, trace, G, Gp,
                           ma_outcome, None, polar)
        try:
            new_rings = levels_of(new)
        except (ArithmeticError, NotImplementedError, InputError) as err:
            trace_entry(trace, "MakeAsym", None, [gt.name], "MakeAsym",
                        f"exactsym cannot analyse the configuration after the moves ({err})",
                        round=rnd)
            return finish(limits, bounded, config,
                           orderable, gathering, None, moves, False, trace, G, Gp,
                           ma_outcome, None, polar)
        # MakeAsym's correctness paragraph ("|G_t| > 3 ... the SEC would not change"):
        # this round's moves against the SEC they started from (a later round is not
        # blamed again for an SEC an earlier round changed)
        # (polar levels: turns about C, no Cartesian system is built for the comparison)
        grown = None if cur_rings.polar or new.system is current.system else new.system
        if not _same_sec(cur_rings, new_rings, grown):
            trace_entry(trace, "MakeAsym", None, [gt.name], "MakeAsym",
                        "the SEC changed during the move (the paper: |G_t| > 3 ensures it does "
                        "not)" + _sense_note(current, new, result, cur_rings), holds=False,
                        round=rnd)
        if check_vl and gathering:
            # lem-vl-move is about MakeAsym's run, which GatheringPattern starts only
            # when G' is in O_A (line 6)
            _check_vl_move(trace, current, new, result, orientation, reading, rnd, limits)
        rnd += 1
        current, cur_rings = new, new_rings
        rounds.append((len(moves), new))
        G2 = concentric_polygons(current, cur_rings)
        stats2: dict = {}
        cur_Gp = preprocess(G2, [], limits, stats2)
        if not stats2.get("complete", True):
            bounded["preprocess_complete"] = False
        trace_entry(trace, "GatheringPattern", 3, few_names(cur_Gp), "Preprocess",
                    f"after the moves, G' = ({family_text(cur_Gp)})", round=rnd)
    el = elect_leader(cur_Gp, trace, orientation, reading, degree, rnd)
    moves.extend(el.moves)
    leader = el.leader
    complete = complete and el.computed
    final = _after_move(current, cur_rings, el.moved_to) if moves else None
    return finish(limits, bounded, config,
                   orderable, gathering, leader, moves, complete, trace, G, Gp,
                   ma_outcome, el.branch, polar, final, tuple(rounds))


def _after_move(current: Configuration, rings: Levels, moved_to: dict):
    """``current`` with the robot Make_SymToAsym moved at its new direction from C (None
    when that point cannot be built exactly here)."""
    if not moved_to:
        return current
    (v, d), = moved_to.items()
    try:
        if rings.polar and current.radii is not None:
            return current.moved(v, Polar(current.radius(v), d))
        cx, cy = rings.sec.centre
        return current.moved(v, (cx + d[0], cy + d[1]))
    except (MoveImpossible, ArithmeticError, TypeError, ValueError):
        return None


def _finish(limits: Limits, bounded: dict, config, orderable, gathering, leader, moves,
            complete, trace, G, Gp, ma, el, polar, final=None, rounds=(),
            describe_polygons: bool = True) -> PaperResult:
    if not bounded.get("preprocess_complete", True):
        complete, leader = False, None        # G' is not the one the paper computes
    first = moves[0]["robot"] if moves else leader
    trace, omitted = compact_trace(trace, limits.trace_entries)
    bounded["trace_entries_omitted"] = omitted
    if limits.described is not None and max(len(G), len(Gp)) > limits.described:
        bounded["polygons_described"] = limits.described
    G, Gp = tuple(G), tuple(Gp)
    described = Described(G, Gp, polar, limits.described, describe_polygons)
    return PaperResult(orderable, gathering, leader, moves, first, complete, trace,
                       described, ma, el, bounded, G, final, rounds)


def _sense_note(before: Configuration, after: Configuration, result: MakeAsymResult,
                ring_data: Levels) -> str:
    """Which sense the last epsilon move of MakeAsym took ("clockwise for this observer":
    the reading of :func:`make_asym`) and whether the same move in the other sense keeps
    the SEC (the mover may choose it: only one robot moves)."""
    eps = [m for m in result.moves if m.get("kind") == "epsilon"]
    if not eps:
        return ""
    v = eps[-1]["robot"]
    head = f": robot {v} moved by epsilon clockwise for this observer"
    try:
        if before.radii is not None and after.radii is not None and ring_data.polar:
            (_, ta), (_, tb) = before.polar[v], after.polar[v]
            other = after.moved(v, Polar(after.radius(v), normal_turn(2 * ta - tb)))
            sec = polar_sec(other.polar)
            keeps = sec is not None and sec.radius_squared == ring_data.sec.radius_squared
        else:
            # a radial move of this round may have adjoined a square root: ``after`` is
            # then in a larger system, and ``before``'s numbers are written in it
            system = after.system if after.system is not before.system else None
            to = system.coerce if system is not None else (lambda x: x)
            cx, cy = (to(x) for x in ring_data.sec.centre)
            (ux, uy), (wx, wy) = ((to(p[0]) - cx, to(p[1]) - cy) for p in (before.points[v],
                                                                             after.points[v]))
            norm = ux * ux + uy * uy
            c, s_ = (ux * wx + uy * wy) / norm, (ux * wy - uy * wx) / norm
            other = after.moved(v, (cx + ux * c + uy * s_, cy - ux * s_ + uy * c))
            keeps = _same_sec(ring_data, levels_of(other), system)
    except (MoveImpossible, ArithmeticError, InputError, NotImplementedError, TypeError,
            ValueError):
        return head + "; the move in the other sense could not be built exactly"
    return head + ("; the same move counter-clockwise keeps the SEC" if keeps else
                   "; the same move counter-clockwise changes the SEC too")


def _same_sec(a: Levels, b: Levels, system=None) -> bool:
    """``system``: the number system of ``b`` when a radial move adjoined a square root
    (``a``'s numbers are written in it first: a cyclotomic number and one of a tower over
    that field do not compare directly)."""
    return a.sec.same_circle(b.sec, system.coerce if system is not None else None)


def _check_vl_move(trace, before: Configuration, after: Configuration, result: MakeAsymResult,
                   orientation, reading, rnd, limits: Limits | None = None) -> None:
    """``lem-vl-move``: "When v_l is moving no other robot will be selected as leader".
    We stop the last moving robot half way (polar configurations: half the turn, or half
    way out radially) and run one round of the procedure there: its first actor must be
    the same robot (or nobody moves and ElectLeader elects it)."""
    if not result.moves or before.radii is None or after.radii is None:
        return
    last = result.moves[-1]
    v = last["robot"]
    (r2a, ta), (r2b, tb) = before.polar[v], after.polar[v]
    if r2a == r2b:
        half_way = Polar(after.radius(v), ta + (normal_turn(tb - ta + HALF) - HALF) / 2)
    else:
        half_way = Polar((before.radius(v) + after.radius(v)) / 2, tb)
    try:
        mid = after.moved(v, half_way)
    except MoveImpossible:
        return
    sub = paper_procedure(mid, orientation=orientation, reading=reading, max_rounds=1,
                          claims=False, check_vl=False, limits=limits)
    actor = sub.first_actor
    # "no other robot will be selected": nobody acting and nobody elected selects no
    # other robot either
    holds = actor == v or actor is None and sub.leader in (None, v)
    trace_entry(trace, "MakeAsym", last["line"], [], "lem-vl-move",
                f"with robot {v} half way, the procedure's first robot to act is {actor}",
                robots=[actor] if actor is not None else None, holds=holds, round=rnd)
