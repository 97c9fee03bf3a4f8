"""The paper's algorithms as an observer of the other handedness runs them.

"Clockwise for this observer" (MakeAsym's and Make_SymToAsym's epsilon moves) and the
ordered pair (CW, ACW) of Elect_Leader_Asym depend on the robot's handedness, which the
paper does not fix (no chirality).  The same configuration may therefore see two runs of
the paper: the one in the file's frame and the one in its mirror image (robot indices
are unchanged by the reflection, so a witness names the same robots in both).  A
guarantee of an algorithm that fails in either run fails on the configuration; listing
both runs' failures makes the audit of a configuration and of its mirror image name the
same statements (issue 32: no robot frame is special).
"""

from __future__ import annotations

__all__ = ["other_handedness_findings", "frames_agree", "decided_without_tie", "MIRROR_RUN"]

MIRROR_RUN = "an observer of the other handedness (the mirror image: turn -> -turn)"


def failed_guarantees(trace: list) -> list[dict]:
    """The algorithms' guarantees the trace records as false (``holds`` False), the
    Section-3 claims, the defects of a literal reading and exactsym's repairs left out:
    the former do not depend on handedness (they are about the polygons), the others
    are notes."""
    return [e for e in trace if e.get("holds") is False and e["algorithm"] != "Section 3"
            and e.get("kind") not in ("literal-reading", "repair")]


def other_handedness_findings(identity_trace: list, mirror_trace: list,
                              claims: dict) -> list[dict]:
    """Audit entries for the guarantees false in ``mirror_trace`` (the run of the
    reflected configuration) whose statement and kind the identity run does not find
    false: the audit's shape, kind ``algorithm`` (``reading`` when the trace names the
    reading it fails under), the witness naming the run.
    ``claims``: statement -> what it claims, in a line."""
    def key(e):
        return e["statement"], "reading" if e.get("reading") else "algorithm"

    seen = {key(e) for e in failed_guarantees(identity_trace)}
    out = []
    for e in failed_guarantees(mirror_trace):
        if key(e) in seen:
            continue
        seen.add(key(e))
        witness = {"run": MIRROR_RUN}
        if isinstance(e.get("witness"), dict):
            witness.update(e["witness"])
        d = {"statement": e["statement"], "says": claims.get(e["statement"], e["statement"]),
             "truth": f"false for {MIRROR_RUN}: {e['detail']}", "witness": witness,
             "kind": "algorithm"}
        if e.get("reading"):
            d.update(kind="reading", reading=e["reading"], rescued_by=e.get("rescued_by"))
        out.append(d)
    return out


def frames_agree(a, b) -> bool:
    """Two runs of the paper (``PaperResult``) act alike: both complete, the same robots
    move and the same leader is elected; a run stopped early (the SEC changed, ...)
    agrees with another while the robots both move agree."""
    ma, mb = [m["robot"] for m in a.moves], [m["robot"] for m in b.moves]
    if a.complete and b.complete:
        return ma == mb and a.leader == b.leader
    k = min(len(ma), len(mb))
    return ma[:k] == mb[:k] and (k > 0 or a.complete == b.complete)


def decided_without_tie(run) -> bool:
    """The run (``PaperResult``) chose every leader without a tie: no choice depended on
    how the observer labels the vertices (a tied lexicographic minimum is taken at the
    first vertex from the observer's +x ray, which a rotation of the frame changes).  A
    reading whose runs agree only through such a tie does not rescue a statement: the
    agreement would not survive a rotated frame."""
    return run.complete and not any(e.get("labelling_dependent") for e in run.trace)
