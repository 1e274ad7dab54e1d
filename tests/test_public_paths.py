"""Every documented import path works (issue 21).

Each module of ``src/graspcompass`` that defines ``__all__`` is its names' documented
path: every name of it imports from there (``from module import name``).  The modules
moved by the layout of issue 21 keep their public paths of before (the old path
re-exports the same objects), and a public class is pickled under a path that imports
it back (its ``__module__``).
"""

from __future__ import annotations

import ast
import importlib
import pickle
from pathlib import Path

import pytest

SRC = Path(__file__).resolve().parents[1] / "src"


def _all_of(path: Path) -> list[str] | None:
    """The literal ``__all__`` of a module's source, or None."""
    for node in ast.parse(path.read_text(encoding="utf-8")).body:
        targets = (
            node.targets
            if isinstance(node, ast.Assign)
            else [node.target]
            if isinstance(node, ast.AnnAssign)
            else []
        )
        if any(isinstance(t, ast.Name) and t.id == "__all__" for t in targets):
            try:
                return list(ast.literal_eval(node.value))
            except ValueError:  # ``list(_home.__all__)``: a re-export (COMPUTED)
                return None
    return None


def _modules() -> tuple[dict[str, list[str]], set[str]]:
    found, computed = {}, set()
    for path in sorted((SRC / "graspcompass").rglob("*.py")):
        parts = list(path.relative_to(SRC).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts.pop()
        names = _all_of(path)
        if names is not None:
            found[".".join(parts)] = names
        elif "__all__" in path.read_text(encoding="utf-8"):
            computed.add(".".join(parts))
    return found, computed


MODULES, COMPUTED = _modules()

#: The public paths of before issue 21 and where their code lives now.
OLD_PATHS = {
    "graspcompass.errors": "graspcompass.boundary.errors",
    "graspcompass.limits": "graspcompass.boundary.limits",
    "graspcompass.expr": "graspcompass.boundary.expr",
    "graspcompass.inputs": "graspcompass.boundary.inputs",
    "graspcompass.grasp": "graspcompass.grasp",
    "graspcompass.world": "graspcompass.world",
    "graspcompass.cli": "graspcompass.cli",
    "graspcompass.outlines": "graspcompass.outlines",
    "graspcompass.diagnosis": "graspcompass.diagnosis",
}


def test_the_package_declares_its_names() -> None:
    assert len(MODULES) > 80
    assert "graspcompass" in MODULES and "graspcompass.boundary.expr" in MODULES


@pytest.mark.parametrize("module", sorted(MODULES))
def test_every_name_of_all_imports_from_its_module(module: str) -> None:
    names = MODULES[module]
    assert len(set(names)) == len(names), f"{module}.__all__ lists a name twice"
    mod = importlib.import_module(module)
    namespace: dict[str, object] = {}
    exec(f"from {module} import {', '.join(names) or '__name__'}", namespace)
    for name in names:
        assert namespace[name] is getattr(mod, name)


def test_only_the_old_paths_compute_their_all() -> None:
    """A computed ``__all__`` (``list(home.__all__)``) is only the old public paths' re-export
    of their new home, which the next test checks name by name."""
    assert {m for m in COMPUTED if not MODULES.get(m)} == {
        "graspcompass.errors",
        "graspcompass.limits",
        "graspcompass.expr",
        "graspcompass.inputs",
    }


@pytest.mark.parametrize("old", sorted(OLD_PATHS))
def test_the_old_public_paths_give_the_same_objects(old: str) -> None:
    home = importlib.import_module(OLD_PATHS[old])
    mod = importlib.import_module(old)
    names = home.__all__
    assert names and list(mod.__all__) == list(names)
    for name in names:
        assert getattr(mod, name) is getattr(home, name), f"{old}.{name}"


def test_the_old_private_paths_are_gone_and_the_new_ones_work() -> None:
    """The private modules moved without a copy left behind (no second home)."""
    for gone in (
        "graspcompass._cli_k",
        "graspcompass._world_place",
        "graspcompass._grasp_checks",
        "graspcompass._floatpath",
        "graspcompass._infiles",
        "graspcompass._output",
    ):
        with pytest.raises(ModuleNotFoundError):
            importlib.import_module(gone)
    from graspcompass.boundary._infiles import read_bounded
    from graspcompass.cli._k import table
    from graspcompass.grasp._floatpath import FLOAT_MARGIN

    assert callable(read_bounded) and callable(table) and FLOAT_MARGIN == 1e-12


def _public_classes() -> list[tuple[str, str]]:
    out = []
    for module, names in MODULES.items():
        if module.split(".")[-1].startswith("_"):
            continue
        mod = importlib.import_module(module)
        out += [(module, n) for n in names if isinstance(getattr(mod, n), type)]
    return sorted(out)


@pytest.mark.parametrize(("module", "name"), _public_classes())
def test_a_public_class_imports_back_from_its_module_attribute(module: str, name: str) -> None:
    cls = getattr(importlib.import_module(module), name)
    home = importlib.import_module(cls.__module__)
    assert getattr(home, cls.__qualname__) is cls, f"{cls.__module__}.{cls.__qualname__}"


def test_errors_pickle_under_their_public_path() -> None:
    from graspcompass.errors import InputTooLargeError
    from graspcompass.expr import ExpressionError
    from graspcompass.grasp import InvalidGraspError
    from graspcompass.world import VertexContactError

    for cls, path in (
        (InputTooLargeError, "graspcompass.errors"),
        (ExpressionError, "graspcompass.expr"),
        (InvalidGraspError, "graspcompass.grasp"),
        (VertexContactError, "graspcompass.world"),
    ):
        assert cls.__module__ == path
        again = pickle.loads(pickle.dumps(cls("a message")))
        assert type(again) is cls and str(again) == "a message"


def test_the_console_script_is_the_cli_console() -> None:
    tomllib = pytest.importorskip("tomllib")  # Python 3.11
    scripts = tomllib.loads((SRC.parent / "pyproject.toml").read_text())["project"]["scripts"]
    target, _, attr = scripts["graspcompass"].partition(":")
    assert target == "graspcompass.cli" and callable(getattr(importlib.import_module(target), attr))
