"""isaacsim.ros2.bridge.OgnROS2ServiceServerResponse: answer the request its server took.

serverHandle comes from an OgnROS2ServiceServerRequest; the response's fields
come from messageFields (Isaac's ``Response:*`` inputs, gathered on import) and
go out on <service>/response on the topic bus.
"""
from graphflow.ros2.services import servers_of
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

from ._ros2 import send_service_part, service_fields, service_inputs, service_type_of

SPEC = NodeSpec(
    id="isaacsim.ros2.bridge.OgnROS2ServiceServerResponse",
    version=1,
    description=(
        "On onReceived, sends the response (fields from messageFields, a JSON object) of the server "
        "serverHandle names, then fires execOut."),
    categories=("isaacRos2",),
    ui_name="ROS2 Service Server Response",
    inputs=service_inputs(exec_name="onReceived", exec_description="A request was received: respond",
                          with_name=False) + (
        Attribute("serverHandle", "uint64", default=0, description="The server, from the request node"),
        Attribute("messageFields", "string", default="{}", description="Response fields, a JSON object"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires after the response was sent"),
    ),
)


def compute(db):
    if db.inputs.onReceived != ExecState.ENABLED:
        return
    full_type = service_type_of(db)
    if full_type is None:
        return
    server = servers_of(db.world).server(db.inputs.serverHandle)
    if server is None:
        db.error(f"inputs:serverHandle {db.inputs.serverHandle} names no service server: connect it to a "
                 "ROS2 service server request node's serverHandle")
    service, served_type = server
    if served_type != full_type:
        db.error(f"the server of {service} serves {served_type}, this node answers {full_type}")
    send_service_part(db, service, full_type, "response", service_fields(db, full_type, "response"))
    db.outputs.execOut = ExecState.ENABLED
