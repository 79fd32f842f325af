"""The SurfaceGripper node (v3) on graphflow's gantry stage."""
import pytest

from graphflow.gripper import manager_for
from graphflow.physics import create_world
from graphflow.testing import NodeHarness

NODE = "isaacsim.robot.surface_gripper.SurfaceGripper"
GRIPPER = "/World/SurfaceGripper"
CUBE_28 = "/World/Boxes/Cube_28"


@pytest.fixture
def world():
    world = create_world("asset:gantry.usda")
    yield world
    world.close()


def _lower(world, z, frames=240):
    world.set_attribute("/World/Joints/z_joint", "drive:linear:physics:targetPosition", z)
    for _ in range(frames):
        world.step()


def _node(world, **inputs):
    return NodeHarness(NODE, {"SurfaceGripper": GRIPPER, **inputs}, world=world)


def test_close_beats_open_beats_toggle(world):
    node = _node(world)        # the harness resets the world: lower the gantry after creating it
    _lower(world, 0.140)
    result = node.compute("Close", "Open", "Toggle")
    assert result.outputs["status"] == "Closed" and result.outputs["isClosed"] is True
    assert result.fired == {"execOut"}
    assert node.compute("Open", "Toggle").outputs["status"] == "Open"
    for _ in range(10):    # the points' 10-step settling delay survives the open (as in Isaac)
        node.tick()
    assert node.compute("Toggle").outputs["status"] == "Closed"
    assert node.compute("Toggle").outputs["status"] == "Open"


def test_toggle_turns_a_closing_gripper_open(world):
    node = _node(world)                       # 15 cm above the boxes: nothing in reach
    assert node.compute("Toggle").outputs["status"] == "Closing"
    node.tick()
    assert node.compute("Toggle").outputs["status"] == "Open"


def test_disabled_does_nothing(world):
    node = _node(world, enabled=False)
    _lower(world, 0.140)
    result = node.compute("Close")
    assert result.fired == set()
    world.step()
    assert manager_for(world).get_gripper_status(GRIPPER).token == "Open"


def test_grip_events_on_tick_computes(world):
    node = _node(world)
    _lower(world, 0.140)
    first = node.compute("Close")
    assert first.outputs["grippedObjects"] == () and "gripped" not in first.fired   # attaches at the next step
    ticked = node.tick("execIn")
    assert ticked.outputs["grippedObjects"] == (CUBE_28,)
    assert ticked.fired == {"execOut", "gripped"}
    assert node.tick("execIn").fired == {"execOut"}
    opened = node.compute("Open")
    assert opened.fired == {"execOut", "released"} and opened.outputs["grippedObjects"] == ()

    assert node.compute("Close").outputs["status"] == "Closing"     # points still settling after the open
    ticks = [node.tick("execIn") for _ in range(12)]
    gripped_at = [index for index, tick in enumerate(ticks) if "gripped" in tick.fired]
    assert len(gripped_at) == 1 and gripped_at[0] <= 5
    assert ticks[-1].outputs["status"] == "Closed"
    fired = set()
    for _ in range(5):
        world.apply_force(CUBE_28, (0, -500, 0))
        fired |= node.tick("execIn").fired
    assert "broken" in fired and "released" not in fired
    assert node.compute("execIn").outputs["grippedObjects"] == ()


@pytest.mark.parametrize("version", [1, 2])
def test_older_type_versions_load_as_v3(world, version):
    node = NodeHarness(NODE, {"SurfaceGripper": GRIPPER}, world=world, type_version=version)
    assert node.compute("Toggle").outputs["status"] == "Closing"


def test_a_prim_that_is_no_gripper_is_a_clear_error(world):
    node = NodeHarness(NODE, {"SurfaceGripper": "/World/Boxes"}, world=world)
    with pytest.raises(Exception, match="no IsaacSurfaceGripper prim at /World/Boxes"):
        node.compute("Close")
