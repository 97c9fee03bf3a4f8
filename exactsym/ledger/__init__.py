"""The statement ledger (``proofs/statements.toml``): every definition, statement and
algorithm of the paper with its grade, readings, evidence and what its proof uses.

* :mod:`.model` loads and validates the ledger (frozen dataclasses);
* :mod:`.graph` builds the dependency graph (networkx) and propagates "rests on a refuted
  statement" and "rests only on proved statements";
* :mod:`.evidence` re-runs the evidence (case files through :mod:`.analysis_bridge`, the
  only module that imports the analysis; proof scripts; sweep summaries);
* :mod:`.audit_doc` writes ``docs/audit.md`` from the ledger;
* :mod:`.cli` is the command (``python -m exactsym.ledger [--json] [--check]``).
"""

from .model import GRADES, Ledger, LedgerError, Statement, load_ledger

__all__ = ["GRADES", "Ledger", "LedgerError", "Statement", "load_ledger"]
