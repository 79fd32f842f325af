"""The surface-gripper manager on the fake backend: it needs nothing of a world but the declared interface."""
import pytest

pytest.importorskip("pxr")

from pxr import Gf, Sdf, Usd, UsdGeom, UsdPhysics  # noqa: E402

from graphflow.gripper import (  # noqa: E402
    apply_attachment_point_api,
    create_surface_gripper,
    manager_for,
)
from graphflow.testing.fake_world import FakeWorld  # noqa: E402

BODY = "/World/Gripper"
JOINT = "/World/Gripper/D6"


@pytest.fixture
def world():
    """A gripper box whose D6 joint sits 5 cm under its centre, pointing down; a box 5 mm under the joint."""
    stage = Usd.Stage.CreateInMemory()
    UsdGeom.Xform.Define(stage, BODY)
    joint = UsdPhysics.Joint.Define(stage, JOINT)
    joint.CreateBody0Rel().SetTargets([Sdf.Path(BODY)])
    joint.CreateLocalPos0Attr(Gf.Vec3f(0.0, 0.0, -0.05))
    joint.CreateLocalRot0Attr(Gf.Quatf(0.0, 1.0, 0.0, 0.0))           # half a turn about X: +Z points down
    joint.CreateExcludeFromArticulationAttr(True)
    apply_attachment_point_api(joint.GetPrim(), forward_axis="Z")
    gripper = create_surface_gripper(stage, "/World")
    gripper.GetRelationship("isaac:attachmentPoints").SetTargets([Sdf.Path(JOINT)])
    world = FakeWorld(stage=stage)
    world.add_box(BODY, (0.0, 0.0, 1.0), (0.04, 0.04, 0.04))
    world.add_box("/World/Box", (0.0, 0.0, 0.90), (0.05, 0.05, 0.045))  # top at 0.945: 5 mm under the joint
    yield world, gripper.GetPath().pathString


def test_close_holds_the_box_and_switches_its_gravity_off_until_open(world):
    world, gripper = world
    manager = manager_for(world)
    manager.set_gravity_disabled_while_held(gripper, True)
    assert manager.close_gripper(gripper)
    world.step()                                      # the attach queued by the close runs in this update
    assert manager.get_gripped_objects(gripper) == ["/World/Box"]
    assert world.attachments.held() == ["/World/Box"] and not world.gravity_enabled("/World/Box")
    manager.open_gripper(gripper)
    world.step()
    assert world.attachments.holds == {} and world.gravity_enabled("/World/Box")


def test_reset_drops_holds_and_returns_to_open(world):
    world, gripper = world
    manager = manager_for(world)
    manager.close_gripper(gripper)
    world.step()
    world.reset()
    assert world.attachments.holds == {} and manager.get_gripper_status(gripper).token == "Open"
