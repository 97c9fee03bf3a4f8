"""The report writes the SEC's and the levels' numbers with fast_number_text: the same
strings as number_text, also when a coefficient has more digits than Python's int-string
limit (4,300: a pentagon moved by 10^-1000 has a squared radius with such coefficients)."""

from __future__ import annotations

from flint import fmpq

from exactsym.exact.cyclotomic import cos_turn, cyclotomic_field
from exactsym.exact.cyclotomic_text import fast_number_text
from exactsym.exact.text import number_text


def test_huge_coefficients_are_written_as_number_text_writes_them():
    field = cyclotomic_field(5)
    c = cos_turn(field, fmpq(1, 5))
    for e in (10, 1000, 5000):
        x = (1 + fmpq(1, 10 ** e)) * c + fmpq(3, 7) + c * c * fmpq(10 ** e + 1, 3)
        assert fast_number_text(x) == number_text(x)


from hypothesis import given, settings, strategies as st  # noqa: E402
from flint import fmpq_poly  # noqa: E402

from exactsym.exact.cyclotomic_text import cyclotomic_text  # noqa: E402


@settings(max_examples=60, deadline=None)
@given(st.sampled_from([5, 12, 60, 2520]), st.data())
def test_integer_coefficients_are_written_as_number_text_writes_them(m, data):
    """The integer-coefficient branch of cyclotomic_text (no gcd): coefficients 0, +-1 and
    others, and a constant whose rational cosines' parts add up to a half."""
    field = cyclotomic_field(m)
    coeffs = data.draw(st.lists(st.sampled_from([0, 1, -1, 2, -3, 10 ** 20]),
                                min_size=2, max_size=field.degree))
    x = field.element(fmpq_poly(coeffs))
    if not x.is_rational():
        assert cyclotomic_text(x) == number_text(x)
    assert fast_number_text(x) == number_text(x)
