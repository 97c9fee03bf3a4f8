"""Work budgets of the family layer (``docs/interpretations.md``, "Bounds of the
family layer"): :class:`Limits`, :data:`DEFAULT_LIMITS`, :data:`UNBOUNDED`.
"""

from __future__ import annotations

from dataclasses import dataclass


#: Polygons above this size are not given to the O(n^2) string steps of
#: Elect_Leader_Asym (the leader is then reported as not computed).
MAX_QUADRATIC_N = 600


#: Pair and triple statements are checked on at most this many pairs / triples
#: (the defaults of :class:`Limits`).
MAX_PAIRS = 600


MAX_TRIPLES = 3000


class WorkBudgetExceeded(Exception):
    """A step would exceed its work budget (:class:`Limits`); the caller records it."""


@dataclass(frozen=True)
class Limits:
    """Work budgets of the family layer, so that it runs in near-linear time and memory
    for every input (``docs/interpretations.md``, "Bounds of the family layer").  Every
    budget is ``None`` in :data:`UNBOUNDED` (the faithful procedure, exhaustive checks).

    * ``claim_pairs``: the Section-3 pair statements (``family_claims``, the audit's
      ``lem-sym-notord``/``lem-asym-pair-ord``) are checked on every pair when t(t-1)/2 is
      at most this, else on the pairs among the first and last :data:`END_LEVELS` levels
      and then evenly spaced consecutive pairs (i, i+1), up to this many pairs;
    * ``claim_vertices`` + ``claim_vertices_per_robot`` * n: the pairs checked have at most
      this many vertices in all (a pair costs n_i + n_j);
    * ``union_vertices``: ``theorem-los-g1n`` on the projection of every polygon onto the
      outermost circle (one polygon with a vertex on every ray: O(n log n), about a
      second of exact arithmetic per 50,000 Cartesian rays) is checked when the polygons
      have at most this many vertices in all;
    * ``claim_triples``: triples of G' (``lem-3-pair-sym``, ``lem-type4``): all when
      C(t', 3) is at most this, else those among the first and last polygons of G' (as
      many as keep C(m, 3) at most this);
    * ``claim_levels``: the audit's ``lem-asym-ord`` on at most this many asymmetric
      levels (the first and the last);
    * ``claim_examples``: a statement failing more often records this many failures and
      one entry with the count; ``screen_texts``: their texts are for the screen only
      (the text summary): a line's slope whose exact text would be megabytes is written
      by its decimal (:data:`.concentric.SCREEN_ONLY`), not written out to be cut;
    * ``search_steps`` + ``search_steps_per_robot`` * n: work steps of
      ``Find_Asymmetry_Pair`` and of Preprocess's pair scan and printed loop (index steps;
      a G_ij built costs :data:`BUILD_COST` steps a vertex): exact below the budget,
      beyond it the step is reported as not carried out;
    * ``trace_entries``: entries kept in the trace (findings and selections always kept,
      the rest cut, with a final entry counting what was omitted); ``described``:
      polygons listed in ``G`` / ``G_prime``; ``preprocess_entries``: polygons whose
      Preprocess scan gets its own trace entries."""
    claim_pairs: int | None = MAX_PAIRS
    claim_vertices: int | None = 100_000
    claim_vertices_per_robot: int = 2
    claim_triples: int | None = MAX_TRIPLES
    claim_levels: int | None = 200
    claim_examples: int | None = 8
    screen_texts: bool = False
    union_vertices: int | None = 50_000
    search_steps: int | None = 5_000_000
    search_steps_per_robot: int = 50
    trace_entries: int | None = 200
    described: int | None = 200
    preprocess_entries: int | None = 40

    def vertex_budget(self, n: int) -> int | None:
        return None if self.claim_vertices is None else \
            self.claim_vertices + self.claim_vertices_per_robot * n

    def step_budget(self, n: int) -> int | None:
        return None if self.search_steps is None else \
            self.search_steps + self.search_steps_per_robot * n


DEFAULT_LIMITS = Limits()


UNBOUNDED = Limits(claim_pairs=None, claim_vertices=None, claim_triples=None,
                   claim_levels=None, claim_examples=None, union_vertices=None,
                   search_steps=None,
                   trace_entries=None, described=None, preprocess_entries=None)


#: With more than C(2 END_LEVELS, 2) pairs, the pairs among the first and last
#: END_LEVELS levels are checked first (then consecutive pairs).
END_LEVELS = 12
