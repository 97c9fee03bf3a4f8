"""Exact real numbers: the rationals and real elements of one number field.

This module owns exactness for the whole project (the CGAL "kernel" of
``docs/architecture.md``): algorithms only use ``+ - * /``, ``**`` with an integer,
``== < <= > >=``, :func:`sign` and ``hash`` on the numbers it makes, never floats.

* Rationals are python-flint ``fmpq`` (about 9 times faster than ``Fraction``).
* Algebraic numbers are :class:`FieldElement`: a polynomial in a generator
  ``theta`` reduced modulo the minimal polynomial of ``theta``.  Because the
  representation is canonical, equality and hashing are exact and cheap.  The
  sign of a non-zero element is certified by ball arithmetic (Arb) at doubling
  precision until the ball excludes zero; zero itself never needs numerics.
  ``theta`` may be complex (a root of unity); the elements we build are real,
  so only the real part of the enclosure is used.
"""

from __future__ import annotations

from fractions import Fraction
from typing import Callable, Union

from flint import acb_poly, arb, arb_poly, ctx, fmpq, fmpq_poly, fmpz, fmpz_poly

from .cyclotomic_reduce import cyclotomic_arithmetic
from .inverse import inverse_mod, remainder_function

Rational = fmpq
Number = Union[fmpq, "FieldElement"]

_START_PRECISION = 64
_MAX_PRECISION = 1 << 22   # a sign that needs more bits than this means a bug upstream
#: degree from which products are reduced by Barrett's method over Z
_BARRETT_DEGREE = 512
#: products remembered per large cyclotomic field (NumberField.product_sum)
_PRODUCTS_LIMIT = 32
#: inverses remembered per field (PolyElement.inverse, the xgcd path)
_INVERSES_LIMIT = 256
_XGCD_BITS = 20_000        # fmpq_poly.xgcd is faster below this degree x coefficient bits,
                           # and in degree <= 32 whatever the coefficients


def as_fmpq(value) -> fmpq:
    """An exact rational from an ``int``, ``Fraction``, ``fmpz`` or ``fmpq``."""
    if isinstance(value, fmpq):
        return value
    if isinstance(value, (int, fmpz)):
        return fmpq(value)
    if isinstance(value, Fraction):
        return fmpq(value.numerator, value.denominator)
    raise TypeError(f"not an exact rational: {value!r}")


def sign(x) -> int:
    """-1, 0 or 1: the exact sign of a number of this module (or an ``int``)."""
    if isinstance(x, FieldElement):
        return x.sign()
    return (x > 0) - (x < 0)


