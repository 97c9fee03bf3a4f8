"""Extract, for every labelled statement of the paper, the ``\\ref``s inside its proof.

Usage: ``python proofs/extract_refs.py PAPER.txt`` prints one line per statement,
``label: line-range: refs``.  The ledger's ``uses`` (proofs/statements.toml) started from
this output and was then reviewed by hand (``uses_note`` records every change).

What counts as the proof of a statement: the text from the statement's environment
(``\\begin{lemma|theorem|obs|defi|corollary}``) to the first ``\\qed`` after it, unless
another statement environment starts first (then the statement has no printed proof).
An algorithm's proof is its "Correctness of NAME" paragraph.  References to figures and
equations are dropped; the source's labels with spaces or quotes are renamed as in the
project's numbering (``obs-type 4`` -> ``obs-type-4``, ``obs1-G'equiG`` ->
``obs1-Gprime-equiG``, ``G'equiG`` -> ``Gprime-equiG``).  Unlabelled statements are
found by their first words (``UNLABELLED``).
"""

from __future__ import annotations

import re
import sys

ENV = re.compile(r"\\begin\s*\{(lemma|theorem|obs|defi|corollary)\}")
LABEL = re.compile(r"\\label\{([^}]*)\}")
REF = re.compile(r"\\ref\{([^}]*)\}")
QED = re.compile(r"\\qed")
CORRECTNESS = re.compile(r"Correctness of\s*\$?\\?([A-Za-z_\\]+)")

RENAME = {"obs-type 4": "obs-type-4", "obs1-G'equiG": "obs1-Gprime-equiG",
          "G'equiG": "Gprime-equiG"}

#: Figure and equation labels of the source (never statements).
NOT_STATEMENTS = {"mirrorimage", "symconfig", "hullimage", "skew1", "skew", "SkewSymHFig",
                  "skew2", "symmetric", "mod", "1st", "2nd", "3rd", "type3", "oddprime",
                  "oddprime1", "gatheringalgoF", "invariant", "obstacle", "gathpat",
                  "gathpatsym"}

#: Unlabelled statements with a proof: the project's name and the words that open them.
UNLABELLED = {"hull-symmetric": "then ${\\cal H}(P)$ is in",
              "gather-min-distance": "When a robot is moving towards $C$",
              "gather-no-obstacle": "No obstacle appears in the path"}


def _name(label: str) -> str:
    return RENAME.get(label, label)


def statements(text: str) -> list[dict]:
    """``[{"label", "start", "end", "refs"}]`` (1-based lines; ``end`` the line of the
    proof's ``\\qed``, or of the statement's end when it has no proof)."""
    lines = text.splitlines()
    starts = [i for i, line in enumerate(lines) if ENV.search(line)]
    out = []
    for k, i in enumerate(starts):
        nxt = starts[k + 1] if k + 1 < len(starts) else len(lines)
        env = ENV.search(lines[i]).group(1)
        close = next((j for j in range(i, nxt) if f"\\end{{{env}}}" in lines[j]
                      or f"\\end {{{env}}}" in lines[j]), i)
        head = "\n".join(lines[i:close + 1])
        labels = [m for m in LABEL.findall(head) if m not in NOT_STATEMENTS]
        label = _name(labels[0]) if labels else None
        if label is None:
            label = next((n for n, words in UNLABELLED.items() if words in head), None)
        if label is None:
            continue
        # a proof follows the environment directly ("Proof" in the next lines of text)
        after, in_figure = [], False
        for j in range(close + 1, nxt):
            text = lines[j].strip()
            if text.startswith("\\begin{figure"):
                in_figure = True
            elif text.startswith("\\end{figure"):
                in_figure = False
            elif text and not in_figure:
                after.append(j)
        end, refs = close, []
        if after and "Proof" in lines[after[0]]:
            for j in range(after[0], nxt):
                refs.extend(REF.findall(lines[j]))
                if QED.search(lines[j]):
                    end = j
                    break
        refs = [_name(r) for r in refs if r not in NOT_STATEMENTS]
        out.append({"label": label, "start": i + 1, "end": end + 1,
                    "refs": sorted(set(refs) - {label})})
    for j, line in enumerate(lines):
        m = CORRECTNESS.search(line)
        if m:
            name = m.group(1).replace("\\", "")
            refs = []
            for k in range(j, min(j + 12, len(lines))):
                refs.extend(REF.findall(lines[k]))
                if QED.search(lines[k]):
                    break
            out.append({"label": name, "start": j + 1, "end": k + 1,
                        "refs": sorted({_name(r) for r in refs} - NOT_STATEMENTS)})
    return out


def main(argv: list[str]) -> int:
    if len(argv) != 2:
        print(__doc__.splitlines()[2], file=sys.stderr)
        return 2
    with open(argv[1], encoding="utf-8") as fh:
        for s in statements(fh.read()):
            print(f"{s['label']}: {s['start']}-{s['end']}: {', '.join(s['refs'])}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
