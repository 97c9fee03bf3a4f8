"""(T4)'s chord test against exact arithmetic (proofs/coq/Exactsym.v, ``chord_apart``):
two robots on one circle about C, a small turn apart, that the library says are more than
2 apart are so in exactsym's exact numbers (the simulator's: cos/sin of turns j/24 are
multiquadratic); with the proved sine bound 3g - 9/2 g^3 replaced by the false 4g (pi < 4)
the test passes pairs that are closer, and the library's proof of the bound
(``sin_lower_bound``) no longer compiles.  Three ``coqc`` runs; skips without coqc."""

from __future__ import annotations

import re
import shutil
import subprocess
from fractions import Fraction

import pytest

from exactsym.certificates.coq_refutation import library_text
from exactsym.gathering.paper_bridge import read_case

COQC = shutil.which("coqc")
_BOUND = "Definition sine_bound (g : Q) : Q := 3 * g - (9 # 2) * (g * g * g)."


def _pairs() -> list:
    """Robots (r, turn) on one circle: radii k/4 from 1 to 12, gaps j/24 (j = 1..6, up to
    a quarter turn), the first robot at turn k/24 (so the pair is turned as well)."""
    out = []
    for k in range(4, 49, 3):
        r = Fraction(k, 4)
        for j in range(1, 7):
            t = Fraction(k % 24, 24)
            out.append(((r, t), (r, (t + Fraction(j, 24)) % 1)))
    return out


def _more_than_2_apart(pair, tmp_path) -> bool:
    path = tmp_path / "pair.toml"
    rows = ",\n".join(f'  {{ r = "{r}", turn = "{t}" }}' for r, t in pair)
    path.write_text(f'format = 1\nname = "pair"\nmodel = "points"\npoints = [\n{rows},\n]\n')
    (x1, y1), (x2, y2) = read_case(str(path))[0]
    return (x1 - x2) ** 2 + (y1 - y2) ** 2 > 4


def _q(x: Fraction) -> str:
    return f"(Qmake {x.numerator} {x.denominator})"


def _chord_apart(library: str, pairs, tmp_path) -> list:
    terms = "; ".join(f"(Pt {_q(r1 * r1)} {_q(t1)}, Pt {_q(r2 * r2)} {_q(t2)})"
                      for (r1, t1), (r2, t2) in pairs)
    text = (library + "\n" f"Definition pairs : list (pt * pt) := [{terms}].\n"
            "Eval vm_compute in map (fun pq => chord_apart (fst pq) (snd pq)) pairs.\n")
    (tmp_path / "Chord.v").write_text(text)
    run = subprocess.run([COQC, "-q", "Chord.v"], cwd=tmp_path, capture_output=True,
                         text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    said = re.findall(r"\b(true|false)\b", run.stdout.split("=", 1)[1])
    assert len(said) == len(pairs)
    return [s == "true" for s in said]


@pytest.mark.skipif(COQC is None, reason="coqc is not installed (apt-get install coq): the "
                    "Coq library is not run")
def test_chord_apart_implies_more_than_2_apart(tmp_path):
    pairs = _pairs()
    exact = [_more_than_2_apart(p, tmp_path) for p in pairs]
    said = _chord_apart(library_text(), pairs, tmp_path)
    assert not [p for p, s, e in zip(pairs, said, exact) if s and not e]
    assert said.count(True) >= 40                       # the test recognises most pairs
    assert exact.count(False) >= 10                     # and close pairs occur
    text = library_text()
    assert _BOUND in text and "Lemma sin_lower_bound" in text
    weakened = text.replace(_BOUND, "Definition sine_bound (g : Q) : Q := 4 * g.")
    (tmp_path / "Weak.v").write_text(weakened)
    run = subprocess.run([COQC, "-q", "Weak.v"], cwd=tmp_path, capture_output=True,
                         text=True, timeout=300)
    assert run.returncode != 0, "the sine bound's proof accepted a false bound"
    weak = _chord_apart(weakened.split("Module SineBound.")[0], pairs, tmp_path)
    assert [p for p, s, e in zip(pairs, weak, exact) if s and not e], \
        "the weakened bound passed no close pair: the test cannot fail"
