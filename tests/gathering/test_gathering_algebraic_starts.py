"""Starts beyond the rationals (issue 30, point 1): square roots, polar turns, nested
radicals and cos/sin of turns j/36 are read into the motion's numbers
(exactsym.gathering.start_numbers, exactsym.exact.algebraic.turns); beyond the documented
bounds the refusal is an input error (exit 2) naming the bound, quickly."""

from __future__ import annotations

import json
import time
from pathlib import Path

import pytest
from flint import fmpq

from exactsym.cli.main import main
from exactsym.errors import InputError
from exactsym.exact.algebraic.interface import is_multiquadratic, nested_tower
from exactsym.exact.algebraic.turns import TurnBoundError, group_orders, turn_field
from exactsym.exact.multiquadratic import MQ, sqrt_rational
from exactsym.gathering.cases import run_settings, settings_of
from exactsym.gathering.paper_bridge import read_case
from exactsym.gathering.start_numbers import MAX_START_LEVELS

Q = MQ.rational


def _write(tmp_path, name: str, points: str) -> Path:
    path = tmp_path / name
    path.write_text(f'format = 1\nmodel = "fat"\npoints = [\n{points}]\n')
    return path


def _polar(turns, radius="20", den=36) -> str:
    return "".join(f'  {{ r = "{radius}", turn = "{j}/{den}" }},\n' for j in turns)


J36 = (0, 5, 13, 20, 29)


# -- the numbers of turns -------------------------------------------------------------------
@pytest.mark.parametrize("den", [5, 7, 8, 9, 11, 12, 16, 20, 24, 28, 36, 40])
def test_cos_and_sin_of_every_turn_are_exact(den):
    """c^2 + s^2 = 1 exactly, the angle sum formula holds exactly, and the values are the
    cosine and sine (a ball around each holds the true value)."""
    import math
    field = turn_field([fmpq(1, den)])
    values = [field.cos_sin(fmpq(j, den)) for j in range(den)]
    for j, (c, s) in enumerate(values):
        assert (c * c + s * s - 1).sign() == 0
        ball_c, ball_s = c.enclosure(80), s.enclosure(80)
        assert abs(float(ball_c.mid()) - math.cos(2 * math.pi * j / den)) < 1e-12
        assert abs(float(ball_s.mid()) - math.sin(2 * math.pi * j / den)) < 1e-12
    c1, s1 = values[1]
    for j in range(den - 1):
        c, s = values[j]
        cn, sn = values[j + 1]
        assert (c * c1 - s * s1 - cn).sign() == 0 and (s * c1 + c * s1 - sn).sign() == 0


def test_which_turns_are_which_numbers():
    """j/24 multiquadratic; j/5, j/16 nested (one level); j/36, j/7 in K(alpha) of degree
    3 over K; j/13 (a Z/4 in the group) refused, naming the bound."""
    assert turn_field([fmpq(1, 24)]).kind == "multiquadratic"
    assert turn_field([fmpq(1, 5)]).kind == "nested"
    assert turn_field([fmpq(3, 16)]).tower.levels == 1
    f36 = turn_field([fmpq(5, 36)])
    assert f36.kind == "algebraic" and f36.root.degree == 3
    # alpha = 2cos(2pi/36) is the root of x^3 - 3x - sqrt 3 (cos 30 = 4cos^3 10 - 3cos 10)
    assert f36.root.f == (-sqrt_rational(3), Q(-3), Q(0), Q(1))
    assert turn_field([fmpq(1, 7)]).root.degree == 3
    assert group_orders(36) == (6, 3) and group_orders(52) == (12, 6)
    with pytest.raises(TurnBoundError, match="2-part"):
        turn_field([fmpq(1, 13)])


