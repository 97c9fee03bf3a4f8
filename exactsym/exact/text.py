"""Exact numbers and expression trees written back in the configuration syntax.

Every string made here parses (with :func:`exactsym.expr.parse_expression`) to
the same exact number: the JSON output of ``exactsym check`` relies on it.
"""

from __future__ import annotations

from flint import fmpq

from ..exprtree import BinOp, Const, Neg, Node, Pow, Sqrt, Trig
from .field import FieldElement, as_fmpq


def rational_text(q) -> str:
    q = as_fmpq(q)
    return str(q.p) if q.q == 1 else f"{q.p}/{q.q}"


def _pi_multiple_text(q: fmpq) -> str:
    if q == 1:
        return "pi"
    if q.q == 1:
        return f"{q.p}*pi"
    return f"{q.p}*pi/{q.q}"


def expression_text(node: Node) -> str:
    """A fully parenthesised string for an expression tree."""
    if isinstance(node, Const):
        return f"({rational_text(node.value)})"
    if isinstance(node, Neg):
        return f"(-{expression_text(node.arg)})"
    if isinstance(node, BinOp):
        return f"({expression_text(node.left)}{node.op}{expression_text(node.right)})"
    if isinstance(node, Pow):
        return f"({expression_text(node.base)}^({node.exponent}))"
    if isinstance(node, Sqrt):
        return f"sqrt{expression_text(node.arg)}"
    if isinstance(node, Trig):
        return f"{node.func}({_pi_multiple_text(as_fmpq(node.pi_multiple))})"
    raise TypeError(type(node).__name__)


def _sum_text(terms: list[tuple[fmpq, str]]) -> str:
    """``c1*t1 + c2*t2 ...`` with ``t == ""`` for a constant; ``"0"`` for no term."""
    out = []
    for coeff, term in terms:
        if coeff == 0:
            continue
        neg = coeff < 0
        mag = -coeff if neg else coeff
        if term == "":
            body = rational_text(mag)
        elif mag == 1:
            body = term
        elif mag.q == 1:
            body = f"{mag.p}*{term}"
        elif mag.p == 1:
            body = f"{term}/{mag.q}"
        else:
            body = f"{mag.p}*{term}/{mag.q}"
        if not out:
            out.append(("-" if neg else "") + body)
        else:
            out.append((" - " if neg else " + ") + body)
    return "".join(out) if out else "0"


def number_text(x) -> str:
    """The configuration-syntax text of an exact number."""
    if not isinstance(x, FieldElement):
        return rational_text(x)
    if x.is_rational():
        return rational_text(x.rational())
    field = x.field
    coeffs = x.poly.coeffs()
    if field.conductor is not None:
        # x = sum c_k zeta^k is real, so x = sum c_k cos(2 pi k / M)
        m = field.conductor
        terms = [(coeffs[0], "")] + [(c, f"cos({_pi_multiple_text(fmpq(2 * k, m))})")
                                    for k, c in enumerate(coeffs) if k and c != 0]
        return _sum_text(terms)
    theta = f"({field.theta_text})"
    terms = [(coeffs[0], "")] + [(c, theta if k == 1 else f"{theta}^{k}")
                                for k, c in enumerate(coeffs) if k and c != 0]
    return _sum_text(terms)
