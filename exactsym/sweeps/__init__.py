"""Sweeps: run an analysis over a whole family of configurations, on Dask distributed.

Modules (``docs/sweeps.md``): :mod:`.canonical` (bracelets, orderly generation, Burnside),
:mod:`.families` (the family texts and their enumerators), :mod:`.analysis_bridge` (the
only module importing the rest of exactsym), :mod:`.job` (one batch), :mod:`.engine`
(serial / Dask runs), :mod:`.results` (the JSON-lines file), :mod:`.summary` (counts,
smallest counterexamples, case files, ledger evidence), :mod:`.casefile` (TOML text),
:mod:`.cli` (the command).
"""
