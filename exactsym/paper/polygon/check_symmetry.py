"""``Check_Symmetry_Odd`` and ``Check_Symmetry_Even`` (Section 4.1): as printed
(literal), a reference implementation, and the efficient versions (equal, tested).
"""

from __future__ import annotations

from dataclasses import dataclass

from ...exact import fmpq
from ..circle_polygon import CirclePolygon
from .strings import cw_string, string_classes


@dataclass(frozen=True)
class CheckResult:
    """What Check_Symmetry_Odd / Check_Symmetry_Even report.

    ``degree``: the degree of symmetry as reported (``deg_sym`` for the odd check,
    ``deg_sym/2`` as an exact rational for the even check; 0 when asymmetric);
    ``deg_sym``: the raw counter; ``axis_vertices``: vertices with CW = ACW;
    ``terminated``/``steps``: for the literal odd loop, whether it stopped within the
    step bound."""
    symmetric: bool
    straight: bool
    skew: bool
    degree: object
    reports: tuple
    algorithm: str
    deg_sym: int
    axis_vertices: tuple = ()
    terminated: bool = True
    steps: int = 0


def visit_order(n: int, orientation: int) -> list[int]:
    """The paper's v_1..v_n as storage indices: counter-clockwise from index 0 for the
    observer +1, clockwise from index 0 for the observer -1."""
    return [(orientation * k) % n for k in range(n)]


def _odd_result(algorithm, deg_sym, axis, terminated=True, steps=0) -> CheckResult:
    if deg_sym > 0:
        reports = ("G is symmetric", f"The degree of symmetry is: {deg_sym}")
    else:
        reports = ("G is asymmetric",)
    if not terminated:
        reports += (f"(did not terminate within {steps} steps: the printed loop only "
                    "increments i when CW != ACW)",)
    return CheckResult(deg_sym > 0, deg_sym > 0, False, fmpq(deg_sym), reports, algorithm,
                       deg_sym, tuple(axis), terminated, steps)


def check_symmetry_odd_literal(polygon: CirclePolygon, orientation: int = 1,
                               max_steps: int | None = None) -> CheckResult:
    """Check_Symmetry_Odd *as printed* (Section 4.1)::

        deg_sym = 0; i = 1
        while i <= n: compute CW_vi, ACW_vi
            if CW_vi = ACW_vi: deg_sym = deg_sym + 1   else: i++

    i is only incremented in the else branch, so once some vertex has CW = ACW the loop
    never ends.  We run at most ``max_steps`` iterations (default 4n) and report
    ``terminated=False`` (a finding) instead of looping."""
    n = polygon.n
    if n % 2 == 0:
        raise ValueError("Check_Symmetry_Odd needs an odd number of vertices")
    max_steps = 4 * n if max_steps is None else max_steps
    v = visit_order(n, orientation)
    deg_sym, i, steps, axis = 0, 1, 0, []
    while i <= n:
        if steps >= max_steps:
            return _odd_result("Check_Symmetry_Odd (literal)", deg_sym, sorted(set(axis)),
                               False, steps)
        steps += 1
        cw = cw_string(polygon, v[i - 1], orientation)
        acw = cw[::-1]
        if cw == acw:
            deg_sym += 1
            axis.append(v[i - 1])
        else:
            i += 1
    return _odd_result("Check_Symmetry_Odd (literal)", deg_sym, sorted(axis), True, steps)


def check_symmetry_odd_reference(polygon: CirclePolygon, orientation: int = 1) -> CheckResult:
    """Check_Symmetry_Odd as evidently intended (i++ after every vertex), with the paper's
    strings: deg_sym = number of vertices with CW = ACW.  O(n^2)."""
    n = polygon.n
    if n % 2 == 0:
        raise ValueError("Check_Symmetry_Odd needs an odd number of vertices")
    axis = []
    for i in visit_order(n, orientation):
        cw = cw_string(polygon, i, orientation)
        if cw == cw[::-1]:
            axis.append(i)
    return _odd_result("Check_Symmetry_Odd", len(axis), sorted(axis))


