"""The exact gathering simulator (GatheringPattern, FormGPattern; docs/gathering.md).

Modules: :mod:`.geometry` (exact points, paths, collision predicates), :mod:`.pattern`
(``gathering_pattern``), :mod:`.robot` (the per-robot algorithm), :mod:`.world` and
:mod:`.schedulers` (the model and the adversary), :mod:`.invariants` (I1-I10),
:mod:`.trace` (trace files, replay), :mod:`.search` (shortest violating schedules),
:mod:`.cases` (case-file expectations), :mod:`.cli` (commands), :mod:`.paper_bridge`
(the only module importing the paper layer and the kernel), :mod:`.drawing` (a run as a
picture: the only module importing the pictures package, lazily).
"""
