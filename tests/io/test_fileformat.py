"""Reading configuration files (exactsym.io.fileformat)."""

import io
import sys
import types
from fractions import Fraction as F

import pytest
from hypothesis import given, settings, strategies as st

from exactsym.io.fileformat import (EXPECT_KEYS, ConfigFile, PointSpec, parse_config_text,
                             read_config)
from exactsym.errors import ExpressionError, InputError
from exactsym.io.exprtree import BinOp, Const, Sqrt, Trig


def C(value) -> Const:
    return Const(F(value))


def toml(text: str) -> ConfigFile:
    return parse_config_text(text, "case.toml", "toml")


def txt(text: str) -> ConfigFile:
    return parse_config_text(text, "case.txt", "txt")


def toml_error(text: str) -> InputError:
    with pytest.raises(InputError) as info:
        toml(text)
    return info.value


def txt_error(text: str) -> InputError:
    with pytest.raises(InputError) as info:
        txt(text)
    return info.value


# ---------------------------------------------------------------- TOML

SPEC_EXAMPLE = """\
format = 1                        # required
name = "Chiral nine-gon"          # optional
notes = "free text"               # optional
model = "points"                  # optional
lemmas = ["obs-asymmetric-polygon"]
points = [
  ["1/2", "sqrt(3)/2"],
  { r = "2", turn = "1/3" },
  [3, "-1"],
  {turn = '1/5', r = "cos(pi/5)"},
]

[expect]
orderable = false
group = "C3"
paper_orderable = true
n = 4
levels = 2
sec_radius_squared = "4"
"""


def test_toml_example_of_the_spec():
    cfg = toml(SPEC_EXAMPLE)
    assert cfg == ConfigFile(
        source="case.toml",
        points=(
            PointSpec(0, 7, 3, x=C(F(1, 2)), y=BinOp("/", Sqrt(C(3)), C(2)),
                      texts=("1/2", "sqrt(3)/2"), columns=(5, 12)),
            PointSpec(1, 8, 3, r=C(2), turn=F(1, 3), texts=("2", "1/3"), columns=(10, 22)),
            PointSpec(2, 9, 3, x=C(3), y=C(-1), texts=("3", "-1"), columns=(4, 8)),
            PointSpec(3, 10, 3, r=Trig("cos", F(1, 5)), turn=F(1, 5),
                      texts=("cos(pi/5)", "1/5"), columns=(23, 12)),
        ),
        name="Chiral nine-gon", notes="free text", model="points",
        lemmas=("obs-asymmetric-polygon",),
        expect={"orderable": False, "group": "C3", "paper_orderable": True, "n": 4,
                "levels": 2, "sec_radius_squared": "4"},
    )
    assert [p.is_polar for p in cfg.points] == [False, True, False, True]


def test_minimal_toml_and_defaults():
    cfg = toml('format = 1\npoints = [["0", "0"]]\n')
    assert cfg.points == (PointSpec(0, 2, 11, x=C(0), y=C(0), texts=("0", "0"),
                                    columns=(13, 18)),)
    assert (cfg.name, cfg.notes, cfg.model, cfg.lemmas, dict(cfg.expect)) == \
        (None, None, "points", (), {})


def test_expect_is_read_only():
    cfg = toml(SPEC_EXAMPLE)
    assert isinstance(cfg.expect, types.MappingProxyType)
    with pytest.raises(TypeError):
        cfg.expect["n"] = 5


def test_fat_model_and_array_of_tables():
    cfg = toml('format = 1\nmodel = "fat"\n[[points]]\nr = "1"\nturn = 0\n'
               '[[points]]\nr = 1\nturn = "1/2"\n')
    assert cfg.model == "fat"
    assert [(p.r, p.turn, p.line) for p in cfg.points] == [(C(1), 0, 4), (C(1), F(1, 2), 7)]


@pytest.mark.parametrize("value", ["0.5", "1e3", "-0.0", "inf", "nan", "1.0"])
def test_unquoted_toml_float_is_rejected(value):
    err = toml_error(f'format = 1\npoints = [["1", "2"], [{value}, "1"]]\n')
    assert "TOML float" in err.message and f'"{value}"' in err.message
    assert (err.source, err.line) == ("case.toml", 2)


