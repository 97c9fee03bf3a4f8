"""The exact gathering simulator (GatheringPattern, FormGPattern; docs/gathering.md).

Modules: :mod:`.geometry` (exact points, paths, collision predicates; the SEC is
:mod:`exactsym.geometry.sec`'s), :mod:`.pattern` (``gathering_pattern``), :mod:`.robot`
(the per-robot algorithm) and :mod:`.corrected` (the corrected variant), :mod:`.world`
and :mod:`.schedulers` (the model and the adversary), :mod:`.invariants` (I1-I10) with
the critical instants of a motion (:mod:`.motion`, :mod:`.point_sets`, :mod:`.instants`,
:mod:`.joint_instants` and the modules they use), :mod:`.run_home` (a run's tower of
nested radicals), :mod:`.trace` (trace files, replay), :mod:`.search` (shortest
violating schedules), :mod:`.cases` (case-file expectations), :mod:`.cli` (commands),
:mod:`.paper_bridge` (the only module importing the paper layer; :mod:`.algebraic_kernel`
writes a K(alpha) snapshot for it), :mod:`.drawing` (a run as a picture: the only module
importing the pictures package, lazily).  The numbers of the motion (roots of
polynomials, nested radicals, K(alpha)) are :mod:`exactsym.exact.algebraic`'s.
"""
