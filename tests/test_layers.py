"""The architecture holds: no import cycle, no import from a lower layer to a higher one.

Issue 21.  Every module of ``src/graspcompass`` is read with :mod:`ast` (not imported),
every ``import`` and ``from ... import`` of it is an edge of the import graph — at the
top of the module or inside a function alike; only the imports under
``if TYPE_CHECKING:`` are left out (they are never executed).  The graph must have no
cycle, and no edge may go up the layers of the project brief::

    boundary < geometry < grasp < construction < proof, scene < render, export
             < applications (world, sizing, planning, diagnosis, batch, outlines, ncontact)
             < cli

``scene`` is the picture model without matplotlib (``layout``, ``labelling``,
``palette``, ``export._scene`` and the ``scene`` package).  Nothing below
``render``/``export`` imports matplotlib.

The checker is tested first on small graphs and a small source tree made here, with
a cycle, an upward edge and a matplotlib import it must reject, and a
``TYPE_CHECKING`` import it must accept.
"""

from __future__ import annotations

import ast
import textwrap
from collections.abc import Iterable, Mapping
from pathlib import Path

import pytest

SRC = Path(__file__).resolve().parents[1] / "src"

#: Rank of each layer, lowest first; proof and scene are siblings, as are render and export.
RANKS = {
    "boundary": 0,
    "geometry": 1,
    "grasp": 2,
    "construction": 3,
    "proof": 4,
    "scene": 4,
    "render": 5,
    "export": 5,
    "applications": 6,
    "cli": 7,
}

#: Module (or package) name -> layer; the longest matching prefix wins.
LAYERS = {
    "graspcompass": "cli",  # the root package only re-exports, lazily (graspcompass._lazy)
    "graspcompass.__main__": "cli",
    "graspcompass.cli": "cli",
    "graspcompass.boundary": "boundary",
    "graspcompass.errors": "boundary",
    "graspcompass.limits": "boundary",
    "graspcompass.expr": "boundary",
    "graspcompass.inputs": "boundary",
    "graspcompass._lazy": "boundary",
    "graspcompass._version": "boundary",
    "graspcompass.presets": "boundary",
    "graspcompass.progress": "boundary",
    "graspcompass.symbols": "boundary",
    "graspcompass.geometry": "geometry",
    "graspcompass.grasp": "grasp",
    "graspcompass.construction": "construction",
    "graspcompass.proof": "proof",
    "graspcompass.scene": "scene",
    "graspcompass.layout": "scene",
    "graspcompass.labelling": "scene",
    "graspcompass.palette": "scene",
    "graspcompass.export._scene": "scene",
    "graspcompass.render": "render",
    "graspcompass.export": "export",
    "graspcompass.world": "applications",
    "graspcompass.sizing": "applications",
    "graspcompass.planning": "applications",
    "graspcompass.diagnosis": "applications",
    "graspcompass.batch": "applications",
    "graspcompass.outlines": "applications",
    "graspcompass.ncontact": "applications",
}

#: The one edge allowed up the layers, and why.  The input boundary refuses a division by
#: a number that is exactly zero in disguise (``1/(sqrt(2) + sqrt(3) - sqrt(5 + 2*sqrt(6)))``)
#: with the kernel's exact zero test: ``inputs.exact_denominators`` and ``exact_sign`` import
#: ``geometry.exact`` inside the function.  The decision procedure (``geometry.exact`` and
#: its ``_exact_*`` modules) reads no outside input and imports nothing of the boundary but
#: ``errors`` and the parser ``expr`` (the cycle test below holds it to that).
ALLOWED_UP = {("graspcompass.boundary.inputs", "graspcompass.geometry.exact")}

#: Third-party packages that only the painters (render) and files (export) may import.
PAINTERS_ONLY = ("matplotlib",)


# --- the checker ------------------------------------------------------------------


def _module_name(path: Path, root: Path) -> tuple[str, bool]:
    parts = list(path.relative_to(root).with_suffix("").parts)
    package = parts[-1] == "__init__"
    if package:
        parts.pop()
    return ".".join(parts), package


def _is_type_checking(test: ast.expr) -> bool:
    return (isinstance(test, ast.Name) and test.id == "TYPE_CHECKING") or (
        isinstance(test, ast.Attribute) and test.attr == "TYPE_CHECKING"
    )


