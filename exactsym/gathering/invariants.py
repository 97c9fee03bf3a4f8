"""Run-time invariants I1-I10 of spec section 4, each tied to the paper's label.

:class:`Checker` is told about every Look, every advance along a path piece and every
arrival (:class:`.world.World` calls it).  A violation raises :class:`Violation` naming
the invariant, the label, the instant (event number), the robots and an exact witness.
``counts`` records how many times each invariant was checked.

Exactness of the "at any instant" checks:

* I1 along a piece is the exact minimum distance over the whole segment or arc
  (:mod:`.geometry`), not a sample;
* I4 over a piece reduces to its end points: the distance to C is convex along a segment
  and constant along an arc about C (the only arcs FormGPattern makes), and the other
  robots are still;
* I6 and I9 are checked at the end of every piece and at every adversary stop point
  (rational instants); I3 and I6 (and I9 at SEC and symmetry instants, the distance ties
  among them: a fresh Look in the reflected frame plans what one in the world's frame
  plans) also at the critical instants inside each piece (:mod:`.instants`): where the
  mover crosses the line through C and another robot, where two distances to C become
  equal, where the SEC's support changes, where a symmetry can appear -- roots of
  polynomials in the path parameter, isolated exactly
  (:mod:`~exactsym.exact.algebraic.roots`).  A Look at each instant the kernel holds, and
  one in each stretch between consecutive instants; an instant that needs a nested radical
  is checked at the instant too, its point in a tower of quadratic extensions
  (:mod:`~exactsym.exact.algebraic.tower_numbers`, counted as ``nested``); only a root of
  a cubic or quartic factor that square roots do not express is seen on both sides only
  (``sided``);
* over a step of several robots moving at once (:meth:`Checker.after_step`): I1 by the
  joint motion's exact polynomial, and I3, I4 and I6 at the critical instants of the
  joint motion (:mod:`.joint_instants`) and between them, I9 at its SEC and symmetry
  instants (and the stretches beside them).
"""

from __future__ import annotations

import contextlib
from dataclasses import dataclass, field

from ..exact.algebraic.algebraic_numbers import is_algebraic
from ..exact.algebraic.tower_numbers import is_tower
from ..exact.multiquadratic import MQ
from . import geometry as g
from .instants import critical_roots, look_points
from .joint_instants import joint_look_points
from .pattern import definition_defects, recognise
from .state_key import piece_key, point_key
from .stops import covered_points
from .world import IDENTITY, MIRROR

#: How a violation names the statement it contradicts: the paper's ``\\label`` where
#: the statement has one (``/paper/README.md``), otherwise the algorithm (or the model
#: item, or the section) with the paper's line numbers.
LABELS = {
    "I1": "gather-no-obstacle",
    "I2": "lem-vl-move",
    "I3": "obs-v-move",
    "I4": "gather-min-distance",
    "I5": "gather-no-obstacle",
    "I6": "MakeAsym (L1487, L1560)",
    "I7": "FormGPattern",
    "I8": "gathering_pattern",
    "I9": "no chirality (L210-214)",
    "I10": "conclusion (L1707-1721)",
}


#: I3 names the statement of the move that a fresh Look contradicts: obs-v-move is about
#: MakeAsym's epsilon mover (its single-vertex branch); a FormGPattern move contradicts
#: the sentence before the gathering lemmas (L1642-1643, "the robot for movement remains
#: invariant"), which belongs to FormGPattern.
I3_LABEL_OF_ROLE = {"MakeAsym": "obs-v-move", "Make_SymToAsym": "obs-v-move"}
I3_LEADER_LABEL = "FormGPattern (L1642-1643)"
#: ... except MakeAsym's move of a robot of G_{t-1} to G_t's circle (L1526): that branch
#: is lem-vl-move's second case ("v_l moves to G_t"), not obs-v-move's epsilon mover.
I3_LABEL_OF_KIND = {("MakeAsym", "to-G_t-circle"): "lem-vl-move"}


def i3_label(role, kind: str = "") -> str:
    """The statement a fresh Look contradicts, by the pending move's role and kind."""
    return I3_LABEL_OF_KIND.get((role, kind)) or I3_LABEL_OF_ROLE.get(role, I3_LEADER_LABEL)

