"""The sparse nested reading (issue 29: code input does not reach leaves the package): nested
radicals with cos/sin beyond the dense base read as levels proved new by Legendre
characters over the sparse Q(zeta_N).  Input refuses these (``evaluate._mixed_system``);
tests swap this reading in to test it and its certificates, until input reaches it
(:func:`swap_in`): the tower extended in place (:func:`adjoin_nested`) and the certificate
of a nested level (:func:`nested_levels`, :func:`level_witness`) moved here with it.
:func:`exactsym.exact.sparse_nested.new_level_proved` stays in the package (MakeAsym's
radial move reaches it), and so does the checker's test of such a level (a certificate
file is input).
"""

from __future__ import annotations

import importlib

from flint import fmpq

from exactsym.certificates.encoder import CertificateError, Encoder
from exactsym.certificates.primes import MR_LIMIT
from exactsym.exact.evaluate import (MultiquadraticSystem, SparseKummerSystem, _collect,
                                     _cosine_conductor, _evaluate)
from exactsym.exact.sparse_nested import (_CONJUGATES, _PRIMES, _Embedding, _primes, _rational,
                                          _roots_of, _split_modulus, _units)
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
    (:func:`adjoin_nested`; FieldTooLargeError when not proved, e.g. a radicand that is
    a square there)."""

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
            return wrap(self.tower, adjoin_nested(self.tower, raw))
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


def swap_in(monkeypatch) -> None:
    """Read input with this reading and certify its nested levels (a test's fixture)."""
    # (the module: the package's name ``evaluate`` is the function)
    monkeypatch.setattr(importlib.import_module("exactsym.exact.evaluate"), "_mixed_system",
                        sparse_nested_system)
    monkeypatch.setattr(Encoder, "_nested_levels", nested_levels)


def adjoin_nested(tower, x):
    """The root of x (a positive raw value, not rational) in ``tower`` (a
    :class:`~exactsym.exact.sparse_tower.SparseKummerTower`), extended in place by the
    level sqrt(x) unless x already is a radicand: a nested radical of the input (read
    after every root of a rational).  FieldTooLargeError as ``tower.extended``."""
    root = tower._roots.get(x)
    return root if root is not None else tower._adjoin_proved(x)


def nested_levels(encoder, tower, levels: list, first: int) -> None:
    """The certificate's nested levels of ``tower`` above its ``first`` rational ones (the
    producer's :meth:`~exactsym.certificates.encoder.Encoder._nested_levels` when this reading
    is swapped in): one ring map onto F_l per level (:func:`level_witness`)."""
    for index in range(first + 1, tower.levels + 1):
        found = level_witness(tower, index, MR_LIMIT)
        if found is None:
            raise CertificateError(f"no prime below {MR_LIMIT} proves level {index} of "
                                   f"{tower.name} new; cannot certify")
        l, w, roots = found
        levels.append({"radicand": encoder._sparse_text(tower.radicands[index - 1]),
                       "prime": str(l), "zeta": str(w), "roots": [str(t) for t in roots]})


def level_witness(tower, index: int, limit: int):
    """``(l, w, roots)`` for the certificate of level ``index`` (1-based) of ``tower``, a
    nested level: l = 1 mod lcm(N, 4, the primes of the rational radicands below; 8 for 2)
    prime below ``limit``, w a primitive N-th root of unity mod l, ``roots`` a root of the
    image of each radicand below (all non-zero residues), and the image of the level's
    radicand a non-residue (``checker_tower_sparse``'s proof).  None when no prime among
    :data:`_PRIMES` (each with :data:`_CONJUGATES` embeddings) gives one."""
    radicands = tower.radicands
    below = range(1, index)
    split = _split_modulus(tower.context.n, [q for q in (_rational(radicands[j - 1])
                                                          for j in below) if q is not None])
    units = _units(tower.context.n, _CONJUGATES)
    # from k = 1: the checker's Miller-Rabin bound is near 3.3 * 10^24 (a denominator that
    # l divides makes an image undefined, and the next prime is taken)
    for l, g in _primes(tower.context, _PRIMES, split, start=1):
        if l >= limit:
            return None
        for u in units:
            w = pow(g, u, l)
            embedding = _Embedding(tower.context.n, l, w)
            roots = _roots_of(embedding, radicands, below)
            if roots is None:
                continue
            image = embedding.value(radicands[index - 1], roots)
            if image and pow(image, (l - 1) // 2, l) == l - 1:
                return l, w, [roots[j] for j in below]
    return None