# -- reading a start -------------------------------------------------------------------------
def test_a_polar_start_at_turns_j36_is_read_exactly(tmp_path):
    """Before issue 30 this file was refused ("needs rational coordinates"); now every
    point is a number of K(alpha) at squared distance exactly 400 from the origin."""
    path = _write(tmp_path, "j36.toml", _polar(J36))
    points, _name, _expect, _src = read_case(path)
    assert points[0] == (20, 0) or (points[0][0] - 20).sign() == 0
    for x, y in points:
        assert (x * x + y * y - 400).sign() == 0
    assert not is_multiquadratic(points[1][0])          # cos 50 degrees: K(alpha)
    # turn 9/36 is a quarter turn: (0, 20), multiquadratic
    path9 = _write(tmp_path, "q.toml", _polar((0, 9, 13, 20, 29)))
    x, y = read_case(path9)[0][1]
    assert is_multiquadratic(x) and x.is_zero() and y == Q(20)


def test_square_roots_and_nested_radicals_are_read_exactly(tmp_path):
    path = _write(tmp_path, "n.toml", '  ["20", "0"],\n  ["0", "10*sqrt(2+sqrt(2))"],\n'
                  '  ["-19", "3"],\n  ["2", "-18"],\n  ["sqrt(2)", "-sqrt(12)"],\n')
    points = read_case(path)[0]
    y = points[1][1]
    assert nested_tower(y) is not None                   # one level of the run's tower
    assert (y * y - Q(200) - sqrt_rational(2) * 100).sign() == 0
    assert points[4] == (sqrt_rational(2), sqrt_rational(3) * -2)
    # sqrt(2 + sqrt 3) denests: (sqrt 6 + sqrt 2)/2, multiquadratic
    path2 = _write(tmp_path, "d.toml", '  ["20", "0"],\n  ["0", "20*sqrt(2+sqrt(3))"],\n'
                   '  ["-19", "3"],\n  ["2", "-18"],\n  ["14", "13"],\n')
    y = read_case(path2)[0][1][1]
    assert y == (sqrt_rational(6) + sqrt_rational(2)) * 10


# -- refusals beyond the bounds --------------------------------------------------------------
REFUSED = {
    "turns j/13": (_polar((0, 1, 5, 8), den=13) + '  ["0", "3"],\n', "2-part", 5),
    "deep nesting": ('  ["20", "0"],\n  ["0", "20"],\n  ["-20", "0"],\n  ["0", "-20"],\n'
                     '  ["sqrt(2 + sqrt(2 + sqrt(2 + sqrt(2 + sqrt(2 + sqrt(2 + sqrt(3)))'
                     '))))", "3"],\n', f"bound is {MAX_START_LEVELS}", 8),
    "sqrt over K(alpha)": ('  ["20", "0"],\n  ["0", "20"],\n  ["-20", "0"],\n  ["0", "-20"],\n'
                           '  ["4*sqrt(cos(pi/18))", "3"],\n', "square root of a number of "
                           "K(alpha)", 8),
    "two systems": (_polar((0, 5)) + '  ["-20", "0"],\n  ["0", "-20"],\n'
                    '  ["sqrt(2 + sqrt(2))", "3"],\n', "one system per run", None),
}


@pytest.mark.parametrize("what", sorted(REFUSED))
def test_beyond_a_bound_the_refusal_is_quick_located_and_names_the_bound(what, tmp_path,
                                                                         capsys):
    points, bound, line = REFUSED[what]
    path = _write(tmp_path, "bad.toml", points)
    start = time.process_time()
    with pytest.raises(InputError) as err:
        read_case(path)
    assert time.process_time() - start < 1.0
    assert bound in str(err.value)
    assert err.value.line is not None and err.value.column is not None
    if line is not None:
        assert err.value.line == line
    assert str(err.value).startswith(f"{path}:{err.value.line}:{err.value.column}: ")
    assert main(["gather", str(path)]) == 2
    assert bound in capsys.readouterr().err


# -- runs --------------------------------------------------------------------------------------
def _outcome(points, algorithm, scheduler="centralised"):
    res = run_settings(points, settings_of({"gather_scheduler": scheduler,
                                            "gather_algorithm": algorithm}))
    v = res.violation
    return res.outcome, res.label, v and v["invariant"], v and sorted(v["robots"]), res