class NumberField:
    """Q(theta) for an algebraic ``theta`` given by its minimal polynomial.

    ``enclose(prec)`` must return an ``acb`` (or ``arb``) ball containing theta
    with radius about ``2**-prec``.  ``name`` says how the field was built
    (``"Q(zeta_60)"``) and ``theta_text`` is an expression of theta in the
    configuration syntax, or ``None`` when theta is not real (a root of unity:
    then :meth:`FieldElement.text` writes the real part instead).
    """

    def __init__(self, minpoly: fmpq_poly, enclose: Callable[[int], object], name: str,
                 theta_text: str | None = None, conductor: int | None = None):
        lead = minpoly.coeffs()[-1]
        self.minpoly = minpoly / lead if lead != 1 else minpoly
        self.degree = self.minpoly.degree()
        self._enclose = enclose
        self._enclosures: dict[int, object] = {}
        self.name = name
        self.theta_text = theta_text
        self.conductor = conductor
        self._remainder = None       # x -> x mod minpoly over Z (Barrett), built when needed
        self._cyclotomic = False     # Phi_M arithmetic (.cyclotomic_reduce), None if not
        self._products: dict = {}    # see product_sum
        self._inverses: dict = {}    # see PolyElement.inverse

    def sqrt_of_integer(self, m: int) -> "PolyElement":
        """The positive square root of the squarefree integer ``m`` in this field; only a
        cyclotomic field holds one (:class:`.cyclotomic.CyclotomicField`)."""
        raise TypeError("elements of two different number fields do not mix")

    def arithmetic(self):
        """The :class:`CyclotomicArithmetic` of a large cyclotomic field, else None."""
        found = self._cyclotomic
        if found is False:
            found = None
            if self.conductor is not None and self.degree >= _BARRETT_DEGREE and \
                    self.minpoly.denom() == 1 and \
                    fmpz_poly(self.minpoly.numer()) == fmpz_poly.cyclotomic(self.conductor):
                found = cyclotomic_arithmetic(self.conductor)
            self._cyclotomic = found
        return found

    def reduce(self, poly: fmpq_poly) -> fmpq_poly:
        """``poly`` modulo the minimal polynomial (deg poly <= 2 degree - 2).  For a large
        monic integer minimal polynomial the numerator is reduced over Z (through
        Phi_r(x^s) for a cyclotomic field, see .cyclotomic_reduce; else by Barrett's
        method: two fast products, where FLINT's division is quadratic), then divided by
        the denominator: the same canonical polynomial."""
        if self.degree < _BARRETT_DEGREE or self.minpoly.denom() != 1:
            return poly % self.minpoly
        arithmetic = self.arithmetic()
        if arithmetic is not None:
            return fmpq_poly(arithmetic.remainder(poly.numer())) / poly.denom()
        if self._remainder is None:
            self._remainder = remainder_function(fmpz_poly(self.minpoly.numer()))
        return fmpq_poly(self._remainder(fmpz_poly(poly.numer()))) / poly.denom()

    def product_sum(self, terms) -> fmpq_poly:
        """``sum(sign * a.poly * b.poly)`` reduced, for ``terms`` ``(a, b)`` or
        ``(a, b, sign)`` of elements of this field (sign +-1): in a large cyclotomic field
        the products of subfield elements are made on deflated polynomials, and all are
        reduced once (.cyclotomic_reduce)."""
        arithmetic = self.arithmetic()
        if arithmetic is not None:
            # remembered by the operands' identities (the entry keeps them alive, so no
            # id is reused while cached): the paper layer, the audit and the truth
            # multiply the same coordinates again (a few percent of the products)
            key = tuple((id(t[0]), id(t[1])) + tuple(t[2:]) for t in terms)
            found = self._products.get(key)
            if found is not None and all(t[0] is u[0] and t[1] is u[1]
                                         for t, u in zip(terms, found[0])):
                return found[1]
            out = arithmetic.product_sum([
                (t[0]._prepared(arithmetic), t[1]._prepared(arithmetic)) + tuple(t[2:])
                for t in terms])
            if len(self._products) >= _PRODUCTS_LIMIT:
                self._products.clear()
            self._products[key] = (tuple(terms), out)
            return out
        total = None
        for t in terms:
            p = t[0].poly * t[1].poly
            if len(t) > 2 and t[2] < 0:
                p = -p
            total = p if total is None else total + p
        return self.reduce(total)

    def enclosure(self, prec: int):
        ball = self._enclosures.get(prec)
        if ball is None:
            ball = self._enclosures[prec] = self._enclose(prec)
        return ball

    def element(self, poly: fmpq_poly) -> "FieldElement":
        if poly.degree() >= self.degree:
            poly = poly % self.minpoly
        return PolyElement(self, poly)

    def __call__(self, value) -> "FieldElement":
        """Coerce a rational (or an element of this field) into the field."""
        if isinstance(value, PolyElement):
            if value.field is self:
                return value
            embed = _embedding(value.field, self)
            if embed is None:
                raise TypeError("elements of two different number fields do not mix")
            return PolyElement(self, embed(value.poly))
        if isinstance(value, FieldElement):
            return _from_multiquadratic(self, value)
        return PolyElement(self, fmpq_poly([as_fmpq(value)]))

    @property
    def gen(self) -> "FieldElement":
        return self.element(fmpq_poly([0, 1]))

    def real_ball(self, poly: fmpq_poly, prec: int, prepared=None):
        """A ball around the real number ``poly(theta)``, at working precision ``prec + 16``.
        ``prepared``: the element's .cyclotomic_reduce operand form (denominator, d,
        the numerator deflated by d): for d > 1 the deflation is evaluated at
        theta^d, a polynomial of degree / d (a subfield element costs half or less)."""
        with ctx.workprec(prec + 16):
            theta = self.enclosure(prec)
            if isinstance(theta, arb):
                return arb_poly(poly)(theta)
            if prepared is not None and prepared[1] > 1:
                den, d, q = prepared[:3]
                power = self._enclosures.get((prec, d))
                if power is None:
                    power = self._enclosures[(prec, d)] = theta ** d
                return acb_poly(q)(power).real / den
            return acb_poly(poly)(theta).real

    def sign_of(self, poly: fmpq_poly, prepared=None) -> int:
        """Certified sign of the real number ``poly(theta)`` (``poly`` not zero in the field;
        ``prepared`` as in :meth:`real_ball`)."""
        prec = _START_PRECISION
        while prec <= _MAX_PRECISION:
            with ctx.workprec(prec + 16):
                value = self.real_ball(poly, prec, prepared)
                if value > 0:
                    return 1
                if value < 0:
                    return -1
            prec *= 2
        raise ArithmeticError("sign undecided at the precision limit: a non-zero "
                              "element evaluated as zero (bug in the enclosure)")

    def __repr__(self) -> str:
        return f"NumberField({self.name}, degree {self.degree})"


