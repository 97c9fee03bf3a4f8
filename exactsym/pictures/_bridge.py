"""The one place where the plot package reads the library: an analysis -> :class:`.scene.Scene`.

Every import from the rest of exactsym is in this module (plus the stable public names
of :mod:`exactsym.exact`), so that a change of the library's layout touches one file.
A picture is made from one :class:`~exactsym.analysis.Analysis` only: handed a
configuration, this module calls :func:`~exactsym.analysis.analyse` once for the parts the
picture shows, and never the truth, the paper or the audit itself.
Coordinates become floats here, only for drawing (through the kernel's ``float`` of
its numbers, and ``arb`` balls for polar points); nothing drawn decides anything.
"""

from __future__ import annotations

import math
import re
from dataclasses import replace

from flint import arb

from ..analysis import PARTS, analyse
from ..exact import fmpq
from ..geometry.configuration import Configuration, load
from ..errors import InputError
from .scene import Circle, Line, Paper, PaperLevel, Robot, Rotation, Scene, Witness

__all__ = ["scene_of", "analysis_of", "load_configuration", "Configuration", "InputError"]

#: Up to this many ground-truth mirrors are all drawn; above, only the first (a regular
#: 1000-gon has 1000: drawn, they would paint a disc).
MAX_MIRRORS = 24
#: The paper's per-level tests are drawn for at most this many levels of at most
#: :data:`MAX_PAPER_VERTICES` vertices (the rest are listed as not drawn).
MAX_PAPER_LEVELS = 60
MAX_PAPER_VERTICES = 400


def load_configuration(path) -> Configuration:
    """Read a configuration file (the library's reader and validation)."""
    return load(path)


def _float(x) -> float:
    """A float copy of an exact number, for drawing only."""
    return float(x)


def _polar_xy(r2, turn) -> tuple[float, float]:
    r = arb(fmpq(r2)).sqrt()
    t2 = arb(2 * fmpq(turn))
    return (float((r * t2.cos_pi()).mid()), float((r * t2.sin_pi()).mid()))


def _line_angle(key, polar: bool) -> float:
    """Float angle of a line through C from the paper layer's exact line key: the turn
    of the line (polar) or ``(sign x, y/x)`` of its doubled angle's ray (Cartesian)."""
    if polar:
        return 2 * math.pi * _float(key)
    s, q = key
    if s == 0:
        return q * math.pi / 4
    return math.atan2(s * _float(q), s) / 2


#: The parts of an analysis a picture reads -> the field of :class:`~exactsym.analysis.Analysis`
#: that holds each.
FIELDS = {"truth": "truth", "polygons": "level_verdicts", "family": "paper", "audit": "audit"}


def analysis_of(subject, show_paper: bool = False, show_audit: bool = False):
    """An analysis of ``subject`` with the parts a picture shows: ``subject`` itself when
    it has them; else, for a :class:`Configuration` or an analysis lacking some part,
    :func:`analyse` once for the missing parts (a part ``subject`` holds is kept)."""
    config = getattr(subject, "config", subject)
    wanted = {"truth"} | ({"polygons", "family"} if show_paper else set()) | \
        ({"audit"} if show_audit else set())
    given = {} if config is subject else \
        {name: getattr(subject, name, None) for name in ("levels", *FIELDS.values())}
    missing = [part for part in PARTS if part in wanted and given.get(FIELDS[part]) is None]
    if given.get("levels") is not None and not missing:
        return subject
    fresh = analyse(config, sections=missing)
    kept = {name: value for name, value in given.items()
            if value is not None and name != "levels"}
    return replace(fresh, **kept) if kept else fresh