def test_float_turn_is_rejected():
    err = toml_error('format = 1\npoints = [{ r = "1", turn = 0.25 }]\n')
    assert "TOML float" in err.message


@pytest.mark.parametrize("head, words", [
    ("", "missing 'format = 1'"),
    ("format = 2\n", "format must be 1"),
    ('format = "1"\n', "format must be 1"),
    ("format = true\n", "format must be 1"),
    ("format = 1.0\n", "format must be 1"),
])
def test_format_is_required_and_must_be_1(head, words):
    assert words in toml_error(head + 'points = [["0", "0"]]\n').message


@pytest.mark.parametrize("text, words, line", [
    ('format = 1\npoints = [["0", "0"]]\nnmae = "x"\n', "unknown key 'nmae'", 3),
    ('format = 1\npoints = [["0", "0"]]\n[expected]\nn = 1\n', "unknown key 'expected'", 3),
    ('format = 1\npoints = [["0", "0"]]\n[expect]\norderable = true\nordreable = true\n',
     "unknown [expect] key 'ordreable'", 5),
    ('format = 1\npoints = [["0", "0"]]\n[expect]\norderable = 1\n',
     "orderable must be true or false, not an integer", 4),
    ('format = 1\npoints = [["0", "0"]]\n[expect]\nn = true\n',
     "n must be an integer, not true", 4),
    ('format = 1\npoints = [["0", "0"]]\n[expect]\nn = 3.0\n',
     "n must be an integer, not a float", 4),
    ('format = 1\npoints = [["0", "0"]]\n[expect]\ngroup = 3\n', "group must be a string", 4),
    ('format = 1\npoints = [["0", "0"]]\n[expect]\nlevels = "2"\n', "levels must be an integer", 4),
    ('format = 1\npoints = [["0", "0"]]\n[expect]\nsec_radius_squared = 4\n',
     "sec_radius_squared must be an expression string", 4),
    ('format = 1\npoints = [["0", "0"]]\nexpect = 3\n', "expect must be a table", 3),
    ('format = 1\npoints = [["0", "0"]]\nmodel = "fatt"\n', 'model must be "points" or "fat"', 3),
    ('format = 1\npoints = [["0", "0"]]\nmodel = 1\n', "model must be a string", 3),
    ('format = 1\npoints = [["0", "0"]]\nname = 1\n', "name must be a string", 3),
    ('format = 1\npoints = [["0", "0"]]\nnotes = ["a"]\n', "notes must be a string", 3),
    ('format = 1\npoints = [["0", "0"]]\nlemmas = "a"\n', "lemmas must be an array", 3),
    ('format = 1\npoints = [["0", "0"]]\nlemmas = ["a", 1]\n', "lemmas must be strings", 3),
    ("format = 1\n", "missing 'points'", None),
    ("format = 1\npoints = []\n", "non-empty array", 2),
    ('format = 1\npoints = "0 0"\n', "non-empty array", 2),
    ('format = 1\npoints = [["0", "0", "0"]]\n', "point 0 must be [x, y]", 2),
    ('format = 1\npoints = [["0"]]\n', "an array of length 1", 2),
    ('format = 1\npoints = [["0", "0"], "1 1"]\n', "point 1 must be [x, y]", 2),
    ('format = 1\npoints = [{ r = "1" }]\n', "a table with keys 'r'", 2),
    ('format = 1\npoints = [{ r = "1", turn = "0", x = "1" }]\n', "point 0 must be", 2),
    ('format = 1\npoints = [{ x = "1", y = "0" }]\n', "point 0 must be", 2),
    ('format = 1\npoints = [["0", true]]\n', "y must be an expression string or an integer, "
     "not true", 2),
    ('format = 1\npoints = [["0", ["1"]]]\n', "not an array", 2),
    ('format = 1\npoints = [{ r = "1", turn = "sqrt(2)" }]\n', "turn must be a rational", 2),
])
def test_toml_validation_errors_name_the_key_and_line(text, words, line):
    err = toml_error(text)
    assert words in err.message
    assert err.source == "case.toml"
    assert err.line == line


def test_pi_in_turn_is_transcendental():
    err = toml_error('format = 1\npoints = [{ r = "1", turn = "pi/3" }]\n')
    assert isinstance(err, ExpressionError) and "transcendental" in err.message


