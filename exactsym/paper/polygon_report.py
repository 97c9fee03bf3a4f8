"""The paper's verdicts on each level polygon (Section 3 and 4.1), for the report.

:func:`level_reports` gives, per level, the ``"paper"`` entry of ``report["levels"]``
(:mod:`exactsym.analysis` calls it once; :mod:`exactsym.report.check` places it)::

    {"straight": bool, "skew": bool, "degree": int or "p/q" string,
     "type": "type-0".."type-4" | "unclassified" | null, "type_reason": str,
     "symmetric": bool, "theorem1_symmetric": bool, "lines_by_strings": int, "check": name}

``straight``/``skew``/``degree``/``symmetric`` are what Check_Symmetry_Odd/Even report
(efficient versions, equal to the printed loops; the odd check read with i++ after every
vertex); ``degree`` is deg_sym/2 for even n and may be a fraction (written "3/2");
``theorem1_symmetric`` is Theorem 1's verdict; ``lines_by_strings`` counts the lines of
straight symmetry the strings find (vertex and edge-midpoint palindromes,
``lemma-straight-sym``), which can exceed the mirrors; ``type`` is the type by its
definition, from the exact mirrors (:func:`exactsym.paper.polygon.polygon_type`).
``loop_terminates`` (odd n): whether Check_Symmetry_Odd *as printed* stops (it does not
once a vertex has CW = ACW).  ``definition``: ``def-straight-symmetric-poly`` /
``def-skew-symmetric-poly`` evaluated exactly, with the number of mirrors (null above
:data:`DEFINITION_LIMIT`).  ``leader_sym`` / ``leader_sym_by_lines``: Elect_Leader_Sym with
the check's degree / with the number of lines (when the check says symmetric);
``leader_asym``: Elect_Leader_Asym for the observers of both handednesses, ``{"+1": label,
"-1": label, "tie": bool}`` (when the check says asymmetric); labels are point indices,
null when no leader is elected; all three null above :data:`LEADER_LIMIT`.
The level of radius 0 (a robot at C) gets ``"paper": null``.

Verdicts are computed once per polygon *shape* (:func:`verdict_key`: for 4 to
:data:`MEMO_LIMIT` vertices the combinatorial shape of
:mod:`exactsym.paper.polygon_shape`, gaps, lines and chord ranks interned to small
integers, with the proof that equal shapes get equal verdicts; otherwise
:func:`shape_key`, equal counter-clockwise gaps from vertex 0, i.e. a rotation and
scaling keeping the storage order) and relabelled by position for the other levels of
that shape (every single-robot level shares one): a configuration of t levels of one
shape costs one computation.

With ``options["strings"]`` the entry also gains ``"strings"``:
``{"metric": "angular-distance" | "signed-squared-cosine", "cw": [[...], ...],
"acw": [[...], ...]}`` (per vertex, in the level's order, orientation of the file's
axes), or ``{"omitted": reason}`` above :data:`STRING_LIMIT` vertices.
"""

from __future__ import annotations

import json
from collections.abc import Sequence

from dataclasses import dataclass, field

from ..exact import as_fmpq, exact_key, number_text, sign
from ..exact.number import any_algebraic
from ..geometry.configuration import no_cycle_collection
from . import polygon as paper
from .circle_polygon import level_polygon
from .family.concentric import mirror_lines
from .keys import ccw_gap_key, gap_equality_key
from .polygon_shape import MIN_VERTICES, combinatorial_key

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
    return _verdicts_and_type(polygon)[0]


def _type_facts(kind) -> tuple | None:
    """What the audit reads of a polygon's type (:func:`exactsym.audit.levels.level_findings`,
    ``lemma-sym-regular``): its name and whether every mirror passes through a vertex."""
    if kind is None:
        return None
    return (str(kind), all(t > 0 for t in kind.through))


