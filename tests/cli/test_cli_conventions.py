"""Conventions of every command: --version, examples in --help, options that do not apply
rejected, several files with the worst exit status, a quiet end when the reader of the
output goes away, and the README's examples run as written."""

import re
import shlex
import subprocess
import sys
from pathlib import Path

import pytest

import exactsym
from exactsym.cli import main as cli
from exactsym.cli.main import main

ROOT = Path(__file__).resolve().parents[2]
NINE = "cases/examples/chiral-nine-gon.toml"


def run(capsys, *argv):
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def test_version(capsys):
    assert run(capsys, "--version") == (0, f"exactsym {exactsym.__version__}\n", "")


@pytest.mark.parametrize("command", sorted(cli.COMMANDS))
def test_every_command_has_help_with_an_example(command, capsys):
    code, out, err = run(capsys, command, "--help")
    assert code == 0 and out.startswith(f"usage: exactsym {command}")
    assert "\nexample" in out and f"exactsym {command}" in out.split("\nexample")[-1]
    assert cli.EXAMPLES[command]


def test_the_examples_of_check_help_run(capsys, monkeypatch):
    monkeypatch.chdir(ROOT)
    for example in cli.EXAMPLES["check"]:
        argv = [expanded for a in shlex.split(example.split("#")[0])[1:]
                for expanded in ([str(p.relative_to(ROOT)) for p in sorted(ROOT.glob(a))]
                                 if "*" in a else [a])]
        assert run(capsys, *argv)[0] == 0, example


@pytest.mark.parametrize("argv, words", [
    (["check", NINE, "--compact"], "--compact applies only with --json"),
    (["check", NINE, "--json", "--verbose"], "--json and --verbose do not go together"),
    (["check", NINE, NINE, "--json"], "--json takes one FILE"),
    (["cases", "--labels", "--lemma", "Pasym-Pord"], "--labels and --lemma do not go together"),
    (["check"], "the following arguments are required: FILE"),
])
def test_options_that_do_not_apply_are_rejected(argv, words, capsys, monkeypatch):
    monkeypatch.chdir(ROOT)
    code, out, err = run(capsys, *argv)
    assert code == 2 and out == ""
    assert err.startswith("exactsym: command line: ") and words in err
    assert len(err.strip().splitlines()) == 1


def test_several_files_one_line_each_and_the_worst_status(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(ROOT)
    false = tmp_path / "false.toml"
    false.write_text('format = 1\npoints = [["0","0"], ["2","0"]]\n[expect]\ngroup = "D1"\n')
    broken = tmp_path / "broken.txt"
    broken.write_text("0 0\n1 foo(2)\n")
    pentagon = "cases/examples/rational-pentagon.txt"

    code, out, err = run(capsys, "check", NINE, pentagon)
    assert code == 0 and err == ""
    assert out.splitlines() == [
        f"{NINE}: 9 robots, C3, not orderable, no leader; paper: orderable, leader 6; "
        "audit: 8 statements false",
        f"{pentagon}: 5 robots, D1, not orderable, leader 3; paper: not orderable, "
        "leader 3; audit: 2 statements false"]

    code, out, err = run(capsys, "check", NINE, str(false))
    assert code == 1 and len(out.splitlines()) == 2
    assert out.splitlines()[1].endswith("; 1 [expect] claim false")
    assert "[expect] group = 'D1' is false: exactsym finds 'D2'" in err

    code, out, err = run(capsys, "check", str(broken), NINE, str(false))
    assert code == 2 and len(out.splitlines()) == 2       # the others are still checked
    assert "broken.txt:2" in err and "Traceback" not in err

    code, out, err = run(capsys, "check", "--verbose", NINE, pentagon)
    assert code == 0 and out.count("\nsymmetry   ") == 2 and "levels, nearest first" in out


def _pipe_closed_early(argv, lines=1):
    """Run exactsym with its standard output read for ``lines`` lines, then closed."""
    proc = subprocess.Popen([sys.executable, "-m", "exactsym", *argv], cwd=ROOT,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    for _ in range(lines):
        proc.stdout.readline()
    proc.stdout.close()
    err = proc.stderr.read().decode()
    return proc.wait(timeout=120), err


def test_a_broken_pipe_ends_quietly(tmp_path):
    """`exactsym check F | head -1`: no internal error, no traceback; the exit status is
    the command's own (here 0: every claim of the file holds)."""
    big = tmp_path / "big.txt"
    big.write_text("".join(f"{i} {i * i % 1009}\n" for i in range(1500)))
    code, err = _pipe_closed_early(["check", "--json", str(big)])
    assert (code, err) == (0, "")
    code, err = _pipe_closed_early(["check", "--verbose", str(big)])
    assert (code, err) == (0, "")


def test_a_broken_pipe_keeps_the_exit_status(tmp_path):
    false = tmp_path / "false.toml"
    false.write_text('format = 1\npoints = [["0","0"], ["2","0"]]\n[expect]\ngroup = "D1"\n')
    big = tmp_path / "big.txt"
    big.write_text("".join(f"{i} {i * i % 1009}\n" for i in range(1500)))
    code, err = _pipe_closed_early(["check", "--verbose", str(big), str(big), str(false)])
    assert code == 1 and "is false" in err and "internal error" not in err


# ---------------------------------------------------------------- the README
README = (ROOT / "README.md").read_text()


def test_the_readme_toml_example_runs_as_written(tmp_path, capsys):
    (toml,) = re.findall(r"```toml\n(.*?)```", README, re.S)
    example = tmp_path / "example.toml"
    example.write_text(toml)
    code, out, err = run(capsys, "check", str(example))
    assert code == 0, err
    assert "symmetry   D1: " in out and "sqrt" not in err


def test_the_readme_summary_is_what_check_prints(capsys, monkeypatch):
    """The sample output in the README (lines ending in "..." are cut there) is what
    `exactsym check` prints on the chiral nine-gon."""
    monkeypatch.chdir(ROOT)
    (sample,) = re.findall(r"`exactsym check cases/examples/chiral-nine-gon.toml` prints a "
                           r"summary:\n\n```text\n(.*?)```", README, re.S)
    code, out, err = run(capsys, "check", NINE)
    printed = out.splitlines()
    position = 0
    for line in sample.splitlines():
        if line.strip() == "...":
            continue
        cut = line.endswith("...")
        match = [i for i, p in enumerate(printed) if i >= position and
                 (p.startswith(line[:-3]) if cut else p == line)]
        assert match, line
        position = match[0] + 1


def test_the_readme_python_example_runs(monkeypatch):
    import doctest
    monkeypatch.chdir(ROOT)
    (block,) = re.findall(r"```python\n(.*?)```", README, re.S)
    parser = doctest.DocTestParser()
    test = parser.get_doctest(block, {}, "README", "README.md", 0)
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS)
    runner.run(test)
    assert runner.summarize(verbose=False) == (0, 3)
