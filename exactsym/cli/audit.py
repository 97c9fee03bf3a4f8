"""``exactsym audit FILE [--json]``: where the paper and the ground truth part ways.

Exit 1 when the audit finds a discrepancy (named on standard error), else 0.
"""

from __future__ import annotations

import json
import sys

from ..analysis import analyse
from ..geometry.configuration import load
from ..errors import EXIT_FALSE, EXIT_OK
from ..paper.family_report import paper_json
from ..version import json_head

#: a witness's keys that repeat its words as data (docs/json.md): not printed twice
DATA_KEYS = ("robot_map", "isometry", "turn", "lines")


def _words(witness):
    if not isinstance(witness, dict):
        return witness
    return {k: v for k, v in witness.items() if k not in DATA_KEYS}


def add_arguments(parser) -> None:
    parser.add_argument("file", metavar="FILE",
                        help="configuration file ('-' for standard input)")
    parser.add_argument("--json", action="store_true", help="one JSON object on standard output")


def run(args) -> int:
    config = load(args.file)
    analysis = analyse(config, sections=("audit",))
    res, result = analysis.paper, analysis.audit
    if args.json:
        print(json.dumps({**json_head("exactsym-audit", config.source, config.name),
                          "paper": paper_json(res), "audit": result.as_dict()}, indent=2))
    else:
        from ..report.summary import plain, prose      # words on screen, never Python values
        truth = result.truth
        print(f"truth: group {truth.group}, "
              f"{'orderable' if truth.orderable else 'not orderable'}, leader "
              f"{plain(truth.leader)}")
        print(f"paper: {'orderable' if res.orderable else 'not orderable'}, leader "
              f"{plain(res.leader)}, moves {plain([m['robot'] for m in res.moves])}")
        covered = result.covered
        if result.agrees:
            print(f"audit: the paper agrees: no statement is false here; {len(covered)} "
                  "covered: " + ", ".join(covered))
        else:
            print(f"audit: {len(covered)} statements covered: " + ", ".join(covered))
        for d in result.discrepancies:
            print(f"- {d['statement']} ({d['kind']})\n    says:  {prose(d['says'])}\n"
                  f"    truth: {prose(d['truth'])}")
            if d.get("rescued_by"):
                print(f"    under the reading: {prose(d['reading'])}; rescued by: "
                      f"{prose(d['rescued_by'])}")
            if d.get("witness"):
                print(f"    witness: {plain(_words(d['witness']))}")
        for d in result.notes:
            print(f"  note: {d['statement']} ({d['kind']}): {prose(d['truth'])}")
    if not result.agrees:
        print(f"{config.source}: the audit finds {len(result.discrepancies)} "
              f"discrepancy(ies); the first: {result.discrepancies[0]['statement']}",
              file=sys.stderr)
        return EXIT_FALSE
    return EXIT_OK
