"""ROS2ServicePrim: Isaac's four prim services on the topic bus, answered from the UR10 cell's world."""
import json

import pytest

from graphflow.physics import create_world
from graphflow.ros2.bus import topic_bus_for
from graphflow.testing import GraphHarness

STAGE = "asset:ur10_pick_place.usda"
PACKAGE = "isaac_ros2_messages/srv/"


def _server(world):
    return GraphHarness({
        "nodes": [{"name": "tick", "type": "omni.graph.action.OnPlaybackTick"},
                  {"name": "prims", "type": "isaacsim.ros2.bridge.ROS2ServicePrim"}],
        "connections": [{"src": "tick.outputs:tick", "dst": "prims.inputs:execIn"}],
    }, world=world)


def _call(world, graph, service, type_name, **request):
    bus = topic_bus_for(world)
    bus.publish_service_part(f"/{service}/request", f"{PACKAGE}{type_name}_Request", request)
    graph.run(1)
    return bus.latest(f"/{service}/response").message


def test_listings_come_from_the_stage():
    with create_world(STAGE) as world:
        graph = _server(world)
        prims = _call(world, graph, "get_prims", "GetPrims", path="/World/ur10/ee_link")
        assert prims["success"] and prims["paths"][0] == "/World/ur10/ee_link"
        assert "/World/ur10/ee_link/SurfaceGripper" in prims["paths"] and len(prims["types"]) == len(prims["paths"])
        assert all(path.startswith("/World/ur10/ee_link") for path in prims["paths"])
        attributes = _call(world, graph, "get_prim_attributes", "GetPrimAttributes", path="/World/Cube")
        listed = dict(zip(attributes["names"], attributes["types"]))
        assert listed["physics:mass"] == "float" and listed["xformOp:translate"] == "double3"
        missing = _call(world, graph, "get_prims", "GetPrims", path="/World/Nothing")
        assert missing == {"paths": [], "types": [], "success": False, "message": "Invalid prim: '/World/Nothing'"}


def test_a_write_acts_on_the_simulation_and_a_read_sees_one_step_of_free_fall():
    with create_world(STAGE) as world:
        graph = _server(world)
        written = _call(world, graph, "set_prim_attribute", "SetPrimAttribute",
                        path="/World/Cube", attribute="xformOp:translate", value="[0.6, 0.3, 0.5]")
        assert written == {"success": True, "message": ""}
        read = _call(world, graph, "get_prim_attribute", "GetPrimAttribute",
                     path="/World/Cube", attribute="xformOp:translate")
        assert read["success"] and read["type"] == "double3"
        x, y, z = json.loads(read["value"])
        # placed at rest at 0.5 m, then one physics step of free fall in n semi-implicit Euler substeps of h:
        # the drop is g h^2 (1 + 2 + ... + n) = g dt^2 (n + 1) / (2 n)
        g, dt, n = 9.81, world.time_step, world.substeps
        assert (x, y) == pytest.approx((0.6, 0.3), abs=1e-6)
        assert z == pytest.approx(0.5 - g * dt * dt * (n + 1) / (2 * n), abs=1e-6)


def test_quaternions_travel_as_w_x_y_z_and_refusals_are_answers():
    with create_world(STAGE) as world:
        from pxr import Gf, Sdf

        turn = world.stage.GetPrimAtPath("/World/Cube").CreateAttribute("test:turn", Sdf.ValueTypeNames.Quatd)
        turn.Set(Gf.Quatd(0.8, Gf.Vec3d(0.6, 0.0, 0.0)))           # real part 0.8: 73.7 degrees about x
        graph = _server(world)
        read = _call(world, graph, "get_prim_attribute", "GetPrimAttribute", path="/World/Cube", attribute="test:turn")
        assert read["type"] == "quatd" and json.loads(read["value"]) == pytest.approx([0.8, 0.6, 0.0, 0.0])
        size = _call(world, graph, "set_prim_attribute", "SetPrimAttribute", path="/World/Cube", attribute="size",
                     value="0.2")
        assert size["success"] is False and "writing size would change what is simulated" in size["message"]
        bad = _call(world, graph, "set_prim_attribute", "SetPrimAttribute", path="/World/Cube",
                    attribute="physics:mass", value="heavy")
        assert bad == {"success": False, "message": "Given value is not a valid JSON: 'heavy'"}
        assert any("Given value is not a valid JSON" in line for line in graph.logs)
