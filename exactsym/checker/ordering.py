"""The checker of the canonical ordering and the leader (docs/certificates.md, "Ordering and
leader").  c is the centre of the smallest enclosing circle (SEC) of P; the points off c lie
on rays about c.  A frame is the plane as given ("ccw") or mirrored ("cw": y -> -y).  In a
frame, list the rays counter-clockwise R_0 .. R_(m-1); the symbol of R_j is (the squared
distances to c of its points, increasing; the angle from R_j to R_(j+1), in [0, 2pi)),
compared by the tuple (lexicographically, a proper prefix first), then by the angle.  The
canonical reading is the least of the 2m cyclic strings of symbols (both frames, every first
ray); the ordering lists the point at c (if any), then the rays of a least reading, each by
increasing distance (two least readings differ by an isometry of P, which moves no point when
P is orderable).  The leader: the first of the ordering when orderable; else the point at c;
else, for D1, the nearest point on the mirror's fixed ray whose reading is least (two cannot
read alike: the half-turn would be a symmetry); else none.

The witness is the frame of a least reading (for D1 without an ordering, also the points in
angular order).  The checker verifies the claimed order is angular in that frame (one
comparison a point) and proves its reading X least by the Z-algorithm on X + sentinel + (the
other string doubled): the common prefix with X of every other start in O(m) equalities, and
one comparison where it ends.  Linear.

In a number field, c = (X, Y)/k: distances compare by key_i = sign(k) (k |p_i|^2 - 2 X . p_i),
as |k p_i - X|^2 = |k| key_i + |X|^2, with no square of X (in a sparse Q(zeta_N) a sum of
hundreds of cosines).  A field whose numbers have integer enclosures brings its class of
angles (``field.Angle``, ext_boxes), made exactly only where the enclosures hold 0.
"""

from __future__ import annotations

from math import gcd, lcm

from .numbers import is_int, need, rat, scaled, sgn

class _Plane:
    """Points about c in one frame: a key of the distance from c and the direction of each
    point off c.  ``native``: ints and Fractions, whose own comparisons are exact (symbols get
    canonical forms, _symbols).  ``Angle``: the field's angles from enclosures, or None."""

    def __init__(self, polar: bool, r2: list, dirs: list, turn: int, native: bool = False,
                 Angle=None):
        self.polar, self.r2, self.dirs, self.turn = polar, r2, dirs, turn
        self.native, self.Angle, self.boxes = native, Angle, {}
        self.sign = (lambda v: (v > 0) - (v < 0)) if native else sgn

    def mirrored(self) -> "_Plane":
        if self.polar:
            return _Plane(True, self.r2, [None if d is None else -d % self.turn
                                          for d in self.dirs], self.turn, self.native)
        return _Plane(False, self.r2, [None if d is None else (d[0], -d[1])
                                       for d in self.dirs], self.turn, self.native, self.Angle)

    def angle(self, i: int, j: int):
        """The angle from the direction of point i to that of j, in [0, 2pi): a turn (polar,
        in units of 1/turn) or the vector (u . v, u x v), or the field's ``Angle``."""
        if self.polar:
            return (self.dirs[j] - self.dirs[i]) % self.turn
        if self.Angle:
            return self.Angle(self, i, j)
        (ux, uy), (vx, vy) = self.dirs[i], self.dirs[j]
        return ux * vx + uy * vy, ux * vy - uy * vx

    def cmp_angle(self, a, b) -> int:
        if self.polar:
            return (a > b) - (a < b)
        if self.Angle:
            return a.cmp(b)
        # upper half [0, pi) before lower half [pi, 2pi); in one half, the cross product
        sign = self.sign
        half = [0 if sign(y) > 0 or (y == 0 and sign(x) > 0) else 1 for x, y in (a, b)]
        if half[0] != half[1]:
            return -1 if half[0] < half[1] else 1
        return -sign(a[0] * b[1] - a[1] * b[0])

def _rays(plane: _Plane, order: list) -> list:
    """The rays of ``order`` (points off c), checked to be sorted counter-clockwise from the
    first point's direction, each ray by increasing distance."""
    need(order, "the canonical order lists no point off the centre")
    if plane.native and not plane.polar:
        return _rays_native(plane, order)
    rays, last = [[order[0]]], plane.angle(order[0], order[0])
    for i in order[1:]:
        a = plane.angle(order[0], i)
        step = plane.cmp_angle(a, last)
        if step == 0:
            need(plane.sign(plane.r2[i] - plane.r2[rays[-1][-1]]) > 0, f"ordering: point {i} "
                 "is not farther from the centre than the point before it on its ray")
            rays[-1].append(i)
        else:
            need(step > 0, f"ordering: point {i} is not in angular order")
            rays.append([i])
        last = a
    return rays

