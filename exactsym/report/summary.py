"""The text report of ``exactsym check``, for people: a short summary, the per-level
detail with ``--verbose``, one line per file when several files are checked.

Everything is read from one :class:`~exactsym.analysis.Analysis` (the near-symmetry hint,
never a verdict, is made on demand by :meth:`~exactsym.analysis.Analysis.near_symmetry`) and
from its JSON form (:func:`exactsym.report.json_form.report_json`), so that fields other layers add
later are shown too: a value is never printed as a Python dict or repr but in words
(:func:`plain`).  Numbers go through :mod:`exactsym.exact.text_numbers`: exact text, a decimal
beside every irrational number, long numbers and lists cut.  The paper's words are
explained once, in the "words" lines at the end (``docs/glossary.md`` has them all).
"""

from __future__ import annotations

import re

from flint import fmpq

from ..analysis import Analysis
from ..exact.number import is_plain_rational
from ..exact.text_numbers import annotated, approx, is_irrational, listed, number, square_root
from . import json_form      # called through the module: a test adds fields to the JSON form

__all__ = ["summary_text", "one_line", "plain", "prose", "GLOSSARY_PAGE", "WORDS"]

GLOSSARY_PAGE = "docs/glossary.md"
#: Per-level detail, trace entries and discrepancies shown with --verbose before "... more".
MAX_LEVELS, MAX_TRACE, MAX_DISCREPANCIES = 30, 40, 60
#: Width of a summary line's label column, and the longest audit line of the summary.
LABEL, AUDIT_LINE = 11, 220

#: Short words for the paper's vocabulary: a term found in the report is explained once,
#: in the "words" lines at its end (``docs/glossary.md`` has them all).  term -> (how
#: to find it, what it means)
WORDS = (
    ("P", re.compile(r"\bP is\b|\bG_P\b|\bG is\b"),
     "this configuration; G (or G_P): its levels, as the paper's family of polygons"),
    ("O_A / O_S", re.compile(r"\bO_[AS]\b"),
     "the paper's asymmetric / symmetric configurations (by lines of symmetry only)"),
    ("straight", re.compile(r"\bstraight\b"), "a mirror line through C"),
    ("skew", re.compile(r"\bskew"), 'the paper\'s "skew line": a half-turn about C'),
    ("<G_i, G_j>", re.compile(r"<G"), "a pair of levels; symmetric when they have a common "
                                       "line of symmetry, asymmetric otherwise"),
    ("G_ij", re.compile(r"\bG_ij\b|\bG\(\d"),
     "G_i projected radially onto G_j's circle, merged with G_j"),
    ("G'", re.compile(r"\bG'|\bG_prime\b"), "the family after Preprocess's merges"),
    ("type", re.compile(r"\btype[- ][0-4]\b"), "the paper's polygon types 0-4 (type-0 "
                                                 "regular, ..., type-4 from merging)"),
    ("degree", re.compile(r"\bdegree\b"), "the paper's degree of symmetry: its number of "
                                             "lines, as Check_Symmetry_Odd/Even report it"),
    ("CW / ACW", re.compile(r"\bA?CW\b"), "a vertex's distances to the others, clockwise / "
                                           "anticlockwise"),
    ("turn", re.compile(r"\bturns?\b"), "an angle as a fraction of a full turn (1/4 turn = "
                                         "90 degrees), counter-clockwise from the +x ray"),
)


def _words_used(lines: list[str]) -> list[str]:
    text = "\n".join(lines)
    used = [f"  {term}: {meaning}" for term, pattern, meaning in WORDS if pattern.search(text)]
    return ["", "words:"] + used if used else []


def plain(value) -> str:
    """Any JSON value in words: yes/no, none, lists cut, mappings as ``key value``
    pairs, numbers in prose with their decimals; never a Python repr.

    >>> plain({"straight": True, "skew": False, "mirrors": 3, "leader": None})
    'straight yes; skew no; mirrors 3; leader none'
    >>> plain({"witness": {"line": "1/8", "slope": "sqrt(2)"}, "robots": [3, 4]})
    'witness (line 1/8; slope sqrt(2) ≈ 1.41421); robots 3, 4'
    """
    if value is None:
        return "none"
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, (int, float)):
        return str(value)
    if isinstance(value, str):
        return prose(value)
    if isinstance(value, dict):
        return "; ".join(f"{_key(key)} " + (f"({plain(v)})" if isinstance(v, dict)
                                                         and len(v) > 1 else plain(v))
                         for key, v in value.items())
    if isinstance(value, (list, tuple)):
        if all(isinstance(v, int) and not isinstance(v, bool) for v in value):
            return listed(value) if value else "none"
        shown = [plain(v) for v in value[:8]]
        more = f", ... ({len(value)} in all)" if len(value) > 8 else ""
        return ", ".join(shown) + more if shown else "none"
    return prose(value)