#: I6 (C does not change while a robot moves): for MakeAsym's epsilon mover, its
#: correctness sentence "more than 3 robots on G_t keep the SEC" (L1487, L1560); for
#: every other move, the conclusion's "destination which remains invariant during the
#: run time of the algorithm" (L1708-1710).
I6_LABEL_OF_ROLE = {"MakeAsym": LABELS["I6"]}
I6_OTHER_LABEL = "conclusion (L1708-1710)"


class Violation(Exception):
    def __init__(self, invariant: str, instant: int, robots, witness: str,
                 label: str | None = None, time=None):
        self.invariant = invariant
        # the instant inside the event's piece or step (exact, in [0, 1]) when the
        # violation is seen at a critical instant of a motion; None: at the event itself
        self.time = time
        self.label = label or LABELS[invariant]
        self.instant = instant
        self.robots = tuple(robots)
        self.witness = witness
        # robot -> its centre when the check fired (:func:`_located`), exact
        self.positions: dict = {}
        super().__init__(f"{invariant} ({self.label}) violated at event {instant}, robots "
                         f"{list(self.robots)}: {witness}")

    def as_dict(self) -> dict:
        out = {"invariant": self.invariant, "label": self.label, "instant": self.instant,
               "robots": list(self.robots), "witness": self.witness}
        if self.time is not None:
            out["time"] = self.time.text()
        if self.positions:
            out["positions"] = {str(r): [c.text() for c in p]
                                for r, p in sorted(self.positions.items())}
        return out


ALL = tuple(f"I{k}" for k in range(1, 11))


