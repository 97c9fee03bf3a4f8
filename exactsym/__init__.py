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
* :func:`plot` -- a picture (matplotlib, imported when called);
* :func:`report_text` / :func:`report_json` -- the two renderings of an analysis;
* :func:`certify` -- a certificate of the symmetry verdict, checked by the standalone checker;
* :func:`gather` -- the paper's gathering algorithm, simulated exactly;
* :func:`sweep` -- a whole family of configurations, summarised;
* :func:`to_sympy` -- exact numbers, points and configurations out as sympy numbers
  (``Configuration.from_points`` reads sympy numbers and strings in).

>>> from exactsym import load, analyse, symmetry_group
>>> a = analyse(load("cases/examples/chiral-nine-gon.toml"))
>>> a.truth.name, a.truth.orderable, a.paper.orderable
('C3', False, True)
>>> sorted({d["statement"] for d in a.audit.discrepancies})[:3]
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
    "to_sympy": ".geometry.configuration",
}

__all__ = sorted(_EXPORTS) + ["certify", "gather", "plot", "sweep", "__version__"]


def _config(config_or_path):
    if isinstance(config_or_path, (str, bytes)) or hasattr(config_or_path, "__fspath__"):
        from .geometry.configuration import load
        return load(config_or_path)
    return config_or_path


def certify(config_or_path) -> dict:
    """A certificate of the ground truth's verdict (group, orderability) on a
    configuration (or a file name): a JSON-ready dict that :mod:`exactsym.checker` (the
    standard library only) has accepted before it is returned (``docs/certificates.md``).
    Raises ``exactsym.certificates.certificate.CertificateError`` when none can be made.

    >>> from exactsym import Configuration, certify
    >>> from exactsym.checker import verify_certificate
    >>> cert = certify(Configuration.from_points([(1, 0), (0, 1), (-1, 0), (0, -1)]))
    >>> cert["claim"]["group"], cert["claim"]["orderable"], verify_certificate(cert)[0]
    ('D4', False, True)
    """
    from .cli.certify import checked_certificate       # the runner of the checker
    return checked_certificate(_config(config_or_path))


def gather(config_or_path, scheduler: str = "async", seed: int = 0,
           algorithm: str = "paper", readings=(), max_events: int = 2000):
    """Simulate GatheringPattern and FormGPattern (``algorithm="corrected"``: the corrected
    variant, not the paper's) on fat robots at rational points, under the adversarial
    ``scheduler`` (``centralised``, ``fsync``, ``ssync``, ``async``) drawing its choices
    from ``seed``, with every invariant I1..I10 checked (``docs/gathering.md``);
    ``readings``: the readings of the paper's ambiguous lines (``["A3=all"]``).  Returns
    the run's result: ``outcome`` (``gathered``, ``violated``, ...), ``violation`` (the
    statement's label, robots and instant) and ``detail``.

    >>> from exactsym import gather
    >>> run = gather("cases/gathering/obstacle-beside-path.toml", scheduler="centralised",
    ...              seed=1, readings=["A3=all"])
    >>> run.outcome, run.label, sorted(run.violation["robots"])
    ('violated', 'gather-no-obstacle', [0, 1])
    >>> gather("cases/gathering/corrected-obstacle-beside-path.toml", "centralised", 1,
    ...        algorithm="corrected").outcome
    'gathered'
    """
    from .gathering.cases import run_settings, settings_of
    from .gathering.paper_bridge import read_case
    if isinstance(config_or_path, (str, bytes)) or hasattr(config_or_path, "__fspath__"):
        points = read_case(config_or_path)[0]
    else:
        points = [tuple(p) for p in config_or_path.points]
    return run_settings(points, settings_of({
        "gather_scheduler": scheduler, "gather_seed": seed, "gather_algorithm": algorithm,
        "gather_readings": list(readings), "gather_max_events": max_events}))


def sweep(family: str, out, what: str = "audit", serial: bool = True, workers: int = 2,
           resume: bool = False):
    """Run the analysis ``what`` (``truth``, ``paper``, ``audit``, ``gather``) over every
    configuration of ``family`` (``roots:M:K``, ``grid:N:K``, ...: ``docs/sweeps.md``),
    recording each in the results file ``out``; ``serial=False`` runs on ``workers`` of a
    local Dask cluster (the ``sweep`` extra).  Returns the summary: per statement, the
    configurations where its hypotheses hold, where it fails, and the smallest
    counterexample.

    >>> import os, tempfile
    >>> from exactsym import sweep
    >>> s = sweep("roots:6:<=3", os.path.join(tempfile.mkdtemp(), "r.jsonl"), what="truth")
    >>> s.configurations, s.groups["D3"]
    (7, 1)
    """
    from .sweeps import analysis_bridge as bridge
    from .sweeps.engine import SweepOptions, run_sweep
    from .sweeps.families import parse_family
    from .sweeps.summary import summarise
    run_sweep(parse_family(family, bridge.file_points), what, out, resume,
              SweepOptions(workers=workers, serial=serial))
    return summarise(out)


def plot(config_or_analysis, path=None, show_paper: bool = False, show_audit: bool = False):
    """Draw a configuration (a :class:`Configuration`, a file name, or an
    :class:`Analysis`, whose results are drawn, not recomputed); write it to ``path``
    (``.svg``, ``.png`` or ``.pdf``) when given; return the matplotlib ``Figure``.

    ``show_paper`` adds the lines of symmetry the paper's tests report and the paper's
    leader; ``show_audit`` the witness of each statement of the paper that fails here.
    Raises ``exactsym.pictures.PlotUnavailable`` without matplotlib (a dependency of
    exactsym).  Everything drawn is in ``docs/pictures.md``
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
