"""Issue 33: `exactsym --version` and `exactsym --help` build no command's arguments, so
they import none of the analysis (they took 0.8 s CPU for a version string)."""

import subprocess
import sys

PROBE = ("import sys; from exactsym.cli.main import main; code = main({argv!r}); "
         "print(sorted(m for m in sys.modules if m.startswith('exactsym.') and "
         "m.split('.')[1] in ('analysis', 'audit', 'gathering', 'sweeps', 'pictures', "
         "'ledger', 'truth', 'paper'))); sys.exit(code)")


def _loaded(argv) -> tuple[int, str]:
    done = subprocess.run([sys.executable, "-c", PROBE.format(argv=argv)],
                          capture_output=True, text=True, timeout=60)
    return done.returncode, done.stdout.strip().splitlines()[-1]


def test_version_and_help_import_no_analysis():
    assert _loaded(["--version"]) == (0, "[]")
    assert _loaded(["--help"]) == (0, "[]")
    # a command's help still builds its arguments: gather's come from the gathering package
    code, loaded = _loaded(["gather", "--help"])
    assert code == 0 and "exactsym.gathering.cli" in loaded
