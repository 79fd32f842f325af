"""Node registry: built-in discovery, aliases, third-party entry points, and no code named by graph files."""
import subprocess
import sys
import types

import pytest

from graphflow.document import GraphError, parse_document
from graphflow.registry import Registry, _load_entry_point, default_registry
from graphflow.spec import Attribute, NodeSpec


def _node_module(name, spec):
    module = types.ModuleType(name)
    module.SPEC = spec
    module.compute = lambda db: None
    return module


def test_builtin_nodes_are_discovered():
    ids = {t.spec.id for t in default_registry().types()}
    assert {"omni.graph.action.OnTick", "omni.graph.action.Branch", "omni.graph.action.Delay",
            "omni.graph.nodes.Add", "omni.graph.ui_nodes.PrintText", "graphflow.StopRun"} <= ids


def test_aliases_resolve_to_the_current_type():
    registry = Registry()
    registry.register_module(_node_module("acme_nodes.grip", NodeSpec(
        id="acme.robot.Grip", version=2, description="Grips.", aliases=("omni.isaac.acme.Grip",),
        inputs=(Attribute("execIn", "execution"),))))
    assert registry.get("omni.isaac.acme.Grip").spec.id == "acme.robot.Grip"
    document = parse_document({"format": "graphflow", "formatVersion": [1, 0],
                               "nodes": [{"name": "g", "type": "omni.isaac.acme.Grip"}]}, registry=registry)
    assert document.node("g").type == "omni.isaac.acme.Grip"


def test_require_gives_the_type_by_id_or_alias_and_names_a_type_it_does_not_have():
    registry = Registry()
    registry.register_module(_node_module("acme_nodes.grip", NodeSpec(
        id="acme.robot.Grip", version=2, description="Grips.", aliases=("omni.isaac.acme.Grip",),
        inputs=(Attribute("execIn", "execution"),))))
    assert registry.require("omni.isaac.acme.Grip").spec.id == "acme.robot.Grip"
    with pytest.raises(KeyError, match="node type 'acme.robot.Grab' is not in this registry"):
        registry.require("acme.robot.Grab")


def test_entry_point_packages_and_modules_register():
    package = types.ModuleType("acme_pkg")
    package.__path__ = []
    module = _node_module("acme_single", NodeSpec(id="acme.Single", version=1, description="One."))

    class FakeEntryPoint:
        def __init__(self, value, loaded):
            self.value, self._loaded = value, loaded

        def load(self):
            if isinstance(self._loaded, Exception):
                raise self._loaded
            return self._loaded

    registry = Registry()
    _load_entry_point(registry, FakeEntryPoint("acme_single", module))
    _load_entry_point(registry, FakeEntryPoint("acme_pkg", package))
    _load_entry_point(registry, FakeEntryPoint("broken", ImportError("no module named broken")))
    assert registry.get("acme.Single") is not None


def test_same_id_from_two_modules_is_refused():
    registry = Registry()
    spec = NodeSpec(id="acme.Twice", version=1, description="Twice.")
    registry.register_module(_node_module("first", spec))
    with pytest.raises(ValueError, match="defined twice"):
        registry.register_module(_node_module("second", spec))


def test_a_graph_naming_a_python_path_does_not_import_it():
    assert "antigravity" not in sys.modules
    with pytest.raises(GraphError) as caught:
        parse_document({"format": "graphflow", "formatVersion": [1, 0],
                        "nodes": [{"name": "x", "type": "antigravity"}, {"name": "y", "type": "os.system"}]})
    assert "antigravity" not in sys.modules
    assert [p.message for p in caught.value.problems] == ["unknown node type 'antigravity'", "unknown node type 'os.system'"]


def test_loading_the_builtin_nodes_imports_neither_numpy_nor_the_ik_solver():
    # every graph loads the registry: the pick-and-place nodes import their solver (and numpy) on first use
    code = ("import sys; from graphflow.registry import default_registry; default_registry(); "
            "print([m for m in ('numpy', 'graphflow.kinematics') if m in sys.modules])")
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert result.stdout.strip() == "[]"