def _verdicts_and_type(polygon) -> tuple[dict, tuple | None]:
    """``(level_verdicts(polygon), type facts)`` (:func:`_type_facts`)."""
    n = polygon.n
    check = paper.check_symmetry(polygon)
    lines = paper.straight_line_count(polygon)       # no line values: no division
    mirrors = mirror_lines(polygon)       # exact line keys, O(n), no division
    kind = paper.polygon_type(polygon, mirrors)
    out = {
        "check": check.algorithm,
        "symmetric": check.symmetric,
        "straight": check.straight,
        "skew": check.skew,
        "degree": degree_json(check.degree),
        "loop_terminates": (not check.axis_vertices) if n % 2 else None,
        "theorem1_symmetric": not paper.theorem1_asymmetric(polygon),
        "lines_by_strings": lines,
        "type": None if kind is None else str(kind),
        "type_reason": None if kind is None else kind.reason,
    }
    if n <= DEFINITION_LIMIT:
        mirrors = paper.definition_mirror_keys(polygon)
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
    return out, _type_facts(kind)


def _key_text(key) -> str:
    return number_text(key)


def level_strings(polygon) -> dict:
    if polygon.n > STRING_LIMIT:
        return {"omitted": f"{polygon.n} vertices: strings are written for at most "
                f"{STRING_LIMIT}"}
    # the values of the metric (the separation), not the polygon's undivided chord keys
    n = polygon.n
    cw = [[_key_text(polygon.separation(i, (i - s) % n)) for s in range(1, n)]
          for i in range(n)]
    return {"metric": polygon.metric,
            "vertices": list(polygon.labels),
            "cw": cw,
            "acw": [row[::-1] for row in cw]}


#: Polygons of MIN_VERTICES to MEMO_LIMIT vertices share their verdicts with every
#: polygon of the same combinatorial shape (:func:`exactsym.paper.polygon_shape.combinatorial_key`,
#: O(n^2) small integers); the others with every polygon of the same exact shape
#: (:func:`shape_key`, O(n)).
MEMO_LIMIT = 64


def _hashable(key):
    if isinstance(key, tuple):
        return tuple(_hashable(k) for k in key)
    return exact_key(key)


def shape_key(polygon):
    """An exact hashable key equal for two polygons iff one is the image of the other by
    a rotation about C (and a scaling) that maps vertex k to vertex k (storage order):
    the counter-clockwise angular gaps between consecutive vertices, from vertex 0, as
    exact keys strictly increasing in the angle.  The paper's verdicts on one polygon
    depend only on its distances (the strings, Section 3) and on the storage order, so
    polygons with equal keys get equal verdicts, labels taken at the same positions."""
    n, dirs = polygon.n, polygon.directions
    if not polygon.polar and any_algebraic(c for d in dirs for c in d):
        # algebraic: keys equal iff the gap keys are (no inverse of a squared length: in
        # a field of degree thousands an inverse costs a second)
        return (False, n, tuple(gap_equality_key(dirs[k], dirs[(k + 1) % n])
                                for k in range(n)))
    return (polygon.polar, n, tuple(_hashable(ccw_gap_key(polygon.polar, dirs[k],
                                                          dirs[(k + 1) % n]))
                                    for k in range(n)))


_LABEL_KEYS = ("leader_sym", "leader_sym_by_lines")


def _relabelled(verdict: dict, labels: tuple, new_labels: tuple) -> dict:
    """``verdict`` (of a polygon with ``labels``) for a polygon of the same shape whose
    vertices, in the same storage order, carry ``new_labels``."""
    where = {lab: k for k, lab in enumerate(labels)}

    def relabel(lab):
        return lab if lab is None else new_labels[where[lab]]
    out = dict(verdict)
    for key in _LABEL_KEYS:
        out[key] = relabel(verdict.get(key))
    if isinstance(verdict.get("leader_asym"), dict):
        la = verdict["leader_asym"]
        out["leader_asym"] = {"+1": relabel(la["+1"]), "-1": relabel(la["-1"]),
                              "tie": la["tie"]}
    if isinstance(verdict.get("definition"), dict):
        out["definition"] = dict(verdict["definition"])
    return out


def verdict_key(polygon):
    """The key under which :class:`VerdictMemo` shares verdicts: the combinatorial shape
    (:func:`exactsym.paper.polygon_shape.combinatorial_key`: gaps, diameters, lines and
    chord ranks interned to small integers; its docstring proves that equal keys give
    equal verdicts) for :data:`MIN_VERTICES` to :data:`MEMO_LIMIT` vertices, else the
    exact shape (:func:`shape_key`)."""
    if MIN_VERTICES <= polygon.n <= MEMO_LIMIT:
        return combinatorial_key(polygon)
    return shape_key(polygon)


