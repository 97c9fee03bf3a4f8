"""The analysis pipeline (exactsym.analysis) and the command table (exactsym.cli.main)."""

from __future__ import annotations

import pytest

from exactsym.cli import main as cli
from exactsym.analysis import PARTS, Options, analyse
from exactsym.geometry.configuration import load
from exactsym.report.check import EXPECTATIONS, report_json
from exactsym.io.fileformat import EXPECT_KEYS

CASE = "cases/family/single-vertex-on-mirror.toml"


def test_parts_asked_for_and_what_they_need_are_computed_and_nothing_else():
    config = load(CASE)
    levels_only = analyse(config, sections=())
    assert (levels_only.truth, levels_only.level_verdicts, levels_only.paper,
            levels_only.audit) == (None, None, None, None)
    assert set(report_json(levels_only)) == {"format", "schema_version", "file", "name", "n",
                                             "sec", "levels", "number_field"}
    audited = analyse(config, sections=("audit",))
    assert audited.truth is not None and audited.paper is not None
    assert audited.level_verdicts is not None        # the audit covers the per-level statements
    assert audited.level_strings is None
    assert audited.audit.truth.group == audited.truth.name


def test_the_whole_analysis_equals_its_parts():
    config = load(CASE)
    whole = report_json(analyse(config, options=Options(strings=True)))
    for part in PARTS:
        alone = report_json(analyse(config, sections=(part,), options=Options(strings=True)))
        assert {k: v for k, v in alone.items() if k != "levels"}.items() <= whole.items()
    assert whole["levels"] == report_json(analyse(config, sections=("polygons",),
                                                  options=Options(strings=True)))["levels"]


def test_unknown_part_is_an_error():
    with pytest.raises(ValueError, match="unknown analysis part"):
        analyse(load(CASE), sections=("truth", "gathering"))


def test_every_expect_key_has_exactly_one_check():
    from exactsym.gathering.cases import CHECKED_KEYS, SETTING_KEYS
    from exactsym.report.check import GATHER_PREFIX
    check_keys = {k for k in EXPECT_KEYS if not k.startswith(GATHER_PREFIX)}
    assert set(EXPECTATIONS) == check_keys
    assert {k for k in EXPECT_KEYS if k.startswith(GATHER_PREFIX)} == \
        set(CHECKED_KEYS) | set(SETTING_KEYS)


def test_every_command_of_the_table_is_reachable_and_has_help():
    parser = cli.build_parser()
    for name, (text, add_arguments, run) in cli.COMMANDS.items():
        assert text and callable(add_arguments) and callable(run)
    assert parser.parse_args(["cases", "cases/family"]).command == "cases"
    assert {"check", "audit", "certify", "verify", "cases"} <= set(cli.COMMANDS)