def _key(key) -> str:
    """A JSON key in words: ``in_O_S`` stays (the paper's name), ``first_actor`` is
    ``first actor``."""
    key = str(key)
    return key.replace("_", " ") if re.fullmatch(r"[a-z0-9_]+", key) else key


def _row(label: str, text: str) -> str:
    return f"{label:<{LABEL}}{text}"


def _short_number(x) -> str:
    """:func:`number`, with a decimal also beside a rational whose text is long."""
    text = number(x)
    if not is_irrational(x) and "/" in text and len(text) > 12 and "≈" not in text:
        text += f" ≈ {approx(x)}"
    return text


#: a rational whose numerator or denominator has more bits than this (about 3,000 digits)
#: has its square root shown by its decimal only: its exact text is long anyway, and
#: taking square factors out would write integers beyond Python's int-to-text limit
HUGE_BITS = 10_000


def _radius(r2) -> str:
    """A radius from its exact square (:func:`square_root`); a huge or tiny rational one by
    its decimal, from the exact value, and the length of the exact text."""
    if is_plain_rational(r2) and max(int(r2.p).bit_length(), int(r2.q).bit_length()) > HUGE_BITS:
        return (f"≈ {approx(r2, sqrt=True)} (exact: sqrt of {len(str(r2)):,} characters, "
                "in --json)")
    return square_root(r2)


def _point(p) -> str:
    return f"({_short_number(p[0])}, {_short_number(p[1])})"


# ---------------------------------------------------------------- the summary
def summary_text(analysis: Analysis, verbose: bool = False, hint: bool = True) -> str:
    """The report ``exactsym check`` prints (``--verbose``: with the per-level detail,
    the paper's trace and every discrepancy; ``hint``: look for a near symmetry)."""
    report = json_form.report_json(analysis, brief=not (verbose or analysis.options.strings))
    lines = _head(analysis, report)
    if analysis.truth is not None:
        lines += _truth_rows(analysis)
    if "paper" in report:
        lines.append(_row("paper", _paper_verdict(report["paper"])))
    if "audit" in report:
        lines += _audit_rows(report["audit"], verbose, analysis.config.source)
    if analysis.options.strings and not verbose:
        lines += ["", "strings (CW and ACW of each robot, per level):"] + _all_strings(report)
    if verbose:
        lines += _detail(analysis, report)
    if hint:
        near = _near_symmetry(analysis)
        if near:
            lines += ["", "near symmetry (a hint, not a verdict):", "  " + near]
    lines += _words_used(lines)
    lines += ["", f"(more words: {GLOSSARY_PAGE}"
                  + ("" if verbose else "; the detail of each level: --verbose") + ")"]
    return "\n".join(lines)


def _head(analysis: Analysis, report: dict) -> list[str]:
    config, levels = analysis.config, analysis.levels
    known = config.source != "<memory>"
    title = (config.name or "") + (f"  ({config.source})" if config.name and known else
                                   config.source if known else "")
    title = title or "configuration"
    kind = ("fat robot" if config.model == "fat" else "point robot") + \
        ("s" if config.n != 1 else "") + (" (unit discs)" if config.model == "fat" else "")
    field = report["number_field"]
    field_text = "rational" if field == "Q" else f"exact, in the number field {field}"
    if config.polar is not None:
        field_text = f"polar (radius, turn), {field_text}"
    counts = [len(level.points) for level in levels.levels]
    t = len(counts)
    if t <= 12:
        per_level = ", ".join(f"G{k} {c}" for k, c in enumerate(counts, 1))
    else:
        per_level = (f"{sum(1 for c in counts if c == 1):,} with one robot, the largest "
                     f"with {max(counts):,}")
    return [
        title,
        _row("robots", f"{config.n:,} {kind}; coordinates {field_text}"),
        _row("SEC", f"smallest enclosing circle: centre C = {_point(levels.sec.centre)}, "
                    f"radius {_radius(levels.sec.radius_squared)}"),
        _row("levels", f"{t:,} (robots at one distance from C, nearest first), robots on "
                       f"each: {per_level}"),
    ]


