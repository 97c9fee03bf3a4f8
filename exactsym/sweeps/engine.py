"""Running a sweep: serially in this process, or on Dask distributed.

:func:`run_sweep` enumerates the family (skipping the keys the results file already
holds), cuts the stream into batches, has them analysed (:func:`.job.analyse_batch`) by
a ``LocalCluster`` of ``workers`` processes, an existing cluster (``scheduler``), or this
process (``serial``), and appends each batch's records to the results file as it comes
back.  Only this process writes the file.

Batches: the first ones are small (to measure the time per configuration); afterwards a
batch is sized to take about ``batch_seconds`` (1 s: Dask's cost per task, a few
milliseconds, is then well under 1 %), but never more than a quarter of a worker's share
of what remains, so small sweeps still spread over every worker.  At most two batches
per worker are in flight, so a family of any size streams in constant memory (besides
the few gaps in the indices already done: :class:`.results.IndexSet`).

A batch whose worker dies is sent again (up to :data:`BATCH_ATTEMPTS` times), then
recorded configuration by configuration as errors (with their input); the sweep goes on.
A configuration that overruns ``timeout`` is recorded as an error (:mod:`.job`) and its
worker is restarted (the thread cannot be stopped); batches lost with it are sent again.
"""

from __future__ import annotations

import logging
import time
from dataclasses import dataclass, replace
from itertools import islice
from typing import Iterator, TextIO

from ..progress import Progress
from .analysis_bridge import warm_up
from .families import (ENUMERATION, Family, SweepItem, can_jump, family_items,
                       family_size)
from .job import analyse_batch, error_record
from .results import IndexSet, key_of, open_for_append, record_line

__all__ = ["SweepOptions", "SweepRun", "run_sweep", "timed_batch", "DEFAULT_GATHER_BUDGET"]

#: Adversary steps per gathering run when the family is not a ``gather:BUDGET:...`` one.
DEFAULT_GATHER_BUDGET = 1000

#: Times a batch is sent before its configurations are recorded as errors (a batch is
#: lost when its worker dies or is restarted, not when a configuration raises).
BATCH_ATTEMPTS = 3

#: Seconds one configuration may take before it is recorded as an error (``--timeout``).
DEFAULT_TIMEOUT = 600.0


@dataclass(frozen=True)
class SweepOptions:
    workers: int = 2
    scheduler: str | None = None
    serial: bool = False
    batch_size: int | None = None        # fixed size (None: adaptive)
    batch_seconds: float = 1.0
    stop_after: int | None = None        # stop once this many new records are written
    timeout: float | None = DEFAULT_TIMEOUT   # seconds per configuration (None: no limit)
    progress: TextIO | None = None


@dataclass(frozen=True)
class SweepRun:
    """What one run did: ``new`` records written, ``skipped`` (already in the file),
    ``errors`` and ``failing`` (records with a failed statement) among the new ones,
    ``complete`` (False when stopped by ``stop_after``), ``dashboard`` link if any;
    ``seconds`` from the first batch (a LocalCluster's start excluded), ``busy`` the
    workers' analysing time summed."""
    new: int
    skipped: int
    errors: int
    failing: int
    seconds: float
    complete: bool
    workers: int
    batches: int
    dashboard: str | None = None
    busy: float = 0.0                    # seconds the workers spent analysing

    @property
    def utilisation(self) -> float | None:
        """Share of the workers' time spent analysing (1 - overhead), from the first
        batch on; None for a serial run."""
        if not self.workers or self.seconds <= 0:
            return None
        return self.busy / (self.seconds * self.workers)


def timed_batch(items: list, what: str, budget: int = 0, timeout: float | None = None,
                in_worker: bool = False) -> tuple[list, float, str | None]:
    """The records of ``items``, the seconds the analysis took (worker side) and, when a
    configuration overran ``timeout`` on a Dask worker, that worker's address (its
    thread still runs: the engine restarts it)."""
    start = time.perf_counter()
    records = analyse_batch(items, what, budget, timeout)
    seconds = time.perf_counter() - start
    stuck = None
    if in_worker and any(r.get("timeout") for r in records):
        from distributed import get_worker
        stuck = get_worker().address
    return records, seconds, stuck


