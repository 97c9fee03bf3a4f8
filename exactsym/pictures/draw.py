"""Draw a :class:`.scene.Scene` with matplotlib, deterministically.

No pyplot and no global state: one :class:`matplotlib.figure.Figure` per picture, drawn
under fixed rc settings (DejaVu Sans, which matplotlib ships; a fixed SVG hash salt;
text kept as ``<text>`` in SVG) and saved without dates or version strings, so that
the same input gives byte-identical SVG.  Every artist carries an SVG id (``gid``):
``sec``, ``level-G2``, ``robot-3``, ``label-3``, ``rank-3``, ``leader``, ``mirror-0``,
``centre``, ``paper-line-G1-0``, ``paper-skew-G1-0``, ``paper-leader``, ``witness-0``,
``robots`` (all robots, for large configurations), so that tests and people can find
them in the file.
"""

from __future__ import annotations

import math
import textwrap
from pathlib import Path

from .scene import Scene

#: Figure size (inches) and PNG resolution: fixed, so pictures compare.
FIGSIZE = (11.0, 7.0)
DPI = 100
#: Above this many robots, no per-robot labels; above LARGE, one marker collection.
LABEL_LIMIT = 150
LARGE = 2000
#: At most this many level circles are drawn (random inputs have one level per robot).
MAX_LEVEL_CIRCLES = 60

RC = {
    "svg.hashsalt": "exactsym",
    "svg.fonttype": "none",
    "font.family": "DejaVu Sans",
    "font.size": 9,
    "pdf.fonttype": 42,
    "path.simplify": False,
}

#: Metadata that would change from run to run or version to version, removed.
METADATA = {
    "svg": {"Date": None, "Creator": None},
    "pdf": {"CreationDate": None, "ModDate": None, "Creator": None, "Producer": None},
    "png": {"Software": None},
}

COLOURS = {
    "sec": "#444444", "level": "#9aa5b1", "robot": "#cfe3f7", "robot_edge": "#1f4e79",
    "point": "#1f4e79", "leader": "#e69f00", "mirror": "#009e73", "rotation": "#009e73",
    "paper": "#cc79a7", "skew": "#56b4e9", "paper_leader": "#cc79a7", "witness": "#d55e00",
    "witness_line": "#8c7aa9",
}


class PlotUnavailable(RuntimeError):
    """matplotlib is not installed."""


def matplotlib_modules():
    """``(matplotlib, Figure)``, or :class:`PlotUnavailable` naming the ``plot`` extra."""
    try:
        import matplotlib
        from matplotlib.figure import Figure
    except ImportError as err:          # pragma: no cover - depends on the environment
        raise PlotUnavailable(
            "drawing needs matplotlib, a dependency of exactsym (also the 'plot' extra): "
            "pip install matplotlib, or from a checkout pip install -e .") from err
    return matplotlib, Figure


def figure(scene: Scene, *, show_paper: bool = False, show_audit: bool = False):
    """A new matplotlib Figure showing ``scene`` (its paper and audit parts when asked
    and present)."""
    matplotlib, Figure = matplotlib_modules()
    with matplotlib.rc_context(RC):
        fig = Figure(figsize=FIGSIZE, dpi=DPI)
        _draw(fig, scene, show_paper and scene.paper is not None,
              show_audit and scene.audit is not None)
    return fig


def save(fig, path, fmt: str | None = None) -> Path:
    """Save ``fig`` to ``path`` (format from ``fmt`` or the suffix: svg, png, pdf)."""
    matplotlib, _ = matplotlib_modules()
    path = Path(path)
    fmt = (fmt or path.suffix.lstrip(".") or "svg").lower()
    if fmt not in METADATA:
        raise ValueError(f"{path}: unknown picture format {fmt!r} (use .svg, .png or .pdf)")
    with matplotlib.rc_context(RC):
        fig.savefig(path, format=fmt, dpi=DPI, metadata=METADATA[fmt])
    return path


