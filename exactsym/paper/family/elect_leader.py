"""``ElectLeader`` (Section 4.2) on G', and Elect_Leader_Asym applied to a polygon of
G' (``lem-asym-ord``, ``lem-asym-pair-ord``).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Sequence

from .. import polygon as P
from ...exact import number_text
from ..circle_polygon import CirclePolygon
from .concentric import Ring, mirror_lines
from .limits import MAX_QUADRATIC_N
from .projection import coincidence_note, radial_projection, robot_in
from .trace import trace_entry


def first_of_ring_in_ordering(poly: CirclePolygon, leader: P.AsymLeader, ring: Ring):
    """The first vertex of the ordering whose label holds a robot of ``ring``:
    ``(storage index, robot)`` or ``(None, None)``."""
    for idx in leader.ordering:
        robot = robot_in(poly.labels[idx], ring)
        if robot is not None:
            return idx, robot
    return None, None


def elect_leader_asym_on(trace, alg, line, ring_poly: Ring, target: Ring, orientation, reading,
                         statement, branch=None, rnd=None):
    """Elect_Leader_Asym on ``ring_poly`` and the first vertex of ``target`` in its ordering.
    Records a failure when the lexicographic minimum is tied (the polygon is symmetric:
    the claim that it is orderable is false)."""
    poly = ring_poly.polygon
    if poly.n > MAX_QUADRATIC_N:
        trace_entry(trace, alg, line, [ring_poly.name], statement,
                    f"Elect_Leader_Asym not run: {poly.n} vertices (O(n^2) strings; limit "
                    f"{MAX_QUADRATIC_N})", branch=branch, round=rnd)
        return None, "too-large"
    res = P.elect_leader_asym(poly, orientation, reading)
    idx, robot = first_of_ring_in_ordering(poly, res, target)
    printed = None if res.leader is None else robot_in(poly.labels[res.leader], ring_poly)
    detail = (f"Elect_Leader_Asym({ring_poly.name}): lexicographic minimum at "
              f"{list(poly.labels[res.v_m])}, ordering by {res.direction}; the printed "
              f"v_l is robot {printed}; the first vertex of {target.name} in the ordering is "
              f"robot {robot}")
    trace_entry(trace, alg, line, [ring_poly.name, target.name], statement, detail,
                robots=[robot] if robot is not None else None, branch=branch, round=rnd,
                uses="Elect_Leader_Asym")
    if printed != robot:
        printed_line(trace, alg, line, ring_poly, target, printed, robot, rnd)
    if res.tie:
        trace_entry(trace, alg, line, [ring_poly.name],
                    "obs-merg-asym-pair" if len(ring_poly.levels) > 1 else "lem-asym-ord",
                    f"{ring_poly.name} is assumed asymmetric (orderable) but the lexicographic "
                    f"minimum of the (CW, ACW) tuples is attained at more than one vertex",
                    holds=False, labelling_dependent=True, round=rnd)
    return robot, None


def printed_line(trace, alg, line, ring_poly: Ring, target: Ring, printed, robot, rnd) -> None:
    """The printed line's own result beside exactsym's repair (issue 32).  The printed
    ``v_l = Elect_Leader_Asym(...)`` is the first vertex of the ordering whose removal
    leaves an asymmetric polygon; the caller needs a robot of ``target``, which exactsym
    takes as the first vertex of ``target`` in the ordering.  A defect of the printed
    algorithm (``holds`` False): it elects nobody, or (ElectLeader, whose output is "a
    leader vertex v_l from G_1") a robot outside G_1.  Otherwise the repair is exactsym's
    choice (MakeAsym's own text restricts v_l to G_t: "such that v_l is in G_t"),
    recorded with ``kind`` "repair", a note."""
    inside = printed is not None and printed in target.robots
    defect = printed is None or (alg == "ElectLeader" and not inside)
    said = "elects nobody (every G \\ v_i is symmetric)" if printed is None else \
        f"returns robot {printed}" + ("" if inside else f", not a robot of {target.name}")
    repair = f"the first vertex of {target.name} in the ordering (exactsym's repair)"
    trace_entry(trace, alg, line, [ring_poly.name, target.name], alg,
                f"line {line} as printed {said}; {repair} is robot {robot}", holds=False,
                witness={"printed": printed, "repair": robot},
                kind=None if defect else "repair", round=rnd,
                reading=f"literal: line {line} as printed, v_l = Elect_Leader_Asym("
                f"{ring_poly.name})" if defect else None,
                rescued_by=repair if defect and robot is not None else None)


def line_four(poly: CirclePolygon, check: P.CheckResult, degree: str = "paper"):
    """ElectLeader's line 4, "G_1 is symmetric with degree of symmetry one and the line of
    symmetry passes through either a single vertex or through two vertices": ``(bool,
    why)``.  "Symmetric" and the degree are what Check_Symmetry_Odd/Even report (the
    algorithms the paper gives for them, lines 1-3; ``degree="lines"`` reads the degree
    as the number of lines of straight symmetry, by the definition).  "The line of
    symmetry" and the vertices on it have no algorithm in the paper: they are evaluated
    by the definition -- the polygon has exactly one exact mirror
    (:func:`exactsym.paper.family.mirror_lines`) and it passes through one or two vertices.
    A 2-gon's only mirror is the perpendicular bisector of its vertices (through none), so
    line 4 is false for it."""
    mirrors = mirror_lines(poly)              # LineKeys: no division
    if degree == "lines":
        deg = len(mirrors)
    elif degree == "paper":
        deg = check.degree
    else:
        raise ValueError("degree must be 'paper' or 'lines'")
    if not check.symmetric:
        return False, f"{check.algorithm} reports G_1 asymmetric"
    if deg != 1:
        return False, f"degree of symmetry {number_text(deg)}, not one"
    if len(mirrors) != 1:
        return False, f"degree one, but G_1 has {len(mirrors)} lines of straight symmetry " \
                      "by the definition, not one"
    on = len(P.vertices_on_line(poly, mirrors[0]))
    if on not in (1, 2):
        return False, "degree one, but the line of symmetry (by the definition) passes " \
                      "through no vertex"
    return True, ("degree one, the line of symmetry passes through "
                  + ("a single vertex" if on == 1 else "two vertices"))


@dataclass
class ElectLeaderResult:
    """``leader``: the configuration index elected (None when none); ``moves``: robots
    moved by Make_SymToAsym; ``branch``: see :data:`BRANCHES`; ``moved_to``: the moved
    robot's direction from C after Make_SymToAsym (a turn, or a vector from C)."""
    leader: int | None
    branch: str
    moves: list = field(default_factory=list)
    computed: bool = True
    moved_to: dict = field(default_factory=dict)    # robot -> its direction after the move


def elect_leader(Gp: Sequence[Ring], trace: list, orientation: int = 1,
                 reading: str = "literal", degree: str = "paper",
                 rnd: int = 1) -> ElectLeaderResult:
    """``ElectLeader`` (Section 4.2) on G' (meant for G' with G_t asymmetric).

    Lines 1-3: Check_Symmetry_Even/Odd(G_1).  Line 4: "G_1 is symmetric with degree of
    symmetry one and the line passes through a single vertex or two vertices"
    (:func:`line_four`: symmetry and degree as the check reports them, the line and the
    vertices on it by the definition); then Make_SymToAsym(G_1) and Elect_Leader_Asym on
    the moved G_1.  Line 8: G_1 asymmetric (as
    Check_Symmetry reports): Elect_Leader_Asym(G_1).  Line 11-12: G_1t (G_1 projected onto G_t's
    circle) and Elect_Leader_Asym(G_1t); the output must be "a leader vertex from G_1":
    the first vertex of G_1 in the ordering of G_1t.  The robot at C as G_1 is a single
    vertex with CW = ACW = (): it is elected (it cannot move on a circle of radius 0)."""
    alg = "ElectLeader"
    g1 = Gp[0]
    gt = Gp[-1]
    if g1.at_centre:
        v = g1.robots[0]
        trace_entry(trace, alg, 3, [g1.name], "obs-asymmetric-polygon",
                    f"{g1.name} is the robot {v} at C: Check_Symmetry_Odd reports degree 1 "
                    "(CW = ACW = ())", round=rnd)
        trace_entry(trace, alg, 6, [g1.name], alg, f"leader: robot {v} (at C)", robots=[v],
                    branch="centre", round=rnd)
        return ElectLeaderResult(v, "centre")
    poly = g1.polygon
    check = P.check_symmetry(poly, orientation)
    trace_entry(trace, alg, 2 if poly.n % 2 == 0 else 3, [g1.name], "obs-asymmetric-polygon",
                f"{check.algorithm}({g1.name}): " + "; ".join(check.reports), round=rnd)
    line4, why = line_four(poly, check, degree)
    if check.symmetric:
        trace_entry(trace, alg, 4, [g1.name], alg, f"line 4 is {'true' if line4 else 'false'}"
                    f": {why}", round=rnd)
    if line4:
        branch = "sym-degree-one"
        axis = list(P.vertices_on_line(poly, mirror_lines(poly)[0]))   # on the mirror
        if poly.n % 2 == 0 and len(axis) >= 2 and \
                P.cw_string(poly, axis[0], orientation) == P.cw_string(poly, axis[1], orientation):
            trace_entry(trace, alg, 5, [g1.name], "Elect_Leader_Sym",
                        f"Elect_Leader_Sym: VI = VJ for the two vertices on the line (robots "
                        f"{[robot_in(poly.labels[a], g1) for a in axis[:2]]}), so 'if VI > VJ "
                        f"return v_i else v_j' picks by the labelling, not by the geometry",
                        holds=False, labelling_dependent=True, round=rnd)
        moved = P.make_sym_to_asym(poly, orientation, degree)
        mover = robot_in(poly.labels[moved.leader], g1) if moved.leader is not None else None
        moves = [{"robot": mover, "algorithm": "Make_SymToAsym", "line": 2, "kind": "epsilon",
                  "amount": number_text(moved.parameter) if moved.parameter is not None
                  else None}] if mover is not None else []
        trace_entry(trace, alg, 5, [g1.name], "Elect_Leader_Sym",
                    f"degree of symmetry one: Make_SymToAsym moves robot {mover} to its right "
                    f"side "
                    f"({'asymmetric now' if moved.asymmetric else 'still symmetric'})",
                    robots=[mover] if mover is not None else None, branch=branch, round=rnd,
                    uses="Make_SymToAsym")
        if not moved.asymmetric:
            # a single vertex included: the paper gives it degree one (line 4 calls
            # Make_SymToAsym), and no epsilon move makes one point asymmetric
            trace_entry(trace, alg, 5, [g1.name], "Make_SymToAsym",
                        "Make_SymToAsym is meant to make G_1 asymmetric; it is not"
                        + (" (a single vertex is symmetric wherever it moves)"
                           if poly.n == 1 else ""), holds=False, round=rnd)
        moved_to = {}
        if mover is not None:
            label = poly.labels[moved.leader]
            moved_to = {mover: next(d for lab, d in zip(moved.polygon.labels,
                                                        moved.polygon.directions)
                                    if lab == label)}
        if moved.polygon.n > MAX_QUADRATIC_N:
            return ElectLeaderResult(None, branch, moves, False, moved_to)
        res = P.elect_leader_asym(moved.polygon, orientation, reading)
        leader = None if res.leader is None else robot_in(moved.polygon.labels[res.leader], g1)
        if res.tie:
            trace_entry(trace, alg, 6, [g1.name], "lem-asym-ord",
                        "the lexicographic minimum of the (CW, ACW) tuples is tied", holds=False,
                        labelling_dependent=True, round=rnd)
        trace_entry(trace, alg, 6, [g1.name], "lem-asym-ord",
                    f"Elect_Leader_Asym(moved {g1.name}): leader robot {leader}",
                    robots=[leader] if leader is not None else None, branch=branch, round=rnd,
                    uses="Elect_Leader_Asym")
        return ElectLeaderResult(leader, branch, moves, True, moved_to)
    if not check.symmetric:
        branch = "asymmetric"
        if poly.n > MAX_QUADRATIC_N:
            trace_entry(trace, alg, 9, [g1.name], alg, "too large for Elect_Leader_Asym",
                        branch=branch, round=rnd)
            return ElectLeaderResult(None, branch, [], False)
        res = P.elect_leader_asym(poly, orientation, reading)
        leader = None if res.leader is None else robot_in(poly.labels[res.leader], g1)
        trace_entry(trace, alg, 9, [g1.name], "lem-asym-ord",
                    f"{g1.name} asymmetric: Elect_Leader_Asym elects robot {leader}",
                    robots=[leader] if leader is not None else None, branch=branch, round=rnd,
                    uses="Elect_Leader_Asym")
        if res.tie:
            trace_entry(trace, alg, 9, [g1.name], "lem-asym-ord",
                        "the lexicographic minimum of the (CW, ACW) tuples is tied", holds=False,
                        labelling_dependent=True, round=rnd)
        return ElectLeaderResult(leader, branch)
    branch = "project-1t"
    if gt.at_centre:
        return ElectLeaderResult(None, branch)
    proj = radial_projection(g1, gt)
    trace_entry(trace, alg, 11, [g1.name, gt.name, proj.ring.name], "obs-merg-asym-pair",
                f"compute G_1t = {proj.ring.name} ({proj.ring.n} vertices)"
                + coincidence_note(proj), branch=branch, round=rnd)
    robot, problem = elect_leader_asym_on(trace, alg, 12, proj.ring, g1, orientation, reading,
                                          "lem-asym-pair-ord", branch, rnd)
    return ElectLeaderResult(robot, branch, [], problem is None)
