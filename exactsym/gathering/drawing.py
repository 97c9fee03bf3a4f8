"""A simulated run as a picture: the one module of the simulator that imports the
pictures package (``exactsym.pictures.run``, the ``plot`` extra), lazily.

:func:`run_picture` turns a :class:`.schedulers.Result` -- its path log, one
:class:`.world.Step` per Look and per advance, exact -- into the plain float data of
``exactsym.pictures.run.Run``.  Floats are made here and only here, for drawing.

Time in the picture: event ``k`` of the run happens at ``t = k``; an advance at event
``k`` moves its robot along its piece during ``[k - 1, k]`` (uniformly: linearly on a
segment, by angle on an arc).  The pattern's layers drawn are those of the complete
pattern of ``n`` robots about the last C seen.  The violation's witness:

* I1 (a collision along a piece moved): the pair, at the first instant of that piece
  where their centres are 2 apart (found in floats on the drawn path: drawing only;
  the exact predicate has decided that they come closer than 2); two robots moving
  at once in one step: both centres at the exact instant ``geometry.joint_motion_overlap``
  gives (``Violation.at``; both in motion, not one against the other's end);
* I5 (a planned path that is not free): at the Look, the planned path, dashed
  (``Run.planned``: not travelled, the run stopped at the Look), and the two discs where
  the path first touches the other robot (``Violation.at``, found in floats);
* any other invariant naming two robots: the pair at the violation's event -- or, when
  it was seen at a critical instant inside the last piece or step (``Result.violation_time``,
  tau in [0, 1]), at that instant, ``t = k - 1 + tau`` (exact on segments; on an arc the
  picture's uniform angle stands in for the piece's parameter); naming one or three and
  more: the robots highlighted by an event text, no pair.
"""

from __future__ import annotations

import math

from ..exact.multiquadratic import MQ
from . import geometry as g
from .pattern import capacity

__all__ = ["add_arguments", "wants_pictures", "run_picture", "write_pictures",
           "PICTURE_OPTIONS"]

PICTURE_OPTIONS = ("plot", "frames", "gif", "html")
_MISSING = ("pictures need matplotlib, the `plot` extra: pip install 'exactsym[plot]' "
            "(from a checkout: pip install -e '.[plot]')")


def add_arguments(parser) -> None:
    """``--plot OUT``, ``--frames DIR``, ``--gif OUT.gif``, ``--html OUT.html``."""
    grp = parser.add_argument_group("pictures (the plot extra: matplotlib)")
    grp.add_argument("--plot", metavar="OUT", default=None,
                     help="the whole run in one picture (.svg, .png or .pdf): paths, the "
                     "pattern's layers, the violation's pair and instant")
    grp.add_argument("--frames", metavar="DIR", default=None,
                     help="one PNG per event in DIR (and one of the start)")
    grp.add_argument("--gif", metavar="OUT", default=None, help="an animated GIF of the frames")
    grp.add_argument("--html", metavar="OUT", default=None,
                     help="one self-contained HTML page to step through the frames")


def wants_pictures(args) -> bool:
    return any(getattr(args, k, None) for k in PICTURE_OPTIONS)


def _xy(p) -> tuple:
    return (float(p[0]), float(p[1]))


def _piece(piece, R):
    """A simulator piece as a picture path (``R``: the pictures' run module)."""
    if isinstance(piece, g.Segment):
        return R.Segment(_xy(piece.start), _xy(piece.end))
    return R.Arc.through(_xy(piece.centre), _xy(piece.start), _xy(piece.end), piece.sense)


def _chord(piece) -> float:
    """The distance between a piece's ends, from the exact difference (an epsilon move's
    ends are equal as doubles): for the picture's "too small to draw"."""
    dx, dy = piece.start[0] - piece.end[0], piece.start[1] - piece.end[1]
    return math.sqrt(float(dx * dx + dy * dy))


def _first_contact(path, other, steps: int = 400) -> float:
    """The first parameter of ``path`` (a picture path) where the distance to ``other``
    is at most 2 (floats: where to draw the collision); 1.0 when none is found."""
    def close(s):
        x, y = path.at(s)
        return math.hypot(x - other[0], y - other[1]) <= 2.0
    prev = 0.0
    if close(0.0):
        return 0.0
    for k in range(1, steps + 1):
        s = k / steps
        if close(s):
            lo, hi = prev, s
            for _ in range(50):
                mid = (lo + hi) / 2
                lo, hi = (lo, mid) if close(mid) else (mid, hi)
            return hi
        prev = s
    return 1.0


def _joint_witness(piece_a, piece_b):
    """``(tau, (centre a, centre b))`` at the instant of the common interval where two
    robots moving at once are closer than 2 (``geometry.joint_motion_overlap``, exact;
    floats only for drawing), or None."""
    tau = g.joint_motion_overlap(piece_a, piece_b)
    if tau is None:
        return None
    t = MQ.rational(tau)
    return float(tau), (_xy(piece_a.at(t)), _xy(piece_b.at(t)))


