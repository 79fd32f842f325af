"""graphflow.ReadJointState: joint names, positions and velocities of an articulation."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.world import WorldError

SPEC = NodeSpec(
    id="graphflow.ReadJointState",
    version=1,
    description=(
        "The movable joints of an articulation (named by its root or any of its prims), in DOF order: "
        "names, positions (rad or m) and velocities (rad/s or m/s)."),
    categories=("isaacCore",),
    ui_name="Read Joint State",
    inputs=(
        Attribute("prim", "target", description="The articulation root, or any body or joint prim of it"),
    ),
    outputs=(
        Attribute("jointNames", "token[]", description="Joint prim names in DOF order"),
        Attribute("positions", "double[]", description="Joint positions, rad or m"),
        Attribute("velocities", "double[]", description="Joint velocities, rad/s or m/s"),
    ),
)


def compute(db):
    if not db.inputs.prim:
        db.error("no prim given")
    path = db.inputs.prim[0]
    try:
        db.outputs.jointNames = tuple(db.world.joint_names(path))
        db.outputs.positions = tuple(float(q) for q in db.world.joint_positions(path))
        db.outputs.velocities = tuple(float(v) for v in db.world.joint_velocities(path))
    except WorldError as error:
        db.error(str(error))
