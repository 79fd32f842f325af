"""IsaacReadIMU, IsaacReadContactSensor and IsaacConveyor on a real PyBullet world."""
import pytest

from graphflow.physics import create_world
from graphflow.testing import NodeHarness

CUBE_MASS = 2.0
STAGE = '''#usda 1.0
(
    upAxis = "Z"
    metersPerUnit = 1
)
def Cube "Belt" (
    prepend apiSchemas = ["PhysicsCollisionAPI"]
)
{
    double size = 1
    double3 xformOp:translate = (0, 0, -0.5)
    double3 xformOp:scale = (4, 1, 1)
    uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:scale"]
}
def Cube "Box" (
    prepend apiSchemas = ["PhysicsRigidBodyAPI", "PhysicsCollisionAPI", "PhysicsMassAPI"]
)
{
    double size = 0.1
    float physics:mass = 2
    double3 xformOp:translate = (0, 0, 0.05)
    uniform token[] xformOpOrder = ["xformOp:translate"]
    def Xform "Sensor"
    {
    }
}
def Sphere "Ball" (
    prepend apiSchemas = ["PhysicsRigidBodyAPI", "PhysicsCollisionAPI"]
)
{
    double radius = 0.05
    double3 xformOp:translate = (2, 3, 10)
    uniform token[] xformOpOrder = ["xformOp:translate"]
}
'''


@pytest.fixture()
def world(tmp_path):
    stage = tmp_path / "belt.usda"
    stage.write_text(STAGE)
    with create_world(stage, time_step=1.0 / 240.0) as built:
        yield built


def _settle(world, steps=240):
    for _ in range(steps):
        world.step()


def test_imu_reads_gravity_at_rest_and_nothing_in_free_fall(world):
    resting = NodeHarness("isaacsim.sensors.physics.IsaacReadIMU", {"imuPrim": ["/Box/Sensor"]}, world=world)
    falling = NodeHarness("omni.isaac.isaac_sensor.IsaacReadIMU", {"imuPrim": ["/Ball"]}, world=world)
    _settle(world)
    for _ in range(3):
        rest, fall = resting.tick("execIn"), falling.tick("execIn")
    assert rest.outputs["linAcc"] == pytest.approx((0.0, 0.0, 9.81), abs=0.05)   # the table pushes up with 1 g
    assert fall.outputs["linAcc"] == pytest.approx((0.0, 0.0, 0.0), abs=1e-6)     # free fall: weightless
    assert rest.outputs["angVel"] == pytest.approx((0.0, 0.0, 0.0), abs=1e-3)
    assert rest.fired == {"execOut"}


def test_contact_sensor_reads_the_weight_of_the_resting_box(world):
    sensor = NodeHarness("omni.isaac.isaac_sensor.IsaacReadContactSensor", {"csPrim": ["/Box/Sensor"]}, world=world)
    _settle(world)
    result = sensor.tick("execIn")
    assert result.outputs["inContact"] is True
    assert result.outputs["value"] == pytest.approx(CUBE_MASS * 9.81, rel=0.02)
    airborne = NodeHarness("omni.isaac.isaac_sensor.IsaacReadContactSensor", {"csPrim": ["/Ball"]}, world=world)
    assert airborne.compute("execIn").outputs["inContact"] is False


def test_conveyor_carries_the_box_along_its_direction(world):
    belt = NodeHarness("isaacsim.asset.gen.conveyor.IsaacConveyor",
                       {"conveyorPrim": ["/Belt"], "velocity": 0.2, "direction": (1.0, 0.0, 0.0)}, world=world)
    _settle(world, 60)
    start = world.prim_pose("/Box")[0]
    for _ in range(240):   # one second
        belt.tick("onStep")
    end = world.prim_pose("/Box")[0]
    # the node sets the belt speed after each step; friction then slows the box during the next one
    assert 0.9 * 0.2 - 0.01 < end[0] - start[0] <= 0.2
    assert end[1] - start[1] == pytest.approx(0.0, abs=1e-3)
