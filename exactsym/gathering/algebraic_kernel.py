"""Snapshots at a K(alpha) instant as kernel numbers, for the paper layer.

The paper layer (:mod:`.paper_bridge`) reads a snapshot through the kernel
(:mod:`exactsym.exact`): rationals, multiquadratic numbers, towers, and general number
fields ``Q(gamma)`` (:class:`~exactsym.exact.field.NumberField`, exact arithmetic modulo
gamma's minimal polynomial over Q, signs by Arb).  A snapshot taken at a root ``alpha`` of
a cubic or quartic factor (:mod:`~exactsym.exact.algebraic.algebraic_numbers`) holds
numbers of ``L = K(alpha)``, ``K = Q(sqrt b_1, ..., sqrt b_m)`` the multiquadratic field
of every square root in the snapshot and in alpha's polynomial ``f``.
:func:`kernel_configuration` writes it in one kernel field:

* ``[L:Q] = d 2^m`` (``d = deg f``; ``f`` stays irreducible over every multiquadratic
  field, :mod:`~exactsym.exact.algebraic.algebraic_numbers`), with the basis ``alpha^i
  sqrt(s)``, ``s`` running over the ``2^m`` square-free products of the ``b_j``;
* ``gamma = alpha + c theta`` (``theta = sum sqrt b_j``, ``c = 0, 1, 2, ...``) is a
  primitive element as soon as its powers ``1, ..., gamma^(D-1)`` are linearly
  independent (an exact rational determinant); ``gamma^D`` in that basis gives its
  minimal polynomial, and each coordinate is the solution of one linear system;
* a ball around gamma is alpha's ball plus ``c`` times theta's.

Square roots of rationals that lie in ``K`` are the field's atoms; any other square root
the paper layer asks for is a ``ValueError`` (its decision is then ``undecided``).
"""

from __future__ import annotations

from flint import fmpq, fmpq_mat, fmpq_poly

from ..exact.algebraic.algebraic_numbers import AlgebraicNumber, is_algebraic
from ..exact.algebraic.factor import group_basis
from ..exact.evaluate import FieldSystem
from ..exact.field import NumberField
from ..exact.multiquadratic import MQ
from ..geometry.configuration import Configuration

__all__ = ["kernel_field", "kernel_configuration"]

#: The largest degree of L over Q written in one kernel field.
MAX_DEGREE = 64


class _Atoms(dict):
    """The field's square roots; a miss is a ValueError (an undecided paper decision)."""

    def __missing__(self, key):
        raise ValueError(f"{key[0]}({key[1]}) is not in the snapshot's number field")


def _coords(x, d: int, rads: list) -> list:
    """The coordinates of ``x`` (MQ or AlgebraicNumber) in the basis alpha^i sqrt(s)."""
    cs = x.c if is_algebraic(x) else (x,)
    out = []
    for i in range(d):
        c = cs[i] if i < len(cs) else MQ()
        extra = set(c.terms) - set(rads)
        if extra:
            raise ValueError(f"sqrt({min(extra)}) is outside the field")
        out += [c.terms.get(s, fmpq(0)) for s in rads]
    return out


def kernel_field(root, numbers):
    """``(field, to_kernel)`` for the numbers of ``K(alpha)`` in ``numbers`` (MQ or
    :class:`AlgebraicNumber` of ``root``): the kernel field ``Q(gamma) = L`` and the map
    from them to its elements (exact).  The same root and square roots give the same
    field object (a Look's checks meet one instant several times)."""
    basis, _ = group_basis(list(root.f) + [c for x in numbers
                                      for c in (x.c if is_algebraic(x) else (x,))])
    cache = root.__dict__.setdefault("_kernel_fields", {})
    if basis not in cache:
        cache[basis] = _kernel_field(root, basis)
    return cache[basis]


def _kernel_field(root, basis):
    d = root.degree
    m = len(basis)
    size = d << m
    if size > MAX_DEGREE:
        raise ValueError(f"the snapshot's field has degree {size} over Q")
    rads = [1]
    for b in basis:
        rads += [next(iter((MQ({r: fmpq(1)}) * MQ({b: fmpq(1)})).terms)) for r in rads]
    theta = MQ({b: fmpq(1) for b in basis})
    for c in range(0, 16):
        gamma = AlgebraicNumber(root, (theta * c, MQ.rational(1)))
        powers, g = [], MQ.rational(1)
        for _ in range(size + 1):
            powers.append(_coords(g, d, rads))
            g = gamma * g
        a = fmpq_mat(size, size, [powers[k][r] for r in range(size) for k in range(size)])
        if a.det() == 0:
            continue                       # gamma is not primitive: another c
        top = a.solve(fmpq_mat(size, 1, powers[size]))
        minpoly = fmpq_poly([-top[k, 0] for k in range(size)] + [1])

        def enclose(prec, gamma=gamma):
            return gamma.enclosure(prec)
        field = NumberField(minpoly, enclose, f"Q(gamma), gamma = alpha + {c}*theta, "
                            f"alpha = {root.text()}")

        return field, _ToKernel(field, a, d, rads)
    raise ValueError("no primitive element found")


class _ToKernel:
    """The map from numbers of ``K(alpha)`` to ``Q(gamma)``: the coordinates in the basis
    ``alpha^i sqrt(s)`` solved against the powers of gamma (``a``, exact); ``many``
    solves for several numbers at once (one elimination: a snapshot's numbers, with
    coefficients of thousands of bits, cost one solve instead of one each)."""

    def __init__(self, field, a, d: int, rads: list):
        self.field, self.a, self.d, self.rads = field, a, d, rads

    def __call__(self, x):
        return self.many([x])[0]

    def many(self, xs) -> list:
        xs = list(xs)
        if not xs:
            return []
        size = self.a.nrows()
        cols = [_coords(x, self.d, self.rads) for x in xs]
        v = self.a.solve(fmpq_mat(size, len(cols), [c[r] for r in range(size) for c in cols]))
        return [self.field.element(fmpq_poly([v[k, j] for k in range(size)]))
                for j in range(len(cols))]


def kernel_configuration(points):
    """A kernel :class:`~exactsym.geometry.configuration.Configuration` of the snapshot ``points``
    (pairs of MQ and :class:`AlgebraicNumber` numbers of one root), in a
    :class:`~exactsym.exact.evaluate.FieldSystem` over ``Q(gamma)``."""
    roots = {x.root for p in points for x in p if is_algebraic(x)}
    if len(roots) != 1:
        raise ValueError("kernel_configuration: the points hold no number of one K(alpha)")
    numbers = [x for p in points for x in p]
    field, to_kernel = kernel_field(roots.pop(), numbers)
    radicands = sorted({s for x in numbers for c in (x.c if is_algebraic(x) else (x,))
                        for s in c.terms if s != 1})
    values = to_kernel.many([MQ({s: fmpq(1)}) for s in radicands] + numbers)
    atoms = _Atoms({("sqrt", fmpq(s)): v for s, v in zip(radicands, values)})
    coords = values[len(radicands):]
    pts = list(zip(coords[0::2], coords[1::2]))
    return Configuration.from_points(pts, system=FieldSystem(field, atoms))
