"""What the ROS 2 bridge nodes share: Isaac's common inputs, topic names, the bus, message times.

Not a node type. Every bridge node publishes to or takes from the world's topic
bus (``graphflow.ros2.bus``), never from a ROS installation; the run decides
where the bus leads (a scripted timeline, an MCAP recording, the trace).
"""
from __future__ import annotations

import math

from graphflow.spec import Attribute


def common_inputs(topic: str, *, exec_description: str) -> tuple[Attribute, ...]:
    """Isaac's inputs on every publisher and subscriber: execIn, context, nodeNamespace, qosProfile, queueSize, topicName."""
    return (
        Attribute("execIn", "execution", description=exec_description),
        Attribute("context", "uint64", default=0, description="ROS 2 context handle from ROS2Context (0: the default)"),
        Attribute("nodeNamespace", "string", default="", description="Namespace prefixed to a relative topic name"),
        Attribute("qosProfile", "string", default="",
                  description="QoS profile (JSON, as Isaac); the headless bus always delivers in order, latest wins"),
        Attribute("queueSize", "uint64", default=10, description="Queue depth (the headless bus keeps the latest)"),
        Attribute("topicName", "string", default=topic, description="Topic name, relative to nodeNamespace unless it starts with /"),
    )


def topic_of(db) -> str:
    """The fully qualified topic: /namespace/name for a relative name, the name itself when absolute."""
    name = db.inputs.topicName.strip()
    if not name:
        db.error("inputs:topicName is empty")
    if name.startswith("/"):
        return name
    namespace = db.inputs.nodeNamespace.strip().strip("/")
    return f"/{namespace}/{name}" if namespace else f"/{name}"


def bus(db):
    from graphflow.ros2.bus import topic_bus_for

    return topic_bus_for(db.world)


def publish(db, type_name: str, message: dict) -> None:
    """Publish on the node's topic; a message that does not fit its type is a run-time error naming the node."""
    from graphflow.ros2.messages import MessageError

    try:
        bus(db).publish(topic_of(db), type_name, message)
    except MessageError as error:
        db.error(str(error))


def take(db, type_name: str) -> dict | None:
    """The topic's newest message if this node has not taken it yet, completed to *type_name*; else None."""
    from graphflow.ros2.messages import MessageError, complete

    latest = bus(db).latest(topic_of(db))
    if latest is None or latest.sequence <= db.internal.get("taken", 0):
        return None
    db.internal["taken"] = latest.sequence
    if latest.type is not None and latest.type != type_name:
        db.error(f"topic {latest.topic} carries {latest.type}, this node subscribes to {type_name}")
    try:
        return complete(type_name, latest.message, f"topic {latest.topic}")
    except MessageError as error:
        db.error(str(error))


def header(seconds: float, frame_id: str = "") -> dict:
    from graphflow.ros2.messages import stamp

    return {"stamp": stamp(seconds), "frame_id": frame_id}


def seconds_of(stamp: dict) -> float:
    return stamp["sec"] + stamp["nanosec"] * 1e-9


def vector(values) -> dict:
    x, y, z = (float(v) for v in values)
    return {"x": x, "y": y, "z": z}


def quaternion(values) -> dict:
    """graphflow's (x, y, z, w) as geometry_msgs/Quaternion."""
    x, y, z, w = (float(v) for v in values)
    return {"x": x, "y": y, "z": z, "w": w}


def rotate_into(orientation, value):
    """*value* (a world-frame vector) in the frame of *orientation* (x, y, z, w): q^-1 v q."""
    x, y, z, w = orientation
    norm = math.sqrt(x * x + y * y + z * z + w * w) or 1.0
    x, y, z, w = -x / norm, -y / norm, -z / norm, w / norm   # the inverse rotation
    vx, vy, vz = value
    # v' = v + 2w (q x v) + 2 q x (q x v)
    cx, cy, cz = y * vz - z * vy, z * vx - x * vz, x * vy - y * vx
    ccx, ccy, ccz = y * cz - z * cy, z * cx - x * cz, x * cy - y * cx
    return (vx + 2 * (w * cx + ccx), vy + 2 * (w * cy + ccy), vz + 2 * (w * cz + ccz))
