"""The Python API: `from exactsym import load, analyse, symmetry_group, plot`, the examples
in its docstrings (doctested from the repository's root), and what importing it costs."""

import doctest
import importlib
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent

DOCUMENTED = ["exactsym", "exactsym.geometry.configuration", "exactsym.analysis", "exactsym.truth.symmetry",
              "exactsym.exact.text_numbers", "exactsym.report.summary",
              "exactsym.io.sympy_trees"]
# (exactsym.truth.near_symmetry and exactsym.pictures are doctested by their own test modules)


@pytest.mark.parametrize("name", DOCUMENTED)
def test_docstring_examples_run(name, monkeypatch):
    monkeypatch.chdir(ROOT)
    result = doctest.testmod(importlib.import_module(name), optionflags=doctest.ELLIPSIS)
    assert result.attempted > 0 and result.failed == 0, result


def test_the_four_names_and_their_docstrings():
    import exactsym
    from exactsym import analyse
    from exactsym import load
    from exactsym import plot
    from exactsym import symmetry_group
    for function in (load, analyse, symmetry_group, plot):
        assert callable(function) and ">>> " in function.__doc__, function
    assert set(exactsym.__all__) >= {"load", "analyse", "symmetry_group", "plot"}
    assert "plot" in dir(exactsym)
    with pytest.raises(AttributeError):
        exactsym.no_such_name


def test_importing_exactsym_loads_neither_the_kernel_nor_matplotlib():
    """`import exactsym` is lazy; `analyse` loads the kernel but not matplotlib; `plot`
    loads matplotlib when called."""
    code = ("import sys, exactsym\n"
            "heavy = lambda: sorted(m for m in ('flint', 'matplotlib', 'exactsym.analysis') "
            "if m in sys.modules)\n"
            "print(heavy())\n"
            "from exactsym import analyse, plot\n"
            "print(heavy())\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         cwd=ROOT, timeout=120)
    assert out.stdout.split("\n")[:2] == ["[]", "['exactsym.analysis', 'flint']"], out


# ---------------------------------------------------------------- issue 34, item 6
def test_gather_sweep_certify_and_to_sympy_are_public_and_doctested():
    import exactsym
    assert set(exactsym.__all__) >= {"gather", "sweep", "certify", "to_sympy"}
    for name in ("gather", "sweep", "certify", "to_sympy"):
        assert callable(getattr(exactsym, name)), name
        assert ">>> " in getattr(exactsym, name).__doc__, name
    # the packages have other names (certificates, sweeps): importing them rebinds nothing
    function = exactsym.certify
    import exactsym.certificates.certificate  # noqa: F401
    import exactsym.sweeps.engine  # noqa: F401
    assert exactsym.certify is function and exactsym.sweep.__doc__.startswith("Run the analysis")


def test_from_points_reads_sympy_numbers_and_strings_exactly():
    import sympy
    from fractions import Fraction
    from exactsym import Configuration, symmetry_group
    half, root = sympy.Rational(1, 2), sympy.sqrt(3) / 2
    by_sympy = Configuration.from_points([(1, 0), (-half, root), (-half, -root)])
    by_text = Configuration.from_points([("1", "0"), ("-1/2", "sqrt(3)/2"),
                                         ("-0.5", "-sqrt(3)/2")])
    assert symmetry_group(by_sympy).name == symmetry_group(by_text).name == "D3"
    assert by_sympy.points == by_text.points
    # cos/sin of rational multiples of pi, walked (sympy keeps cos(2*pi/7) unevaluated)
    seven = [(sympy.cos(2 * sympy.pi * k / 7), sympy.sin(2 * sympy.pi * k / 7))
             for k in range(7)]
    assert symmetry_group(Configuration.from_points(seven)).name == "D7"
    # mixed with Python's exact numbers
    mixed = Configuration.from_points([(Fraction(1, 3), sympy.sqrt(2)), (0, "1")])
    assert mixed.to_sympy() == ((sympy.Rational(1, 3), sympy.sqrt(2)), (0, 1))


@pytest.mark.parametrize("value, words", [
    (0.5, "a float is not exact"),
    ("sympy.Float(0.25)", "a float is not exact"),
    ("2^(1/3)", "exponent"),
    ("cbrt", "point 1, x"),
])
def test_from_points_refuses_what_is_not_exact_in_one_line(value, words):
    import sympy
    from exactsym import Configuration, InputError
    if value == "sympy.Float(0.25)":
        value = sympy.Float(0.25)
    if value == "cbrt":
        value = sympy.Integer(2) ** sympy.Rational(1, 3)
    with pytest.raises(InputError) as err:
        Configuration.from_points([(0, 0), (value, 1)])
    assert words in str(err.value) and "\n" not in str(err.value)


def test_to_sympy_of_numbers_points_and_configurations_reads_back():
    import sympy
    from exactsym import Configuration, load, symmetry_group, to_sympy
    config = load(ROOT / "cases/examples/chiral-nine-gon.toml")
    points = to_sympy(config)
    assert len(points) == 9 and points[1] == (-2, 2 * sympy.sqrt(3))
    again = Configuration.from_points(points)       # read back: the same numbers
    assert symmetry_group(again).name == "C3"
    def radii(c):
        return [str(to_sympy(x * x + y * y)) for x, y in c.points]
    assert radii(again) == radii(config)


def test_configuration_repr_says_what_it_is():
    from exactsym import Configuration, load
    config = load(ROOT / "cases/examples/chiral-nine-gon.toml")
    assert repr(config) == ("<Configuration 'Nine robots with threefold rotational symmetry "
                            f"and no mirror': 9 points from {config.source}>")
    assert repr(Configuration.from_points([(1, 0), (0, "1/2")])) == \
        "<Configuration: 2 points from <memory>: (1, 0), (0, 1/2)>"


def test_api_page_doctests_from_another_directory(tmp_path):
    """`python -m doctest docs/api.md` passes outside the repository's root."""
    done = subprocess.run([sys.executable, "-m", "doctest", str(ROOT / "docs" / "api.md")],
                          capture_output=True, text=True, cwd=tmp_path, timeout=600)
    assert done.returncode == 0 and done.stdout == "", done.stdout[-3000:]
