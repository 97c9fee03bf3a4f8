"""The one place where the sweep touches the rest of exactsym.

Everything the sweep needs from the analysis layers is imported here, and only here
(besides :mod:`exactsym.exact`), so that when modules move (the analysis pipeline, the configuration reader, the family
layer, the gathering simulator) one file changes.

What it offers, all on plain data (points as in :class:`.families.SweepItem`):

* :func:`analyse` -- one configuration, ``what`` in ``truth | paper | audit | gather``:
  ``{"failed": [labels], "applicable": [labels] | None, ...}``;
* :func:`discrepancy_text` -- what the analysis says about one label (a case file's notes);
* :func:`expect_block` -- the ``[expect]`` block a counterexample's case file carries;
* :func:`check_case_file` -- load a case file and compare its ``[expect]`` block with
  ``exactsym check`` (the messages of ``exactsym cases``);
* :func:`file_points` -- a configuration file's points as text (``perturb:``);
* :func:`statement_labels` -- the labels an analysis can report;

"Applicable" (the statement's hypotheses held on the configuration) is derived as follows
(``docs/sweeps.md``): for the audit's own statements from the same data the audit uses
(``lemma-sym-ord``: n > 1 and P in O_S; ``Psym-Gsym``: every configuration; ``Pasym-Pord``
and ``cor-Pasym-Pord``: n > 1 (see :data:`_MIN_N`); the conclusion ``GatheringPattern``
and ``MakeAsym``: n >= 5;
``lem-asym-ord``: an asymmetric level, or a true orderable configuration whose leader is
checked for observer independence; ``lem-sym-notord`` / ``lem-asym-pair-ord``: a
symmetric / asymmetric pair among the pairs the audit checks; ``lem-all-pair-asym-ord`` /
``lem-one-pair-asym-ord``: Find_Asymmetry_Pair / FindAsymmetry finds one); for every
other label, the paper's trace shows it on this configuration (a claim checked on at
least one instance -- an entry with ``holds`` -- or an algorithm that ran).  A label
that fails within its hypotheses is applicable; a failure outside them (a single robot
for ``Pasym-Pord``) is moved from ``failed`` to ``outside`` and counts as neither; a label
the audit finds false only under a named reading is in ``reading``, and one whose claim
holds while the audit blames it for the paper's procedure in ``procedure`` (:func:`_split`):
neither is a failure.  Truth
has no statements (``applicable`` is None).
"""

from __future__ import annotations

from fractions import Fraction

from .casefile import case_text

__all__ = ["analyse", "warm_up", "discrepancy_text", "expect_block", "check_case_file", "file_points",
           "statement_labels", "is_label", "scaled_points", "adversary_settings", "WHATS",
           "BridgeInputError"]

WHATS = ("truth", "paper", "audit", "gather", "gather-corrected")

#: The conclusions the audit reports besides the statements (``exactsym.audit.statements``).
_AUDIT_CONCLUSIONS = ("GatheringPattern", "ElectLeader", "MakeAsym")
#: The statements the audit checks itself against the truth (their hypotheses are
#: derived by :func:`_audit_hypotheses`, never from the paper's trace).
_AUDIT_OWN = ("lemma-sym-ord", "lem-asym-ord", "lem-sym-notord", "lem-asym-pair-ord",
              "lem-all-pair-asym-ord", "lem-one-pair-asym-ord", "Psym-Gsym", "Pasym-Pord",
              "cor-Pasym-Pord")
