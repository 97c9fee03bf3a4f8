"""sympy as an independent oracle of the number layer (issue 29): random expressions of the
configuration syntax are read by exactsym, and by sympy from the same tree (the one walk,
:func:`exactsym.io.exprtree.fold`).  sympy's minimal polynomial of the value must vanish at
exactsym's number, decided by exactsym's exact arithmetic, and sympy's numerical value at
60 digits (mpmath) must lie in exactsym's Arb ball with the same sign.  sympy never decides
an equality here (no ``==``, ``equals`` or ``simplify`` on radicals), and nothing is
sympified from text."""

from __future__ import annotations

import sympy
from flint import arb, ctx
from hypothesis import given, settings, strategies as st

from exactsym.exact import evaluate_all, sign
from exactsym.exact.number import enclosure
from exactsym.io.expr import parse_expression
from exactsym.io.exprtree import Fold, fold

X = sympy.Symbol("x")


class _Sympy(Fold):
    """The sympy expression of a tree, built node by node (no parsing of text)."""

    def const(self, node):
        return sympy.Rational(node.value.numerator, node.value.denominator)

    def neg(self, node, arg):
        return -arg

    def binop(self, node, left, right):
        return {"+": sympy.Add, "*": sympy.Mul}[node.op](left, right) if node.op in "+*" \
            else (left - right if node.op == "-" else left / right)

    def power(self, node, base):
        return base ** node.exponent

    def sqrt(self, node, arg):
        return sympy.sqrt(arg)

    def trig(self, node):
        angle = sympy.pi * sympy.Rational(node.pi_multiple.numerator,
                                          node.pi_multiple.denominator)
        return sympy.cos(angle) if node.func == "cos" else sympy.sin(angle)


def _rational():
    return st.builds(lambda p, q: f"{p}/{q}" if q != 1 else str(p),
                     st.integers(-9, 9), st.integers(1, 5))


def _square_root():
    return st.builds(lambda k: f"sqrt({k})", st.integers(2, 30))


def _trig():
    return st.builds(lambda f, a, b: f"{f}({a}*pi/{b})", st.sampled_from(["cos", "sin"]),
                     st.integers(1, 23), st.integers(5, 12))


def _nested():
    # a + b sqrt(c) > 0 with a >= 1 and b > 0
    return st.builds(lambda a, b, c: f"sqrt({a} + {b}*sqrt({c}))", st.integers(1, 6),
                     st.integers(1, 3), st.integers(2, 11))


def _combined(atoms):
    """Sums and products of up to three atoms with rational coefficients, maybe squared or
    divided by a rational."""
    def build(terms, ops, power, divisor):
        text = terms[0]
        for op, term in zip(ops, terms[1:]):
            text = f"({text}) {op} {term}"
        if power:
            text = f"({text})^{power}"
        return f"({text})/{divisor}" if divisor != 1 else text
    term = st.one_of(atoms, st.builds(lambda c, a: f"{c}*{a}", _rational(), atoms))
    return st.builds(build, st.lists(term, min_size=1, max_size=3),
                     st.lists(st.sampled_from("+-*"), min_size=2, max_size=2),
                     st.sampled_from([0, 0, 2, 3]), st.integers(1, 4))


def _check(text: str) -> None:
    tree = parse_expression(text)
    _, (value,) = evaluate_all([tree])
    expr = fold(tree, _Sympy())
    # the value is a root of sympy's minimal polynomial: decided exactly by exactsym
    poly = sympy.Poly(sympy.minimal_polynomial(expr, X), X)
    acc = 0
    for c in poly.all_coeffs():
        acc = acc * value + int(c)
    assert acc == 0, (text, poly)
    # and the right root: sympy's 60 digits lie in exactsym's ball
    numeric = sympy.N(expr, 60)
    with ctx.workprec(256):
        ball = enclosure(value, 256)
        assert (ball - arb(str(numeric))).abs_upper() < arb("1e-50"), (text, ball, numeric)
    if abs(numeric) > sympy.Float("1e-40"):
        assert sign(value) == (1 if numeric > 0 else -1), text


@settings(max_examples=40, deadline=None)
@given(_combined(st.one_of(_rational(), _square_root())))
def test_square_roots_of_rationals_agree_with_sympy(text):
    _check(text)


@settings(max_examples=30, deadline=None)
@given(_combined(st.one_of(_rational(), _square_root(), _trig())))
def test_cyclotomic_numbers_agree_with_sympy(text):
    _check(text)


@settings(max_examples=25, deadline=None)
@given(_combined(st.one_of(_rational(), _square_root(), _nested())))
def test_nested_radicals_agree_with_sympy(text):
    _check(text)


def test_a_wrong_value_is_caught():
    """The oracle can fail: sqrt(2) is not a root of the minimal polynomial of sqrt(3)."""
    _, (value,) = evaluate_all([parse_expression("sqrt(2)")])
    poly = sympy.Poly(sympy.minimal_polynomial(sympy.sqrt(3), X), X)
    acc = 0
    for c in poly.all_coeffs():
        acc = acc * value + int(c)
    assert acc != 0
