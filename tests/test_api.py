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
              "exactsym.exact.text_numbers", "exactsym.report.summary"]
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
