"""The work of one batch: analyse each configuration, never let one stop the others.

:func:`analyse_batch` is what a Dask worker runs (and the serial loop): plain data in
(:class:`.families.SweepItem`), plain records out (:mod:`.results`).  An exception raised
by one configuration becomes that configuration's record (``status: "error"``, the
exception, the input); the next configuration runs as usual.
"""

from __future__ import annotations

from . import analysis_bridge as bridge
from .families import SweepItem

__all__ = ["analyse_batch", "analyse_item", "error_record"]


def _base(item: SweepItem) -> dict:
    return {"index": item.index, "key": item.key, "n": item.n, "denominator": item.denominator,
            "size": item.size}


def error_record(item: SweepItem, message: str) -> dict:
    """The record of a configuration whose analysis did not finish, with its input."""
    return dict(_base(item), status="error", error=message, failed=[], applicable=None,
                points=[list(p) for p in item.points])


def analyse_item(item: SweepItem, what: str, budget: int = 0) -> dict:
    try:
        result = bridge.analyse(what, item.points, budget)
    except (bridge.GatheringUnavailable, KeyboardInterrupt, SystemExit):
        raise
    except Exception as err:                # recorded with the input; the sweep goes on
        return error_record(item, f"{type(err).__name__}: {err}")
    record = dict(_base(item), status="ok", **result)
    if record["failed"]:
        record["points"] = [list(p) for p in item.points]
    return record


def analyse_batch(items: list, what: str, budget: int = 0) -> list[dict]:
    """One record per item, in order."""
    return [analyse_item(item, what, budget) for item in items]