def test_expression_error_is_located_in_the_toml_file():
    err = toml_error('format = 1\npoints = [\n  ["1", "2"],\n  ["1/2", "sqrt(3)/x"],\n]\n')
    assert isinstance(err, ExpressionError)
    assert (err.source, err.line, err.column) == ("case.toml", 4, 20)
    assert str(err) == "case.toml:4:20: unknown name 'x' (the only names are sqrt, cos, sin and pi)"
    err = toml_error("format = 1\n"
                     "points = [['0', '0'], { turn = '1', r = '__import__(\"os\")' }]\n")
    assert (err.line, err.column, err.offset) == (2, 42, 0)


def test_sec_radius_squared_must_parse():
    err = toml_error('format = 1\npoints = [["0", "0"]]\n[expect]\nsec_radius_squared = "2+pi"\n')
    assert isinstance(err, ExpressionError)
    assert (err.line, err.column) == (4, 25)
    assert toml('format = 1\npoints = [["0", "0"]]\n[expect]\n'
                'sec_radius_squared = "1/2 + sqrt(2)/4"\n').expect["sec_radius_squared"] == \
        "1/2 + sqrt(2)/4"


@pytest.mark.parametrize("text, line, column", [
    ("format = 1\npoints = [[\"0\", \"0\"]\n", 3, None),   # at end of document
    ("format = 1\npoints = [[\"0\" \"0\"]]\n", 2, 16),
    ("format = 1\nformat = 1\n", 2, 11),
    ("format = = 1\n", 1, 10),
    ("format = 1\npoints = [[\"0\", \"0]]\n", 2, 21),
])
def test_malformed_toml_reports_line_and_column(text, line, column):
    err = toml_error(text)
    assert err.message.startswith("malformed TOML: ")
    assert "(at line" not in err.message
    assert (err.source, err.line, err.column) == ("case.toml", line, column)


def test_toml_pathologies_are_input_errors():
    assert "malformed TOML" in toml_error("a = " + "[" * 100_000).message
    assert "malformed TOML" in toml_error("a = " + "1" * 5000).message   # int digit limit
    assert toml_error("format = 1\npoints = [[\"0\", \"" + "1" * 5001 + "\"]]\n").line == 2


def test_expect_keys_registry_is_generic(monkeypatch):
    monkeypatch.setitem(EXPECT_KEYS, "leader", (int, bool))
    assert toml('format = 1\npoints = [["0", "0"]]\n[expect]\nleader = 3\n').expect == \
        {"leader": 3}
    assert toml('format = 1\npoints = [["0", "0"]]\n[expect]\nleader = false\n').expect == \
        {"leader": False}
    assert "leader must be an integer or true or false, not a string" in toml_error(
        'format = 1\npoints = [["0", "0"]]\n[expect]\nleader = "x"\n').message
    monkeypatch.setitem(EXPECT_KEYS, "ordering", list)
    assert toml('format = 1\npoints = [["0", "0"]]\n[expect]\nordering = [0]\n').expect == \
        {"ordering": [0]}
    assert "ordering must be an array" in toml_error(
        'format = 1\npoints = [["0", "0"]]\n[expect]\nordering = [0.5]\n').message


# ---------------------------------------------------------------- plain text

def test_plain_text_forms():
    cfg = txt("# a comment\n"
              "\n"
              "1/2 sqrt(3)/2\n"
              "  -1 -1   # trailing comment\n"
              "sqrt(2) / 2  1/3\n"
              "1, 2\n"
              "sqrt(2) / 2, - 1/3\n"
              "polar 2 1/3\n"
              "\tpolar cos(pi/5), -1/4\n"
              "(1 + 2) (3)\n")
    assert cfg == ConfigFile(source="case.txt", points=(
        PointSpec(0, 3, 1, x=C(F(1, 2)), y=BinOp("/", Sqrt(C(3)), C(2)),
                  texts=("1/2", "sqrt(3)/2"), columns=(1, 5)),
        PointSpec(1, 4, 3, x=C(-1), y=C(-1), texts=("-1", "-1"), columns=(3, 6)),
        PointSpec(2, 5, 1, x=BinOp("/", Sqrt(C(2)), C(2)), y=C(F(1, 3)),
                  texts=("sqrt(2) / 2", "1/3"), columns=(1, 14)),
        PointSpec(3, 6, 1, x=C(1), y=C(2), texts=("1", "2"), columns=(1, 4)),
        PointSpec(4, 7, 1, x=BinOp("/", Sqrt(C(2)), C(2)), y=C(F(-1, 3)),
                  texts=("sqrt(2) / 2", "- 1/3"), columns=(1, 14)),
        PointSpec(5, 8, 1, r=C(2), turn=F(1, 3), texts=("2", "1/3"), columns=(7, 9)),
        PointSpec(6, 9, 2, r=Trig("cos", F(1, 5)), turn=F(-1, 4),
                  texts=("cos(pi/5)", "-1/4"), columns=(8, 19)),
        PointSpec(7, 10, 1, x=C(3), y=C(3), texts=("(1 + 2)", "(3)"), columns=(1, 9)),
    ))


