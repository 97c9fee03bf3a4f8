"""Pictures of a gathering run: a still, one frame per event, an animated GIF and a
standalone HTML stepper.

A run is plain data (:class:`Run`), filled by whoever simulated it; floats only, since
pictures decide nothing.  Each robot starts at ``Run.start[i]`` and follows its
:class:`Move`\\ s, each a straight :class:`Segment` or a circular :class:`Arc`,
traversed uniformly between ``start_time`` and ``end_time`` (a robot's moves must not
overlap in time).  ``layers`` are the circles of the target pattern; ``violation``
names the colliding pair and the instant.  :func:`run_from_dict` reads the same data
from JSON-like dicts (the format is :func:`run_to_dict`'s output).

Frames are drawn at :func:`frame_times`: the first instant, every event, the end of
every move and the violation.
"""

from __future__ import annotations

import io
import math
import textwrap
from dataclasses import asdict, dataclass, field
from pathlib import Path

from .draw import COLOURS, DPI, METADATA, RC, matplotlib_modules

Point = tuple[float, float]


@dataclass(frozen=True)
class Segment:
    """A straight move from ``start`` to ``end``."""
    start: Point
    end: Point

    def at(self, s: float) -> Point:
        return (self.start[0] + s * (self.end[0] - self.start[0]),
                self.start[1] + s * (self.end[1] - self.start[1]))


@dataclass(frozen=True)
class Arc:
    """A move along the circle about ``centre`` of ``radius``, from ``start_angle`` to
    ``end_angle`` (radians; counter-clockwise when ``end_angle > start_angle``)."""
    centre: Point
    radius: float
    start_angle: float
    end_angle: float

    def at(self, s: float) -> Point:
        a = self.start_angle + s * (self.end_angle - self.start_angle)
        return (self.centre[0] + self.radius * math.cos(a),
                self.centre[1] + self.radius * math.sin(a))

    @classmethod
    def through(cls, centre: Point, start: Point, end: Point, sense: int) -> "Arc":
        """The arc about ``centre`` from ``start`` to ``end`` (both on one circle),
        counter-clockwise when ``sense > 0``, going the short way round in that sense."""
        a0 = math.atan2(start[1] - centre[1], start[0] - centre[0])
        a1 = math.atan2(end[1] - centre[1], end[0] - centre[0])
        sweep = (a1 - a0) % (2 * math.pi) if sense > 0 else -((a0 - a1) % (2 * math.pi))
        return cls(tuple(centre), math.dist(start, centre), a0, a0 + sweep)

    @property
    def start(self) -> Point:
        return self.at(0.0)

    @property
    def end(self) -> Point:
        return self.at(1.0)


@dataclass(frozen=True)
class Move:
    robot: int
    start_time: float
    end_time: float
    path: Segment | Arc
    #: the distance between the move's ends when the simulator knows it better than the
    #: floats of ``path`` (an epsilon move of 1e-19 has equal float ends); None: from path
    size: float | None = None


@dataclass(frozen=True)
class Layer:
    """A circle of the target pattern."""
    label: str
    centre: Point
    radius: float


@dataclass(frozen=True)
class Event:
    time: float
    text: str
    robots: tuple[int, ...] = ()


@dataclass(frozen=True)
class Violation:
    """Robots ``robots`` collide (or come closer than allowed) at ``time``.  ``at``: the
    two centres where they would touch, when that is not where they are at ``time``
    (a planned path that is not free): drawn as dashed discs joined by the bar."""
    robots: tuple[int, int]
    time: float
    text: str = "collision"
    at: tuple[Point, Point] | None = None


