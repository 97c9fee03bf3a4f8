"""The paper on each level in the report (exactsym.paper.polygon_report)."""

from __future__ import annotations

import json
from fractions import Fraction

from exactsym.cli.main import main
from exactsym.geometry.configuration import Configuration, load
from exactsym.report.check import check_report, failed_expectations
from exactsym.paper import polygon_report
from strategies import polar_configuration


def test_report_with_strings_cartesian_sqrt3(tmp_path, capsys):
    path = "cases/polygon/regular-hexagon-sqrt3.toml"
    assert main(["check", path, "--json", "--strings"]) == 0
    report = json.loads(capsys.readouterr().out)
    level = report["levels"][0]
    assert level["paper"]["type"] == "type-0" and level["paper"]["degree"] == 3
    strings = level["strings"]
    assert strings["metric"] == "signed-squared-cosine"
    # from a vertex of the regular hexagon: 60, 120, 180, 120, 60 degrees
    assert strings["cw"][0] == ["-1/4", "1/4", "1", "1/4", "-1/4"]
    assert strings["acw"][0] == strings["cw"][0][::-1]


def test_report_polar_strings_and_centre_level():
    config = polar_configuration([(0, 0), (1, Fraction(0)), (1, Fraction(1, 3)),
                                  (1, Fraction(2, 3))])
    report = check_report(config, strings=True)
    assert report["levels"][0]["paper"] is None                       # the robot at C
    strings = report["levels"][1]["strings"]
    assert strings["metric"] == "angular-distance"
    assert strings["cw"] == [["1/3", "1/3"]] * 3


def test_large_polygon_is_cheap_and_strings_omitted():
    n = 1500
    config = polar_configuration([(1, Fraction(k, n)) for k in range(n)])
    report = check_report(config, strings=True)
    level = report["levels"][0]
    assert level["paper"]["lines_by_strings"] == n and level["paper"]["degree"] == n // 2
    assert "omitted" in level["strings"]
    assert level["paper"]["leader_sym"] is None and level["paper"]["definition"] is None
    json.dumps(report)


def test_fractional_degree_and_per_level_expectations():
    config = load("cases/polygon/kite-polar.toml")
    report = check_report(config)
    assert report["levels"][0]["paper"]["degree"] == "3/2"
    assert polygon_report.degree_json(Fraction(3, 2)) == "3/2"
    config.expect.clear()
    config.expect.update({"paper_degree": ["3/2"], "paper_type": "type-2",
                          "paper_leader_sym": "none", "paper_straight": [True]})
    assert failed_expectations(config, report) == []
    config.expect.update({"paper_degree": 1, "paper_lines_by_strings": [1, 1]})
    assert len(failed_expectations(config, report)) == 2


def test_cartesian_configuration_with_other_centre():
    config = Configuration.from_points([(1, 1), (6, 1), (1, 6), (-4, 1), (1, -4)])
    report = check_report(config)
    paper = report["levels"][-1]["paper"]
    assert paper["type"] == "type-0" and paper["lines_by_strings"] == 4


def test_single_robot_verdicts_are_made_when_read():
    """Levels of one robot (random input): the verdicts are a SingleVerdicts sequence,
    equal to the tuple of the verdicts each level's polygon gets on its own, item by item,
    by slices and as a whole; pickled as that tuple."""
    import pickle
    import random
    from exactsym.analysis import built_levels
    from exactsym.geometry.configuration import from_file
    from exactsym.geometry.levels import levels_of
    from exactsym.io.fileformat import parse_config_text
    from exactsym.paper.circle_polygon import level_polygon
    from exactsym.paper.polygon_report import SingleVerdicts, level_section, level_verdicts
    rnd = random.Random(11)
    pts = {(rnd.randint(-500, 500), rnd.randint(-500, 500)) for _ in range(40)}
    pts |= {(3, 4), (-3, -4), (4, -3), (-4, 3)}        # one level of four robots
    text = "".join(f"{x}/3 {y}/7\n" for x, y in sorted(pts))
    config = from_file(parse_config_text(text, "<test>", "txt"))
    levels = built_levels(levels_of(config))
    section = level_section(config, levels)
    assert isinstance(section.verdicts, SingleVerdicts)
    want = tuple(level_verdicts(level_polygon(config, levels, k))
                 for k in range(len(levels.levels)))
    assert tuple(section.verdicts) == want and section.verdicts == want
    assert section.verdicts[3:9] == want[3:9] and section.verdicts[-1] == want[-1]
    assert any(len(level.points) > 1 for level in levels.levels)
    assert pickle.loads(pickle.dumps(section.verdicts)) == want