def _layers(n: int, centre, R) -> tuple:
    """The circles (radius 2L) of the complete pattern of ``n`` robots about ``centre``."""
    out, placed, L = [], 1, 1
    while placed < n:
        out.append(R.Layer(f"layer {L}", centre, 2.0 * L))
        placed += capacity(L)
        L += 1
    return tuple(out)


def _title(name: str, res) -> str:
    if res.outcome == "violated":
        v = res.violation
        return f"{name}: violated, {v['label']} ({v['invariant']}) at event {v['instant']}"
    return f"{name}: {res.outcome}, {res.events} events"


def run_picture(points, res, name: str = "run", model: str = "fat"):
    """The ``exactsym.pictures.run.Run`` of a simulated run (``points``: the start)."""
    R = _run_module()
    start = tuple(_xy(p) for p in points)
    now = list(start)                       # positions as the log goes (floats)
    moves, events = [], []
    centre = None
    for step in res.log:
        t = float(step.event)
        if step.kind == "look":
            centre = _xy(step.centre) if step.centre is not None else centre
            what = "plans a move" if step.pieces else "stays"
            events.append(R.Event(t, f"event {step.event}: robot {step.robot} Looks and "
                                  f"{what}", (step.robot,)))
        else:
            path = _piece(step.pieces[0], R)
            moves.append(R.Move(step.robot, t - 1.0, t, path, _chord(step.pieces[0])))
            now[step.robot] = path.end
            events.append(R.Event(t, f"event {step.event}: robot {step.robot} moves",
                                  (step.robot,)))
    violation, planned, at = None, (), None
    v = res.violation
    if v is not None and len(v["robots"]) == 2:
        a, b = v["robots"]
        when = float(v["instant"])
        text = f"{v['invariant']} {v['label']}"
        last = res.log[-1] if res.log else None
        step = {s.robot: s for s in res.log
                if last is not None and s.event == last.event and s.kind == "advance"}
        if v["invariant"] == "I1" and a in step and b in step:
            # two robots moving at once: both where they are at the exact instant the
            # joint check found (not one against the other's end position)
            at = _joint_witness(step[a].pieces[0], step[b].pieces[0])
            if at is not None:
                tau, at = at
                when = float(last.event) - 1.0 + tau
            text = f"robots {a} and {b} move at once and collide ({text})"
        elif v["invariant"] == "I1" and moves and last is not None and last.kind == "advance":
            mover = a if a in step else b
            other = b if mover == a else a
            move = next(m for m in reversed(moves) if m.robot == mover)
            s = _first_contact(move.path, now[other])
            when = move.start_time + s
            text = f"collision ({text})"
        elif (res.violation_time is not None and last is not None
              and last.kind == "advance"):
            when = float(last.event) - 1.0 + float(res.violation_time)
        elif v["invariant"] == "I5" and last is not None and last.kind == "look":
            planned = tuple(_piece(piece, R) for piece in last.pieces)
            mover = last.robot
            other = b if mover == a else a
            for path in planned:
                s = _first_contact(path, now[other])
                if s < 1.0:
                    at = (path.at(s), now[other])
                    break
            text = (f"the path robot {mover} plans passes within 2 of robot {other} "
                    f"({text})")
        violation = R.Violation((a, b), when, text, at)
    elif v is not None:
        events.append(R.Event(float(v["instant"]), f"{v['invariant']} {v['label']}: robots "
                              f"{v['robots']}", tuple(v["robots"])))
    if centre is None and res.pattern:
        centre = tuple(float(x) for x in _parse_centre(res.pattern["centre"]))
    layers = _layers(len(points), centre, R) if centre is not None else ()
    return R.Run(_title(name, res), model, start, tuple(moves), layers, tuple(events),
                 violation, planned=planned)


def _parse_centre(items):
    from fractions import Fraction
    out = []
    for text in items:
        try:
            out.append(float(Fraction(text)))
        except ValueError:
            out.append(float("nan"))
    return out


def _run_module():
    """``exactsym.pictures.run`` (the pictures package; the only import of it here)."""
    try:
        from ..pictures import run as R
        from ..pictures.draw import matplotlib_modules
        matplotlib_modules()
    except (ImportError, RuntimeError) as err:   # RuntimeError: the PlotUnavailable
        raise PicturesUnavailable(_MISSING) from err
    return R


class PicturesUnavailable(RuntimeError):
    """matplotlib (the ``plot`` extra) is not installed."""


def write_pictures(points, res, args, name: str = "run") -> list[str]:
    """Write the pictures ``args`` asks for (``--plot``, ``--frames``, ``--gif``,
    ``--html``); the lines to print.  Raises :class:`PicturesUnavailable` without
    matplotlib, ``ValueError``/``OSError`` for an output that cannot be written."""
    run = run_picture(points, res, name)
    from ..pictures.run_cli import outputs
    return outputs(run, args)
