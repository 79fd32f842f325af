"""omni.graph.nodes.ExtractPrim: one prim's child bundle out of a bundle of several prims."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.ExtractPrim",
    version=1,
    description=(
        "outputs:primBundle = the child bundle of 'prims' whose sourcePrimPath is the prim of 'prim' (or "
        "primPath when 'prim' is empty). The node fails, naming the prims the bundle holds, when none is."),
    categories=("bundle",),
    ui_name="Extract Prim",
    inputs=(
        Attribute("prim", "target", optional=True, description="The prim to extract"),
        Attribute("primPath", "path", default="", description="Its path, used when 'prim' is empty"),
        Attribute("prims", "bundle", description="A bundle of prims (ReadPrims' output)"),
    ),
    outputs=(
        Attribute("primBundle", "bundle", description="That prim's bundle"),
    ),
)


def compute(db):
    wanted = db.inputs.prim[0] if db.inputs.prim else db.inputs.primPath
    if not wanted:
        db.error("no prim given (set 'prim' or 'primPath')")
    children = db.inputs.prims.children
    for child in children:
        if child.source_prim_path == wanted:
            db.outputs.primBundle = child
            return
    held = ", ".join(child.source_prim_path for child in children) or "none"
    db.error(f"no prim {wanted} in the bundle (its prims: {held})")
