"""The audit's result as data: :class:`AuditResult` (``Analysis.audit``), beside the
truth's :class:`~exactsym.truth.symmetry.SymmetryGroup` and the paper's
:class:`~exactsym.paper.family.PaperResult`.

The discrepancies and notes stay JSON-ready dicts (``statement``, ``says``, ``truth``,
``witness``, ``kind``, ``count``, ...: the keys of ``docs/cli.md``); :meth:`AuditResult.as_dict`
is the object ``check --json`` writes under ``audit``, key for key as before the class.
Reading it as a mapping (``result["agrees"]``) still works, for code written against the
dict.
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["AuditResult", "AuditTruth"]


@dataclass(frozen=True)
class AuditTruth:
    """What the audit compared against: the true group's name (``Ck``, ``Dk``, ``O2``),
    orderability, leader (a robot index or None) and ``in_O_S`` (``def-symmetric-conf``
    decided from the true group)."""
    group: str
    orderable: bool
    leader: int | None
    in_O_S: bool

    def as_dict(self) -> dict:
        return {"group": self.group, "orderable": self.orderable, "leader": self.leader,
                "in_O_S": self.in_O_S}


@dataclass(frozen=True)
class AuditResult:
    """The paper against the ground truth on one configuration
    (:func:`exactsym.audit.statements.audit`).

    ``agrees``: no statement of the paper is false here; ``conclusions_agree``: the
    procedure's conclusions (GatheringPattern, MakeAsym, ElectLeader) agree with the
    truth; ``discrepancies`` and ``notes``: lists of JSON-ready dicts; ``covered``: the
    labels evaluated here, in the paper's order; ``truth``; ``bounded``: what the work
    budgets cut."""
    agrees: bool
    conclusions_agree: bool
    discrepancies: list
    notes: list
    covered: list
    truth: AuditTruth
    bounded: dict

    @classmethod
    def from_dict(cls, data: dict) -> "AuditResult":
        return cls(data["agrees"], data["conclusions_agree"], data["discrepancies"],
                   data["notes"], data["covered"], AuditTruth(**data["truth"]),
                   data["bounded"])

    def as_dict(self) -> dict:
        """The JSON object of ``check --json``'s ``audit`` (docs/cli.md)."""
        return {"agrees": self.agrees, "conclusions_agree": self.conclusions_agree,
                "discrepancies": self.discrepancies, "notes": self.notes,
                "covered": self.covered, "truth": self.truth.as_dict(),
                "bounded": self.bounded}

    def __getitem__(self, key: str):
        """``result["agrees"]``: the dict's reading (``truth`` as its dict)."""
        if key not in _KEYS:
            raise KeyError(key)
        value = getattr(self, key)
        return value.as_dict() if isinstance(value, AuditTruth) else value

    def get(self, key: str, default=None):
        return self[key] if key in _KEYS else default

    def __contains__(self, key) -> bool:
        return key in _KEYS

    def keys(self):
        return iter(_KEYS)


_KEYS = ("agrees", "conclusions_agree", "discrepancies", "notes", "covered", "truth",
         "bounded")
