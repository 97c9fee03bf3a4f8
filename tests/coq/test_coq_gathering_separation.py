"""(T4), the fat-robot argument of proofs/coq/Exactsym.v (first written for Gathering.v,
whose exports inline both libraries, as here), against exact
arithmetic: whenever the library's ``robots_apart`` says two robots are more than 2
apart, exactsym's exact distance (the simulator's numbers: cos/sin of turns j/24 are
multiquadratic) is more than 2.  The tests are sufficient only, so some pairs more than 2
apart are not recognised; none recognised is closer.  One ``coqc`` run; skips without
coqc."""

from __future__ import annotations

import random
import re
import shutil
import subprocess
from fractions import Fraction

import pytest

from exactsym.certificates.coq_gathering import gathering_library_text
from exactsym.certificates.coq_refutation import library_text
from exactsym.gathering.paper_bridge import read_case

COQC = shutil.which("coqc")


def _pairs(count: int = 200) -> list:
    """Seeded pairs (r, turn) of robots: radii k/4 up to 10 (half of them up to 4, where
    the tests are tight), C included, turns j/24."""
    rng = random.Random(35)
    out = []
    while len(out) < count:
        top = 41 if rng.random() < 0.5 else 17
        pair = tuple((Fraction(rng.randrange(top), 4), Fraction(rng.randrange(24), 24))
                     for _ in range(2))
        if pair[0][0] == 0:
            pair = ((Fraction(0), Fraction(0)), pair[1])
        if pair[0] != pair[1] and not (pair[0][0] == pair[1][0] == 0):
            out.append(pair)
    return out


def _more_than_2_apart(pair, tmp_path) -> bool:
    path = tmp_path / "pair.toml"
    rows = ",\n".join(f'  {{ r = "{r}", turn = "{t}" }}' for r, t in pair)
    path.write_text(f'format = 1\nname = "pair"\nmodel = "points"\npoints = [\n{rows},\n]\n')
    (x1, y1), (x2, y2) = read_case(str(path))[0]
    return (x1 - x2) ** 2 + (y1 - y2) ** 2 > 4


def _q(x: Fraction) -> str:
    return f"(Qmake {x.numerator} {x.denominator})"


@pytest.mark.skipif(COQC is None, reason="coqc is not installed (apt-get install coq): the "
                    "Coq library is not run")
def test_robots_apart_implies_more_than_2_apart(tmp_path):
    pairs = _pairs()
    terms = "; ".join(f"(Pt {_q(r1 * r1)} {_q(t1)}, Pt {_q(r2 * r2)} {_q(t2)})"
                      for (r1, t1), (r2, t2) in pairs)
    text = (library_text() + "\n" + gathering_library_text() + "\n"
            f"Definition pairs : list (pt * pt) := [{terms}].\n"
            "Eval vm_compute in map (fun pq => robots_apart (fst pq) (snd pq)) pairs.\n")
    (tmp_path / "Separation.v").write_text(text)
    run = subprocess.run([COQC, "-q", "Separation.v"], cwd=tmp_path, capture_output=True,
                         text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    said = re.findall(r"\b(true|false)\b", run.stdout.split("=", 1)[1])
    assert len(said) == len(pairs)
    exact = [_more_than_2_apart(p, tmp_path) for p in pairs]
    recognised = [e for s, e in zip(said, exact) if s == "true"]
    assert all(recognised), [p for p, s, e in zip(pairs, said, exact) if s == "true" and not e]
    assert len(recognised) >= 60                        # the tests recognise most pairs
    assert exact.count(False) >= 20                     # and close pairs occur
