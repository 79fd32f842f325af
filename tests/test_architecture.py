"""The package layering the architecture relies on, read from the source with ``ast``.

Units are the top-level modules of ``graphflow`` and its sub-packages (a package is one unit);
every import counts, lazy ones inside functions included.
"""
import ast
from pathlib import Path

import networkx as nx
from conftest import ROOT

PACKAGE = ROOT / "graphflow"


def _unit(module: str) -> str | None:
    """The unit a dotted module name belongs to: ``graphflow.physics.world`` -> ``graphflow.physics``."""
    parts = module.split(".")
    if parts[0] != "graphflow":
        return None
    if len(parts) == 1 or not ((PACKAGE / parts[1]).is_dir() or (PACKAGE / f"{parts[1]}.py").exists()):
        return "graphflow"
    return f"graphflow.{parts[1]}"


def _module_name(path: Path) -> str:
    parts = list(path.relative_to(ROOT).with_suffix("").parts)
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def _imports(path: Path):
    """(module imported, line) for every import statement in a file, relative imports resolved."""
    package = _module_name(path).split(".") if path.name == "__init__.py" else _module_name(path).split(".")[:-1]
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            for alias in node.names:
                yield alias.name, node.lineno
        elif isinstance(node, ast.ImportFrom):
            base = package[:len(package) - node.level + 1] if node.level else []
            module = ".".join(base + ([node.module] if node.module else []))
            for alias in node.names:
                yield (f"{module}.{alias.name}" if not node.module or module == "graphflow" else module), node.lineno


def _unit_graph() -> nx.DiGraph:
    graph = nx.DiGraph()
    for path in PACKAGE.rglob("*.py"):
        source = _unit(_module_name(path))
        for module, line in _imports(path):
            target = _unit(module)
            if target is not None and target != source:
                graph.add_edge(source, target, where=f"{path.relative_to(ROOT)}:{line}")
    return graph


def test_no_import_cycle_between_packages_and_modules():
    graph = _unit_graph()
    cycles = list(nx.simple_cycles(graph))
    described = [" -> ".join(f"{a} ({graph.edges[a, b]['where']})" for a, b in zip(c, c[1:] + c[:1]))
                 for c in cycles]
    assert cycles == [], described


def _module_graph() -> nx.DiGraph:
    """Module-level imports (``graphflow.validate.preflight`` -> ``graphflow.usd.resolver``), lazy ones included."""
    modules = {_module_name(path) for path in PACKAGE.rglob("*.py")}
    graph = nx.DiGraph()
    for path in PACKAGE.rglob("*.py"):
        source = _module_name(path)
        graph.add_node(source)
        for module, line in _imports(path):
            while module and module not in modules:   # "graphflow.usd.resolver.resolve_stage" -> the module
                module = module.rpartition(".")[0]
            if module and module != source:
                graph.add_edge(source, module, where=f"{path.relative_to(ROOT)}:{line}")
    return graph


def _reaches_physics(graph: nx.DiGraph, module: str) -> bool:
    return any(reached.startswith("graphflow.physics") for reached in nx.descendants(graph, module))


def test_the_core_and_the_gripper_stand_on_the_world_interface_not_on_physics():
    graph = _unit_graph()
    for unit in ("graphflow.world", "graphflow.poses", "graphflow.gripper"):
        reached = nx.descendants(graph, unit)
        assert "graphflow.physics" not in reached, f"{unit} reaches graphflow.physics"
    assert graph.has_edge("graphflow.physics", "graphflow.world")     # the backend implements the interface
    assert not _reaches_physics(_module_graph(), "graphflow.testing.fake_world")


APPLICATIONS = ("cli", "verdicts", "validate", "observe", "inputs", "testing", "catalog", "sweep", "variants", "report")


def test_the_engine_imports_no_application_folder():
    """Flat modules are the engine: they may be used by the applications, never the other way round."""
    graph = _unit_graph()
    engine = [f"graphflow.{path.stem}" for path in PACKAGE.glob("*.py") if path.stem not in ("__init__", "__main__")]
    for module in engine:
        reached = {unit.split(".")[1] for unit in nx.descendants(graph, module) if unit.count(".") == 1}
        assert not reached & set(APPLICATIONS), f"{module} reaches {sorted(reached & set(APPLICATIONS))}"


def test_validate_and_usd_never_reach_physics():
    """``graphflow validate`` and the USD side read stages with usd-core alone: no PyBullet, no physics world."""
    graph = _module_graph()
    for module in graph.nodes:
        if module.startswith(("graphflow.validate", "graphflow.usd")):
            assert not _reaches_physics(graph, module), f"{module} reaches graphflow.physics"


def test_every_application_folder_is_one_package_and_no_module_is_over_500_lines():
    for folder in APPLICATIONS:
        assert (PACKAGE / folder / "__init__.py").is_file(), folder
    long = [f"{path.relative_to(ROOT)}: {n}" for path in [*PACKAGE.rglob("*.py"), *(ROOT / "nodes").rglob("*.py")]
            if (n := len(path.read_text(encoding="utf-8").splitlines())) > 500]
    assert long == []


def test_only_graphflow_physics_imports_pybullet():
    importers = sorted(str(path.relative_to(ROOT)) for folder in (PACKAGE, ROOT / "nodes")
                       for path in folder.rglob("*.py")
                       if any(module.split(".")[0] in ("pybullet", "pybullet_utils") for module, _ in _imports(path)))
    assert importers and all(path.startswith("graphflow/physics/") for path in importers), importers


def test_nodes_reach_physics_only_through_the_world_they_are_given():
    importers = sorted(str(path.relative_to(ROOT)) for path in (ROOT / "nodes").rglob("*.py")
                       if any(module.startswith("graphflow.physics") for module, _ in _imports(path)))
    assert importers == []


def test_no_private_name_is_imported_across_modules():
    """A leading underscore means "this module's own": another module that needs it gets a public name instead."""
    offenders = []
    for folder in (PACKAGE, ROOT / "nodes"):
        for path in folder.rglob("*.py"):
            for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
                if isinstance(node, ast.ImportFrom) and (node.module or "").startswith(("graphflow", "graphflow_nodes")):
                    offenders += [f"{path.relative_to(ROOT)}:{node.lineno} {alias.name}" for alias in node.names
                                  if alias.name.startswith("_") and not alias.name.startswith("__")]
    assert offenders == []


def test_every_test_folder_is_collected(pytestconfig):
    """pytest skips folders matching ``norecursedirs`` (by default ``build``): no folder under tests/ may match one,
    or its tests silently never run (tests/build, mirroring graphflow/build, once did not)."""
    import fnmatch

    patterns = pytestconfig.getini("norecursedirs")
    folders = [path.name for path in (ROOT / "tests").rglob("*") if path.is_dir() and path.name != "__pycache__"]
    assert "build" in folders
    assert [name for name in folders if any(fnmatch.fnmatch(name, pattern) for pattern in patterns)] == []