_ALWAYS = ("Psym-Gsym", "Pasym-Pord", "cor-Pasym-Pord", "GatheringPattern")
#: The least number of robots within each statement's hypotheses, where the audit's own
#: test does not say it.  ``Pasym-Pord`` / ``cor-Pasym-Pord``: a single robot is in O_S by
#: def-symmetric-conf and trivially orderable, so the "only if" direction fails on it
#: literally; but that direction's proof is lemma-sym-ord ("lemma 1"), stated for a
#: non-singleton set, so the theorem is read with lemma 1's hypothesis n > 1 (the C3
#: configurations refute both statements with n >= 3 anyway).  ``GatheringPattern``: the
#: gathering algorithm is for n >= 5 robots (the audit lists no discrepancy below that),
#: and so is ``MakeAsym``, one of its steps (its ledger entry's hypothesis ``n >= 5``;
#: the audit still lists it below 5, e.g. on an isosceles triangle: outside, not counted).
#: Lemmas whose claim is "... is orderable" and to which the audit also attributes the
#: paper's leader depending on the observer (a discrepancy of kind ``conclusion``): on a
#: configuration that is orderable the claim holds, and the fault is the procedure's
#: (Elect_Leader_Asym on a triangle elects nobody, differently in mirrored frames).
_ORDERABLE_CLAIMS = ("lem-asym-ord",)
_MIN_N = {"Pasym-Pord": 2, "cor-Pasym-Pord": 2, "GatheringPattern": 5, "MakeAsym": 5}


class BridgeInputError(ValueError):
    """A file the user named cannot be used (exit 2); the message names it."""


# ---------------------------------------------------------------- configurations
def configuration(points, source: str = "<sweep>"):
    """The :class:`exactsym.geometry.configuration.Configuration` of ``points``, read from the
    same text a case file holds (so a worker analyses exactly what is written)."""
    from ..geometry.configuration import from_file
    from ..io.fileformat import parse_config_text
    return from_file(parse_config_text(case_text(points), source, "toml"))


def file_points(path: str) -> tuple:
    """The points of a configuration file as text: polar points as written (radius text,
    rational turn), Cartesian points when every coordinate is rational."""
    from ..geometry.configuration import load
    from ..errors import InputError
    from ..exact import RationalSystem
    try:
        config = load(path)
    except InputError as err:
        raise BridgeInputError(str(err)) from None
    if config.polar is not None and config.specs:
        return tuple(("polar", s.texts[0] if s.texts else "1", str(Fraction(s.turn)))
                     for s in config.specs)
    if not isinstance(config.system, RationalSystem):
        raise BridgeInputError(f"{path}: perturb needs rational Cartesian or polar points")
    return tuple(("xy", _q(x), _q(y)) for x, y in config.points)


def _q(x) -> str:
    return str(x.p) if x.q == 1 else f"{x.p}/{x.q}"


# ---------------------------------------------------------------- the analyses
def warm_up(what: str) -> None:
    """Import what ``analyse(what, ...)`` needs (a worker does it once, before the clock
    of its first batch: the imports take about a second)."""
    from ..audit import statements  # noqa: F401
    from ..truth import symmetry  # noqa: F401
    from ..paper import family  # noqa: F401
    if what in ("gather", "gather-corrected"):
        from ..gathering import cases  # noqa: F401


def statement_labels(what: str) -> tuple:
    """Every label ``analyse(what, ...)`` checks, in the paper's order (``paper``: not the
    statements about orderability, which need the truth)."""
    if what in ("audit", "paper"):
        from ..audit.statements import CLAIMS, STATEMENT_ORDER
        labels = list(STATEMENT_ORDER) + [c for c in CLAIMS if c not in STATEMENT_ORDER]
        if what == "audit":
            labels += [c for c in _AUDIT_CONCLUSIONS if c not in labels]
        else:                         # the paper alone cannot check the truth's statements
            labels = [c for c in labels if c not in _AUDIT_OWN]
        return tuple(labels)
    return ()


def analyse(what: str, points, budget=0) -> dict:
    """Run one analysis on the configuration ``points`` (see the module docstring);
    ``budget``: the gathering run's events, or ``(events, states)`` with the searching
    adversary's states."""
    from ..geometry.configuration import no_cycle_collection
    config = configuration(points)
    with no_cycle_collection():
        if what == "truth":
            return _truth(config)
        if what == "paper":
            return _paper(config)
        if what == "audit":
            return _audit(config)
        if what == "gather":
            return _gather(config, budget, "paper", points)
        if what == "gather-corrected":
            return _gather(config, budget, "corrected", points)
    raise ValueError(f"unknown analysis {what!r}")


