"""Generated from graphflow/usd/libraries.py: every library id and alias, as a one-node Isaac graph, imports.

Each case writes the .usda Kit would save for a graph holding one node of that
type (an OmniGraph prim, a node prim with node:type and node:typeVersion) and
imports it through graphflow's importer: implemented ids (and every alias of
the implemented types) come in as that node; renderer and GUI ids are dropped
with their one line; the coverage table says why the others are not there.
"""
import pytest

from graphflow.registry import default_registry
from graphflow.usd.libraries import DROPPED, IMPLEMENTED, MISSING, coverage
from graphflow.usd.omnigraph import import_graph

REGISTRY = default_registry()
ROWS = [row for rows in coverage(REGISTRY).values() for row in rows]
IMPLEMENTED_IDS = sorted({row.type_id for row in ROWS if row.state == IMPLEMENTED}
                         | {alias for row in ROWS if row.state == IMPLEMENTED for alias in row.aliases})
DROPPED_IDS = sorted(row.type_id for row in ROWS if row.state == DROPPED)


def _one_node_stage(tmp_path, type_id: str, version: int):
    path = tmp_path / "one_node.usda"
    path.write_text(f'''#usda 1.0
(
    defaultPrim = "World"
)
def Xform "World"
{{
    def OmniGraph "ActionGraph"
    {{
        token evaluator:type = "execution"
        int2 fileFormatVersion = (1, 9)
        token pipelineStage = "pipelineStageSimulation"
        def OmniGraphNode "node"
        {{
            token node:type = "{type_id}"
            int node:typeVersion = {version}
        }}
    }}
}}
''')
    return path


@pytest.mark.parametrize("type_id", IMPLEMENTED_IDS)
def test_every_implemented_library_id_and_alias_imports_as_its_node(tmp_path, type_id):
    spec = REGISTRY.get(type_id).spec
    result = import_graph(str(_one_node_stage(tmp_path, type_id, spec.version)))
    (node,) = result.document.nodes
    assert REGISTRY.get(node.type).spec.id == spec.id
    assert not [w for w in result.warnings if "typeVersion" in w]


@pytest.mark.parametrize("type_id", DROPPED_IDS)
def test_every_renderer_or_gui_id_is_dropped_with_one_line(tmp_path, type_id):
    result = import_graph(str(_one_node_stage(tmp_path, type_id, 1)))
    assert result.document.nodes == ()
    assert [w for w in result.warnings if type_id in w and "dropped:" in w] != []


def test_every_library_type_is_covered_or_says_why_not():
    assert len(ROWS) > 150
    assert all(row.why for row in ROWS if row.state == MISSING)
