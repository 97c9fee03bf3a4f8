"""Exact numbers and expression trees written back in the configuration syntax.

Every string made here parses (with :func:`exactsym.io.expr.parse_expression`) to
the same exact number: the JSON output of ``exactsym check`` relies on it.
"""

from __future__ import annotations

from flint import fmpq

from ..io.exprtree import Fold, Node, fold
from .field import FieldElement, as_fmpq, pi_multiple_text, rational_text


# Binding strength of what a string is, loosest first: a sum, a product or quotient, a
# negation, a power, an atom (a number, a function call, a parenthesised expression).
_SUM, _PRODUCT, _NEGATION, _POWER, _ATOM = range(5)


def _wrap(text_and_level: tuple[str, int], least: int) -> str:
    text, level = text_and_level
    return text if level >= least else f"({text})"


def _rational_level(q: fmpq) -> tuple[str, int]:
    text = rational_text(q)
    if q < 0:
        return text, _NEGATION
    return text, (_PRODUCT if q.q != 1 else _ATOM)


class _Texts(Fold):
    """``(text, level)``: the text of a node and how strongly it binds (see ``_SUM``...)."""

    def const(self, node):
        return _rational_level(as_fmpq(node.value))

    def neg(self, node, arg):
        return "-" + _wrap(arg, _POWER), _NEGATION

    def binop(self, node, left, right):
        if node.op in "+-":
            # a - b needs b parenthesised when b is a sum; a + b never does, but a negated
            # right operand reads better as a subtraction
            if node.op == "+" and right[1] == _NEGATION and right[0].startswith("-"):
                return f"{left[0]} - {right[0][1:]}", _SUM
            return f"{left[0]} {node.op} {_wrap(right, _PRODUCT if node.op == '-' else _SUM)}", _SUM
        # the grammar reads 2*-3 as 2*(-3), but write the parentheses
        return f"{_wrap(left, _PRODUCT)}{node.op}{_wrap(right, _POWER)}", _PRODUCT

    def power(self, node, base):
        exponent = str(node.exponent) if node.exponent >= 0 else f"({node.exponent})"
        return f"{_wrap(base, _ATOM)}^{exponent}", _POWER

    def sqrt(self, node, arg):
        return f"sqrt({arg[0]})", _ATOM

    def trig(self, node):
        return f"{node.func}({pi_multiple_text(as_fmpq(node.pi_multiple))})", _ATOM


_TEXTS = _Texts()


def expression_text(node: Node) -> str:
    """The text of an expression tree with only the parentheses it needs; it parses back
    (:func:`exactsym.io.expr.parse_expression`) to an expression of the same value."""
    return fold(node, _TEXTS)[0]


def number_text(x) -> str:
    """The configuration-syntax text of an exact number."""
    if not isinstance(x, FieldElement):
        return rational_text(x)
    return x.text()                     # each kind writes itself (ExactNumber.text)
