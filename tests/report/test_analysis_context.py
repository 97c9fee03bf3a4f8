"""The caches of an analysis live in its context, not in modules (issue 29, point 3): no
module dict grows from one ``analyse()`` to the next, analyses in one process give what
fresh processes give, and the pictures read an analysis only."""

import ast
import collections
import importlib
import json
import pkgutil
import subprocess
import sys
from pathlib import Path

import exactsym
from exactsym.analysis import analyse
from exactsym.exact.context import AnalysisContext, Cache
from exactsym.geometry.configuration import load
from exactsym.report.check import json_text, report_json

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "cases" / "examples"
#: algebraic inputs of three kinds (cyclotomic turns, nested radicals, square roots over
#: turns): each fills the caches of the truth, the paper layer and the filters
FILES = [EXAMPLES / "big-turns-asymmetric.toml", EXAMPLES / "nested-radical-pentagon.toml",
         EXAMPLES / "square-roots-over-turns-7.toml",
         EXAMPLES / "big-turns-two-heptagons-off-centre.toml"]

#: The module dicts that may grow from one analysis to the next: tables keyed by *value*
#: (an integer, a pair of integers), never by id(), each bounded (cleared when full) and
#: holding nothing of a configuration but the fields it names.  Everything else a
#: computation remembers lives in its AnalysisContext (exactsym/exact/context.py).
VALUE_KEYED = {
    # M -> (r, Phi_r), the radical's cyclotomic polynomial: at most 256 entries
    ("exactsym.exact.cyclotomic", "_RADICAL"),
    # M -> (p, two primitive M-th roots of unity mod p): at most 17 entries
    ("exactsym.exact.cyclotomic_modular", "_EMBEDDINGS"),
    # p -> the least quadratic non-residue mod p: at most 4,096 entries
    ("exactsym.exact.modular", "_NON_RESIDUES"),
    # (m1, m2) squarefree radicands -> their gcd: at most 2^20 pairs of integers
    ("exactsym.exact.mq_products", "_PAIRS"),
    # N -> the sparse Q(zeta_N)'s tables (one per conductor): at most 65 entries
    ("exactsym.exact.sparse_context", "_CONTEXTS"),
}


def _modules() -> list:
    found = []
    for info in pkgutil.walk_packages(exactsym.__path__, "exactsym."):
        if ".pictures" in info.name or info.name.endswith("__main__"):
            continue        # matplotlib is an extra; __main__ runs the command
        found.append(importlib.import_module(info.name))
    return found


def _dict_sizes(modules) -> dict:
    return {(m.__name__, name): len(value) for m in modules for name, value in vars(m).items()
            if type(value) in (dict, collections.OrderedDict)}


def test_no_module_dict_grows_across_analyses():
    """After a first analysis (tables of constants are filled once), analysing and
    reporting more configurations leaves every module dict of the package as it was,
    but the few value-keyed bounded tables of :data:`VALUE_KEYED`: the balls, gaps,
    vectors, forms and F_p images of one configuration are its analysis's, dropped with
    it."""
    modules = _modules()
    report_json(analyse(load(FILES[0])))
    before = _dict_sizes(modules)
    for path in FILES[1:]:
        report_json(analyse(load(path)))
    after = _dict_sizes(modules)
    grown = sorted(k for k, size in after.items()
                   if size > before.get(k, 0) and k not in VALUE_KEYED)
    assert grown == []


def test_the_value_keyed_tables_are_bounded_and_keyed_by_value():
    """Each table :data:`VALUE_KEYED` lets grow exists, is cleared when full (its module
    compares its size with a bound) and is keyed by no ``id()``."""
    for module_name, name in sorted(VALUE_KEYED):
        module = importlib.import_module(module_name)
        assert type(getattr(module, name)) is dict, (module_name, name)
        source = Path(module.__file__).read_text()
        assert f"len({name})" in source and f"{name}.clear()" in source, (module_name, name)
        uses = [line for line in source.splitlines() if name in line]
        assert not any("id(" in line for line in uses), (module_name, name)


def test_the_caches_are_the_analysis_context():
    """The analysis keeps the tables it filled; outside an analysis a table is a fresh
    dict each time (nothing is remembered across calls); ``forget`` is gone."""
    import exactsym.paper.homogeneous as homogeneous
    analysis = analyse(load(FILES[0]))
    sizes = analysis.context.sizes()
    assert sizes.get("truth balls", 0) > 0 and sizes.get("paper balls", 0) > 0, sizes
    cache = Cache("a test's table")
    outside = cache.table()
    outside["x"] = 1
    assert cache.table() == {}
    context = AnalysisContext()
    with context.active():
        cache.table()["x"] = 1
        assert cache.table() == {"x": 1}
    assert context.sizes()["a test's table"] == 1 and cache.table() == {}
    assert not hasattr(homogeneous, "forget")


def test_analyses_in_one_process_are_those_of_fresh_processes():
    """Each configuration analysed after others in one process (objects of one analysis
    gone, their ids free for the next) is reported as a fresh process reports it."""
    order = FILES[:3] + FILES[:3][::-1]
    texts = {}
    for path in order:
        text = json_text(report_json(analyse(load(path))))
        assert texts.setdefault(path, text) == text, path
    for path in FILES[:3]:
        fresh = subprocess.run([sys.executable, "-m", "exactsym", "check", "--json", str(path)],
                               capture_output=True, text=True, cwd=ROOT)
        assert json.loads(fresh.stdout) == json.loads(texts[path]), path


def test_pictures_read_an_analysis_only():
    """The pictures' one bridge to the library imports the analysis, never the truth,
    the paper or the audit."""
    tree = ast.parse((ROOT / "exactsym" / "pictures" / "_bridge.py").read_text())
    imported = {node.module for node in ast.walk(tree)
                if isinstance(node, ast.ImportFrom) and node.level}
    assert "analysis" in imported
    assert not {m for m in imported if m.split(".")[0] in ("truth", "paper", "audit")}
