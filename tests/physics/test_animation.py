"""``World.local_transform``/``set_local_transform`` on PyBullet: what the animation nodes move and what they may not."""
import pytest
from pxr import Gf, Usd

from graphflow.physics import create_world
from graphflow.world import WorldError

STAGE = """#usda 1.0
(
    metersPerUnit = 1
    upAxis = "Z"
)
def PhysicsScene "physicsScene"
{
    vector3f physics:gravityDirection = (0, 0, -1)
    float physics:gravityMagnitude = 9.81
}
def Xform "World"
{
    def Xform "Marker"
    {
        float3 xformOp:translate = (1, 2, 3)
        float3 xformOp:scale = (1, 1, 2)
        uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:scale"]
    }
    def Cube "Platform" (
        prepend apiSchemas = ["PhysicsRigidBodyAPI", "PhysicsCollisionAPI"]
    )
    {
        bool physics:kinematicEnabled = 1
        double size = 0.2
        double3 xformOp:translate = (0, 0, 1)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }
    def Xform "Body" (
        prepend apiSchemas = ["PhysicsRigidBodyAPI", "PhysicsMassAPI"]
    )
    {
        float physics:mass = 1
        double3 xformOp:translate = (2, 0, 1)
        uniform token[] xformOpOrder = ["xformOp:translate"]
        def Cube "collider" (
            prepend apiSchemas = ["PhysicsCollisionAPI"]
        )
        {
            double size = 0.1
        }
    }
}
"""
TURNED = (0.0, 0.0, 0.7071067811865476, 0.7071067811865476)    # 90 degrees about Z


@pytest.fixture()
def stage(tmp_path):
    path = tmp_path / "animated.usda"
    path.write_text(STAGE)
    return Usd.Stage.Open(str(path))


def test_a_plain_prim_keeps_its_authored_precision_and_a_new_world_on_the_stage_starts_from_the_file(stage):
    with create_world(stage) as world:
        assert world.local_transform("/World/Marker") == ((1.0, 2.0, 3.0), (0.0, 0.0, 0.0, 1.0), (1.0, 1.0, 2.0))
        world.set_local_transform("/World/Marker", (4.0, 5.0, 6.0), TURNED, (1.0, 1.0, 1.0))
        marker = stage.GetPrimAtPath("/World/Marker")
        assert marker.GetAttribute("xformOp:translate").Get() == Gf.Vec3f(4, 5, 6)        # still float3
        assert world.prim_pose("/World/Marker")[0] == pytest.approx((4.0, 5.0, 6.0))
        assert world.prim_pose("/World/Marker")[1] == pytest.approx(TURNED)
    with create_world(stage) as again:
        assert again.local_transform("/World/Marker")[0] == (1.0, 2.0, 3.0)
    assert stage.GetPrimAtPath("/World/Marker").GetAttribute("xformOp:translate").Get() == Gf.Vec3f(1, 2, 3)


def test_a_kinematic_body_is_placed_and_a_free_body_teleported_at_rest(stage):
    with create_world(stage) as world:
        world.set_local_transform("/World/Platform", (0.5, 0.0, 1.0), TURNED, (1.0, 1.0, 1.0))
        assert world.prim_pose("/World/Platform")[0] == pytest.approx((0.5, 0.0, 1.0), abs=1e-9)
        for _ in range(30):
            world.step()
        assert world.prim_velocity("/World/Body")[0][2] < -1.0                   # falling
        world.set_local_transform("/World/Body", (2.0, 0.0, 3.0), TURNED, (1.0, 1.0, 1.0))
        assert world.prim_velocity("/World/Body") == ((0.0, 0.0, 0.0), (0.0, 0.0, 0.0))
        position, orientation = world.prim_pose("/World/Body")
        assert position == pytest.approx((2.0, 0.0, 3.0), abs=1e-9)
        assert orientation == pytest.approx(TURNED, abs=1e-9)
        assert world.local_transform("/World/Body")[0] == pytest.approx((2.0, 0.0, 3.0), abs=1e-9)


@pytest.mark.parametrize("path, reason", [
    ("/World/Body/collider", "collider of body /World/Body"),
    ("/World", "simulated body /World/Body under it"),
])
def test_what_physics_places_is_refused_by_name(stage, path, reason):
    with create_world(stage) as world:
        with pytest.raises(WorldError, match=reason):
            world.set_local_transform(path, (0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0), (1.0, 1.0, 1.0))


def test_a_body_is_not_rescaled(stage):
    with create_world(stage) as world:
        with pytest.raises(WorldError, match="/World/Body is a simulated body: PyBullet cannot rescale"):
            world.set_local_transform("/World/Body", (2.0, 0.0, 1.0), (0.0, 0.0, 0.0, 1.0), (2.0, 2.0, 2.0))


def test_a_session_layer_override_is_not_silently_hidden(stage):
    with Usd.EditContext(stage, stage.GetSessionLayer()):
        stage.GetPrimAtPath("/World/Marker").GetAttribute("xformOp:translate").Set(Gf.Vec3f(0, 0, 9))
    with create_world(stage) as world:
        with pytest.raises(WorldError, match="xformOp:translate is set on the stage's session layer"):
            world.set_local_transform("/World/Marker", (0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0), (1.0, 1.0, 1.0))
