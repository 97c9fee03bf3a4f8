"""Pictures of configurations and runs (the ``plot`` extra: matplotlib).

:func:`plot` draws a configuration: its robots (unit discs for fat robots), the SEC
and each level's circle, the ground truth's mirrors and rotation centre, its leader
and canonical ordering; optionally the lines the paper's tests report and the
witnesses of the audit.  Floats are used for drawing only.
"""

from __future__ import annotations

from .draw import PlotUnavailable

__all__ = ["plot", "PlotUnavailable"]


def plot(config_or_analysis, path=None, show_paper: bool = False, show_audit: bool = False):
    """Draw a configuration; save it to ``path`` (``.svg``, ``.png`` or ``.pdf``) when
    given, and return the matplotlib ``Figure``.

    ``config_or_analysis``: an :class:`exactsym.analysis.Analysis` (what it holds is drawn;
    a part it lacks is analysed once), a
    :class:`exactsym.geometry.configuration.Configuration` or a path to a configuration
    file (analysed once, with the parts the picture shows).
    ``show_paper``: also draw the lines of symmetry the paper's tests report per level
    (straight: dashed; skew: the pairs the half-turn swaps, dotted) and the paper's
    leader (a square).  ``show_audit``: also draw the witness of each statement of the
    paper that fails on this configuration, labelled in the legend.  Both run the
    paper's algorithms (slower on large inputs).  The output is deterministic: the
    same input gives the same SVG, byte for byte.

    Raises :class:`PlotUnavailable` when matplotlib is missing (install the ``plot``
    extra), ``ValueError`` for an unknown picture format.

    >>> from exactsym.geometry.configuration import Configuration
    >>> from exactsym.pictures import plot
    >>> square = Configuration.from_points([(1, 0), (0, 1), (-1, 0), (0, -1)])
    >>> fig = plot(square)
    >>> sorted(a.get_gid() for a in fig.axes[0].lines if (a.get_gid() or "").startswith("mirror"))
    ['mirror-0', 'mirror-1', 'mirror-2', 'mirror-3']
    >>> import tempfile, os
    >>> out = os.path.join(tempfile.mkdtemp(), "square.svg")
    >>> _ = plot(square, out)
    >>> open(out).read().count('id="robot-')
    4
    """
    from . import _bridge
    from .draw import figure, matplotlib_modules, save
    matplotlib_modules()            # fail early, naming the extra
    subject = config_or_analysis
    if isinstance(subject, (str, bytes)) or hasattr(subject, "__fspath__"):
        subject = _bridge.load_configuration(subject)
    # an analysis's results are drawn (what it lacks is analysed once, _bridge.analysis_of)
    scene = _bridge.scene_of(subject, show_paper=show_paper, show_audit=show_audit)
    fig = figure(scene, show_paper=show_paper, show_audit=show_audit)
    if path is not None:
        save(fig, path)
    return fig
