"""The one analysis pipeline: levels, truth, the paper's verdicts and the audit, once each.

:func:`analyse` is the only place that decides what is computed and in which order::

    config -> levels (SEC, G1..Gt) -> truth (symmetry group)
                                   -> paper, per level (polygon layer)
                                   -> paper, whole family (Preprocess, MakeAsym, ElectLeader)
                                   -> audit (paper against truth)

Every command and both renderings of the report (:mod:`exactsym.report.check`: JSON and text)
read the :class:`Analysis` it returns; nothing appends itself to anything at import.

The work the layers remember per number or vector object (balls, gaps, homogeneous forms
of directions) is held by one :class:`~exactsym.exact.context.AnalysisContext`
per analysis, made here and kept in the :class:`Analysis` (its report reads the same
forms): no module keeps anything of one configuration for the next.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

from .audit.result import AuditResult
from .audit.statements import audit as run_audit
from .exact.context import AnalysisContext
from .geometry.configuration import Configuration, no_cycle_collection
from .geometry.levels import Level, Levels, RationalLevels, VectorTable, levels_of
from .paper.family import DEFAULT_LIMITS, PaperResult, paper_procedure
from .paper.circle_polygon import level_polygon
from .paper.polygon import straight_lines
from .paper.polygon_report import level_section
from .truth.near_symmetry import NearSymmetry, near_symmetry_hint
from .truth.symmetry import SymmetryGroup, symmetry_group

#: The parts :func:`analyse` can compute, in the order it computes them.
PARTS = ("truth", "polygons", "family", "audit")
#: What each part needs besides the levels (always computed).
NEEDS = {"truth": (), "polygons": (), "family": (), "audit": ("truth", "polygons", "family")}


@dataclass(frozen=True)
class Options:
    """Readings passed to the paper's algorithms and what the report shows.

    ``strings``: the CW/ACW strings of each level; ``reading``/``degree``: the readings
    of Elect_Leader_Asym / Elect_Leader_Sym (:mod:`exactsym.paper.polygon`);
    ``invariance``: the audit recomputes the paper in other frames; ``listed``: how many
    failures of a statement checked on many levels or pairs are listed with their
    witnesses before the rest are only counted (None: the family layer's default,
    :class:`exactsym.paper.family.Limits`; the text summary, which shows the first, asks
    for 1: in a field of degree thousands each witness is megabytes of exact text);
    ``screen``: the witnesses are read on the screen only (the text summary), so a
    number whose exact text would be megabytes is written by its decimal
    (:class:`exactsym.paper.family.Limits` ``screen_texts``)."""
    strings: bool = False
    reading: str = "literal"
    degree: str = "paper"
    invariance: bool = True
    listed: int | None = None
    screen: bool = False


@dataclass(frozen=True)
class Analysis:
    """Everything ``exactsym check`` knows about one configuration.  A part not asked
    for (``sections`` of :func:`analyse`) is None.

    ``levels``: the SEC and G1..Gt; ``truth``: the exact symmetry group;
    ``level_verdicts``: per level, the polygon layer's verdicts (a JSON-ready dict, None
    for the robot at C); ``level_strings``: per level, the CW/ACW strings (None unless
    ``options.strings``); ``paper``: the family layer's result; ``audit``: the audit's
    :class:`~exactsym.audit.result.AuditResult` (:func:`exactsym.audit.statements.audit`;
    ``.as_dict()``: its JSON); ``context``: the caches the
    analysis filled, which its report reads (:meth:`reading`)."""
    config: Configuration
    options: Options
    levels: Levels
    truth: SymmetryGroup | None = None
    level_verdicts: tuple | None = None
    level_strings: tuple | None = None
    paper: PaperResult | None = None
    audit: AuditResult | None = None
    context: AnalysisContext = field(default_factory=AnalysisContext, compare=False,
                                     repr=False)

    def reading(self):
        """A ``with`` block in which lazy texts of the analysis read its caches (the
        short texts of directions, :mod:`exactsym.paper.homogeneous`)."""
        return self.context.active()

    def straight_lines(self, k: int) -> tuple:
        """The exact keys of the lines of straight symmetry that the CW/ACW strings find
        on level ``k`` (0-based; ``lemma-straight-sym``, :func:`exactsym.paper.polygon.straight_lines`),
        made on demand: the pictures draw them, the report only counts them
        (``lines_by_strings``)."""
        with self.reading():
            return tuple(line.key for line in
                         straight_lines(level_polygon(self.config, self.levels, k)))

    def near_symmetry(self) -> NearSymmetry | None:
        """A configuration of a larger group near this one
        (:func:`exactsym.truth.near_symmetry.near_symmetry_hint`: a hint, never a verdict),
        made on demand: the text summary shows it, nothing else reads it."""
        return near_symmetry_hint(self.config)


def analyse(config: Configuration, sections=PARTS, options: Options | None = None) -> Analysis:
    """Compute ``sections`` (names from :data:`PARTS`, and what they need) of ``config``,
    each once, in the order of :data:`PARTS`.  Raises ValueError for an unknown name.

    >>> from exactsym import analyse, load, report_text
    >>> a = analyse(load("cases/discrepancies/d3-hexagon.toml"))
    >>> a.truth.name, a.truth.mirrors, a.truth.orderable, a.audit.agrees
    ('D3', 3, False, False)
    >>> [d["statement"] for d in a.audit.discrepancies]
    ['obs-exh-poly', 'Check_Symmetry_Even']
    >>> [len(level.points) for level in a.levels.levels]
    [6]
    >>> print(report_text(a).splitlines()[4])
    symmetry   D3: 3 rotations about C (by multiples of 1/3 turn), 3 mirror lines through C (one between robots 0 and 1, which it swaps)
    >>> analyse(a.config, sections=["truth"]).paper is None     # only what is asked for
    True
    """
    options = options if options is not None else Options()
    wanted = set(sections)
    unknown = wanted - set(PARTS)
    if unknown:
        raise ValueError(f"unknown analysis part(s): {sorted(unknown)}; known: {PARTS}")
    for part in PARTS[::-1]:
        if part in wanted:
            wanted.update(NEEDS[part])
    context = AnalysisContext()         # this configuration's caches, dropped with it
    with no_cycle_collection(), context.active():
        levels = levels_of(config)
        truth = symmetry_group(config, levels) if "truth" in wanted else None
        if wanted - {"truth"}:
            levels = built_levels(levels)
        verdicts = strings = types = polygons = None
        if "polygons" in wanted:
            section = level_section(config, levels, options.strings)
            verdicts, strings, types = section.verdicts, section.strings, section.types
            polygons = section.polygons
        limits = replace(DEFAULT_LIMITS, screen_texts=options.screen) if options.listed is None \
            else replace(DEFAULT_LIMITS, claim_examples=options.listed, screen_texts=options.screen)
        paper = paper_procedure(config, levels, reading=options.reading,
                                degree=options.degree, level_polygons=polygons,
                                limits=limits) if "family" in wanted else None
        audited = run_audit(config, levels, paper, {"reading": options.reading,
                                                    "degree": options.degree,
                                                    "invariance": options.invariance,
                                                    "limits": limits},
                            group=truth, level_verdicts=verdicts,
                            level_types=types) if "audit" in wanted else None
    return Analysis(config, options, levels, truth, verdicts, strings, paper, audited,
                    context)


def built_levels(levels: Levels) -> Levels:
    """``levels`` with its levels built once as a tuple of :class:`Level` (equal to the
    lazy :class:`RationalLevels` it may hold, which builds a level each time it is read):
    the truth reads few levels, but the polygon layer, the family layer, the audit and the
    report each read all of them (issue 9: on 100,000 random points that was 400,000
    levels built)."""
    lazy = levels.levels
    if not isinstance(lazy, RationalLevels):
        return levels
    flat, bounds, known = lazy.flat, lazy.bounds, lazy.known
    # a one-point level's squared radius is |p - C|^2 of its point, as
    # RationalLevels.radius_squared writes it; the vector p - C is kept (Levels.vectors)
    # for the family layer's polygons, which computed it again (one per robot on random
    # input).  The vectors are named by the configuration's own point sequence, which
    # Levels.floats holds (the lazy levels hold a copy of it).
    pts, centre = lazy.points, lazy.centre
    owner = levels.floats[0] if levels.floats is not None else None
    vectors = VectorTable([None] * len(pts)) \
        if lazy.radii is None and pts is not None and owner is not None else None
    if vectors is not None:
        cx, cy = centre
    new, setter = object.__new__, object.__setattr__
    built = []
    any_vector = False
    for k, (start, stop) in enumerate(zip(bounds, bounds[1:])):
        points = (flat[start],) if stop - start == 1 else tuple(flat[start:stop])
        r2 = known.get(k)
        if r2 is None:
            if vectors is not None and stop - start == 1:
                any_vector = True
                i = points[0]
                x, y = pts[i]
                dx, dy = x - cx, y - cy
                vectors[i] = (dx, dy)
                r2 = dx * dx + dy * dy
            else:
                r2 = lazy.level_radius(k, points[0])
        level = new(Level)          # Level(r2, points) without the frozen __init__
        setter(level, "radius_squared", r2)
        setter(level, "points", points)
        built.append(level)
    return replace(levels, levels=tuple(built),
                   vectors=(owner, vectors) if vectors and any_vector else levels.vectors)


__all__ = ["Analysis", "Options", "analyse", "PARTS"]
