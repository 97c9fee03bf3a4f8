"""The number layer's declared interface (issue 29, docs/numbers.md): the layers above
exact/ ask :mod:`exactsym.exact.number` instead of testing concrete number classes."""

import ast
import math
from pathlib import Path

from flint import fmpq
from hypothesis import given, settings, strategies as st

from exactsym.exact import number
from exactsym.exact.factor import is_prime
from exactsym.exact.cyclotomic import cyclotomic_field, sqrt_element
from exactsym.exact.multiquadratic import MQ

PACKAGE = Path(__file__).resolve().parents[2] / "exactsym"

#: the concrete number classes (and their fields and towers) of the kernel
NUMBER_CLASSES = {"fmpq", "fmpz", "Fraction", "MQ", "PolyElement", "FieldElement",
                  "SparseCyclotomic", "TowerElement", "LevelRadius", "TowerLevelRadius",
                  "NumberField", "Tower", "CyclotomicTower", "SparseKummerTower",
                  "SparseContext",
                  # the motion's (exact/algebraic/)
                  "TowerNumber", "AlgebraicNumber", "AlgebraicTowerNumber", "AlgebraicRoot",
                  "AlgebraicTower", "RunTower"}
#: packages that own numbers (exact/), or check them on their own (certificates/, checker/)
OWNERS = {"exact", "certificates", "checker"}
#: the count in the whole package outside OWNERS (issue 29: 80 before, at most 10 asked;
#: left: two checks that a file's input is rational, gathering/paper_bridge.read_case and
#: sweep/analysis_bridge): it may only go down
LIMIT = 3


def _class_checks(package: Path = PACKAGE) -> list[str]:
    found = []
    for path in sorted(package.rglob("*.py")):
        if path.relative_to(package).parts[0] in OWNERS:
            continue
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.Call) and getattr(node.func, "id", None) == "isinstance" \
                    and len(node.args) == 2:
                kinds = node.args[1].elts if isinstance(node.args[1], ast.Tuple) \
                    else [node.args[1]]
                names = {getattr(k, "id", None) or getattr(k, "attr", None) for k in kinds}
                if names & NUMBER_CLASSES:
                    found.append(f"{path.relative_to(package.parent)}:{node.lineno}")
    return found


def test_few_class_checks_on_numbers_outside_the_number_layer():
    found = _class_checks()
    assert len(found) <= LIMIT, "\n".join(found)


def test_the_counter_sees_a_class_check(tmp_path):
    for unit, text in (("paper", "isinstance(x, (int, PolyElement))\nisinstance(x, tower.MQ)\n"
                                 "isinstance(x, tuple)\n"),
                       ("exact", "isinstance(x, PolyElement)\n")):
        (tmp_path / "pkg" / unit).mkdir(parents=True)
        (tmp_path / "pkg" / unit / "m.py").write_text(text)
    assert _class_checks(tmp_path / "pkg") == ["pkg/paper/m.py:1", "pkg/paper/m.py:2"]


def test_the_questions_answer_for_rationals_and_field_elements():
    q = fmpq(3, 7)
    field = cyclotomic_field(8)
    root = sqrt_element(field, fmpq(2))
    mq = MQ({2: fmpq(1)})
    assert number.is_plain_rational(q) and not number.is_algebraic(q)
    assert number.is_algebraic(root) and number.is_algebraic(mq)
    assert number.is_number(q) and number.is_number(mq) and not number.is_number((q,))
    assert number.any_algebraic([q, root]) and not number.any_algebraic([q, q])
    assert number.all_plain_rational([q, fmpq(1)]) and not number.all_plain_rational([q, mq])
    assert number.rational_value(q) == q and number.rational_value(root) is None
    assert number.rational_value(root * root) == 2
    assert number.sign(-root) == -1 and number.sign(q) == 1
    assert number.enclosure(root, 64).overlaps(number.enclosure(mq, 64))
    assert not number.enclosure(root, 64).overlaps(number.enclosure(q, 64))
    assert number.dense_field(root) is field and number.dense_field(mq) is None
    assert not number.large_dense(root) and not number.big_field(q, mq)
    assert number.big_field(root) == (field.degree >= number.RATIO_KEY_DEGREE)
    assert number.largest_field([q, root, mq]) is field