@dataclass(frozen=True)
class Run:
    name: str
    model: str                      # "fat" (unit discs) or "points"
    start: tuple[Point, ...]
    moves: tuple[Move, ...] = ()
    layers: tuple[Layer, ...] = ()
    events: tuple[Event, ...] = ()
    violation: Violation | None = None
    notes: tuple[str, ...] = field(default=())
    #: paths planned but not travelled (a run stopped at the Look that planned them):
    #: drawn dashed, never moving a robot
    planned: tuple[Segment | Arc, ...] = field(default=())

    def __post_init__(self):
        by_robot: dict = {}
        for m in self.moves:
            if not 0 <= m.robot < len(self.start):
                raise ValueError(f"move of robot {m.robot}: there are {len(self.start)} robots")
            if m.end_time < m.start_time:
                raise ValueError(f"move of robot {m.robot} ends before it starts")
            by_robot.setdefault(m.robot, []).append(m)
        for robot, ms in by_robot.items():
            ms.sort(key=lambda m: m.start_time)
            for a, b in zip(ms, ms[1:]):
                if b.start_time < a.end_time:
                    raise ValueError(f"robot {robot}: moves overlap in time "
                                     f"({a.start_time}..{a.end_time} and {b.start_time}..)")


def position(run: Run, robot: int, t: float) -> Point:
    """Where ``robot`` is at time ``t``."""
    p = run.start[robot]
    for m in sorted((m for m in run.moves if m.robot == robot), key=lambda m: m.start_time):
        if t < m.start_time:
            break
        if t >= m.end_time:
            p = m.path.end
            continue
        span = m.end_time - m.start_time
        return m.path.at((t - m.start_time) / span if span else 1.0)
    return p


def frame_times(run: Run) -> list[float]:
    times = {0.0 if not run.moves else min(0.0, min(m.start_time for m in run.moves))}
    times.update(e.time for e in run.events)
    times.update(m.end_time for m in run.moves)
    if run.violation is not None:
        times.add(run.violation.time)
    return sorted(times)


def end_time(run: Run) -> float:
    if run.violation is not None:
        return run.violation.time
    return max(frame_times(run))


# ---------------------------------------------------------------- JSON form
def run_to_dict(run: Run) -> dict:
    d = asdict(run)
    for m, move in zip(d["moves"], run.moves):
        m["path"]["kind"] = "arc" if isinstance(move.path, Arc) else "segment"
    for p, path in zip(d["planned"], run.planned):
        p["kind"] = "arc" if isinstance(path, Arc) else "segment"
    return d


def run_from_dict(d: dict) -> Run:
    def path(p):
        p = dict(p)
        kind = p.pop("kind", "segment")
        if kind == "arc":
            return Arc(tuple(p["centre"]), float(p["radius"]), float(p["start_angle"]),
                       float(p["end_angle"]))
        return Segment(tuple(p["start"]), tuple(p["end"]))
    v = d.get("violation")
    return Run(name=d.get("name", "run"), model=d.get("model", "points"),
               start=tuple(tuple(map(float, p)) for p in d["start"]),
               moves=tuple(Move(int(m["robot"]), float(m["start_time"]), float(m["end_time"]),
                                path(m["path"]), m.get("size"))
                           for m in d.get("moves", ())),
               layers=tuple(Layer(str(x["label"]), tuple(x["centre"]), float(x["radius"]))
                            for x in d.get("layers", ())),
               events=tuple(Event(float(e["time"]), str(e["text"]), tuple(e.get("robots", ())))
                            for e in d.get("events", ())),
               violation=None if not v else Violation(
                   tuple(v["robots"]), float(v["time"]), v.get("text", "collision"),
                   None if not v.get("at") else tuple(tuple(map(float, p)) for p in v["at"])),
               notes=tuple(d.get("notes", ())),
               planned=tuple(path(p) for p in d.get("planned", ())))


# ---------------------------------------------------------------- drawing
def _extent(run: Run) -> tuple[float, float, float, float]:
    xs, ys = [p[0] for p in run.start], [p[1] for p in run.start]
    for m in run.moves:
        for s in (0.0, 0.25, 0.5, 0.75, 1.0):
            x, y = m.path.at(s)
            xs.append(x)
            ys.append(y)
    for path in run.planned:
        for s in (0.0, 0.25, 0.5, 0.75, 1.0):
            x, y = path.at(s)
            xs.append(x)
            ys.append(y)
    for layer in run.layers:
        xs += [layer.centre[0] - layer.radius, layer.centre[0] + layer.radius]
        ys += [layer.centre[1] - layer.radius, layer.centre[1] + layer.radius]
    pad = 1.0 if run.model == "fat" else 0.0
    span = max(max(xs) - min(xs), max(ys) - min(ys), 1e-9)
    pad += 0.06 * span
    return min(xs) - pad, max(xs) + pad, min(ys) - pad, max(ys) + pad


