"""Issue 34, item 7: ``exactsym`` alone lists the commands, every option has help, ``ledger``
writes docs/audit.md only with ``--write``, docs/cli.md covers every command."""

from __future__ import annotations

import re
import shutil
from pathlib import Path

from exactsym.cli.main import COMMANDS, build_parser, main

ROOT = Path(__file__).resolve().parents[2]


def test_exactsym_alone_lists_every_command(capsys):
    assert main([]) == 0
    out = capsys.readouterr().out
    for name in COMMANDS:
        assert re.search(rf"^\s+{name}\s", out, re.M), name


def _subparsers():
    parser = build_parser()
    action = next(a for a in parser._actions if a.__class__.__name__ == "_SubParsersAction")
    return action.choices


OWN = list(COMMANDS)                # gather and replay too (issue 34, item 7)


def test_every_option_of_every_command_has_help():
    missing = [(name, a.option_strings or a.dest) for name, sub in _subparsers().items()
               if name in OWN for a in sub._actions if not a.help]
    assert missing == []


def test_docs_cli_covers_every_command_and_option():
    text = (ROOT / "docs" / "cli.md").read_text(encoding="utf-8")
    for name, sub in _subparsers().items():
        assert f"exactsym {name}" in text, name
        for action in sub._actions:
            for option in action.option_strings:
                if option.startswith("--") and option != "--help":
                    assert option in text, (name, option)


def _tree(tmp_path: Path) -> Path:
    shutil.copytree(ROOT / "proofs", tmp_path / "proofs")
    (tmp_path / "docs").mkdir()
    (tmp_path / "docs" / "audit.md").write_text("stale\n", encoding="utf-8")
    return tmp_path


def test_ledger_writes_docs_audit_only_with_write(tmp_path, capsys):
    root = _tree(tmp_path)
    audit = root / "docs" / "audit.md"
    main(["ledger", "--root", str(root)])
    assert audit.read_text(encoding="utf-8") == "stale\n"
    main(["ledger", "--root", str(root), "--write"])
    assert audit.read_text(encoding="utf-8").startswith("#")
    capsys.readouterr()


def test_ledger_outside_a_checkout_is_one_line_exit_2(tmp_path, capsys, monkeypatch):
    from exactsym.ledger import cli
    monkeypatch.chdir(tmp_path)
    # an installed package: its own tree holds no proofs/
    monkeypatch.setattr(cli, "__file__", str(tmp_path / "site" / "exactsym" / "ledger" / "cli.py"))
    assert main(["ledger"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("exactsym: ") and "--root" in err[0]
