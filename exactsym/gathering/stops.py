"""Where the adversary may stop a mover: rational points and exact critical instants.

The model lets the adversary stop a moving robot anywhere on its piece (spec section 1;
``docs/gathering.md``, "Stops"): the paper's robots act asynchronously under CORDA
("the movement of the robots is not instantaneous. While in motion, a robot may be
observed by other robots", L200-208), so a Look may happen with a mover at any point of
its path -- at a graze, where ``gather-no-obstacle`` is tight, or at a tie, where
``obs-v-move``'s fresh Look can change.  A trace names a stop in one of two ways:

* a **rational fraction** of the piece, a string (``"3/7"``): the point ``piece.at(f)``
  (on an arc, the rational rotation's parameter, so the point stays in the field);
* an **exact critical instant** of the current motion, a root of one of the relations
  that :mod:`.instants` (one mover) or :mod:`.joint_instants` (a joint step: every mover
  of the step at full speed, the instant ``tau`` common to all) enumerates -- a graze, a
  distance tie, an SEC change, a symmetry instant -- whose value is often irrational: a
  quadratic irrational (multiquadratic) or a nested radical (a number of the run's
  tower).  Such a stop is recorded as ``{"instant": k, "lo": "a/b", "hi": "c/d",
  "value": "0.41421356..."}``: ``k`` its index among the critical instants of that
  motion at that state (in increasing order), ``(lo, hi)`` a rational interval holding
  it and no other instant, ``value`` a decimal for the reader only.  Replaying it
  recomputes the instants of the same motion in the same state (a pure function of the
  state), takes the ``k``-th and checks exactly that it lies in ``(lo, hi)``
  (:class:`.schedulers.TraceMismatch` otherwise).

A root of a cubic or quartic factor (a number of K(alpha)) is not offered as a stop:
K(alpha) numbers do not mix with the run's tower (:func:`.run_home.mixes`), and a robot
standing at such a point would make every later instant a polynomial over K(alpha).

:func:`simplest_between` picks the stop inside a stretch between two instants: the
rational of least height there (on an arc, the one whose remaining arc has the simplest
half-angle tangent), so that repeated stops do not double the size of the numbers (a stop
at 1/2 of an arc's parameter squares the height of the remaining arc's tangent).
"""

from __future__ import annotations

from fractions import Fraction
from math import floor

from flint import fmpq

from ..exact.algebraic.algebraic_numbers import is_algebraic
from ..exact.algebraic.interface import float_and_error
from ..exact.multiquadratic import MQ
from . import geometry as g
from .instants import critical_roots
from .joint_instants import joint_critical_roots, joint_look_points
from .run_home import instant_or_none
from .state_key import piece_key, point_key, shared_by_copies, state_key, tower_free

__all__ = ["simplest_between", "stretch_stop", "instant_stop", "motion_roots", "resolve",
           "before_stop", "covered_points",
           "stop_record", "exact_instant"]


def simplest_between(a: Fraction, b: Fraction) -> Fraction:
    """The rational of least denominator strictly between ``a < b`` (continued
    fractions: the Stern-Brocot tree's first node inside the open interval)."""
    if not a < b:
        raise ValueError(f"an empty interval ({a}, {b})")
    n = floor(a)
    if n + 1 < b:
        return Fraction(n + 1)
    lo, hi = a - n, b - n                  # 0 <= lo < hi <= 1
    if lo == 0:
        return n + Fraction(1, floor(1 / hi) + 1)
    return n + 1 / simplest_between(1 / hi, 1 / lo)


def _fraction(q) -> Fraction:
    return Fraction(int(q.p), int(q.q))


def _arc_tangent(piece) -> Fraction | None:
    """The half-angle tangent of an arc piece when it is rational (None otherwise)."""
    a, b = g.sub(piece.start, piece.centre), g.sub(piece.end, piece.centre)
    t = g.cross(a, b) / (g.dot(a, a) + g.dot(a, b))
    return _fraction(t.to_fmpq()) if t.is_rational() else None


def stretch_stop(piece, a: Fraction, b: Fraction) -> Fraction:
    """A rational stop strictly inside ``(a, b)`` (``0 <= a < b <= 1``, a stretch of
    ``piece`` between two instants): the simplest rational there; on an arc of rational
    half-angle tangent ``T``, the fraction whose remaining arc has the simplest tangent
    ``u`` (``u(f) = T (1 - f) / (1 + f T^2)``, monotone in ``f``; inverted exactly)."""
    tan = _arc_tangent(piece) if isinstance(piece, g.Arc) else None
    if not tan:
        return simplest_between(a, b)

    def rest(f):
        return tan * (1 - f) / (1 + f * tan * tan)
    ua, ub = rest(a), rest(b)
    u = simplest_between(min(ua, ub), max(ua, ub))
    f = (tan - u) / (tan * (1 + tan * u))
    return f if a < f < b else simplest_between(a, b)


