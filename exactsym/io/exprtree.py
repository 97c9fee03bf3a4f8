"""Expression trees of the configuration format (``docs/format.md``).

The parser (:mod:`exactsym.io.expr`) builds them; the number kernel
(:mod:`exactsym.exact`) evaluates them.  Nothing here evaluates Python code.
``offset`` is the 0-based position in the source string of the node's first
character; it takes no part in equality.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from fractions import Fraction


@dataclass(frozen=True)
class Node:
    offset: int = field(default=0, compare=False, kw_only=True)


@dataclass(frozen=True)
class Const(Node):
    """A rational constant (integers, exact decimals, ``3/7`` folded by the parser or not)."""
    value: Fraction


@dataclass(frozen=True)
class Neg(Node):
    arg: Node


@dataclass(frozen=True)
class BinOp(Node):
    """``op`` is one of ``+ - * /``."""
    op: str
    left: Node
    right: Node


@dataclass(frozen=True)
class Pow(Node):
    """``base ^ exponent`` with an integer exponent (possibly negative)."""
    base: Node
    exponent: int


@dataclass(frozen=True)
class Sqrt(Node):
    """The non-negative square root of a non-negative expression."""
    arg: Node


@dataclass(frozen=True)
class Trig(Node):
    """``cos(q*pi)`` or ``sin(q*pi)``: ``func`` is ``"cos"`` or ``"sin"``, ``pi_multiple`` is q.

    The angle is ``pi_multiple * pi`` radians, i.e. ``pi_multiple / 2`` turns.
    """
    func: str
    pi_multiple: Fraction


Expr = Node