def _rays_native(plane: _Plane, order: list) -> list:
    """_rays written out for Python numbers: v is in the upper half (h = 0) of the first
    direction u when u x v > 0, or = 0 and u . v > 0; in one half v is after the direction p
    before it iff p x v > 0, and p x v = 0 iff v is p's direction."""
    dirs, r2 = plane.dirs, plane.r2
    ux, uy = px, py = dirs[order[0]]
    rays, lh = [[order[0]]], 0
    for i in order[1:]:
        vx, vy = dirs[i]
        c = ux * vy - uy * vx
        h = 0 if c > 0 or (c == 0 and ux * vx + uy * vy > 0) else 1
        x = px * vy - py * vx if h == lh else h - lh
        if x == 0:
            need(r2[i] > r2[rays[-1][-1]], f"ordering: point {i} is not farther from the "
                 "centre than the point before it on its ray")
            rays[-1].append(i)
        else:
            need(x > 0, f"ordering: point {i} is not in angular order")
            rays.append([i])
        px, py, lh = vx, vy, h
    return rays

def _symbols(plane: _Plane, rays: list) -> tuple[list, list]:
    """The readings from R_0: counter-clockwise, and clockwise (the string of the mirror image
    read from R_0: rays R_0, R_-1, ..., each with the angle from the ray before it)."""
    m = len(rays)
    radii = [tuple(plane.r2[i] for i in ray) for ray in rays]
    gaps = [plane.angle(rays[j][0], rays[(j + 1) % m][0]) for j in range(m)]
    if plane.native and not plane.polar:        # equal angles: equal primitive vectors
        gaps = [_primitive(x, y) for x, y in gaps]
    return (list(zip(radii, gaps)),
            [(radii[-j % m], gaps[(-j - 1) % m]) for j in range(m)])

def _primitive(x, y) -> tuple[int, int]:
    """The positive multiple of the vector (x, y) != 0 with coprime integer coordinates."""
    d = lcm(x.denominator, y.denominator)
    g = gcd(int(x * d), int(y * d))
    return int(x * d) // g, int(y * d) // g

def _cmp_symbol(plane: _Plane, s, t) -> int:
    if s is t:                                  # one symbol read twice (a reading against
        return 0                                # its own rotations): no products
    if plane.native:                            # canonical radii and angles (see _symbols):
        if s[0] != t[0]:                        # tuples compare with a proper prefix first
            return -1 if s[0] < t[0] else 1
        return 0 if s[1] == t[1] else plane.cmp_angle(s[1], t[1])
    for x, y in zip(s[0], t[0]):
        c = sgn(x - y)
        if c:
            return c
    if len(s[0]) != len(t[0]):
        return -1 if len(s[0]) < len(t[0]) else 1
    return plane.cmp_angle(s[1], t[1])

def _least(plane: _Plane, x: list, cw: list) -> None:
    """The ccw reading x is no greater than any rotation of itself or of cw (Z-algorithm)."""
    m = len(x)
    for other in (x, cw):
        s = x + [None] + other + other[:-1]
        z, left, right = [0] * len(s), 0, 0
        for i in range(1, 2 * m + 1):           # s[m + 1 + j:]: the rotation by j
            zi = min(right - i, z[i - left]) if i < right else 0
            while i + zi < len(s) and zi < m and s[i + zi] is not None and \
                    _cmp_symbol(plane, s[zi], s[i + zi]) == 0:
                zi += 1
            z[i] = zi
            if i + zi > right:
                left, right = i, i + zi
            if i > m and zi < m:
                need(_cmp_symbol(plane, s[i + zi], x[zi]) > 0, "ordering: the reading from "
                     f"ray {i - m - 1} is less than the claimed one (they differ at symbol "
                     f"{zi}): the claimed order is not the canonical one")