class FieldElement:
    """An exact real algebraic number of the kernel: a :class:`PolyElement` (a polynomial in
    the generator of a :class:`NumberField`) or a multiquadratic element
    (:class:`exactsym.exact.multiquadratic.MQ`).  Both offer ``+ - * / **``, exact
    comparisons, ``sign()``, ``is_zero()``, ``is_rational()``, ``to_fmpq()`` and ``hash``
    (:class:`~.number.ExactNumber`); algorithms only
    ask ``isinstance(x, FieldElement)`` to tell them from ``fmpq``.  The order comparisons
    below read ``self._cmp(other)``: the sign of ``self - other``, or None for a foreign
    type (MQ writes its own)."""

    __slots__ = ()

    def is_zero(self) -> bool:
        """Whether the number is 0 (exactly; a kind with a cheaper test overrides it)."""
        return self.sign() == 0

    def __pow__(self, k: int):
        """Square and multiply; ``self._one()`` is the subclass's 1 (for ``k = 0``)."""
        if not isinstance(k, int):
            return NotImplemented
        if k < 0:
            return self.inverse() ** (-k)
        out, base = None, self
        while k:
            if k & 1:
                out = base if out is None else out * base
            k >>= 1
            if k:
                base = base * base
        return self._one() if out is None else out

    def __lt__(self, other):
        c = self._cmp(other)
        return NotImplemented if c is None else c < 0

    def __le__(self, other):
        c = self._cmp(other)
        return NotImplemented if c is None else c <= 0

    def __gt__(self, other):
        c = self._cmp(other)
        return NotImplemented if c is None else c > 0

    def __ge__(self, other):
        c = self._cmp(other)
        return NotImplemented if c is None else c >= 0


def _embedding(small: NumberField, large: NumberField):
    """The map of polynomials representing Q(zeta_a) in Q(zeta_b), a | b, or None."""
    a, b = small.conductor, large.conductor
    if a is None or b is None or b % a:
        return None
    step = b // a

    def embed(poly: fmpq_poly) -> fmpq_poly:
        coeffs = [fmpq(0)] * ((len(poly.coeffs()) - 1) * step + 1)
        for i, c in enumerate(poly.coeffs()):
            coeffs[i * step] = c
        return fmpq_poly(coeffs) % large.minpoly
    return embed


def _common(x, y):
    """``(x, y)`` written in one field: a cyclotomic field holds the elements of its
    cyclotomic subfields (a polar file's radii and its Cartesian coordinates, issue 9)."""
    if not isinstance(y, PolyElement):             # a multiquadratic element
        return x, _from_multiquadratic(x.field, y)
    if not isinstance(x, PolyElement):
        return _from_multiquadratic(y.field, x), y
    embed = _embedding(y.field, x.field)
    if embed is not None:
        return x, PolyElement(x.field, embed(y.poly))
    embed = _embedding(x.field, y.field)
    if embed is not None:
        return PolyElement(y.field, embed(x.poly)), y
    raise TypeError("elements of two different number fields do not mix")


def _from_multiquadratic(field: NumberField, x) -> "PolyElement":
    """A multiquadratic element written in a cyclotomic field holding its square roots."""
    total = field(0)
    for m, c in x.terms.items():
        total = total + c * (field.sqrt_of_integer(m) if m != 1 else field(1))
    return total


def _mixing(method):
    """Let a binary operation take an element of another field that one of the two
    fields contains (see :func:`_common`)."""
    def wrapper(self, other):
        if isinstance(other, FieldElement) and (not isinstance(other, PolyElement)
                                                or other.field is not self.field):
            self, other = _common(self, other)
        return method(self, other)
    wrapper.__name__ = method.__name__
    wrapper.__doc__ = method.__doc__
    return wrapper


