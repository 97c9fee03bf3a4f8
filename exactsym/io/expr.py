"""Tokenizer and recursive-descent parser for the expressions of configuration
format 1 (``docs/format.md``).

Grammar, loosest binding first::

    expression := term (('+' | '-') term)*
    term       := unary (('*' | '/') unary)*
    unary      := ('+' | '-')* power               # so -2^2 is -(2^2) = -4
    power      := primary [('^' | '**') unary]     # right associative: 2^3^2 = 2^9
    primary    := number | '(' expression ')' | 'sqrt' '(' expression ')'
                | ('cos' | 'sin') '(' expression ')'    # a rational multiple of pi
    number     := digits ['.' [digits]] | '.' digits, then optionally ('e' | 'E') ['+' | '-'] digits

Exponents must fold to an integer constant.  ``pi`` (or ``π``) is allowed only inside
the argument of ``cos``/``sin``, which must fold to ``q*pi`` with q rational or be 0;
there a number written just before pi multiplies it (``cos(2pi/7)``).
Rational constant subexpressions are folded into :class:`~exactsym.io.exprtree.Const`
(while their size stays small); ``sqrt`` is never evaluated here.

Nothing here evaluates Python code, and every input either gives a tree or
raises :class:`~exactsym.errors.ExpressionError`: the limits below keep time,
memory and recursion bounded.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from fractions import Fraction
from typing import NamedTuple

from ..errors import ExpressionError
from .exprtree import BinOp, Const, Neg, Node, Pow, Sqrt, Trig

MAX_LENGTH = 10_000            # characters in one expression
MAX_DEPTH = 100                # nested parentheses and function calls
MAX_EXPONENT = 10_000          # |k| in base^k
MAX_DECIMAL_EXPONENT = 10_000  # |k| in 1.5e<k>
MAX_DIGITS = 5_000             # digits in one number literal
MAX_FOLD_BITS = 100_000        # constants are folded only while they stay this small

FUNCTIONS = ("sqrt", "cos", "sin")
_PI = ("pi", "π")

_NUMBER = re.compile(r"(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)(?:([eE])([+-]?)([0-9]+))?")
_NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
_SPACE = " \t\r\n\f\v"


class Token(NamedTuple):
    """One token: ``kind`` is ``"number"``, ``"name"``, ``"op"`` (``+ - * / ^ ** ( )``),
    ``"bad"`` (any other single character, a comma included) or ``"end"``.
    ``offset`` is 0-based in the text; ``value`` is the exact value of a number."""
    kind: str
    text: str
    offset: int
    value: Fraction | None = None

    @property
    def end(self) -> int:
        return self.offset + len(self.text)


def tokenize(text: str, max_digits: int | None = MAX_DIGITS) -> list[Token]:
    """Return the tokens of ``text``, always ending with an ``"end"`` token.

    Unknown characters become ``"bad"`` tokens (the parser rejects them where it
    meets them).  Raises :class:`ExpressionError` for a malformed number literal, or one
    of more than ``max_digits`` digits (None: any).
    """
    tokens: list[Token] = []
    i, n = 0, len(text)
    while i < n:
        ch = text[i]
        if ch in _SPACE:
            i += 1
        elif ch.isascii() and (ch.isdigit() or (ch == "." and i + 1 < n and text[i + 1].isdigit()
                                               and text[i + 1].isascii())):
            match = _NUMBER.match(text, i)
            tokens.append(Token("number", match.group(), i,
                                _number_value(match, i, max_digits)))
            i = match.end()
            if i < n and text[i] in "eE":
                raise ExpressionError("malformed decimal exponent (write e.g. 1e-3)", offset=i)
        elif ch.isascii() and (ch.isalpha() or ch == "_"):
            match = _NAME.match(text, i)
            tokens.append(Token("name", match.group(), i))
            i = match.end()
        elif ch == "π":                 # the letter a user may paste: the name pi
            tokens.append(Token("name", ch, i))
            i += 1
        elif text.startswith("**", i):
            tokens.append(Token("op", "**", i))
            i += 2
        elif ch in "+-*/^()":
            tokens.append(Token("op", ch, i))
            i += 1
        else:
            tokens.append(Token("bad", ch, i))
            i += 1
    tokens.append(Token("end", "", n))
    return tokens


def _number_value(match: re.Match, offset: int, max_digits: int | None) -> Fraction:
    """Return the exact value of a number literal; raise ExpressionError past the limits."""
    mantissa = match.group().split("e")[0].split("E")[0]
    whole, _, frac = mantissa.partition(".")
    if max_digits is not None and len(whole) + len(frac) > max_digits:
        raise ExpressionError(f"number has {len(whole) + len(frac)} digits "
                              f"(at most {max_digits})", offset=offset)
    exponent = 0
    if match.group(1):
        digits = match.group(3).lstrip("0") or "0"
        if len(digits) > 6 or int(digits) > MAX_DECIMAL_EXPONENT:
            raise ExpressionError(f"decimal exponent is too large (at most "
                                  f"{MAX_DECIMAL_EXPONENT} in absolute value)",
                                  offset=match.start(1))
        exponent = -int(digits) if match.group(2) == "-" else int(digits)
    exponent -= len(frac)
    value = _int_from_digits(whole + frac)
    return Fraction(value * 10 ** exponent) if exponent >= 0 else Fraction(value, 10 ** -exponent)


def _int_from_digits(digits: str) -> int:
    """``int(digits)`` in chunks, below Python's limit on int-from-string conversion."""
    value = 0
    for start in range(0, len(digits), 1000):
        chunk = digits[start:start + 1000]
        value = value * 10 ** len(chunk) + int(chunk)
    return value