# ---------------------------------------------------------------- drawing
def _scale(scene: Scene) -> float:
    r = scene.sec.radius
    return r if r > 0 else 1.0


def _point_radius(scene: Scene) -> float:
    """Radius of a point robot's dot, in data units: small against the SEC and against
    the closest pair (so that dots do not overlap)."""
    import numpy as np
    R = _scale(scene)
    rho = 0.02 * R
    n = scene.n
    if 1 < n <= LARGE:
        pts = np.array([r.xy for r in scene.robots])
        d = np.sqrt(((pts[:, None, :] - pts[None, :, :]) ** 2).sum(-1))
        d[np.diag_indices(n)] = np.inf
        rho = min(rho, 0.35 * float(d.min()))
    return rho


def _draw(fig, scene: Scene, show_paper: bool, show_audit: bool) -> None:
    from matplotlib.lines import Line2D
    from matplotlib.patches import Circle as CirclePatch

    ax = fig.add_axes((0.01, 0.03, 0.55, 0.86))
    ax.set_aspect("equal")
    ax.set_axis_off()
    R = _scale(scene)
    cx, cy = scene.centre
    fat = scene.model == "fat"
    pad = 0.12 * R + (1.0 if fat else 0.0)
    ax.set_xlim(cx - R - pad, cx + R + pad)
    ax.set_ylim(cy - R - pad, cy + R + pad)
    handles = []

    def legend(handle, label):
        handle.set_label(textwrap.fill(label, 58, subsequent_indent="  "))
        handles.append(handle)

    # SEC and level circles
    sec = CirclePatch(scene.centre, scene.sec.radius, fill=False, lw=1.4,
                      ec=COLOURS["sec"], gid="sec", zorder=1)
    ax.add_patch(sec)
    legend(Line2D([], [], color=COLOURS["sec"], lw=1.4), "smallest enclosing circle (SEC)")
    levels = [c for c in scene.levels if c.radius > 0 and c.radius_squared != scene.sec.radius_squared]
    if len(scene.levels) <= MAX_LEVEL_CIRCLES:
        for c in levels:
            ax.add_patch(CirclePatch(c.centre, c.radius, fill=False, lw=0.8, ls=(0, (4, 3)),
                                     ec=COLOURS["level"], gid=f"level-{c.label}", zorder=1))
        if levels:
            legend(Line2D([], [], color=COLOURS["level"], lw=0.8, ls=(0, (4, 3))),
                   f"level circles G1..G{len(scene.levels)}")
    else:
        fig.text(0.01, 0.005, f"{len(scene.levels)} levels: circles not drawn", fontsize=8)

    # ground truth: mirrors and rotation
    for j, line in enumerate(scene.mirrors):
        _line(ax, line, color=COLOURS["mirror"], lw=3.0, alpha=0.45, ls="-", gid=f"mirror-{j}",
              zorder=2)
    if scene.mirrors:
        shown = "" if len(scene.mirrors) == scene.mirrors_total else \
            f", {len(scene.mirrors)} drawn (the others: multiples of 1/{2 * scene.mirrors_total}" \
            " turn from it)"
        legend(Line2D([], [], color=COLOURS["mirror"], lw=3.0, alpha=0.45),
               f"mirrors (truth): {scene.mirrors_total}{shown}")
    if scene.rotation is not None:
        k = scene.rotation.order
        marker = _rotation_marker(k)
        ax.plot([cx], [cy], marker=marker, ms=11, mfc="white", mec=COLOURS["rotation"],
                mew=1.6, ls="none", gid="centre", zorder=6)
        # on a white box, above the lines through C (the paper's lines meet there)
        ax.annotate(f"k={k}", (cx, cy), xytext=(9, -14), textcoords="offset points",
                    fontsize=8, color=COLOURS["rotation"], weight="bold",
                    bbox=dict(boxstyle="round,pad=0.15", fc="white", ec="none", alpha=0.9),
                    gid="rotation-order", zorder=7)
        legend(Line2D([], [], marker=marker, ms=9, mfc="white", mec=COLOURS["rotation"],
                      mew=1.6, ls="none"),
               f"rotation centre C, order k = {k} (truth: rotations by 1/{k} turn)")
    else:
        ax.plot([cx], [cy], marker="+", ms=8, color=COLOURS["sec"], ls="none", gid="centre",
                zorder=6)
        legend(Line2D([], [], marker="+", ms=8, color=COLOURS["sec"], ls="none"),
               "SEC centre C (no rotation)")

    # the paper's tests
    if show_paper:
        _draw_paper(ax, scene, legend)

    # robots
    _draw_robots(ax, scene, fat, legend)

    if show_audit:
        _draw_audit(ax, scene, legend)

    group = f"truth: group {scene.group}, " + \
        ("orderable" if scene.orderable else "not orderable") + \
        (f", leader {scene.leader}" if scene.leader is not None else ", no leader")
    fig.text(0.01, 0.965, _short(scene.title, 95), fontsize=11, weight="bold", va="top")
    fig.text(0.01, 0.925, f"n = {scene.n}, model {scene.model}; {group}", fontsize=9,
             va="top")
    for k, note in enumerate(scene.notes):
        fig.text(0.58, 0.02 + 0.025 * k, textwrap.fill(note, 75), fontsize=7)
    lines = sum(h.get_label().count("\n") + 1 for h in handles)
    fig.legend(handles=handles, loc="upper left", bbox_to_anchor=(0.57, 0.9),
               frameon=False, fontsize=8 if lines <= 34 else 6, handlelength=2.2)


