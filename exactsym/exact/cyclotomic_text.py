"""The text of an element of Q(zeta_M), written fast: the same string as
:func:`exactsym.exact.text.number_text`, from integer coefficients.

``number_text`` walks the element's ``fmpq`` coefficients (5,760 of them in Q(zeta_27720))
and builds each term's ``cos(k*pi/M)`` anew: 60 ms per number, and the paper layer prints
hundreds of lines of symmetry whose slopes are such numbers (issue 9).  Here the numerator's
integer coefficients and the one denominator are read once (a rational coefficient is
``n_k / den`` reduced by one integer gcd), and each field's term texts are made once.
Exact: integer arithmetic only; :func:`fast_number_text` falls back to ``number_text`` for
every other number, and a property test compares the two.
"""

from __future__ import annotations

from math import gcd

from flint import fmpz

from .field import PolyElement
from .text import number_text

#: cos(2 pi k/M) by the denominator of k/M, where it is rational (as text.py's table):
#: the value as (numerator, denominator)
_RATIONAL_COS = {1: (1, 1), 2: (-1, 1), 3: (-1, 2), 4: (0, 1), 6: (1, 2)}

_TERMS: dict = {}        # (conductor, degree) -> list: the text of cos(2 pi k/M), or the
                         # rational value (p, q) of that cosine


def _terms(m: int, degree: int) -> list:
    found = _TERMS.get((m, degree))
    if found is not None:
        return found
    out = [None] * degree
    for k in range(1, degree):
        g = gcd(k, m)
        rational = _RATIONAL_COS.get(m // g)
        if rational is not None:
            out[k] = rational
            continue
        g2 = gcd(2 * k, m)
        p, q = 2 * k // g2, m // g2
        head = "pi" if p == 1 else f"{p}*pi"
        out[k] = f"cos({head if q == 1 else f'{head}/{q}'})"
    if len(_TERMS) > 8:
        _TERMS.clear()
    _TERMS[(m, degree)] = out
    return out


def cyclotomic_text(x: PolyElement) -> str:
    """``number_text(x)`` for an irrational element of a cyclotomic field (conductor set)."""
    field = x.field
    m = field.conductor
    # fmpz, not int: FLINT writes a 4,000-bit integer in decimal four times faster than
    # Python, and has no 4,300-digit limit
    den = x.poly.denom()
    coeffs = x.poly.numer().coeffs()
    terms = _terms(m, field.degree)
    # the constant: c_0 plus the rational cosines' contributions, over den * 2
    const2 = 2 * coeffs[0]
    out = []                    # " + |term|" or " - |term|" in the order of the powers
    append = out.append
    if den == 1:                # integer coefficients: no gcd (the common case of slopes)
        for k in range(1, len(coeffs)):
            c = coeffs[k]
            if not c:
                continue
            term = terms[k]
            if type(term) is tuple:
                const2 += 2 * c * term[0] // term[1]
            elif c > 0:
                append(f" + {term}" if c == 1 else f" + {c}*{term}")
            else:
                append(f" - {term}" if c == -1 else f" - {-c}*{term}")
    else:                       # |c/den| reduced, as text.py's sum_text writes it (inline:
        for k in range(1, len(coeffs)):     # the loop runs once per coefficient)
            c = coeffs[k]
            if not c:
                continue
            term = terms[k]
            if type(term) is tuple:
                const2 += 2 * c * term[0] // term[1]
                continue
            g = c.gcd(den)
            if c < 0:
                p, sep = -c // g, " - "
            else:
                p, sep = c // g, " + "
            q = den // g
            if q == 1:
                append(f"{sep}{term}" if p == 1 else f"{sep}{p}*{term}")
            elif p == 1:
                append(f"{sep}{term}/{q}")
            else:
                append(f"{sep}{p}*{term}/{q}")
    head = ""
    if const2:
        g = fmpz(const2).gcd(2 * den)
        p, q = const2 // g, 2 * den // g
        head = ("-" if p < 0 else "") + (str(abs(p)) if q == 1 else f"{abs(p)}/{q}")
    elif out:                   # the first term carries its sign alone: "-t", "t"
        first = out[0]
        out[0] = ("-" if first[1] == "-" else "") + first[3:]
    else:
        return "0"
    return head + "".join(out)


def fast_number_text(x) -> str:
    """:func:`exactsym.exact.text.number_text`, by :func:`cyclotomic_text` where it applies."""
    if isinstance(x, PolyElement) and x.field.conductor is not None and not x.is_rational():
        return cyclotomic_text(x)
    return number_text(x)


__all__ = ["cyclotomic_text", "fast_number_text"]