def _truth(config) -> dict:
    from ..analysis import analyse as run_analysis
    group = run_analysis(config, sections=("truth",)).truth
    return {"failed": [], "applicable": None,
            "truth": {"group": group.name, "orderable": group.orderable}}


def _paper_summary(res) -> dict:
    return {"orderable": res.orderable, "leader": res.leader, "complete": res.complete}


def _outside_instance(e) -> bool:
    """A trace entry the family layer marks outside the statement's hypotheses (the audit
    makes it a note, ``exactsym.audit.statements.HYPOTHESIS_MARKED``)."""
    witness = e.get("witness")
    return isinstance(witness, dict) and witness.get("within_hypotheses") is False


def _paper_findings(res) -> tuple[set, set]:
    """(labels false on the configuration, labels the trace names) from the paper alone."""
    failed = {e["statement"] for e in res.trace
              if e.get("holds") is False and e.get("kind") != "literal-reading"
              and not _outside_instance(e)}
    named = {e["algorithm"] for e in res.trace} | \
        {e["statement"] for e in res.trace if "holds" in e}
    return failed, named - set(_AUDIT_OWN) - {"Section 3"}


def _paper(config) -> dict:
    from ..analysis import analyse as run_analysis
    res = run_analysis(config, sections=("family",)).paper
    failed, named = _paper_findings(res)
    outside = {e["statement"] for e in res.trace
               if e.get("holds") is False and _outside_instance(e)} - failed
    below = {label for label, least in _MIN_N.items() if config.n < least}
    outside |= failed & below
    return {"failed": sorted(failed - below), "applicable": sorted((named | failed) - below),
            "outside": sorted(outside), "paper": _paper_summary(res)}


def _audit(config) -> dict:
    from ..analysis import analyse as run_analysis
    analysis = run_analysis(config, sections=("audit",))
    res, result = analysis.paper, analysis.audit
    truth = result.truth
    failed, reading, procedure = _split(result.discrepancies, truth.orderable)
    _, named = _paper_findings(res)
    with analysis.reading():        # the paper's polygons again: the analysis's caches
        hypotheses = _audit_hypotheses(config.n, res, result)
    applicable = named | failed | reading | procedure | set(_ALWAYS) | hypotheses
    below = {label for label, least in _MIN_N.items() if config.n < least}
    outside = (failed | reading | procedure) & below
    failed, reading, procedure, applicable = (x - below for x in (failed, reading,
                                                                  procedure, applicable))
    return {"failed": sorted(failed), "applicable": sorted(applicable),
            "outside": sorted(outside), "reading": sorted(reading),
            "procedure": sorted(procedure),
            "truth": {"group": truth.group, "orderable": truth.orderable},
            "paper": _paper_summary(res)}


def _split(discrepancies, orderable: bool) -> tuple[set, set, set]:
    """(failed, reading, procedure): the labels the audit lists, by what the entries say.
    A label fails when some entry is false outright; it is ``reading`` when every entry is
    of kind ``reading`` (false under the reading in effect, rescued by another); it is
    ``procedure`` when the only entries are conclusions about the paper's leader on a
    configuration its claim says is orderable and that is orderable
    (:data:`_ORDERABLE_CLAIMS`): the fault is the procedure's, the claim holds."""
    kinds: dict = {}
    for d in discrepancies:
        kinds.setdefault(d["statement"], set()).add(d.get("kind"))
    failed, reading, procedure = set(), set(), set()
    for label, ks in kinds.items():
        genuine = ks - {"reading"}
        if label in _ORDERABLE_CLAIMS and orderable:
            genuine -= {"conclusion"}
        if genuine:
            failed.add(label)
        elif "reading" in ks:
            reading.add(label)
        else:
            procedure.add(label)
    return failed, reading, procedure


