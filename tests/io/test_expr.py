"""The expression parser of configuration format 1 (exactsym.io.expr)."""

import re
from fractions import Fraction as F
from pathlib import Path

import pytest
from hypothesis import given, settings, strategies as st

from exactsym.io import expr
from exactsym.errors import ExpressionError, InputError
from exactsym.io.expr import parse_expression as parse
from exactsym.io.exprtree import BinOp, Const, Neg, Node, Pow, Sqrt, Trig


def C(value) -> Const:
    return Const(F(value))


def error(text: str) -> ExpressionError:
    with pytest.raises(ExpressionError) as info:
        parse(text)
    return info.value


# ---------------------------------------------------------------- numbers

@pytest.mark.parametrize("text, value", [
    ("0", 0), ("-12", -12), ("+7", 7), ("007", 7),
    ("0.125", F(1, 8)), ("1e-3", F(1, 1000)), ("2.5E+4", 25000), ("1E3", 1000),
    ("1.5e-1", F(3, 20)), (".5", F(1, 2)), ("5.", 5), ("0.1", F(1, 10)),
    ("3/7", F(3, 7)), ("-3/7", F(-3, 7)), ("6/4", F(3, 2)), ("1e0", 1),
    ("1e00003", 1000), ("1e-3000", F(1, 10 ** 3000)),
])
def test_number_literals_are_exact(text, value):
    assert parse(text) == C(value)


def test_exact_decimal_is_not_the_float():
    assert parse("0.1") != Const(F(0.1))
    assert parse("0.1").value == F(1, 10)


# ---------------------------------------------------------------- operators

@pytest.mark.parametrize("text, value", [
    ("1+2*3", 7), ("(1+2)*3", 9), ("1-2-3", -4), ("2/3/4", F(1, 6)), ("8/2*2", 8),
    ("-2^2", -4), ("(-2)^2", 4), ("-2**2", -4), ("2^-2", F(1, 4)), ("2**-2", F(1, 4)),
    ("2^3^2", 512), ("2**3**2", 512), ("2^-3^2", F(1, 2 ** 9)), ("(2^3)^2", 64),
    ("2^(-1)", F(1, 2)), ("2^(1+1)", 4), ("2^(4/2)", 4), ("(1/2)^-3", 8),
    ("--3", 3), ("-+-3", 3), ("---3", -3), ("2*-3", -6), ("2--3", 5), ("2^+3", 8),
    ("0^0", 1), ("3 * ( 1 / 3 )", 1), (" \t1\n+ 1 ", 2), ("1e3/1e-3", 10 ** 6),
])
def test_rational_arithmetic_folds_exactly(text, value):
    assert parse(text) == C(value)


def test_sqrt_is_kept_unevaluated():
    assert parse("sqrt(2)") == Sqrt(C(2))
    assert parse("sqrt(4)") == Sqrt(C(4))
    assert parse("sqrt(3)/2") == BinOp("/", Sqrt(C(3)), C(2))
    assert parse("sqrt(1/2+1/4)") == Sqrt(C(F(3, 4)))
    assert parse("sqrt(sqrt(2))") == Sqrt(Sqrt(C(2)))
    assert parse("sqrt(0)") == Sqrt(C(0))


def test_trees_with_irrational_parts():
    assert parse("1 + sqrt(2)") == BinOp("+", C(1), Sqrt(C(2)))
    assert parse("-sqrt(2)") == Neg(Sqrt(C(2)))
    assert parse("--sqrt(2)") == Sqrt(C(2))
    assert parse("-sqrt(2)^2") == Neg(Pow(Sqrt(C(2)), 2))
    assert parse("sqrt(2)^-3") == Pow(Sqrt(C(2)), -3)
    assert parse("sqrt(2)**(2^2)") == Pow(Sqrt(C(2)), 4)
    assert parse("(1+sqrt(5))/2") == BinOp("/", BinOp("+", C(1), Sqrt(C(5))), C(2))
    assert parse("2*sqrt(2)-sqrt(3)*3") == BinOp(
        "-", BinOp("*", C(2), Sqrt(C(2))), BinOp("*", Sqrt(C(3)), C(3)))
    assert parse("sqrt(2)/sqrt(3)/4") == BinOp("/", BinOp("/", Sqrt(C(2)), Sqrt(C(3))), C(4))


def test_offsets_of_nodes():
    tree = parse("1 + sqrt(2)")
    assert (tree.offset, tree.right.offset, tree.right.arg.offset) == (0, 4, 9)
    assert parse("  -sqrt(2)").offset == 2


