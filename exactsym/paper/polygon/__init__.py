"""Section 3 and Section 4.1 of the paper for one convex polygon inscribed in a circle.

One module per part of the paper: :mod:`.strings` (CW/ACW strings and their classes),
:mod:`.definitions` (the definitions evaluated exactly, Theorem 1), :mod:`.types`
(lines of straight symmetry, polygon types), :mod:`.check_symmetry`
(Check_Symmetry_Odd/Even) and :mod:`.leaders` (Elect_Leader_Sym, Make_SymToAsym,
Elect_Leader_Asym); this package re-exports their public names.

Everything here follows the paper's words; where the paper is ambiguous the
reading chosen is stated in the docstring and in ``docs/interpretations.md``.
This module never imports the ground truth (:mod:`exactsym.truth.symmetry`).

Strings (Section 3, before ``lemma-straight-sym``)
--------------------------------------------------
For a point m where a line meets the polygon, "the vertices are labeled starting
from the vertex next (clockwise) to m up to the previous vertex of m, as
v_1, ..., v_n" (n = k-1 for a vertex m, n = k for a point m on an edge) and
``CW_m = (|m v_1|, ..., |m v_n|)``, ``ACW_m`` its reverse.  Our polygons are stored
counter-clockwise, so for the observer of ``orientation = +1`` (same handedness
as the file's axes) "next clockwise" is the previous index; an observer of the
other handedness (``orientation = -1``) swaps CW and ACW.  Distances are exact
*keys* (:mod:`exactsym.paper.circle_polygon`): strictly increasing maps preserve equality and
lexicographic order, which is all the paper uses.  For m on an edge we take the
edge's midpoint (where the edge's perpendicular bisector meets the polygon).

Two facts used throughout (proved in ``docs/interpretations.md``):

* equal chord strings do not always mean congruent views: a chord length
  ``2r sin(pi d)`` does not tell an arc d from its complement 1-d.  For a string
  of odd length (a vertex of an even polygon, an edge point of an odd polygon)
  ``CW_m = ACW_m`` says nothing about the middle vertex, so it does *not* imply a
  mirror through m; and two vertices may have equal strings with no isometry
  mapping one to the other (the farthest vertex read on the other side);
* a string is determined by its *canonical angle sequence*: read each chord as
  the arc below half a turn up to the first maximum of the string, as the
  complement after it.  :func:`string_classes` groups the 2n vertex strings by
  this canonical form in near-linear time (rolling hashes proposing, exact
  comparison deciding), and is proved equal to the literal strings by tests.
"""

from __future__ import annotations

from __future__ import annotations

from .strings import (cw_string, acw_string, cw_string_edge, acw_string_edge, vertex_strings,
                      edge_strings, string_classes, string_classes_reference, perpendicular)
from .definitions import (is_straight_symmetric, is_skew_symmetric, is_symmetric,
                          definition_mirrors, definition_mirror_keys, theorem1_asymmetric, theorem1_1_asymmetric,
                          theorem1_violations)
from .types import (vertex_palindromes, edge_palindromes, StraightLine, straight_lines,
                    straight_line_count,
                    is_regular, TypeVerdict, polygon_type, vertices_on_line)
from ...exact.factor import is_prime
from .check_symmetry import (CheckResult, check_symmetry_odd, check_symmetry_even, check_symmetry,
                             check_symmetry_odd_reference, check_symmetry_even_reference,
                             check_symmetry_odd_literal)
from .leaders import (SymLeader, elect_leader_sym, MoveResult, make_sym_to_asym, AsymLeader,
                      elect_leader_asym, remove_vertex, reflect_polygon)

__all__ = [
    "cw_string",
    "acw_string",
    "cw_string_edge",
    "acw_string_edge",
    "vertex_strings",
    "edge_strings",
    "is_straight_symmetric",
    "is_skew_symmetric",
    "is_symmetric",
    "definition_mirrors",
    "definition_mirror_keys",
    "theorem1_asymmetric",
    "theorem1_1_asymmetric",
    "theorem1_violations",
    "string_classes",
    "string_classes_reference",
    "vertex_palindromes",
    "edge_palindromes",
    "StraightLine",
    "straight_lines",
    "straight_line_count",
    "is_regular",
    "is_prime",
    "TypeVerdict",
    "polygon_type",
    "vertices_on_line",
    "CheckResult",
    "check_symmetry_odd",
    "check_symmetry_even",
    "check_symmetry",
    "check_symmetry_odd_reference",
    "check_symmetry_even_reference",
    "check_symmetry_odd_literal",
    "SymLeader",
    "elect_leader_sym",
    "MoveResult",
    "make_sym_to_asym",
    "AsymLeader",
    "elect_leader_asym",
    "remove_vertex",
    "reflect_polygon",
    "perpendicular",
]
