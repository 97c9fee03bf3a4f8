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
