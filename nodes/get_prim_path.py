"""omni.graph.nodes.GetPrimPath: the path of a prim input, as a token."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.GetPrimPath",
    version=1,
    description="outputs:primPath = the absolute path of the prim input (the first, if several).",
    categories=("sceneGraph",),
    ui_name="Get Prim Path",
    inputs=(
        Attribute("prim", "target", description="The prim"),
    ),
    outputs=(
        Attribute("primPath", "token", description="Its absolute path"),
    ),
)


def compute(db):
    if not db.inputs.prim:
        db.error("inputs:prim is not set: no prim to give the path of")
    db.outputs.primPath = db.inputs.prim[0]