def _imports(tree: ast.AST) -> Iterable[ast.Import | ast.ImportFrom]:
    """Every import statement that can run: all but those under ``if TYPE_CHECKING:``."""
    stack: list[ast.AST] = [tree]
    while stack:
        node = stack.pop()
        if isinstance(node, (ast.Import, ast.ImportFrom)):
            yield node
        if isinstance(node, ast.If) and _is_type_checking(node.test):
            stack.extend(node.orelse)  # the else branch runs
            continue
        stack.extend(ast.iter_child_nodes(node))


def import_graph(
    root: Path, top: str = "graspcompass"
) -> tuple[dict[str, set[str]], dict[str, set[str]]]:
    """``(graph, external)`` of the package ``top`` under ``root``.

    ``graph`` maps each module to the package modules it imports; ``external`` to the
    top-level names of the other packages it imports.  ``from p import m`` with ``m``
    a module of ``p`` is an edge to ``p.m``; ``import p.m`` to ``p.m``.
    """
    files = {}
    for path in sorted((root / top).rglob("*.py")):
        files[_module_name(path, root)] = path
    modules = {name for name, _ in files}
    graph: dict[str, set[str]] = {}
    external: dict[str, set[str]] = {}
    for (name, package), path in files.items():
        edges = graph.setdefault(name, set())
        ext = external.setdefault(name, set())
        here = name.split(".") if package else name.split(".")[:-1]
        for node in _imports(ast.parse(path.read_text(encoding="utf-8"), str(path))):
            if isinstance(node, ast.Import):
                targets = [a.name for a in node.names]
            elif node.level == 0:
                base = node.module or ""
                targets = [
                    f"{base}.{a.name}" if f"{base}.{a.name}" in modules else base
                    for a in node.names
                ]
            else:
                up = here[: len(here) - node.level + 1]
                base = ".".join(up + ([node.module] if node.module else []))
                targets = [
                    f"{base}.{a.name}" if f"{base}.{a.name}" in modules else base
                    for a in node.names
                ]
            for target in targets:
                if target == top or target.startswith(top + "."):
                    while target not in modules and "." in target:
                        target = target.rpartition(".")[0]  # an attribute of a module
                    if target != name:
                        edges.add(target)
                else:
                    ext.add(target.split(".")[0])
    return graph, external


