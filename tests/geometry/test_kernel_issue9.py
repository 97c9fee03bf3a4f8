"""Issue 9: each crash and refusal on valid input, as a test."""

from __future__ import annotations

import json

import pytest

from exactsym import checker
from exactsym.certificates.certificate import make_certificate
from exactsym.geometry.configuration import load
from exactsym.errors import InputError
from exactsym.exact import evaluate, evaluate_all, exact_key
from exactsym.io.expr import parse_expression
from exactsym.geometry.levels import levels_of
from exactsym.truth.symmetry import symmetry_group


def _toml(tmp_path, points: list[str]) -> str:
    path = tmp_path / "c.toml"
    path.write_text("format = 1\npoints = [\n" + ",\n".join(points) + "\n]\n")
    return str(path)


def _certified(config) -> dict:
    cert = json.loads(json.dumps(make_certificate(config)))
    ok, message = checker.verify_certificate(cert)
    assert ok, message
    return cert


def test_txt_literal_of_4500_digits_is_read_and_6000_refused(tmp_path):
    big = "1" + "0" * 4500
    path = tmp_path / "big.txt"
    path.write_text(f"{big} 0\n0 1\n")
    config = load(str(path))
    assert config.points[0][0] == 10 ** 4500
    assert _certified(config)["claim"]["group"] == "D2"
    path.write_text("1" + "0" * 5999 + " 0\n0 1\n")
    with pytest.raises(InputError, match="6000 digits"):
        load(str(path))


def test_checker_reads_rationals_beyond_4300_digits():
    big = "7" * 4999
    assert checker.rat(f"-{big}/3") == (-checker.integer(big), 3)
    assert checker.integer(big) % 10 ** 4000 == int("7" * 4000)
    for bad in ("1e5", "", "--1", "١٢"):
        with pytest.raises(checker.Invalid):
            checker.rat(bad)


def test_polar_radius_with_square_root_and_cyclotomic_turns(tmp_path):
    # 7 robots at r = 1 and 7 at r = sqrt(2): radii in Q(zeta_8), Cartesian points in a
    # larger cyclotomic field; comparing the two crashed ("two different number fields")
    rows = [f'{{ r = "1", turn = "2/45 + {k}/7" }}' for k in range(7)] + \
           [f'{{ r = "sqrt(2)", turn = "1/9 + {k}/7" }}' for k in range(7)]
    config = load(_toml(tmp_path, rows))
    polar = levels_of(config).sec.centre
    cartesian_origin = config.points[0][0] * 0
    assert polar[0] == cartesian_origin and cartesian_origin == polar[0]
    assert config.points[0][0] * config.points[0][0] + config.points[0][1] ** 2 == 1
    assert symmetry_group(config).name == "C7"


def test_denestable_radical_is_not_a_coincidence(tmp_path):
    config = load(_toml(tmp_path, ['["sqrt(3+2*sqrt(2))", "0"]', '["1", "0"]']))
    x = config.points[0][0]
    assert exact_key(x) != exact_key(config.points[1][0])
    _, (a, b) = evaluate_all([parse_expression("sqrt(3+2*sqrt(2))"),
                              parse_expression("1 + sqrt(2)")])
    assert a == b


def test_off_centre_polar_with_large_cyclotomic_field_is_answered(tmp_path):
    # Q(zeta_20020), degree 5760, was refused ("above the limit 4096")
    rows = [f'{{ r = "1", turn = "{t}" }}' for t in ("0", "1/7", "2/5", "3/11", "5/13")]
    config = load(_toml(tmp_path, rows))
    group = symmetry_group(config)
    assert group.name == "C1" and sorted(group.ordering) == [0, 1, 2, 3, 4]
    assert config.system.degree == 5760


def test_nine_square_roots_truth(tmp_path):
    rows = ['["sqrt(2)", "sqrt(3)"]', '["sqrt(5)+sqrt(7)", "sqrt(11)"]',
            '["sqrt(13)-sqrt(17)", "sqrt(19)+sqrt(23)"]']
    config = load(_toml(tmp_path, rows))
    group = symmetry_group(config)
    assert group.name == "C1"
    # the SEC is the circumcircle or a diameter circle: all points within, support on it
    sec = levels_of(config).sec
    assert all(sec.contains(p) for p in config.points)
    assert all(sec.scaled_power(config.points[i]) == 0 for i in sec.support)


def test_power_of_a_number_of_a_tower_over_the_sparse_base(tmp_path):
    # a power's size bound read the base numbers as dense polynomials: exit 3
    rows = ['{ r = "sqrt(145)", turn = "680/997" }',
            '{ r = "(sqrt(2)*cos(2*pi/997) + sqrt(3))^2", turn = "183/997" }',
            '{ r = "sqrt(63)", turn = "339/997" }']
    config = load(_toml(tmp_path, rows))
    x, y = config.points[1]
    r2 = x * x + y * y                                   # the squared radius
    c = "cos(2*pi/997)"
    square = f"(2*{c}*{c} + 2*sqrt(6)*{c} + 3)"         # r, expanded: no power
    assert r2 == evaluate(parse_expression(f"{square}*{square}"), config.system)
    assert symmetry_group(config).name == "C1"