class _Progress:
    """The sweep's progress bar on stderr (:class:`exactsym.progress.Progress`): done/total,
    rate, time left, failures; on a terminal only (a log or a pipe gets nothing)."""

    def __init__(self, stream, total: int, done_before: int, label: str):
        self.stream = stream
        self.bar = Progress(label, total, done=done_before, stream=stream, unit=" conf") \
            if stream is not None else None
        self.start = self.last = time.monotonic()

    def show(self, new: int, failing: int, errors: int, final: bool = False) -> None:
        if self.bar is None:
            return
        if self.bar.start < self.start:          # the rate from the cluster's start on
            self.bar.start = self.start
        self.bar.done = self.bar.before + new
        rate = new / max(time.monotonic() - self.start, 1e-9)
        self.bar.note = f"{rate:,.1f} conf/s, failing {failing:,}, errors {errors:,}"
        self.bar.draw(force=final)
        if final:
            self.bar.close()


def _todo(family: Family, done: IndexSet, prefix_key: str | None) -> Iterator[SweepItem]:
    """The family's items not yet in the file, numbered by their enumeration index.

    When the file holds the indices 0..e-1 and the family can start after a key
    (``prefix_key``, the key of index e-1), enumeration starts there instead of
    replaying the prefix.  A random draw equal to an earlier one is skipped (its key is
    kept for this run only)."""
    repeats = not can_jump(family)
    seen: set = set()
    intervals = done.intervals()
    first = 0
    items = family_items(family)
    if prefix_key is not None and can_jump(family):
        first = intervals[0][1]
        items = family_items(family, after=prefix_key)
    k = 0
    for i, item in enumerate(items, first):
        if repeats:
            if item.key in seen:
                continue
            seen.add(item.key)
        while k < len(intervals) and intervals[k][1] <= i:
            k += 1
        if k < len(intervals) and intervals[k][0] <= i:
            continue                          # already in the file
        yield replace(item, index=i)