def _audit_hypotheses(n: int, res, result) -> set:
    """The audit's own statements whose hypotheses hold (module docstring)."""
    from ..paper import family as F
    truth = result.truth
    out = set()
    if n > 1 and truth.in_O_S:
        out.add("lemma-sym-ord")
    G = res.G_rings
    if any(not F.is_symmetric_polygon(g) for g in G) or (truth.orderable and res.complete):
        out.add("lem-asym-ord")
    pairs, _ = F.select_pairs(G, F.DEFAULT_LIMITS)
    for i, j in pairs:
        out.add("lem-sym-notord" if F.is_symmetric_pair(G[i], G[j]) else "lem-asym-pair-ord")
    try:
        if F.find_asymmetry_pair(G, F.DEFAULT_LIMITS.step_budget(n)) is not None:
            out.add("lem-all-pair-asym-ord")
    except F.WorkBudgetExceeded:
        pass
    if F.find_asymmetry(G) is not None:
        out.add("lem-one-pair-asym-ord")
    return out


# ---------------------------------------------------------------- gathering
#: delta of the searching adversary's non-rigid moves (``gather:EVENTS+STATES:``): a move
#: may end at any stop once its straight distance from the start is at least this
ADVERSARY_DELTA = "1/4"
#: the searching adversary's bounds besides its states (``search.Bounds``): actions per
#: schedule; no time bound, so a record is reproducible from its seed alone
ADVERSARY_DEPTH = 16

#: a record's ``gather.class`` for each way a start can end (``docs/sweeps.md``); the
#: failed label of the classes that are failures
GATHER_FAILURES = {"stalled": "gather-stalled", "undecided": "gather-undecided",
                   "not-possible-with-leader": "gather-not-possible-with-leader",
                   "other": "gathering-within-budget"}


def _start(points, config):
    """The start as the simulator reads it: fmpq pairs when every coordinate is rational
    Cartesian, else the numbers of the motion's one system
    (:func:`exactsym.gathering.start_numbers.start_points`, the reader of ``gather``)."""
    from ..exact.number import all_plain_rational
    if config.polar is None and all(all_plain_rational(p) for p in config.points):
        return [tuple(p) for p in config.points]
    from ..errors import InputError
    from ..gathering.start_numbers import start_points
    from ..io.fileformat import parse_config_text
    try:
        parsed = parse_config_text(case_text(points), "<sweep>", "toml")
        return start_points(parsed.points, "<sweep>")
    except InputError as err:
        raise BridgeInputError(f"the gathering simulator cannot read this start: {err}") \
            from None


def _sign(x) -> int:
    """The exact sign of a rational (fmpq) or of a number of the motion (``sign``)."""
    from ..exact.number import sign
    return sign(x)


