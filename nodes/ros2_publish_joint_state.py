"""isaacsim.ros2.bridge.ROS2PublishJointState: the measured joint state of an articulation.

Two ways in, as in Isaac Sim 6: the arrays of an Isaac Read Joint State node
(jointNames ... stageMetersPerUnit, preferred: published as given, prismatic
values and efforts converted with Isaac's own stage-unit factors, rounded to
1e-4 as Isaac rounds them, stamped sensorTime when it is positive), or the
older targetPrim: names, positions (rad, m) and velocities from the world;
effort stays empty (ROS 2 allows empty arrays). targetPrim may be the
articulation root or, as in Isaac, any link of it: the first ancestor the
world knows as an articulation.
"""
import math

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
        Attribute("jointNames", "token[]", description="Joint names from Isaac Read Joint State (instead of targetPrim)"),
        Attribute("jointPositions", "double[]", description="Joint positions from Isaac Read Joint State, rad or m"),
        Attribute("jointVelocities", "double[]", description="Joint velocities from Isaac Read Joint State"),
        Attribute("jointEfforts", "double[]", description="Joint efforts from Isaac Read Joint State, N m or N"),
        Attribute("jointDofTypes", "uchar[]", description="Per DOF from Isaac Read Joint State: 0 revolute, 1 prismatic"),
        Attribute("stageMetersPerUnit", "float", default=0.0, description="Stage metres per unit of the arrays"),
        Attribute("sensorTime", "float", default=0.0, description="The reading's time, s: the stamp when positive"),
    ),
)
SENSOR_ARRAYS = ("jointNames", "jointPositions", "jointVelocities", "jointEfforts", "jointDofTypes")


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    if any(len(getattr(db.inputs, name) or ()) for name in SENSOR_ARRAYS):
        publish_reading(db)
        return
    if not db.inputs.targetPrim:
        db.error("inputs:targetPrim is not set and no Isaac Read Joint State arrays are connected: nothing to publish")
    path = articulation_of(db, db.inputs.targetPrim[0])
    publish(db, "sensor_msgs/msg/JointState", {
        "header": header(db.inputs.timeStamp),
        "name": list(db.world.joint_names(path)),
        "position": list(db.world.joint_positions(path)),
        "velocity": list(db.world.joint_velocities(path)),
    })


def publish_reading(db) -> None:
    """The JointState of an Isaac Read Joint State reading, converted as Isaac's message writer converts it."""
    names, positions, velocities, efforts, kinds = (tuple(getattr(db.inputs, name) or ()) for name in SENSOR_ARRAYS)
    if not names or any(len(values) != len(names) for values in (positions, velocities, efforts, kinds)):
        db.error(f"inputs:jointNames ... jointDofTypes must all have one entry per joint (got {len(names)} names, "
                 f"{len(positions)} positions, {len(velocities)} velocities, {len(efforts)} efforts, "
                 f"{len(kinds)} DOF types)")
    meters_per_unit = float(db.inputs.stageMetersPerUnit)
    if not (meters_per_unit > 0.0 and math.isfinite(meters_per_unit)):
        db.error(f"inputs:stageMetersPerUnit must be a positive finite value, got {meters_per_unit}")
    units = 1.0 / meters_per_unit
    position, velocity, effort = [], [], []
    for q, v, e, kind in zip(positions, velocities, efforts, kinds):
        linear = int(kind) == 1
        position.append(_rounded(q * units if linear else q))
        velocity.append(_rounded(v * units if linear else v))
        effort.append(_rounded(e * units if linear else e * units * units))
    stamp = float(db.inputs.sensorTime) if db.inputs.sensorTime > 0.0 else db.inputs.timeStamp
    publish(db, "sensor_msgs/msg/JointState", {"header": header(stamp), "name": [str(n) for n in names],
                                                "position": position, "velocity": velocity, "effort": effort})


def _rounded(value: float) -> float:
    return round(float(value) * 10000.0) / 10000.0


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