@dataclass
class Checker:
    enabled: frozenset = frozenset(ALL)
    # each invariant's checks; "instants": fresh Looks at critical instants of a motion
    # and just beside them; "nested": of those, instants at a nested radical (a point in
    # a tower); "algebraic": at a root of a cubic or quartic factor (a point of K(alpha));
    # "sided": instants seen only on both sides (no exact value held)
    counts: dict = field(default_factory=lambda: {**{k: 0 for k in ALL}, "instants": 0,
                                                  "nested": 0, "algebraic": 0, "sided": 0})
    in_pattern: set = field(default_factory=set)       # robots ever recognised in P
    undecided_fresh: int = 0      # I3 / I9 Looks skipped: the kernel could not hold them
    frames: tuple = ()                                  # extra frames for I9 (besides mirror)
    # robot -> the plan of its last Look (every mover it named): what I3 compares with
    look_plans: dict = field(default_factory=dict)

    def _on(self, key) -> bool:
        if key in self.enabled:
            self.counts[key] += 1
            return True
        return False

    # -- after a Look -------------------------------------------------------------------
    def after_look(self, world, i, frame, decision, paths):
        t = world.events
        self.in_pattern |= set(decision.pattern.robots)
        mine = paths.get(i)
        if self._on("I2"):
            busy = world.busy()
            if len(busy) > 1:
                raise _located(world, Violation(
                    "I2", t, busy, f"robots {busy} have pending moves at once "
                                f"(robot {i} has just Looked)"))
        if not mine:
            return
        self.look_plans[i] = _plan(paths, decision)
        if self._on("I7") and i in self.in_pattern:
            raise _located(world, Violation(
                "I7", t, [i], f"robot {i} was in the pattern and plans a move"))
        if self._on("I5"):
            for k, rob in enumerate(world.robots):
                if k == i:
                    continue
                for piece in mine:
                    if g.piece_hits(piece, rob.pos):
                        raise _located(world, Violation(
                            "I5", t, [i, k], f"the planned path of robot {i} "
                                        f"{_piece_text(piece)} passes within 2 of robot {k} at "
                                        f"{g.fmt_point(rob.pos)}"))
        if self._on("I4") and (world.robots[i].role or "").startswith("leader"):
            self._nearest(world, i, t, strict=False)
        if self._on("I9"):
            self._frames_agree(world, i, frame, paths, decision, t)

    def _frames_agree(self, world, i, frame, paths, decision, t):
        mine = _plan(paths, decision)
        for other in (IDENTITY, MIRROR) + tuple(self.frames):
            if other == frame:
                continue
            d2, theirs = world.fresh_plan(other)
            agree = None if d2.status == "undecided" else _same_plan(mine, theirs, world.home)
            if agree is None:
                self.undecided_fresh += 1
                continue
            if not agree:
                raise _located(world, Violation("I9", t, sorted(set(mine) | set(theirs)),
                                f"a Look in frame {frame.as_list()} plans {_plan_text(mine)}, "
                                f"one in frame {other.as_list()} plans {_plan_text(theirs)}"))

    def _nearest(self, world, i, t, strict: bool, where: str = ""):
        """The lemma: the mover's distance to C is the minimum over R (at the Look a tie is
        allowed: "no other robot is inside the circle of radius d"; once moving, strictly)."""
        rob = world.robots[i]
        d_i = g.dist2(rob.pos, rob.centre)
        for k in rob.r_set:
            if k == i:
                continue
            d_k = g.dist2(world.robots[k].pos, rob.centre)
            if (d_i - d_k).sign() > (-1 if strict else 0):
                raise _located(world, Violation(
                    "I4", t, [i, k], f"moving robot {i} is at squared distance "
                                f"{d_i.text()} from C = {g.fmt_point(rob.centre)}, robot {k} "
                                f"of R at {d_k.text()}{where}"))

    # -- after an advance ----------------------------------------------------------------
    def after_advance(self, world, i, piece):
        t = world.events
        rob = world.robots[i]
        if self._on("I1"):
            for k, other in enumerate(world.robots):
                if k != i and g.piece_hits(piece, other.pos):
                    # along the piece: the robot standing still (the mover's piece is in
                    # the prose; its point of closest approach is not computed)
                    raise _located(world, Violation(
                        "I1", t, sorted((i, k)), f"robot {i} moving {_piece_text(piece)} "
                        f"comes closer than 2 to robot {k} at {g.fmt_point(other.pos)}"),
                        {k: other.pos})
        if (rob.role or "").startswith("leader") and self._on("I4"):
            self._nearest(world, i, t, strict=True)
        if self._on("I6") and rob.centre is not None:
            self._same_centre(world, i, t, "")
        looked = rob.target is not None                   # no target: a made-up move
        # a joint step's end is checked on a zero-length piece; a mover whose move ended
        # there has arrived, and a fresh Look need not name it again (after_arrival's)
        arrived = not rob.path and isinstance(piece, g.Segment) and piece.start == piece.end
        i3 = looked and not arrived and self._on("I3")
        i9 = looked and "I9" in self.enabled
        if i3 or i9 or ("I6" in self.enabled and rob.centre is not None):
            # the critical instants inside the piece (each exactly when the kernel holds
            # it, and one Look in each stretch between them), then (unless it was the last
            # piece) its end: the fresh Look must name the same mover and target (I3), C
            # must not have moved (I6), and at SEC and symmetry instants (the distance
            # ties among them) the reflected frame must plan what the world's frame
            # plans (I9)  (:mod:`.instants`)
            end = rob.pos
            try:
                points, sided = look_points(piece, world, i, rob.centre,
                                            world.readings.A1 == "sec-r")
                self.counts["sided"] += sided
                self.counts["nested"] += sum(1 for lp in points if is_tower(lp.f))
                self.counts["algebraic"] += sum(1 for lp in points if is_algebraic(lp.f))
                for lp in points:
                    rob.pos = lp.point
                    self.counts["instants"] += 1
                    where = f" ({lp.where})"
                    with _at_time(lp.f):
                        if "I6" in self.enabled and rob.centre is not None:
                            self.counts["I6"] += 1
                            self._same_centre(world, i, t, where)
                        if i3:
                            self._fresh_look(world, i, t, where)
                        if i9 and lp.families & {"sec", "symmetry"}:
                            self.counts["I9"] += 1
                            self._mirror_look(world, [i], t, where)
            finally:
                rob.pos = end
            if i3 and rob.path:
                self._fresh_look(world, i, t, "")

    def _same_centre(self, world, i, t, where: str):
        rob = world.robots[i]
        d = world.fresh_decision(IDENTITY)      # only its centre is read
        if d.centre != rob.centre:
            raise _located(world, Violation(
                "I6", t, [i], f"C moved from {g.fmt_point(rob.centre)} to "
                            f"{g.fmt_point(d.centre)} while robot {i} moves ({rob.role} "
                            f"move), robot {i} at {g.fmt_point(rob.pos)}{where}",
                            label=I6_LABEL_OF_ROLE.get(rob.role, I6_OTHER_LABEL)))

    def _fresh_look(self, world, i, t, where: str):
        rob = world.robots[i]
        d, plan = world.fresh_plan(IDENTITY)
        own = {i: (rob.role, rob.target)}
        agree = None if d.status == "undecided" else (
            _names_the_mover(plan, self.look_plans.get(i) or own, i, world.home)
            if world.readings.A3 == "all" else _same_plan(plan, own, world.home))
        if agree is None:
            self.undecided_fresh += 1
            return
        if not agree:
            raise _located(world, Violation("I3", t, sorted(set(plan) | {i}),
                            f"robot {i} is on its way to {g.fmt_point(rob.target)}; a fresh "
                            f"Look with robot {i} at {g.fmt_point(rob.pos)}{where} plans "
                            f"{_plan_text(plan)} ({d.status}: {d.detail})",
                            label=i3_label(rob.role, rob.kind)))

    # -- after a step of several robots ---------------------------------------------------
    def after_step(self, world, pieces: dict, full=None):
        """One interval of simultaneous motion (``World.advance_together``; the world's
        positions are already the step's end).  I1, exact: each mover's piece against
        every robot standing still, each two movers by their joint motion
        (``geometry.joint_motion_overlap``, a polynomial in the common time, its roots
        isolated exactly); counted once per mover.  Then I3, I4, I6 and I9 at the
        critical instants of the joint motion (:mod:`.joint_instants`): every mover
        where it is at each instant (the step's end is checked by ``after_advance``)."""
        self._joint_collision(world, pieces)
        self._joint_instants(world, pieces, full)

    def _joint_collision(self, world, pieces: dict):
        if "I1" not in self.enabled:
            return
        t = world.events
        movers = sorted(pieces)
        self.counts["I1"] += len(movers)
        for i in movers:
            for k, other in enumerate(world.robots):
                if k not in pieces and g.piece_hits(pieces[i], other.pos):
                    raise _located(world, Violation(
                        "I1", t, sorted((i, k)), f"robot {i} moving {_piece_text(pieces[i])} "
                        f"comes closer than 2 to robot {k} at {g.fmt_point(other.pos)}"),
                        {k: other.pos})
        for x, i in enumerate(movers):
            for k in movers[x + 1:]:
                tau = g.joint_motion_overlap(pieces[i], pieces[k])
                if tau is not None:
                    p, q = pieces[i].at(MQ.rational(tau)), pieces[k].at(MQ.rational(tau))
                    raise _located(world, Violation(
                        "I1", t, [i, k], f"robots {i} and {k} move at once (robot {i} "
                        f"{_piece_text(pieces[i])}, robot {k} {_piece_text(pieces[k])}); at "
                        f"time {tau} of the interval robot {i} is at {g.fmt_point(p)}, robot "
                        f"{k} at {g.fmt_point(q)}: squared distance {g.dist2(p, q).text()} "
                        f"< 4"), {i: p, k: q})

    def _joint_instants(self, world, pieces: dict, full=None):
        """A fresh Look (I3), C unchanged (I6) and the leader strictly nearest (I4) at
        each critical instant of the joint motion that the kernel holds and at one
        rational instant in each stretch between: all movers moved to that instant.  At
        the ``sec`` and ``symmetry`` instants (and the stretches beside them), I9: a
        fresh Look in the reflected frame plans what one in the world's frame plans
        (with several movers the fresh plan names one of them at most, so I9 compares
        the two fresh plans, not the pending moves: that is I3's job)."""
        movers = sorted(pieces)
        rob = world.robots
        looked = [i for i in movers if rob[i].target is not None]   # not made up (tests)
        i3 = "I3" in self.enabled and bool(looked)
        i6 = "I6" in self.enabled and any(rob[i].centre is not None for i in movers)
        i4 = "I4" in self.enabled and any((rob[i].role or "").startswith("leader")
                                          for i in movers)
        i9 = "I9" in self.enabled
        if not (i3 or i6 or i4 or i9):
            return
        t = world.events
        ends = {i: rob[i].pos for i in movers}
        sec_r = world.readings.A1 == "sec-r"
        shared = None if full is None or not REUSE_JOINT else \
            covered_points(world, full, sec_r)
        entry = (dict(self.counts), self.undecided_fresh)
        if shared is None:
            points, sided = joint_look_points(pieces, world, sec_r)
            motion, scale = None, None
        else:
            points, sided, scale = shared
            motion = _joint_key(self, world, full[0], sec_r)
        self.counts["sided"] += sided
        self.counts["nested"] += sum(1 for jp in points if is_tower(jp.tau))
        self.counts["algebraic"] += sum(1 for jp in points if is_algebraic(jp.tau))
        try:
            for index, jp in enumerate(points):
                done = None if motion is None else _VERDICTS.get((motion, index))
                if done is not None:          # this instant of this motion passed before
                    for name, k in done[0]:
                        self.counts[name] += k
                    self.undecided_fresh += done[1]
                    continue
                before = (dict(self.counts), self.undecided_fresh)
                if motion is None:
                    for i in movers:
                        rob[i].pos = pieces[i].at(jp.tau)
                    tau = jp.tau
                else:
                    for i in movers:
                        rob[i].pos = full[0][i].at(jp.tau)
                    tau = _step_time(scale, jp.tau)   # the time of the (shorter) step
                self.counts["instants"] += 1
                where = f" (time {'?' if tau is None else tau.text()} of the step: {jp.where})"
                with _at_time(tau), _exact_time_for_witness(tau):
                    for i in looked:
                        if i4 and (rob[i].role or "").startswith("leader"):
                            self.counts["I4"] += 1
                            self._nearest(world, i, t, strict=True, where=where)
                        if i6 and rob[i].centre is not None:
                            self.counts["I6"] += 1
                            self._same_centre(world, i, t, where)
                        if i3:
                            self.counts["I3"] += 1
                            self._fresh_look(world, i, t, where)
                    if i9 and jp.families & {"sec", "symmetry"}:
                        self.counts["I9"] += 1
                        self._mirror_look(world, movers, t, where)
                if motion is not None:        # passed: a sibling stop reuses it
                    if len(_VERDICTS) >= _VERDICTS_MAX:
                        _VERDICTS.clear()
                    _VERDICTS[(motion, index)] = (
                        tuple((name, k - before[0].get(name, 0))
                              for name, k in self.counts.items()
                              if k != before[0].get(name, 0)),
                        self.undecided_fresh - before[1])
        except _NoStepTime:
            # a failure at an instant whose time in the step does not divide out (the
            # stop and the instant in two fields): checked again on the step's own
            # instants, for the witness's exact time (the counts as if checked once)
            self.counts.clear()
            self.counts.update(entry[0])
            self.undecided_fresh = entry[1]
            for i in movers:
                rob[i].pos = ends[i]
            self._joint_instants(world, pieces, None)
        finally:
            for i in movers:
                rob[i].pos = ends[i]

    def _mirror_look(self, world, movers, t, where: str):
        """I9 inside a piece (one mover) or a joint step: fresh Looks in the world's
        frame, the reflected one (and the extra frames) plan the same movers and leader
        targets (the fresh plans are compared, not the pending moves: that is I3's)."""
        d0, mine = world.fresh_plan(IDENTITY)
        if d0.status == "undecided":
            self.undecided_fresh += 1
            return
        for other in (MIRROR,) + tuple(self.frames):
            d, theirs = world.fresh_plan(other)
            agree = None if d.status == "undecided" else _same_plan(mine, theirs, world.home)
            if agree is None:
                self.undecided_fresh += 1
                continue
            if not agree:
                at = ", ".join(f"robot {i} at {g.fmt_point(world.robots[i].pos)}"
                               for i in movers)
                moving = (f"robot {movers[0]} moves" if len(movers) == 1 else
                          f"robots {list(movers)} move at once")
                raise _located(world, Violation("I9", t, sorted(set(mine) | set(theirs)),
                                f"{moving}; with {at}{where} a "
                                f"fresh Look in the world's frame plans {_plan_text(mine)}, "
                                f"one in frame {other.as_list()} plans "
                                f"{_plan_text(theirs)}"))


    # -- after an arrival ----------------------------------------------------------------
    def after_arrival(self, world, i):
        t = world.events
        rob = world.robots[i]
        pts = world.positions()
        centre = rob.centre
        if centre is None:            # a move the adversary made up (tests): no Look
            return
        pat = recognise(pts, centre, world.readings.lone)
        if self._on("I8"):
            lost = self.in_pattern - set(pat.robots) - {i}
            defects = definition_defects(pts, pat, world.readings.lone)
            if lost:
                raise _located(world, Violation(
                    "I8", t, sorted(lost), f"robots {sorted(lost)} were in the "
                                f"pattern and are no longer (C = {g.fmt_point(centre)})"))
            if defects:
                raise _located(world, Violation("I8", t, [i], "; ".join(defects)))
        if (rob.role or "").startswith("leader") and self._on("I10"):
            if rob.cut:
                self._cut_progress(world, i, t, pat)
            elif i not in pat.robots:
                raise _located(world, Violation("I10", t, [i], f"leader {i} arrived at "
                                f"{g.fmt_point(rob.pos)} but is not in the recognised pattern "
                                f"about {g.fmt_point(centre)}: P did not grow"))
        self.in_pattern |= set(pat.robots)

    def _cut_progress(self, world, i, t, pat):
        """I10 after a leader move the adversary ended early (non-rigid, after at least
        delta): the progress measure (|R|, the leader's remaining path) decreased when P
        grew, or when a fresh Look plans the same leader to the same target (the rest of
        its path: at least delta shorter; with an epsilon part the same leader, as I3
        compares plans).  Anything else (another mover, another
        target) gives no decrease: the adversary could cut every move there
        (``docs/gathering.md``, "Progress")."""
        if i in pat.robots:
            return
        rob = world.robots[i]
        d, plan = world.fresh_plan(IDENTITY)
        if d.status == "undecided":
            self.undecided_fresh += 1
            return
        # the same leader, to the same target where the move is FormGPattern's alone
        # (a move with an epsilon part, A3 = all, has the mover's own target: I3's rule)
        same = i in plan and _same_plan({i: plan[i]}, {i: (rob.role, rob.target)},
                                        world.home)
        if same is None:
            self.undecided_fresh += 1
            return
        if not same:
            raise _located(world, Violation(
                "I10", t, sorted(set(plan) | {i}), f"the adversary ended leader "
                            f"{i}'s move at {g.fmt_point(rob.pos)}, at least delta along its "
                            f"path to {g.fmt_point(rob.target)}; a fresh Look there plans "
                            f"{_plan_text(plan)} ({d.status}): the progress measure "
                            f"(|R|, the leader's remaining path) does not decrease"))