def scene_of(subject, *, show_paper: bool = False, show_audit: bool = False) -> Scene:
    """The :class:`Scene` of ``subject`` (an analysis or a :class:`Configuration`,
    :func:`analysis_of`): ground truth always, the paper's tests and the audit's witnesses
    when asked (they run the paper's algorithms: slower)."""
    analysis = analysis_of(subject, show_paper, show_audit)
    config, ring, group = analysis.config, analysis.levels, analysis.truth
    centre_exact = ring.sec.centre
    centre = (_float(centre_exact[0]), _float(centre_exact[1]))
    if config.polar is not None:
        xy = [_polar_xy(r2, t) for r2, t in config.polar]
        exact = list(config.polar)
    else:
        xy = [(_float(x), _float(y)) for x, y in config.points]
        exact = list(config.points)
    rank = {}
    if group.ordering is not None:
        rank = {i: k for k, i in enumerate(group.ordering)}
    robots = tuple(Robot(i, tuple(exact[i]), config.polar is not None, xy[i], rank.get(i))
                   for i in range(config.n))
    sec_r = math.sqrt(_float(ring.sec.radius_squared))
    sec = Circle("SEC", centre, ring.sec.radius_squared, sec_r, ())
    levels = tuple(Circle(f"G{k + 1}", centre, level.radius_squared,
                          math.sqrt(_float(level.radius_squared)), tuple(level.points))
                   for k, level in enumerate(ring.levels))

    mirrors, total = _mirrors(group, centre, sec_r)
    rotation = Rotation(centre, group.rotations) if group.rotations > 1 else None
    title = config.name or (str(config.source) if not str(config.source).startswith("<")
                            else "configuration")
    notes = []
    paper = witnesses = None
    if show_paper:
        paper, skipped = _paper(analysis, centre)
        if skipped:
            notes.append(f"paper's tests not drawn on {skipped} level(s): past the "
                         f"first {MAX_PAPER_LEVELS}, or over {MAX_PAPER_VERTICES} "
                         "vertices")
    if show_audit:
        witnesses = _witnesses(analysis.audit["discrepancies"], centre, xy, sec_r)
    return Scene(title=title, model=config.model, robots=robots, centre=centre,
                 centre_exact=tuple(centre_exact), sec=sec, levels=levels, group=group.name,
                 rotation=rotation, mirrors=mirrors, mirrors_total=total,
                 leader=group.leader, orderable=group.orderable, paper=paper,
                 audit=witnesses, notes=tuple(notes))


def _mirrors(group, centre, reach) -> tuple[tuple[Line, ...], int]:
    """The ground truth's mirrors: one exact reflection gives the first; the others are
    at multiples of pi/k from it (float angles, for drawing)."""
    m = group.mirrors
    if not m or group.mirror is None:
        return (), m
    g = group.mirror
    if g.turn is not None:
        first = 2 * math.pi * _float(g.turn)
        exact = g.turn
    else:
        (c, s), _ = g.matrix            # ((cos 2a, sin 2a), (sin 2a, -cos 2a))
        first = math.atan2(_float(s), _float(c)) / 2
        exact = g.matrix
    lines = []
    for j in range(m if m <= MAX_MIRRORS else 1):
        lines.append(Line("mirror", centre, first + j * math.pi / m, reach, "mirror",
                          exact if j == 0 else None))
    return tuple(lines), m


