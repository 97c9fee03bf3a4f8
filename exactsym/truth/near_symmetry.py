"""Near symmetry, as a hint (never a verdict).

A configuration typed with decimals (a regular hexagon to 6 digits) is exactly less
symmetric than the shape it was meant to be: its exact group is the truth and stays
so.  :func:`near_symmetry_hint` says, beside it, that a more symmetric configuration
lies within a tiny distance: "exact group D2; within 6e-7 of D6".

Floats only *propose* the candidate: a rotation order k (and a mirror) under which the
points match up to a tolerance, the matching of the points, and rounded (decimal
grid) positions.  Everything stated is then proved exactly:

* the candidate Q is built with exact numbers: a rational centre c, the rotation by
  1/k turn (its cosine and sine in the kernel's number field), a reflection in a line
  of rational direction (a rational matrix), and orbits of rational representatives
  (a representative on a mirror is projected onto it exactly);
* its group is computed by the ground truth (:func:`exactsym.truth.symmetry.symmetry_group`)
  on Q itself: the group named is Q's exact group, larger than the input's;
* the distance: every ``|p_i - q_i|^2 <= bound^2`` is checked exactly, so each robot is
  within ``bound`` of its place in Q (max displacement, a proved upper bound).

Nothing here changes a verdict; a hint that cannot be proved is not given (None).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction

from ..geometry.configuration import Configuration
from ..errors import InputError
from ..exact import fmpq, number_system
from ..exact.number import all_plain_rational
from .symmetry import symmetry_group

__all__ = ["NearSymmetry", "near_symmetry_hint", "hint_text"]

#: Hints are looked for on Cartesian inputs of at most this many points (the float
#: matching is quadratic).
MAX_POINTS = 400
#: Default tolerance, relative to the SEC radius: farther than this is not "near".
TOLERANCE = 1e-6


@dataclass(frozen=True)
class NearSymmetry:
    """``candidate`` (an exact configuration, same indices) has group
    ``candidate_group``, larger than ``exact_group``, and every robot of the input lies
    within ``bound`` (exact, proved) of its place in it."""
    exact_group: str
    candidate_group: str
    bound: fmpq
    candidate: Configuration

    @property
    def text(self) -> str:
        return (f"exact group {self.exact_group}; within {_decimal(self.bound)} of "
                f"{self.candidate_group} (hint only: the exact group stands)")

    def __str__(self) -> str:
        return self.text


def _order(group) -> int:
    return group.rotations + group.mirrors


def _decimal(q: fmpq) -> str:
    f = float(q)
    text = f"{f:.0e}" if f else "0"
    return text.replace("e-0", "e-").replace("e+0", "e+")


def _round_up_1digit(x: float) -> Fraction:
    """The least number d * 10^e (d one digit) at least x: a short bound to state."""
    if x <= 0:
        return Fraction(0)
    e = math.floor(math.log10(x))
    d = math.ceil(x / 10 ** e - 1e-12)
    if d >= 10:
        d, e = 1, e + 1
    return Fraction(d) * Fraction(10) ** e


def _grid(x: float, step: Fraction) -> Fraction:
    return Fraction(round(x / float(step))) * step


def _match(P, images, tol) -> list | None:
    """The permutation i -> j with ``images[i]`` within ``tol`` of ``P[j]``, else None."""
    import numpy as np
    d = np.sqrt(((images[:, None, :] - P[None, :, :]) ** 2).sum(-1))
    j = d.argmin(axis=1)
    if d[np.arange(len(P)), j].max() > tol or len(set(j.tolist())) != len(P):
        return None
    return j.tolist()


def _float_rotation(P, c, k):
    import numpy as np
    a = 2 * math.pi / k
    R = np.array([[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]])
    return (P - c) @ R.T + c


def _float_reflection(P, c, phi):
    import numpy as np
    S = np.array([[math.cos(2 * phi), math.sin(2 * phi)], [math.sin(2 * phi), -math.cos(2 * phi)]])
    return (P - c) @ S.T + c


def _propose(P, c, tol, n, exact_order):
    """Float proposal: ``(k, rho, phi, sigma)`` of the largest group C_k (``phi`` None)
    or D_k (mirror at angle ``phi``) matching the points within ``tol``, with the
    point permutations of the rotation by 1/k turn and of the mirror; None if none is
    larger than ``exact_order``."""
    at_centre = int((((P - c) ** 2).sum(1) < tol * tol).sum())
    best = None
    for k in range(n, 0, -1):
        if best is not None and 2 * k <= best[0]:
            break                   # neither C_k nor D_k beats the C_k' found
        if 2 * k <= exact_order or (n - at_centre) % k:
            continue
        rho = _match(P, _float_rotation(P, c, k), tol) if k > 1 else list(range(n))
        if rho is None:
            continue
        # mirror candidates: through the first point off the centre, or bisecting it
        # and a point at the same distance
        off = [i for i in range(n) if ((P[i] - c) ** 2).sum() >= tol * tol]
        i0 = off[0] if off else 0
        r0 = math.dist(P[i0], c)
        for j in off:
            if abs(math.dist(P[j], c) - r0) > tol:
                continue
            mid = (P[i0] + P[j]) / 2 - c
            if j == i0 or math.hypot(*mid) < tol:
                v = P[i0] - c if j == i0 else [-(P[j] - P[i0])[1], (P[j] - P[i0])[0]]
            else:
                v = mid
            phi = math.atan2(v[1], v[0])
            sigma = _match(P, _float_reflection(P, c, phi), tol)
            if sigma is not None:
                return (k, rho, phi, sigma)
        if k > exact_order and best is None:
            best = (k, rho, None, None)
    return best


def near_symmetry_hint(config: Configuration, tolerance: float = TOLERANCE
                       ) -> NearSymmetry | None:
    """A configuration of a larger symmetry group within ``tolerance`` times the SEC
    radius of every robot of ``config``, with an exactly proved distance bound; None
    when there is none (or the input is polar, not rational, or has more than
    :data:`MAX_POINTS` points).  Never changes any verdict.

    >>> from exactsym.geometry.configuration import Configuration
    >>> hexagon = [("1", "0"), ("0.5", "0.866025"), ("-0.5", "0.866025"), ("-1", "0"),
    ...            ("-0.5", "-0.866025"), ("0.5", "-0.866025")]
    >>> from fractions import Fraction
    >>> hint = near_symmetry_hint(Configuration.from_points(
    ...     [(Fraction(x), Fraction(y)) for x, y in hexagon]))
    >>> hint.text
    'exact group D2; within 5e-7 of D6 (hint only: the exact group stands)'
    """
    import numpy as np
    n = config.n
    if config.polar is not None or n < 2 or n > MAX_POINTS:
        return None
    pts = config.points
    if not all_plain_rational(v for p in pts for v in p):
        return None
    group = symmetry_group(config)
    exact_order = _order(group) if group.name != "O2" else math.inf
    if exact_order == math.inf:
        return None
    P = np.array([(float(x), float(y)) for x, y in pts])
    # every symmetry fixes the centroid, so it proposes the centre of the candidate (the
    # SEC centre rests on two or three points and moves with their rounding)
    c = P.mean(axis=0)
    radius = float(np.sqrt(((P - c) ** 2).sum(1)).max()) or 1.0
    tol = tolerance * radius
    proposal = _propose(P, c, tol, n, exact_order)
    if proposal is None:
        return None
    k, rho, phi, sigma = proposal
    step = Fraction(10) ** math.floor(math.log10(tol / 100))
    candidate = _candidate(pts, P, c, step, k, rho, phi, sigma, tol)
    if candidate is None:
        return None
    points, system = candidate
    try:
        q_config = Configuration.from_points(points, system=system, name="candidate")
    except InputError:          # coincident candidate points: no hint
        return None
    q_group = symmetry_group(q_config)
    if q_group.name == "O2" or _order(q_group) <= exact_order:
        return None
    coerce = system.coerce
    d2 = [(coerce(x) - qx) ** 2 + (coerce(y) - qy) ** 2 for (x, y), (qx, qy) in zip(pts, points)]
    worst = max(float(v) for v in d2)
    bound = _round_up_1digit(math.sqrt(worst) * (1 + 1e-9))
    for _ in range(2):
        b = fmpq(bound.numerator, bound.denominator)
        if all(v <= coerce(b * b) for v in d2):          # exact comparisons decide
            if float(b) > tol:
                return None
            return NearSymmetry(group.name, q_group.name, b, q_config)
        bound *= 2
    return None


def _candidate(pts, P, c, step, k, rho, phi, sigma, tol):
    """The exact symmetric configuration proposed by the floats: ``(points, system)``."""
    system = number_system([], turns=[fmpq(1, k)])
    F = system.coerce
    cos, sin = system.cos_turn(fmpq(1, k)), system.sin_turn(fmpq(1, k))
    centre = (F(_q(_grid(c[0], step))), F(_q(_grid(c[1], step))))

    def rotate(u, j):
        x, y = u
        for _ in range(j % k):
            x, y = cos * x - sin * y, sin * x + cos * y
        return (x, y)
    reflect = None
    if phi is not None:
        scale = 10 ** 9           # a rational direction within about 1e-9 rad of phi
        a1, a2 = round(math.cos(phi) * scale), round(math.sin(phi) * scale)
        den = fmpq(a1 * a1 + a2 * a2)
        reflect = _mirror(F(fmpq(a1 * a1 - a2 * a2) / den), F(fmpq(2 * a1 * a2) / den))
    n = len(pts)
    # group elements as (j, mirrored): g = R^j or R^j S, with their float permutations
    elements = [(j, False) for j in range(k)] + ([(j, True) for j in range(k)] if reflect else [])

    def perm_of(j, mirrored):
        p = list(range(n)) if not mirrored else list(sigma)
        for _ in range(j):
            p = [rho[i] for i in p]
        return p
    perms = {g: perm_of(*g) for g in elements}

    def act(g, u):
        j, mirrored = g
        return rotate(reflect(u) if mirrored else u, j)
    out = [None] * n
    for i in range(n):
        if out[i] is not None:
            continue
        if ((P[i] - c) ** 2).sum() < tol * tol:
            u = (F(0), F(0))                    # at the centre
        else:
            v = (F(_q(_grid(P[i][0] - c[0], step))), F(_q(_grid(P[i][1] - c[1], step))))
            fixer = next((g for g in elements if g[1] and perms[g][i] == i), None)
            if fixer is not None:               # on a mirror: project onto it exactly
                w = act(fixer, v)
                u = ((v[0] + w[0]) / 2, (v[1] + w[1]) / 2)
            else:
                u = v
        for g in elements:
            j = perms[g][i]
            x, y = act(g, u)
            image = (centre[0] + x, centre[1] + y)
            if out[j] is None:
                out[j] = image
            elif out[j] != image:               # the float matching was inconsistent
                return None
    return out, system


def _mirror(m11, m12):
    """The reflection with matrix [[m11, m12], [m12, -m11]] (a mirror through 0)."""
    def reflect(u):
        return (m11 * u[0] + m12 * u[1], m12 * u[0] - m11 * u[1])
    return reflect


def _q(f: Fraction) -> fmpq:
    return fmpq(f.numerator, f.denominator)


def hint_text(config: Configuration) -> str | None:
    """The hint as one line, or None (for the text summary)."""
    hint = near_symmetry_hint(config)
    return None if hint is None else hint.text