def _colour(i: int) -> str:
    palette = ["#0072b2", "#009e73", "#cc79a7", "#e69f00", "#56b4e9", "#f0e442", "#000000",
               "#8c564b"]
    return palette[i % len(palette)]


def _path_xy(path, upto: float = 1.0, steps: int = 64):
    if isinstance(path, Segment):
        a, b = path.start, path.at(upto)
        return [a[0], b[0]], [a[1], b[1]]
    pts = [path.at(upto * k / steps) for k in range(steps + 1)]
    return [p[0] for p in pts], [p[1] for p in pts]


#: The zoom beside a violation: half the width of its window (in robot radii), and how
#: much larger the whole picture must be for the zoom to be drawn.
ZOOM_HALF = 5.0
ZOOM_WHEN = 3.0


def time_colour(fraction: float) -> tuple:
    """The colour of a move by its time in the run (0: first, 1: last): viridis, dark to
    light, so that order reads in grey too."""
    matplotlib, _ = matplotlib_modules()
    return matplotlib.colormaps["viridis"](min(max(fraction, 0.0), 1.0) * 0.85)


def _path_length(path) -> float:
    if isinstance(path, Segment):
        return math.dist(path.start, path.end)
    return abs(path.end_angle - path.start_angle) * path.radius


def _arrow(ax, path, done: float, colour, half: float, gid: str) -> None:
    """An arrowhead at the middle of what is travelled, pointing the way the robot went;
    none on a path too short to show at this scale."""
    if _path_length(path) * done < 0.02 * half:
        return
    s = done / 2
    a, b = path.at(max(s - 0.01 * done, 0.0)), path.at(s + 0.01 * done)
    from matplotlib.patches import FancyArrowPatch
    ax.add_patch(FancyArrowPatch(a, b, arrowstyle="-|>", color=colour, lw=1.2,
                                 mutation_scale=12, shrinkA=0, shrinkB=0, zorder=4.7,
                                 gid=gid))


def _moves_box(run: Run):
    """The smallest square (centre, half width) holding every move, or None."""
    pts = [m.path.at(k / 16) for m in run.moves for k in range(17) if _size(m) > 0]
    if not pts:
        return None
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    half = max(max(xs) - min(xs), max(ys) - min(ys)) / 2
    return ((max(xs) + min(xs)) / 2, (max(ys) + min(ys)) / 2), half