def exact_instant(root, pieces):
    """The root's value as an instant the pieces can move to, or None: a rational, a
    multiquadratic irrational or a nested radical re-homed into the pieces' tower; not
    a number of K(alpha)."""
    if root.exact is None or is_algebraic(root.exact):
        return None
    return instant_or_none(root.exact, pieces)


def instant_stop(roots, k: int) -> dict:
    """The trace form of the ``k``-th critical instant (see the module docstring)."""
    r = roots[k]
    value, _err = float_and_error(r.exact)
    return {"instant": k, "lo": str(_fraction(r.lo)), "hi": str(_fraction(r.hi)),
            "value": f"{value:.12g}"}


#: (motion key) -> its critical instants, when every exact value is valid in every copy
#: of the world (:func:`.state_key.shared_by_copies`: a multiquadratic number, one of
#: K(alpha), a nested radical of an instant's own tower; not a number of a run's tower,
#: which each copy, :func:`.search.fork`, owns); the search offers the stops of a state
#: and then applies each in a copy of it
_ROOTS: dict = {}
_ROOTS_MAX = 256


def _motion_key(world, movers) -> tuple:
    """Everything the critical instants of the motion depend on: every position and
    pending path (:func:`.state_key.state_key`), the readings, and each mover's C and R
    at its Look (exact keys, never ``==`` on numbers)."""
    return (state_key(world), world.readings, tuple(movers),
            tuple((None if world.robots[i].centre is None else point_key(world.robots[i].centre),
                   tuple(sorted(world.robots[i].r_set))) for i in movers))


def motion_roots(world, movers) -> list:
    """The critical instants of the motion of ``movers`` along their current pieces
    (one mover: :func:`.instants.critical_roots`; several: the joint motion's)."""
    sec_r = world.readings.A1 == "sec-r"
    movers = sorted(movers)
    key = _motion_key(world, movers)
    roots = _ROOTS.get(key)
    if roots is not None:
        return roots
    if len(movers) == 1:
        i = movers[0]
        rob = world.robots[i]
        roots = critical_roots(rob.path[0], world, i, rob.centre, sec_r)
    else:
        roots = joint_critical_roots({i: world.robots[i].path[0] for i in movers}, world,
                                     sec_r)
    if tower_free(world) and all(shared_by_copies(r.exact) for r in roots):
        if len(_ROOTS) >= _ROOTS_MAX:
            _ROOTS.clear()
        _ROOTS[key] = roots
    return roots


def piece_stops(world, movers) -> list:
    """The stops the adversary offers for ``movers`` (their current pieces): one
    rational in each stretch between consecutive instants and every instant that a
    stop can be -- rationals as strings, irrational instants as trace dicts; in order.
    ValueError / ArithmeticError when the kernel cannot hold the instants."""
    roots = motion_roots(world, movers)
    piece = world.robots[min(movers)].path[0]
    pieces = [world.robots[i].path[0] for i in movers]
    out, left = [], Fraction(0)
    for k, r in enumerate(roots):
        lo, hi = _fraction(r.lo), _fraction(r.hi)
        out.append(str(stretch_stop(piece, left, lo) if left < lo else lo))
        value = exact_instant(r, pieces)
        if value is not None:
            q = _rational_value(value)
            out.append(str(q) if q is not None else instant_stop(roots, k))
        left = hi
    out.append(str(stretch_stop(piece, left, Fraction(1))))
    return [s for s in out if isinstance(s, dict) or 0 < Fraction(s) < 1]


def before_stop(x, f) -> bool | None:
    """Is the instant ``x`` strictly before the stop ``f`` (both exact)?  By the sign of
    ``x - f``; for numbers that do not mix (two instants' own towers): False when ``x``
    is ``f`` itself (the stop resolved from this instant, :func:`.stops.resolve`), else
    by Arb balls when they are apart (a proven enclosure, never a float's guess); None
    when undecided (the caller then computes the step's own instants).  ``x`` and ``f``
    are instants of one motion, each separated from the others (:func:`motion_roots`)."""
    try:
        return (x - f).sign() < 0
    except (TypeError, ValueError, ArithmeticError):
        pass
    if x is f:
        return False
    try:
        (vx, ex), (vf, ef) = float_and_error(x), float_and_error(f)
    except (AttributeError, TypeError, ValueError, ArithmeticError):
        return None
    if vx + ex < vf - ef:
        return True
    if vx - ex > vf + ef:
        return False
    return None


def _rational_value(x) -> Fraction | None:
    """``x`` as a Fraction when it is rational, else None."""
    try:
        return _fraction(x.to_fmpq()) if x.is_rational() else None
    except (AttributeError, ValueError):
        return None


