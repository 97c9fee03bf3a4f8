"""A progress bar on standard error for the commands that can run past a few seconds
(``ledger --check``, ``gather --search``, ``gather --readings all``, ``gather`` runs and
their pictures, ``sweep``: ``docs/cli.md``).

One line, redrawn in place at most :data:`REDRAW` times a second: the label, a bar when
the total is known (``[#######.......] 12/29 41%``), the elapsed time, an estimate of the
time left and a note.  Quiet when the stream is not a terminal (a log, a pipe, a test):
the commands' output is the same with and without it.  ``tqdm`` is not needed; this is the
standard library only.

>>> import io
>>> with Progress("ledger --check", total=4, stream=io.StringIO()) as bar:
...     bar.update(note="cases/a.toml")
>>> bar.done, bar.shown            # counted, but nothing drawn: not a terminal
(1, False)
"""

from __future__ import annotations

import sys
import threading
import time

__all__ = ["Progress", "ticking", "REDRAW"]

#: redraws per second at most
REDRAW = 4
WIDTH = 24


def _clock(seconds: float) -> str:
    seconds = int(seconds)
    if seconds < 60:
        return f"{seconds}s"
    if seconds < 3600:
        return f"{seconds // 60}m{seconds % 60:02d}s"
    return f"{seconds // 3600}h{seconds // 60 % 60:02d}m"


def _is_terminal(stream) -> bool:
    try:
        return bool(stream is not None and stream.isatty())
    except (AttributeError, ValueError, OSError):
        return False


class Progress:
    """``with Progress(label, total) as bar: ... bar.update(k, note=...)``.

    ``total``: the units of work (None: unknown, the bar shows the count and the time);
    ``done``: units done before this run (a resumed sweep); ``force``: draw even when
    the stream is not a terminal (tests)."""

    def __init__(self, label: str, total: int | None = None, *, done: int = 0,
                 stream=None, unit: str = "", force: bool = False):
        self.label, self.total, self.unit = label, total, unit
        self.stream = sys.stderr if stream is None else stream
        self.active = force or _is_terminal(self.stream)
        self.done, self.before, self.note = done, done, ""
        self.start = self.last = time.monotonic()
        self.shown = False
        self.estimate = True            # the time left from the rate (not for a clock)
        self._width = 0
        self._lock = threading.Lock()

    def __enter__(self) -> "Progress":
        self.draw(force=True)
        return self

    def __exit__(self, *exc) -> None:
        self.close()

    def update(self, k: int = 1, note: str | None = None) -> None:
        self.done += k
        if note is not None:
            self.note = note
        self.draw()

    def text(self) -> str:
        elapsed = time.monotonic() - self.start
        parts = [f"{self.label}:"]
        if self.total:
            frac = min(self.done / self.total, 1.0)
            fill = int(round(frac * WIDTH))
            parts.append(f"[{'#' * fill}{'.' * (WIDTH - fill)}] {self.done:,}/"
                         f"{self.total:,}{self.unit} {100 * frac:3.0f}%")
            rate = (self.done - self.before) / elapsed if elapsed > 0 else 0
            left = self.total - self.done
            parts.append(_clock(elapsed) + (f", about {_clock(left / rate)} left"
                                            if self.estimate and rate > 0 and left > 0
                                            else ""))
        else:
            parts.append(f"{self.done:,}{self.unit}, {_clock(elapsed)}" if self.done
                         else _clock(elapsed))
        if self.note:
            parts.append(self.note)
        return " ".join(parts)

    def draw(self, force: bool = False) -> None:
        if not self.active:
            return
        now = time.monotonic()
        if not force and now - self.last < 1 / REDRAW:
            return
        with self._lock:
            self.last = now
            line = self.text()
            try:
                width = _terminal_width(self.stream)
                line = line[:width - 1]
                pad = max(self._width - len(line), 0)
                self.stream.write("\r" + line + " " * pad)
                self.stream.flush()
            except (OSError, ValueError):          # the terminal went away
                self.active = False
                return
            self._width, self.shown = len(line), True

    def close(self) -> None:
        """Clear the line: what the command prints next starts at the left margin."""
        if self.active and self.shown:
            with self._lock:
                try:
                    self.stream.write("\r" + " " * self._width + "\r")
                    self.stream.flush()
                except (OSError, ValueError):
                    pass
        self.active = False


def _terminal_width(stream) -> int:
    import os
    try:
        columns = os.get_terminal_size(stream.fileno()).columns
    except (AttributeError, ValueError, OSError):
        return 100
    return columns if columns >= 20 else 100          # a pseudo-terminal of no size


class ticking:
    """A :class:`Progress` redrawn by a thread every quarter second, for work that
    reports nothing while it runs (a search bounded by time: ``total`` is then its
    seconds, ``timed=True``, and the bar fills with the clock)."""

    def __init__(self, label: str, total: float | None = None, *, timed: bool = False,
                 stream=None, force: bool = False):
        self.bar = Progress(label, None if timed else total, stream=stream, force=force)
        self.timed, self.seconds = timed, total
        self._stop = threading.Event()
        self._thread = None

    def __enter__(self) -> Progress:
        if self.bar.active:
            if self.timed and self.seconds:
                self.bar.total, self.bar.unit = int(self.seconds), " s"
                self.bar.estimate = False     # the bound is known; the work may end sooner
            self._thread = threading.Thread(target=self._run, daemon=True)
            self._thread.start()
        return self.bar

    def _run(self) -> None:
        while not self._stop.wait(1 / REDRAW):
            if self.timed:
                self.bar.done = min(int(time.monotonic() - self.bar.start),
                                    self.bar.total or 0)
            self.bar.draw(force=True)

    def __exit__(self, *exc) -> None:
        self._stop.set()
        if self._thread is not None:
            self._thread.join()
        self.bar.close()