def _draw_scene(ax, run: Run, t, when: float, half: float, prefix: str, handles: list,
                hollow: bool = False):
    """Layers, paths, planned paths, robots and the violation into ``ax``; legend
    handles are appended to ``handles`` when it is not None; ``hollow``: robots drawn
    faint, paths above them (a zoom on moves smaller than a robot)."""
    from matplotlib.lines import Line2D
    from matplotlib.patches import Circle as CirclePatch

    def handle(**kw):
        if handles is not None:
            handles.append(Line2D([], [], **kw))

    for k, layer in enumerate(run.layers):
        ax.add_patch(CirclePatch(layer.centre, layer.radius, fill=False, ls=(0, (4, 3)),
                                 ec=COLOURS["level"], lw=1.0, gid=f"{prefix}layer-{k}"))
    if run.layers:
        c = run.layers[0].centre
        ax.plot([c[0]], [c[1]], marker="+", ms=8, color="#444444", ls="none", zorder=2,
                gid=f"{prefix}pattern-centre")
        handle(color=COLOURS["level"], ls=(0, (4, 3)), marker="+", mec="#444444",
               label=f"the pattern's centre C and the layer circles it fills "
                     f"({len(run.layers)})")
    total = max(end_time(run), 1e-9)
    for k, m in enumerate(run.moves):
        done = 1.0 if when >= m.end_time else 0.0 if when <= m.start_time else \
            (when - m.start_time) / (m.end_time - m.start_time)
        colour = time_colour((m.start_time + m.end_time) / 2 / total)
        if t is not None:                   # the whole path, faint, then what is done
            xs, ys = _path_xy(m.path)
            ax.plot(xs, ys, color=colour, lw=0.8, alpha=0.25, zorder=2)
        if done > 0:
            xs, ys = _path_xy(m.path, done)
            ax.plot(xs, ys, color=colour, lw=1.6, zorder=4.6 if hollow else 3,
                    gid=f"{prefix}path-{m.robot}-{k}")
            _arrow(ax, m.path, done, colour, half, f"{prefix}arrow-{m.robot}-{k}")
    if run.moves:
        handle(color=time_colour(0.5), lw=1.6, marker=">", ms=5,
               label="paths (segments and arcs), arrow: direction; colour: time, from "
                     "the first move (dark) to the last (light)")
    for k, path in enumerate(run.planned):
        xs, ys = _path_xy(path)
        ax.plot(xs, ys, color="#d55e00", lw=1.2, ls=(0, (2, 2)), zorder=2,
                gid=f"{prefix}planned-{k}")
    if run.planned:
        handle(color="#d55e00", lw=1.2, ls=(0, (2, 2)), label="planned path, not travelled")
    fat = run.model == "fat"
    rho = 1.0 if fat else 0.015 * half
    hit = set(run.violation.robots) if run.violation and when >= run.violation.time else set()
    for i, p in enumerate(run.start):
        ax.add_patch(CirclePatch(p, rho, fill=False, ec=_colour(i), lw=0.8, ls=":",
                                 gid=f"{prefix}start-{i}", zorder=3))
        q = position(run, i, when)
        # hollow (a zoom on small moves): the paths inside a disc stay visible
        ax.add_patch(CirclePatch(q, rho, fc=_colour(i), alpha=0.15 if hollow else
                                 0.7 if fat else 1.0,
                                 ec="#d55e00" if i in hit else "#222222",
                                 lw=2.2 if i in hit else 0.8, gid=f"{prefix}robot-{i}",
                                 zorder=4))
        if fat:
            ax.text(q[0], q[1], str(i), ha="center", va="center", fontsize=8,
                    gid=f"{prefix}label-{i}", zorder=5, clip_on=True)
        else:
            ax.annotate(str(i), q, xytext=(5, 5), textcoords="offset points", fontsize=8,
                        gid=f"{prefix}label-{i}", zorder=5, annotation_clip=True)
    handle(marker="o", ls="none", mfc="none", mec="#555555", label="start positions (dotted)")
    handle(marker="o", ls="none", mfc="#555555", mec="#222222", label=f"robots at t = {when:g}")
    if hit:
        a, b = run.violation.robots
        pa, pb = _witness(run, when)
        if run.violation.at is not None:
            for k, q in enumerate((pa, pb)):
                ax.add_patch(CirclePatch(q, rho, fill=False, ec="#d55e00", lw=1.2,
                                         ls=(0, (2, 2)), zorder=4,
                                         gid=f"{prefix}violation-disc-{k}"))
        ax.plot([pa[0], pb[0]], [pa[1], pb[1]], color="#d55e00", lw=2.4,
                gid=f"{prefix}violation", zorder=4.5)   # under the robots' numbers
        handle(color="#d55e00", lw=2.4, label=f"{run.violation.text}: robots {a} and {b} at "
                                              f"t = {run.violation.time:g}")
    return hit


def _witness(run: Run, when: float):
    """The two points the violation's bar joins."""
    if run.violation.at is not None:
        return run.violation.at
    a, b = run.violation.robots
    return position(run, a, when), position(run, b, when)


