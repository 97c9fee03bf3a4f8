"""Certified canonical ordering and leader (issue 9, point 6): claim.ordering and claim.leader
proved by the checker (checker_ordering), and every tampering of them caught."""

from __future__ import annotations

import copy
import json
import tempfile
from pathlib import Path

import pytest
from hypothesis import given, settings, strategies as st

from exactsym import checker
from exactsym.certificates.certificate import make_certificate
from exactsym.geometry.configuration import Configuration, load
from exactsym.truth.symmetry import symmetry_group


def certify_text(tmp_path, text: str) -> dict:
    path = tmp_path / "c.txt"
    path.write_text(text)
    return json.loads(json.dumps(make_certificate(load(path))))


def verdict(cert: dict) -> tuple[bool, str]:
    cert["configuration_sha256"] = checker.digest(cert["configuration"])
    return checker.verify_certificate(json.loads(json.dumps(cert)))


def rejected(cert: dict, fragment: str) -> None:
    ok, message = verdict(cert)
    assert not ok and fragment in message, message


# an asymmetric rational set: many rays, distinct radii (orderable, C1)
C1 = "0 0\n3 1\n1 5\n7 2\n-4 3\n-2 -6\n5 -5\n"
C1_POLAR = "".join(f"polar {r} {t}\n" for r, t in
                   [(2, "0"), (2, "1/3"), (2, "2/3"), (1, "1/10"), (1, "1/7"), (3, "1/2")])
D1_KITE = "-1 0\n1 0\n0 3\n0 1\n"             # not orderable; leader on the mirror
D1_POLAR = "".join(f"polar {r} {t}\n" for r, t in
                   [(2, "0"), (2, "1/3"), (2, "2/3"), (1, "1/10"), (1, "-1/10")])


# two polar rays (certify crashed on them: a turn difference taken "% 1" on an fmpq)
TWO_RAYS_POLAR = "polar 1 0\npolar 2 0\npolar 3 1/3\n"


# a tower of nested radicals (checker/ext_tower: angles compared from integer boxes, exactly on
# a tie), two points on one ray
NESTED = "sqrt(2+sqrt(3)) 0\n0 sqrt(2+sqrt(3))\n-1 -1\n2 3\n2*sqrt(2+sqrt(3)) 0\n" \
    "-3 sqrt(5+sqrt(2))\n"


@pytest.mark.parametrize("text", [C1, C1_POLAR, TWO_RAYS_POLAR,
                                  "0 0\nsqrt(2) 0\n0 sqrt(3)\n1 1\n", NESTED])
def test_orderable_certificate_proves_the_ordering(tmp_path, text):
    cert = certify_text(tmp_path, text)
    order = cert["claim"]["ordering"]
    assert cert["claim"]["orderable"] and cert["claim"]["leader"] == order[0]
    assert verdict(copy.deepcopy(cert))[0]
    # a swapped pair, anywhere in the ordering (leader moved along when it is the first)
    for a in range(len(order) - 1):
        bad = copy.deepcopy(cert)
        o = bad["claim"]["ordering"]
        o[a], o[a + 1] = o[a + 1], o[a]
        bad["claim"]["leader"] = o[0]
        rejected(bad, "ordering")
    # another leader
    for other in order[1:]:
        bad = copy.deepcopy(cert)
        bad["claim"]["leader"] = other
        rejected(bad, "leader")
    # another starting ray: a rotation of the ordering is angularly sorted but not least
    bad = copy.deepcopy(cert)
    bad["claim"]["ordering"] = order[1:] + order[:1]
    bad["claim"]["leader"] = order[1]
    rejected(bad, "ordering")
    # the wrong frame
    bad = copy.deepcopy(cert)
    frame = bad["witness"]["canonical"]
    frame["orientation"] = {"ccw": "cw", "cw": "ccw"}[frame["orientation"]]
    rejected(bad, "ordering")
    # an ordering where none exists, or none where one does
    bad = copy.deepcopy(cert)
    bad["claim"]["ordering"] = None
    rejected(bad, "exactly when")


def test_reversed_ordering_is_caught(tmp_path):
    """The ordering read in the other frame is sorted there too: only the least reading
    passes."""
    cert = certify_text(tmp_path, C1)
    bad = copy.deepcopy(cert)
    o = bad["claim"]["ordering"]
    bad["claim"]["ordering"] = o[:1] + o[1:][::-1]
    frame = bad["witness"]["canonical"]
    frame["orientation"] = {"ccw": "cw", "cw": "ccw"}[frame["orientation"]]
    rejected(bad, "not the canonical one")


def test_cartesian_sec_witness(tmp_path):
    cert = certify_text(tmp_path, C1)
    sec = cert["witness"]["sec"]
    bad = copy.deepcopy(cert)
    bad["witness"]["sec"]["support"] = [i for i in range(7) if i not in sec["support"]][:3]
    rejected(bad, "sec")
    bad = copy.deepcopy(cert)
    bad["witness"]["sec"]["centre"] = ["0", "0"]
    rejected(bad, "sec")
    bad = copy.deepcopy(cert)
    bad["witness"]["sec"]["support"] = sec["support"][:1]     # a wrong position
    rejected(bad, "sec")


