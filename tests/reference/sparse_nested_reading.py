"""The sparse nested reading (issue 29: code input does not reach leaves the package): nested
radicals with cos/sin beyond the dense base read as levels proved new by Legendre
characters over the sparse Q(zeta_N).  Input refuses these (``evaluate._mixed_system``);
tests swap this reading in to test it and its certificates, until input reaches it.
The tower's :meth:`~exactsym.exact.sparse_tower.SparseKummerTower.adjoin_nested` and
:mod:`exactsym.exact.sparse_nested` stay in the package: the certifier reads them.
"""

from __future__ import annotations

from flint import fmpq

from exactsym.exact.evaluate import (MultiquadraticSystem, SparseKummerSystem, _collect,
                                     _cosine_conductor, _evaluate)
from exactsym.exact.mq_closure import decided_sqrt
from exactsym.exact.multiquadratic import MQ
from exactsym.exact.sparse_cyclotomic import SparseCyclotomic
from exactsym.exact.tower import TowerElement, wrap
from exactsym.io.exprtree import Node


class SparseNestedSystem(SparseKummerSystem):
    """Nested radicals of the input with cos/sin whose dense base would pass
    :data:`exactsym.exact.cyclotomic_tower.MAX_BASE_DEGREE` (turns j/97 and sqrt(1 + sqrt(2)): Q(zeta_2328),
    degree 768): the tower of :class:`SparseKummerSystem`, its rational levels made first
    (:func:`sparse_nested_system`, not yet reached from input: see there), then each
    nested radical a level proved new by characters, added in place
    (:meth:`~exactsym.exact.sparse_tower.SparseKummerTower.adjoin_nested`; FieldTooLargeError when not
    proved, e.g. a radicand that is a square there)."""

    def __init__(self, conductor: int):
        super().__init__(conductor)
        self.denested: dict = {}        # raw radicand -> its root, an MQ (see denest)

    def sqrt(self, x):
        raw = x.v if isinstance(x, TowerElement) else self.coerce(x)
        if type(raw) is tuple or (isinstance(raw, SparseCyclotomic) and not raw.is_rational()):
            root = self.denested.get(raw)
            if root is not None:
                return sum((c * super(SparseNestedSystem, self).sqrt(fmpq(m))
                            for m, c in root.terms.items()), self.coerce(0))
            return wrap(self.tower, self.tower.adjoin_nested(raw))
        return super().sqrt(x)

    def denest(self, node: Node) -> None:
        """Before any nested level: when the radicand of the nested radical ``node`` is
        written with square roots of rationals only and has a root in the multiquadratic
        closure (:func:`exactsym.exact.mq_closure.decided_sqrt`: sqrt(3 + sqrt(5)) = (sqrt(10) +
        sqrt(2))/2), that root's square roots of rationals are read now and the radical
        is read as that root (characters cannot prove a square new)."""
        inner: list = []
        _collect(node.arg, inner)
        if any(kind != "sqrt" for kind, *_ in inner):
            return
        value = _evaluate(node.arg, MultiquadraticSystem(()))
        if not isinstance(value, MQ) or value.sign() <= 0:
            return
        root, _ = decided_sqrt(value)
        if root is None:
            return
        for m in root.terms:
            super().sqrt(fmpq(m))
        raw = _evaluate(node.arg, self)
        self.denested[raw.v if isinstance(raw, TowerElement) else self.coerce(raw)] = root


def sparse_nested_system(atoms):
    """The cosines' sparse Q(zeta_N) with every square root of a rational among the atoms a
    Kummer level (or a Gauss sum) first, so that the nested radicals, read later, are the
    top levels (above them a new root of a rational is refused).

    Not yet reached from input (``evaluate._mixed_system`` refuses beyond the dense base): on
    30 random sets of rings with nested radii and turns j/53 to j/999983 it answered 25,
    24 certified in about a second each, but two robots on two nested radii took a minute
    to certify, and five sets ran past two minutes (a mirror pair of two such pairs, and
    four near misses at 10^-30 in the paper layer's exact SEC of the moved
    configurations: numbers of thousands of terms about an irrational centre).  Tested by
    swapping it in for ``evaluate._mixed_system`` (tests/test_sparse_nested_input.py);
    its levels certify (``checker_tower_sparse``)."""
    system = SparseNestedSystem(_cosine_conductor(atoms))
    for atom in atoms:
        if atom[0] == "sqrt":
            system.sqrt(atom[1])
    for atom in atoms:
        if atom[0] == "nested":
            system.denest(atom[1])
    return system
