"""Numbers and lists as a person reads them (the text report; never ``--json``).

The exact text of a number is :func:`exactsym.exact.number_text` (the configuration
syntax: it parses back to the same number).  On top of it, for people:

* every irrational number gets a decimal beside it, ``sqrt(2) ≈ 1.41421``, read off the
  kernel's certified enclosure (an ``arb`` ball: the digits shown are the ball's, not a
  float's); rationals are shown exactly;
* a number whose exact text is long is shown by its decimal only, with the length of
  the exact text (which ``--json`` prints in full);
* long lists of robots are cut after a few entries, with the count;
* :func:`annotated` does the same to numbers inside prose written by other layers
  (the audit's and the paper's sentences), so that no irrational number reaches the
  screen without its decimal.

Decimals are for reading only: nothing decides anything on them.
"""

from __future__ import annotations

import re

from flint import arb, ctx, fmpq

from ..errors import ExpressionError
from . import FieldElement, evaluate, number_system, number_text
from ..io.expr import parse_expression

__all__ = ["DIGITS", "LONG", "approx", "is_irrational", "number", "square_root",
           "annotated", "listed"]

#: Significant digits of the decimals shown beside irrational numbers.
DIGITS = 6
#: An exact text longer than this is shown by its decimal only.
LONG = 40
#: Robots listed before "... (n in all)".
LISTED = 12


def is_irrational(x) -> bool:
    return isinstance(x, FieldElement) and not x.is_rational()


def _ball(x, sqrt: bool = False):
    """A ball around ``x`` (or its square root) narrow enough for :data:`DIGITS` digits."""
    prec = 64
    while True:
        with ctx.workprec(prec + 16):
            ball = x.enclosure(prec) if isinstance(x, FieldElement) else arb(fmpq(x))
            if sqrt:
                ball = ball.sqrt()
            if ball.rad() == 0 or prec >= 4096 or \
                    ball.rad() * 10 ** (DIGITS + 2) < abs(ball.mid()):
                return ball
        prec *= 4


def approx(x, sqrt: bool = False) -> str:
    """``x`` (or ``sqrt(x)``) to :data:`DIGITS` significant digits, from a certified
    enclosure.

    >>> approx(fmpq(1, 7)), approx(fmpq(2), sqrt=True)
    ('0.142857', '1.41421')
    """
    ball = _ball(x, sqrt)
    if ball.is_zero():
        return "0"
    return ball.str(DIGITS, radius=False)


def number(x) -> str:
    """The exact text of ``x`` with a decimal beside it when irrational; by its decimal
    only (and the length of the exact text) when the exact text is long.

    >>> number(fmpq(3, 7))
    '3/7'
    >>> number(fmpq(10**60, 7))
    '≈ 1.42857e+59 (exact: 63 characters, in --json)'
    >>> from exactsym.io.expr import parse_expression
    >>> node = parse_expression("sqrt(2)")
    >>> number(evaluate(node, number_system([node]))).endswith(" ≈ 1.41421")
    True
    """
    size = _huge_text(x)
    if size is not None:
        return f"≈ {approx(x)} (exact: about {size} characters, in --json)"
    text = number_text(x)
    if len(text) > LONG:
        return _long(text, approx(x))
    return f"{text} ≈ {approx(x)}" if is_irrational(x) else text


def _long(text: str, decimal: str) -> str:
    return f"≈ {decimal} (exact: {len(text)} characters, in --json)"


#: an exact text estimated longer than this is not written to be measured (a summary
#: shows a decimal; in a field of degree thousands a coordinate's text is megabytes)
HUGE = 100_000


def _huge_text(x) -> str | None:
    """The estimated length of ``number_text(x)`` in words ("4.8 million") when it is
    above :data:`HUGE`, else None (:func:`estimated_length`)."""
    size = estimated_length(x)
    return None if size is None else size_words(size)