class _Sizer:
    """Adaptive batch size from the measured seconds per configuration."""

    def __init__(self, options: SweepOptions, workers: int, remaining: int):
        self.fixed = options.batch_size
        self.target = options.batch_seconds
        self.workers = max(workers, 1)
        self.remaining = remaining
        self.per_item: float | None = None

    def observe(self, items: int, seconds: float) -> None:
        if items:
            x = seconds / items
            self.per_item = x if self.per_item is None else 0.7 * self.per_item + 0.3 * x
        self.remaining = max(self.remaining - items, 0)

    def size(self) -> int:
        if self.fixed:
            return self.fixed
        if self.per_item is None:
            return 4
        by_time = int(self.target / max(self.per_item, 1e-6))
        share = max(1, self.remaining // (4 * self.workers))
        return max(1, min(by_time, share, 20_000))


def run_sweep(family: Family, what: str, out, resume: bool = False,
              options: SweepOptions = SweepOptions()) -> SweepRun:
    """Sweep ``family`` with the analysis ``what`` into the results file ``out``."""
    handle, done = open_for_append(out, family.text, what, resume, ENUMERATION)
    total = family_size(family)
    progress = _Progress(options.progress, total, len(done), f"sweep {family.text}")
    intervals = done.intervals()
    prefix_key = None
    if can_jump(family) and intervals and intervals[0][0] == 0:
        prefix_key = key_of(out, intervals[0][1] - 1)
    todo = _todo(family, done, prefix_key)
    budget = family.budget if family.kind == "gather" else DEFAULT_GATHER_BUDGET
    if family.kind == "gather" and family.states:
        budget = (budget, family.states)     # events per run, the search's states
    try:
        if options.serial:
            return _serial(todo, what, budget, handle, done, total, options, progress)
        return _distributed(todo, what, budget, handle, done, total, options, progress)
    finally:
        handle.close()


class _Writer:
    def __init__(self, handle, options: SweepOptions, progress: _Progress):
        self.handle, self.options, self.progress = handle, options, progress
        self.new = self.errors = self.failing = 0

    def write(self, records: list) -> None:
        self.handle.write("".join(record_line(r) for r in records))
        self.handle.flush()
        self.new += len(records)
        self.errors += sum(r["status"] == "error" for r in records)
        self.failing += sum(bool(r["failed"]) for r in records)
        self.progress.show(self.new, self.failing, self.errors)

    def stop(self) -> bool:
        return self.options.stop_after is not None and self.new >= self.options.stop_after


def _serial(todo, what, budget, handle, done, total, options, progress) -> SweepRun:
    start = time.perf_counter()
    writer = _Writer(handle, options, progress)
    sizer = _Sizer(options, 1, total - len(done))
    batches, complete = 0, True
    while True:
        batch = list(islice(todo, sizer.size()))
        if not batch:
            break
        records, seconds, _ = timed_batch(batch, what, budget, options.timeout)
        sizer.observe(len(batch), seconds)
        writer.write(records)
        batches += 1
        if writer.stop():
            complete = next(todo, None) is None
            break
    progress.show(writer.new, writer.failing, writer.errors, final=True)
    return SweepRun(writer.new, len(done), writer.errors, writer.failing,
                    time.perf_counter() - start, complete, 0, batches)


def _require_dask() -> None:
    """Dask is the 'sweep' extra: without it, one line (exit 2) instead of a traceback."""
    try:
        import distributed  # noqa: F401
    except ModuleNotFoundError:
        from .families import FamilyError
        raise FamilyError("a sweep on workers needs Dask distributed: pip install "
                          "'dask[distributed]' (from a checkout: pip install -e '.[sweep]'), "
                          "or run it with --serial") from None


def _client(options: SweepOptions):
    from distributed import Client, LocalCluster
    if options.scheduler:
        return Client(options.scheduler), None, True
    try:
        import bokeh  # noqa: F401  (the dashboard needs it)
        dashboard = ":0"
    except ImportError:
        dashboard = None
    cluster = LocalCluster(n_workers=options.workers, threads_per_worker=1, processes=True,
                           dashboard_address=dashboard, silence_logs=logging.ERROR)
    return Client(cluster), cluster, dashboard is not None


def _distributed(todo, what, budget, handle, done, total, options, progress) -> SweepRun:
    _require_dask()
    from distributed import as_completed
    start = time.perf_counter()
    client, cluster, has_dashboard = _client(options)
    try:
        if cluster is not None:
            client.wait_for_workers(options.workers)
        client.run(warm_up, what)          # every worker imports the analysis once, now
        workers = max(1, len(client.scheduler_info(n_workers=-1).get("workers", {})))
        link = getattr(client, "dashboard_link", None) if has_dashboard else None
        if options.progress is not None:
            options.progress.write(f"sweep: {workers} worker(s); dashboard: "
                                   f"{link or 'not available (needs bokeh)'}\n")
        progress.start = progress.last = time.monotonic()   # rate without the cluster's start
        start = time.perf_counter()
        busy = 0.0
        writer = _Writer(handle, options, progress)
        sizer = _Sizer(options, workers, total - len(done))
        pending: dict = {}                 # future -> (batch, attempts so far)
        batches, exhausted = 0, False

        def send(batch: list, attempts: int):
            fut = client.submit(timed_batch, batch, what, budget, options.timeout, True,
                                pure=False)
            pending[fut] = (batch, attempts)
            return fut

        def submit():
            batch = list(islice(todo, sizer.size()))
            return send(batch, 0) if batch else None

        queue = as_completed()
        for _ in range(2 * workers):
            fut = submit()
            if fut is None:
                exhausted = True
                break
            queue.add(fut)
        for fut in queue:
            batch, attempts = pending.pop(fut)
            try:
                records, seconds, stuck = fut.result()
            except Exception as err:          # the worker died or was restarted
                if attempts + 1 < BATCH_ATTEMPTS:
                    queue.add(send(batch, attempts + 1))
                    continue
                records = [error_record(item, f"batch failed {BATCH_ATTEMPTS} times: "
                                        f"{type(err).__name__}: {err}") for item in batch]
                seconds, stuck = 0.0, None
            if stuck is not None:             # a configuration's thread still runs there
                client.restart_workers([stuck], raise_for_error=False)
            sizer.observe(len(batch), seconds)
            busy += seconds
            writer.write(records)
            batches += 1
            if writer.stop():
                for other in pending:
                    other.cancel()
                break
            if not exhausted:
                nxt = submit()
                if nxt is None:
                    exhausted = True
                else:
                    queue.add(nxt)
        complete = not pending and exhausted or (not pending and next(todo, None) is None)
        progress.show(writer.new, writer.failing, writer.errors, final=True)
        return SweepRun(writer.new, len(done), writer.errors, writer.failing,
                        time.perf_counter() - start, complete, workers, batches, link, busy)
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
