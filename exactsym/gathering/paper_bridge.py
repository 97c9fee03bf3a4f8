"""The one place where the gathering simulator imports the rest of exactsym.

The paper layer (Preprocess, MakeAsym, ElectLeader on concentric polygons) works on
:class:`~exactsym.geometry.configuration.Configuration` objects whose numbers live in one
number system of the kernel; the simulator holds points as multiquadratic elements.
:func:`paper_decision` converts a snapshot of R, runs GatheringPattern's decision and
the leader election exactly as the paper layer implements them, and returns who moves
and where (targets of epsilon moves are rebuilt here, in the multiquadratic field, from
the paper layer's rotation parameters: the same rational rotation about the SEC centre).

When the kernel cannot hold the snapshot's numbers (a field over the size limit), the
decision is ``complete=False``: the simulator then stops as undecided rather than guess.
A snapshot at a root of a cubic or quartic factor (numbers of K(alpha),
:mod:`~exactsym.exact.algebraic.algebraic_numbers`) is written in one kernel field Q(gamma)
(:func:`.algebraic_kernel.kernel_configuration`); a square root the paper layer then
asks for outside that field makes the decision incomplete in the same way.
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction

from ..errors import InputError
from ..exact import evaluate, fmpq, number_system
from ..exact.algebraic.algebraic_numbers import is_algebraic
from ..exact.algebraic.interface import is_multiquadratic
from ..geometry.configuration import Configuration, from_file
from ..geometry.levels import levels_of as compute_rings
from ..io.expr import parse_expression
from ..io.fileformat import read_config
from ..paper.family import (concentric_polygons, elect_leader, is_symmetric_family,
                            is_symmetric_polygon, make_asym, preprocess)
from .algebraic_kernel import kernel_configuration
from .start_numbers import start_points

__all__ = ["PaperDecision", "paper_decision", "configuration_of", "GatheringInputError",
           "read_case"]

GatheringInputError = InputError


@dataclass(frozen=True)
class PaperMove:
    """A move the paper's leader election makes: ``robot`` (index in the snapshot),
    ``algorithm`` (MakeAsym or Make_SymToAsym), ``kind`` ("epsilon", "to-G_t-circle",
    "off-centre"), ``tau`` (the rational rotation parameter of an epsilon move)."""
    robot: int
    algorithm: str
    kind: str
    tau: Fraction | None
    target_ring_robot: int | None = None


@dataclass(frozen=True)
class PaperDecision:
    possible: bool          # GatheringPattern: G' not in O_S
    orderable: bool         # MakeAsym did not report "not orderable"
    moves: tuple            # PaperMove, in the order the paper makes them
    leader: int | None      # ElectLeader's robot (after MakeAsym's moves)
    complete: bool
    detail: str = ""


def _algebraic(points) -> bool:
    return any(is_algebraic(c) for p in points for c in p)


def configuration_of(points) -> Configuration:
    """A kernel configuration of MQ points (rational when they all are), of tower
    numbers, or of K(alpha) numbers."""
    if _algebraic(points):
        return kernel_configuration(points)
    if all(x.is_rational() and y.is_rational() for x, y in points):
        return Configuration.from_points([(x.to_fmpq(), y.to_fmpq()) for x, y in points])
    exprs = [parse_expression(c.text(), written=True) for p in points for c in p]
    system = number_system(exprs)
    vals = [evaluate(e, system) for e in exprs]
    return Configuration.from_points(list(zip(vals[0::2], vals[1::2])), system=system)


def _tau(amount) -> Fraction | None:
    if amount is None:
        return None
    text = str(amount).replace("rotation with tau =", "").strip()
    try:
        return Fraction(text)
    except ValueError:
        return None


def paper_decision(points, orientation: int = 1, reading: str = "literal") -> PaperDecision:
    """GatheringPattern lines 1-6 on the snapshot ``points`` of R (MQ pairs), as seen by an
    observer of handedness ``orientation``: "not possible" (G' in O_S), MakeAsym's moves
    when G_t is symmetric (the caller recomputes on the moved positions for the leader,
    as every oblivious robot would), else ElectLeader's moves and leader.  ``reading``:
    the paper layer's reading of Elect_Leader_Asym's tuples ("literal": (CW, ACW) in the
    observer's handedness; "unordered": each tuple sorted, the same in both)."""
    try:
        config = configuration_of(points)
        ring_data = compute_rings(config)
    except (InputError, ArithmeticError, NotImplementedError, ValueError) as err:
        return PaperDecision(False, False, (), None, False, f"kernel: {err}")
    if not _algebraic(points):
        return _decision(config, ring_data, orientation, reading)
    try:        # Q(gamma) holds the snapshot, not every square root the layer may ask for
        return _decision(config, ring_data, orientation, reading)
    except (ArithmeticError, NotImplementedError, ValueError) as err:
        return PaperDecision(False, False, (), None, False, f"kernel: {err}")


def _decision(config, ring_data, orientation: int, reading: str) -> PaperDecision:
    G = concentric_polygons(config, ring_data)
    Gp = preprocess(G, [])
    if is_symmetric_family(Gp):
        return PaperDecision(False, False, (), None, True, "G' is in O_S")
    trace: list = []
    if is_symmetric_polygon(Gp[-1]):
        res = make_asym(config, ring_data, Gp, trace, orientation, reading)
        if res.outcome == "not-orderable":
            return PaperDecision(True, False, (), None, True, "MakeAsym: not orderable")
        moves = tuple(PaperMove(m["robot"], m["algorithm"], m["kind"], _tau(m.get("amount")),
                                Gp[-1].own[0] if m["kind"] == "to-G_t-circle" else None)
                      for m in res.moves)
        # "undecided": the paper layer could not place a robot exactly (a radial move to
        # G_t's circle by an irrational ratio); the simulator places it in the
        # multiquadratic field
        placeable = bool(moves) and all(m.kind in ("epsilon", "to-G_t-circle") for m in moves)
        if res.outcome == "orderable" or (res.outcome == "undecided" and placeable):
            return PaperDecision(True, True, moves, None, True, "MakeAsym moves first")
        return PaperDecision(True, True, moves, None, False, f"MakeAsym: {res.outcome}")
    el = elect_leader(Gp, trace, orientation, reading)
    moves = tuple(PaperMove(m["robot"], m["algorithm"], m["kind"], _tau(m.get("amount")))
                  for m in el.moves)
    return PaperDecision(True, True, moves, el.leader, el.computed,
                         f"ElectLeader: {el.branch}")


def read_case(path):
    """Read a case file (configuration format 1): ``(points, name, expect, source)``.
    Every start ``check`` accepts is read (its validation first: distinct points, the fat
    model); rational points as fmpq pairs, others as numbers of the motion's one number
    system (:func:`.start_numbers.start_points`: square roots, nested radicals, cos/sin of
    rational turns, within its documented bounds); raises :class:`InputError` with the
    file location (beyond a bound: the bound named)."""
    parsed = read_config(path)
    config = from_file(parsed)
    if config.radii is None and all(isinstance(x, fmpq) and isinstance(y, fmpq)
                                    for x, y in config.points):
        pts = [(x, y) for x, y in config.points]
    else:
        pts = start_points(parsed.points, config.source)
        if all(is_multiquadratic(c) and c.is_rational() for p in pts for c in p):
            pts = [(x.to_fmpq(), y.to_fmpq()) for x, y in pts]
    return pts, config.name, dict(config.expect), config.source
