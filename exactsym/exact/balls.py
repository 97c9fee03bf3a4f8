"""Arb balls of expression trees: the evaluator's walk (:func:`exactsym.io.exprtree.fold`)
over balls instead of exact numbers, so the coordinate filters of
:mod:`exactsym.geometry.algebraic_filtered` enclose a point without its exact value (0.4 ms
less per coordinate in degree 960: a cosine there is a polynomial of that degree to
evaluate).

Public names: :func:`expression_ball`.
"""

from __future__ import annotations

from flint import arb, fmpq

from ..io.exprtree import Fold, Node, fold


class _Balls(Fold):
    """Balls at the current working precision: rigorous, so only wide (cancellation) or
    not finite (a divisor or radicand whose ball meets zero), never wrong."""

    def const(self, node):
        return arb(fmpq(node.value.numerator, node.value.denominator))

    def neg(self, node, arg):
        return -arg

    def binop(self, node, left, right):
        if node.op == "+":
            return left + right
        if node.op == "-":
            return left - right
        if node.op == "*":
            return left * right
        return left / right

    def power(self, node, base):
        return base ** node.exponent if node.exponent >= 0 else 1 / base ** -node.exponent

    def trig(self, node):
        q = fmpq(node.pi_multiple.numerator, node.pi_multiple.denominator)
        return arb.cos_pi_fmpq(q) if node.func == "cos" else arb.sin_pi_fmpq(q)

    def sqrt(self, node, arg):
        return arg.sqrt() if arg > 0 else (arb(0) if arg == 0 else arb("nan"))


_BALLS = _Balls()


def expression_ball(node: Node) -> arb:
    """An Arb ball around the exact value of an expression tree, at the current working
    precision: rigorous, so it may only be wide (cancellation), or not finite (a divisor
    or radicand whose ball meets zero), never wrong."""
    return fold(node, _BALLS)


__all__ = ["expression_ball"]