# ---------------------------------------------------------------- cos and sin

@pytest.mark.parametrize("text, func, q", [
    ("cos(pi)", "cos", 1), ("sin(pi)", "sin", 1), ("cos(-pi)", "cos", -1),
    ("cos(2*pi/7)", "cos", F(2, 7)), ("cos(pi*2/7)", "cos", F(2, 7)),
    ("cos((2/7)*pi)", "cos", F(2, 7)), ("cos(2/7*pi)", "cos", F(2, 7)),
    ("cos(pi/7)", "cos", F(1, 7)), ("sin(-pi/3)", "sin", F(-1, 3)),
    ("sin(0.5*pi)", "sin", F(1, 2)), ("cos(pi*0.25)", "cos", F(1, 4)),
    ("cos(0*pi)", "cos", 0), ("sin(3*pi/2)", "sin", F(3, 2)), ("cos(pi/2 + pi/3)", "cos", F(5, 6)),
    ("cos(pi - pi/4)", "cos", F(3, 4)), ("cos((pi))", "cos", 1),
    ("cos(-(2*pi)/5)", "cos", F(-2, 5)), ("sin(2^3*pi/3^2)", "sin", F(8, 9)),
    ("cos(pi/(1/2))", "cos", 2), ("cos( pi / 12 )", "cos", F(1, 12)),
])
def test_trig_of_rational_multiples_of_pi(text, func, q):
    assert parse(text) == Trig(func, F(q))


def test_trig_in_expressions():
    assert parse("-cos(pi/5)") == Neg(Trig("cos", F(1, 5)))
    assert parse("2*sin(pi/9)^2") == BinOp("*", C(2), Pow(Trig("sin", F(1, 9)), 2))
    assert parse("sqrt(cos(pi/5))") == Sqrt(Trig("cos", F(1, 5)))


@pytest.mark.parametrize("text", [
    "cos(pi+1)", "cos(1)", "cos(60)", "sin(2/7)", "cos(pi*pi)", "cos(pi^2)", "cos(sqrt(pi))",
    "cos(sqrt(2)*pi)", "cos(1/pi)", "cos(pi-1)", "cos(2^pi)", "sin(cos(pi))", "cos(sin(pi)*pi)",
])
def test_trig_argument_must_be_a_rational_multiple_of_pi(text):
    err = error(text)
    assert "rational multiple of pi" in err.message or "exponent" in err.message


@pytest.mark.parametrize("text, turns", [
    ("cos(0)", 0), ("sin(0)", 0), ("cos(pi)", F(1, 2)), ("cos(2*pi/7)", F(1, 7)),
    ("cos(2pi/7)", F(1, 7)), ("cos(2 pi / 7)", F(1, 7)), ("sin(pi*2/7)", F(1, 7)),
    ("sin(2/7*pi)", F(1, 7)), ("cos(2π/7)", F(1, 7)), ("cos(1.5pi)", F(3, 4)),
    ("cos(-2pi/3)", F(-1, 3)), ("cos((2pi)/7)", F(1, 7)), ("cos(2*(pi/7))", F(1, 7)),
])
def test_every_spelling_of_a_rational_multiple_of_pi(text, turns):
    """Issue 12: the spellings a user tries for cos(2*pi/7) all give q*pi, q = 2*turns."""
    assert parse(text) == Trig(text[:3], 2 * F(turns))


def test_trig_error_offsets():
    assert error("cos(pi+1)").offset == 6      # the '+'
    assert error("cos(1)").offset == 4         # the argument
    assert "inside cos()" in error("cos(sin(pi))").message


@pytest.mark.parametrize("text, offset", [
    ("pi", 0), ("2*pi", 2), ("pi^2", 0), ("sqrt(pi)", 5), ("1 + pi/2", 4), ("(pi)", 1),
])
def test_pi_outside_trig_is_transcendental(text, offset):
    err = error(text)
    assert "transcendental" in err.message
    assert err.offset == offset


# ---------------------------------------------------------------- errors