def _least_native(plane: _Plane, rays: list) -> None:
    """_least for Python numbers, symbols made only where needed.  Both frames' readings have
    the same radii, so a start with other first radii is larger when X's are the least (one
    min).  The Z-algorithm visits only starts with X's first radii (elsewhere z = 0, which
    leaves the Z-box as it is); one whose first gap differs is larger by one comparison."""
    m, r2 = len(rays), plane.r2
    one = sum(map(len, rays)) == m              # one point a ray: its radius for its tuple
    radii = [r2[ray[0]] if one else tuple(map(r2.__getitem__, ray)) for ray in rays]
    r0 = radii[0]
    need(min(radii) == r0, "ordering: a reading is less than the claimed one at symbol 0: "
         "the claimed order is not the canonical one")
    starts = [j for j, r in enumerate(radii) if r == r0] if radii.count(r0) > 1 else [0]
    gaps = {}

    def gap(j):         # the angle from R_j to R_(j+1), canonical: equal angles compare ==
        j %= m
        if j not in gaps:
            a = plane.angle(rays[j][0], rays[(j + 1) % m][0])
            gaps[j] = a if plane.polar else _primitive(*a)
        return gaps[j]

    readings = ((lambda j: (radii[j % m], gap(j))), starts[1:]), \
        ((lambda j: (radii[-j % m], gap(-j - 1))), sorted(-j % m for j in starts))
    x0 = (x := readings[0][0])(0)
    for other, js in readings:                  # s = X + sentinel + other doubled
        def sym(i):
            return x(i) if i < m else None if i == m else other(i - m - 1)
        z, left, right = {}, 0, 0
        for i in starts[1:] + [m + 1 + j for j in js]:
            if sym(i) != x0:                    # same radii, another first gap
                need(i < m or plane.cmp_angle(sym(i)[1], x0[1]) > 0, "ordering: the "
                     f"reading from ray {i - m - 1} is less than the claimed one at symbol 0:"
                     " the claimed order is not the canonical one")
                continue
            zi = min(right - i, z.get(i - left, 0)) if i < right else 0
            while zi < m and sym(i + zi) == x(zi):
                zi += 1
            z[i] = zi
            if i + zi > right:
                left, right = i, i + zi
            if i > m and zi < m:
                need(_cmp_symbol(plane, sym(i + zi), x(zi)) > 0, "ordering: the reading from "
                     f"ray {i - m - 1} is less than the claimed one (they differ at symbol "
                     f"{zi}): the claimed order is not the canonical one")

def _indices(order, n: int, what: str) -> list:
    need(isinstance(order, list) and all(is_int(i) and 0 <= i < n for i in order)
         and len(set(order)) == len(order), f"{what}: not a list of distinct point indices")
    return order

def _plane(kind: str, points: list, field, witness: dict, read) -> _Plane:
    """The points about the SEC centre c (polar: the origin, verified by the group check;
    Cartesian: witness.sec, verified here; ``read``: the group check's (points times
    scale > 0, scale, reader of one number))."""
    if kind == "polar":
        turns, T = scaled([rat(t) for _, t in points])
        r2 = scaled([rat(r) for r, _ in points])[0] if field is None else [
            field.num(r) for r, _ in points]
        return _Plane(True, r2, [None if r == 0 else t % T for r, t in zip(r2, turns)], T,
                      field is None)
    sec = witness["sec"]
    xy, scale, num = read                       # the group check's points, times scale
    cx, cy = (num(v) * scale for v in sec["centre"])
    support = _indices(sec["support"], len(points), "witness.sec.support")
    need(1 <= len(support) <= 3, "witness.sec.support: one to three points")
    if field is None:                           # all times k: c has integer coordinates
        k = lcm(cx.denominator, cy.denominator)
        xy = [(k * x, k * y) for x, y in xy] if k > 1 else xy
        cx, cy = int(cx * k), int(cy * k)
        w = [(x - cx, y - cy) for x, y in xy]
        r2 = [x * x + y * y for x, y in w]
    else:
        # c = (X, Y) / k: the plane scaled by k != 0 (k < 0 adds a half turn, a rotation),
        # w = k p - c, distances by their keys (module docstring)
        k = num(sec["scale"]) if "scale" in sec else 1
        need(k != 0, "sec: the scale is zero")
        sk = sgn(k)
        w = [(k * x - cx, k * y - cy) for x, y in xy]
        r2 = [sk * (k * (x * x + y * y) - 2 * (cx * x + cy * y)) for x, y in xy]
    at_c = [x == 0 and y == 0 for x, y in w]
    dirs = [None if z else d for z, d in zip(at_c, w)]
    plane = _Plane(False, r2, dirs, 1, field is None, getattr(field, "Angle", None))
    # c is the SEC centre: no point beyond R, and c in the hull of support points at R (a
    # circle about c' != c misses the one s with (s - c) . (c' - c) <= 0)
    big = r2[support[0]]
    need(all(r2[i] == big for i in support), "sec: the support points are not on one circle")
    need(max(r2) <= big if field is None else all(sgn(v - big) <= 0 for v in r2),
         "sec: a point lies outside the circle")
    if len(support) == 2:
        (ax, ay), (bx, by) = (w[i] for i in support)
        need(ax + bx == 0 and ay + by == 0, "sec: the centre is not the midpoint of the support")
    elif len(support) == 3:
        need(not any(at_c[i] for i in support), "sec: a support point is the centre")
        turns = {_cross_sign(plane, a, b) for a, b in zip(support, support[1:] + support[:1])}
        need(not {-1, 1} <= turns, "sec: the centre is outside the support triangle")
    else:
        need(at_c[support[0]], "sec: one support point must be the centre")
    return plane

