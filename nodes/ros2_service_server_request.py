"""isaacsim.ros2.bridge.OgnROS2ServiceServerRequest: serve a ROS 2 service: take its requests.

Pairs with OgnROS2ServiceServerResponse through serverHandle. Headless the
requests come from <service>/request on the topic bus (a client node, or a
scripted timeline); Isaac's ``Request:*`` outputs are one JSON object here.
"""
import json

from graphflow.ros2.services import servers_of
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

from ._ros2 import service_inputs, service_of, service_type_of, take_service_part

SPEC = NodeSpec(
    id="isaacsim.ros2.bridge.OgnROS2ServiceServerRequest",
    version=1,
    description=(
        "On execIn, takes the newest request to serviceName not yet taken: request holds its fields as a "
        "JSON object and onReceived fires. serverHandle names this server to the response node."),
    categories=("isaacRos2",),
    ui_name="ROS2 Service Server Request",
    inputs=service_inputs(exec_name="execIn", exec_description="Check for a request") + (
        Attribute("qosProfile", "string", default="", description="QoS profile (the headless bus delivers in order)"),
    ),
    outputs=(
        Attribute("onReceived", "execution", description="Fires when a request was taken"),
        Attribute("serverHandle", "uint64", default=0, description="This server, for the response node"),
        Attribute("request", "string", default="", description="The request's fields, a JSON object"),
    ),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    full_type = service_type_of(db)
    if full_type is None:
        return
    service = service_of(db)
    db.outputs.serverHandle = servers_of(db.world).handle_for(service, full_type)
    request = take_service_part(db, service, full_type, "request")
    if request is None:
        return
    db.outputs.request = json.dumps(request, sort_keys=True)
    db.outputs.onReceived = ExecState.ENABLED
