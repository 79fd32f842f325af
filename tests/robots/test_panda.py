"""The packaged Panda (graphflow/assets/panda.usda, converted from pybullet_data's panda.urdf by ``graphflow
robot add``): it holds its home pose under gravity as statics says it must, its IK chain read off the stage
is the simulated arm's, and it runs the suction pick-and-place graph to its checks."""
import math
import warnings

import numpy as np
import pytest
from conftest import GRAPHS, ROOT

from graphflow.physics import create_world
from graphflow.poses import AXIS_VECTORS, compose, quat_rotate
from graphflow.usd.physics_import import load_description

PANDA = ROOT / "graphflow" / "assets" / "panda.usda"
HOME = (0.0, -math.pi / 4, 0.0, -3 * math.pi / 4, 0.0, math.pi / 2, math.pi / 4)   # Franka's "ready" pose
SECONDS = 2.0
HELD = 0.005           # rad: the largest a joint may leave home in 2 s under gravity (a 3.4 mm tip shift at 0.68 m)
HAND = "/panda/Geometry/panda_link0/panda_link1/panda_link2/panda_link3/panda_link4/panda_link5/panda_link6/" \
       "panda_link7/panda_link8/panda_hand"
G = 9.81


def description():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return load_description(str(PANDA))


def gravity_torques(parsed):
    """Per arm joint (1..7), the gravity torque about its axis at the authored (home) pose: sum over the bodies
    beyond it of (c - p) x (m g) . a, in numpy from the stage's masses and poses (not the simulator's)."""
    from graphflow.robots.gains import bodies_beyond

    torques = []
    for index in range(1, 8):
        joint = parsed.joints[f"/panda/Physics/panda_joint{index}"]
        frame = compose(parsed.bodies[joint.body0].pose, joint.pose0)
        axis, origin = np.array(quat_rotate(frame[1], AXIS_VECTORS[joint.axis])), np.array(frame[0])
        total = 0.0
        for path in bodies_beyond(parsed, joint):
            body = parsed.bodies[path]
            centre = np.array(compose(body.pose, (body.mass.center_of_mass, (0, 0, 0, 1)))[0])
            total += np.cross(centre - origin, np.array([0.0, 0.0, -G * body.mass.mass])) @ axis
        torques.append(total)
    return np.array(torques)


@pytest.fixture(scope="module")
def held():
    """(joint positions, joint efforts, joint velocities) of the seven arm joints after SECONDS at home."""
    with create_world(str(PANDA)) as world:
        names = world.joint_names("/panda")
        arm = [names.index(f"panda_joint{i}") for i in range(1, 8)]
        for _ in range(round(SECONDS / world.time_step)):
            world.step()
        pick = (lambda values: np.array([values[i] for i in arm]))
        return (pick(world.joint_positions("/panda")), pick(world.joint_efforts("/panda")),
                pick(world.joint_velocities("/panda")))


def test_the_panda_holds_its_home_pose_under_gravity(held):
    positions, _efforts, velocities = held
    assert np.max(np.abs(positions - HOME)) < HELD
    assert np.max(np.abs(velocities)) < 1e-4


def test_each_joint_sags_by_its_gravity_torque_over_its_stiffness(held):
    """Statics: a drive holds its load tau_g with k (q* - q) = tau_g, so q - q* = tau_g / k and the drive
    pushes -tau_g. Joint 4 carries -19.40 N m (k 5730: -3.39 mrad), joint 2 2.72 N m (k 8493: 0.32 mrad), joint 6
-1.56 N m (k 2121: -0.73 mrad); joints 1 and 7, vertical at home, carry none."""
    positions, efforts, _velocities = held
    parsed = description()
    torques = gravity_torques(parsed)
    stiffness = np.array([parsed.joints[f"/panda/Physics/panda_joint{i}"].drive.stiffness for i in range(1, 8)])
    sag = positions - HOME
    for joint in range(7):
        expected = torques[joint] / stiffness[joint]
        assert abs(sag[joint] - expected) <= max(0.05 * abs(expected), 2e-5), (joint + 1, sag[joint], expected)
        assert abs(efforts[joint] + torques[joint]) <= max(0.05 * abs(torques[joint]), 0.02), (joint + 1,)
    assert torques[3] == pytest.approx(-19.40, abs=0.01) and torques[1] == pytest.approx(2.72, abs=0.01)