#: a joint step checks the instants of the whole joint motion that it covers, each
#: verdict shared with the sibling stops of the same motion (``_VERDICTS``); False: every
#: step's own instants, checked anew (the reference the tests compare with)
REUSE_JOINT = True
#: (joint motion key, index of an instant among the motion's look points) -> the counts
#: and undecided Looks its checks added, when they all passed (a failure is never
#: stored: it is checked again, with the stop's own time in its text)
_VERDICTS: dict = {}
_VERDICTS_MAX = 20_000


def _joint_key(checker, world, full_pieces: dict, sec_r: bool) -> tuple:
    """Everything the checks at an instant of a joint motion read: the robots standing
    still, each mover's whole piece, role, kind, C, R, target and last plan, the
    readings, the checker's switches and the deciding function (exact keys:
    :mod:`.state_key`, never ``==``)."""
    def plan_key(plan):
        return None if plan is None else tuple(
            (k, role, point_key(target)) for k, (role, target) in sorted(plan.items()))
    movers = sorted(full_pieces)
    rob = world.robots
    return (tuple(None if k in full_pieces else point_key(r.pos) for k, r in enumerate(rob)),
            tuple((i, piece_key(full_pieces[i]), rob[i].role, rob[i].kind,
                   None if rob[i].centre is None else point_key(rob[i].centre),
                   tuple(sorted(rob[i].r_set)),
                   None if rob[i].target is None else point_key(rob[i].target),
                   plan_key(checker.look_plans.get(i))) for i in movers),
            world.readings, sec_r, checker.enabled, tuple(f.as_list() for f in checker.frames)
            if checker.frames else (),
            # the algorithm deciding (the paper's, the corrected variant, a test's stub):
            # a verdict of one is never another's
            world.decide)


