"""A sweep's results file: JSON lines, one record per configuration, keyed by its canonical
form (``docs/sweeps.md``).

The first line is the header ``{"sweep": {"format": 1, "family": ..., "what": ...,
"enumeration": ...}}``; every other line is a record ``{"index", "key", "n",
"denominator", "size", "status", "failed", "applicable", ...}`` written with sorted keys
and no timing, so two runs over the same family write the same set of lines.  ``index``
is the configuration's position in the family's enumeration (deterministic for a given
``enumeration`` version): what ``--resume`` skips by, in memory proportional to the gaps
(:class:`IndexSet`), not to the sweep.  Records carry their points only when they are
needed later (a statement failed, or the analysis raised): a counterexample's case file
and a failure's input are rebuilt from the file alone.

A sweep killed while writing leaves at most one partial last line; :func:`open_for_append`
cuts it, so a resumed sweep starts from whole records and never counts one twice.

**Compressed** (a name ending in ``.gz``): the same lines, gzip'd.  Each batch is
written and sync-flushed (``Z_SYNC_FLUSH``), so everything up to the last whole batch
decompresses even when the sweep is killed before the gzip member is closed; the reader
(:func:`_gz_lines`) decompresses member after member and stops quietly at a truncated or
unterminated end.  ``--resume`` on a ``.gz`` file rewrites its whole records into a fresh
file (one pass over it, done once per resume) and then appends new gzip members.
"""

from __future__ import annotations

import gzip
import json
import os
import zlib
from bisect import bisect_right
from pathlib import Path
from typing import Iterator

from ..version import SCHEMA_VERSION

__all__ = ["FORMAT", "ResultsError", "IndexSet", "header", "open_for_append",
           "read_records", "read_header", "record_line", "key_of"]

FORMAT = 1


class ResultsError(ValueError):
    """A results file that cannot be used as asked (exit 2)."""


class IndexSet:
    """A set of enumeration indices held as disjoint sorted intervals [start, end): a
    sweep's records arrive nearly in order (a few batches in flight), so the set of done
    configurations of a sweep of any size takes memory for its few gaps only."""

    def __init__(self):
        self.starts: list[int] = []
        self.ends: list[int] = []
        self.count = 0

    def __len__(self) -> int:
        return self.count

    def __contains__(self, i: int) -> bool:
        k = bisect_right(self.starts, i) - 1
        return k >= 0 and i < self.ends[k]

    def add(self, i: int) -> bool:
        """Add ``i``; False when it was already there."""
        k = bisect_right(self.starts, i) - 1
        if k >= 0 and i < self.ends[k]:
            return False
        self.count += 1
        joins_left = k >= 0 and self.ends[k] == i
        joins_right = k + 1 < len(self.starts) and self.starts[k + 1] == i + 1
        if joins_left and joins_right:
            self.ends[k] = self.ends[k + 1]
            del self.starts[k + 1], self.ends[k + 1]
        elif joins_left:
            self.ends[k] = i + 1
        elif joins_right:
            self.starts[k + 1] = i
        else:
            self.starts.insert(k + 1, i)
            self.ends.insert(k + 1, i + 1)
        return True

    def intervals(self) -> list[tuple[int, int]]:
        return list(zip(self.starts, self.ends))


def header(family: str, what: str, enumeration: int) -> dict:
    """The first line; ``format`` and ``schema_version`` beside ``sweep`` (docs/json.md:
    ``sweep.format`` is the results file's own version, read by ``--resume``)."""
    return {"format": "exactsym-sweep-results", "schema_version": SCHEMA_VERSION,
            "sweep": {"format": FORMAT, "family": family, "what": what,
                      "enumeration": enumeration}}


def compressed(path) -> bool:
    return str(path).endswith(".gz")


def _gz_lines(path) -> Iterator[str]:
    """The whole lines of a gzip file, member after member; stops at a truncated or
    unterminated end (a killed sweep), dropping a partial last line.  A damaged piece is
    fed again byte by byte from a copy of the decompressor, so everything before the
    damage is kept."""
    dec, buf, data = zlib.decompressobj(wbits=31), b"", b""
    with open(path, "rb") as f:
        while True:
            data = data or f.read(1 << 12)
            if not data:
                break
            piece, data = data, b""
            saved = dec.copy()
            try:
                buf += dec.decompress(piece)
            except zlib.error:
                dec = saved
                for k in range(len(piece)):
                    try:
                        buf += dec.decompress(piece[k:k + 1])
                    except zlib.error:
                        break
                    if dec.eof:
                        break
                data = b"" if not dec.eof else dec.unused_data + piece[k + 1:]
                if not dec.eof:
                    f.seek(0, os.SEEK_END)      # nothing after the damage is trusted
            if dec.eof:                         # next member, if any
                data, dec = dec.unused_data + data, zlib.decompressobj(wbits=31)
            *lines, buf = buf.split(b"\n")
            for line in lines:
                yield line.decode("utf-8") + "\n"


