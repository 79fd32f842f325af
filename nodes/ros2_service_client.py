"""isaacsim.ros2.bridge.OgnROS2ServiceClient: call a ROS 2 service on the topic bus.

As Isaac's client, each execIn sends a request (its fields from messageFields,
Isaac's ``Request:*`` inputs gathered on import) and takes whatever response
has arrived since the last one; execOut fires every call. Headless, a service
is a request and a response topic on the bus (``graphflow.ros2.services``).
"""
import json

from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

from ._ros2 import send_service_part, service_fields, service_inputs, service_of, service_type_of, take_service_part

SPEC = NodeSpec(
    id="isaacsim.ros2.bridge.OgnROS2ServiceClient",
    version=1,
    description=(
        "On execIn, sends a messagePackage/messageSubfolder/messageName request (fields from messageFields, "
        "a JSON object) to serviceName, takes the newest response not yet taken into response (JSON) and "
        "fires execOut. On the bus the request goes to <service>/request, the response comes from "
        "<service>/response."),
    categories=("isaacRos2",),
    ui_name="ROS2 Service Client",
    inputs=service_inputs(exec_name="execIn", exec_description="Send a request") + (
        Attribute("qosProfile", "string", default="", description="QoS profile (the headless bus delivers in order)"),
        Attribute("messageFields", "string", default="{}", description="Request fields, a JSON object"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires after each call"),
        Attribute("response", "string", default="", description="The newest response, a JSON object"),
    ),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    full_type = service_type_of(db)
    if full_type is None:
        return
    service = service_of(db)
    send_service_part(db, service, full_type, "request", service_fields(db, full_type, "request"))
    response = take_service_part(db, service, full_type, "response")
    if response is not None:
        db.outputs.response = json.dumps(response, sort_keys=True)
    db.outputs.execOut = ExecState.ENABLED
