"""The caches of one analysis: made by :func:`exactsym.analysis.analyse`, dropped with it.

The truth, the paper layer and the filters remember work per number or vector *object*
(a ball, a squared length, a gap, the homogeneous form of a direction): in a field of
degree thousands each costs milliseconds to seconds and the same objects are read many
times.  Those tables live in an :class:`AnalysisContext`, never in a module: ``analyse``
makes one per configuration, computes inside :meth:`AnalysisContext.active` and keeps it
in the :class:`~exactsym.analysis.Analysis`, whose report reads the same context.  An
entry keeps its objects, and the context lives no longer than the analysis, so an
``id()`` is never mistaken for another object's (an id is reused only after its object
is collected), and nothing of one configuration survives into the next: a sweep or
``cases`` holds one analysis's tables at a time, not every one's.

A function that memoises names its table by a module-level :class:`Cache` (a name and
nothing else).  Outside any analysis (a test or the simulator calling the paper layer
directly) :meth:`Cache.table` is a fresh empty dict each time: nothing is remembered
across calls, every value is computed as it would be on a miss.
"""

from __future__ import annotations

from contextlib import contextmanager
from contextvars import ContextVar

__all__ = ["AnalysisContext", "Cache"]

# the context of the analysis being computed or reported (set only inside
# AnalysisContext.active, restored on leaving it)
_ACTIVE: ContextVar = ContextVar("exactsym_analysis_context", default=None)


class Cache:
    """The name of one table of an :class:`AnalysisContext` (it holds no entries)."""
    __slots__ = ("name",)

    def __init__(self, name: str):
        self.name = name

    def table(self) -> dict:
        """This analysis's dict for this cache (an empty throwaway dict outside one)."""
        context = _ACTIVE.get()
        if context is None:
            return {}
        tables = context.tables
        found = tables.get(self.name)
        if found is None:
            found = tables[self.name] = {}
        return found

    def __repr__(self) -> str:
        return f"Cache({self.name!r})"


class AnalysisContext:
    """The caches of one analysis, by name (:class:`Cache`).  Pickled empty: its entries
    are objects of this process, remembered only to save work."""

    def __init__(self):
        self.tables: dict = {}

    @contextmanager
    def active(self):
        """Make this the context of the memoising functions while the block runs."""
        token = _ACTIVE.set(self)
        try:
            yield self
        finally:
            _ACTIVE.reset(token)

    def sizes(self) -> dict:
        """``{cache name: entries}``."""
        return {name: len(table) for name, table in self.tables.items()}

    def __reduce__(self):
        return (AnalysisContext, ())
