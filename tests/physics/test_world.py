"""PyBulletWorld behaviour: clock, reset, determinism, queries and actions, errors."""
import hashlib
import math
import struct

import pytest

from graphflow.physics import create_world
from graphflow.usd.resolver import resolve_stage
from graphflow.world import World, WorldError

PICK_PLACE = "asset:ur10_pick_place.usda"


def trajectory_digest(world, steps):
    """SHA-256 over every dynamic body's pose and the arm's joint state after each step."""
    digest = hashlib.sha256()
    bodies = sorted(p for p, h in world.scene.bodies.items() if h.kind == "dynamic")
    for _ in range(steps):
        world.step()
        for path in bodies:
            position, orientation = world.prim_pose(path)
            digest.update(struct.pack("7d", *position, *orientation))
        digest.update(struct.pack("6d", *world.joint_positions("/World/ur10")))
    return digest.hexdigest()


def test_world_follows_the_world_protocol_and_isaac_default_rate():
    with create_world() as world:
        assert isinstance(world, World)
        assert world.time_step == pytest.approx(1.0 / 60.0)
        world.step()
        world.step()
        assert (world.step_index, world.time) == (2, pytest.approx(2.0 / 60.0))


def test_free_fall_matches_gravity(tmp_path):
    stage = tmp_path / "ball.usda"
    stage.write_text('''#usda 1.0
(
    upAxis = "Z"
    metersPerUnit = 1
)
def Sphere "Ball" (
    prepend apiSchemas = ["PhysicsRigidBodyAPI", "PhysicsCollisionAPI"]
)
{
    double radius = 0.05
    double3 xformOp:translate = (0, 0, 10)
    uniform token[] xformOpOrder = ["xformOp:translate"]
}
''')
    with create_world(stage, time_step=1.0 / 240.0) as world:
        for _ in range(240):
            world.step()
        height = world.prim_pose("/Ball")[0][2]
        velocity = world.prim_velocity("/Ball")[0][2]
    # semi-implicit Euler: z = 10 - g dt^2 n (n + 1) / 2, v = -g t; angular damping only
    assert height == pytest.approx(10.0 - 9.81 * (1 / 240) ** 2 * 240 * 241 / 2, abs=1e-6)
    assert velocity == pytest.approx(-9.81, abs=1e-6)


def test_reset_replays_the_same_trajectory_bit_for_bit():
    with create_world(PICK_PLACE) as world:
        world.set_joint_targets("/World/ur10", range(6), positions=[0.4, -1.2, -1.6, -1.9, 1.6, 0.3])
        world.apply_force("/World/Cube", (0.5, 0.0, 0.0))
        first = trajectory_digest(world, 240)
        world.reset()
        assert (world.step_index, world.time) == (0, 0.0)
        world.set_joint_targets("/World/ur10", range(6), positions=[0.4, -1.2, -1.6, -1.9, 1.6, 0.3])
        world.apply_force("/World/Cube", (0.5, 0.0, 0.0))
        assert trajectory_digest(world, 240) == first
    with create_world(PICK_PLACE) as fresh:
        fresh.set_joint_targets("/World/ur10", range(6), positions=[0.4, -1.2, -1.6, -1.9, 1.6, 0.3])
        fresh.apply_force("/World/Cube", (0.5, 0.0, 0.0))
        assert trajectory_digest(fresh, 240) == first


def test_reset_restores_targets_and_resets_services_in_order():
    calls = []

    class Service:
        def __init__(self, name):
            self.name = name

        def after_step(self, dt):
            calls.append((self.name, dt))

        def reset(self):
            calls.append((self.name, "reset"))

    class Other(Service):
        pass

    with create_world(PICK_PLACE) as world:
        world.services.add(Service("first"))
        world.services.add(Other("second"))
        world.set_attribute("/World/ur10/base_link/shoulder_pan_joint", "drive:angular:physics:targetPosition", 10.0)
        world.step()
        world.reset()
        assert world.get_attribute("/World/ur10/base_link/shoulder_pan_joint",
                                   "drive:angular:physics:targetPosition") == pytest.approx(-90.0)
    assert calls == [("first", pytest.approx(1 / 60)), ("second", pytest.approx(1 / 60)),
                     ("first", "reset"), ("second", "reset")]


def test_two_worlds_in_one_process_are_independent():
    with create_world(PICK_PLACE) as moving, create_world(PICK_PLACE) as still:
        moving.set_joint_targets("/World/ur10", [0], positions=[0.0])
        for _ in range(60):
            moving.step()
            still.step()
        assert moving.joint_positions("/World/ur10")[0] == pytest.approx(0.0, abs=1e-4)
        assert still.joint_positions("/World/ur10")[0] == pytest.approx(-math.pi / 2, abs=1e-9)


def test_pause_stops_the_clock_and_stop_resets():
    with create_world(PICK_PLACE) as world:
        world.step()
        world.pause()
        world.step()
        assert world.step_index == 1
        world.play()
        world.step()
        assert world.step_index == 2
        world.stop()
        assert world.step_index == 0 and not world.playing


def test_raycast_hits_the_cube_top_and_names_the_prim():
    with create_world(PICK_PLACE) as world:
        hit = world.raycast((0.3, 0.3, 0.5), (0, 0, -1), 1.0)
        assert hit.prim_path == "/World/Cube"
        assert hit.position[2] == pytest.approx(0.0515, abs=1e-3)
        assert hit.distance == pytest.approx(0.5 - 0.0515, abs=1e-3)
        assert hit.normal == pytest.approx((0, 0, 1), abs=1e-3)
        hits = world.raycast_batch([(0.3, 0.3, 0.5), (2.0, 2.0, 0.5)], [(0, 0, -1), (0, 0, 1)], 1.0)
        assert hits[0].prim_path == "/World/Cube" and hits[1] is None


