"""isaacsim.sensors.physics nodes on the examples of Isaac Sim's own node tests (isaacsim.sensors.physics.nodes/
python/tests): Isaac's stages written as USD text (a 1 kg cube dropped on a ground plane carrying an IMU or a
contact sensor; a one-joint arm for the effort sensor), simulated at Isaac's 60 Hz, read with Isaac's tolerances
and against statics."""
import pytest

from graphflow.physics import create_world
from graphflow.testing import NodeHarness

G = 9.81
CUBE_ON_GROUND = '''#usda 1.0
(
    upAxis = "Z"
    metersPerUnit = 1
)
def Xform "World"
{
    def Cube "GroundPlane" (prepend apiSchemas = ["PhysicsCollisionAPI"])
    {
        double size = 1
        double3 xformOp:translate = (0, 0, -0.5)
        double3 xformOp:scale = (50, 50, 1)
        uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:scale"]
    }
    def Cube "Cube" (prepend apiSchemas = ["PhysicsRigidBodyAPI", "PhysicsCollisionAPI", "PhysicsMassAPI"])
    {
        double size = 1
        float physics:mass = 1
        double3 xformOp:translate = (0, 0, 1)
        uniform token[] xformOpOrder = ["xformOp:translate"]
        def IsaacImuSensor "imu_sensor"
        {
            int linearAccelerationFilterWidth = 10
        }
        def IsaacContactSensor "contact_sensor"
        {
            float2 threshold = (0, 10000000)
        }
    }
}
'''


@pytest.fixture()
def cube(tmp_path):
    """Isaac's scene: a 1 m, 1 kg cube whose centre starts 1 m above the ground (it drops 0.5 m and settles)."""
    stage = tmp_path / "cube.usda"
    stage.write_text(CUBE_ON_GROUND)
    with create_world(stage, time_step=1.0 / 60.0) as world:
        yield world


def _read(node, seconds):
    for _ in range(round(seconds * 60)):
        outputs = node.tick("execIn").outputs
    return outputs


@pytest.mark.parametrize("latest", [False, True])
def test_imu_on_the_settled_cube_reads_gravity(cube, latest):
    """Isaac's test_valid_imu_sensor_ogn (and _use_latest_data): after 1.5 s, linAcc (0, 0, 9.81) within 0.01,
    angVel within 0.2 of 0, a unit orientation, a sensor time not 0."""
    node = NodeHarness("isaacsim.sensors.physics.IsaacReadIMU",
                       {"imuPrim": ["/World/Cube/imu_sensor"], "useLatestData": latest}, world=cube)
    outputs = _read(node, 1.5)
    assert outputs["linAcc"] == pytest.approx((0.0, 0.0, G), abs=0.01)
    assert outputs["angVel"] == pytest.approx((0.0, 0.0, 0.0), abs=0.2)
    assert sum(c * c for c in outputs["orientation"]) == pytest.approx(1.0, abs=1e-4)
    assert outputs["sensorTime"] == pytest.approx(1.5, abs=1e-6)


def test_imu_without_gravity_reads_nothing_at_rest(cube):
    """Isaac's test_read_gravity_toggle: readGravity false, after 1 s linAcc z within 0.01 of 0."""
    node = NodeHarness("isaacsim.sensors.physics.IsaacReadIMU",
                       {"imuPrim": ["/World/Cube/imu_sensor"], "readGravity": False}, world=cube)
    assert _read(node, 1.0)["linAcc"] == pytest.approx((0.0, 0.0, 0.0), abs=0.01)


def test_imu_recovers_after_a_stop_and_play(cube):
    """Isaac's stop/play lifecycle: after a reset of the run (world and graph) the IMU reads gravity again."""
    node = NodeHarness("isaacsim.sensors.physics.IsaacReadIMU", {"imuPrim": ["/World/Cube/imu_sensor"]}, world=cube)
    assert _read(node, 1.5)["linAcc"][2] == pytest.approx(G, abs=0.01)
    cube.reset()
    node.reset()
    again = _read(node, 1.5)
    assert again["linAcc"][2] == pytest.approx(G, abs=0.01) and again["sensorTime"] != 0.0


def test_contact_sensor_on_the_settled_cube_reads_its_weight(cube):
    """Isaac's test_valid_contact_sensor_ogn: after 1 s the force is not 0 and the time not 0; statics: the
    ground carries the cube's weight, m g = 9.81 N; it recovers after a stop and play."""
    node = NodeHarness("isaacsim.sensors.physics.IsaacReadContactSensor",
                       {"csPrim": ["/World/Cube/contact_sensor"]}, world=cube)
    outputs = _read(node, 1.0 + 1 / 60)
    assert outputs["inContact"] is True and outputs["sensorTime"] != 0.0
    assert outputs["value"] == pytest.approx(1.0 * G, rel=0.02)
    cube.reset()
    node.reset()
    assert _read(node, 1.0 + 1 / 60)["value"] == pytest.approx(1.0 * G, rel=0.02)


