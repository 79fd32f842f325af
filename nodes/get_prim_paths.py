"""omni.graph.nodes.GetPrimPaths: the paths of a relationship's prims as tokens."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.GetPrimPaths",
    version=1,
    description="outputs:primPaths = the absolute paths of the prims of inputs:prims, as a token array.",
    categories=("sceneGraph",),
    ui_name="Get Prim Paths",
    inputs=(
        Attribute("prims", "target", description="The prims"),
    ),
    outputs=(
        Attribute("primPaths", "token[]", description="Their paths"),
    ),
)


def compute(db):
    db.outputs.primPaths = tuple(db.inputs.prims)
