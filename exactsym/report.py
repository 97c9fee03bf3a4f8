"""What ``exactsym check`` reports about a configuration, and the check of its ``[expect]`` block.

:func:`check_report` returns a JSON-ready dict with the keys of
``../shared/spec/cli-1.md``; exact numbers are strings in the configuration
syntax.  Later layers (ground truth, the paper) add keys through
:data:`SECTIONS`: functions ``(config, rings, report) -> None`` run in order.
"""

from __future__ import annotations

from typing import Callable

from .configuration import Configuration
from .errors import InputError
from .exact import number_system, number_text, evaluate
from .levels import Rings, rings

#: Extra report sections, each ``(config, rings, report) -> None``; appended by later modules.
SECTIONS: list[Callable] = []


def check_report(config: Configuration, options: dict | None = None) -> dict:
    ring = rings(config)
    report = {
        "n": config.n,
        "sec": {"center": [number_text(c) for c in ring.sec.centre],
                "radius_squared": number_text(ring.sec.radius_squared)},
        "levels": [{"radius_squared": number_text(level.radius_squared),
                    "points": list(level.points)} for level in ring.levels],
        "number_field": getattr(config.polar_system if ring.polar else config.system, "name", "Q"),
    }
    for section in SECTIONS:
        section(config, ring, report, options or {})
    return report


def _same_number(text_a: str, text_b: str) -> bool:
    """Exact equality of two numbers written in the configuration syntax."""
    from .expr import parse_expression
    a, b = parse_expression(text_a), parse_expression(text_b)
    system = number_system([a, b])
    return evaluate(a, system) == evaluate(b, system)


#: How an ``[expect]`` key is compared with the report: key -> (report path, comparison).
EXPECT_CHECKS: dict[str, tuple[Callable[[dict], object], Callable[[object, object], bool]]] = {
    "n": (lambda r: r["n"], lambda want, got: want == got),
    "levels": (lambda r: len(r["levels"]), lambda want, got: want == got),
    "sec_radius_squared": (lambda r: r["sec"]["radius_squared"], _same_number),
    "orderable": (lambda r: r.get("orderable"), lambda want, got: want == got),
    "group": (lambda r: r.get("group"), lambda want, got: want == got),
    "paper_orderable": (lambda r: (r.get("paper") or {}).get("orderable"),
                        lambda want, got: want == got),
    # the family layer (exactsym.paper.family_report): -1 stands for "no leader"
    "paper_leader": (lambda r: None if "leader" not in (r.get("paper") or {}) else
                     (-1 if r["paper"]["leader"] is None else r["paper"]["leader"]),
                     lambda want, got: want == got),
    "audit_agrees": (lambda r: (r.get("audit") or {}).get("agrees"),
                     lambda want, got: want == got),
}



# [expect] paper_* keys of the paper's verdicts per level (exactsym.paper.polygon_report)
def _paper_level_values(*path):
    """Getter: the value at ``path`` in each level's ``"paper"`` entry ("none" for null),
    nearest first; None when that report section has not run."""
    def get(report):
        out = []
        for level in report["levels"]:
            if "paper" not in level:
                return None
            value = level["paper"]
            for key in path:
                value = None if value is None else value.get(key)
            out.append("none" if value is None else value)
        return out
    return get


def _paper_level_check(want, got) -> bool:
    """An array ``want`` has one value per level; a single value is the outermost level's."""
    def same(a, b):
        return isinstance(a, bool) == isinstance(b, bool) and str(a) == str(b)
    if isinstance(want, list):
        return len(want) == len(got) and all(same(a, b) for a, b in zip(want, got))
    return bool(got) and same(want, got[-1])


EXPECT_CHECKS.update({
    f"paper_{key}": (_paper_level_values(*path), _paper_level_check) for key, path in {
        "symmetric": ("symmetric",), "straight": ("straight",), "skew": ("skew",),
        "degree": ("degree",), "type": ("type",), "lines": ("lines",),
        "theorem1_symmetric": ("theorem1_symmetric",), "loop_terminates": ("loop_terminates",),
        "def_straight": ("definition", "straight"), "def_skew": ("definition", "skew"),
        "def_mirrors": ("definition", "mirrors"), "leader_sym": ("leader_sym",),
        "leader_sym_by_lines": ("leader_sym_by_lines",),
        "leader_asym": ("leader_asym", "+1"), "leader_asym_mirrored": ("leader_asym", "-1"),
    }.items()})


def failed_expectations(config: Configuration, report: dict) -> list[str]:
    """One message per ``[expect]`` claim that the report contradicts (or cannot check)."""
    failures = []
    for key, want in config.expect.items():
        check = EXPECT_CHECKS.get(key)
        if check is None:
            failures.append(f"[expect] {key}: no check is implemented for this key")
            continue
        got = check[0](report)
        if got is None:
            failures.append(f"[expect] {key} = {want!r}: this version does not compute it")
        elif not check[1](want, got):
            failures.append(f"[expect] {key} = {want!r} is false: exactsym finds {got!r}")
    return failures


__all__ = ["check_report", "failed_expectations", "SECTIONS", "EXPECT_CHECKS", "InputError", "Rings"]