@pytest.mark.parametrize("text, offset, words", [
    ("__import__('os')", 0, "unknown name '__import__'"),
    ("__import__('os').system('ls')", 0, "unknown name"),
    ("().__class__", 1, "expected"),
    ("x", 0, "unknown name 'x'"), ("os", 0, "unknown name 'os'"), ("1 + e", 4, "unknown name"),
    ("exp(1)", 0, "unknown name 'exp'"), ("Sqrt(2)", 0, "unknown name 'Sqrt'"),
    ("1.5.real", 3, "unexpected character '.'"), ("'1'", 0, "unexpected character"),
    ('"1"', 0, "unexpected character"), ("[1]", 0, "unexpected character '['"),
    ("{1}", 0, "unexpected character"), ("1,2", 1, "unexpected character ','"),
    ("sqrt(2,3)", 6, "','"), ("1;2", 1, "';'"), ("1 @ 2", 2, "'@'"), ("a.b", 0, "unknown name"),
    ("", 0, "empty expression"), ("   ", 0, "empty expression"), ("1 2", 2, "expected an operator"),
    ("2pi", 1, "pi is transcendental"), ("(1", 2, "missing ')'"), ("1)", 1, "unbalanced ')'"),
    ("()", 1, "expected"), ("1+", 2, "the end"), ("*1", 0, "expected"), ("1*/2", 2, "expected"),
    ("sqrt 2", 5, "expected '(' after sqrt"), ("sqrt", 4, "'(' after sqrt"),
    ("cos", 3, "'(' after cos"),
    ("2e", 1, "malformed decimal exponent"), ("1e+", 1, "malformed"), ("1.2.3", 3, "expected"),
    ("\x00", 0, "'\\x00'"), ("1\x00", 1, "unexpected character"), ("é", 0, "unexpected character"),
    ("\u00bd", 0, "unexpected character"), ("\uff11", 0, "unexpected character"),  # ½, １
    ("\u0661", 0, "unexpected character"), ("2\u00b2", 1, "unexpected character"),  # Arabic 1, ²
    ("1\u00a02", 1, "unexpected character"), ("\U0001F600", 0, "unexpected character"),
    ("π", 0, "pi is transcendental"), ("√2", 0, "unexpected character"),
    ("cos(2pi pi)", 8, "expected ')'"), ("sin(sqrt(2)pi)", 11, "expected ')'"),
    ("2^(1/2)", 3, "integer constant"), ("2^0.5", 2, "integer constant"),
    ("2^sqrt(4)", 2, "integer constant"), ("2^cos(pi)", 2, "integer constant"),
    ("sqrt(-2)", 0, "sqrt of a negative number"), ("sqrt(1-2)", 0, "negative"),
    ("1 + sqrt(-1/4)", 4, "negative"),
    ("1/0", 2, "division by zero"), ("1/(1-1)", 3, "division by zero"), ("sqrt(2)/0.0", 8, "zero"),
    ("0^-1", 0, "division by zero"), ("cos(pi/0)", 7, "division by zero"),
    ("2^1000000", 2, "exponent is too large"), ("2^-10001", 2, "exponent is too large"),
    ("2^2^2^2^2", 2, "exponent is too large"), ("sqrt(2)^99999", 8, "exponent is too large"),
    ("1e999999999", 1, "decimal exponent is too large"), ("1e-10001", 1, "decimal exponent"),
    ("1e" + "9" * 5000, 1, "decimal exponent"), ("9" * 5001, 0, "5001 digits"),
    ("0." + "0" * 5000, 0, "digits"),
])
def test_errors(text, offset, words):
    err = error(text)
    assert words in err.message
    assert err.offset == offset
    assert isinstance(err, InputError)