def test_contacts_of_a_resting_cube_carry_its_weight():
    with create_world(PICK_PLACE) as world:
        for _ in range(30):
            world.step()
        contacts = world.contacts("/World/Cube")
        assert {c.other_prim for c in contacts} == {"/World/GroundPlane"}
        assert sum(c.normal_force for c in contacts) == pytest.approx(0.0515 ** 3 * 1000 * 9.81, rel=0.05)


def test_apply_force_pushes_for_one_step_only():
    with create_world() as world, create_world(PICK_PLACE) as stage_world:
        del world
        cube = "/World/Cube"
        mass = stage_world.get_attribute(cube, "physics:mass")
        stage_world.set_gravity_enabled(cube, False)
        stage_world.apply_force(cube, (0.0, 0.0, 10.0))
        stage_world.step()
        stage_world.step()
        velocity = stage_world.get_attribute(cube, "physics:velocity")[2]
        assert velocity == pytest.approx(10.0 / mass / 60.0, rel=0.02)


def test_body_attributes_read_and_write():
    with create_world(PICK_PLACE) as world:
        cube = "/World/Cube"
        assert world.get_attribute(cube, "xformOp:translate") == pytest.approx((0.3, 0.3, 0.02575), abs=1e-6)
        world.set_attribute(cube, "xformOp:translate", (0.5, -0.2, 0.3))
        assert world.prim_pose(cube)[0] == pytest.approx((0.5, -0.2, 0.3), abs=1e-9)
        world.set_attribute(cube, "physics:mass", 0.5)
        assert world.get_attribute(cube, "physics:mass") == 0.5
        world.set_attribute(cube, "physics:velocity", (1.0, 0.0, 0.0))
        assert world.get_attribute(cube, "physics:velocity") == pytest.approx((1.0, 0.0, 0.0))
        assert world.get_attribute("/World/ur10/upper_arm_link/elbow_joint", "physics:lowerLimit") == -180.0
        assert world.get_attribute("/World/ur10/ee_link/SurfaceGripper", "isaac:maxGripDistance") == \
            pytest.approx(0.01)


def test_prim_pose_of_a_frame_carried_by_a_body():
    with create_world(PICK_PLACE) as world:
        ee_position, ee_orientation = world.prim_pose("/World/ur10/ee_link")
        gripper = world.prim_pose("/World/ur10/ee_link/SurfaceGripper")
        tip = world.prim_pose("/World/ur10/ee_link/attachment_joint")
        assert gripper[0] == pytest.approx(ee_position)
        assert math.dist(tip[0], ee_position) == pytest.approx(0.1611, abs=1e-6)
        assert tip[0][2] == pytest.approx(ee_position[2] - 0.1611, abs=1e-6)   # default pose: tool points down


def test_body_poses_are_each_bodys_prim_pose_in_one_query():
    """The batched query a recorder uses gives the very numbers of ``prim_pose``, arm links and free cube alike."""
    with create_world(PICK_PLACE) as world:
        world.set_joint_targets("/World/ur10", [0, 1, 2], positions=[0.4, -1.2, 0.9])
        moving = [path for path, handle in world.scene.bodies.items() if handle.kind != "static"]
        for _ in range(3):
            for _ in range(20):
                world.step()
            assert world.body_poses(moving) == [world.prim_pose(path) for path in moving]
            assert world.body_poses(moving[::-1]) == [world.prim_pose(path) for path in moving[::-1]]
        resting = world.body_poses(moving)
        world.set_attribute("/World/Cube", "xformOp:translate", (0.7, 0.1, 0.3))   # a resting body moved
        poses = dict(zip(moving, world.body_poses(moving)))
        assert poses["/World/Cube"][0] == pytest.approx((0.7, 0.1, 0.3), abs=1e-9)
        assert poses["/World/Cube"] != resting[moving.index("/World/Cube")]
        assert list(poses.values()) == [world.prim_pose(path) for path in moving]
        with pytest.raises(WorldError, match="/World/ur10/ee_link/collision is not a rigid body"):
            world.body_poses(["/World/ur10/ee_link/collision"])


def test_backend_internal_lookups_round_trip():
    with create_world(PICK_PLACE) as world:
        for path in world.scene.bodies:
            assert world.prim_at(*world.body_link(path)) == path
        assert world.body_link("/World/ur10/ee_link/collision") == world.body_link("/World/ur10/ee_link")
        assert world.prim_at(99, 0) is None


@pytest.mark.parametrize("call, message", [
    (lambda w: w.prim_pose("/World/Nothing"), "/World/Nothing"),
    (lambda w: w.joint_names("/World/Cube"), "/World/Cube is not part of an articulation"),
    (lambda w: w.get_attribute("/World/Cube", "physics:bogus"), "/World/Cube has no attribute physics:bogus"),
    (lambda w: w.set_attribute("/World/Cube", "physics:bogus", 1), "/World/Cube: no attribute /World/Cube.physics:bogus on this stage"),
    (lambda w: w.set_attribute("/World/ur10/upper_arm_link/elbow_joint", "physics:lowerLimit", 0), "read-only"),
    (lambda w: w.set_joint_targets("/World/ur10", [7], positions=[0.0]), "joint index 7 out of range"),
])
def test_errors_name_the_prim(call, message):
    with create_world(PICK_PLACE) as world:
        with pytest.raises(WorldError, match=message.replace(".", r"\.")):
            call(world)


def test_resolve_stage_for_assets_and_relative_paths(tmp_path):
    assert resolve_stage("asset:gantry.usda").name == "gantry.usda"
    assert resolve_stage("scenes/a.usda", tmp_path) == tmp_path / "scenes" / "a.usda"