def _close(run: Run, when: float) -> bool:
    pa, pb = _witness(run, when)
    return math.hypot(pa[0] - pb[0], pa[1] - pb[1]) <= ZOOM_HALF


def draw_run(run: Run, t: float | None = None, prefix: str = ""):
    """A Figure of ``run``: the whole run (``t`` None: every path, robots where the run
    ends, the violation) or the instant ``t`` (paths travelled so far).  When the
    violation is shown and the picture is much wider than a few robots, a zoom on the
    colliding pair is drawn under the legend (SVG ids prefixed ``zoom-``) -- when the pair
    is near enough for both to show in it (a pair that a fresh Look names is often far
    apart: no zoom then)."""
    matplotlib, Figure = matplotlib_modules()
    from matplotlib.patches import Rectangle

    with matplotlib.rc_context(RC):
        fig = Figure(figsize=(9.0, 7.0), dpi=DPI)
        ax = fig.add_axes((0.01, 0.03, 0.64, 0.86))
        ax.set_aspect("equal")
        ax.set_axis_off()
        x0, x1, y0, y1 = _extent(run)
        half = max(x1 - x0, y1 - y0) / 2
        cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
        ax.set_xlim(cx - half, cx + half)
        ax.set_ylim(cy - half, cy + half)
        when = end_time(run) if t is None else t
        handles: list = []
        hit = _draw_scene(ax, run, t, when, half, prefix, handles)
        zoomed = False
        if hit and run.model == "fat" and half > ZOOM_WHEN * ZOOM_HALF and _close(run, when):
            zoomed = True
            a, b = run.violation.robots
            pa, pb = _witness(run, when)
            mx, my = (pa[0] + pb[0]) / 2, (pa[1] + pb[1]) / 2
            zoom = fig.add_axes((0.68, 0.04, 0.30, 0.40))
            zoom.set_aspect("equal")
            zoom.set_xlim(mx - ZOOM_HALF, mx + ZOOM_HALF)
            zoom.set_ylim(my - ZOOM_HALF, my + ZOOM_HALF)
            zoom.set_xticks([])
            zoom.set_yticks([])
            for spine in zoom.spines.values():
                spine.set_edgecolor("#d55e00")
            zoom.set_title(f"zoom on robots {a} and {b} ({2 * ZOOM_HALF:g} robot radii wide)",
                           fontsize=8)
            _draw_scene(zoom, run, t, when, ZOOM_HALF, f"{prefix}zoom-", None)
            ax.add_patch(Rectangle((mx - ZOOM_HALF, my - ZOOM_HALF), 2 * ZOOM_HALF,
                                   2 * ZOOM_HALF, fill=False, ec="#d55e00", lw=0.8,
                                   gid=f"{prefix}zoom-window"))
        tiny = _tiny_moves(run, half)
        if tiny:
            _mark_tiny(fig, ax, run, when, tiny, prefix)
        box = _moves_box(run)
        if not zoomed and box is not None and 0 < box[1] < half / (2 * ZOOM_WHEN):
            _motion_zoom(fig, ax, run, t, when, box, prefix)
            zoomed = True
        if not zoomed and run.layers and t is None:
            outer = max(layer.radius for layer in run.layers) + 2.0
            if outer < half / ZOOM_WHEN:
                c = run.layers[0].centre
                _motion_zoom(fig, ax, run, t, when, (c, outer / 1.3), prefix,
                             "the pattern at the end", "zoom-pattern-", False)
        if run.moves:
            _time_bar(fig, end_time(run), prefix)
        title = run.name if t is None else f"{run.name}: t = {t:g}"
        fig.text(0.01, 0.965, title, fontsize=11, weight="bold", va="top")
        now = [e.text for e in run.events if e.time == when] if t is not None else []
        if now:
            fig.text(0.01, 0.925, "; ".join(now)[:110], fontsize=9, va="top",
                     gid=f"{prefix}event")
        for h in handles:
            h.set_label(textwrap.fill(h.get_label(), 40, subsequent_indent="  "))
        fig.legend(handles=handles, loc="upper left", bbox_to_anchor=(0.66, 0.9),
                   frameon=False, fontsize=8)
    return fig


