"""The examples of docs/api.md run as written (from the repository's root)."""

import doctest
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def test_api_page_examples(monkeypatch):
    monkeypatch.chdir(ROOT)
    result = doctest.testfile(str(ROOT / "docs/api.md"), module_relative=False,
                              optionflags=doctest.ELLIPSIS)
    assert result.attempted >= 20 and result.failed == 0


def test_picture_commands_in_docs_make_the_pictures_shown(tmp_path, monkeypatch):
    """Each picture command of docs/pictures.md (`exactsym plot ...`, `exactsym gather
    ... --plot`, `python -m exactsym.pictures.run_cli ...`), run with its output sent
    elsewhere, draws the same elements (SVG ids and texts) as the committed picture."""
    import shlex
    import xml.etree.ElementTree as ET

    from exactsym.cli.main import main as exactsym_main
    from exactsym.pictures.run_cli import main as run_main

    def content(path):
        root = ET.parse(path).getroot()
        ids = sorted(e.get("id") for e in root.iter() if e.get("id"))
        texts = sorted("".join(e.itertext()) for e in root.iter("{http://www.w3.org/2000/svg}text"))
        return ids, texts

    monkeypatch.chdir(ROOT)
    commands = [line.strip() for line in (ROOT / "docs/pictures.md").read_text().splitlines()
                if line.startswith(("exactsym plot", "exactsym gather",
                                    "python -m exactsym.pictures"))
                and "docs/img/" in line]
    assert len(commands) == 2 and any(c.startswith("exactsym gather") for c in commands)
    for command in commands:
        words = shlex.split(command)
        run_picture = words[0] == "python"
        argv = words[3:] if run_picture else words[1:]
        shown = next(a for a in argv if a.startswith("docs/img/"))
        argv[argv.index(shown)] = str(tmp_path / Path(shown).name)
        assert (run_main if run_picture else exactsym_main)(argv) == 0
        assert content(tmp_path / Path(shown).name) == content(ROOT / shown), command