@pytest.mark.parametrize("line, x, y", [
    ("1 -2", 1, -2), ("1 - 2 3", -1, 3), ("1 -2 3", -1, 3), ("-1 -1", -1, -1),
    ("1/2 -1/2", F(1, 2), F(-1, 2)), ("2^-1 2", F(1, 2), 2), ("1 +2", 1, 2),
    ("(1) (2)", 1, 2), ("1 (2)", 1, 2), ("(1 - 2) -3", -1, -3), ("1,-2", 1, -2),
    ("1e-3 2E+2", F(1, 1000), 200), ("  1\t\t2  ", 1, 2), ("1 2\r", 1, 2),
    ("sqrt (4) 2", None, 2), ("sqrt(2)*sqrt(2) 0", None, 0),
])
def test_plain_text_split_rule(line, x, y):
    point = txt(line).points[0]
    if x is not None:
        assert point.x == C(x)
    assert point.y == C(y)


@pytest.mark.parametrize("line, column, words", [
    ("1 - 2 -3", 7, "ambiguous"),
    ("1 + 2 +3", 7, "ambiguous"),
    ("1 2 3", 5, "more than two expressions"),
    ("1", 2, "expected two expressions"),
    ("sqrt(2)/2", 10, "expected two expressions"),
    ("1, 2, 3", 5, "unexpected character ','"),
    ("1 ,", 4, "empty expression"),
    (", 1", 1, "empty expression"),
    ("x 2", 1, "unknown name 'x'"),
    ("1 y", 3, "unknown name 'y'"),
    ("1 2)", 4, "unbalanced ')'"),
    ("1 -2 -3 )", 9, "unbalanced ')'"),
    ("(1 2", 4, "expected ')'"),
    ("1 2e", 4, "malformed decimal exponent"),
    ("1 \x00", 3, "unexpected character '\\x00'"),
    ("1 pi", 3, "transcendental"),
    ("1 sqrt(-1)", 3, "negative"),
    ("1/0 1", 3, "division by zero"),
    ("polar 1 sqrt(2)", 9, "turn must be a rational"),
    ("polar 1 pi", 9, "transcendental"),
    ("polar 1", 8, "expected two expressions"),
    ("polar", 6, "empty expression"),
    ("  [1, 2]", 3, "unexpected character '['"),
    ("1 __import__('os')", 3, "unknown name"),
])
def test_plain_text_errors_are_located(line, column, words):
    err = txt_error("# header\n" + line + "\n")
    assert words in err.message
    assert (err.source, err.line, err.column) == ("case.txt", 2, column)


def test_plain_text_needs_a_point():
    for text in ["", "\n\n", "# only a comment\n", "   \n\t\n"]:
        assert "no points" in txt_error(text).message


def test_plain_text_line_length_limit():
    assert "line is too long" in txt_error("1 " * 20_000).message
    assert txt("1" + " " * 15_000 + "2").points[0].y == C(2)


def test_crlf_and_bom_free_text():
    cfg = txt("1 2\r\n3 4\r\n")
    assert [(p.x, p.y, p.line) for p in cfg.points] == [(C(1), C(2), 1), (C(3), C(4), 2)]


# ---------------------------------------------------------------- files

