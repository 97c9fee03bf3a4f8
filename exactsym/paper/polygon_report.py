"""Report section: the paper's verdicts on each level polygon (Section 3 and 4.1).

Each entry of ``report["levels"]`` gains ``"paper"``::

    {"straight": bool, "skew": bool, "degree": int or "p/q" string,
     "type": "type-0".."type-4" | "unclassified" | null, "type_reason": str,
     "symmetric": bool, "theorem1_symmetric": bool, "lines": int, "check": name}

``straight``/``skew``/``degree``/``symmetric`` are what Check_Symmetry_Odd/Even report
(efficient versions, equal to the printed loops; the odd check read with i++ after every
vertex); ``degree`` is deg_sym/2 for even n and may be a fraction (written "3/2");
``theorem1_symmetric`` is Theorem 1's verdict; ``lines`` and ``type`` come from the
lines of straight symmetry the strings find (vertex and edge-midpoint palindromes).
``loop_terminates`` (odd n): whether Check_Symmetry_Odd *as printed* stops (it does not
once a vertex has CW = ACW).  ``definition``: ``def-straight-symmetric-poly`` /
``def-skew-symmetric-poly`` evaluated exactly, with the number of mirrors (null above
:data:`DEFINITION_LIMIT`).  ``leader_sym`` / ``leader_sym_by_lines``: Elect_Leader_Sym with
the check's degree / with the number of lines (when the check says symmetric);
``leader_asym``: Elect_Leader_Asym for the observers of both handednesses, ``{"+1": label,
"-1": label, "tie": bool}`` (when the check says asymmetric); labels are point indices,
null when no leader is elected; all three null above :data:`LEADER_LIMIT`.
The level of radius 0 (a robot at C) gets ``"paper": null``.

With ``options["strings"]`` the entry also gains ``"strings"``:
``{"metric": "angular-distance" | "signed-squared-cosine", "cw": [[...], ...],
"acw": [[...], ...]}`` (per vertex, in the level's order, orientation of the file's
axes), or ``{"omitted": reason}`` above :data:`STRING_LIMIT` vertices.
"""

from __future__ import annotations

from ..exact import as_fmpq, number_text, sign
from ..report import SECTIONS
from . import polygon as paper
from .circle_polygon import level_polygon

#: Largest polygon whose CW/ACW strings are written out (n^2 numbers).
STRING_LIMIT = 60
#: Largest polygon on which the definitions are evaluated exactly (O(n^2)).
DEFINITION_LIMIT = 400
#: Largest polygon on which Elect_Leader_Sym / Elect_Leader_Asym are run (O(n^2 log n)).
LEADER_LIMIT = 200


def degree_json(value):
    """An exact degree as JSON: an int when integral, else the string "p/q"."""
    q = as_fmpq(value)
    return int(q.p) if q.q == 1 else f"{q.p}/{q.q}"


def level_verdicts(polygon) -> dict:
    """The ``"paper"`` entry for one polygon."""
    n = polygon.n
    check = paper.check_symmetry(polygon)
    lines = paper.straight_lines(polygon)
    kind = paper.polygon_type(polygon, lines)
    out = {
        "check": check.algorithm,
        "symmetric": check.symmetric,
        "straight": check.straight,
        "skew": check.skew,
        "degree": degree_json(check.degree),
        "loop_terminates": (not check.axis_vertices) if n % 2 else None,
        "theorem1_symmetric": not paper.theorem1_asymmetric(polygon),
        "lines": len(lines),
        "type": None if kind is None else str(kind),
        "type_reason": None if kind is None else kind.reason,
    }
    if n <= DEFINITION_LIMIT:
        mirrors = paper.definition_mirrors(polygon)
        out["definition"] = {"straight": bool(mirrors), "skew": paper.is_skew_symmetric(polygon),
                             "mirrors": len(mirrors)}
    else:
        out["definition"] = None
    if n <= LEADER_LIMIT:
        if check.symmetric:
            out["leader_sym"] = paper.elect_leader_sym(polygon).label
            out["leader_sym_by_lines"] = paper.elect_leader_sym(polygon, degree="lines").label
            out["leader_asym"] = None
        else:
            plus = paper.elect_leader_asym(polygon, 1)
            minus = paper.elect_leader_asym(polygon, -1)
            out["leader_sym"] = out["leader_sym_by_lines"] = None
            out["leader_asym"] = {"+1": plus.label, "-1": minus.label,
                                  "tie": plus.tie or minus.tie}
    else:
        out["leader_sym"] = out["leader_sym_by_lines"] = out["leader_asym"] = None
    return out


def _key_text(key) -> str:
    return number_text(key)


def level_strings(polygon) -> dict:
    if polygon.n > STRING_LIMIT:
        return {"omitted": f"{polygon.n} vertices: strings are written for at most "
                           f"{STRING_LIMIT}"}
    strings = paper.vertex_strings(polygon)
    return {"metric": polygon.metric,
            "vertices": list(polygon.labels),
            "cw": [[_key_text(k) for k in cw] for cw, _ in strings],
            "acw": [[_key_text(k) for k in acw] for _, acw in strings]}


def polygon_section(config, rings, report, options) -> None:
    for index, (level, entry) in enumerate(zip(rings.levels, report["levels"])):
        if sign(level.radius_squared) == 0:
            entry["paper"] = None
            continue
        polygon = level_polygon(config, rings, index)
        entry["paper"] = level_verdicts(polygon)
        if options.get("strings"):
            entry["strings"] = level_strings(polygon)


if polygon_section not in SECTIONS:
    SECTIONS.append(polygon_section)