@dataclass(frozen=True)
class _PiMultiple(Node):
    """``coefficient * pi`` while parsing the argument of cos/sin; never returned."""
    coefficient: Fraction


def _bits(q: Fraction) -> int:
    return max(q.numerator.bit_length(), q.denominator.bit_length())


def _show(token: Token) -> str:
    if token.kind == "end":
        return "the end"
    if token.kind == "bad":
        return f"character {token.text!r}"
    text = token.text if len(token.text) <= 20 else token.text[:17] + "..."
    return f"'{text}'"


class _Parser:
    """One parse of one expression string; see :func:`parse_expression`."""

    def __init__(self, text: str, max_digits: int | None = MAX_DIGITS):
        self.tokens = tokenize(text, max_digits)
        self.pos = 0
        self.depth = 0                  # open parentheses and function calls
        self.trig: str | None = None    # "cos"/"sin" while parsing its argument

    # -- token helpers
    def peek(self) -> Token:
        return self.tokens[self.pos]

    def advance(self) -> Token:
        token = self.tokens[self.pos]
        self.pos += 1
        return token

    def at_op(self, *ops: str) -> bool:
        token = self.peek()
        return token.kind == "op" and token.text in ops

    def open_paren(self, what: str) -> Token:
        token = self.peek()
        if not self.at_op("("):
            raise ExpressionError(f"expected '(' after {what}, found {_show(token)}",
                                  offset=token.offset)
        self.depth += 1
        if self.depth > MAX_DEPTH:
            raise ExpressionError(f"expression nests too deeply (at most {MAX_DEPTH} levels "
                                  "of parentheses and function calls)", offset=token.offset)
        return self.advance()

    def close_paren(self, opening: Token) -> None:
        token = self.peek()
        if not self.at_op(")"):
            if token.kind == "end":
                raise ExpressionError(f"missing ')' to close the '(' at offset {opening.offset}",
                                      offset=token.offset)
            raise ExpressionError(f"expected ')' or an operator, found {_show(token)}",
                                  offset=token.offset)
        self.depth -= 1
        self.advance()

    # -- grammar
    def expression(self) -> Node:
        node = self.term()
        while self.at_op("+", "-"):
            op = self.advance()
            node = self.binop(op, node, self.term())
        return node

    def term(self) -> Node:
        node = self.unary()
        while self.at_op("*", "/"):
            op = self.advance()
            node = self.binop(op, node, self.unary())
        return node

    def signs(self) -> tuple[bool, int]:
        """Consume unary signs; return (odd number of minus signs, offset of the first)."""
        negative, offset = False, self.peek().offset
        while self.at_op("+", "-"):
            negative ^= self.advance().text == "-"
        return negative, offset

    def unary(self) -> Node:
        negative, offset = self.signs()
        node = self.power()
        return self.negate(node, offset) if negative else node

    def power(self) -> Node:
        # Iterative (not recursive) so that long chains like 2^2^2^... cannot
        # exhaust the Python stack: collect "^ signs primary" links, fold from the right.
        base = self.primary()
        links = []
        while self.at_op("^", "**"):
            self.advance()
            negative, offset = self.signs()
            links.append((negative, offset, self.primary()))
        exponent = None
        for negative, offset, operand in reversed(links):
            node = operand if exponent is None else self.pow(operand, exponent)
            exponent = self.negate(node, offset) if negative else node
        return base if exponent is None else self.pow(base, exponent)

    def primary(self) -> Node:
        token = self.peek()
        if token.kind == "number":
            self.advance()
            following = self.peek()
            if following.kind == "name" and following.text in _PI:
                if self.trig is None:
                    self.name()         # outside cos()/sin(): pi's own message
                self.advance()          # "2pi" inside cos()/sin(): 2*pi, as it is written
                return _PiMultiple(token.value, offset=token.offset)
            return Const(token.value, offset=token.offset)
        if token.kind == "op" and token.text == "(":
            opening = self.open_paren("")
            node = self.expression()
            self.close_paren(opening)
            return node
        if token.kind == "name":
            return self.name()
        if token.kind == "bad":
            raise ExpressionError(f"unexpected character {token.text!r}", offset=token.offset)
        raise ExpressionError(f"expected a number, '(' or a function, found {_show(token)}",
                              offset=token.offset)

    def name(self) -> Node:
        token = self.advance()
        if token.text in _PI:
            if self.trig is None:
                raise ExpressionError("pi is transcendental: it may appear only as a rational "
                                      "multiple inside cos() or sin(), as in cos(2*pi/7)",
                                      offset=token.offset)
            return _PiMultiple(Fraction(1), offset=token.offset)
        if token.text not in FUNCTIONS:
            raise ExpressionError(f"unknown name {token.text!r} (the only names are "
                                  "sqrt, cos, sin and pi)", offset=token.offset)
        if token.text != "sqrt" and self.trig is not None:
            raise ExpressionError(f"{token.text}() inside {self.trig}(): the argument of "
                                  f"{self.trig}() must be a rational multiple of pi",
                                  offset=token.offset)
        opening = self.open_paren(token.text)
        outer, self.trig = self.trig, (self.trig if token.text == "sqrt" else token.text)
        argument = self.expression()
        self.close_paren(opening)
        self.trig = outer
        if token.text == "sqrt":
            return self.sqrt(argument, token.offset)
        if isinstance(argument, Const) and argument.value == 0:
            argument = _PiMultiple(Fraction(0), offset=argument.offset)     # cos(0) = cos(0*pi)
        if not isinstance(argument, _PiMultiple):
            raise self.not_pi_multiple(argument.offset, token.text)
        return Trig(token.text, argument.coefficient, offset=token.offset)

    # -- building nodes (with folding of rational constants)
    def not_pi_multiple(self, offset: int, func: str | None = None) -> ExpressionError:
        func = func or self.trig
        return ExpressionError(f"the argument of {func}() must be a rational multiple of pi, "
                               "such as 2*pi/7, 2pi/7 or -pi/3 (radians: 60 degrees is pi/3)",
                               offset=offset)

    def negate(self, node: Node, offset: int) -> Node:
        if isinstance(node, Const):
            return Const(-node.value, offset=offset)
        if isinstance(node, _PiMultiple):
            return _PiMultiple(-node.coefficient, offset=offset)
        return Neg(node, offset=offset)

    def binop(self, op: Token, left: Node, right: Node) -> Node:
        if op.text == "/" and isinstance(right, Const) and right.value == 0:
            raise ExpressionError("division by zero", offset=right.offset)
        if isinstance(left, _PiMultiple) or isinstance(right, _PiMultiple):
            return self.pi_binop(op, left, right)
        if isinstance(left, Const) and isinstance(right, Const) \
                and _bits(left.value) + _bits(right.value) <= MAX_FOLD_BITS:
            x, y = left.value, right.value
            value = {"+": x + y, "-": x - y, "*": x * y}[op.text] if op.text != "/" else x / y
            return Const(value, offset=left.offset)
        return BinOp(op.text, left, right, offset=left.offset)

    def pi_binop(self, op: Token, left: Node, right: Node) -> Node:
        """Fold q1*pi +- q2*pi, q*pi * r, r * q*pi, q*pi / r; anything else is an error."""
        pl, pr = isinstance(left, _PiMultiple), isinstance(right, _PiMultiple)
        cl, cr = isinstance(left, Const), isinstance(right, Const)
        if op.text in "+-" and pl and pr:
            sign = 1 if op.text == "+" else -1
            coefficient = left.coefficient + sign * right.coefficient
        elif op.text == "*" and pl and cr:
            coefficient = left.coefficient * right.value
        elif op.text == "*" and cl and pr:
            coefficient = left.value * right.coefficient
        elif op.text == "/" and pl and cr:
            coefficient = left.coefficient / right.value
        else:
            raise self.not_pi_multiple(op.offset)
        if _bits(coefficient) > MAX_FOLD_BITS:
            raise ExpressionError("the multiple of pi is too large", offset=op.offset)
        return _PiMultiple(coefficient, offset=left.offset)

    def pow(self, base: Node, exponent: Node) -> Node:
        if not (isinstance(exponent, Const) and exponent.value.denominator == 1):
            raise ExpressionError("the exponent must be an integer constant",
                                  offset=exponent.offset)
        k = exponent.value.numerator
        if abs(k) > MAX_EXPONENT:
            raise ExpressionError(f"exponent is too large (at most {MAX_EXPONENT} in absolute "
                                  "value)", offset=exponent.offset)
        if isinstance(base, _PiMultiple):
            raise self.not_pi_multiple(base.offset)
        if isinstance(base, Const):
            if base.value == 0 and k < 0:
                raise ExpressionError("division by zero (zero to a negative power)",
                                      offset=base.offset)
            if _bits(base.value) * abs(k) <= MAX_FOLD_BITS:
                return Const(base.value ** k, offset=base.offset)
        return Pow(base, k, offset=base.offset)

    def sqrt(self, argument: Node, offset: int) -> Node:
        if isinstance(argument, _PiMultiple):
            raise self.not_pi_multiple(argument.offset)
        if isinstance(argument, Const) and argument.value < 0:
            raise ExpressionError("sqrt of a negative number", offset=offset)
        return Sqrt(argument, offset=offset)


