"""exactsym: the leader-election and gathering algorithms of Gan Chaudhuri and
Mukhopadhyaya, *Leader Election and Gathering for Asynchronous Transparent Fat Robots
without Chirality*, made executable with exact arithmetic and checked against the truth.

The Python API (``docs/api.md``), in the style of networkx: plain functions over plain
immutable values.

* :func:`load` -- read a configuration file (:class:`Configuration`);
  ``Configuration.from_points`` builds one from exact numbers;
* :func:`analyse` -- everything ``exactsym check`` computes, once: the SEC and the levels,
  the ground truth, the paper's verdicts and the audit (:class:`Analysis`);
* :func:`symmetry_group` -- the ground truth alone (:class:`SymmetryGroup`);
* :func:`plot` -- a picture (needs the ``plot`` extra, matplotlib);
* :func:`report_text` / :func:`report_json` -- the two renderings of an analysis.

>>> from exactsym import load, analyse, symmetry_group
>>> a = analyse(load("cases/examples/chiral-nine-gon.toml"))
>>> a.truth.name, a.truth.orderable, a.paper.orderable
('C3', False, True)
>>> sorted({d["statement"] for d in a.audit["discrepancies"]})[:3]
['ElectLeader', 'GatheringPattern', 'MakeAsym']

The names are loaded on first use, so that ``import exactsym.checker`` (the standalone
certificate checker) loads nothing else and ``exactsym --version`` stays fast; ``plot``
imports matplotlib only when it is called.
"""

from importlib import import_module

from .version import __version__

#: name -> the module that defines it (imported on first use).
_EXPORTS = {
    "load": ".geometry.configuration", "Configuration": ".geometry.configuration",
    "analyse": ".analysis", "Analysis": ".analysis", "Options": ".analysis",
    "symmetry_group": ".truth.symmetry", "SymmetryGroup": ".truth.symmetry",
    "report_text": ".report.check", "report_json": ".report.check",
    "near_symmetry_hint": ".truth.near_symmetry",
    "InputError": ".errors",
}

__all__ = sorted(_EXPORTS) + ["plot", "__version__"]


def plot(config_or_analysis, path=None, show_paper: bool = False, show_audit: bool = False):
    """Draw a configuration (a :class:`Configuration`, a file name, or an
    :class:`Analysis`, whose results are drawn, not recomputed); write it to ``path``
    (``.svg``, ``.png`` or ``.pdf``) when given; return the matplotlib ``Figure``.

    ``show_paper`` adds the lines of symmetry the paper's tests report and the paper's
    leader; ``show_audit`` the witness of each statement of the paper that fails here.
    Raises ``exactsym.pictures.PlotUnavailable`` without matplotlib (the ``plot``
    extra).  Everything drawn is in ``docs/pictures.md``
    (:func:`exactsym.pictures.plot` does the work).

    >>> import os, tempfile
    >>> from exactsym import analyse, load, plot
    >>> a = analyse(load("cases/examples/chiral-nine-gon.toml"))
    >>> out = os.path.join(tempfile.mkdtemp(), "nine.svg")
    >>> fig = plot(a, out, show_audit=True)
    >>> open(out).read().count('id="robot-')
    9
    """
    from .pictures import plot as draw
    return draw(config_or_analysis, path, show_paper=show_paper, show_audit=show_audit)


def __getattr__(name):
    if name in _EXPORTS:
        value = getattr(import_module(_EXPORTS[name], __name__), name)
        globals()[name] = value
        return value
    raise AttributeError(f"module 'exactsym' has no attribute {name!r}")


def __dir__():
    return sorted(set(globals()) | set(_EXPORTS))