def _separated(points):
    """``points`` scaled by the least integer s with every distance > 2 (unit discs apart,
    the simulator's start condition); an exact similarity, which changes no decision.
    Exact in every number system of the motion: the sign of ``s^2 d^2 - 4`` for the
    least squared distance ``d^2``."""
    d2s = [(a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2
           for i, a in enumerate(points) for b in points[:i]]
    d2 = d2s[0]
    for x in d2s[1:]:
        if _sign(x - d2) < 0:
            d2 = x
    s = 1
    while _sign(d2 * (s * s) - 4) <= 0:
        s += 1
    return [(x * s, y * s) for x, y in points], s


def scaled_points(points, s: int) -> tuple:
    """The sweep's ``points`` (text, :class:`.families.SweepItem`) scaled by the integer
    ``s``: what the simulator starts from, as a case file writes it."""
    if s == 1:
        return tuple(tuple(p) for p in points)
    out = []
    for kind, a, b in points:
        if kind == "polar":
            r = Fraction(a) * s if _rational_text(a) else None
            out.append(("polar", _q_text(r) if r is not None else f"{s}*({a})", b))
        else:
            out.append(("xy", _q_text(Fraction(a) * s), _q_text(Fraction(b) * s)))
    return tuple(out)


def _rational_text(text: str) -> bool:
    try:
        Fraction(text)
    except (ValueError, ZeroDivisionError):
        return False
    return True


def _q_text(q: Fraction) -> str:
    return str(q.numerator) if q.denominator == 1 else f"{q.numerator}/{q.denominator}"


def _gather(config, budget, algorithm: str = "paper", points=()) -> dict:
    """One run of the paper's algorithm (``algorithm`` "paper"; "corrected": the
    corrected variant, ``--what gather-corrected``) (reference readings, seeded ASYNC
    scheduler, every invariant on) from ``config``, at most ``budget`` events (default
    2000).  Failed labels: the violated statement, or ``gathering-within-budget`` when
    the run neither gathered nor violated anything (for the corrected variant, a
    ``not-possible`` run on a start the ground truth finds symmetric is no failure: it
    is recorded with the group).  ``budget`` a pair ``(events, states)``: the searching
    adversary first (:func:`_adversary`).  Fewer than 5 robots: not applicable."""
    from ..gathering.cases import run_settings, settings_of
    if config.n < 5:
        return {"failed": [], "applicable": None,
                "gather": {"outcome": "not-applicable (n < 5)", "gathered": None}}
    events, states = budget if isinstance(budget, tuple) else (budget, 0)
    start, scale = _separated(_start(points, config))
    if states:
        return _adversary(config, start, events or 2000, states, algorithm, scale)
    res = run_settings(start, settings_of({"gather_max_events": events or 2000,
                                           "gather_algorithm": algorithm}))
    ok = res.outcome == "gathered"
    out = {"outcome": res.outcome, "gathered": ok, "steps": res.events}
    if algorithm == "corrected":
        from ..truth.symmetry import symmetry_group
        group = symmetry_group(config)         # scaling by _separated keeps the group
        out["group"] = group.name
        ok = ok or (res.outcome == "not-possible" and not group.orderable)
    failed = [res.label] if res.label else ([] if ok else ["gathering-within-budget"])
    return {"failed": failed, "applicable": None, "gather": out}


def adversary_settings(events: int, algorithm: str = "corrected") -> dict:
    """The run settings of the searching adversary's sweep (:func:`_adversary`): seeded
    ASYNC (seed 0, frames of both handednesses), non-rigid with :data:`ADVERSARY_DELTA`,
    every invariant, ``events`` events at most."""
    from ..gathering.cases import settings_of
    return settings_of({"gather_max_events": events, "gather_algorithm": algorithm,
                        "gather_non_rigid": ADVERSARY_DELTA})


def _adversary(config, start, events: int, states: int, algorithm: str,
               scale: int = 1) -> dict:
    """The strongest adversary of the instrument on one start (``docs/sweeps.md``,
    "The searching adversary"): first the search (``exactsym.gathering.search``: Looks
    in both handednesses and in generic frames, stops at and between the critical
    instants of every motion, joint steps, non-rigid ends after delta) over ``states``
    states, depth :data:`ADVERSARY_DEPTH`; when it finds no violation, the seeded
    non-rigid ASYNC run to its end.  Classified against the ground truth's leader
    (``SymmetryGroup.leader``): a start that is not gathered must have none."""
    from ..gathering.cases import run_settings
    from ..gathering.search import Bounds, search
    from ..truth.symmetry import symmetry_group
    settings = adversary_settings(events, algorithm)
    try:
        report = search(start, settings, Bounds(budget=states, depth=ADVERSARY_DEPTH,
                                                seed=0, seconds=None))
        searched = {"states": report.states, "depth": report.depth,
                    "stopped": report.stopped}
        result = report.result
    except TypeError as err:
        # the search cannot fork a world whose numbers live in a tower of nested radicals
        # (docs/sweeps.md, "The searching adversary"): recorded, the run still decides
        searched, result = {"states": None, "depth": None, "stopped": "error",
                            "error": f"{type(err).__name__}: {err}"[:200]}, None
    found = "search" if result is not None else "run"
    res = result if result is not None else run_settings(start, settings)
    group = symmetry_group(config)             # scaling by _separated keeps the group
    leader = group.leader is not None
    kind = _gather_class(res.outcome, leader)
    out = {"outcome": res.outcome, "class": kind, "label": res.label, "events": res.events,
           "max_events": events,
           "looks": res.looks, "found_by": found, "leader": leader, "search": searched,
           "scale": scale}
    if res.outcome != "gathered":
        out["detail"] = res.detail[:300]
    failed = [res.label] if kind == "violated" else \
        ([GATHER_FAILURES[kind]] if kind in GATHER_FAILURES else [])
    return {"failed": failed, "applicable": None, "gather": out,
            "truth": {"group": group.name, "orderable": group.orderable}}


def _gather_class(outcome: str, leader: bool) -> str:
    """gathered | no-leader | not-possible-with-leader | violated | stalled | undecided |
    other (max-events, a replay that stopped)."""
    if outcome in ("gathered", "violated", "stalled"):
        return outcome
    if outcome == "not-possible":
        return "not-possible-with-leader" if leader else "no-leader"
    if outcome.startswith("undecided"):
        return "undecided"
    return "other"


# ---------------------------------------------------------------- case files
def discrepancy_text(what: str, points, label: str) -> str:
    """What the analysis says about ``label`` on ``points``, in one paragraph."""
    if what not in ("audit", "paper"):
        return ""
    from ..analysis import analyse as run_analysis
    analysis = run_analysis(configuration(points),
                            sections=("audit",) if what == "audit" else ("family",))
    res = analysis.paper
    if what == "audit":
        found = [d for d in analysis.audit.discrepancies if d["statement"] == label]
        return " ".join(f"says: {d['says']}; truth: {d['truth']}." for d in found[:2])
    if what == "paper":
        found = [e for e in res.trace if e.get("statement") == label and e.get("holds") is False]
        return " ".join(f"{e['algorithm']}: {e['detail']}." for e in found[:2])
    return ""


def expect_block(what: str, record: dict) -> dict:
    """The ``[expect]`` keys a counterexample found by ``what`` can state exactly."""
    out: dict = {"n": record["n"]}
    truth, paper = record.get("truth"), record.get("paper")
    if truth:
        out["orderable"] = truth["orderable"]
        out["group"] = truth["group"]
    if paper:
        out["paper_orderable"] = paper["orderable"]
        out["paper_leader"] = -1 if paper["leader"] is None else paper["leader"]
    if what == "audit":
        out["audit_agrees"] = not record["failed"]
    g = record.get("gather") or {}
    if what == "gather-corrected" and "class" in g:
        # the seeded run of the searching adversary's settings (adversary_settings);
        # a violation the search found needs the search: `gather --search` (notes)
        out.update(gather_algorithm="corrected", gather_non_rigid=ADVERSARY_DELTA,
                   gather_max_events=g["max_events"] if "max_events" in g else 3000)
        if g["found_by"] == "run":
            out["gather_outcome"] = g["outcome"]
            if g.get("label"):
                out["gather_label"] = g["label"]
    return out


def is_label(label: str) -> bool:
    """Is ``label`` a label a case file's ``lemmas`` may name (``exactsym.labels``)?  The
    gathering sweep's own failure names (``gather-stalled``, ...) are not."""
    from ..labels import LABELS
    return label in LABELS


def check_case_file(path) -> list[str]:
    """The ``[expect]`` claims of the case file at ``path`` that ``exactsym check``
    contradicts (empty: the case passes), as ``exactsym cases`` prints them."""
    from ..report.cases import run_case
    return list(run_case(path).failures)