def _lines(path) -> Iterator[str]:
    if compressed(path):
        yield from _gz_lines(path)
        return
    with open(path, encoding="utf-8") as f:
        yield from f


def record_line(record: dict) -> str:
    return json.dumps(record, sort_keys=True, separators=(",", ":")) + "\n"


def _cut_partial_tail(path: Path) -> None:
    """Drop a last line without its newline (a write the sweep was killed in)."""
    size = path.stat().st_size
    if size == 0:
        return
    with open(path, "rb+") as f:
        f.seek(size - 1)
        if f.read(1) == b"\n":
            return
        block = 1 << 16
        pos = size
        while pos > 0:
            start = max(0, pos - block)
            f.seek(start)
            chunk = f.read(pos - start)
            nl = chunk.rfind(b"\n")
            if nl >= 0:
                f.truncate(start + nl + 1)
                return
            pos = start
        f.truncate(0)


def read_header(path) -> dict | None:
    first = next(iter(_lines(path)), "")
    if not first.endswith("\n"):
        return None
    try:
        data = json.loads(first)
    except json.JSONDecodeError:
        return None
    return data.get("sweep") if isinstance(data, dict) else None


def read_records(path) -> Iterator[dict]:
    """Every whole record of the file, in file order (a partial last line is skipped)."""
    lines = _lines(path)
    next(lines, None)
    for line in lines:
        if not line.endswith("\n"):
            break
        try:
            record = json.loads(line)
        except json.JSONDecodeError:
            if compressed(path):                # a damaged compressed tail: stop there
                break
            raise
        yield record


def remove_if_unstarted(path) -> bool:
    """Remove ``path`` when it holds a header and no record (a sweep that could not start:
    no Dask, no scheduler), so that the same command can be run again without
    ``--resume``; returns whether it was removed."""
    path = Path(path)
    try:
        if not path.is_file() or read_header(path) is None:
            return False
        if next(read_records(path), None) is not None:
            return False
    except (OSError, EOFError, ValueError):     # unreadable: not ours to remove
        return False
    path.unlink()
    return True


def key_of(path, index: int) -> str | None:
    """The key of the record with enumeration index ``index`` (None if absent)."""
    for record in read_records(path):
        if record["index"] == index:
            return record["key"]
    return None


def _open(path: Path, mode: str):
    if compressed(path):
        return gzip.open(path, mode + "t", encoding="utf-8", compresslevel=6)
    return open(path, mode, encoding="utf-8")


def _rewrite_whole(path: Path) -> None:
    """Replace a gzip results file by one holding exactly its whole lines (an unterminated
    member or a damaged tail of a killed sweep cannot be appended to)."""
    tmp = path.with_name(path.name + ".resume-tmp")
    with gzip.open(tmp, "wt", encoding="utf-8", compresslevel=6) as out:
        for line in _gz_lines(path):
            try:
                json.loads(line)
            except json.JSONDecodeError:        # a damaged tail: nothing after it is kept
                break
            out.write(line)
    os.replace(tmp, path)


def open_for_append(path, family: str, what: str, resume: bool, enumeration: int):
    """``(handle, done)``: a new file with its header, or, with ``resume``, the existing
    file (partial last line cut) and the :class:`IndexSet` of the enumeration indices it
    already holds.  Raises :class:`ResultsError` when the file exists without ``resume``,
    or belongs to another family, analysis or version of the enumerators
    (``enumeration``: the indices would name other configurations)."""
    path = Path(path)
    done = IndexSet()
    if path.exists() and path.stat().st_size > 0:
        if not resume:
            raise ResultsError(f"{path}: results file exists; use --resume to continue it "
                               "or choose another --out")
        head = read_header(path)
        if head is None or head.get("format") != FORMAT:
            raise ResultsError(f"{path}: not a sweep results file (format {FORMAT})")
        if head.get("family") != family or head.get("what") != what:
            raise ResultsError(f"{path}: holds a sweep of {head.get('family')} --what "
                               f"{head.get('what')}, not {family} --what {what}")
        if head.get("enumeration") != enumeration:
            raise ResultsError(f"{path}: written by another version of the enumerators "
                               f"({head.get('enumeration')}, now {enumeration}); start a "
                               "new results file")
        if compressed(path):
            _rewrite_whole(path)
        else:
            _cut_partial_tail(path)
        for record in read_records(path):
            done.add(record["index"])
        handle = _open(path, "a")
    else:
        if path.parent and not path.parent.exists():
            os.makedirs(path.parent, exist_ok=True)
        handle = _open(path, "w")
        handle.write(json.dumps(header(family, what, enumeration), sort_keys=True) + "\n")
        handle.flush()
    return handle, done