def critical_points(piece, centre, world, mover: int) -> list:
    """The exact points strictly inside ``piece`` where the mover crosses the line through
    C and another robot, or is as far from C as another robot (the ``ray`` and
    ``distance`` instants of :func:`.instants.critical_roots` that the kernel holds):
    ``[(description, point)]``."""
    if centre is None:
        return []
    out = []
    for r in critical_roots(piece, world, mover, centre):
        if r.exact is None:
            continue
        for fam, what in r.tags:
            if fam in ("ray", "distance"):
                out.append((what, piece.at(r.exact)))
    return out


def _located(world, v: Violation, where: dict | None = None) -> Violation:
    """``v`` with the named robots' centres as data (issue 34: witnesses as data beside
    the prose): where they are when the check fires -- at the Look, at the critical
    instant ``v.time`` inside the piece or step (the checker has put the movers there), or
    at the event's end; ``where`` gives them when the world does not hold them."""
    v.positions = dict(where) if where is not None else \
        {r: world.robots[r].pos for r in v.robots}
    return v


def _step_time(scale, tau):
    """The whole motion's instant ``tau`` as a time of the shorter step, or None when it
    does not divide out (an instant and the stop in two fields that do not mix)."""
    try:
        return scale(tau)
    except (TypeError, ValueError, ArithmeticError):
        return None


