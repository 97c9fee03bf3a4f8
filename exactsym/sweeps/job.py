"""The work of one batch: analyse each configuration, never let one stop the others.

:func:`analyse_batch` is what a Dask worker runs (and the serial loop): plain data in
(:class:`.families.SweepItem`), plain records out (:mod:`.results`).  An exception raised
by one configuration becomes that configuration's record (``status: "error"``, the
exception, the input); the next configuration runs as usual.

With a time limit, each configuration runs in a daemon thread of its own, joined with the
limit (about 0.1 ms a configuration).  Python cannot stop a thread: a configuration that
overruns is recorded (``"timeout": true``) and left running; the batch goes on, and the
engine restarts a Dask worker that reports one (:mod:`.engine`).
"""

from __future__ import annotations

import threading

from . import analysis_bridge as bridge
from .families import SweepItem

#: Record keys of labels found false but not counted as failures (analysis_bridge).
SET_ASIDE = ("outside", "reading", "procedure")

__all__ = ["SET_ASIDE", "analyse_batch", "analyse_item", "error_record", "ConfigurationTimeout"]


class ConfigurationTimeout(Exception):
    """One configuration overran the time limit (its thread is still running)."""


def _limited(fn, args: tuple, seconds: float | None):
    """``fn(*args)``, or :class:`ConfigurationTimeout` after ``seconds``."""
    if seconds is None:
        return fn(*args)
    box: dict = {}

    def target():
        try:
            box["value"] = fn(*args)
        except BaseException as err:          # handed to the caller's thread
            box["error"] = err

    thread = threading.Thread(target=target, daemon=True, name="exactsym-sweep-configuration")
    thread.start()
    thread.join(seconds)
    if thread.is_alive():
        raise ConfigurationTimeout(f"no result after {seconds:g} s (time limit)")
    if "error" in box:
        raise box["error"]
    return box["value"]


def _base(item: SweepItem) -> dict:
    return {"index": item.index, "key": item.key, "n": item.n, "denominator": item.denominator,
            "size": item.size}


def error_record(item: SweepItem, message: str) -> dict:
    """The record of a configuration whose analysis did not finish, with its input."""
    return dict(_base(item), status="error", error=message, failed=[], applicable=None,
                points=[list(p) for p in item.points])


def analyse_item(item: SweepItem, what: str, budget: int = 0,
                 timeout: float | None = None) -> dict:
    try:
        result = _limited(bridge.analyse, (what, item.points, budget), timeout)
    except (KeyboardInterrupt, SystemExit):
        raise
    except ConfigurationTimeout as err:
        return dict(error_record(item, f"ConfigurationTimeout: {err}"), timeout=True)
    except Exception as err:                # recorded with the input; the sweep goes on
        return error_record(item, f"{type(err).__name__}: {err}")
    record = dict(_base(item), status="ok", **result)
    if record["failed"] or any(record.get(k) for k in SET_ASIDE):
        record["points"] = [list(p) for p in item.points]
    return record


def analyse_batch(items: list, what: str, budget: int = 0,
                  timeout: float | None = None) -> list[dict]:
    """One record per item, in order (``timeout``: seconds per configuration)."""
    return [analyse_item(item, what, budget, timeout) for item in items]
