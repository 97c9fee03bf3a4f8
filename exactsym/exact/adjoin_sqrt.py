"""A square root that the configuration's number system may not hold: adjoin it.

MakeAsym moves a robot radially to another circle (L1526, "move v_l to the circumference
of the enclosing circle of G_t"): the scale factor is ``sqrt(r_to^2 / r_from^2)``.  When
that square root is not in the configuration's field, the configuration after the move
lives in a larger one: the multiquadratic field with one more square root of a rational,
or a tower of quadratic extensions over it (:class:`~.evaluate.TowerSystem`, a nested
radical).  :func:`adjoin_sqrt` returns the root and the number system that holds it with
every number of the configuration.

A configuration in a cyclotomic field (``FieldSystem`` of Q(zeta_M)) or already in a tower
over one (:class:`~.evaluate.CyclotomicTowerSystem`) gets the root from that tower's
complete square-root test (:mod:`.cyclotomic_sqrt`): a new level only for a non-square.

Over the sparse Q(zeta_N) (cosines of turns of large denominators) the root is a new level
of a copy of the configuration's tower when Legendre characters prove it new
(:mod:`.sparse_nested`); a radicand they do not settle is out of reach.

Over a tower whose radicands all lie in K_0 (nested radicals sqrt(1 + sqrt p), whose
levels are square roots of numbers of K_0), a radicand x that uses the levels S only lies
in F = K_0(y_s : s in S), and by Kummer theory x is a square of the top field
F(y_t : t not in S) iff x prod(r_t : t in U) is a square of F for some set U of the other
levels.  Legendre characters of F (ring maps F -> F_p at primes unramified in F) that no U
can satisfy prove x a non-square there (:func:`_kummer_nonsquare`): the new level is then
adjoined without the tower's complete test, which branches twice per level that x does not
use (ten nested radicals, MakeAsym's radial move: 4 s of a 5 s check, issue 33).

Out of reach (None): a base Q(zeta_M) beyond the tower's a-priori bound
(:data:`~.cyclotomic_tower.MAX_BASE_DEGREE`), a number field that is not cyclotomic, and a
root sqrt(m) w whose integer m has more than 160 bits (:func:`~.mq_closure.decided_sqrt`
without its bounded split: a root found that way would make the check analyse a moved
copy of the whole configuration in a larger field, at a cost out of proportion).
"""

from __future__ import annotations

from flint import fmpq, fmpz

from ..errors import FieldTooLargeError
import random

from .evaluate import (CyclotomicTowerSystem, FieldSystem, MultiquadraticSystem,
                       RationalSystem, SparseCyclotomicSystem, SparseKummerSystem, TowerSystem)
from .field import FieldElement
from .modular import image, kummer_split_primes, sqrt_mod
from .mq_closure import decided_sqrt
from .multiquadratic import MQ
from .tower import TowerElement, wrap
from .tower_proof import norm

__all__ = ["adjoin_sqrt"]


def _as_mq(x):
    if isinstance(x, MQ):
        return x
    if isinstance(x, FieldElement):
        return None                       # a cyclotomic (or tower) number
    return MQ.rational(x)


def _radicands(values) -> set:
    out: set = set()
    for v in values:
        out |= set(v.radicands())
    return out


def _sparse_level(system, x):
    """``(system2, root)`` with sqrt(x) a new level over the sparse Q(zeta_N) (a copy of the
    tower: the configuration's own tower keeps its levels), or None."""
    if not isinstance(system, SparseKummerSystem) or not isinstance(x, TowerElement):
        return None
    try:
        bigger = system.extended(x)
    except FieldTooLargeError:          # not proved new: x may be a square there
        return None
    tower = bigger.tower
    return bigger, wrap(tower, (tower.levels, tower.zero, tower.one))


def _levels_used(v, out: set, base: int) -> set | None:
    """The levels s whose generator y_s occurs in the raw tower value v (a tuple
    (s, a, b) is a + b y_s with b != 0); None when a base number of v is not an ``MQ``
    whose radicands divide ``base`` (then no map below is defined on it)."""
    if type(v) is tuple:
        out.add(v[0])
        if _levels_used(v[1], out, base) is None or _levels_used(v[2], out, base) is None:
            return None
        return out
    if type(v) is not MQ or any(base % int(m) for m in v.terms):
        return None
    return out