class _NoStepTime(Exception):
    """A violation seen at an instant of the whole motion whose time in the step is not
    known: the step is checked again on its own instants."""


@contextlib.contextmanager
def _exact_time_for_witness(tau):
    try:
        yield
    except Violation:
        if tau is None:
            raise _NoStepTime() from None
        raise


@contextlib.contextmanager
def _at_time(tau):
    """A violation raised inside marks the instant ``tau`` of the piece or step."""
    try:
        yield
    except Violation as v:
        if v.time is None:
            v.time = tau
        raise


def _plan(paths, decision) -> dict:
    """Mover -> (role, final target)."""
    out = {}
    for r, p in paths.items():
        if p:
            m = decision.move_of(r)
            out[r] = (m.role if m is not None else "leader", p[-1].final)
    return out


def _same_plan(a: dict, b: dict, home) -> bool | None:
    """Same movers, and the same final target for each, except where either plan starts
    with an epsilon move (MakeAsym, Make_SymToAsym): its sense is the mover's own choice
    (reading A8) and a fresh Look during it asks for a further epsilon.  Targets of two
    towers are compared in the run's (``home``: the world's :class:`.run_home.RunHome`);
    None when that cannot be decided (the Look counts as undecided)."""
    if set(a) != set(b):
        return False
    for r in a:
        (role_a, ta), (role_b, tb) = a[r], b[r]
        if role_a == role_b == "leader":
            try:
                if not home.same_point(ta, tb):
                    return False
            except ValueError:
                return None
    return True


