"""graphflow.ComposePoses: a pose given in a parent frame, expressed in the world (parent * child)."""
from graphflow.poses import compose, quat_normalize
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="graphflow.ComposePoses",
    version=1,
    description=("outputs = parent * child: the child pose (position m, orientation x, y, z, w) given in the "
                 "parent's frame, expressed where the parent is given (e.g. a place pose relative to a "
                 "target prim's pose from ReadPrimPose)."),
    categories=("math:operator",),
    ui_name="Compose Poses",
    inputs=(
        Attribute("parentPosition", "double[3]", default=(0.0, 0.0, 0.0), description="Parent frame origin (m)"),
        Attribute("parentOrientation", "quatd[4]", default=(0.0, 0.0, 0.0, 1.0), description="Parent frame rotation"),
        Attribute("childPosition", "double[3]", default=(0.0, 0.0, 0.0), description="Child position in the parent frame (m)"),
        Attribute("childOrientation", "quatd[4]", default=(0.0, 0.0, 0.0, 1.0), description="Child rotation in the parent frame"),
    ),
    outputs=(
        Attribute("position", "double[3]", description="The child position in the parent's reference (m)"),
        Attribute("orientation", "quatd[4]", description="The child rotation in the parent's reference"),
    ),
)


def compute(db):
    parent = (tuple(db.inputs.parentPosition), quat_normalize(tuple(db.inputs.parentOrientation)))
    child = (tuple(db.inputs.childPosition), quat_normalize(tuple(db.inputs.childOrientation)))
    db.outputs.position, db.outputs.orientation = compose(parent, child)
