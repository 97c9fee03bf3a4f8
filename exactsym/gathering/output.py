"""Readable text for ``gather``: invariants by name and label, decimals beside long exact
numbers, schedules as numbered sentences, the reading matrix as a table (issue 30,
point 7).  Text only: the JSON keeps every exact value as it is (``docs/gathering.md``,
"Output and JSON"); a decimal here is shown, never compared.
"""

from __future__ import annotations

import re
from decimal import Context, Decimal

from .invariants import LABELS

__all__ = ["NAMES", "READING_WORDS", "readings_help", "invariant_title", "with_decimals",
           "schedule_lines", "matrix_table", "checks_line"]

#: a short name per invariant (the spec's section 4 table, docs/gathering.md)
NAMES = {
    "I1": "no overlap",
    "I2": "one pending move",
    "I3": "a fresh Look agrees",
    "I4": "the mover nearest to C",
    "I5": "a free path",
    "I6": "C unchanged",
    "I7": "P stays put",
    "I8": "a valid pattern",
    "I9": "no chirality",
    "I10": "progress",
}

#: each reading switch of an ambiguous line of the paper in words, its values first the
#: default (docs/gathering.md's table; ``robot.READINGS`` holds the values)
READING_WORDS = {
    "A1": "the centre C: sec-all, the SEC of every robot; sec-r, the SEC of R (literal)",
    "A3": "several moves named in one procedure: first, only the first this cycle; all, "
          "every named move, then the leader's FormGPattern, in one cycle",
    "A4": "'C is not occupied': exact, no centre at C; covers, no disc covers C; within2, "
          "no centre within 2",
    "A5": "the path to a slot of a layer not full: radial-arc, radially to radius 2l then "
          "along that circle; straight, one segment; arc-radial, along the mover's circle "
          "then radially in",
    "A6": "slide direction: nearer, the nearer chain end (a tie: counter-clockwise)",
    "A7": "the last layer: largest, the largest occupied layer",
    "A8": "epsilon moves: rational-rotation, rational rotations about the SEC centre of R, "
          "sense chosen by the mover",
    "lone": "Definition 1's 'at least 1': accept or reject a lone robot in a new layer",
    "EL": "Elect_Leader_Asym's tuples {CW, ACW}: literal, ordered pairs in the observer's "
          "handedness; unordered, sorted pairs (the same in both handednesses)",
}


def readings_help(readings: dict) -> str:
    """The help of ``--reading``: each switch ``KEY=v1|v2`` and its meaning in words."""
    return "; ".join(f"{k}={'|'.join(v)} ({READING_WORDS.get(k, '')})"
                     for k, v in readings.items())


#: a rational with more than 12 digits in all
_LONG = re.compile(r"(?<![\w.])(-?\d+)/(\d+)(?![\w.])")
_CONTEXT = Context(prec=6)


def invariant_title(key: str, label: str | None = None) -> str:
    """``I1 no overlap (gather-no-obstacle)``; ``label``: the violation's own label
    (I3 and I6 name the statement by the move's role)."""
    return f"{key} {NAMES.get(key, '')} ({label or LABELS.get(key, '')})".replace("  ", " ")


def _decimal(num: str, den: str) -> str:
    d = _CONTEXT.divide(Decimal(int(num)), Decimal(int(den)))
    return f"{d:.6g}" if abs(d) < Decimal(10) ** 7 else f"{d:.5e}"


def with_decimals(text: str) -> str:
    """Every rational of more than 12 digits in ``text`` followed by its decimal,
    ``p/q [~ 1.23457]``."""
    def one(m):
        num, den = m.group(1), m.group(2)
        if len(num.lstrip("-")) + len(den) <= 12:
            return m.group(0)
        return f"{m.group(0)} [~ {_decimal(num, den)}]"
    return _LONG.sub(one, text)


def _frame_text(frame) -> str:
    a, b, reflect, tx, ty = frame
    if (a, b, tx, ty) == ("1", "0", "0", "0"):
        return "the mirrored frame" if reflect else "the plain frame"
    return f"a {'mirrored' if reflect else 'plain'} frame (a={a}, b={b}, origin ({tx}, {ty}))"


def _stop_text(stop, end) -> str:
    where = "to the end of its piece" if stop is None else f"to {stop} of its piece"
    if isinstance(stop, dict):         # an exact critical instant (gathering/stops.py)
        where = (f"to critical instant {stop['instant']} of its motion (about "
                 f"{stop['value']}, in ({stop['lo']}, {stop['hi']}))")
    return where + (", and the adversary ends the move there" if end else "")


def schedule_lines(actions) -> list:
    """One numbered sentence per adversary action."""
    out = []
    for k, act in enumerate(actions or (), 1):
        if act["a"] == "look":
            out.append(f"{k:3d}. robot {act['robot']} Looks in {_frame_text(act['frame'])}")
        elif act["a"] == "advance":
            out.append(f"{k:3d}. robot {act['robot']} moves "
                       f"{_stop_text(act.get('stop'), act.get('end'))}")
        else:
            moves = ", ".join(f"robot {i} {_stop_text(stop, end)}"
                              for i, stop, end in act["moves"])
            out.append(f"{k:3d}. at once: {moves}")
    return out


def checks_line(checks: dict) -> str:
    """``I1 no overlap 12, I2 one pending move 3, ...`` (the invariants checked)."""
    return ", ".join(f"{k} {NAMES.get(k, '')} {v}" for k, v in checks.items()
                     if k in NAMES)


def _outcome_text(row: dict) -> str:
    if row["outcome"] == "violated":
        return "violated " + invariant_title(row["invariant"], row["label"])
    return row["outcome"]


def _schedule_text(row: dict) -> str:
    if row["schedule"]:
        k = len(row["schedule"])
        return f"{k} action{'s' if k != 1 else ''}"
    if row["same_as"]:
        return f"(the {row['same_as']} row: the only reading)"
    return f"(seeded run, {row['length']} events)"


def matrix_table(rows: list) -> str:
    """The reading matrix as an aligned text table."""
    head = ("reading", "outcome", "schedule", "search")
    body = [(r["reading"] + (" (mirror image)" if r["mirrored"] else ""), _outcome_text(r),
             _schedule_text(r),
             f"{r['search']['states']} states, {r['search']['stopped']}")
            for r in rows]
    widths = [max(len(x[k]) for x in [head] + body) for k in range(len(head))]
    fmt = "  ".join(f"{{:{w}}}" for w in widths)
    lines = [fmt.format(*head).rstrip(), fmt.format(*("-" * w for w in widths))]
    lines += [fmt.format(*row).rstrip() for row in body]
    return "\n".join(lines)
