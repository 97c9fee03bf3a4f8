"""The checker of refutation certificates (docs/certificates.md, "Refutations").

A refutation wraps a group certificate of P: once that proves G and its orderability, the
premise of the label and its failed conclusion are facts about G, derived by the function
``dispatch.REFUTATIONS`` names for the label: here for P in O_A, in the extension
``ext_polygons`` for the statements about the polygons (levels) of G_P.
"""

from __future__ import annotations

from .dispatch import REFUTATIONS, load
from .groups import verify_certificate
from .numbers import Invalid, frac, is_int, need

REFUTABLE = {"Pasym-Pord": "P is orderable if P is in O_A",
             "lem-asym-ord": "an asymmetric polygon is orderable",
             "cor-Pasym-Pord": "P is orderable if G_P is in O_A",
             "lem-one-pair-asym-ord": "if G_P contains an asymmetric polygon, P is orderable",
             "lem-asym-pair-ord": "an asymmetric pair is orderable",
             "lem-all-pair-asym-ord": "if G_P has an asymmetric pair, P is orderable",
             "obs-merg-asym-pair": "if <G_i, G_j> is an asymmetric pair, G_ij is asymmetric",
             "lemma-sym-regular": "a convex polygon with more than one line of symmetry, "
                                  "each through a vertex, is regular",
             "obs-exh-poly": "every straight symmetric polygon is of type 0, 1, 2, 3 or 4"}

def not_orderable(premise: str, name: str, k: int, orderable: bool) -> str:
    """The conclusion "P is orderable" fails: some element of G moves a point."""
    need(orderable is False, f"the conclusion holds: group {name} is orderable")
    mover = f"its rotation of order {k}" if k > 1 else "its mirror"
    return f"{premise}, yet P (group {name}) is not orderable: {mover} moves a point"

def in_o_a(obj: dict, name: str, k: int, n: int, orderable: bool) -> str:
    """Pasym-Pord, lem-asym-ord: P is in O_A -- at least two points, no mirror that moves a
    point (a reflection in G moves one unless G = D1 fixes every point), no half-turn (k
    odd); for lem-asym-ord also one level -- and P is not orderable."""
    need(n >= 2 and (name.startswith("C") or name == "D1" and orderable) and k % 2 == 1,
         f"the premise fails: group {name} on {n} point(s) is in O_S")
    if obj["label"] == "lem-asym-ord":
        need(_one_level(obj["certificate"]["configuration"]), "the premise fails: not one polygon")
    return not_orderable(f"group {name} has no mirror moving a point and no half-turn", name, k,
                         orderable)

def _one_level(config) -> bool:
    """All points at one distance from c (rational coordinates only)."""
    pts = config["points"]
    need(all(isinstance(v, (str, int)) for p in pts for v in p),
         "one level: only rational coordinates are supported")
    if config["coordinates"] == "polar":
        return len({frac(p[0]) for p in pts}) == 1
    xs, ys = [frac(p[0]) for p in pts], [frac(p[1]) for p in pts]
    cx, cy = sum(xs) / len(xs), sum(ys) / len(ys)
    return len({(x - cx) ** 2 + (y - cy) ** 2 for x, y in zip(xs, ys)}) == 1

def verify_refutation(obj) -> tuple[bool, str]:
    """``(True, summary)`` when the refutation certificate shows a configuration meeting the
    premise of ``obj["label"]`` whose conclusion is false, all derived from the groups its
    embedded certificates prove, else ``(False, reason)``."""
    try:
        need(isinstance(obj, dict) and obj.get("format") == "exactsym-refutation"
             and is_int(obj.get("version")) and obj["version"] == 1,
             "not an exactsym refutation of version 1")
        label = obj.get("label")
        need(label in REFUTABLE, f"no refutation by symmetry facts for {label!r}")
        need(obj.get("statement") == REFUTABLE[label], "the statement is not the label's")
        cert = obj["certificate"]
        ok, why = verify_certificate(cert)
        need(ok, f"the embedded certificate is invalid: {why}")
        name, orderable = cert["claim"]["group"], cert["claim"]["orderable"]
        n, k = len(cert["configuration"]["points"]), 1 if name == "O2" else int(name[1:])
        return True, f"{label} refuted: " + load(REFUTATIONS, label)(obj, name, k, n, orderable)
    except Invalid as err:
        return False, str(err)
    except (KeyError, TypeError, ValueError, IndexError, AttributeError) as err:
        return False, f"malformed refutation ({type(err).__name__}: {err})"