# -- one primality test in the solver: python-flint's, agreeing with the tests it replaced


def _trial_division(n: int) -> bool:       # paper/polygon/types.py had this one
    return n >= 2 and all(n % p for p in range(2, math.isqrt(n) + 1))


def _miller_rabin(n: int) -> bool:          # exact/cyclotomic_sqrt.py had this one
    if n < 2:
        return False
    for q in (2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37):
        if n % q == 0:
            return n == q
    d, s = n - 1, 0
    while d % 2 == 0:
        d, s = d // 2, s + 1
    for a in (2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37):   # deterministic below 3.3e24
        x = pow(a, d, n)
        if x in (1, n - 1):
            continue
        for _ in range(s - 1):
            x = x * x % n
            if x == n - 1:
                break
        else:
            return False
    return True


def test_is_prime_agrees_with_trial_division_below_20000():
    assert [n for n in range(-5, 20_000) if is_prime(n)] == \
        [n for n in range(-5, 20_000) if _trial_division(n)]


@settings(max_examples=300, deadline=None)
@given(st.integers(min_value=0, max_value=3 * 10 ** 24))
def test_is_prime_agrees_with_deterministic_miller_rabin(n):
    assert is_prime(n) == _miller_rabin(n)


def test_is_prime_on_carmichael_numbers_and_strong_pseudoprimes():
    # 3215031751 is a strong pseudoprime to bases 2, 3, 5, 7; 561, 41041 are Carmichael
    for n in (561, 41041, 3215031751, 3825123056546413051):
        assert not is_prime(n) and not _miller_rabin(n)
    for p in (2, 3, 2 ** 61 - 1, 10 ** 18 + 9):
        assert is_prime(p) and _miller_rabin(p)


# -- one protocol, every kind ------------------------------------------------------------
def _kinds():
    """``(name, number, value)``: one irrational number of every kind of the number layer
    and of the motion's numbers, with its value from floats (an independent oracle)."""
    from exactsym.exact.algebraic.algebraic_tower import sqrt_over_k_alpha
    from exactsym.exact.algebraic.roots import algebraic_root
    from exactsym.exact.algebraic.run_tower import RunTower, sqrt_exact
    from exactsym.exact.algebraic.tower_numbers import mq_sqrt_any
    from exactsym.exact.context import AnalysisContext
    from exactsym.exact.evaluate import evaluate_all
    from exactsym.exact.level_radius import LevelRadius, TowerLevelRadius
    from exactsym.exact.multiquadratic import sqrt_rational
    from exactsym.io.expr import parse_expression

    def one(text):
        return evaluate_all([parse_expression(text)])[1][0]

    c7 = math.cos(2 * math.pi / 7)
    field = cyclotomic_field(8)
    r2 = sqrt_element(field, fmpq(2))
    nested = one("sqrt(2 + cos(2*pi/7))")                 # a tower over Q(zeta_7)
    s2, s3 = sqrt_rational(2), sqrt_rational(3)
    with AnalysisContext().active():                      # a run of its own: a fresh root
        alpha = algebraic_root(tuple(MQ.coerce(c) for c in (-s3 / 4, -1, 0, 8)),
                               fmpq(0), fmpq(1))
        level = sqrt_over_k_alpha(alpha + 3)
    a = next(x for x in _real_cubic_roots(8, 0, -1, -3 ** 0.5 / 4) if 0 < x < 1)
    return [
        ("MQ", s2 + 1, 2 ** 0.5 + 1),
        ("PolyElement", r2 + 1, 2 ** 0.5 + 1),
        ("SparseCyclotomic", one("cos(2*pi/1001) + sqrt(2)"),
         math.cos(2 * math.pi / 1001) + 2 ** 0.5),
        ("TowerElement", nested, (2 + c7) ** 0.5),
        ("TowerNumber", mq_sqrt_any(1 + s2), (1 + 2 ** 0.5) ** 0.5),
        ("TowerNumber of a run", sqrt_exact(1 + s2, RunTower()), (1 + 2 ** 0.5) ** 0.5),
        ("AlgebraicNumber", alpha, a),
        ("AlgebraicTowerNumber", level, (a + 3) ** 0.5),
        ("LevelRadius", LevelRadius(field, lambda: (r2 + 1) * (r2 + 1), (r2 + 1, fmpq(0)),
                                    (fmpq(0), fmpq(0)), 1, object(), 0), (2 ** 0.5 + 1) ** 2),
        # |p - C|^2 for p = (sqrt(2 + cos(2 pi/7)), 0) and C = (-1/2, 0)
        ("TowerLevelRadius", TowerLevelRadius(nested.tower,
                                              lambda: nested * nested + nested + fmpq(1, 4),
                                              (nested, fmpq(0)), (fmpq(-1), fmpq(0), 2),
                                              object(), 0), ((2 + c7) ** 0.5 + 0.5) ** 2),
    ]


