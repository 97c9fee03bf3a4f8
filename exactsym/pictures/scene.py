"""What a picture of a configuration shows, as plain data (no exactsym imports).

:mod:`._bridge` fills a :class:`Scene` from the library's results; :mod:`.draw` draws
it with matplotlib.  Exact numbers are kept beside the float copies that are only
for drawing (``xy``, ``radius``, ``angle``): nothing here decides anything.
Angles are in radians, counter-clockwise from the +x axis of the file.
"""

from __future__ import annotations

from dataclasses import dataclass, field


@dataclass(frozen=True)
class Robot:
    """Robot ``index`` (as numbered in the file).  ``exact``: its exact coordinates as
    held by the library (``(x, y)``, or ``(r^2, turn)`` when ``polar``); ``xy``: floats
    for drawing; ``rank``: its place in the canonical ordering (None if not orderable)."""
    index: int
    exact: tuple
    polar: bool
    xy: tuple[float, float]
    rank: int | None = None


@dataclass(frozen=True)
class Circle:
    """A circle about ``centre`` (floats); ``radius_squared`` exact, ``radius`` float."""
    label: str
    centre: tuple[float, float]
    radius_squared: object
    radius: float
    robots: tuple[int, ...] = ()


@dataclass(frozen=True)
class Line:
    """A line through ``through`` at angle ``angle`` (mod pi); drawn as the chord of the
    circle of radius ``reach`` about ``through``.  ``kind``: ``"mirror"`` (ground truth),
    ``"straight"`` (a paper test's line of straight symmetry) or ``"witness"``."""
    label: str
    through: tuple[float, float]
    angle: float
    reach: float
    kind: str
    exact: object = None


@dataclass(frozen=True)
class Rotation:
    """The ground truth's rotations: order ``order`` about ``centre``."""
    centre: tuple[float, float]
    order: int


@dataclass(frozen=True)
class PaperLevel:
    """What the paper's symmetry test (Check_Symmetry_Odd/Even) reports on one level.
    ``straight``: the lines of straight symmetry its strings find; ``skew``: whether it
    reports skew symmetry (a half-turn about C); ``skew_pairs``: vertex pairs the
    half-turn exchanges (drawn), ``symmetric``: its verdict."""
    level: int
    check: str
    symmetric: bool
    straight: tuple[Line, ...]
    skew: bool
    skew_pairs: tuple[tuple[int, int], ...] = ()


@dataclass(frozen=True)
class Paper:
    """The paper's side: per-level tests and the leader its procedure elects."""
    levels: tuple[PaperLevel, ...]
    leader: int | None
    orderable: bool


@dataclass(frozen=True)
class Witness:
    """One failing statement of the audit and what can be drawn of its witness.

    ``statements``: the labels it stands for (one witness drawn once for several);
    ``text``: a legend line; ``kind``: ``"rotation"`` (``robots = (a, b)``: the
    rotation about ``centre`` by ``angle`` radians maps a to b), ``"mirror"``
    (``line``: the mirror maps a to b), ``"robots"`` (robots to mark, e.g. two
    leaders), ``"levels"`` (level numbers to mark), ``"line"`` or ``"none"``."""
    statements: tuple[str, ...]
    text: str
    kind: str
    robots: tuple[int, ...] = ()
    levels: tuple[int, ...] = ()
    centre: tuple[float, float] | None = None
    angle: float | None = None
    line: Line | None = None


@dataclass(frozen=True)
class Scene:
    """Everything a picture of a configuration shows."""
    title: str
    model: str                      # "fat": unit discs; "points"
    robots: tuple[Robot, ...]
    centre: tuple[float, float]     # the SEC centre C
    centre_exact: tuple
    sec: Circle
    levels: tuple[Circle, ...]
    group: str
    rotation: Rotation | None
    mirrors: tuple[Line, ...]
    mirrors_total: int
    leader: int | None
    orderable: bool
    paper: Paper | None = None
    audit: tuple[Witness, ...] | None = None
    notes: tuple[str, ...] = field(default=())

    @property
    def n(self) -> int:
        return len(self.robots)