def _names_the_mover(fresh: dict, looked: dict, i: int, home) -> bool | None:
    """I3 for mover ``i`` under A3 = all, where a Look names several movers, each making
    its own move: the fresh plan names ``i`` with the same target, and each robot that
    both plans name the same way (as :func:`_same_plan` compares them).  A further mover
    is not ``i``'s business: it may come from another robot's move since ``i``'s Look,
    and its own Look is checked when it moves.  (Asking, as with one mover per Look,
    that the fresh plan name ``i`` alone fired at every Look that named two movers,
    before any motion.)"""
    if i not in fresh:
        return False
    common = set(fresh) & set(looked)
    return _same_plan({r: fresh[r] for r in common}, {r: looked[r] for r in common}, home)


def _plan_text(plan: dict) -> str:
    if not plan:
        return "no move"
    return ", ".join(f"robot {r} ({role}) to {g.fmt_point(p)}"
                     for r, (role, p) in sorted(plan.items()))


def _piece_text(piece) -> str:
    if isinstance(piece, g.Segment):
        return f"along the segment {g.fmt_point(piece.start)} -> {g.fmt_point(piece.end)}"
    return (f"along the arc about {g.fmt_point(piece.centre)} from {g.fmt_point(piece.start)} "
            f"to {g.fmt_point(piece.end)}")