def test_the_stage_chain_puts_the_tool_where_the_simulated_arm_has_it():
    """The controllers' IK chain, read off the stage (base link, 7 joints, two fixed joints, the attachment
    frame): its forward kinematics at home is the simulated hand's frame 0.13 m along its +Z, to 1 um, and
    the tool's +X (the suction axis) is the hand's +Z."""
    from graphflow_nodes._arm import chain_from_stage

    with create_world(str(PANDA)) as world:
        chain, base = chain_from_stage(world, HAND + "/SurfaceGripper")
        tool = chain.forward(HOME)
        base_pose, hand_pose = world.prim_pose(base), world.prim_pose(HAND)
    assert chain.names == tuple(f"panda_joint{i}" for i in range(1, 8))
    position = compose(base_pose, (tuple(tool[:3, 3]), (0, 0, 0, 1)))[0]
    expected = compose(hand_pose, ((0.0, 0.0, 0.13), (0, 0, 0, 1)))[0]
    assert np.allclose(position, expected, atol=1e-6)
    suction_axis = quat_rotate(base_pose[1], tuple(tool[:3, 0]))
    assert np.allclose(suction_axis, quat_rotate(hand_pose[1], (0.0, 0.0, 1.0)), atol=1e-6)


@pytest.mark.slow
def test_the_panda_picks_and_places_the_cube_with_suction():
    """graphs/panda_pick_place.json, the UR10's routine unchanged on the Panda: the cube ends within 5 mm of
    (0.45, 0.2) resting on the ground, upright, held from the close to the release."""
    from graphflow.runtime import Simulation

    simulation = Simulation.load(GRAPHS / "panda_pick_place.json")
    with simulation:
        result = simulation.run(seconds=30.0)
        world = simulation.world
        position, _orientation = world.prim_pose("/World/Cube")
        linear, _angular = world.prim_velocity("/World/Cube")
        logs = [event.message for event in simulation.instance.events]
    assert result.stopped_by_graph
    assert math.dist(position, (0.45, 0.2, 0.0515 / 2)) < 0.005
    assert math.hypot(*linear) < 1e-3
    assert logs[3] == "phase 3 gripper_close: gripper Closed" and logs[5] == "phase 5 move_to_place: gripper Closed"
    assert logs[-1] == "pick and place done"


def test_the_gravity_load_is_pybullets_inverse_dynamics_too():
    """Before anything moves, the torques PyBullet's inverse dynamics needs to hold the built Panda at home
    are -tau_g of the numpy statics (to 0.01 N m: the two 1 g frames graphflow gives its massless links)."""
    parsed = description()
    torques = gravity_torques(parsed)
    with create_world(str(PANDA)) as world:
        articulation = world.scene.articulations["/panda"]
        states = world.client.getJointStates(articulation.body_id, articulation.joint_indices)
        rest = [0.0] * len(states)
        holding = world.client.calculateInverseDynamics(articulation.body_id, [s[0] for s in states], rest, rest)
        by_path = {path: sign * torque for path, sign, torque in zip(articulation.joint_paths, articulation.signs,
                                                                      holding)}
    for index in range(1, 8):
        assert by_path[f"/panda/Physics/panda_joint{index}"] == pytest.approx(-torques[index - 1], abs=0.01)


def test_any_stage_composes_the_panda_by_its_asset_path(tmp_path):
    """@graphflow/panda.usda@ resolves through the asset roots: a cell of one's own gets the arm and gripper."""
    from graphflow.usd.asset_roots import asset_roots

    assert (asset_roots()["graphflow"] / "panda.usda").is_file()
    cell = tmp_path / "cell.usda"
    cell.write_text('#usda 1.0\n(\n    defaultPrim = "World"\n    metersPerUnit = 1\n    upAxis = "Z"\n)\n'
                    'def Xform "World"\n{\n    def Xform "panda" (\n        prepend references = @graphflow/panda.usda@\n'
                    '    )\n    {\n    }\n}\n')
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        parsed = load_description(str(cell))
    assert [g.path for g in parsed.surface_grippers] == ["/World" + HAND + "/SurfaceGripper"]
    assert [a.path for a in parsed.articulations] == ["/World/panda"]
