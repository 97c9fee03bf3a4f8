"""The dependency graph of the ledger and what each statement rests on (networkx).

An edge ``a -> b`` says that ``a``'s proof cites ``b`` (``uses``) or that the algorithm
``a`` runs ``b`` (``calls``).  A statement *rests on a refuted statement* when some
statement it reaches (not itself) is graded ``refuted``; it *rests on a reading* when one
it reaches is ``refuted-under-reading``; it *rests only on proved statements* when every
statement it reaches is ``proved`` or a definition (a statement that reaches nothing rests
only on proved statements vacuously).  Cycles are allowed (networkx descendants handle
them) and reported by :func:`cycles`.
"""

from __future__ import annotations

from dataclasses import dataclass

import networkx as nx

from .model import Ledger

__all__ = ["Support", "dependency_graph", "support", "cycles"]

SOUND = ("proved", "definition")


@dataclass(frozen=True)
class Support:
    """What ``label`` rests on (labels it reaches, sorted)."""
    label: str
    rests_on_refuted: tuple[str, ...]
    rests_on_reading: tuple[str, ...]
    unproved: tuple[str, ...]

    @property
    def rests_only_on_proved(self) -> bool:
        return not self.unproved


def dependency_graph(ledger: Ledger) -> nx.DiGraph:
    g = nx.DiGraph()
    for s in ledger.statements:
        g.add_node(s.label, grade=s.grade, kind=s.kind)
    for s in ledger.statements:
        for u in s.uses:
            g.add_edge(s.label, u, relation="uses")
        for c in s.calls:
            g.add_edge(s.label, c, relation="calls")
    return g


def support(ledger: Ledger, graph: nx.DiGraph | None = None) -> dict[str, Support]:
    """label -> :class:`Support`, for every statement of the ledger."""
    g = graph if graph is not None else dependency_graph(ledger)
    grade = nx.get_node_attributes(g, "grade")
    out = {}
    for label in g.nodes:
        reach = nx.descendants(g, label) - {label}
        out[label] = Support(
            label=label,
            rests_on_refuted=tuple(sorted(x for x in reach if grade[x] == "refuted")),
            rests_on_reading=tuple(sorted(x for x in reach
                                          if grade[x] == "refuted-under-reading")),
            unproved=tuple(sorted(x for x in reach if grade[x] not in SOUND)))
    return out


def cycles(ledger: Ledger) -> list[list[str]]:
    return [sorted(c) for c in nx.simple_cycles(dependency_graph(ledger))]