def _paper(analysis, centre) -> tuple[Paper, int]:
    """The paper's per-level tests as the analysis found them (its level verdicts: the
    test run, symmetric, straight, skew) and the family layer's leader."""
    ring, result = analysis.levels, analysis.paper
    levels, skipped = [], 0
    for k, level in enumerate(ring.levels):
        if ring.levels[k].radius_squared == 0:
            continue
        if len(levels) >= MAX_PAPER_LEVELS or len(level.points) > MAX_PAPER_VERTICES:
            skipped += 1
            continue
        check = analysis.level_verdicts[k]
        reach = math.sqrt(_float(level.radius_squared))
        # the lines as the strings find them (lemma-straight-sym), when the test reports
        # straight symmetry at all (Check_Symmetry_Even may report skew only)
        straight = tuple(Line(f"G{k + 1}", centre, _line_angle(key, ring.polar),
                              reach, "straight", key)
                         for key in analysis.straight_lines(k)) if check["straight"] else ()
        labels = tuple(level.points)        # the level polygon's vertices, in its order
        n = len(labels)
        pairs = tuple((labels[i], labels[i + n // 2]) for i in range(n // 2)) \
            if check["skew"] and n % 2 == 0 else ()
        levels.append(PaperLevel(k + 1, check["check"], check["symmetric"], straight,
                                 check["skew"], pairs))
    return Paper(tuple(levels), result.leader, result.orderable), skipped


_MAPS = re.compile(r"robot (\d+) -> robot (\d+)")
_LEVEL = re.compile(r"G\(?([\d,]+)")


def _ccw_angle(centre, a, b) -> float:
    ax, ay = a[0] - centre[0], a[1] - centre[1]
    bx, by = b[0] - centre[0], b[1] - centre[1]
    return math.atan2(ax * by - ay * bx, ax * bx + ay * by) % (2 * math.pi)


def _robot_map(w: dict) -> tuple[int, int] | None:
    """The witness's robot pair: the audit's ``robot_map`` data, else its ``maps``
    sentence (written by audits before ``robot_map`` existed, e.g. a stored JSON)."""
    data = w.get("robot_map")
    if isinstance(data, dict) and "from" in data and "to" in data:
        return int(data["from"]), int(data["to"])
    sentence = _MAPS.search(str(w.get("maps", "")))
    return (int(sentence.group(1)), int(sentence.group(2))) if sentence else None


def _witness(d: dict, centre, xy, reach) -> tuple:
    """``(kind, robots, levels, angle, line, text)`` of one discrepancy's witness (the
    audit's dicts: ``maps`` "robot a -> robot b" with ``symmetry``; ``leaders``;
    ``pair`` of level names; ``line`` as a turn)."""
    w = d.get("witness") or {}
    pair = _robot_map(w)
    if pair:
        a, b = pair
        what = str(w.get("symmetry", ""))
        if what.startswith(("mirror", "reflection")):
            mx, my = (xy[a][0] + xy[b][0]) / 2 - centre[0], (xy[a][1] + xy[b][1]) / 2 - centre[1]
            if math.hypot(mx, my) < 1e-12 * (1 + reach):     # a, b opposite: the perpendicular
                mx, my = -(xy[b][1] - xy[a][1]), xy[b][0] - xy[a][0]
            line = Line("witness", centre, math.atan2(my, mx), reach, "witness")
            return ("mirror", (a, b), (), None, line, f"{what or 'mirror'}: robot {a} -> {b}")
        angle = _ccw_angle(centre, xy[a], xy[b])
        return ("rotation", (a, b), (), angle, None, f"{what or 'rotation'}: robot {a} -> {b}")
    if "leaders" in w:
        leaders = tuple(x for x in w["leaders"] if x is not None)
        frames = " / ".join(w.get("frames", ()))
        return ("robots", leaders, (), None, None,
                f"leader {' vs '.join(map(str, leaders))} ({frames} frames)")
    if "pair" in w:
        levels = tuple(int(x) for name in w["pair"] for m in [_LEVEL.match(str(name))] if m
                       for x in m.group(1).split(","))
        return ("levels", (), levels, None, None, f"pair {', '.join(map(str, w['pair']))}")
    if "line" in w and re.fullmatch(r"-?\d+(/\d+)?", str(w["line"])):
        turn = fmpq(*map(int, str(w["line"]).split("/"))) if "/" in str(w["line"]) \
            else fmpq(int(w["line"]))
        line = Line("witness", centre, 2 * math.pi * _float(turn), reach, "witness", turn)
        return ("line", (), (), None, line, f"line through C at {w['line']} turn")
    return ("none", (), (), None, None, "says " + str(d.get("says", "")))


def _witnesses(discrepancies, centre, xy, reach) -> tuple[Witness, ...]:
    """One :class:`Witness` per distinct drawable witness, naming every statement that
    it witnesses (the audit lists a statement once per failing level or pair)."""
    merged: dict = {}
    for d in discrepancies:
        kind, robots, levels, angle, line, text = _witness(d, centre, xy, reach)
        # one entry per drawn thing; statements without a drawable witness, one each
        key = (kind, robots, levels, text if kind == "line" else
               d["statement"] if kind == "none" else None)
        entry = merged.setdefault(key, [[], kind, robots, levels, angle, line, text])
        if d["statement"] not in entry[0]:
            entry[0].append(d["statement"])
    return tuple(Witness(tuple(st), text, kind, robots, levels,
                         centre if kind == "rotation" else None, angle, line)
                 for st, kind, robots, levels, angle, line, text in merged.values())
