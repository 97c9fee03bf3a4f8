"""Relations between robots moving at once, as polynomials in the common time ``tau``.

In a step every mover is at ``p = (X, Y) / D`` (:func:`.motion.motion_of`: ``D = 1``
on a segment, ``1 + T^2 tau^2 > 0`` on an arc) and a robot standing still is a constant
motion (:func:`still`).  Each relation below is a polynomial in ``tau`` with
multiquadratic coefficients, denominators cleared by positive factors (so its sign is
the relation's): :mod:`.joint_instants` and :mod:`.joint_symmetry` take their roots.
"""

from __future__ import annotations

from ..exact.algebraic.polynomials import padd, pmul, pscale, psub
from ..exact.multiquadratic import MQ
from .motion import Motion

ONE = MQ.rational(1)


def const(m: Motion):
    """The point of a motion standing still."""
    return (m.nx[0] if m.nx else MQ(), m.ny[0] if m.ny else MQ())


def still(p) -> Motion:
    return Motion((p[0],), (p[1],), (ONE,))


def rel(m: Motion, c):
    """``D (p - c)``."""
    return psub(m.nx, pscale(m.d, c[0])), psub(m.ny, pscale(m.d, c[1]))


def sq(u, v):
    return padd(pmul(u, u), pmul(v, v))


def diff(a: Motion, b: Motion):
    """``D_a D_b (p_a - p_b)``."""
    return (psub(pmul(a.nx, b.d), pmul(b.nx, a.d)), psub(pmul(a.ny, b.d), pmul(b.ny, a.d)))


def tie_poly(a: Motion, b: Motion, c) -> tuple:
    """``D_a^2 D_b^2 (|p_a - c|^2 - |p_b - c|^2)``."""
    return psub(pmul(pmul(b.d, b.d), sq(*rel(a, c))), pmul(pmul(a.d, a.d), sq(*rel(b, c))))


def ray_poly(a: Motion, b: Motion, c) -> tuple:
    """``D_a D_b cross(p_a - c, p_b - c)``: zero where both are on one line through c."""
    (ua, va), (ub, vb) = rel(a, c), rel(b, c)
    return psub(pmul(ua, vb), pmul(va, ub))


def contact_poly(a: Motion, b: Motion, r2) -> tuple:
    """``D_a^2 D_b^2 (|p_a - p_b|^2 - r2)``."""
    dd = pmul(a.d, b.d)
    return psub(sq(*diff(a, b)), pscale(pmul(dd, dd), r2))


def right_poly(q: Motion, a: Motion, b: Motion) -> tuple:
    """``dot(p_q - p_a, p_q - p_b)`` times ``D_q^2 D_a D_b``: zero where ``q`` is on the
    circle on the diameter ``a b`` (the angle at ``q`` is right)."""
    (ux, uy), (wx, wy) = diff(q, a), diff(q, b)
    return padd(pmul(ux, wx), pmul(uy, wy))


def incircle_poly(ms) -> tuple:
    """The in-circle determinant of four moving points, homogenised (rows
    ``(X D, Y D, X^2 + Y^2, D^2)`` with ``p = (X, Y) / D``): zero where they are on one
    circle (or one line)."""
    rows = [(pmul(m.nx, m.d), pmul(m.ny, m.d), sq(m.nx, m.ny), pmul(m.d, m.d)) for m in ms]
    return _det(rows)


def _det(rows) -> tuple:
    if len(rows) == 1:
        return rows[0][0]
    out: tuple = ()
    for j in range(len(rows)):
        minor = [r[:j] + r[j + 1:] for r in rows[1:]]
        term = pmul(rows[0][j], _det(minor))
        out = padd(out, term) if j % 2 == 0 else psub(out, term)
    return out


def dotv(u, w) -> tuple:
    """The dot product of a vector of polynomials with a constant vector."""
    return padd(pscale(u[0], w[0]), pscale(u[1], w[1]))


def crossv(u, w) -> tuple:
    """``cross(u, w)`` of a vector of polynomials with a constant vector."""
    return psub(pscale(u[0], w[1]), pscale(u[1], w[0]))


# -- relations about a moving point (a centroid, a moving SEC centre) -------------------
def centroid_motion(motions: dict, members) -> Motion:
    """The centroid of ``members`` as a motion: ``(sum_m N_m W / D_m) / (|X| W)``, ``W``
    the product of the members' denominators (1 for a robot standing still)."""
    members = sorted(members)
    nx, ny, W = (), (), (ONE,)
    for k in members:
        m = motions[k]
        nx, ny = padd(pmul(nx, m.d), pmul(m.nx, W)), padd(pmul(ny, m.d), pmul(m.ny, W))
        W = pmul(W, m.d)
    return Motion(nx, ny, pscale(W, MQ.rational(len(members))))


def midpoint_motion(a: Motion, b: Motion) -> Motion:
    """The midpoint of two moving points (an SEC centre on the diameter a-b)."""
    return Motion(padd(pmul(a.nx, b.d), pmul(b.nx, a.d)), padd(pmul(a.ny, b.d), pmul(b.ny, a.d)),
                  pscale(pmul(a.d, b.d), MQ.rational(2)))