@pytest.mark.parametrize("text", [D1_KITE, D1_POLAR])
def test_d1_leader_on_the_mirror(tmp_path, text):
    cert = certify_text(tmp_path, text)
    truth = symmetry_group(load(tmp_path / "c.txt"))
    assert cert["claim"]["ordering"] is None and cert["claim"]["leader"] == truth.leader
    assert truth.leader is not None and verdict(copy.deepcopy(cert))[0]
    for other in range(len(cert["configuration"]["points"])):
        if other != truth.leader:
            bad = copy.deepcopy(cert)
            bad["claim"]["leader"] = other
            rejected(bad, "leader")
    bad = copy.deepcopy(cert)
    order = bad["witness"]["canonical"]["order"]
    order[0], order[-1] = order[-1], order[0]                 # a wrong witness position
    rejected(bad, "ordering")


def test_symmetric_leader_is_the_centre_or_none(tmp_path):
    cert = certify_text(tmp_path, "0 0\n2 0\n2 2\n0 2\n1 1\n")    # D4 with a centre point
    assert cert["claim"]["leader"] == 4 and verdict(copy.deepcopy(cert))[0]
    cert["claim"]["leader"] = 0
    rejected(cert, "leader must be 4")
    cert = certify_text(tmp_path, "0 0\n2 0\n2 2\n0 2\n")         # D4, nothing fixed
    cert["claim"]["leader"] = 0
    rejected(cert, "leader must be None")


@settings(max_examples=40, deadline=None)
@given(st.lists(st.tuples(st.integers(-6, 6), st.integers(-6, 6)), min_size=2, max_size=9,
                unique=True),
       st.sampled_from([((1, 0), (0, 1)), ((0, -1), (1, 0)), ((1, 0), (0, -1)),
                        ((3, -4), (4, 3))]))
def test_certified_ordering_follows_similarities(points, matrix):
    """Every certificate verifies, and an exact similarity (rotation by a Pythagorean angle,
    reflection, scale 5 for (3, 4)) maps the certified ordering and leader along."""
    config = Configuration.from_points(points)
    (a, b), (c, d) = matrix
    moved = Configuration.from_points([(a * x + b * y + 7, c * x + d * y - 2) for x, y in points])
    one, two = (json.loads(json.dumps(make_certificate(k))) for k in (config, moved))
    assert verdict(one)[0] and verdict(two)[0], (verdict(one), verdict(two))
    assert one["claim"] == two["claim"]


def _every_reading(cert: dict) -> list:
    """(orientation, ordering) for every start in both frames, read off the certified one:
    in its frame the rays R_0 .. R_(m-1) follow the ordering; the other frame reads them
    backwards."""
    from exactsym.checker.groups import read_cartesian
    from exactsym.checker.ordering import _plane, _rays
    config, claim = cert["configuration"], cert["claim"]
    field = checker.number_field(config["field"]) if config.get("field") else None
    kind, points = config["coordinates"], config["points"]
    read = read_cartesian(points, field) if kind == "cartesian" else None
    plane = _plane(kind, points, field, cert["witness"], read)
    centre = [i for i, d in enumerate(plane.dirs) if d is None]
    frame = cert["witness"]["canonical"]["orientation"]
    if frame == "cw":
        plane = plane.mirrored()
    rays = _rays(plane, claim["ordering"][len(centre):])
    m, flip = len(rays), {"ccw": "cw", "cw": "ccw"}[frame]
    out = []
    for k in range(m):
        out.append((frame, centre + [i for r in rays[k:] + rays[:k] for i in r]))
        out.append((flip, centre + [i for j in range(m) for i in rays[(k - j) % m]]))
    return out


_POLAR = st.lists(st.tuples(st.sampled_from([1, 2]), st.integers(0, 11)), min_size=3,
                  max_size=10, unique=True).map(
    lambda ps: "".join(f"polar {r} {t}/12\n" for r, t in ps))
_GRID = st.lists(st.tuples(st.integers(-2, 2), st.integers(-2, 2)), min_size=3, max_size=10,
                 unique=True).map(lambda ps: "".join(f"{x} {y}\n" for x, y in ps))


@settings(max_examples=60, deadline=None)
@given(st.one_of(_POLAR, _GRID))
def test_only_the_least_reading_passes(text):
    """Points at twelfths of a turn on two circles, or on a small grid (many equal radii and
    gaps: the leastness check must follow the symbols past the first): of the 2m readings,
    the checker accepts exactly the certified one."""
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "p.txt"
        path.write_text(text)
        cert = json.loads(json.dumps(make_certificate(load(path))))
    if not cert["claim"]["orderable"]:
        return
    assert verdict(copy.deepcopy(cert))[0]
    for frame, order in _every_reading(cert):
        bad = copy.deepcopy(cert)
        bad["witness"]["canonical"]["orientation"] = frame
        bad["claim"]["ordering"], bad["claim"]["leader"] = order, order[0]
        ok, message = verdict(bad)
        assert ok == (order == cert["claim"]["ordering"]), (frame, order, message)
