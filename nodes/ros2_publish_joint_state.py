"""isaacsim.ros2.bridge.ROS2PublishJointState: the measured joint state of an articulation.

Names, positions (rad, m) and velocities come from the world; effort stays
empty because the world interface reports no measured joint efforts (ROS 2
allows empty arrays). targetPrim may be the articulation root or, as in
Isaac, any link of it: the first ancestor the world knows as an articulation.
"""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState
from graphflow.world import WorldError, on_nearest_ancestor

from ._ros2 import common_inputs, header, publish

SPEC = NodeSpec(
    id="isaacsim.ros2.bridge.ROS2PublishJointState",
    version=1,
    aliases=("omni.isaac.ros2_bridge.ROS2PublishJointState",),
    description=(
        "Publishes sensor_msgs/msg/JointState (name, position, velocity of every joint of the articulation "
        "at targetPrim, stamped timeStamp) on topicName (default joint_states)."),
    categories=("isaacRos2",),
    ui_name="ROS2 Publish Joint State",
    inputs=common_inputs("joint_states", exec_description="Publish") + (
        Attribute("targetPrim", "target", description="The articulation (its root or a link)"),
        Attribute("timeStamp", "double", default=0.0, description="Message stamp, s"),
    ),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    if not db.inputs.targetPrim:
        db.error("inputs:targetPrim is not set: no articulation to publish")
    path = articulation_of(db, db.inputs.targetPrim[0])
    publish(db, "sensor_msgs/msg/JointState", {
        "header": header(db.inputs.timeStamp),
        "name": list(db.world.joint_names(path)),
        "position": list(db.world.joint_positions(path)),
        "velocity": list(db.world.joint_velocities(path)),
    })


def articulation_of(db, path: str) -> str:
    """*path* or its nearest ancestor that the world knows as an articulation."""
    cached = db.internal.get("articulation")
    if cached is not None and cached[0] == path:
        return cached[1]
    try:
        candidate = on_nearest_ancestor(path, db.world.joint_names)[0]
    except WorldError as error:
        db.error(f"inputs:targetPrim: {path} is not (in) an articulation ({error})")
    db.internal["articulation"] = (path, candidate)
    return candidate
