"""The checker of group certificates.  What a valid certificate proves.  P is the embedded point
set, G the group of isometries g with g(P) = P; the "level" of a point: the points as far from c.
 1. c is fixed by every g in G.  Cartesian: c is the centroid (g is affine and permutes P, so it
    fixes the mean of P).  Polar: c is the origin, checked to be the centre of the smallest
    enclosing circle of P, which is unique and so mapped onto itself by every g.
 2. H <= G: each generator (a rotation rho about c; for Dk also a reflection mu through c) maps
    every point i to point perm[i], so it maps P into P and is in G.  A rotation about c fixing
    a point a != c is the identity, so the order k of rho is the length of the cycle of the
    reference point a under its permutation, and H = <rho, mu> is exactly Ck or Dk.
 3. G <= H: every g in G fixes c, so g is determined by its kind (rotation or reflection) and
    by b = g(a), a point of P on the level of a.  For each such b and kind, the candidate is in
    H (b is in the H-orbit of a, computed from the verified permutations) or the witness names
    a point w whose image under the candidate is not in P: then the candidate is not in G.
So G = H: the checker names it, derives "orderable" (no element of G moves a point) and
compares both with the claim.  The cost is O(n) per generator and, per candidate, O(1)
(polar) or the number of points on the circle of w (Cartesian: one when distances differ).
"""

from __future__ import annotations

import gc
import hashlib
import json
from math import lcm

from .dispatch import number_field
from .numbers import Field, Invalid, frac, is_int, need, rat, rats, scaled, sgn
from .ordering import check as check_ordering

def permutation(spec: dict, n: int, name: str) -> list:
    perm = spec["permutation"]
    need(isinstance(perm, list) and len(perm) == n and all(type(j) is int and 0 <= j < n
                                                           for j in perm),   # not bool
         f"{name}: not a list of {n} indices")
    return perm

def reference(witness: dict, n: int) -> int:
    ref = witness["reference"]
    need(is_int(ref) and 0 <= ref < n, f"bad reference point {ref!r}")
    return ref

def group(n, ref, level, rot, mir, witness, image_in) -> tuple[str, bool, list | None]:
    """Order of rho and step 3, given the verified permutations; returns (name, orderable).
    ``image_in(kind, b, w)``: does the isometry of this kind fixing c and taking the reference
    point to point b map point w onto a point of P?"""
    orbit, j = [ref], (rot[ref] if rot else ref)
    while j != ref:                             # rot is a bijection: an injective map of P
        orbit.append(j)
        j = rot[j]
    inside = {"rotation": set(orbit), "reflection": {mir[i] for i in orbit} if mir else set()}
    on_level, refutations = set(level), witness.get("refutations", {})
    for kind in ("rotation", "reflection"):
        refuted = set()
        for b, w in refutations.get(kind, []):
            need(is_int(b) and b in on_level, f"{kind} refutation: point {b!r} is not on the "
                 f"level of the reference point {ref}")
            need(is_int(w) and 0 <= w < n, f"{kind} refutation: bad point {w!r}")
            need(not image_in(kind, b, w), f"the {kind} taking point {ref} to point {b} maps "
                 f"point {w} onto a point of the configuration: it refutes nothing")
            refuted.add(b)
        for b in level:
            need(b in inside[kind] or b in refuted, f"the {kind} taking point {ref} to point "
                 f"{b} is neither in the claimed group nor refuted")
    orderable = len(orbit) == 1 and (mir is None or all(mir[i] == i for i in range(n)))
    return f"{'D' if mir else 'C'}{len(orbit)}", orderable, mir

def distinct(keys: list) -> dict:
    index: dict = {}
    for i, k in enumerate(keys):
        need(index.setdefault(k, i) == i, f"points {index[k]} and {i} coincide")
    return index

def read_cartesian(points: list, field: Field | None) -> tuple[list, int, object]:
    """(pts, scale, num), shared with the ordering check: the points times scale > 0 (ints after
    scaling by a common denominator, or Fractions, or field elements), the number reader."""
    if field is None:
        flat, scale = scaled(rats([v for p in points for v in p]))
        return list(zip(flat[0::2], flat[1::2])), scale, frac
    return [(field.num(x), field.num(y)) for x, y in points], 1, field.num

