"""The exact number kernel: one module decides how every number is held.

The declared interface is :mod:`.number` (:class:`~.number.ExactNumber`,
:class:`~.number.NumberSystem` and the questions asked of any number).

Public names: :func:`sign`, :class:`FieldElement`, :class:`NumberField`,
:func:`number_system`, :func:`evaluate`, :func:`evaluate_all`, :func:`number_text`,
``fmpq`` (the rationals).
"""

from flint import fmpq

from .evaluate import (FieldSystem, RationalSystem, evaluate, evaluate_all, normal_turn,
                       number_system, rational_cos_turn, rational_sqrt)
from .field import FieldElement, NumberField, as_fmpq, sign
from .number import ExactNumber, NumberSystem
from .ordering import exact_key, exact_sorted
from .text import expression_text, number_text, rational_text

__all__ = ["fmpq", "sign", "FieldElement", "NumberField", "ExactNumber", "NumberSystem", "FieldSystem", "RationalSystem",
           "number_system", "evaluate", "evaluate_all", "number_text", "rational_text",
           "expression_text", "as_fmpq", "exact_key", "exact_sorted", "normal_turn", "rational_cos_turn", "rational_sqrt"]