#: A move shorter than this fraction of the picture cannot be drawn in doubles at all
#: (its ends round to one point); it is ringed and counted instead.
TINY = 1e-9


def _size(m: Move) -> float:
    return m.size if m.size is not None else _path_length(m.path)


def _tiny_moves(run: Run, half: float) -> dict:
    """robot -> [sizes] of its moves too small to draw."""
    out: dict = {}
    for m in run.moves:
        if _size(m) < TINY * half:
            out.setdefault(m.robot, []).append(_size(m))
    return out


def _mark_tiny(fig, ax, run: Run, when: float, tiny: dict, prefix: str) -> None:
    """Ring each robot whose moves are too small to draw, and say how many and how
    small under the title."""
    from matplotlib.patches import Circle as CirclePatch
    parts = []
    for robot, sizes in sorted(tiny.items()):
        q = position(run, robot, when)
        # a dashed double ring: not the dotted start circles
        for r in (1.35, 1.6):
            ax.add_patch(CirclePatch(q, r, fill=False, ec="#d55e00", lw=1.2,
                                     ls=(0, (4, 2)), zorder=4.8,
                                     gid=f"{prefix}tiny-{robot}" if r == 1.35 else None))
        parts.append(f"robot {robot}: {len(sizes)} move{'s' if len(sizes) > 1 else ''} of "
                     f"{max(sizes):.1e} at most")
    fig.text(0.01, 0.93, "too small to draw (dashed double ring): " + "; ".join(parts),
             fontsize=8,
             va="top", color="#d55e00", gid=f"{prefix}tiny-note")


def _motion_zoom(fig, ax, run: Run, t, when: float, box, prefix: str,
                 what: str = "zoom on the moves", gid: str = "zoom-moves-",
                 hollow: bool = True) -> None:
    """Every move is small beside the picture (epsilon moves, a short slide): a zoom on
    the square that holds them, robots faint so the paths show (also: the pattern at the
    end of a run, small beside the start)."""
    from matplotlib.patches import Rectangle
    (mx, my), h = box
    h = max(h * 1.3, 1e-6)
    zoom = fig.add_axes((0.68, 0.04, 0.30, 0.40))
    zoom.set_aspect("equal")
    zoom.set_xlim(mx - h, mx + h)
    zoom.set_ylim(my - h, my + h)
    zoom.set_xticks([])
    zoom.set_yticks([])
    for spine in zoom.spines.values():
        spine.set_edgecolor("#555555")
    zoom.set_title(f"{what}, {2 * h:.3g} wide", fontsize=8)
    _draw_scene(zoom, run, t, when, h, f"{prefix}{gid}", None, hollow=hollow)
    ax.add_patch(Rectangle((mx - h, my - h), 2 * h, 2 * h, fill=False, ec="#555555",
                           lw=0.8, gid=f"{prefix}{gid}window"))


def _time_bar(fig, total: float, prefix: str) -> None:
    """The colour scale of time: event 0 to the last event."""
    matplotlib, _ = matplotlib_modules()
    from matplotlib.cm import ScalarMappable
    from matplotlib.colors import ListedColormap, Normalize
    cmap = ListedColormap([time_colour(k / 255) for k in range(256)])
    cax = fig.add_axes((0.68, 0.58, 0.27, 0.018))
    bar = fig.colorbar(ScalarMappable(norm=Normalize(0, total), cmap=cmap), cax=cax,
                       orientation="horizontal")
    bar.set_label("time: event number of each move", fontsize=8)
    from matplotlib.ticker import MaxNLocator
    bar.ax.xaxis.set_major_locator(MaxNLocator(integer=True))   # events are whole numbers
    bar.ax.tick_params(labelsize=7)
    cax.set_gid(f"{prefix}time-bar")


def _save(fig, path_or_buffer, fmt: str) -> None:
    matplotlib, _ = matplotlib_modules()
    with matplotlib.rc_context(RC):
        fig.savefig(path_or_buffer, format=fmt, dpi=DPI, metadata=METADATA[fmt])