def test_read_toml_and_txt_files(tmp_path):
    (tmp_path / "a.toml").write_text(SPEC_EXAMPLE)
    (tmp_path / "b.txt").write_text("0 0\n1 1\n")
    (tmp_path / "c.conf").write_text("# TOML after all\n\nformat = 1\npoints = [[1, 2]]\n")
    (tmp_path / "d").write_text("0 0\n")
    (tmp_path / "e.TOML").write_bytes(b"\xef\xbb\xbfformat = 1\npoints = [[1, 2]]\n")
    assert read_config(tmp_path / "a.toml") == toml(SPEC_EXAMPLE).__class__(
        **{**toml(SPEC_EXAMPLE).__dict__, "source": str(tmp_path / "a.toml")})
    assert len(read_config(str(tmp_path / "b.txt")).points) == 2
    assert read_config(tmp_path / "c.conf").points[0].y == C(2)
    assert read_config(tmp_path / "d").source == str(tmp_path / "d")
    assert read_config(tmp_path / "e.TOML").points[0].x == C(1)


def test_unreadable_files_are_input_errors(tmp_path):
    with pytest.raises(InputError, match="no such file") as info:
        read_config(tmp_path / "missing.toml")
    assert info.value.source == str(tmp_path / "missing.toml")
    with pytest.raises(InputError, match="is a directory"):
        read_config(tmp_path)
    (tmp_path / "latin1.txt").write_bytes(b"0 0\n1 \xe9\n")
    with pytest.raises(InputError, match="not UTF-8") as info:
        read_config(tmp_path / "latin1.txt")
    assert (info.value.line, info.value.column) == (2, 3)


def test_standard_input(monkeypatch):
    monkeypatch.setattr(sys, "stdin", io.TextIOWrapper(io.BytesIO(b"0 0\n1 1\n")))
    cfg = read_config("-")
    assert cfg.source == "<stdin>" and len(cfg.points) == 2
    monkeypatch.setattr(sys, "stdin", io.TextIOWrapper(io.BytesIO(b"format = 1\npoints=[[1,2]]")))
    assert read_config("-").points[0].y == C(2)
    monkeypatch.setattr(sys, "stdin", io.TextIOWrapper(io.BytesIO(b"0 x\n")))
    with pytest.raises(ExpressionError) as info:
        read_config("-")
    assert str(info.value).startswith("<stdin>:1:3: unknown name 'x'")


def test_unknown_kind_is_a_programming_error():
    with pytest.raises(ValueError):
        parse_config_text("0 0", "x", "yaml")


# ---------------------------------------------------------------- properties

def _check_total(text: str, kind: str) -> None:
    try:
        cfg = parse_config_text(text, "fuzz", kind)
    except InputError as err:
        assert err.source == "fuzz"
    else:
        assert cfg.points and all(isinstance(p, PointSpec) for p in cfg.points)


@settings(max_examples=300, deadline=None)
@given(st.text(), st.sampled_from(["toml", "txt"]))
def test_arbitrary_text_gives_a_config_or_an_input_error(text, kind):
    _check_total(text, kind)


_FRAGMENTS = ["format = 1\n", "format = 2\n", "points = [", "]\n", "[\"1\", \"2\"]", ", ",
              "{ r = \"1\", turn = \"1/3\" }", "[1, 2]", "[0.5, 1]", "\"sqrt(2)\"", "\"pi\"",
              "\n[expect]\n", "n = 3\n", "orderable = true\n", "group = \"C3\"\n",
              "sec_radius_squared = \"2\"\n", "model = \"fat\"\n", "lemmas = [\"a\"]\n",
              "# c\n", "\n", "[[points]]\nr = \"1\"\nturn = \"0\"\n", "{", "}", "=", "\"",
              "1 2\n", "1, 2\n", "polar 1 1/2\n", "sqrt(2)/2 -1\n", "1 - 2 -3\n", "x y\n",
              "cos(pi/3) sin(pi/3)\n", "(", ")", " ", "-", "1e-3", "pi", "turn", "r = "]


@settings(max_examples=500, deadline=None)
@given(st.lists(st.sampled_from(_FRAGMENTS), max_size=12), st.sampled_from(["toml", "txt"]))
def test_format_fragments_give_a_config_or_an_input_error(fragments, kind):
    _check_total("".join(fragments), kind)