def cartesian(read: tuple, field: Field | None, witness: dict) -> tuple[str, bool, list | None]:
    pts, scale, num = read
    n = len(pts)
    sx, sy = sum(x for x, _ in pts), sum(y for _, y in pts)
    w = [(n * x - sx, n * y - sy) for x, y in pts]     # n * scale * (p - centroid): exact
    if len(set(w)) < n:
        distinct(w)                             # names two points that coincide
    if n == 1:
        return "O2", True, None

    def isometry(name, det):                    # step 2 for one generator
        spec = witness.get(name)
        if spec is None:
            return None
        cx, cy = (num(v) for v in spec["centre"])
        need(cx * (n * scale) == sx and cy * (n * scale) == sy,
             f"{name}: the centre is not the centroid of the points")
        (a, b), (c, d) = [[num(v) for v in row] for row in spec["matrix"]]
        # "scale": the matrix is [[a, b], [c, d]] / k (a sparse field has no short quotients)
        k = num(spec["scale"]) if field and "scale" in spec else 1
        need(k != 0, f"{name}: the scale is zero")
        k2 = k * k
        need(a * a + c * c == k2 and b * b + d * d == k2 and a * b + c * d == 0,
             f"{name}: the matrix is not orthogonal")
        need(a * d - b * c == det * k2, f"{name}: the matrix does not have determinant {det}")
        m = k if field else lcm(a.denominator, b.denominator, c.denominator, d.denominator)
        a, b, c, d = (e if field else int(e * m) for e in (a, b, c, d))
        perm = permutation(spec, n, name)
        for i, (x, y) in enumerate(w):          # m g(p_i) = m p_perm[i], in the w frame
            need((m * w[perm[i]][0], m * w[perm[i]][1]) == (a * x + b * y, c * x + d * y),
                 f"{name}: the image of point {i} is not point {perm[i]}")
        return perm

    rot, mir, ref = isometry("rotation", 1), isometry("mirror", -1), reference(witness, n)
    need(w[ref][0] != 0 or w[ref][1] != 0, "the reference point is the centre")
    # |w_i|^2 = n (n |p_i|^2 - 2 S.p_i) + |S|^2, S = (sx, sy): one circle about c, one key_i =
    # n |p_i|^2 - 2 S.p_i, with no square of S (in a sparse Q(zeta_N): minutes)
    key = [n * (x * x + y * y) - 2 * (sx * x + sy * y) for x, y in pts] if field is not None \
        else [x * x + y * y for x, y in w]
    level = [i for i, k in enumerate(key) if k == key[ref]]
    on_circle: dict = {}                        # key -> the points with it, when first asked

    def circle(k):
        if not on_circle:
            for i, v in enumerate(key):
                on_circle.setdefault(v, []).append(i)
        return on_circle[k]

    def distance2(i, j):                        # |p_i - p_j|^2: no S
        (x, y), (u, v) = pts[i], pts[j]
        return (x - u) * (x - u) + (y - v) * (y - v)

    def side(i, j):                     # sign of w_i x w_j = n (n p_i x p_j - (p_i - p_j) x S)
        (x, y), (u, v) = pts[i], pts[j]
        return sgn(n * (x * v - y * u) - ((x - u) * sy - (y - v) * sx))

    def image_in(kind, b, i):
        # g about c with g(p_ref) = p_b maps p_i to the point at distance |p_i - c| from c and
        # |p_i - p_ref| from p_b on the side det(g) side(ref, i) of the line c p_b: the two
        # circles (centres c != p_b) meet in at most two points, mirror images in that line
        d = distance2(i, ref)
        turn = side(ref, i) * (1 if kind == "rotation" else -1)
        return any(distance2(j, b) == d and side(b, j) == turn for j in circle(key[i]))

    return group(n, ref, level, rot, mir, witness, image_in)

