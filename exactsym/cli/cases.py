"""The ``cases`` command: run the case library, one line per case (``docs/cases.md``)."""

from __future__ import annotations

from ..errors import EXIT_FALSE, EXIT_OK
from ..report.cases import label_counts, run_cases


def run(args) -> int:
    if args.labels:
        for label, count in label_counts(args.directory).items():
            print(f"{count:4d}  {label}")
        return EXIT_OK
    results = run_cases(args.directory, args.lemma)
    for result in results:
        print(f"{'PASS' if result.passed else 'FAIL'}  {result.path}  "
              f"[{', '.join(result.lemmas)}]")
        for failure in result.failures:
            print(f"      {failure}")
    failed = sum(1 for r in results if not r.passed)
    print(f"{len(results) - failed} passed, {failed} failed")
    return EXIT_FALSE if failed else EXIT_OK


def add_arguments(parser) -> None:
    parser.add_argument("directory", nargs="?", default="cases", metavar="DIR",
                        help="the case library: every .toml/.txt file under DIR "
                             "(default: cases)")
    parser.add_argument("--lemma", metavar="LABEL", help="only the cases tagged with LABEL")
    parser.add_argument("--labels", action="store_true",
                        help="list every known label with the number of cases tagged with it")
