"""The caches of one analysis or one gathering run: made by :func:`exactsym.analysis.analyse`
(or the run), dropped with it.

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

A table whose entries are *identities* rather than a memo (the roots of the motion's
K(alpha) instants: every number of an instant must share one root object, and the
levels built over it) is a ``Cache(name, shared_outside=True)``: in a context it is the
context's, so a run gets the roots and levels it built and no other run's; outside any
context (a test driving the simulator's pieces by hand) one table of the process.

This module sits in exact/, below every layer that memoises, so the number layer's own
per-object tables (F_p images of coordinates, a tower's maps into F_p) are Caches too.
"""

from __future__ import annotations

from contextlib import contextmanager
from contextvars import ContextVar
from functools import wraps

__all__ = ["AnalysisContext", "Cache", "in_own_context"]

# the context of the analysis being computed or reported (set only inside
# AnalysisContext.active, restored on leaving it)
_ACTIVE: ContextVar = ContextVar("exactsym_analysis_context", default=None)


class Cache:
    """The name of one table of an :class:`AnalysisContext` (it holds no entries but,
    when ``shared_outside``, the one table used outside every context)."""
    __slots__ = ("name", "_outside")

    def __init__(self, name: str, shared_outside: bool = False):
        self.name = name
        self._outside = {} if shared_outside else None

    def table(self) -> dict:
        """This analysis's dict for this cache (outside one: an empty throwaway dict, or
        the process's table when ``shared_outside``)."""
        context = _ACTIVE.get()
        if context is None or not (context.memo or self._outside is not None):
            return {} if self._outside is None else self._outside
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

    def __init__(self, memo: bool = True):
        self.tables: dict = {}
        # False: a gathering run's context, which holds the identity tables only (its
        # memo tables stay throwaway, as outside any context: a run's memory as before)
        self.memo = memo

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
        return (AnalysisContext, (self.memo,))


def in_own_context(function):
    """``function`` run in a fresh :class:`AnalysisContext` of its own at each call (a
    gathering run: the roots and levels it builds are its own, dropped when it ends; its
    memo tables stay throwaway, as outside any context)."""
    @wraps(function)
    def run(*args, **kwargs):
        with AnalysisContext(memo=False).active():
            return function(*args, **kwargs)
    return run
