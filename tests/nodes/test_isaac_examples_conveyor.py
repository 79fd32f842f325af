"""isaacsim.asset.gen.conveyor.IsaacConveyor on the example of Isaac Sim's own test (test_conveyor.py): a
kinematic 1 m cube is the belt, a 0.1 m cube lies on it, the belt runs at 0.1 m/s; after 1 s the small cube
moves with the belt within Isaac's 0.01 m/s, along x and along y."""
import pytest

from graphflow.physics import create_world
from graphflow.testing import NodeHarness

STAGE = '''#usda 1.0
(
    upAxis = "Z"
    metersPerUnit = 1
)
def PhysicsScene "physics"
{
    vector3f physics:gravityDirection = (0, 0, -1)
    float physics:gravityMagnitude = 9.81
}
def Cube "cube" (prepend apiSchemas = ["PhysicsRigidBodyAPI", "PhysicsCollisionAPI"])
{
    double size = 1
    bool physics:kinematicEnabled = 1
    double3 xformOp:translate = (0, 0, 0)
    uniform token[] xformOpOrder = ["xformOp:translate"]
}
def Cube "cube2" (prepend apiSchemas = ["PhysicsRigidBodyAPI", "PhysicsCollisionAPI"])
{
    double size = 0.1
    double3 xformOp:translate = (0, 0, 0.55)
    uniform token[] xformOpOrder = ["xformOp:translate"]
}
'''


@pytest.mark.parametrize("direction", [(1.0, 0.0, 0.0), (0.0, 1.0, 0.0)])
def test_a_cube_on_the_belt_moves_with_it(tmp_path, direction):
    stage = tmp_path / "conveyor.usda"
    stage.write_text(STAGE)
    with create_world(stage, time_step=1.0 / 60.0) as world:
        belt = NodeHarness("isaacsim.asset.gen.conveyor.IsaacConveyor",
                           {"conveyorPrim": ["/cube"], "velocity": 0.1, "direction": direction}, world=world)
        for _ in range(60):
            belt.tick("onStep")
        velocity = world.prim_velocity("/cube2")[0]
        resting = world.prim_pose("/cube2")[0][2]
    assert velocity == pytest.approx(tuple(0.1 * d for d in direction), abs=1e-2)
    assert resting == pytest.approx(0.55, abs=1e-2)   # still on the belt's top face