class PolyElement(FieldElement):
    """A real number ``poly(theta)`` of a :class:`NumberField`, exact.

    Mixes with ``int`` and ``fmpq`` operands; two elements must share one field.
    """

    __slots__ = ("field", "poly", "_hash", "_sign", "_prep", "_ball")

    def __init__(self, field: NumberField, poly: fmpq_poly):
        self.field = field
        self.poly = poly
        self._hash = self._sign = self._prep = self._ball = None

    def _prepared(self, arithmetic):
        """The operand form of .cyclotomic_reduce (numerator, denominator, deflation),
        remembered: coordinates enter many products."""
        prep = self._prep
        if prep is None:
            prep = self._prep = arithmetic.prepared(self.poly)
        return prep

    # -- coercion -----------------------------------------------------------
    def _other(self, other):
        if isinstance(other, PolyElement):
            if other.field is not self.field:
                raise TypeError("elements of two different number fields do not mix")
            return other.poly
        if isinstance(other, (int, fmpq, fmpz)):
            return fmpq_poly([other])
        if isinstance(other, Fraction):
            return fmpq_poly([as_fmpq(other)])
        return None

    # -- arithmetic ----------------------------------------------------------
    @_mixing
    def __add__(self, other):
        o = self._other(other)
        return NotImplemented if o is None else PolyElement(self.field, self.poly + o)

    __radd__ = __add__

    @_mixing
    def __sub__(self, other):
        o = self._other(other)
        return NotImplemented if o is None else PolyElement(self.field, self.poly - o)

    @_mixing
    def __rsub__(self, other):
        o = self._other(other)
        return NotImplemented if o is None else PolyElement(self.field, o - self.poly)

    def __neg__(self):
        return PolyElement(self.field, -self.poly)

    def __pos__(self):
        return self

    @_mixing
    def __mul__(self, other):
        o = self._other(other)
        if o is None:
            return NotImplemented
        if o.degree() <= 0 or self.poly.degree() <= 0:
            return PolyElement(self.field, self.poly * o)
        if self.field.degree >= _BARRETT_DEGREE and isinstance(other, PolyElement):
            return PolyElement(self.field, self.field.product_sum([(self, other)]))
        return PolyElement(self.field, self.field.reduce(self.poly * o))

    __rmul__ = __mul__

    def inverse(self) -> "FieldElement":
        if self.poly.is_zero():
            raise ZeroDivisionError("division by zero")
        if self.poly.degree() == 0:
            return PolyElement(self.field, fmpq_poly([1 / self.poly.coeffs()[0]]))
        field = self.field
        if field.degree <= 32 or (field.degree < _BARRETT_DEGREE and
                                  field.degree * self.poly.numer().height_bits()
                                  <= _XGCD_BITS):
            # remembered per field by exact value: a gathering search's fresh Looks
            # divide by the same squared lengths of a K(alpha) snapshot in decision
            # after decision, and in Q(gamma) (.gathering.algebraic_kernel) one xgcd of
            # coefficients of 19,000 bits costs seconds
            key = (tuple(int(c) for c in self.poly.numer().coeffs()), int(self.poly.denom()))
            found = field._inverses.get(key)
            if found is None:
                g, s, _ = self.poly.xgcd(field.minpoly)
                found = s / g.coeffs()[0]
                if len(field._inverses) >= _INVERSES_LIMIT:
                    field._inverses.clear()
                field._inverses[key] = found
            return PolyElement(field, found)
        # large degree or coefficients: fmpq_poly.xgcd explodes (minutes); see .inverse
        arithmetic = self.field.arithmetic()
        return PolyElement(self.field, inverse_mod(
            self.poly, self.field.minpoly,
            arithmetic.remainder if arithmetic is not None else None))

    @_mixing
    def __truediv__(self, other):
        o = self._other(other)
        if o is None:
            return NotImplemented
        if o.degree() == 0:
            return PolyElement(self.field, self.poly / o.coeffs()[0])
        return self * PolyElement(self.field, o).inverse()

    @_mixing
    def __rtruediv__(self, other):
        o = self._other(other)
        return NotImplemented if o is None else PolyElement(self.field, o) * self.inverse()

    def _one(self):
        return PolyElement(self.field, fmpq_poly([1]))

    # -- exact comparison -----------------------------------------------------
    def is_rational(self) -> bool:
        return self.poly.degree() <= 0

    def is_zero(self) -> bool:
        return self.poly.is_zero()

    def text(self) -> str:
        """The configuration-syntax text: the real part's cosines for a cyclotomic field
        (rational ones in the constant), else a polynomial in the field's theta."""
        x = self
        if x.is_rational():
            return rational_text(x.to_fmpq())
        field = x.field
        coeffs = x.poly.coeffs()
        if field.conductor is not None:
            # x = sum c_k zeta^k is real, so x = sum c_k cos(2 pi k / M); the cosines that
            # are rational (k/M of denominator 1, 2, 3, 4 or 6) join the constant term
            m = field.conductor
            const, terms = fmpq(coeffs[0]), []
            for k, c in enumerate(coeffs):
                if not k or c == 0:
                    continue
                rational = _RATIONAL_COS.get(fmpq(k, m).q)
                if rational is not None:
                    const += c * rational
                else:
                    terms.append((c, f"cos({pi_multiple_text(fmpq(2 * k, m))})"))
            return sum_text([(const, "")] + terms)
        theta = f"({field.theta_text})"
        terms = [(coeffs[0], "")] + [(c, theta if k == 1 else f"{theta}^{k}")
                                    for k, c in enumerate(coeffs) if k and c != 0]
        return sum_text(terms)

    def to_fmpq(self) -> fmpq:
        """The value as ``fmpq``; raises ``ValueError`` when it is irrational."""
        if not self.is_rational():
            raise ValueError("not a rational number")
        return self.poly.coeffs()[0] if not self.poly.is_zero() else fmpq(0)

    def sign(self) -> int:
        if self.poly.is_zero():
            return 0
        if self.poly.degree() == 0:
            c = self.poly.coeffs()[0]
            return (c > 0) - (c < 0)
        s = self._sign           # remembered: in degree thousands a sign costs milliseconds
        if s is None:
            s = self._sign = self.field.sign_of(self.poly, self._ball_form())
        return s

    @_mixing
    def __eq__(self, other):
        o = self._other(other)
        return NotImplemented if o is None else self.poly == o

    @_mixing
    def __ne__(self, other):
        o = self._other(other)
        return NotImplemented if o is None else self.poly != o

    @_mixing
    def _cmp(self, other) -> int | None:
        o = self._other(other)
        if o is None:
            return None
        diff = self.poly - o
        if diff.is_zero():
            return 0
        return PolyElement(self.field, diff).sign()

    def __hash__(self):
        # remembered: in degree thousands the coefficient tuple hashes in milliseconds
        # (elements are never mutated: every operation makes a new one)
        # (the integer numerator's coefficients and the denominator: seven times faster
        # than hashing each fmpq, which python-flint does through a Fraction)
        h = self._hash
        if h is None:
            poly = self.poly
            h = self._hash = hash(self.to_fmpq()) if poly.degree() <= 0 else \
                hash((tuple(int(c) for c in poly.numer().coeffs()), int(poly.denom())))
        return h

    def __bool__(self):
        return not self.poly.is_zero()

    def enclosure(self, prec: int = 53):
        """An ``arb`` ball around the value (for drawing and float filters only); in a
        large field the last one is remembered (filters ask for one number's ball again)."""
        form = self._ball_form()
        if form is None:
            return self.field.real_ball(self.poly, prec)
        last = self._ball
        if last is not None and last[0] == prec:
            return last[1]
        ball = self.field.real_ball(self.poly, prec, form)
        self._ball = (prec, ball)
        return ball

    def _ball_form(self):
        """The deflated operand form where it pays (large cyclotomic fields), else None."""
        if self.poly.degree() < _BARRETT_DEGREE:
            return None
        arithmetic = self.field.arithmetic()
        return None if arithmetic is None else self._prepared(arithmetic)

    def __float__(self):  # display and float filters only: never decides anything
        return float(self.enclosure(53).mid())

    def __repr__(self):
        return f"PolyElement({self.poly} in {self.field.name})"


# -- texts in the configuration syntax (exact/text.py writes the other kinds) --------

def rational_text(q) -> str:
    q = as_fmpq(q)
    return str(q.p) if q.q == 1 else f"{q.p}/{q.q}"


#: cos(2 pi k/M) by the denominator of k/M, where it is rational
_RATIONAL_COS = {1: fmpq(1), 2: fmpq(-1), 3: fmpq(-1, 2), 4: fmpq(0), 6: fmpq(1, 2)}


def pi_multiple_text(q: fmpq) -> str:
    sign, p = ("-", -q.p) if q < 0 else ("", q.p)
    head = "pi" if p == 1 else f"{p}*pi"
    return sign + (head if q.q == 1 else f"{head}/{q.q}")


def sum_text(terms: list[tuple[fmpq, str]]) -> str:
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
