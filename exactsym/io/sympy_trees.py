"""sympy expressions to and from the expression trees of the configuration format.

In: a number handed to the Python API as a sympy expression (``sympy.sqrt(2)``,
``sympy.cos(2*sympy.pi/7)/3``) is read by walking its tree node by node into
:mod:`.exprtree` nodes, exactly as a file's expression is parsed: only rationals, ``+``,
``*``, integer and half-integer powers, and ``cos``/``sin`` of a rational multiple of pi
are accepted.  Nothing is evaluated, simplified or compared by sympy (no ``sympify``, no
``==`` on radicals): the number kernel evaluates the tree.

Out: an exact number's text (which parses back to the same number) becomes a sympy
expression built from the parsed tree by sympy's constructors.

sympy is imported only when one of these functions is called.
"""

from __future__ import annotations

from fractions import Fraction

from ..errors import ExpressionError
from .exprtree import BinOp, Const, Neg, Node, Pow, Sqrt, Trig

__all__ = ["is_sympy", "tree_of_sympy", "sympy_of_tree"]


def is_sympy(value) -> bool:
    """Whether ``value`` is a sympy object (decided by its class, without importing sympy)."""
    return type(value).__module__.split(".")[0] == "sympy"


def _refuse(what: str, value) -> ExpressionError:
    return ExpressionError(f"{what} is not an exact number exactsym reads: {value} "
                           "(rationals, +, -, *, /, integer powers, sqrt, and cos/sin of a "
                           "rational multiple of pi)")


def tree_of_sympy(value, depth: int = 0) -> Node:
    """The expression tree of a sympy number, walked node by node (never evaluated).

    >>> import sympy
    >>> tree_of_sympy(sympy.sqrt(2) / 2) == BinOp("*", Const(Fraction(1, 2)),
    ...                                           Sqrt(Const(Fraction(2))))
    True
    >>> tree_of_sympy(sympy.cos(2 * sympy.pi / 7)) == Trig("cos", Fraction(2, 7))
    True
    >>> tree_of_sympy(sympy.Float(0.5))
    Traceback (most recent call last):
    ...
    exactsym.errors.ExpressionError: a float is not exact: 0.500000000000000 (write it as a string, '0.5', or a Fraction)
    """
    import sympy
    if depth > 100:
        raise ExpressionError("sympy expression nested too deeply")
    if isinstance(value, sympy.Float):
        raise ExpressionError(f"a float is not exact: {value} (write it as a string, "
                              "'0.5', or a Fraction)")
    if isinstance(value, sympy.Rational):            # Integer, Half, One, ... included
        return Const(Fraction(int(value.p), int(value.q)))
    args = value.args
    if isinstance(value, sympy.Add):
        return _chain("+", [tree_of_sympy(a, depth + 1) for a in args])
    if isinstance(value, sympy.Mul):
        return _chain("*", [tree_of_sympy(a, depth + 1) for a in args])
    if isinstance(value, sympy.Pow):
        base, exponent = args
        if not isinstance(exponent, sympy.Rational) or exponent.q not in (1, 2):
            raise _refuse("a power", value)
        tree = tree_of_sympy(base, depth + 1)
        if exponent.q == 2:
            tree = Sqrt(tree)
        k = int(exponent.p)
        return tree if k == 1 else Pow(tree, k)
    if isinstance(value, (sympy.cos, sympy.sin)):
        if isinstance(args[0], sympy.Rational) and args[0].p == 0:     # cos(0), sin(0)
            return Trig(type(value).__name__, Fraction(0))
        coeff, rest = args[0].as_coeff_Mul()        # structural: q * pi, never evaluated
        if rest is not sympy.pi or not isinstance(coeff, sympy.Rational):
            raise _refuse("a cos/sin argument", args[0])
        return Trig(type(value).__name__, Fraction(int(coeff.p), int(coeff.q)))
    raise _refuse("a sympy expression", value)


def _chain(op: str, trees: list[Node]) -> Node:
    tree = trees[0]
    for t in trees[1:]:
        tree = BinOp(op, tree, t)
    return tree


def sympy_of_tree(tree: Node):
    """A sympy expression built from an expression tree with sympy's constructors.

    >>> from exactsym.io.expr import parse_expression
    >>> sympy_of_tree(parse_expression("sqrt(2)/2 + cos(2*pi/7)"))
    cos(2*pi/7) + sqrt(2)/2
    """
    import sympy
    if isinstance(tree, Const):
        return sympy.Rational(tree.value.numerator, tree.value.denominator)
    if isinstance(tree, Neg):
        return -sympy_of_tree(tree.arg)
    if isinstance(tree, BinOp):
        left, right = sympy_of_tree(tree.left), sympy_of_tree(tree.right)
        if tree.op == "+":
            return left + right
        if tree.op == "-":
            return left - right
        return left * right if tree.op == "*" else left / right
    if isinstance(tree, Pow):
        return sympy_of_tree(tree.base) ** tree.exponent
    if isinstance(tree, Sqrt):
        return sympy.sqrt(sympy_of_tree(tree.arg))
    if isinstance(tree, Trig):
        q = tree.pi_multiple
        angle = sympy.Rational(q.numerator, q.denominator) * sympy.pi
        return (sympy.cos if tree.func == "cos" else sympy.sin)(angle)
    raise TypeError(f"not an expression tree: {tree!r}")
