"""What the ROS 2 bridge nodes share: Isaac's common inputs, topic names, the bus, message times.

Not a node type. Every bridge node publishes to or takes from the world's topic
bus (``graphflow.ros2.bus``), never from a ROS installation; the run decides
where the bus leads (a scripted timeline, an MCAP recording, the trace).
"""
from __future__ import annotations

import math

from graphflow.node_api import NodeDb
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


def take(db: NodeDb, type_name: str) -> dict | None:
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


def service_inputs(*, exec_name: str, exec_description: str, with_name: bool = True) -> tuple[Attribute, ...]:
    """Isaac's inputs on the service nodes: the exec input, context, nodeNamespace, serviceName, the type."""
    return ((Attribute(exec_name, "execution", description=exec_description),
             Attribute("context", "uint64", default=0, description="ROS 2 context handle (0: the default)"),
             Attribute("nodeNamespace", "string", default="", description="Namespace prefixed to a relative name"))
            + ((Attribute("serviceName", "string", default="/service_name", description="Name of the service"),)
               if with_name else ())
            + (Attribute("messagePackage", "string", default="", description="Package (example_interfaces)"),
               Attribute("messageSubfolder", "string", default="srv", description="Subfolder (srv)"),
               Attribute("messageName", "string", default="", description="Service type name (AddTwoInts)")))


def service_type_of(db: NodeDb) -> str | None:
    """The node's ``pkg/srv/Name``; None (with Isaac's warning) while package or name is empty."""
    from graphflow.ros2.services import MessageError, service_type

    inputs = db.inputs
    if not inputs.messagePackage.strip() or not inputs.messageName.strip():
        db.log("messagePackage or messageName is empty: nothing to call or serve", "warning")
        return None
    try:
        return service_type(inputs.messagePackage, inputs.messageSubfolder, inputs.messageName)
    except MessageError as error:
        db.error(str(error))


def service_of(db) -> str:
    """The fully qualified service name, /namespace/name for a relative one."""
    name = db.inputs.serviceName.strip()
    if not name:
        db.error("inputs:serviceName is empty")
    if name.startswith("/"):
        return name
    namespace = db.inputs.nodeNamespace.strip().strip("/")
    return f"/{namespace}/{name}" if namespace else f"/{name}"


def service_fields(db: NodeDb, full_type: str, part: str) -> dict:
    """messageFields (Isaac's ``Request:a`` / ``Response:sum`` inputs, gathered on import) as a whole *part*."""
    import json

    from graphflow.ros2.services import MessageError, complete

    try:
        fields = json.loads(db.inputs.messageFields or "{}")
    except json.JSONDecodeError as error:
        db.error(f"inputs:messageFields: not JSON ({error.msg})")
    prefix = part.capitalize() + ":"
    if isinstance(fields, dict):
        fields = {key[len(prefix):] if key.startswith(prefix) else key: value for key, value in fields.items()}
    try:
        return complete(full_type, part, fields, "inputs:messageFields")
    except MessageError as error:
        db.error(str(error))


def take_service_part(db: NodeDb, service: str, full_type: str, part: str) -> dict | None:
    """The newest *part* of *service* this node has not taken yet, checked; else None."""
    from graphflow.ros2.services import MessageError, complete, topic

    latest = bus(db).latest(topic(service, part))
    if latest is None or latest.sequence <= db.internal.get("taken", 0):
        return None
    db.internal["taken"] = latest.sequence
    try:
        return complete(full_type, part, latest.message, f"service {service} {part}")
    except MessageError as error:
        db.error(str(error))


def send_service_part(db, service: str, full_type: str, part: str, message: dict) -> None:
    from graphflow.ros2.services import topic

    bus(db).publish_service_part(topic(service, part), f"{full_type}_{part.capitalize()}", message)