def test_the_j36_start_runs_exactly_and_decides(tmp_path):
    """The paper's algorithm: I9 fails for robots 2 and 3; the corrected variant gathers,
    every critical instant checked at the instant (none ``sided``)."""
    points = read_case(_write(tmp_path, "j36.toml", _polar(J36)))[0]
    assert _outcome(points, "paper")[:4] == ("violated", "no chirality (L210-214)", "I9",
                                             [2, 3])
    outcome, _label, _inv, _robots, res = _outcome(points, "corrected")
    assert outcome == "gathered"
    assert res.checks["sided"] == 0 and res.checks["instants"] > 0


def _similar(points, kind):
    if kind == "rotation":                 # by the Pythagorean angle (3/5, 4/5)
        c, s = fmpq(3, 5), fmpq(4, 5)
        return [(x * c - y * s, x * s + y * c) for x, y in points]
    if kind == "mirror":
        return [(x, -y) for x, y in points]
    if kind == "translation":
        return [(x + 7, y - fmpq(3, 2)) for x, y in points]
    return [(x * 3, y * 3) for x, y in points]        # scale: a similarity too (robots
    # keep radius 1: not the same configuration, so not used below)


@pytest.mark.parametrize("kind", ["rotation", "mirror", "translation"])
@pytest.mark.parametrize("start,algorithm", [("j36", "paper"), ("j36", "corrected"),
                                             ("j5", "paper")])
def test_the_verdict_is_the_same_after_a_rigid_motion_of_the_algebraic_start(
        tmp_path, kind, start, algorithm):
    text = (_polar(J36) if start == "j36" else
            '  { r = "20", turn = "0" },\n  { r = "20", turn = "1/5" },\n'
            '  { r = "16", turn = "2/5" },\n  { r = "20", turn = "3/5" },\n  ["0", "3"],\n')
    points = read_case(_write(tmp_path, "s.toml", text))[0]
    assert _outcome(_similar(points, kind), algorithm)[:4] == _outcome(points, algorithm)[:4]


def test_shuffling_the_robots_keeps_the_verdict_up_to_the_renaming(tmp_path):
    points = read_case(_write(tmp_path, "j36.toml", _polar(J36)))[0]
    order = [3, 0, 4, 1, 2]
    shuffled = [points[i] for i in order]
    got = _outcome(shuffled, "paper")
    want = _outcome(points, "paper")
    assert got[:3] == want[:3]
    assert sorted(order[i] for i in got[3]) == want[3]


def test_a_trace_of_an_algebraic_start_replays_with_its_file(tmp_path, capsys):
    path = _write(tmp_path, "j36.toml", _polar(J36))
    trace = tmp_path / "t.json"
    assert main(["gather", str(path), "--scheduler", "centralised", "--trace",
                 str(trace)]) == 0
    data = json.loads(trace.read_text())
    assert "a = the root of" in data["points"][1][0]       # exact text, not a float
    capsys.readouterr()
    assert main(["replay", str(trace), str(path)]) == 0
    assert "identical" in capsys.readouterr().out
    assert main(["replay", str(trace)]) == 2               # no file: told to give it
    assert "replay TRACE FILE" in capsys.readouterr().err


# -- the number layer under such a start -------------------------------------------------------
def _alpha36():
    from exactsym.exact.algebraic.algebraic_numbers import AlgebraicNumber
    root = turn_field([fmpq(1, 36)]).root
    return root, AlgebraicNumber(root, (Q(0), Q(1)))


def test_products_in_k_alpha_reduce_as_the_polynomial_remainder():
    """The power-table reduction and the fused a*b +- c*d give the remainder modulo f."""
    import random
    from exactsym.exact.algebraic.algebraic_numbers import AlgebraicNumber
    from exactsym.exact.algebraic.interface import two_products
    from exactsym.exact.algebraic.polynomials import pdivmod, pmul, trim
    root, _alpha = _alpha36()
    rng = random.Random(3)

    def rnd():
        return trim(MQ({1: fmpq(rng.randint(-9, 9), rng.randint(1, 4)),
                        3: fmpq(rng.randint(-3, 3)), 2: fmpq(rng.randint(-1, 1))})
                    for _ in range(3))
    for _ in range(40):
        a, b, c, d = rnd(), rnd(), rnd(), rnd()
        x, y, z, w = (AlgebraicNumber(root, p) for p in (a, b, c, d))
        want = pdivmod(pmul(a, b), root.f)[1]
        got = x * y
        assert tuple(getattr(got, "c", (got,) if not got.is_zero() else ())) == want
        for sign in (1, -1):
            assert two_products(x, y, z, w, sign) == x * y + (z * w) * sign


