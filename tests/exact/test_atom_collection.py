"""The atoms of an expression (exactsym.exact.evaluate._collect, which picks the number
system) are read by a fold over the one expression walker, io/exprtree.fold: on random
expressions with square roots of negatives, divisions by zero, huge powers, nested and
plain radicals and rational and irrational cosines, it finds the atoms the former
recursive walk found (tests/reference/atom_walk.py), in the same order, and raises the
same first error at the same offset."""

from __future__ import annotations

from hypothesis import given, settings, strategies as st

from exactsym.errors import ExpressionError
from exactsym.exact.evaluate import _collect
from exactsym.io.expr import parse_expression
from reference.atom_walk import collect as recursive_collect


def _texts():
    # cosines with rational values (-1, 0, 1/2, 1): the parser folds constants, so its
    # own errors (1/0, sqrt(-2)) would hide the walk's
    leaves = st.one_of(
        st.sampled_from(["2", "1/2", "9/4", "cos(pi)", "cos(pi/2)", "cos(pi/3)", "sin(pi/2)",
                         "3*cos(pi)", "4*cos(pi/3)", "sqrt(2)"]),
        st.builds(lambda f, k, m: f"{f}({k}*pi/{m})", st.sampled_from(["cos", "sin"]),
                  st.integers(-3, 7), st.sampled_from([1, 2, 3, 4, 5, 6, 12, 13])))

    def extend(inner):
        return st.one_of(
            st.builds(lambda a: f"sqrt({a})", inner),
            st.builds(lambda a: f"-({a})", inner),
            st.builds(lambda a, k: f"({a})^{k}", inner, st.sampled_from([-2, -1, 0, 2, 3])),
            st.builds(lambda a: f"(({a})^4000)^4000", inner),
            st.builds(lambda a, op, b: f"({a}) {op} ({b})", inner,
                      st.sampled_from(["+", "-", "*", "/"]), inner))
    return st.recursive(leaves, extend, max_leaves=8)


def _outcome(walk, text):
    atoms: list = []
    try:
        walk(parse_expression(text), atoms)
    except ExpressionError as err:
        return "error", str(err), err.offset
    # a nested radical's node: compared by where it starts
    return "atoms", [(kind, rest[0].offset) if kind == "nested" else (kind, *rest)
                     for kind, *rest in atoms]


@settings(max_examples=400, deadline=None)
@given(_texts())
def test_the_fold_finds_what_the_recursive_walk_found(text):
    assert _outcome(_collect, text) == _outcome(recursive_collect, text), text


def test_the_first_error_inside_a_radicand_is_the_one_reading_it_meets():
    # (cos(pi) = -1 and cos(pi/2) = 0: the parser folds constants, not cosines)
    # the radicand's reading in Q meets 1/0 before the inner square root of -2
    for walk in (_collect, recursive_collect):
        assert _outcome(walk, "sqrt(1/cos(pi/2) + sqrt(2*cos(pi)))") == \
            ("error", "division by zero", 5)
        # an irrational atom first: a nested radical, whose own square root of -2 is the error
        assert _outcome(walk, "sqrt(sqrt(2) + sqrt(2*cos(pi)))") == \
            ("error", "square root of a negative number", 15)
        # outside a square root nothing is read in Q: 1/0 is the evaluation's to report
        assert _outcome(walk, "1/cos(pi/2) + sqrt(3)") == ("atoms", [("sqrt", 3)])
