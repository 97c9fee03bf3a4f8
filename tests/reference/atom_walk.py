"""The recursive atom walk that ``exactsym.exact.evaluate._collect`` was before it became a
fold over the one expression walker (issue 29: one expression walker), kept as the oracle
of tests/exact/test_atom_collection.py: the same atoms in the same order, the same first
error (message and offset)."""

from __future__ import annotations

from flint import fmpq

from exactsym.errors import ExpressionError
from exactsym.exact.evaluate import (RationalSystem, _evaluate, normal_turn, rational_cos_turn,
                                     rational_sqrt)
from exactsym.exact.field import as_fmpq
from exactsym.io.exprtree import BinOp, Const, Neg, Node, Pow, Sqrt, Trig


def _rational_value(node: Node) -> fmpq | None:
    """The value of ``node`` if it is rational without any field work, else None."""
    try:
        value = _evaluate(node, RationalSystem())
    except ValueError:
        return None
    return value


def collect(node: Node, atoms: list) -> None:
    """Append the irrational atoms of ``node``: ("sqrt", q), ("cos", turn), ("nested",
    Sqrt node)."""
    if isinstance(node, Const):
        return
    if isinstance(node, Neg):
        collect(node.arg, atoms)
    elif isinstance(node, BinOp):
        collect(node.left, atoms)
        collect(node.right, atoms)
    elif isinstance(node, Pow):
        collect(node.base, atoms)
    elif isinstance(node, Trig):
        turn = fmpq(1, 4) - as_fmpq(node.pi_multiple) / 2 if node.func == "sin" \
            else as_fmpq(node.pi_multiple) / 2
        if rational_cos_turn(turn) is None:
            atoms.append(("cos", normal_turn(turn), node.func))
    elif isinstance(node, Sqrt):
        q = _rational_value(node.arg)
        if q is None:
            collect(node.arg, atoms)
            atoms.append(("nested", node))
        elif q < 0:
            raise ExpressionError("square root of a negative number", offset=node.offset)
        elif rational_sqrt(q) is None:
            atoms.append(("sqrt", q))
    else:  # pragma: no cover - the parser makes no other nodes
        raise ExpressionError(f"unknown expression node {type(node).__name__}", offset=node.offset)
