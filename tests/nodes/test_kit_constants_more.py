"""The omni.graph.nodes constants whose USD types are half colours, texture coordinates, timecodes and matrices.

Each is written in a .usda as Kit saves it (the constant read from inputs:value)
and imported: the authored value reaches the node (a matrix4d flat, row by row),
and downstream nodes compute with it.
"""
import math

import pytest

from graphflow.testing import GraphHarness, NodeHarness
from graphflow.usd.omnigraph import import_graph

STAGE = '''#usda 1.0
def Xform "World"
{{
    def OmniGraph "Graph"
    {{
        token evaluator:type = "execution"
{nodes}
    }}
}}
'''
NODE = '''        def OmniGraphNode "{name}"
        {{
            token node:type = "omni.graph.nodes.{type}"
            int node:typeVersion = 1
            custom {usd_type} inputs:value = {value}
        }}
'''
AUTHORED = [
    ("ConstantColor3h", "color3h", "(0.5, 0.25, 1)", (0.5, 0.25, 1.0)),
    ("ConstantColor4h", "color4h", "(0.5, 0.25, 1, 0.125)", (0.5, 0.25, 1.0, 0.125)),
    ("ConstantNormal3h", "normal3h", "(0, 0, 1)", (0.0, 0.0, 1.0)),
    ("ConstantPoint3h", "point3h", "(1, 2, 3)", (1.0, 2.0, 3.0)),
    ("ConstantTexCoord2f", "texCoord2f", "(0.5, 0.75)", (0.5, 0.75)),
    ("ConstantTexCoord3d", "texCoord3d", "(0.5, 0.75, 1)", (0.5, 0.75, 1.0)),
    ("ConstantTimecode", "timecode", "24", 24.0),
    ("ConstantUChar", "uchar", "200", 200),
    ("ConstantMatrix2d", "matrix2d", "((0, -1), (1, 0))", (0.0, -1.0, 1.0, 0.0)),
    ("ConstantMatrix4d", "matrix4d", "((1, 0, 0, 0), (0, 1, 0, 0), (0, 0, 1, 0), (1, 2, 3, 1))",
     (1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 2.0, 3.0, 1.0)),
]


def test_authored_constants_import_with_their_values(tmp_path):
    nodes = "".join(NODE.format(name=f"n{i}", type=t, usd_type=u, value=v) for i, (t, u, v, _) in enumerate(AUTHORED))
    path = tmp_path / "constants.usda"
    path.write_text(STAGE.format(nodes=nodes))
    document = import_graph(str(path)).document
    values = {node.type.rsplit(".", 1)[1]: node.inputs["value"] for node in document.nodes}
    for type_name, _, _, expected in AUTHORED:
        authored = tuple(values[type_name]) if isinstance(expected, tuple) else values[type_name]
        assert authored == expected
        assert NodeHarness(f"omni.graph.nodes.{type_name}", inputs={"value": values[type_name]}).compute() \
            .outputs["value"] == pytest.approx(expected)


def test_matrix_constants_default_to_identity_and_feed_the_matrix_nodes():
    assert NodeHarness("omni.graph.nodes.ConstantMatrix3d").compute().outputs["value"] == (1.0, 0.0, 0.0, 0.0, 1.0, 0.0,
                                                                                         0.0, 0.0, 1.0)
    translated = (1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 2.0, 3.0, 1.0)
    g = GraphHarness({"nodes": [
        {"name": "tick", "type": "omni.graph.action.OnTick"},
        {"name": "frame", "type": "omni.graph.nodes.ConstantFrame", "inputs": {"value": translated}},
        {"name": "where", "type": "omni.graph.nodes.GetMatrix4Translation"},
        {"name": "text", "type": "omni.graph.nodes.ToString"},
        {"name": "print", "type": "omni.graph.ui_nodes.PrintText"}],
        "connections": [{"src": "tick.outputs:tick", "dst": "print.inputs:execIn"},
                        {"src": "frame.outputs:value", "dst": "where.inputs:matrix"},
                        {"src": "where.outputs:translation", "dst": "text.inputs:value"},
                        {"src": "text.outputs:converted", "dst": "print.inputs:text"}]})
    g.run(ticks=1)
    assert g.output("where", "translation") == (1.0, 2.0, 3.0)


def test_constant_e_is_a_multiple_of_e():
    assert NodeHarness("omni.graph.nodes.ConstantE", inputs={"factor": 2}).compute().outputs["value"] == \
        pytest.approx(2 * math.e)
