"""Every number exactsym writes reads back to itself (issue 9: ``sqrtsqrt(2)``, ``sqrtcos``).

Law: for every expression tree E, ``parse(text(E))`` and ``parse(number_text(value(E)))``
have the value of E.  Both are evaluated in one number system with E, so equality is exact.
"""

from __future__ import annotations

import contextlib
import io
import json
from fractions import Fraction

import pytest
from hypothesis import given, settings, strategies as st

from exactsym.cli.main import main
from exactsym.errors import ExpressionError
from exactsym.exact import evaluate_all, expression_text, number_text
from exactsym.io.expr import MAX_LENGTH, parse_expression
from exactsym.io.exprtree import BinOp, Const, Neg, Pow, Sqrt, Trig

consts = st.builds(lambda p, q: Const(Fraction(p, q)), st.integers(-12, 12), st.integers(1, 5))
square_roots = st.builds(lambda p, q: Sqrt(Const(Fraction(p, q))), st.integers(0, 30),
                         st.integers(1, 4))
trig = st.builds(lambda f, p, q: Trig(f, Fraction(p, q)), st.sampled_from(["cos", "sin"]),
                 st.integers(-12, 12), st.sampled_from([1, 2, 3, 5, 8, 10, 12]))


def trees(atoms, max_leaves=6):
    """Expression trees over ``atoms``: sums, products, quotients, negations, small powers."""
    return st.recursive(atoms, lambda sub: st.one_of(
        st.builds(BinOp, st.sampled_from("+-*"), sub, sub),
        st.builds(lambda a, b: BinOp("/", a, BinOp("+", Const(Fraction(3)), BinOp("*", b, b))),
                  sub, sub),                      # 3 + b^2 is never zero
        st.builds(Neg, sub),
        st.builds(Pow, sub, st.integers(0, 3))), max_leaves=max_leaves)


nested = st.builds(lambda t: Sqrt(BinOp("+", Const(Fraction(5)), BinOp("*", t, t))),
                   square_roots)                 # sqrt(5 + r^2): a nested radical
KINDS = {
    "rational": trees(consts),
    "square roots": trees(st.one_of(consts, square_roots)),
    "trigonometry": trees(st.one_of(consts, trig, square_roots)),
    # nested radicals of square roots live in a tower of quadratic extensions (cheap), so
    # draws of four radicals are fine (sympy's primitive element took minutes for six)
    "nested": trees(st.one_of(consts, square_roots, nested,
                              st.builds(Sqrt, st.builds(Sqrt, square_roots))), max_leaves=4),
}


def same_value(tree, text: str) -> bool:
    """``text`` (as exactsym wrote it: no limit on its length) has the value of ``tree``."""
    _, (a, b) = evaluate_all([tree, parse_expression(text, written=True)])
    return a == b


@pytest.mark.parametrize("kind", sorted(KINDS))
def test_printed_numbers_read_back(kind):
    @settings(max_examples=25, deadline=None)
    @given(KINDS[kind])
    def law(tree):
        try:
            _, (value,) = evaluate_all([tree])
        except ExpressionError:
            return                                  # e.g. a power of zero with exponent < 0
        assert same_value(tree, expression_text(tree))
        assert same_value(tree, number_text(value))
    law()


def test_numbers_longer_than_the_input_limit_read_back():
    """A sum of many cosines of a large denominator is written in more than the 10,000
    characters a configuration's expression may have: read as a written number it is
    itself, and as input it is refused with the limit named."""
    tree = parse_expression("0")
    for k in range(1, 400):
        tree = BinOp("+", tree, BinOp("*", Const(Fraction(k * 7919, 13)),
                                      Trig("cos", Fraction(2 * k, 997))))
    _, (value,) = evaluate_all([tree])
    printed = number_text(value)
    assert len(printed) > MAX_LENGTH
    assert same_value(tree, printed)
    with pytest.raises(ExpressionError, match="too long"):
        parse_expression(printed)


def test_long_nested_text():
    # nested radicals print as a tower of quadratic extensions, a + b*sqrt(radicand)
    tree = parse_expression("sqrt(5 + sqrt(2/3)*sqrt(2/3)) + sqrt(sqrt(sqrt(1/2)))")
    _, (value,) = evaluate_all([tree])
    assert len(number_text(value)) <= MAX_LENGTH


@pytest.mark.parametrize("text, printed", [
    ("sqrt(sqrt(2))", "sqrt(sqrt(2))"),
    ("sqrt(cos(pi/5))", "sqrt(cos(pi/5))"),
    ("(1)*sqrt(2)", "1*sqrt(2)"),
    ("-(2+3*sqrt(2))", "-(2 + 3*sqrt(2))"),
    ("2^(-3)*sqrt(2)", "1/8*sqrt(2)"),
    ("(1/2)^3 - (sqrt(2) - sqrt(3))", "1/8 - (sqrt(2) - sqrt(3))"),
])
def test_expression_text_is_short(text, printed):
    tree = parse_expression(text)
    assert expression_text(tree) == printed
    assert same_value(tree, printed)


def test_issue_examples_number_text():
    # (1 + 2*sqrt(2))^2 = 9 + 4*sqrt(2): short text, no "((1)*sqrt(2))"
    _, (x,) = evaluate_all([parse_expression("(1+2*sqrt(2))^2")])
    assert number_text(x) == "9 + 4*sqrt(2)"
    for text in ("sqrt(sqrt(2))", "sqrt(cos(pi/5))", "sqrt(2+sqrt(3)) + 1/3"):
        tree = parse_expression(text)
        _, (x,) = evaluate_all([tree])
        printed = number_text(x)
        assert "sqrtsqrt" not in printed and "sqrtcos" not in printed and "(1)*" not in printed
        assert same_value(tree, printed)


def test_a_long_written_number_as_an_expectation(tmp_path):
    """The SEC's squared radius of three robots at turns j/999983 is written in about 28,000
    characters; copied into [expect], it is read (not refused as too long) and met."""
    points = ('  { r = "987654321/1234567", turn = "1/999983" },\n'
              '  { r = "876543219/2345671", turn = "300001/999983" },\n'
              '  { r = "765432198/3456712", turn = "600011/999983" },\n')
    plain = tmp_path / "three.toml"
    plain.write_text("format = 1\npoints = [\n" + points + "]\n")
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        assert main(["check", "--json", str(plain)]) == 0
    radius = json.loads(out.getvalue())["sec"]["radius_squared"]
    assert len(radius) > MAX_LENGTH
    expected = tmp_path / "expected.toml"
    expected.write_text(plain.read_text() + f'\n[expect]\nsec_radius_squared = "{radius}"\n')
    with contextlib.redirect_stdout(io.StringIO()):
        assert main(["check", str(expected)]) == 0
    wrong = tmp_path / "wrong.toml"
    wrong.write_text(plain.read_text() + f'\n[expect]\nsec_radius_squared = "1 + {radius}"\n')
    with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()):
        assert main(["check", str(wrong)]) == 1
