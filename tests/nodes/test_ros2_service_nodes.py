"""The ROS 2 service client and server nodes talking over the topic bus."""
import json

import pytest

from graphflow.executor import GraphRuntimeError
from graphflow.ros2.bus import topic_bus_for
from graphflow.testing import GraphHarness, NodeHarness

CLIENT = "isaacsim.ros2.bridge.OgnROS2ServiceClient"
REQUEST = "isaacsim.ros2.bridge.OgnROS2ServiceServerRequest"
RESPONSE = "isaacsim.ros2.bridge.OgnROS2ServiceServerResponse"
ADD_TWO_INTS = {"messagePackage": "example_interfaces", "messageName": "AddTwoInts", "serviceName": "add"}


def _call_graph():
    """On each tick a client asks add(2, 3); a server in the same graph answers sum = 5."""
    return {"nodes": [
        {"name": "tick", "type": "omni.graph.action.OnTick"},
        {"name": "client", "type": CLIENT,
         "inputs": {**ADD_TWO_INTS, "messageFields": json.dumps({"Request:a": 2, "Request:b": 3})}},
        {"name": "server", "type": REQUEST, "inputs": ADD_TWO_INTS},
        {"name": "answer", "type": RESPONSE,
         "inputs": {"messagePackage": "example_interfaces", "messageName": "AddTwoInts",
                    "messageFields": json.dumps({"Response:sum": 5})}},
        {"name": "served", "type": "omni.graph.action.Counter"}],
        "connections": [{"src": "tick.outputs:tick", "dst": "client.inputs:execIn"},
                        {"src": "client.outputs:execOut", "dst": "server.inputs:execIn"},
                        {"src": "server.outputs:onReceived", "dst": "answer.inputs:onReceived"},
                        {"src": "server.outputs:serverHandle", "dst": "answer.inputs:serverHandle"},
                        {"src": "answer.outputs:execOut", "dst": "served.inputs:execIn"}]}


def test_a_client_call_reaches_the_server_and_its_response_comes_back_on_the_next_call():
    harness = GraphHarness(_call_graph())
    harness.run(1)
    assert json.loads(harness.output("server", "request")) == {"a": 2, "b": 3}
    assert harness.output("served", "count") == 1
    assert harness.output("client", "response") == ""          # the answer came after the client's call
    published = [(m.topic, m.type, m.message) for m in topic_bus_for(harness.world).published]
    assert published == [("/add/request", "example_interfaces/srv/AddTwoInts_Request", {"a": 2, "b": 3}),
                         ("/add/response", "example_interfaces/srv/AddTwoInts_Response", {"sum": 5})]
    harness.run(1)
    assert json.loads(harness.output("client", "response")) == {"sum": 5}
    assert harness.output("served", "count") == 2


def test_a_request_field_the_service_type_lacks_is_an_error_naming_it():
    node = NodeHarness(CLIENT, {**ADD_TWO_INTS, "messageFields": json.dumps({"Request:c": 1})})
    with pytest.raises(GraphRuntimeError, match="AddTwoInts request has no field c"):
        node.compute("execIn")


def test_an_unknown_service_type_is_refused_by_name_and_an_empty_one_only_warns():
    with pytest.raises(GraphRuntimeError, match="unknown ROS 2 service type 'my_pkg/srv/Teleport'"):
        NodeHarness(CLIENT, {"messagePackage": "my_pkg", "messageName": "Teleport"}).compute("execIn")
    idle = NodeHarness(REQUEST)
    assert idle.compute("execIn").fired == set()
    assert any("messagePackage or messageName is empty" in line for line in idle.logs)


def test_a_response_without_a_server_names_the_handle():
    node = NodeHarness(RESPONSE, {"messagePackage": "std_srvs", "messageName": "Trigger", "serverHandle": 7})
    with pytest.raises(GraphRuntimeError, match="serverHandle 7 names no service server"):
        node.compute("onReceived")