def resolve(world, movers, stop):
    """The stop of a trace action as the instant :meth:`.world.World.advance` takes:
    None (the piece's end), a Fraction, or an exact irrational instant (recomputed from
    the state, checked against the recorded interval; ValueError when it is not there)."""
    if stop is None:
        return None
    if not isinstance(stop, dict):
        return Fraction(stop)
    k = int(stop["instant"])
    lo, hi = Fraction(stop["lo"]), Fraction(stop["hi"])
    roots = motion_roots(world, movers)
    if not 0 <= k < len(roots):
        raise ValueError(f"the motion has {len(roots)} critical instants, not an instant {k}")
    value = exact_instant(roots[k], [world.robots[i].path[0] for i in movers])
    if value is None:
        raise ValueError(f"critical instant {k} of the motion has no exact value here")
    if (value - fmpq(lo.numerator, lo.denominator)).sign() <= 0 or \
            (value - fmpq(hi.numerator, hi.denominator)).sign() >= 0:
        raise ValueError(f"critical instant {k} of the motion is not in ({lo}, {hi})")
    return value


def stop_record(stop):
    """How a trace writes a stop: None, a dict as it is, else the fraction as a string."""
    if stop is None or isinstance(stop, dict):
        return stop
    return str(stop)


#: (the whole joint motion and the state before it) -> its look points, when each is
#: valid in every copy of the world (:func:`.state_key.shared_by_copies`; each copy,
#: :func:`.search.fork`, owns its run's tower)
_POINTS: dict = {}
_POINTS_MAX = 512


def _whole_motion_points(world, pieces: dict, before: dict, sec_r: bool) -> tuple:
    """:func:`.joint_instants.joint_look_points` of the whole pieces, computed on the
    state before the step (every mover at its piece's start, its whole path pending):
    the same for every stop of the motion, so computed once for them all."""
    rob = world.robots
    key = (tuple((point_key(r.pos) if k not in pieces else None,
                  tuple(piece_key(pc) for pc in (before[k][1] if k in pieces else r.path)),
                  None if r.target is None else point_key(r.target),
                  None if r.centre is None else point_key(r.centre), tuple(sorted(r.r_set)))
                 for k, r in enumerate(rob)), tuple(sorted(pieces)), world.readings, sec_r)
    got = _POINTS.get(key)
    if got is not None:
        return got
    after = {i: (rob[i].pos, rob[i].path) for i in pieces}
    try:
        for i in pieces:
            rob[i].pos, rob[i].path = before[i][0], before[i][1]
        # the roots the step's stops were resolved from (the same state and motion):
        # an exact stop is then the very object of its instant (:func:`.stops.before_stop`)
        free = tower_free(world)
        got = joint_look_points(pieces, world, sec_r, motion_roots(world, sorted(pieces)))
    finally:
        for i in pieces:
            rob[i].pos, rob[i].path = after[i]
    if free and all(shared_by_copies(jp.tau) for jp in got[0]):
        if len(_POINTS) >= _POINTS_MAX:
            _POINTS.clear()
        _POINTS[key] = got
    return got


def _not_after(f, lo) -> bool:
    """Is the stop ``f`` at or before the rational ``lo`` (exactly; False when unknown)?
    Then an instant isolated in ``(lo, hi)`` lies after the stop."""
    if lo is None:
        return False
    try:
        return (f - MQ.rational(fmpq(lo))).sign() <= 0
    except (TypeError, ValueError, ArithmeticError):
        return False


def covered_points(world, full, sec_r: bool):
    """``(points, sided, scale)`` for a joint step that moved every mover from the start
    of its piece ``full[0][i]`` to the common stop ``full[1]`` (None: the pieces' ends):
    the look points of the whole motion (:func:`.joint_instants.joint_look_points`) that
    lie before the stop, and ``scale`` mapping the whole motion's time to the step's.
    A piece's prefix moves along the piece's own parametrisation (``split(f)``:
    ``prefix.at(s) = piece.at(f s)``, segment and arc alike), so the step's instants are
    the whole motion's before ``f`` and each stretch between them is sampled by the
    whole motion's point there.  None when a stretch of the step holds no such point
    (the stop inside the first stretch, or inside an instant's isolating interval: an
    instant without an exact value is placed by that interval, ``JointPoint.root_from``)
    or a comparison fails: the caller computes the step's own instants."""
    pieces, f, before = full
    points, sided = _whole_motion_points(world, pieces, before, sec_r)
    if f is None:
        return points, sided, (lambda tau: tau)
    kept = []
    for jp in points:
        b = before_stop(jp.tau, f)
        if b is None:
            return None
        if not b:
            break
        kept.append(jp)
    if not kept or kept[-1].exact:
        return None
    after = points[len(kept):len(kept) + 1]
    if after and not after[0].exact and after[0].where.startswith("just after") and \
            not _not_after(f, after[0].root_from):
        return None               # an instant not held: is it before the stop?
    held = sum(1 for jp in kept if jp.exact)
    sided_kept = sum(1 for jp in kept if jp.where.startswith("just after")) - held
    if getattr(f, "is_rational", lambda: False)():
        q = f.to_fmpq()
        inv = MQ.rational(fmpq(q.q, q.p))
        return kept, sided_kept, (lambda tau: tau * inv)
    return kept, sided_kept, (lambda tau: tau / f)