def _truth_rows(analysis: Analysis) -> list[str]:
    group = analysis.truth
    rows = [_row("symmetry", _group_words(group))]
    if group.orderable:
        rows.append(_row("orderable", f"yes: ordering {listed(group.ordering)}"))
        rows.append(_row("leader", f"robot {group.leader} (the first of the ordering)"))
    else:
        rows.append(_row("orderable", "no: a symmetry moves some robot, so observers "
                                      "cannot all number the robots the same way"))
        rows.append(_row("leader", f"robot {group.leader} (fixed by every symmetry)"
                         if group.leader is not None
                         else "none (no robot is fixed by every symmetry)"))
    return rows


def _group_words(group) -> str:
    name, k, m = group.name, group.rotations, group.mirrors
    if name == "O2":
        return "O2: a single robot (every rotation about it, every mirror through it)"
    if k == 1 and m == 0:
        return "C1: none but the identity (asymmetric)"
    rotations = "no rotation but the identity" if k == 1 else \
        f"{k} rotations about C (by multiples of 1/{k} turn)"
    if m == 0:
        return f"{name}: {rotations}, no mirror"
    mirrors = "1 mirror line" if m == 1 else f"{m} mirror lines"
    where = _mirror_place(group)
    return f"{name}: {rotations}, {mirrors} through C{where}"


def _mirror_place(group) -> str:
    """Where one mirror is, in the user's terms: a robot on it, else a pair it swaps."""
    mirror = group.mirror
    if mirror is None:
        return ""
    perm = mirror.permutation
    layout = getattr(group, "_layout", None)
    at_centre = getattr(layout, "centre_index", None)
    on = [i for i, j in enumerate(perm) if i == j and i != at_centre]
    if on:
        return f" (one through robot{'s' if len(on) > 1 else ''} {listed(on, 4)})"
    swapped = next((i for i, j in enumerate(perm) if i != j), None)
    if swapped is None:
        return ""
    return f" (one between robots {swapped} and {perm[swapped]}, which it swaps)"


def _paper_verdict(paper: dict) -> str:
    parts = ["orderable" if paper.get("orderable") else "not orderable"]
    if paper.get("leader") is not None:
        parts.append(f"leader robot {paper['leader']}")
    elif paper.get("orderable"):
        parts.append("no leader computed")
    if "gathering_possible" in paper:
        parts.append("gathering " + ("possible" if paper["gathering_possible"]
                                     else "not possible"))
    moves = paper.get("moves") or []
    if moves:
        first = moves[0]
        where = first.get("algorithm", "")
        if first.get("line") is not None:
            where += f" line {first['line']}"
        parts.append(f"first move: robot {first.get('robot')}" + (f" ({where})" if where else "")
                     + (f", {len(moves)} moves in all" if len(moves) > 1 else ""))
    if paper.get("complete") is False:
        parts.append("incomplete: a step could not be carried out exactly")
    return "; ".join(parts)


def _by_statement(discrepancies: list) -> list[tuple[str, list]]:
    groups: dict[str, list] = {}
    for d in discrepancies:
        groups.setdefault(str(d.get("statement", "?")), []).append(d)
    return list(groups.items())


def _instances(items: list) -> int:
    """How many instances a statement's entries stand for: one per listed failure, and
    the unlisted rest of an entry that counts them (``{"failures": k, "listed": m}``:
    a statement failing more often than its failures are listed)."""
    total = 0
    for d in items:
        w = d.get("witness")
        if isinstance(w, dict) and isinstance(w.get("failures"), int) and \
                isinstance(w.get("listed"), int):
            total += max(w["failures"] - w["listed"], 0)
        else:
            total += 1
    return total


_PYTHON_WORDS = re.compile(r"\b(None|True|False)\b")


def prose(text) -> str:
    """A sentence written by another layer, for the screen: numbers with their decimals
    (:func:`annotated`), Python's None/True/False as none/yes/no."""
    return _PYTHON_WORDS.sub(lambda m: {"None": "none", "True": "yes", "False": "no"}[m[1]],
                             annotated(str(text)))