def polar(points: list, field: Field | None, witness: dict) -> tuple[str, bool, list | None]:
    n = len(points)
    rot, mir = witness.get("rotation"), witness.get("mirror")
    extra = [rat(rot["turn"])] if rot else []
    if mir:
        p, q = rat(mir["turn"])
        extra.append((2 * p, q))                # 2 alpha: the reflection is t -> 2 alpha - t
    turns, T = scaled([rat(t) for _, t in points] + extra)    # whole turns are T
    r2 = scaled([rat(r) for r, _ in points])[0] if field is None else [
        field.num(r) for r, _ in points]
    values = set(r2)
    need(all(sgn(v) >= 0 for v in values), "a squared radius is negative")

    def key(r, t):                              # the point (r2, turn mod 1)
        return (r, 0) if r == 0 else (r, t % T)

    keys = [key(r, t) for r, t in zip(r2, turns)]
    index = distinct(keys)
    if n == 1:
        return "O2", True, None
    # Step 1: the origin is the SEC centre iff the points at the largest distance R leave no
    # angular gap above half a turn (else a smaller circle holds them all)
    big = next(iter(values))
    for v in values:
        big = v if sgn(v - big) > 0 else big
    rim = sorted(t for r, t in keys if r == big)
    gaps = [b - a for a, b in zip(rim, rim[1:])] + [rim[0] + T - rim[-1]]
    need(2 * max(gaps) <= T, "the origin is not the centre of the smallest enclosing circle")

    def isometry(name, spec, image):            # step 2 for one generator
        if spec is None:
            return None
        perm = permutation(spec, n, name)
        for i, (r, t) in enumerate(keys):
            need(key(r, image(t)) == keys[perm[i]],
                 f"{name}: the image of point {i} is not point {perm[i]}")
        return perm

    tau, sigma = turns[n] if rot else None, turns[-1] if mir else None
    rot = isometry("rotation", rot, lambda t: t + tau)
    mir = isometry("mirror", mir, lambda t: sigma - t)
    ref = reference(witness, n)
    ra, ta = keys[ref]
    need(ra != 0, "the reference point is the centre")
    level = [i for i, (r, _) in enumerate(keys) if r == ra]

    def image_in(kind, b, i):                   # rotation by tb - ta; reflection t -> ta + tb - t
        (r, t), tb = keys[i], keys[b][1]
        return key(r, t + tb - ta if kind == "rotation" else ta + tb - t) in index

    return group(n, ref, level, rot, mir, witness, image_in)

# ------------------------------------------------------------------ the certificate

def digest(configuration) -> str:
    text = json.dumps(configuration, sort_keys=True, separators=(",", ":"))
    return hashlib.sha256(text.encode()).hexdigest()

def verify_certificate(cert) -> tuple[bool, str]:
    """``(True, summary)`` when the certificate proves its claim, else ``(False, reason)``."""
    collecting = gc.isenabled()
    gc.disable()        # ~10^5 new tuples and lists, no cycles: the collector would only rescan
    try:
        need(isinstance(cert, dict) and cert.get("format") == "exactsym-certificate"
             and is_int(cert.get("version")) and cert["version"] == 1,
             "not an exactsym certificate of version 1")
        config, claim, witness = cert["configuration"], cert["claim"], cert["witness"]
        # A fingerprint of the configuration: it catches edits; the proof does not rely on it.
        need(cert.get("configuration_sha256") == digest(config),
             "configuration_sha256 does not match the embedded configuration")
        field = number_field(config["field"]) if config.get("field") is not None else None
        points, kind = config["points"], config["coordinates"]
        need(isinstance(points, list) and points and all(
            isinstance(p, list) and len(p) == 2 for p in points), "points must be pairs")
        need(kind in ("cartesian", "polar"), f"unknown coordinates {kind!r}")
        read = read_cartesian(points, field) if kind == "cartesian" else None
        name, orderable, mirror = cartesian(read, field, witness) if read else polar(
            points, field, witness)
        need(claim["group"] == name, f"the claim says group {claim['group']!r} but the "
             f"witness proves {name}")
        need(claim["orderable"] is orderable, f"the claim says orderable "
             f"{claim['orderable']!r} but group {name} makes it {orderable}")
        proved = ""
        if "ordering" in claim or "leader" in claim:    # optional: older certificates lack them
            proved = ", " + check_ordering(kind, points, field, witness, claim, name,
                                           orderable, mirror, read)
        return True, f"group {name}, orderable {str(orderable).lower()}{proved}"
    except Invalid as err:
        return False, str(err)
    except (KeyError, TypeError, ValueError, IndexError, AttributeError, ZeroDivisionError) as err:
        return False, f"malformed certificate ({type(err).__name__}: {err})"
    finally:
        if collecting:
            gc.enable()