def test_limits_are_inclusive():
    assert parse("2^10000") == C(2 ** 10000)
    assert parse("2^-10000") == C(F(1, 2 ** 10000))
    assert parse("1e10000") == C(10 ** 10000)
    assert parse("1" * 5000) == C((10 ** 5000 - 1) // 9)
    assert parse("9" * 5000 + "e-10000") == C(F(10 ** 5000 - 1, 10 ** 10000))
    assert parse("0." + "0" * 4998 + "1") == C(F(1, 10 ** 4999))
    assert parse("(" * 100 + "7" + ")" * 100) == C(7)
    assert parse("1" + " " * (expr.MAX_LENGTH - 1)) == C(1)


def test_expression_length_limit():
    err = error("1+" * 10_000 + "1")            # 20,001 characters
    assert "too long" in err.message and err.offset == expr.MAX_LENGTH
    assert "too long" in error("1" + " " * expr.MAX_LENGTH).message


@pytest.mark.parametrize("text", [
    "(" * 10_000,
    "(" * 4_999 + "1" + ")" * 4_999,
    "sqrt(" * 101 + "1" + ")" * 101,
    "(" * 101 + "1" + ")" * 101,
    "cos(" + "(" * 100 + "pi" + ")" * 101,
])
def test_nesting_depth_limit_is_an_expression_error_not_recursion(text):
    err = error(text)
    assert "nests too deeply" in err.message
    assert err.offset == 100 or text.startswith(("sqrt", "cos"))


def test_long_flat_inputs_do_not_recurse():
    assert parse("-" * 9_999 + "1") == C(-1)
    assert parse("+".join(["1"] * 4_000)) == C(4_000)
    assert "too large" in error("2^" * 4_999 + "2").message
    assert parse("2^" * 3 + "2") == C(2 ** 16)


def test_large_constants_are_left_unfolded_rather_than_computed():
    # a product past MAX_FOLD_BITS stays a tree: the kernel decides what to do with it
    tree = parse("1e10000*1e10000*1e10000*1e10000")
    assert isinstance(tree, BinOp)
    assert parse("(2^10000)^10000") == Pow(C(2 ** 10000), 10000)


def test_the_parser_evaluates_no_python():
    for module in ("expr.py", "fileformat.py"):
        source = (Path(expr.__file__).parent / module).read_text()
        banned = re.findall(r"(?<![\w.])(?:eval|exec|compile|__import__)\(|sympify|parse_expr\b"
                            r"|literal_eval|import sympy", source)
        assert banned == [], module


# ---------------------------------------------------------------- properties

def _check_total(text: str) -> None:
    try:
        node = parse(text)
    except ExpressionError as err:
        assert 0 <= err.offset <= len(text)
    else:
        assert isinstance(node, Node)


@settings(max_examples=400, deadline=None)
@given(st.text())
def test_arbitrary_text_gives_a_tree_or_an_expression_error(text):
    _check_total(text)


@settings(max_examples=600, deadline=None)
@given(st.text(alphabet="0123456789.+-*/^()e sqrtcosinp,", max_size=40))
def test_grammar_alphabet_gives_a_tree_or_an_expression_error(text):
    _check_total(text)


_TOKENS = ["1", "2", "0", "7", "0.5", "1e-3", "+", "-", "*", "/", "^", "**", "(", ")",
           "sqrt(", "cos(", "sin(", "pi", " ", "3/7", "e", ","]


@settings(max_examples=600, deadline=None)
@given(st.lists(st.sampled_from(_TOKENS), max_size=30))
def test_grammar_tokens_give_a_tree_or_an_expression_error(tokens):
    _check_total("".join(tokens))


_rationals = st.fractions(max_denominator=50).filter(lambda q: abs(q.numerator) < 10 ** 6)


def _written(q: F) -> str:
    return f"({q.numerator}/{q.denominator})" if q.denominator != 1 else f"({q.numerator})"


_rational_trees = st.recursive(
    _rationals.map(lambda q: (_written(q), q)),
    lambda inner: st.one_of(
        st.tuples(inner, st.sampled_from("+-*"), inner).map(
            lambda t: (f"({t[0][0]}{t[1]}{t[2][0]})",
                       {"+": t[0][1] + t[2][1], "-": t[0][1] - t[2][1],
                        "*": t[0][1] * t[2][1]}[t[1]])),
        st.tuples(inner, inner).filter(lambda t: t[1][1] != 0).map(
            lambda t: (f"({t[0][0]}/{t[1][0]})", t[0][1] / t[1][1])),
        st.tuples(inner, st.integers(-3, 3)).filter(lambda t: t[0][1] != 0 or t[1] >= 0).map(
            lambda t: (f"({t[0][0]}^({t[1]}))", t[0][1] ** t[1])),
        inner.map(lambda t: (f"(-{t[0]})", -t[1])),
    ),
    max_leaves=8,
)


@settings(max_examples=200, deadline=None)
@given(_rational_trees)
def test_rational_expressions_fold_to_their_exact_value(written):
    text, value = written
    assert parse(text) == Const(value)


@settings(max_examples=200, deadline=None)
@given(_rationals, st.sampled_from(["cos", "sin"]),
       st.sampled_from(["{q}*pi", "pi*{q}", "({q})*pi", "{n}*pi/{d}", "pi*{n}/{d}", "pi/{d}*{n}"]))
def test_every_written_form_of_a_rational_multiple_of_pi(q, func, form):
    argument = form.format(q=_written(q), n=f"({q.numerator})", d=q.denominator)
    assert parse(f"{func}({argument})") == Trig(func, q)
