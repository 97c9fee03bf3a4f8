"""The import structure of ``docs/architecture.md``: every import goes down the layers,
no module imports another in a circle, and no private name crosses a module."""

import ast
import functools
import re
from pathlib import Path

import networkx as nx
import pytest

ROOT = Path(__file__).resolve().parents[1]
PACKAGE = ROOT / "exactsym"


UNITS = sorted({p.name for p in (Path(__file__).resolve().parents[1] / "exactsym").iterdir()
                if p.is_dir() and (p / "__init__.py").exists()})


def _layers() -> dict:
    """package (or root module) -> its layer, read from the table in docs/architecture.md."""
    text = (ROOT / "docs" / "architecture.md").read_text()
    block = text.split("<!-- layers -->")[1].split("<!-- /layers -->")[0]
    layers = {}
    for row in block.splitlines():
        cells = [c.strip() for c in row.strip().strip("|").split("|")]
        if len(cells) >= 2 and cells[0].isdigit():
            for name in re.findall(r"`([\w.]+)`", cells[1]):
                layers[name] = int(cells[0])
    return layers


@functools.cache
def _modules() -> dict:
    """dotted module name -> path, for every module of the package."""
    found = {}
    for path in PACKAGE.rglob("*.py"):
        parts = path.relative_to(ROOT).with_suffix("").parts
        if parts[-1] == "__init__":
            parts = parts[:-1]
        found[".".join(parts)] = path
    return found


def _imports(modules: dict):
    """(importer, imported module, names) for every import of a module of the package,
    function-level imports included."""
    return _all_imports()


@functools.cache
def _all_imports() -> tuple:
    return tuple(_scan(_modules()))


def _scan(modules: dict):
    for name, path in modules.items():
        package = name if path.name == "__init__.py" else name.rpartition(".")[0]
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.ImportFrom):
                if node.level:
                    base = package.split(".")
                    base = base[:len(base) - node.level + 1]
                    target = ".".join(base + ([node.module] if node.module else []))
                else:
                    target = node.module or ""
                for alias in node.names:
                    sub = f"{target}.{alias.name}"
                    if sub in modules:
                        yield name, sub, ()
                    elif target in modules:
                        yield name, target, (alias.name,)
            elif isinstance(node, ast.Import):
                for alias in node.names:
                    if alias.name in modules:
                        yield name, alias.name, ()


def _unit(module: str) -> str:
    """The unit a module belongs to in the layer table: its sub-package of ``exactsym``, or
    the root module itself."""
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else "exactsym"


def test_every_unit_has_a_layer():
    layers = _layers()
    units = {_unit(m) for m in _modules()}
    assert units <= set(layers), sorted(units - set(layers))


def test_imports_go_down_the_layers():
    layers, modules = _layers(), _modules()
    wrong = []
    for importer, imported, _ in _imports(modules):
        a, b = _unit(importer), _unit(imported)
        if a != b and layers[b] >= layers[a]:
            wrong.append(f"{importer} ({a}, layer {layers[a]}) imports {imported} "
                         f"({b}, layer {layers[b]})")
    assert not wrong, "\n".join(wrong)


@pytest.mark.parametrize("unit", UNITS)
def test_no_import_circle(unit):
    modules = _modules()
    graph = nx.DiGraph()
    graph.add_nodes_from(modules)
    for importer, imported, _ in _imports(modules):
        # a package's __init__ is imported with every module below it: not an edge back
        if importer != imported and not importer.startswith(imported + "."):
            graph.add_edge(importer, imported)
    circles = sorted(sorted(c) for c in nx.strongly_connected_components(graph)
                     if len(c) > 1 and any(_unit(m) == unit for m in c))
    assert not circles, circles


@pytest.mark.parametrize("unit", UNITS)
def test_no_private_name_crosses_a_module(unit):
    modules = _modules()
    crossing = sorted(f"{importer} imports {imported}.{name}"
                      for importer, imported, names in _imports(modules)
                      for name in names if name.startswith("_") and not name.startswith("__")
                      and _unit(importer) == unit)
    assert not crossing, "\n".join(crossing)


def test_every_module_is_in_the_architecture():
    text = (ROOT / "docs" / "architecture.md").read_text()
    missing = sorted(str(p.relative_to(ROOT)) for p in PACKAGE.rglob("*.py")
                     if p.name not in ("__init__.py", "__main__.py")
                     and str(p.relative_to(ROOT)) not in text
                     and f"`{p.relative_to(PACKAGE.parent).with_suffix('')}`" not in text)
    assert not missing, missing


@pytest.mark.parametrize("unit", UNITS)
def test_no_module_over_700_lines(unit):
    long = sorted((len(p.read_text().splitlines()), str(p.relative_to(ROOT)))
                  for p in (PACKAGE / unit).rglob("*.py") if len(p.read_text().splitlines()) > 700)
    assert not long, long