ARM = '''#usda 1.0
(
    upAxis = "Z"
    metersPerUnit = 1
)
def Xform "Articulation" (prepend apiSchemas = ["PhysicsArticulationRootAPI"])
{
    def Cube "Base" (prepend apiSchemas = ["PhysicsRigidBodyAPI", "PhysicsMassAPI"])
    {
        double size = 0.2
        float physics:mass = 5
        double3 xformOp:translate = (0, 0, 1)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }
    def PhysicsFixedJoint "RootJoint"
    {
        rel physics:body1 = </Articulation/Base>
        point3f physics:localPos0 = (0, 0, 1)
    }
    def Xform "Arm"
    {
        def Cube "Link" (prepend apiSchemas = ["PhysicsRigidBodyAPI", "PhysicsMassAPI"])
        {
            double size = 0.1
            float physics:mass = 1
            double3 xformOp:translate = (0.5, 0, 1)
            uniform token[] xformOpOrder = ["xformOp:translate"]
        }
        def PhysicsRevoluteJoint "RevoluteJoint" (prepend apiSchemas = ["PhysicsDriveAPI:angular"])
        {
            uniform token physics:axis = "Y"
            rel physics:body0 = </Articulation/Base>
            rel physics:body1 = </Articulation/Arm/Link>
            point3f physics:localPos0 = (0, 0, 0)
            point3f physics:localPos1 = (-0.5, 0, 0)
            float drive:angular:physics:stiffness = 1000
            float drive:angular:physics:damping = 50
            float drive:angular:physics:targetPosition = 0
        }
    }
}
'''


@pytest.mark.parametrize("enabled", [True, False])
def test_effort_sensor_reads_the_torque_holding_the_arm(tmp_path, enabled):
    """Isaac's test_valid_effort_sensor_ogn (and its deprecated enabled=False, which is ignored): a revolute joint
    about y carrying an arm reads a non-zero effort and time. Statics: the drive holds a 1 kg link 0.5 m out,
    |effort| = m g r = 4.905 N m once at rest."""
    stage = tmp_path / "arm.usda"
    stage.write_text(ARM)
    with create_world(stage, time_step=1.0 / 60.0) as world:
        node = NodeHarness("isaacsim.sensors.physics.IsaacReadEffortSensor",
                           {"prim": ["/Articulation/Arm/RevoluteJoint"], "enabled": enabled}, world=world)
        outputs = _read(node, 2.0)
    assert outputs["sensorTime"] != 0.0
    assert abs(outputs["value"]) == pytest.approx(1.0 * G * 0.5, rel=0.01)


def test_an_imu_off_the_centre_of_a_spinning_body_reads_the_centripetal_acceleration(tmp_path):
    """An IsaacImuSensor prim 0.5 m along x of a free (undamped) cube spinning at 2 rad/s about z: its own
    translate places it (usd-core does not know the type, graphflow composes its xformOps all the same), so it
    reads w^2 r = 2 m/s^2 towards the centre, -x in its frame (to the half-step turn of a one-step difference,
    w dt / 2 = 1/60 rad), and nothing of gravity in free fall."""
    stage = tmp_path / "spin.usda"
    stage.write_text('''#usda 1.0
(
    upAxis = "Z"
    metersPerUnit = 1
)
def Cube "Cube" (prepend apiSchemas = ["PhysicsRigidBodyAPI", "PhysicsMassAPI"])
{
    double size = 1
    float physics:mass = 1
    vector3f physics:angularVelocity = (0, 0, 114.59155902616465)
    float physxRigidBody:angularDamping = 0
    double3 xformOp:translate = (0, 0, 10)
    uniform token[] xformOpOrder = ["xformOp:translate"]
    def IsaacImuSensor "imu"
    {
        double3 xformOp:translate = (0.5, 0, 0)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }
}
''')
    with create_world(stage, time_step=1.0 / 60.0) as world:
        node = NodeHarness("isaacsim.sensors.physics.IsaacReadIMU", {"imuPrim": ["/Cube/imu"]}, world=world)
        outputs = _read(node, 0.5)
        position = world.prim_pose("/Cube/imu")[0]
        centre = world.prim_pose("/Cube")[0]
    assert ((position[0] - centre[0]) ** 2 + (position[1] - centre[1]) ** 2) ** 0.5 == pytest.approx(0.5, abs=1e-9)
    assert outputs["linAcc"] == pytest.approx((-(2.0 ** 2) * 0.5, 0.0, 0.0), abs=0.05)
    assert outputs["angVel"] == pytest.approx((0.0, 0.0, 2.0), abs=1e-6)


def test_joint_state_sensor_reads_the_articulation():
    """Isaac's test_valid_joint_state_sensor_ogn (its SimpleArticulation; here the packaged Panda): after 0.5 s
    one name per DOF and arrays of that length, DOF types (0 revolute, 1 prismatic: the Panda's 7 arm joints and
    2 fingers), a positive metres-per-unit and time; the values are the articulation's own. Without a prim
    Isaac outputs nothing; graphflow refuses the run with a one-line error instead."""
    import warnings
    from pathlib import Path

    from graphflow.executor import GraphRuntimeError

    panda = Path(__file__).resolve().parents[2] / "graphflow" / "assets" / "panda.usda"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        world = create_world(str(panda), time_step=1.0 / 60.0)
    with world:
        outputs = _read(NodeHarness("isaacsim.sensors.physics.IsaacReadJointState", {"prim": ["/panda"]}, world=world),
                        0.5)
        positions, velocities = world.joint_positions("/panda"), world.joint_velocities("/panda")
        with pytest.raises(GraphRuntimeError):
            NodeHarness("isaacsim.sensors.physics.IsaacReadJointState", world=world).compute("execIn")
    names = outputs["jointNames"]
    assert len(names) == 9 and all(len(outputs[key]) == 9 for key in (
        "jointPositions", "jointVelocities", "jointEfforts", "jointDofTypes"))
    assert outputs["jointDofTypes"] == (0,) * 7 + (1, 1)
    assert outputs["sensorTime"] > 0.0 and outputs["stageMetersPerUnit"] > 0.0
    assert outputs["jointPositions"] == pytest.approx(positions) and outputs["jointVelocities"] == pytest.approx(velocities)
