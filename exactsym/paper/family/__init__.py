"""The paper on whole configurations: the concentric polygons G = (G_1, ..., G_t).

One module per algorithm of the paper: :mod:`.limits` (work budgets), :mod:`.concentric`
(the G model, lines of symmetry), :mod:`.projection` (radial projection, type 4),
:mod:`.preprocess`, :mod:`.find_asymmetry`, :mod:`.claims` (the Section-3 statements),
:mod:`.make_asym`, :mod:`.elect_leader`, :mod:`.gathering_decision` (the whole procedure)
and :mod:`.trace`; this package re-exports their public names.

Section 3 from ``def-sym-pair`` to ``cor-Pasym-Pord`` and the algorithms of Section 4
that work on G: ``ElectLeader``, ``Preprocess``, ``MakeAsym`` (with the helpers it names
but does not give, ``FindAsymmetry`` and ``Find_Asymmetry_Pair``) and the decision of
``GatheringPattern``.  Single polygons are :mod:`exactsym.paper.polygon`'s business
(Check_Symmetry_*, Elect_Leader_Sym, Make_SymToAsym, Elect_Leader_Asym, polygon types); this
package calls them and never re-implements them.  It never imports the ground truth
(:mod:`exactsym.truth.symmetry`): the audit (:mod:`exactsym.audit.statements`) compares the two.

Every reading chosen where the paper is ambiguous is listed in
``docs/interpretations.md`` (section "The family layer"); the essentials:

Lines of symmetry and "common line" (``def-sym-pair``, ``def-sym-calG``)
    A line of symmetry of a polygon inscribed in a circle passes through the centre C
    (``lemma-LOS-Passes-CenterSECP``), so it is a direction modulo half a turn and is
    held as an exact *line key*: on the polar path the turn of the line in [0, 1/2), on
    the Cartesian path the ray of the doubled angle (the keys of
    :func:`exactsym.paper.polygon.definition_mirrors`).  :func:`lines_of_symmetry` returns

    * :data:`ALL_LINES` when the polygon is skew symmetric (the half-turn about C maps it
      onto itself, :func:`exactsym.paper.polygon.is_skew_symmetric`): by ``lem-skew-los``
      *every* line through C is then a line of (skew) symmetry; likewise for the robot at C (a
      singleton: ``def-symmetric-conf`` says every line through it is a line of symmetry);
    * otherwise the finite set of its lines of straight symmetry (exact mirrors, from the
      definition; a single vertex has exactly the line through C and it, the paper's
      note after ``def-asymmetric-poly``).

    Two or more polygons have a common line iff these sets intersect (ALL_LINES is the
    neutral element).  So a skew symmetric polygon makes a symmetric pair with every
    symmetric polygon, whatever kind of line the other one has: the paper never says a
    "common" line must be of the same kind, and ``lem-3-pair-sym``'s proof uses exactly
    this (first bullet).

Radial projection (G_ij)
    "the vertices of G_i are projected radially on the circumference of the enclosing
    circle of G_j; construct a polygon G_ij with the full set of vertices on the circle":
    :func:`radial_projection` takes *directions only* (rational turns, or exact vectors
    from C scaled to the target circle when the ratio of the radii is rational) and puts
    the union on the target's circle.  When a vertex of G_i and one of G_j lie on one ray
    they would coincide on the circle (the paper ignores this); we merge them into *one*
    vertex whose label lists both robots (set semantics: "the full set of vertices"), and
    the projection records the coincidences (``Projection.coincident``): a finding, since
    G_ij then has fewer than n_i + n_j vertices and its symmetry can differ from the
    paper's counts (``obs-gcd``, ``obs-type-4``).  The robot at C has no direction and is
    never projected.

Vertex labels
    Every polygon here has vertex labels that are *tuples of configuration indices* (one
    robot, or several merged on a ray).  A vertex "of G_t" in a projection is one whose
    label holds a robot of G_t; it is mapped back to the robot of that label lying on
    G_t's own circle (else the innermost robot of the label).

Printed line numbers
    ``line`` in the trace counts, in the printed algorithm, every ``if``/``while``/``for``
    header and every statement ending in ``\\;``, in order; ``else`` and ``end`` are not
    counted (algorithm2e's numbering of those depends on options the source does not
    fix).  The numbers are listed in ``docs/interpretations.md``.

Bounds (near-linear time and memory for every input)
    On random configurations every level is a single robot (t = n).  Nothing computes all
    pairs eagerly: Preprocess builds G_ij only for pairs an exact prefilter cannot reject
    (shared rays counted by hashing exact ray keys), ``Find_Asymmetry_Pair`` finds the
    first pair through an index of lines, the projection of all polygons is built once.
    The Section-3 checks run on a documented selection of pairs and triples, failures are
    listed a few times and then counted, the trace and the lists of polygons are capped:
    :class:`Limits` (``UNBOUNDED``: everything, no budget), ``PaperResult.bounded`` says
    what was bounded; ``docs/interpretations.md``, "Bounds of the family layer".

The trace is a list of dicts ``{"algorithm", "line", "polygons", "statement", "detail"}``
with, where they apply, ``"robots"`` (configuration indices selected or moved), ``"branch"``
(a stable name of the branch taken), ``"holds"`` (False when the step's claim is false on
this configuration: a finding; the audit collects them) and ``"round"``.
"""

from __future__ import annotations

from .limits import (MAX_QUADRATIC_N, Limits, DEFAULT_LIMITS, UNBOUNDED, WorkBudgetExceeded,
                     MAX_PAIRS, MAX_TRIPLES)
from .trace import (BRANCHES, compact_trace)
from .concentric import (ALL_LINES, Ring, concentric_polygons, lines_of_symmetry, common_lines,
                         is_symmetric_polygon, is_symmetric_pair, is_symmetric_family, line_text,
                         mirror_lines, centrally_symmetric, lines_text, intersect_lines, is_polar,
                         has_lines)
from .projection import (Projection, radial_projection, is_type4)
from .preprocess import (preprocess, preprocess_literal, LiteralRun, SMALL_FAMILY)
from .find_asymmetry import (find_asymmetry, find_asymmetry_pair)
from .claims import (family_claims, select_pairs, select_triples, sampled_pairs, union_lines)
from .make_asym import (make_asym, MakeAsymResult)
from .elect_leader import (elect_leader, ElectLeaderResult)
from .gathering_decision import (paper_procedure, PaperResult)

__all__ = [
    "ALL_LINES",
    "Ring",
    "Projection",
    "concentric_polygons",
    "lines_of_symmetry",
    "common_lines",
    "is_symmetric_polygon",
    "is_symmetric_pair",
    "is_symmetric_family",
    "radial_projection",
    "is_type4",
    "preprocess",
    "preprocess_literal",
    "LiteralRun",
    "find_asymmetry",
    "find_asymmetry_pair",
    "family_claims",
    "make_asym",
    "MakeAsymResult",
    "elect_leader",
    "ElectLeaderResult",
    "paper_procedure",
    "PaperResult",
    "line_text",
    "MAX_QUADRATIC_N",
    "BRANCHES",
    "mirror_lines",
    "centrally_symmetric",
    "Limits",
    "DEFAULT_LIMITS",
    "UNBOUNDED",
    "WorkBudgetExceeded",
    "select_pairs",
    "select_triples",
    "MAX_PAIRS",
    "MAX_TRIPLES",
    "SMALL_FAMILY",
    "compact_trace",
    "lines_text",
    "intersect_lines",
    "is_polar",
    "sampled_pairs",
    "union_lines",
    "has_lines",
]