def _kummer_nonsquare(tower, x, primes: int = 24, maps: int = 4) -> bool:
    """True when x (a raw value of ``tower``, x != 0) is proved no square of the tower's top
    field; False decides nothing.  Only for a tower whose radicands r_1..r_L all lie in
    K_0 = Q(sqrt q : q in tower.primes) (``MQ`` whose radicands divide the primes' product).

    With S the levels x uses and F = K_0(y_s : s in S), the top field is F(sqrt r_t : t
    not in S), so x is a square there iff x prod(r_t : t in U) is a square of F for some U
    (Kummer theory).  A ring map phi: R -> F_p on the numbers of F whose coefficients have
    no p in a denominator (p = 1 mod 8 q for every odd base prime q, so each q is a square
    mod p; sqrt q -> a root mod p; y_s -> a root of phi(r_s)) at a p for which no
    N_(K_0/Q)(r_s), s in S, nor its denominator has the factor p is unramified (the
    discriminant of that basis is a p-unit), so its kernel's local ring is integrally
    closed, with residue field F_p: the image of a square p-unit is a square, and
    chi(z) = (phi(z) | p) is a character on the p-units.  Each such chi with chi(x) and
    every chi(r_t) non-zero gives chi(x) = sum(chi(r_t) : t in U) over F_2; a system with
    no solution U proves x no square (the elimination of :func:`.modular.kummer_subset`).
    The maps are ``maps`` sign choices at each of ``primes`` primes (seeded: the same
    primes and maps every run)."""
    radicands = tower.radicands
    base = 1
    for q in tower.primes:
        base *= q
    if not radicands or not all(_levels_used(r, set(), base) == set() for r in radicands):
        return False
    used = _levels_used(x, set(), base)
    if used is None:
        return False
    others = [t for t in range(1, len(radicands) + 1) if t not in used]
    bad = 1
    for s in used:
        n = norm(tower, radicands[s - 1])
        bad *= int(n.p) * int(n.q)
    draw = random.Random(len(radicands))
    rows: dict = {}                     # pivot bit -> reduced row; bit 0: x, bit i: r_(t_i)
    found = kummer_split_primes(tower.primes)
    for _ in range(primes):
        p = next(found)
        if bad % p == 0:
            continue
        roots_q = [sqrt_mod(q, p) for q in tower.primes]
        for _ in range(maps):
            signs = {q: r if draw.random() < 0.5 else p - r
                     for q, r in zip(tower.primes, roots_q)}
            roots = [0] * len(radicands)
            try:
                for s in sorted(used):
                    root = sqrt_mod(image(radicands[s - 1], p, signs, roots), p)
                    if not root:        # phi(r_s) a non-residue or 0: no such map
                        break
                    roots[s - 1] = root if draw.random() < 0.5 else p - root
                else:
                    values = [image(x, p, signs, roots)] + \
                        [image(radicands[t - 1], p, signs, roots) for t in others]
                    if all(values):
                        row = 0
                        for i, v in enumerate(values):
                            if pow(v, (p - 1) // 2, p) != 1:
                                row |= 1 << i
                        for pivot in sorted(rows, reverse=True):
                            if row >> pivot & 1:
                                row ^= rows[pivot]
                        if row == 1:    # chi(x) = 1 + sum over U: no U satisfies it
                            return True
                        if row:
                            rows[row.bit_length() - 1] = row
            except ValueError:          # p divides a denominator: the map is not defined
                continue
    return False


def adjoin_sqrt(system, numbers, x):
    """``(system2, root)``: the non-negative square root of the kernel number ``x >= 0``
    and a number system holding it and every one of ``numbers`` (the configuration's
    coordinates, in ``system``); ``system2`` is ``system`` when it already holds the
    root.  None when out of reach (see the module docstring)."""
    if isinstance(system, FieldSystem) and system.field.conductor is not None:
        try:
            system = CyclotomicTowerSystem(system.field.conductor)
        except FieldTooLargeError:
            return None
    if isinstance(system, CyclotomicTowerSystem):
        # its numbers are Q(zeta_M) elements and MQ rationals only: never an irrational MQ
        try:
            return system, system.sqrt(system.coerce(x))
        except FieldTooLargeError:      # a nested radical over a large base: out of reach
            return None
    if isinstance(system, TowerSystem):
        raw = x.v if isinstance(x, TowerElement) else system.coerce(x)
        if isinstance(raw, MQ):
            root, decided = decided_sqrt(raw, bounded=False)
            if root is not None:
                return system, root
            if not decided:
                return None
        try:
            if type(system) is TowerSystem and type(raw) is tuple and \
                    _kummer_nonsquare(system.tower, raw):
                return system, wrap(system.tower, system.tower.adjoin(raw))
            return system, system.sqrt(x)
        except FieldTooLargeError:      # a tower beyond its bounds, or a sparse base
            return _sparse_level(system, x)
    if isinstance(system, SparseCyclotomicSystem):
        # cosines held as sums of roots of unity: the same numbers in a tower over them
        system = SparseKummerSystem(system.conductor)
        return _sparse_level(system, system.coerce(x))
    if not isinstance(system, (RationalSystem, MultiquadraticSystem)):
        return None
    mx = _as_mq(x)
    # a rational coordinate has no radicand: only the others are converted (100,000
    # random points: 200,000 MQ numbers built for nothing, issue 9)
    values = [_as_mq(v) for v in numbers if type(v) is not fmpq]
    if mx is None or any(v is None for v in values):
        return None
    root, decided = decided_sqrt(mx, bounded=False)
    if root is not None:
        have = set(getattr(system, "radicands", ()))
        need = _radicands([root]) - {1}
        if isinstance(system, MultiquadraticSystem) and need <= have:
            return system, root
        return MultiquadraticSystem(have | need | _radicands(values)), root
    if not decided:
        return None
    primes = sorted({int(p) for m in _radicands(values + [mx]) for p, _ in fmpz(m).factor()})
    tower = TowerSystem(primes)
    return tower, tower.sqrt(mx)