def _discrepancy_text(d: dict) -> str:
    truth = str(d.get("truth", ""))
    if truth.startswith("false here: "):
        truth = truth[len("false here: "):]
    return f"says {prose(d.get('says', ''))}; here: {prose(truth)}"


def _audit_rows(audit: dict, verbose: bool, source: str) -> list[str]:
    disc = audit.get("discrepancies") or []
    if not disc:
        covered = audit.get("covered")       # how many statements were checked, when told
        count = len(covered) if isinstance(covered, (list, tuple, dict)) else covered \
            if isinstance(covered, int) and not isinstance(covered, bool) else None
        checked = f"none of the {count} statements of the paper checked here" \
            if count else "no statement of the paper checked here"
        return [_row("audit", f"agrees: {checked} is false")]
    groups = _by_statement(disc)
    width = max(len(label) for label, _ in groups)
    total = sum(_instances(items) for _, items in groups)
    rows = [_row("audit", f"{len(groups)} statement{'s' if len(groups) != 1 else ''} of the "
                          f"paper false here ({total:,} instance"
                          f"{'s' if total != 1 else ''}; the witnesses: exactsym audit {source if not source.startswith('<') else 'FILE'}):")]
    for label, items in groups:
        many = _instances(items)
        count = f"({many:,}x)" if many > 1 else ""
        line = f"  {label:<{width}} {count:>5}  {_discrepancy_text(items[0])}"
        if not verbose and len(line) > AUDIT_LINE:
            line = _cut(line, AUDIT_LINE)
        rows.append(line)
    return rows


# ---------------------------------------------------------------- --verbose
def _detail(analysis: Analysis, report: dict) -> list[str]:
    lines = ["", "levels, nearest first (robots counter-clockwise from the +x ray):"]
    shown = report["levels"][:MAX_LEVELS]
    for k, (entry, level) in enumerate(zip(shown, analysis.levels.levels), 1):
        lines.append(f"  G{k}  radius {_radius(level.radius_squared)}; "
                     f"{len(level.points):,} robot{'s' if len(level.points) != 1 else ''}: "
                     f"{listed(entry['points'])}")
        if entry.get("paper") is not None:
            lines += ["      " + text for text in _level_paper(entry["paper"])]
        elif "paper" in entry:
            lines.append("      paper: a robot at C (no polygon)")
        if entry.get("strings"):
            lines += ["      " + text for text in _strings(entry["strings"])]
    if len(report["levels"]) > MAX_LEVELS:
        lines.append(f"  ... ({len(report['levels']):,} levels in all; --json lists every one)")
    if analysis.truth is not None:
        lines += ["", "ground truth, symmetries:"] + _symmetry_lines(analysis.truth)
    paper = report.get("paper")
    if paper is not None:
        lines += ["", "the paper's procedure, step by step:"] + _trace(paper)
        rest = {key: value for key, value in paper.items()
                if key not in ("trace", "orderable", "leader", "gathering_possible", "moves",
                               "first_actor", "complete", "G", "G_prime")}
        lines += [f"  {_key(key)}: {plain(value)}" for key, value in rest.items()]
    audit = report.get("audit")
    if audit and audit.get("discrepancies"):
        lines += ["", "audit, every instance:"]
        for d in audit["discrepancies"][:MAX_DISCREPANCIES]:
            lines.append(f"  {d.get('statement', '?')}: {_discrepancy_text(d)}")
            extra = {key: value for key, value in d.items()
                     if key not in ("statement", "says", "truth")}
            if extra:
                lines.append(f"      {plain(extra)}")
        if len(audit["discrepancies"]) > MAX_DISCREPANCIES:
            lines.append(f"  ... ({len(audit['discrepancies'])} in all)")
        rest = {key: value for key, value in audit.items() if key != "discrepancies"}
        lines.append(f"  {plain(rest)}")
    return lines


