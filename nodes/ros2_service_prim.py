"""isaacsim.ros2.bridge.ROS2ServicePrim: Isaac's prim services, served on the topic bus.

Four services (isaac_ros2_messages/srv/*), each a request and a response
topic (``graphflow.ros2.services``): GetPrims lists the prims under a path
with their type names, GetPrimAttributes a prim's attributes (names, display
names, USD types), GetPrimAttribute reads one attribute as JSON and
SetPrimAttribute writes one from JSON. On each execIn every service answers its
newest request not yet answered; execOut fires when one did.

Reads and writes go through the world, so a read gives the simulated value
(a body's pose, a joint's drive target) and a write acts on the simulation;
what the world simulates (xformOp:translate / orient of a free body,
physics:mass, velocities, drive targets) is written to the simulation, any other
attribute to the run's stage-edit layer; a write that would change what is
simulated (a collider's size) is answered success false with the reason:
graphflow composes physics once, at load. Quaternions travel as Isaac's
JSON, [w, x, y, z]. A failed request is an answer (success false, message),
never a run failure, as in Isaac.
"""
import json

from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState
from graphflow.world import WorldError

from ._ros2 import bus

PACKAGE = "isaac_ros2_messages/srv/"

SPEC = NodeSpec(
    id="isaacsim.ros2.bridge.ROS2ServicePrim",
    version=1,
    aliases=("omni.isaac.ros2_bridge.ROS2ServicePrim",),
    description=(
        "On execIn, answers the newest request to each of Isaac's prim services (GetPrims, GetPrimAttributes, "
        "GetPrimAttribute, SetPrimAttribute; isaac_ros2_messages) from the world: listings from the stage, "
        "attribute values as JSON (quaternions [w, x, y, z]) from the simulation; writes simulated attributes "
        "to the simulation and others to the run's stage-edit layer, a write that would change what is simulated "
        "answered success false. execOut fires when a request was answered."),
    categories=("isaacRos2:service",),
    ui_name="ROS2 Service Prim",
    inputs=(
        Attribute("execIn", "execution", description="Answer pending requests"),
        Attribute("context", "uint64", default=0, description="ROS 2 context handle (0: the default)"),
        Attribute("nodeNamespace", "string", default="", description="Namespace prefixed to relative service names"),
        Attribute("primsServiceName", "string", default="get_prims",
                  description="Service listing the prims under a path"),
        Attribute("getAttributesServiceName", "string", default="get_prim_attributes",
                  description="Service listing a prim's attributes"),
        Attribute("getAttributeServiceName", "string", default="get_prim_attribute",
                  description="Service reading one attribute"),
        Attribute("setAttributeServiceName", "string", default="set_prim_attribute",
                  description="Service writing one attribute"),
        Attribute("qosProfile", "string", default="", description="QoS profile (the headless bus delivers in order)"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires when a request was answered"),
    ),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    from graphflow.ros2.services import MessageError, complete, topic

    answered = False
    for name_input, type_name, answer in SERVICES:
        service = _service_name(db, name_input)
        latest = bus(db).latest(topic(service, "request"))
        if latest is None or latest.sequence <= db.internal.get(service, 0):
            continue
        db.internal[service] = latest.sequence
        full_type = PACKAGE + type_name
        try:
            request = complete(full_type, "request", latest.message, f"service {service} request")
        except MessageError as error:
            db.error(str(error))
        response = answer(db.world, request)
        if not response["success"]:
            db.log(f"{service}: {response['message']}", "warning")
        bus(db).publish_service_part(topic(service, "response"), f"{full_type}_Response",
                                     complete(full_type, "response", response, f"service {service} response"))
        answered = True
    if answered:
        db.outputs.execOut = ExecState.ENABLED


def _service_name(db, name_input: str) -> str:
    name = getattr(db.inputs, name_input).strip()
    if not name:
        db.error(f"inputs:{name_input} is empty")
    if name.startswith("/"):
        return name
    namespace = db.inputs.nodeNamespace.strip().strip("/")
    return f"/{namespace}/{name}" if namespace else f"/{name}"


def _prim(world, path: str):
    """(prim, None) or (None, the reason Isaac gives)."""
    if world.stage is None:
        return None, "Unable to query the scene"
    prim = world.stage.GetPrimAtPath(path) if path.startswith("/") else None
    return (prim, None) if prim else (None, f"Invalid prim: '{path}'")


def _failure(message: str, **empty) -> dict:
    return {**empty, "success": False, "message": message}


def get_prims(world, request) -> dict:
    from pxr import Usd

    prim, problem = _prim(world, request["path"])
    if problem:
        return _failure(problem)
    prims = list(Usd.PrimRange(prim))
    return {"paths": [str(p.GetPath()) for p in prims], "types": [str(p.GetTypeName()) for p in prims],
            "success": True, "message": ""}


def get_prim_attributes(world, request) -> dict:
    prim, problem = _prim(world, request["path"])
    if problem:
        return _failure(problem)
    attributes = prim.GetAttributes()
    return {"names": [a.GetName() for a in attributes], "displays": [a.GetDisplayName() for a in attributes],
            "types": [str(a.GetTypeName()) for a in attributes], "success": True, "message": ""}


def get_prim_attribute(world, request) -> dict:
    path, name = request["path"], request["attribute"]
    prim, problem = _prim(world, path)
    if problem:
        return _failure(problem)
    if not prim.HasAttribute(name):
        return _failure(f"Prim has no attribute: '{name}'")
    type_name = str(prim.GetAttribute(name).GetTypeName())
    try:
        value = world.get_attribute(path, name)
    except WorldError as error:
        return _failure(str(error), type=type_name)
    if type_name.startswith("quat"):
        value = (value[3], *value[:3])          # the world's (x, y, z, w) as Isaac's JSON [w, x, y, z]
    return {"value": json.dumps(value), "type": type_name, "success": True, "message": ""}


def set_prim_attribute(world, request) -> dict:
    path, name = request["path"], request["attribute"]
    prim, problem = _prim(world, path)
    if problem:
        return _failure(problem)
    if not prim.HasAttribute(name):
        return _failure(f"Prim has no attribute: '{name}'")
    try:
        value = json.loads(request["value"])
    except json.JSONDecodeError:
        return _failure(f"Given value is not a valid JSON: '{request['value']}'")
    if str(prim.GetAttribute(name).GetTypeName()).startswith("quat"):
        if not isinstance(value, list) or len(value) != 4:
            return _failure(f"{name} is a quaternion: expected [w, x, y, z], got {request['value']}")
        value = (*value[1:], value[0])
    try:
        world.set_attribute(path, name, value)
    except (WorldError, TypeError, ValueError) as error:
        return _failure(str(error))
    return {"success": True, "message": ""}


SERVICES = (
    ("primsServiceName", "GetPrims", get_prims),
    ("getAttributesServiceName", "GetPrimAttributes", get_prim_attributes),
    ("getAttributeServiceName", "GetPrimAttribute", get_prim_attribute),
    ("setAttributeServiceName", "SetPrimAttribute", set_prim_attribute),
)