def _single_relabeller(verdict: dict, label):
    """``lambda new: _relabelled(verdict, (label,), (new,))`` for a single-vertex
    polygon, without the per-call lookups (one call per robot on random
    configurations); None when a label in ``verdict`` is not ``label``."""
    keys = [k for k in _LABEL_KEYS if verdict.get(k) is not None]
    asym = verdict.get("leader_asym")
    asym = asym if isinstance(asym, dict) else None
    labels = [verdict[k] for k in keys] + \
        ([x for x in (asym["+1"], asym["-1"]) if x is not None] if asym else [])
    if any(x != label for x in labels):
        return None
    definition = verdict.get("definition")
    definition = definition if isinstance(definition, dict) else None
    parts = _json_template(verdict, keys, asym)

    def relabelled(new) -> dict:
        out = LabelledVerdict(verdict)
        out.json_parts = parts
        for k in keys:
            out[k] = new
        if asym is not None:
            out["leader_asym"] = {"+1": None if asym["+1"] is None else new,
                                  "-1": None if asym["-1"] is None else new,
                                  "tie": asym["tie"]}
        if definition is not None:
            out["definition"] = dict(definition)
        return out
    relabelled.json_parts = parts       # the JSON text of relabelled(x): str(x).join(parts)
    return relabelled


class LabelledVerdict(dict):
    """A relabelled single-vertex verdict (a plain dict to every reader) that also
    carries its JSON text cut at the label: ``json_parts`` (or None), joined by the label
    it is the text of the dict (:func:`json_text`).  Every robot of a random
    configuration is a level with a verdict of this one shape: the report writes them
    from the template instead of encoding 100,000 dicts (issue 9)."""
    __slots__ = ("json_parts",)

    def json_text(self) -> str | None:
        """The dict's JSON text (separators ``", "`` and ``": "``), or None."""
        parts = self.json_parts
        if parts is None:
            return None
        return str(self[_LABEL_KEYS[0]]).join(parts)


#: A label no verdict holds, for :func:`_json_template` (written "\u0000label").
_MARK = "\0label"
_ENCODE = json.JSONEncoder(separators=(", ", ": ")).encode


def _json_template(verdict: dict, keys: list, asym) -> tuple | None:
    """The JSON text of ``verdict`` relabelled to a mark, cut at the mark (see
    :class:`LabelledVerdict`), or None unless every label in it is the one label of
    ``keys`` (both of them set) and ``leader_asym`` holds none."""
    if list(keys) != list(_LABEL_KEYS) or (asym is not None and (
            asym["+1"] is not None or asym["-1"] is not None)):
        return None
    marked = dict(verdict)
    for k in keys:
        marked[k] = _MARK
    parts = _ENCODE(marked).split(_ENCODE(_MARK))
    return tuple(parts) if len(parts) == len(keys) + 1 else None


class VerdictMemo:
    """:func:`level_verdicts` for many polygons: computed once per shape
    (:func:`verdict_key`), relabelled for the others (a configuration of t levels of one
    shape -- single robots, rotated regular polygons, the generic orbits of a dihedral
    group -- costs one computation, not t).  :meth:`type_facts` gives what the audit
    reads of the polygon's type, shared the same way.  Shapes of different vertex counts
    never match, so a polygon's key is computed only once a second polygon of its vertex
    count arrives (a key costs exact products: a configuration with one polygon of each
    size needs none)."""

    def __init__(self):
        self.memo: dict = {}
        self.waiting: dict = {}         # n -> the first polygon of n vertices, key pending
        self.keyed: set = set()         # vertex counts whose polygons are keyed

    def verdicts(self, polygon) -> dict:
        return self.verdicts_and_type(polygon)[0]

    def _flush(self, n: int) -> None:
        self.keyed.add(n)
        first = self.waiting.pop(n, None)
        if first is not None:
            poly, verdict, facts = first
            self.memo.setdefault(verdict_key(poly), (poly.labels, verdict, facts))

    def verdicts_and_type(self, polygon) -> tuple[dict, tuple | None]:
        n = polygon.n
        if n not in self.waiting and n not in self.keyed:
            verdict, facts = _verdicts_and_type(polygon)
            self.waiting[n] = (polygon, verdict, facts)
            return verdict, facts
        self._flush(n)
        key = verdict_key(polygon)
        hit = self.memo.get(key)
        if hit is None:
            verdict, facts = _verdicts_and_type(polygon)
            self.memo[key] = (polygon.labels, verdict, facts)
            return verdict, facts
        try:
            return _relabelled(hit[1], hit[0], polygon.labels), hit[2]
        except KeyError:            # a label that is not a vertex's: compute it
            return _verdicts_and_type(polygon)