def _rotation_marker(k: int):
    """A marker with the rotation's symmetry where one exists: a thin diamond for k = 2,
    a regular k-gon for 3 <= k < 13, a circle above."""
    if k == 2:
        return "d"
    return (k, 0, 0) if k < 13 else "o"


def _short(text: str, width: int) -> str:
    return text if len(text) <= width else text[:width - 3] + "..."


def _line(ax, line, **style):
    dx, dy = math.cos(line.angle) * line.reach, math.sin(line.angle) * line.reach
    x, y = line.through
    return ax.plot([x - dx, x + dx], [y - dy, y + dy], **style)[0]


def _draw_robots(ax, scene: Scene, fat: bool, legend) -> None:
    from matplotlib.lines import Line2D
    from matplotlib.patches import Circle as CirclePatch

    n = scene.n
    R = _scale(scene)
    xy = {r.index: r.xy for r in scene.robots}
    if n > LARGE:
        xs, ys = zip(*(r.xy for r in scene.robots))
        ax.scatter(xs, ys, s=1.5, c=COLOURS["point"], linewidths=0, gid="robots", zorder=4)
        legend(Line2D([], [], marker="o", ms=3, color=COLOURS["point"], ls="none"),
               f"{n} robots (not numbered)")
        rho = 0.01 * R
    else:
        rho = 1.0 if fat else _point_radius(scene)
        for r in scene.robots:
            # fat discs are translucent: the lines through them stay visible
            ax.add_patch(CirclePatch(r.xy, rho, fc=COLOURS["robot"] if fat else COLOURS["point"],
                                     alpha=0.75 if fat else 1.0, ec=COLOURS["robot_edge"],
                                     lw=0.8, gid=f"robot-{r.index}", zorder=4))
        what = "robots as unit discs (fat)" if fat else "robots (points)"
        legend(Line2D([], [], marker="o", ms=7 if fat else 4,
                      mfc=COLOURS["robot"] if fat else COLOURS["point"],
                      mec=COLOURS["robot_edge"], ls="none"),
               what + (", numbered as in the file" if n <= LABEL_LIMIT else ""))
    if n <= LABEL_LIMIT:
        size = 8 if n <= 40 else 6
        for r in scene.robots:
            x, y = r.xy
            if fat and rho > 0.04 * R:
                ax.text(x, y, str(r.index), ha="center", va="center", fontsize=size,
                        gid=f"label-{r.index}", zorder=5)
            else:
                # offset past the rings drawn around a robot (leader, witnesses)
                ax.annotate(str(r.index), (x, y), xytext=(9, 8), textcoords="offset points",
                            fontsize=size, gid=f"label-{r.index}", zorder=5)
            if r.rank is not None:
                ax.annotate(f"#{r.rank}", (x, y), xytext=(9, -14), textcoords="offset points",
                            fontsize=7, color="#555555", gid=f"rank-{r.index}", zorder=5)
        if any(r.rank is not None for r in scene.robots):
            legend(Line2D([], [], ls="none"), "#k beside a robot: its place in the canonical "
                   "ordering (truth)")
    if scene.leader is not None:
        ring = rho * 1.2 if fat else rho * 1.6 + 0.006 * R
        ax.add_patch(CirclePatch(xy[scene.leader], ring, fill=False,
                                 ec=COLOURS["leader"], lw=2.2, gid="leader", zorder=6))
        legend(Line2D([], [], marker="o", ms=9, mfc="none", mec=COLOURS["leader"], mew=2,
                      ls="none"), f"leader (truth): robot {scene.leader}")