def _cross_sign(plane: _Plane, a: int, b: int) -> int:
    """The sign of w_a x w_b (the directions of points a and b, off c)."""
    if plane.Angle:
        return plane.Angle(plane, a, b).sign(1)
    (ax, ay), (bx, by) = plane.dirs[a], plane.dirs[b]
    return plane.sign(ax * by - ay * bx)

def check(kind: str, points: list, field, witness: dict, claim: dict, name: str,
          orderable: bool, mirror: list | None, read=None) -> str:
    """Check ``claim.ordering`` and ``claim.leader`` (the group and orderability are proved);
    returns a phrase for the summary."""
    n = len(points)
    ordering, leader = claim["ordering"], claim["leader"]
    need(leader is None or is_int(leader), "claim.leader must be a point index or null")
    if n == 1:
        need(ordering == [0] and leader == 0, "one point: the ordering is [0], the leader 0")
        return "ordering and leader"
    need((ordering is not None) == orderable, "claim.ordering must be given exactly when the "
         "configuration is orderable")
    plane = _plane(kind, points, field, witness, read)
    centre = [i for i, d in enumerate(plane.dirs) if d is None]
    if not orderable and (centre or name != "D1"):
        expected = centre[0] if centre else None
        need(leader == expected, f"claim.leader must be {expected}: " + (
            "the point at the centre" if centre else f"no point is fixed by {name}"))
        return "leader"
    spec = witness["canonical"]
    if orderable:
        order = _indices(ordering, n, "claim.ordering")
        need(len(order) == n, "claim.ordering: not a list of every point")
        need(order[:len(centre)] == centre, "claim.ordering: the point at the centre is not "
             "first")
        order = order[len(centre):]
    else:
        order = _indices(spec["order"], n, "witness.canonical.order")
        need(sorted(order + centre) == list(range(n)), "witness.canonical.order: not every "
             "point off the centre")
    need(isinstance(spec, dict) and spec.get("orientation") in ("ccw", "cw"),
         "witness.canonical.orientation must be \"ccw\" or \"cw\"")
    plane = plane.mirrored() if spec["orientation"] == "cw" else plane
    rays = _rays(plane, order)
    if orderable:
        if plane.native:
            _least_native(plane, rays)
        else:
            _least(plane, *_symbols(plane, rays))
        need(leader == ordering[0], "claim.leader is not the first of the ordering")
        return "ordering and leader"
    ccw = _symbols(plane, rays)[0]
    # D1, no point at c: the rays the mirror fixes (their points are fixed), the least reading
    fixed = [j for j, ray in enumerate(rays) if mirror[ray[0]] == ray[0]]
    if not fixed:
        need(leader is None, "claim.leader must be null: no point lies on the mirror")
        return "leader"
    best = fixed[0]
    for j in fixed[1:]:
        a, b = ccw[j:] + ccw[:j], ccw[best:] + ccw[:best]
        c = next((c for c in (_cmp_symbol(plane, s, t) for s, t in zip(a, b)) if c), 0)
        need(c != 0, "two rays on the mirror read alike")
        best = j if c < 0 else best
    need(leader == rays[best][0], f"claim.leader must be point {rays[best][0]}, the nearest "
         "point of the least-reading ray on the mirror")
    return "leader"

