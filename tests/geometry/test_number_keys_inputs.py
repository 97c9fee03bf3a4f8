"""Inputs that colliding number keys answered wrongly (exit 0 with a wrong verdict)."""

from exactsym.io.fileformat import parse_config_text
from exactsym.geometry.configuration import from_file
from exactsym.geometry.levels import levels_of
from exactsym.truth.symmetry import symmetry_group


def _load(text):
    return from_file(parse_config_text(text, "<test>", "toml"))


def test_one_plus_root2_is_not_one():
    config = _load('format = 1\npoints = [["sqrt(3+2*sqrt(2))", "0"], ["1", "0"]]\n')
    assert config.n == 2


def test_rhombus_with_nested_half_diagonal_has_two_levels():
    config = _load('format = 1\npoints = [\n'
                   '{ r = "sqrt(9+4*sqrt(2))", turn = "0" }, { r = "sqrt(9+4*sqrt(2))", turn = "1/2" },\n'
                   '{ r = "3/2", turn = "1/4" }, { r = "3/2", turn = "3/4" }]\n')
    levels = levels_of(config).levels
    assert [sorted(level.points) for level in levels] == [[2, 3], [0, 1]]
    assert symmetry_group(config).name == "D2"


def test_scalene_triangle_with_nested_coordinate():
    config = _load('format = 1\npoints = [["sqrt(3+2*sqrt(2))", "0"], ["1", "2"], ["-3", "1/2"]]\n')
    assert len(levels_of(config).levels) == 2
    assert symmetry_group(config).name == "C1"