#: The paper's lines, level by level: (colour, dash) -- the paper's hue family, told apart
#: by shade and dash as well as colour (readable in grey).
PAPER_LEVEL_STYLES = (("#cc79a7", (0, (5, 3))), ("#8e3b72", (0, (2, 2))),
                      ("#e69f00", (0, (8, 3, 2, 3))), ("#7a5c00", (0, (1, 3))))


def _draw_paper(ax, scene: Scene, legend) -> None:
    from matplotlib.lines import Line2D
    from matplotlib.patches import Rectangle

    paper = scene.paper
    xy = {r.index: r.xy for r in scene.robots}
    any_straight = any_skew = False
    drawn = [lv for lv in paper.levels if lv.straight]
    for k, level in enumerate(drawn):
        # one colour and one dash per level, each named in the legend in words
        colour, dash = PAPER_LEVEL_STYLES[k % len(PAPER_LEVEL_STYLES)]
        for j, line in enumerate(level.straight):
            _line(ax, line, color=colour, lw=1.0, ls=dash,
                  gid=f"paper-line-G{level.level}-{j}", zorder=3)
        count = len(level.straight)
        legend(Line2D([], [], color=colour, lw=1.0, ls=dash),
               f"paper, level G{level.level} ({level.check}): {count} line"
               f"{'s' if count > 1 else ''} of straight symmetry its test reports")
        any_straight = True
    for level in paper.levels:
        for j, (a, b) in enumerate(level.skew_pairs[:24]):
            ax.plot([xy[a][0], xy[b][0]], [xy[a][1], xy[b][1]], color=COLOURS["skew"], lw=1.0,
                    ls=(0, (1, 2)), gid=f"paper-skew-G{level.level}-{j}", zorder=3)
            any_skew = True
    if any_skew:
        legend(Line2D([], [], color=COLOURS["skew"], lw=1.0, ls=(0, (1, 2))),
               "paper: skew symmetry reported (a half-turn about C): the vertex pairs i, i + n/2 it would swap")
    if not paper.levels:
        legend(Line2D([], [], ls="none"), "paper's tests: not drawn (see the note below)")
    elif not any_straight and not any_skew:
        legend(Line2D([], [], ls="none"), "paper: no level drawn is symmetric by its tests")
    if paper.leader is not None:
        R = _scale(scene)
        s = 0.07 * R if scene.model != "fat" else 2.6
        x, y = xy[paper.leader]
        ax.add_patch(Rectangle((x - s / 2, y - s / 2), s, s, fill=False, lw=1.6,
                               ec=COLOURS["paper_leader"], gid="paper-leader", zorder=6))
        legend(Line2D([], [], marker="s", ms=9, mfc="none", mec=COLOURS["paper_leader"],
                      mew=1.6, ls="none"), f"paper's leader: robot {paper.leader}")
    else:
        legend(Line2D([], [], ls="none"),
               "paper's procedure: " + ("no leader" if paper.orderable else "not orderable"))