@dataclass(frozen=True)
class LevelSection:
    """The polygon layer's part of the report, per level of ``levels`` (nearest first):
    ``verdicts``, the ``"paper"`` entries (None for the robot at C); ``strings``, the
    ``"strings"`` entries (None when not asked for); ``types``, what the audit reads of
    each level's type (``(name, every mirror through a vertex)``, None for no type or
    the robot at C: :func:`_type_facts`)."""
    verdicts: tuple
    strings: tuple | None
    types: tuple
    #: per level, the polygon built (None where none was: the robot at C, single robots):
    #: the family layer reuses its directions (``concentric_polygons``)
    polygons: tuple | None = field(default=None, compare=False, repr=False)


def level_reports(config, levels, strings: bool = False) -> tuple[tuple, tuple | None]:
    """``(verdicts, strings)`` of :func:`level_section`."""
    section = level_section(config, levels, strings)
    return section.verdicts, section.strings


def level_section(config, levels, strings: bool = False) -> LevelSection:
    """The :class:`LevelSection` of ``levels``: one verdict per polygon shape
    (:class:`VerdictMemo`), relabelled for the others."""
    with no_cycle_collection():
        return _level_section(config, levels, strings)


def _level_section(config, levels, strings: bool) -> LevelSection:
    memo = VerdictMemo()
    single = None          # the verdict of a single-vertex level, and its label
    verdicts, texts, types, polygons = [], [], [], []
    for index, level in enumerate(levels.levels):
        if index == 0 and sign(level.radius_squared) == 0:
            polygons.append(None)
            verdicts.append(None)
            texts.append(None)
            types.append(None)
            continue
        if len(level.points) == 1 and not strings:
            # every single vertex has the same shape: no polygon needs building
            if single is None:
                polygon = level_polygon(config, levels, index, cleared=True)
                verdict, facts = _verdicts_and_type(polygon)
                single = (_single_relabeller(verdict, polygon.labels[0]), facts)
            if single[0] is not None:
                polygons.append(None)
                verdicts.append(level.points[0])    # made when read (SingleVerdicts)
                types.append(single[1])
                continue
        polygon = level_polygon(config, levels, index, cleared=True)
        polygons.append(polygon)
        verdict, facts = memo.verdicts_and_type(polygon)
        verdicts.append(verdict)
        types.append(facts)
        texts.append(level_strings(polygon) if strings else None)
    made = tuple(verdicts) if single is None or single[0] is None \
        else SingleVerdicts(verdicts, single[0])
    return LevelSection(made, tuple(texts) if strings else None, tuple(types),
                        tuple(polygons))


class SingleVerdicts(Sequence):
    """The per-level verdicts of :func:`level_section` as a read-only sequence equal to the
    tuple of them (``==``; pickled as that tuple): the verdict of a level of one robot
    (every level of a random configuration), the one single-vertex verdict relabelled to
    its robot, is made when it is read (a million levels held a million dicts: issue 33);
    the others are held.  ``items[k]``: level k's verdict, or its robot (an int);
    ``relabelled.json_parts``: the JSON text of the verdict of robot x is
    ``str(x).join(json_parts)`` (None: no template, :class:`LabelledVerdict`)."""

    __slots__ = ("items", "relabelled")

    def __init__(self, items: list, relabelled):
        self.items, self.relabelled = items, relabelled

    def __len__(self) -> int:
        return len(self.items)

    def __getitem__(self, k):
        if isinstance(k, slice):
            relabelled = self.relabelled
            return tuple([relabelled(x) if type(x) is int else x for x in self.items[k]])
        x = self.items[k]
        return self.relabelled(x) if type(x) is int else x

    def __iter__(self):
        relabelled = self.relabelled
        return (relabelled(x) if type(x) is int else x for x in self.items)

    def __eq__(self, other):
        if isinstance(other, (tuple, SingleVerdicts)):
            return len(self) == len(other) and all(a == b for a, b in zip(self, other))
        return NotImplemented

    __hash__ = None

    def __repr__(self) -> str:
        return repr(tuple(self))

    def __reduce__(self):
        return (tuple, (tuple(self),))