def plot_run(run: Run, path) -> Path:
    """The whole run in one picture (``.svg``, ``.png`` or ``.pdf``)."""
    path = Path(path)
    fmt = path.suffix.lstrip(".").lower() or "svg"
    if fmt not in METADATA:
        raise ValueError(f"{path}: unknown picture format {fmt!r} (use .svg, .png or .pdf)")
    _save(draw_run(run), path, fmt)
    return path


def write_frames(run: Run, directory, fmt: str = "png") -> list[Path]:
    """One picture per frame time, ``frame-000.png``, ... in ``directory``."""
    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    out = []
    for k, t in enumerate(frame_times(run)):
        path = directory / f"frame-{k:03d}.{fmt}"
        _save(draw_run(run, t), path, fmt)
        out.append(path)
    return out


def write_gif(run: Run, path, seconds_per_frame: float = 0.8) -> Path | None:
    """An animated GIF of the frames (needs pillow, which matplotlib depends on); None,
    with nothing written, when pillow is missing."""
    try:
        from PIL import Image
    except ImportError:
        return None
    images = []
    for t in frame_times(run):
        buf = io.BytesIO()
        _save(draw_run(run, t), buf, "png")
        buf.seek(0)
        images.append(Image.open(buf).convert("P", palette=Image.ADAPTIVE))
    path = Path(path)
    images[0].save(path, save_all=True, append_images=images[1:], loop=0,
                   duration=int(seconds_per_frame * 1000))
    return path


_HTML = """<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>{title}</title>
<style>body{{font-family:DejaVu Sans,sans-serif;margin:1em}} .frame svg{{max-width:100%;height:auto}}
button{{font-size:1em;margin-right:.3em}}</style></head>
<body><h1 style="font-size:1.2em">{title}</h1>
<p><button id="prev">&#9664; previous</button><button id="play">play</button><button id="next">next &#9654;</button>
<input id="slider" type="range" min="0" max="{last}" value="0"> <span id="where"></span>
(keys: left and right arrows)</p>
{frames}
<script>
const frames = document.querySelectorAll('.frame'), times = {times};
let k = 0, timer = null;
function show(j) {{ k = Math.max(0, Math.min(frames.length - 1, j));
  frames.forEach((f, i) => f.hidden = i !== k);
  document.getElementById('slider').value = k;
  document.getElementById('where').textContent = 'frame ' + (k + 1) + ' of ' + frames.length + ', t = ' + times[k]; }}
document.getElementById('prev').onclick = () => show(k - 1);
document.getElementById('next').onclick = () => show(k + 1);
document.getElementById('slider').oninput = e => show(+e.target.value);
document.getElementById('play').onclick = () => {{ if (timer) {{ clearInterval(timer); timer = null; return; }}
  timer = setInterval(() => {{ if (k === frames.length - 1) {{ clearInterval(timer); timer = null; }} else show(k + 1); }}, 800); }};
document.addEventListener('keydown', e => {{ if (e.key === 'ArrowLeft') show(k - 1); if (e.key === 'ArrowRight') show(k + 1); }});
show(0);
</script></body></html>
"""


def write_html(run: Run, path) -> Path:
    """One self-contained HTML file (inline SVG frames, a few lines of script, no server)."""
    import html
    import json
    times = frame_times(run)
    frames = []
    for k, t in enumerate(times):
        buf = io.StringIO()
        _save(draw_run(run, t, prefix=f"f{k}-"), buf, "svg")
        svg = buf.getvalue()
        svg = svg[svg.index("<svg"):]          # drop the XML declaration and doctype
        frames.append(f'<div class="frame" id="frame-{k}"{" hidden" if k else ""}>{svg}</div>')
    path = Path(path)
    path.write_text(_HTML.format(title=html.escape(run.name), last=len(times) - 1,
                                 frames="\n".join(frames),
                                 times=json.dumps([f"{t:g}" for t in times])),
                    encoding="utf-8")
    return path