def check_symmetry_odd(polygon: CirclePolygon, orientation: int = 1) -> CheckResult:
    """Check_Symmetry_Odd (intended reading, i++ after every vertex), efficient: the
    vertices with CW = ACW from :func:`string_classes`.  Reports the degree of symmetry =
    the number of such vertices; "symmetric" iff it is positive.  Note it never looks at
    conditions 2-3 of Theorem 1: a polygon with only rotational symmetry is reported
    asymmetric (as the definitions say, not as Theorem 1 says)."""
    n = polygon.n
    if n % 2 == 0:
        raise ValueError("Check_Symmetry_Odd needs an odd number of vertices")
    cw, acw = string_classes(polygon, orientation)
    axis = [i for i in range(n) if cw[i] == acw[i]]
    return _odd_result("Check_Symmetry_Odd", len(axis), axis)


def _even_result(deg_sym, st_sym, sk_sym, axis) -> CheckResult:
    reports = []
    degree = fmpq(deg_sym, 2)
    if deg_sym > 0 and st_sym:
        reports += ["G is straight symmetric", f"The degree of symmetry is: {degree}"]
    if deg_sym > 0 and sk_sym:
        reports += ["G is skew symmetric", f"The degree of symmetry is: {degree}"]
    if deg_sym == 0:
        reports.append("G is asymmetric")
    return CheckResult(deg_sym > 0, deg_sym > 0 and st_sym, deg_sym > 0 and sk_sym, degree,
                       tuple(reports), "Check_Symmetry_Even", deg_sym, tuple(axis))


def check_symmetry_even_reference(polygon: CirclePolygon, orientation: int = 1) -> CheckResult:
    """Check_Symmetry_Even exactly as printed (the paper's loops, O(n^3))::

        for i = 1..n: if CW_vi = ACW_vi: st_sym = True; deg_sym++
                      else for j = 1..i-1:
                          if CW_vi = CW_vj or CW_vi = ACW_vj or ACW_vi = CW_vj:
                              sk_sym = True; deg_sym++
        report deg_sym/2

    So deg_sym counts the vertices on a (string) mirror plus the pairs j < i, i not on
    one, with equal strings in either direction -- not twice the number of lines."""
    n = polygon.n
    if n % 2:
        raise ValueError("Check_Symmetry_Even needs an even number of vertices")
    v = visit_order(n, orientation)
    deg_sym, st_sym, sk_sym, axis = 0, False, False, []
    for i in range(1, n + 1):
        cw_i = cw_string(polygon, v[i - 1], orientation)
        acw_i = cw_i[::-1]
        if cw_i == acw_i:
            st_sym = True
            deg_sym += 1
            axis.append(v[i - 1])
        else:
            for j in range(1, i):
                cw_j = cw_string(polygon, v[j - 1], orientation)
                acw_j = cw_j[::-1]
                if cw_i == cw_j or cw_i == acw_j or acw_i == cw_j:
                    sk_sym = True
                    deg_sym += 1
    return _even_result(deg_sym, st_sym, sk_sym, sorted(axis))


def check_symmetry_even(polygon: CirclePolygon, orientation: int = 1) -> CheckResult:
    """Check_Symmetry_Even, same counts as :func:`check_symmetry_even_reference` from the
    string classes in near-linear time (see its docstring for what is counted)."""
    n = polygon.n
    if n % 2:
        raise ValueError("Check_Symmetry_Even needs an even number of vertices")
    cw, acw = string_classes(polygon, orientation)
    deg_sym, st_sym, sk_sym, axis = 0, False, False, []
    seen: dict = {}
    for i in visit_order(n, orientation):
        if cw[i] == acw[i]:
            st_sym = True
            deg_sym += 1
            axis.append(i)
        else:
            count = seen.get(cw[i], 0)
            if count:
                sk_sym = True
                deg_sym += count
        seen[cw[i]] = seen.get(cw[i], 0) + 1
        if acw[i] != cw[i]:
            seen[acw[i]] = seen.get(acw[i], 0) + 1
    return _even_result(deg_sym, st_sym, sk_sym, sorted(axis))


def check_symmetry(polygon: CirclePolygon, orientation: int = 1) -> CheckResult:
    """Check_Symmetry_Odd or Check_Symmetry_Even by the parity of n (efficient versions)."""
    if polygon.n % 2:
        return check_symmetry_odd(polygon, orientation)
    return check_symmetry_even(polygon, orientation)
