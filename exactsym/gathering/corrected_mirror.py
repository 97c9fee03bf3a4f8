"""The corrected variant's first move on a start with a mirror and a leader (issue 31):
``docs/gathering-corrected.md``, step 11; ``proofs/gathering-corrected.md``, Lemma 8.

A start whose symmetry group is D1 has a robot fixed by its symmetry when a robot lies
on the mirror line; the ground truth names one of them, the *leader*
(:func:`.corrected_choice.mirror_leader`, canonical: the same robot in every frame).
Every rule of :mod:`.corrected` needs the configuration after a completed move to have
a leader, and from a D1 snapshot no single robot's move keeps the mirror and ends
orderable except a move off the mirror; so the variant would answer ``not-possible``.
Here the leader makes that move itself, in two kinds of step (role ``asym``):

* **in along the mirror** (``in``): while it is not the only robot nearest to C, it
  moves along its ray from C (which is the mirror line: C, the SEC centre, is on it) to
  the point at squared distance ``lambda^2 d`` from C, ``d`` the smallest squared
  distance of the others, for the first ``lambda`` of 1/2, 1/4, 1/8 whose segment is
  clear, keeps C and from whose end the step off can be made.  The configuration keeps
  its mirror; every frame plans the same point (a distance and the ray).
* **off the mirror** (``off``): once it is the only nearest robot, it turns about C on
  its own circle by the rational rotation of half-angle tangent 1/16 (then 1/32, 1/64),
  in the counter-clockwise sense *of the observer's frame*.  This is the one choice of
  the variant that reads the frame's handedness: the two senses give configurations that
  the start's own mirror maps onto each other (the mirror fixes the leader, and C), so
  the frames name the same mover and plans that differ by the configuration's own
  symmetry -- I9 compares the movers of such a move, not its target (the rule of
  ``invariants._same_plan`` for the paper's epsilon moves).  The step is taken only if
  its path is clear, keeps C, ends in a configuration with a leader, and the plain rule
  of :mod:`.corrected` names the leader (its step aside, or its own move) from the end
  of the arc and from two points inside it (tangents t/2, t/4): a Look during the step
  names the same mover.

``plain`` is the decision of :mod:`.corrected` without this rule (passed in, so that this
module does not import the one that calls it).
"""

from __future__ import annotations

from flint import fmpq

from . import geometry as g
from .corrected_choice import SortKey, keeps_a_leader, mirror_leader
from .corrected_paths import outward_point, path_is_clear, rotate_about
from .robot import Decision, Move

#: tan(angle / 2) of the step off the mirror, largest first.
OFF_TANGENTS = (fmpq(1, 16), fmpq(1, 32), fmpq(1, 64))

#: The fractions of the nearest other robot's distance the leader goes in to.
IN_FRACTIONS = (fmpq(1, 2), fmpq(1, 4), fmpq(1, 8))


def mirror_step(pts, centre, pat, R, unit, approx, tower, readings, plain, keeps_centre):
    """The leader's step (a :class:`.robot.Decision` with one ``asym`` move), or None
    when the snapshot is not D1 with a leader off C, there is a pattern already, or no
    step passes its tests.  ``plain(after_pts)``: the plain decision on a snapshot;
    ``keeps_centre(path, mover)``: :func:`.corrected._keeps_centre` on this snapshot."""
    if pat.centre_robot is not None or len(R) != len(pts):
        return None
    lead = mirror_leader(pts)
    if lead is None or pts[lead] == centre:
        return None
    step = _off(pts, centre, lead, unit, approx, plain, keeps_centre)
    if step is None:
        step = _in(pts, centre, lead, unit, approx, tower, plain, keeps_centre)
    if step is None:
        return None
    path, how = step
    return Decision("move", (Move(lead, path, "asym"),), centre, pat, None,
                    f"corrected: a start with a mirror and a leader (robot {lead}, on the "
                    f"mirror, ground truth): it steps {how}")


def _nearest_alone(pts, centre, lead) -> bool:
    d = g.dist2(pts[lead], centre)
    return all((g.dist2(q, centre) - d).sign() > 0 for j, q in enumerate(pts) if j != lead)


def _names(plain, pts, lead, where) -> bool:
    after = list(pts)
    after[lead] = where
    d = plain(after)
    return any(m.robot == lead for m in d.moves)


def _off(pts, centre, lead, unit, approx, plain, keeps_centre):
    """The turn about C off the mirror, in the observer's counter-clockwise sense."""
    if not _nearest_alone(pts, centre, lead):
        return None
    p = pts[lead]
    for t in OFF_TANGENTS:
        target = rotate_about(centre, p, t, 1)
        path = tuple(g.arc_path(centre, p, target, 1))
        if not (path_is_clear(path, pts, lead, unit * unit, frozenset(), approx)
                and keeps_centre(path, lead) and keeps_a_leader(pts, lead, target)):
            continue
        inside = [rotate_about(centre, p, t / k, 1) for k in (2, 4)]
        if all(_names(plain, pts, lead, q) for q in [target] + inside):
            return path, "off the mirror (a turn about C)"
    return None


def _in(pts, centre, lead, unit, approx, tower, plain, keeps_centre):
    """In along the mirror to a fraction of the nearest other robot's distance, when the
    step off can be made from there."""
    d_lead = g.dist2(pts[lead], centre)
    d_min = min((g.dist2(q, centre) for j, q in enumerate(pts) if j != lead), key=SortKey)
    for lam in IN_FRACTIONS:
        r2 = d_min * lam * lam
        if (r2 - d_lead).sign() >= 0:
            continue
        target = outward_point(centre, pts[lead], r2, tower)
        if target is None:
            continue
        path = (g.Segment(pts[lead], target),)
        if not (path_is_clear(path, pts, lead, unit * unit, frozenset(), approx)
                and keeps_centre(path, lead)):
            continue
        after = list(pts)
        after[lead] = target
        if _off(after, centre, lead, unit, g.approx_points(after), plain,
                lambda pth, m: True) is not None:
            return path, "in along the mirror"
    return None