def circumcentre_motion(a: Motion, b: Motion, c: Motion) -> Motion:
    """The centre of the circle through three moving points: with ``B = D_a D_b (b - a)``,
    ``C = D_a D_c (c - a)`` and ``K = cross(B, C)``, it is ``a + u`` where
    ``u = (C_y |B|^2 D_c - B_y |C|^2 D_b, B_x |C|^2 D_b - C_x |B|^2 D_c) /
    (2 D_a D_b D_c K)``.  The denominator vanishes where the three are collinear (no
    circle: a caller uses it only on a stretch where the three support an SEC); its sign
    is not positive in general, so relations built on it are cleared by its square."""
    B, C = diff(b, a), diff(c, a)
    bb, cc = sq(*B), sq(*C)
    K = psub(pmul(B[0], C[1]), pmul(B[1], C[0]))
    ux = psub(pmul(pmul(C[1], bb), c.d), pmul(pmul(B[1], cc), b.d))
    uy = psub(pmul(pmul(B[0], cc), b.d), pmul(pmul(C[0], bb), c.d))
    e = pscale(pmul(pmul(b.d, c.d), K), MQ.rational(2))     # E = 2 D_b D_c K; den D_a E
    return Motion(padd(pmul(a.nx, e), ux), padd(pmul(a.ny, e), uy), pmul(a.d, e))


def seen_from(a: Motion, c: Motion) -> tuple:
    """What :func:`tie_about` and :func:`ray_about` need of one robot ``a`` and the
    moving point ``c = C / D_c``: ``(N_a, D_a, |N_a|^2, D_a^2, N_a . C, cross(N_a, C))``
    (computed once per robot when a caller relates every pair about one point)."""
    C = (c.nx, c.ny)
    return ((a.nx, a.ny), a.d, sq(a.nx, a.ny), pmul(a.d, a.d),
            padd(pmul(a.nx, C[0]), pmul(a.ny, C[1])), psub(pmul(a.nx, C[1]), pmul(a.ny, C[0])))


def tie_about(a: Motion, b: Motion, c: Motion, seen=None) -> tuple:
    """``D_a^2 D_b^2 D_c (|p_a - c|^2 - |p_b - c|^2)``, ``c = C / D_c`` a moving point:
    ``D_c (D_b^2 |N_a|^2 - D_a^2 |N_b|^2) - 2 (D_a D_b^2 N_a.C - D_a^2 D_b N_b.C)`` (the
    ``|C|^2`` terms cancel, so one factor ``D_c`` is divided out: the sign is the
    relation's times ``sign(D_c)``, constant wherever ``c`` is defined).  ``seen``:
    :func:`seen_from` of a and of b, when the caller has them."""
    (_, da, na2, da2, nca, _), (_, db, nb2, db2, ncb, _) = \
        seen or (seen_from(a, c), seen_from(b, c))
    return psub(pmul(c.d, psub(pmul(db2, na2), pmul(da2, nb2))),
                pscale(psub(pmul(pmul(da, db2), nca), pmul(pmul(da2, db), ncb)),
                       MQ.rational(2)))


def ray_about(a: Motion, b: Motion, c: Motion, seen=None) -> tuple:
    """``D_a D_b D_c cross(p_a - c, p_b - c)``, ``c = C / D_c`` a moving point:
    ``D_c cross(N_a, N_b) - D_b cross(N_a, C) + D_a cross(N_b, C)``, zero where a and b
    are on one line through c (sign: the relation's times ``sign(D_c)``)."""
    ((xa, ya), da, _, _, _, ka), ((xb, yb), db, _, _, _, kb) = \
        seen or (seen_from(a, c), seen_from(b, c))
    return padd(psub(pmul(c.d, psub(pmul(xa, yb), pmul(ya, xb))), pmul(db, ka)),
                pmul(da, kb))


def pair_tie(a: Motion, b: Motion, c: Motion, d: Motion) -> tuple:
    """``|p_a - p_b|^2 - |p_c - p_d|^2`` times ``(D_a D_b D_c D_d)^2``."""
    cd, ab = pmul(c.d, d.d), pmul(a.d, b.d)
    return psub(pmul(pmul(cd, cd), sq(*diff(a, b))), pmul(pmul(ab, ab), sq(*diff(c, d))))


def collinear_poly(a: Motion, b: Motion, c: Motion) -> tuple:
    """``cross(p_b - p_a, p_c - p_a)`` times ``D_a^2 D_b D_c``: zero where the three are
    on one line."""
    (ux, uy), (wx, wy) = diff(b, a), diff(c, a)
    return psub(pmul(ux, wy), pmul(uy, wx))


__all__ = ["still", "const", "rel", "sq", "diff", "tie_poly", "ray_poly", "contact_poly",
           "right_poly", "incircle_poly", "dotv", "crossv", "centroid_motion",
           "midpoint_motion", "circumcentre_motion", "seen_from", "tie_about", "ray_about",
           "pair_tie",
           "collinear_poly"]