_SIMPLE_RATIONAL = re.compile(r"([+-]?[0-9]{1,1000})(?:/([0-9]{1,1000}))?")


def parse_expression(text: str, written: bool = False) -> Node:
    """Parse one expression string of configuration format 1.

    Returns the expression tree (:mod:`exactsym.io.exprtree`), with rational
    constant subexpressions folded into ``Const``.  Raises
    :class:`ExpressionError` whose ``offset`` is the 0-based position in
    ``text`` of the offending character, for anything malformed or beyond the
    limits (``MAX_LENGTH``, ``MAX_DEPTH``, ``MAX_EXPONENT``,
    ``MAX_DECIMAL_EXPONENT``, ``MAX_DIGITS``).

    ``written=True`` reads a number exactsym wrote (a report, ``--json``): the length
    and digit limits, which bound configuration input, do not apply -- an exact number
    of a large field can be written in more than 10,000 characters, and it reads back
    to itself; the other limits do.
    """
    if not written and len(text) > MAX_LENGTH:
        raise ExpressionError(f"expression is too long ({len(text)} characters, at most "
                              f"{MAX_LENGTH})", offset=MAX_LENGTH)
    simple = _SIMPLE_RATIONAL.fullmatch(text)
    if simple and int(simple.group(2) or 1) != 0:   # fast path: most inputs are "p" or "p/q"
        return Const(Fraction(int(simple.group(1)), int(simple.group(2) or 1)), offset=0)
    parser = _Parser(text, None if written else MAX_DIGITS)
    if parser.peek().kind == "end":
        raise ExpressionError("empty expression", offset=0)
    node = parser.expression()
    token = parser.peek()
    if token.kind != "end":
        if token.kind == "bad":
            raise ExpressionError(f"unexpected character {token.text!r}", offset=token.offset)
        if token.kind == "op" and token.text == ")":
            raise ExpressionError("unbalanced ')'", offset=token.offset)
        raise ExpressionError(f"expected an operator or the end, found {_show(token)}",
                              offset=token.offset)
    assert not isinstance(node, _PiMultiple)
    return node