def estimated_length(x) -> int | None:
    """The estimated length of ``number_text(x)`` when it is above :data:`HUGE`, else
    None: a polynomial element's digits are counted from its coefficients' bit lengths
    (0.30103 digits per bit, in integers, plus a dozen characters per term for its
    power), without writing the text."""
    poly = getattr(x, "poly", None)
    if poly is None or not hasattr(poly, "numer") or poly.degree() < 64:
        return None
    num = poly.numer()
    if (poly.degree() + 1) * (num.height_bits() * 30103 // 100_000 + 13) < HUGE:
        return None                     # cannot be that long: measure the text
    den_digits = poly.denom().bit_length() * 30103 // 100_000
    size = sum(c.bit_length() * 30103 // 100_000 + den_digits + 12 for c in num.coeffs() if c)
    return size if size >= HUGE else None


def size_words(size: int) -> str:
    """A length of at least :data:`HUGE` characters in words: "4.8 million", "120 thousand"."""
    if size >= 10 ** 6:
        tenths = (size + 50_000) // 100_000
        return f"{tenths // 10}.{tenths % 10} million"
    return f"{(size + 500) // 1000} thousand"


def huge_quotient(y, x) -> str | None:
    """``y/x`` (``x`` non-zero) for the screen when the exact text ``(y)/(x)`` is
    estimated above :data:`HUGE` characters: its decimal, from the balls of ``y`` and
    ``x`` (no division in the field: in a field of degree thousands one costs seconds),
    and the estimated length; None when the text is shorter (write it)."""
    sizes = [estimated_length(y), estimated_length(x)]
    if sizes == [None, None]:
        return None
    size = sum(s if s is not None else len(number_text(v)) for s, v in zip(sizes, (y, x))) + 5
    return f"≈ {quotient_decimal(y, x)} (exact: about {size_words(size)} characters, in --json)"


def quotient_decimal(y, x) -> str:
    """The decimal of ``y/x`` (``x`` non-zero) from their balls, without dividing."""
    with ctx.workprec(128):
        ball = _ball(y) / _ball(x)        # each to DIGITS + 2 digits: the quotient to DIGITS
    return "0" if ball.is_zero() else ball.str(DIGITS, radius=False)


def square_root(x) -> str:
    """The text of ``sqrt(x)`` for ``x >= 0`` exact: rational when ``x`` is a rational
    square, ``p*sqrt(m)/q`` for other rationals (square factors taken out while they are
    small), ``sqrt(...)`` otherwise; with its decimal when irrational.

    >>> square_root(fmpq(16)), square_root(fmpq(8)), square_root(fmpq(85, 9))
    ('4', '2*sqrt(2) ≈ 2.82843', 'sqrt(85)/3 ≈ 3.07318')
    """
    if isinstance(x, FieldElement) and x.is_rational():
        x = x.to_fmpq()
    if isinstance(x, FieldElement):
        size = _huge_text(x)
        if size is not None:
            return f"≈ {approx(x, sqrt=True)} (exact: sqrt of about {size} characters, in --json)"
        text = f"sqrt({number_text(x)})"
    else:
        q = fmpq(x)
        p, d = int(q.p), int(q.q)
        outside, inside = _square_part(p * d)
        if inside == 1:
            return number(fmpq(outside, d))
        scale = fmpq(outside, d)
        head = "" if scale == 1 else (f"{scale.p}*" if scale.p != 1 else "")
        tail = "" if scale.q == 1 else f"/{scale.q}"
        text = f"{head}sqrt({inside}){tail}"
    if len(text) > LONG:
        return _long(text, approx(x, sqrt=True))
    return f"{text} ≈ {approx(x, sqrt=True)}"


def _square_part(m: int, limit: int = 10_000) -> tuple[int, int]:
    """``(a, b)`` with ``m == a*a*b``, square factors below ``limit`` taken out."""
    from flint import fmpz
    root = fmpz(m).isqrt()
    if root * root == m:
        return int(root), 1
    a, f = 1, 2
    while f < limit and f * f <= m:
        while m % (f * f) == 0:
            m //= f * f
            a *= f
        f += 1
    return a, m


# ---------------------------------------------------------------- numbers in prose
_TOKEN = re.compile(r"(?P<num>[0-9]+(?:\.[0-9]+)?)|(?P<name>[A-Za-z_][A-Za-z0-9_]*)"
                    r"|(?P<op>\*\*|[-+*/^()])|(?P<space>[ \t]+)|(?P<other>.)", re.S)
_EXPRESSION_NAMES = {"sqrt", "cos", "sin", "pi"}
_IRRATIONAL_NAMES = {"sqrt", "cos", "sin"}


def annotated(text: str) -> str:
    """``text`` with a decimal after every irrational number written in it (in the
    configuration syntax, as :func:`number_text` writes them), and long numbers
    (rational or not) replaced by their decimal.  Text that does not parse as a number is left as it is.

    >>> annotated("a mirror at 1/8 turn, slope sqrt(2) - 1, through (sqrt(3)/2, 1/2)")
    'a mirror at 1/8 turn, slope sqrt(2) - 1 ≈ 0.414214, through (sqrt(3)/2 ≈ 0.866025, 1/2)'
    >>> annotated(f"ray (-1, {10**45}/7)")
    'ray (-1, ≈ 1.42857e+44 (exact: 48 characters, in --json))'
    """
    if not any(name in text for name in _IRRATIONAL_NAMES) and \
            not re.search(r"[0-9]{%d}" % (LONG // 2), text):
        return text
    tokens = [(m.lastgroup, m.group(), m.start()) for m in _TOKEN.finditer(text)]
    out, last, i = [], 0, 0
    while i < len(tokens):
        j = i
        while j < len(tokens) and _in_expression(tokens[j]):
            j += 1
        if j > i:
            span = _expression_span(tokens[i:j])
            if span is not None:
                start, end, replacement = span
                out.append(text[last:start])
                out.append(replacement)
                last = end
        i = j + 1 if j == i else j
    out.append(text[last:])
    return "".join(out)


def _in_expression(token) -> bool:
    kind, value, _ = token
    return kind in ("num", "op", "space") or (kind == "name" and value in _EXPRESSION_NAMES)


def _expression_span(run) -> tuple[int, int, str] | None:
    """The part of a run of expression tokens that is an irrational number: (start,
    end, text shown); None when there is none."""
    irrational = any(kind == "name" and value in _IRRATIONAL_NAMES for kind, value, _ in run)
    if not irrational and sum(len(value) for kind, value, _ in run if kind == "num") <= LONG:
        return None
    start = run[0][2]
    source = "".join(value for _, value, _ in run)
    # drop what surrounds the number in prose: spaces, an unmatched '(' or ')'
    lo, hi = 0, len(source)
    while True:
        piece = source[lo:hi]
        stripped = piece.strip()
        if stripped != piece:
            lo += len(piece) - len(piece.lstrip())
            hi -= len(piece) - len(piece.rstrip())
            continue
        if piece.count("(") > piece.count(")") and piece.startswith("("):
            lo += 1
            continue
        if piece.count(")") > piece.count("(") and piece.endswith(")"):
            hi -= 1
            continue
        break
    piece = source[lo:hi]
    try:
        node = parse_expression(piece, written=True)   # exactsym wrote it: no input limits
        value = evaluate(node, number_system([node]))
    except (ExpressionError, ArithmeticError, ValueError):
        return None
    if len(piece) > LONG:
        return start + lo, start + hi, _long(piece, approx(value))
    if not is_irrational(value):
        return None
    shown = f"{piece} ≈ {approx(value)}"
    return start + lo, start + hi, shown


def listed(indices, limit: int = LISTED) -> str:
    """The robots ``indices``, cut after ``limit`` of them.

    >>> listed([6, 7, 8])
    '6, 7, 8'
    >>> listed(range(100_000))
    '0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, ... (100,000 in all)'
    """
    indices = list(indices)
    if len(indices) <= limit:
        return ", ".join(map(str, indices))
    return ", ".join(map(str, indices[:limit])) + f", ... ({len(indices):,} in all)"