def _draw_audit(ax, scene: Scene, legend) -> None:
    from matplotlib.lines import Line2D
    from matplotlib.patches import Arc, Circle as CirclePatch, FancyArrowPatch

    if not scene.audit:
        legend(Line2D([], [], ls="none"), "audit: the paper agrees with the truth here")
        return
    R = _scale(scene)
    xy = {r.index: r.xy for r in scene.robots}
    levels = {c.label: c for c in scene.levels}
    styles = ["-", (0, (6, 2)), (0, (2, 2)), (0, (6, 2, 2, 2))]
    # the symmetries the paper misses first and boldest; lines of merged polygons
    # (G_ij) thin and grey; statements with nothing to draw last
    priority = {"rotation": 0, "mirror": 1, "robots": 2, "levels": 3, "line": 4, "none": 5}
    order = sorted(range(len(scene.audit)), key=lambda j: priority.get(scene.audit[j].kind, 9))
    for j in order:
        w = scene.audit[j]
        label = f"{_statements(w.statements)}: {_short(w.text, 180)}"
        gid = f"witness-{j}"
        ls = styles[j % len(styles)]
        if w.kind == "rotation":
            a, b = w.robots
            cx, cy = w.centre
            ax0 = xy[a][0] - cx
            ay0 = xy[a][1] - cy
            rad = math.hypot(ax0, ay0) * (0.93 - 0.05 * (j % 3))    # inside the SEC
            start = math.degrees(math.atan2(ay0, ax0))
            end = start + math.degrees(w.angle)
            ax.add_patch(Arc((cx, cy), 2 * rad, 2 * rad, theta1=start, theta2=end,
                             ec=COLOURS["witness"], lw=1.8, ls=ls, gid=gid, zorder=7))
            tip = math.radians(end)
            back = math.radians(end - min(8.0, abs(math.degrees(w.angle)) / 3))
            ax.add_patch(FancyArrowPatch((cx + rad * math.cos(back), cy + rad * math.sin(back)),
                                         (cx + rad * math.cos(tip), cy + rad * math.sin(tip)),
                                         arrowstyle="-|>", mutation_scale=14,
                                         color=COLOURS["witness"], lw=0, gid=f"{gid}-head",
                                         zorder=7))
            legend(Line2D([], [], color=COLOURS["witness"], lw=1.8, ls=ls), label)
        elif w.kind == "mirror":
            _line(ax, w.line, color=COLOURS["witness"], lw=1.8, ls=ls, gid=gid, zorder=7)
            legend(Line2D([], [], color=COLOURS["witness"], lw=1.8, ls=ls), label)
        elif w.kind == "line":
            _line(ax, w.line, color=COLOURS["witness_line"], lw=0.9, ls=ls, gid=gid, zorder=3)
            legend(Line2D([], [], color=COLOURS["witness_line"], lw=0.9, ls=ls), label)
        elif w.kind == "robots":
            for i, r in enumerate(w.robots):
                ax.add_patch(CirclePatch(xy[r], 0.05 * R, fill=False, lw=1.8, ls=ls,
                                         ec=COLOURS["witness"], gid=f"{gid}-{i}", zorder=7))
            legend(Line2D([], [], marker="o", ms=10, mfc="none", mec=COLOURS["witness"],
                          ls="none"), label)
        elif w.kind == "levels":
            for i, k in enumerate(w.levels):
                c = levels.get(f"G{k}")
                if c is not None:
                    ax.add_patch(CirclePatch(c.centre, c.radius, fill=False, lw=3, alpha=0.5,
                                             ls=ls, ec=COLOURS["witness"], gid=f"{gid}-{i}",
                                             zorder=2))
            legend(Line2D([], [], color=COLOURS["witness"], lw=3, alpha=0.5, ls=ls), label)
        else:
            legend(Line2D([], [], ls="none"), label + " (no witness to draw)")


def _statements(labels) -> str:
    labels = list(labels)
    return ", ".join(labels[:5]) + (f" +{len(labels) - 5} more" if len(labels) > 5 else "")