def _level_paper(verdict: dict) -> list[str]:
    """A level's polygon-layer verdicts (``levels[k].paper``) in words; keys added later
    are listed after the known ones."""
    v = dict(verdict)
    out = []
    check = v.pop("check", None)
    symmetric = v.pop("symmetric", None)
    straight, skew = v.pop("straight", None), v.pop("skew", None)
    first = f"paper: {check or 'the symmetry test'} says " + \
        ("symmetric" if symmetric else "not symmetric" if symmetric is not None else "?")
    first += f"; straight {plain(straight)}; skew {plain(skew)}"
    if "degree" in v:
        first += f"; degree {plain(v.pop('degree'))}"
    out.append(first)
    second = []
    if "loop_terminates" in v:
        loop = v.pop("loop_terminates")
        if loop is not None:
            second.append("its loop as printed " + ("terminates" if loop else
                                                    "does not terminate"))
    if "theorem1_symmetric" in v:
        second.append(f"Theorem 1: {'symmetric' if v.pop('theorem1_symmetric') else 'not symmetric'}")
    if "lines" in v:
        second.append(f"lines of straight symmetry {plain(v.pop('lines'))}")
    if "type" in v:
        reason = v.pop("type_reason", None)
        second.append(f"{plain(v.pop('type'))}"
                      + (f" ({plain(reason)})" if reason else ""))
    if second:
        out.append("       " + "; ".join(second))
    definition = v.pop("definition", None)
    if isinstance(definition, dict):
        out.append("       the definitions, evaluated exactly: " + plain(definition))
    leaders = {key: v.pop(key) for key in list(v) if key.startswith("leader")}
    if leaders:
        out.append("       " + "; ".join(f"{_leader_name(key)} {plain(value)}"
                                         for key, value in leaders.items()))
    if v:       # fields other layers add later
        out.append("       " + plain(v))
    return out


def _leader_name(key: str) -> str:
    return {"leader_sym": "Elect_Leader_Sym:", "leader_sym_by_lines":
            "Elect_Leader_Sym (degree = number of lines):", "leader_asym":
            "Elect_Leader_Asym:"}.get(key, key.replace("_", " ") + ":")


def _strings(entry: dict, vertices_shown: int = 12) -> list[str]:
    vertices = entry.get("vertices") or []
    cw, acw = entry.get("cw") or [], entry.get("acw") or []
    metric = str(entry.get("metric", "")).replace("-", " ")
    out = [f"strings ({plain(metric)}):"]
    for i, vertex in enumerate(vertices[:vertices_shown]):
        a = plain(cw[i]) if i < len(cw) else "?"
        b = plain(acw[i]) if i < len(acw) else "?"
        out.append(f"  robot {vertex}: CW {a}  ACW {b}")
    if len(vertices) > vertices_shown:
        out.append(f"  ... ({len(vertices):,} vertices in all)")
    return out


def _all_strings(report: dict) -> list[str]:
    lines = []
    for k, entry in enumerate(report["levels"][:MAX_LEVELS], 1):
        if entry.get("strings"):
            lines += [f"  G{k}, " + t[len("strings ("):-2] + ":" if j == 0 else "  " + t
                      for j, t in enumerate(_strings(entry["strings"]))]
    if len(report["levels"]) > MAX_LEVELS:
        lines.append(f"  ... ({len(report['levels']):,} levels in all)")
    return lines


def _symmetry_lines(group) -> list[str]:
    """Every symmetry (the first 12): what it is, in the user's terms, and the robots it
    moves.  :meth:`SymmetryGroup.symmetries` yields the identity, the rotations by j/k
    turn (j = 1..k-1), then the mirrors."""
    if group.name == "O2":
        return ["  a single robot: every rotation about it, every mirror through it"]
    lines = []
    centre = getattr(getattr(group, "_layout", None), "centre_index", None)
    total = group.rotations + group.mirrors
    for index, g in enumerate(group.symmetries()):
        if index == 12 and total > 12:
            lines.append(f"  ... ({total:,} symmetries in all)")
            break
        moved = [(i, j) for i, j in enumerate(g.permutation) if i != j]
        fixed = [i for i, j in enumerate(g.permutation) if i == j]
        if index == 0:
            what = "identity"
        elif index < group.rotations:
            what = f"rotation by {number(fmpq(index, group.rotations))} turn about C"
        else:
            on = [i for i in fixed if i != centre]
            what = "mirror in the line through C" + (
                f" at {number(g.turn)} turn" if g.turn is not None else "") + (
                f" and robot {on[0]}" if on else
                f", between robots {moved[0][0]} and {moved[0][1]}" if moved else "")
        shown = ", ".join(f"{i}->{j}" for i, j in moved[:6]) + \
            (f", ... ({len(moved):,} robots moved)" if len(moved) > 6 else "")
        lines.append(f"  {what}: " + (f"moves {shown}; " if moved else "")
                     + (f"fixes {listed(fixed)}" if fixed else "fixes no robot"))
    return lines