def cycles(graph: Mapping[str, Iterable[str]]) -> list[list[str]]:
    """The strongly connected components with more than one module (Tarjan), sorted."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    on_stack: set[str] = set()
    stack: list[str] = []
    found: list[list[str]] = []
    counter = 0

    def visit(v: str) -> None:
        nonlocal counter
        index[v] = low[v] = counter
        counter += 1
        stack.append(v)
        on_stack.add(v)
        for w in graph.get(v, ()):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1 or v in graph.get(v, ()):
                found.append(sorted(component))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return sorted(found)


def layer_of(module: str, layers: Mapping[str, str] = LAYERS) -> str:
    """The layer of ``module``: that of its longest listed prefix."""
    parts = module.split(".")
    for n in range(len(parts), 0, -1):
        prefix = ".".join(parts[:n])
        if prefix in layers:
            return layers[prefix]
    raise KeyError(f"{module} is in no layer: add it to LAYERS")


def upward(
    graph: Mapping[str, Iterable[str]], layers: Mapping[str, str] = LAYERS
) -> list[tuple[str, str]]:
    """The edges ``(a, b)`` where ``a`` is on a lower layer than ``b``."""
    return sorted(
        (a, b)
        for a, targets in graph.items()
        for b in targets
        if RANKS[layer_of(a, layers)] < RANKS[layer_of(b, layers)]
    )


def painters_only(
    external: Mapping[str, Iterable[str]], layers: Mapping[str, str] = LAYERS
) -> list[tuple[str, str]]:
    """``(module, package)`` for a module below render/export importing matplotlib."""
    return sorted(
        (m, p)
        for m, pkgs in external.items()
        for p in pkgs
        if p in PAINTERS_ONLY and RANKS[layer_of(m, layers)] < RANKS["render"]
    )


# --- the checker on graphs made to fail ----------------------------------------------


def test_checker_finds_a_cycle_and_only_cycles() -> None:
    g = {"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}, "e": set()}
    assert cycles(g) == [["a", "b", "c"]]
    assert cycles({"a": {"b"}, "b": set(), "c": {"b"}}) == []
    assert cycles({"a": {"a"}}) == [["a"]]  # a module importing itself


def test_checker_finds_an_upward_edge() -> None:
    layers = {"p.low": "boundary", "p.mid": "grasp", "p.top": "cli", "p": "cli"}
    g = {"p.low": {"p.top"}, "p.top": {"p.mid"}, "p.mid": {"p.low"}}
    assert upward(g, layers) == [("p.low", "p.top")]
    assert upward({"p.top": {"p.mid", "p.low"}}, layers) == []
    with pytest.raises(KeyError, match="no layer"):
        layer_of("q.x", layers)


def test_checker_reads_function_level_and_skips_type_checking(tmp_path: Path) -> None:
    pkg = tmp_path / "pkg"
    (pkg / "sub").mkdir(parents=True)
    files = {
        "__init__.py": "",
        "low.py": """
            from typing import TYPE_CHECKING
            if TYPE_CHECKING:
                from .top import T  # allowed: never executed
            def f():
                from .sub import deep  # a function-level import is an edge
                import matplotlib.pyplot  # below the painters
            """,
        "top.py": "from . import low\nfrom .low import f as g\n",
        "sub/__init__.py": "",
        "sub/deep.py": "from ..top import g\nimport numpy as np\n",
    }
    for name, text in files.items():
        (pkg / name).write_text(textwrap.dedent(text))
    graph, external = import_graph(tmp_path, "pkg")
    assert graph["pkg.low"] == {"pkg.sub.deep"}
    assert graph["pkg.top"] == {"pkg.low"}
    assert graph["pkg.sub.deep"] == {"pkg.top"}
    assert cycles(graph) == [["pkg.low", "pkg.sub.deep", "pkg.top"]]
    layers = {"pkg": "cli", "pkg.low": "grasp", "pkg.sub": "geometry"}
    assert upward(graph, layers) == [("pkg.sub.deep", "pkg.top")]  # not low: TYPE_CHECKING
    assert painters_only(external, layers) == [("pkg.low", "matplotlib")]
    assert external["pkg.sub.deep"] == {"numpy"}


# --- the package ---------------------------------------------------------------------


@pytest.fixture(scope="module")
def package() -> tuple[dict[str, set[str]], dict[str, set[str]]]:
    return import_graph(SRC)


def test_every_module_is_on_a_layer(package) -> None:
    graph, _ = package
    assert len(graph) > 100
    for module in graph:
        layer_of(module)


def test_no_import_cycle(package) -> None:
    graph, _ = package
    assert cycles(graph) == []


def test_no_import_goes_up_the_layers(package) -> None:
    graph, _ = package
    assert [e for e in upward(graph) if e not in ALLOWED_UP] == []


def test_the_allowed_upward_edge_is_needed_and_the_kernel_is_below_the_inputs(package) -> None:
    """The exception is real (else drop it), and the exact kernel never reads inputs."""
    graph, _ = package
    assert ALLOWED_UP <= set(upward(graph))
    kernel = [
        m
        for m in graph
        if m == "graspcompass.geometry.exact" or m.startswith("graspcompass.geometry._exact_")
    ]
    assert len(kernel) >= 5
    for m in kernel:
        assert {t for t in graph[m] if layer_of(t) == "boundary"} <= {
            "graspcompass.boundary.errors",
            "graspcompass.boundary.expr",
            "graspcompass.boundary.limits",
        }, m


def test_nothing_below_the_painters_imports_matplotlib(package) -> None:
    _, external = package
    assert painters_only(external) == []


def test_modules_are_small() -> None:
    """No module over 600 lines, the median near 150 (issue 21, the project brief)."""
    sizes = {
        p: len(p.read_text(encoding="utf-8").splitlines())
        for p in (SRC / "graspcompass").rglob("*.py")
    }
    assert [str(p.relative_to(SRC)) for p, n in sizes.items() if n > 600] == []
    median = sorted(sizes.values())[len(sizes) // 2]
    assert median <= 200, median