def _real_cubic_roots(a, b, c, d):
    """The real roots of ``a x^3 + b x^2 + c x + d`` by bisection on a float grid."""
    f = lambda x: ((a * x + b) * x + c) * x + d                      # noqa: E731
    roots, grid = [], [k / 64 - 4 for k in range(513)]
    for lo, hi in zip(grid, grid[1:]):
        if f(lo) * f(hi) < 0:
            for _ in range(80):
                mid = (lo + hi) / 2
                lo, hi = (mid, hi) if f(lo) * f(mid) > 0 else (lo, mid)
            roots.append(lo)
    return roots


def test_every_kind_meets_the_one_protocol():
    kinds = _kinds()
    assert {name for name, _, _ in kinds} >= {
        "MQ", "PolyElement", "SparseCyclotomic", "TowerElement", "TowerNumber",
        "AlgebraicNumber", "AlgebraicTowerNumber", "LevelRadius", "TowerLevelRadius"}
    for name, x, value in kinds:
        assert isinstance(x, number.ExactNumber), name
        assert x.sign() == 1 and (-x).sign() == -1, name
        assert not x.is_zero() and not x.is_rational(), name
        try:
            x.to_fmpq()
        except ValueError:
            pass
        else:
            raise AssertionError(f"{name}: an irrational number read as a rational")
        ball = x.enclosure(64)
        assert abs(float(ball.mid()) - value) < 1e-9 and float(ball.rad()) < 1e-15, name
        assert isinstance(x.text(), str) and x.text(), name
        # the questions of exact/number.py answer for it as its methods do
        assert number.sign(x) == 1 and number.rational_value(x) is None, name
        zero = x - x
        assert number.sign(zero) == 0 and (not number.is_algebraic(zero) or zero.is_zero())


def test_fmpq_is_answered_by_the_functions_and_rational_kinds_read_back():
    q = fmpq(-3, 7)
    assert not isinstance(q, number.ExactNumber)           # a C type: the functions answer
    assert number.sign(q) == -1 and number.rational_value(q) == q
    assert number.enclosure(q, 64).contains(q)
    field = cyclotomic_field(8)
    r2 = sqrt_element(field, fmpq(2))
    for x in (r2 * r2 / 7, MQ({2: fmpq(1)}) * MQ({2: fmpq(1)}) / 7):
        assert x.is_rational() and x.to_fmpq() == fmpq(2, 7) and not x.is_zero()
        assert number.rational_value(x) == fmpq(2, 7)
    assert (r2 - r2).is_zero() and MQ().is_zero()