def test_a_quadratic_with_k_alpha_coefficients_has_an_exact_root():
    """(f - alpha/4)(f - 1/2 - alpha/8) has two exact roots in (0, 1), numbers of K(alpha)
    again; f^2 - alpha/4 has the exact root sqrt(alpha)/2 (in K'(alpha), or a number of a
    one-level tower of its own over K(alpha))."""
    from exactsym.exact.algebraic.roots import roots_in_unit
    from exactsym.exact.algebraic.polynomials import pmul
    _root, alpha = _alpha36()
    r1, r2 = alpha / 4, alpha / 8 + fmpq(1, 2)
    p = pmul((-r1, Q(1)), (-r2, Q(1)))
    exact = sorted((r.exact for r in roots_in_unit(p)), key=lambda v: v.enclosure(60).mid())
    assert len(exact) == 2 and exact[0] == r1 and exact[1] == r2
    (only,) = roots_in_unit((-alpha / 4, Q(0), Q(1)))
    assert only.exact is not None and (only.exact * only.exact - alpha / 4).sign() == 0
    assert only.exact.sign() > 0


def test_a_sided_instant_makes_a_positive_verdict_of_an_algebraic_start_undecided():
    from exactsym.gathering.schedulers import Result
    from exactsym.gathering.start_numbers import certified
    _root, alpha = _alpha36()
    algebraic = [(alpha * 10, Q(0))] + [(Q(k), Q(0)) for k in range(4)]
    rational = [(Q(k * 3), Q(0)) for k in range(5)]
    for outcome, sided, points, want in [
            ("gathered", 1, algebraic, "undecided"), ("stalled", 2, algebraic, "undecided"),
            ("gathered", 0, algebraic, "gathered"), ("violated", 1, algebraic, "violated"),
            ("gathered", 1, rational, "gathered")]:
        res = Result(outcome, "d", 3, 2, {"sided": sided}, None, {})
        assert certified(res, points).outcome == want


def test_the_search_forks_worlds_of_an_algebraic_start(tmp_path, capsys):
    """The search deep-copies worlds: numbers of K(alpha) keep their one root (before: a
    TypeError copying its Arb balls, exit 3), and it finds the I9 violation."""
    path = _write(tmp_path, "j36.toml", _polar(J36))
    assert main(["gather", str(path), "--search", "--budget", "150", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["outcome"] == "violated" and out["violation"]["invariant"] == "I9"


def test_quartics_with_tower_coefficients_have_exact_roots():
    """A biquadratic and an arc-like cubic ``(f - r)(1 + 2 f^2)`` whose coefficients are
    numbers of a run's tower (a nested-radical start): exact roots, checked by value."""
    from exactsym.exact.algebraic.polynomials import pmul
    from exactsym.exact.algebraic.roots import roots_in_unit
    from exactsym.exact.algebraic.run_tower import RunTower, sqrt_exact
    tower = RunTower()
    t = sqrt_exact(Q(2) + sqrt_rational(2), tower)          # sqrt(2 + sqrt 2), level 1
    assert nested_tower(t) is tower
    biquadratic = pmul((-t / 4, Q(0), Q(1)), (Q(1), Q(0), Q(1)))   # (f^2 - t/4)(f^2 + 1)
    (root,) = roots_in_unit(biquadratic)
    assert root.exact is not None and (root.exact * root.exact - t / 4).sign() == 0
    cubic = pmul((-t / 3, Q(1)), (Q(1), Q(0), Q(2)))
    (root,) = roots_in_unit(cubic)
    assert root.exact is not None and (root.exact - t / 3).sign() == 0