def _trace(paper: dict) -> list[str]:
    trace = paper.get("trace") or []
    lines = []
    for entry in trace[:MAX_TRACE]:
        where = str(entry.get("algorithm", ""))
        if entry.get("line") is not None:
            where += f" line {entry['line']}"
        label = entry.get("statement")
        detail = entry.get("detail", "")
        extra = {key: value for key, value in entry.items()
                 if key not in ("algorithm", "line", "statement", "detail", "polygons",
                                "branch", "round")}
        lines.append(f"  {where}" + (f" [{label}]" if label and label != entry.get("algorithm")
                                    else "") + f": {plain(detail)}"
                     + (f" ({plain(extra)})" if extra else ""))
    if len(trace) > MAX_TRACE:
        lines.append(f"  ... ({len(trace)} steps in all; --json has every one)")
    return lines


# ---------------------------------------------------------------- hint, one line
def _near_symmetry(analysis: Analysis) -> str | None:
    """The near-symmetry hint (:meth:`~exactsym.analysis.Analysis.near_symmetry`), or None.
    The hint proposes its candidate in floats: coordinates beyond their comfortable range
    (their squares would overflow or vanish) get no hint, the verdict being exact anyway."""
    if not _float_friendly(analysis.config.points):
        return None
    found = analysis.near_symmetry()
    return None if found is None else found.text


#: coordinates whose magnitude lies outside [2^-FLOAT_BITS, 2^FLOAT_BITS] (or 0) get no
#: near-symmetry hint: squares and sums of squares of such floats stay finite and normal
FLOAT_BITS = 480


def _float_friendly(points) -> bool:
    """Whether every rational coordinate is 0 or within 2^+-:data:`FLOAT_BITS` (decided on
    the exact numerator and denominator; other numbers are left to the hint, which takes
    rationals only)."""
    for p in points:
        for x in p:
            if is_plain_rational(x) and x != 0:
                bits = int(abs(x.p)).bit_length() - int(x.q).bit_length()
                if abs(bits) > FLOAT_BITS:
                    return False
    return True


def _cut(line: str, width: int) -> str:
    """``line`` cut to ``width`` characters with an ellipsis, never between an irrational
    number and its decimal: a number whose ``≈`` falls past the cut is dropped whole."""
    kept = line[:width - 1]
    last = max(kept.rfind("≈"), 0)
    pending = re.search(r"\b(sqrt|cos|sin)\(", kept[last:])
    if pending is not None and "≈" in line[width - 1:]:
        start = last + pending.start()
        # back to the start of the expression the function belongs to (after ", " or "(")
        cut = max(kept.rfind(", ", last, start), kept.rfind("(", last, start))
        if cut < 0:
            cut = kept.rfind(" ", last, start)
        kept = kept[:cut + 1] if cut >= 0 else kept[:start]
    return kept.rstrip() + "…"


def one_line(analysis: Analysis, failures: int = 0) -> str:
    """One line for ``exactsym check FILE FILE...``: file, n, group, orderable; the
    paper's verdict; the audit's count of false statements."""
    config, truth = analysis.config, analysis.truth
    parts = [f"{config.n:,} robots"]
    if truth is not None:
        parts.append(truth.name)
        parts.append("orderable" if truth.orderable else "not orderable")
        parts.append(f"leader {truth.leader}" if truth.leader is not None else "no leader")
    report = json_form.report_json(analysis, brief=True)
    text = ", ".join(parts)
    if "paper" in report:
        text += "; paper: " + ("orderable" if report["paper"].get("orderable")
                               else "not orderable")
        if report["paper"].get("leader") is not None:
            text += f", leader {report['paper']['leader']}"
    if "audit" in report:
        disc = report["audit"].get("discrepancies") or []
        labels = len({d.get("statement") for d in disc})
        text += "; audit: " + ("agrees" if not disc else
                               f"{labels} statement{'s' if labels != 1 else ''} false")
    if failures:
        text += f"; {failures} [expect] claim{'s' if failures != 1 else ''} false"
    return f"{config.source}: {text}"
