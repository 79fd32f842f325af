"""isaacsim.core.nodes on the examples of Isaac Sim's own node tests (source/extensions/isaacsim.core.nodes/python/
tests): Isaac's inputs and expected outputs as facts, with the stage each test builds written here as USD text and
simulated by PyBullet at Isaac's 60 Hz; physical numbers also against free-fall and rigid-rotation references."""
import math
import struct
import warnings
from pathlib import Path

import pytest

from graphflow.executor import GraphRuntimeError
from graphflow.physics import create_world
from graphflow.testing import GraphHarness, NodeHarness

ODOMETRY = "isaacsim.core.nodes.IsaacComputeOdometry"
G = 9.81


# --- IsaacTimeSplitter: test_time_splitter ----------------------------------------------------------------------

@pytest.mark.parametrize(("constant", "value", "split"), [
    ("omni.graph.nodes.ConstantDouble", 1.012345678, (1, 12, 12345, 12345678)),
    ("omni.graph.nodes.ConstantInt", 10, (10, 0, 0, 0)),
    ("omni.graph.nodes.ConstantInt64", 20, (20, 0, 0, 0)),
    ("omni.graph.nodes.ConstantUInt", 30, (30, 0, 0, 0)),
    ("omni.graph.nodes.ConstantUInt64", 40, (40, 0, 0, 0))])
def test_time_splitter_example_fed_by_a_constant(constant, value, split):
    """Isaac's test: a constant of each type wired into the splitter; whole seconds, then the fraction in ms, us
    and ns, each rounded down."""
    graph = GraphHarness({
        "nodes": [{"name": "constant", "type": constant, "inputs": {"value": value}},
                  {"name": "split", "type": "isaacsim.core.nodes.IsaacTimeSplitter"}],
        "connections": [{"src": "constant.outputs:value", "dst": "split.inputs:time"}]})
    graph.instance.compute_node("split")
    names = ("seconds", "milliseconds", "microseconds", "nanoseconds")
    assert tuple(graph.output("split", name) for name in names) == split


@pytest.mark.parametrize(("stored_as", "value", "isaac_split", "double_split"), [
    ("f", 2.910123456, (2, 910, 910123, 910123348), (2, 910, 910123, 910123456)),
    ("e", 3.789012345, (3, 789, 789062, 789062500), (3, 789, 789012, 789012345))])
def test_time_splitter_float_and_half_examples_lose_isaacs_storage_precision(stored_as, value, isaac_split,
                                                                            double_split):
    """Isaac's float and half constants store 2.910123456 and 3.789012345 at 32 and 16 bits, so its splitter
    reads 2.9101233 and 3.7890625 (its own test says "precision lost"). graphflow keeps real values as Python
    floats: the same constant splits at full precision, and the value rounded to Isaac's storage gives
    Isaac's numbers exactly."""
    names = ("seconds", "milliseconds", "microseconds", "nanoseconds")
    stored = struct.unpack(stored_as, struct.pack(stored_as, value))[0]
    isaac = NodeHarness("isaacsim.core.nodes.IsaacTimeSplitter", {"time": stored}).compute().outputs
    assert tuple(isaac[name] for name in names) == isaac_split
    constant = "omni.graph.nodes.ConstantFloat" if stored_as == "f" else "omni.graph.nodes.ConstantHalf"
    graph = GraphHarness({
        "nodes": [{"name": "constant", "type": constant, "inputs": {"value": value}},
                  {"name": "split", "type": "isaacsim.core.nodes.IsaacTimeSplitter"}],
        "connections": [{"src": "constant.outputs:value", "dst": "split.inputs:time"}]})
    graph.instance.compute_node("split")
    assert tuple(graph.output("split", name) for name in names) == double_split


# --- IsaacComputeOdometry: test_compute_odometry ----------------------------------------------------------------

def _cube_stage(z, *, ground=False, velocity=None, angular_velocity=None, angular_damping=None):
    """Isaac's add_cube: a 1 m cube of 1 kg at (0, 0, z) (or (x, y, z)), optionally on its ground plane at -0.5."""
    x, y, z = z if isinstance(z, tuple) else (0.0, 0.0, z)
    motion = ""
    if velocity is not None:
        motion += f"    vector3f physics:velocity = {tuple(velocity)}\n"
    if angular_velocity is not None:   # USD's angular velocity is in degrees per second
        motion += f"    vector3f physics:angularVelocity = {tuple(math.degrees(w) for w in angular_velocity)}\n"
    if angular_damping is not None:
        motion += f"    float physxRigidBody:angularDamping = {angular_damping}\n"
    floor = '''def Cube "Ground" (prepend apiSchemas = ["PhysicsCollisionAPI"])
{
    double size = 1
    double3 xformOp:translate = (0, 0, -1)
    double3 xformOp:scale = (40, 40, 1)
    uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:scale"]
}
''' if ground else ""
    return f'''#usda 1.0
(
    upAxis = "Z"
    metersPerUnit = 1
)
{floor}def Cube "Cube" (prepend apiSchemas = ["PhysicsRigidBodyAPI", "PhysicsCollisionAPI", "PhysicsMassAPI"])
{{
    double size = 1
    float physics:mass = 1
{motion}    double3 xformOp:translate = ({x}, {y}, {z})
    uniform token[] xformOpOrder = ["xformOp:translate"]
}}
'''


@pytest.fixture()
def cube_world(tmp_path):
    """A world built from a cube stage, at Isaac's 60 Hz."""
    worlds = []

    def build(*args, **kwargs):
        path = tmp_path / f"cube{len(worlds)}.usda"
        path.write_text(_cube_stage(*args, **kwargs))
        world = create_world(path, time_step=1.0 / 60.0)
        worlds.append(world)
        return world

    yield build
    for world in worlds:
        world.close()


def _odometry(world):
    return NodeHarness(ODOMETRY, {"chassisPrim": ["/Cube"]}, world=world)


def _run(node, steps):
    for _ in range(steps):
        outputs = node.tick("execIn").outputs
    return outputs


def test_odometry_outputs_before_play_are_zero_and_the_identity(cube_world):
    """Isaac's test_odometry_default_outputs: before the first tick every vector is 0, the orientation (x, y, z, w)
    is (0, 0, 0, 1)."""
    outputs = _odometry(cube_world(0.0)).outputs.as_dict()
    for name in ("position", "linearVelocity", "angularVelocity", "linearAcceleration", "angularAcceleration",
                 "globalLinearVelocity", "globalLinearAcceleration"):
        assert tuple(outputs[name]) == (0.0, 0.0, 0.0), name
    assert tuple(outputs["orientation"]) == (0.0, 0.0, 0.0, 1.0)


def test_odometry_of_a_cube_resting_on_the_ground(cube_world):
    """Isaac's test_odometry_rigid_body_stationary: after 180 steps on the ground every rate is within 0.2 of 0
    and the displacement too."""
    outputs = _run(_odometry(cube_world(0.0, ground=True)), 180)
    for name in ("position", "linearVelocity", "angularVelocity", "linearAcceleration", "angularAcceleration",
                 "globalLinearVelocity", "globalLinearAcceleration"):
        assert outputs[name] == pytest.approx((0.0, 0.0, 0.0), abs=0.2), name


def test_odometry_of_a_cube_in_free_fall(cube_world):
    """Isaac's test_odometry_rigid_body_free_fall: after 60 steps (1 s) the velocity, the displacement and the
    acceleration point down (Isaac: below -0.1, -0.1 and -1). Free fall from rest: v = -g t, z = -g t^2 / 2,
    a = -g, to the first step's semi-implicit Euler offset."""
    node = _odometry(cube_world(5.0))
    node.compute("execIn")                         # the start pose, at t = 0
    outputs = _run(node, 60)
    assert outputs["globalLinearVelocity"][2] < -0.1 and outputs["position"][2] < -0.1
    assert outputs["globalLinearAcceleration"][2] < -1.0
    assert outputs["globalLinearVelocity"] == pytest.approx((0.0, 0.0, -G * 1.0), abs=1e-3)
    assert outputs["position"] == pytest.approx((0.0, 0.0, -G / 2), abs=G / 60)   # one step's v dt
    assert outputs["globalLinearAcceleration"] == pytest.approx((0.0, 0.0, -G), abs=1e-3)


def test_odometry_position_is_relative_to_the_start(cube_world):
    """Isaac's test_odometry_position_relative_to_start: a cube at (5, 3, 10) reads ~0 after 2 steps (within
    0.05); pushed down at 1.5 m/s for 30 more steps it has moved below -0.2 and not sideways (within 0.2)."""
    world = cube_world((5.0, 3.0, 10.0))
    node = _odometry(world)
    start = _run(node, 2)
    assert start["position"] == pytest.approx((0.0, 0.0, 0.0), abs=0.05)
    world.set_attribute("/Cube", "physics:velocity", (0.0, 0.0, -1.5))
    later = _run(node, 30)
    assert later["position"][2] < -0.2
    assert later["position"][:2] == pytest.approx((0.0, 0.0), abs=0.2)
    # reference: the push replaces the fall speed, then 1.5 m/s down plus free fall for 30 steps (0.5 s), to one
    # step's semi-implicit Euler offset g dt T
    duration = 30 / 60
    drop = -1.5 * duration - G * duration ** 2 / 2
    assert later["position"][2] - start["position"][2] == pytest.approx(drop, abs=G / 60 * duration)


def test_odometry_of_a_thrown_spinning_cube(cube_world):
    """Isaac's test_odometry_all_outputs_populated: thrown at (0.8, 0, -0.5) m/s spinning 1.2 rad/s about z, after
    30 steps every output is finite and populated: position z < 0, vertical speed not 0, acceleration not 0.
    Reference: the vertical speed is -0.5 - g t at t = 0.5 s; undamped (PhysX's default angular damping 0.05
    turned off: PyBullet damps a spinning body by 0.05 (1 + |w|), not PhysX's 0.05) the yaw rate stays 1.2."""
    node = _odometry(cube_world(3.0, velocity=(0.8, 0.0, -0.5), angular_velocity=(0.0, 0.0, 1.2),
                                angular_damping=0.0))
    node.compute("execIn")
    outputs = _run(node, 30)
    assert all(math.isfinite(v) for values in outputs.values() if isinstance(values, tuple) for v in values)
    assert len(outputs["orientation"]) == 4
    assert outputs["position"][2] < 0.0 and abs(outputs["globalLinearVelocity"][2]) > 0.01
    assert math.hypot(*outputs["globalLinearAcceleration"]) > 0.0
    assert outputs["globalLinearVelocity"][2] == pytest.approx(-0.5 - G * 0.5, abs=1e-3)
    assert outputs["globalLinearVelocity"][0] == pytest.approx(0.8, abs=0.01)
    assert outputs["angularVelocity"][2] == pytest.approx(1.2, rel=1e-6)


def test_odometry_orientation_of_a_spinning_cube(cube_world):
    """Isaac's test_odometry_orientation_changes_on_rotation: spun at 2 rad/s about z, after 2 + 40 steps the
    orientation is a unit quaternion (within 0.01); undamped, relative to the start it has turned 2 rad/s x
    42/60 s."""
    node = _odometry(cube_world(2.0, angular_velocity=(0.0, 0.0, 2.0), angular_damping=0.0))
    node.compute("execIn")
    _run(node, 2)
    outputs = _run(node, 40)
    x, y, z, w = outputs["orientation"]
    assert x * x + y * y + z * z + w * w == pytest.approx(1.0, abs=0.01)
    assert 2 * math.atan2(z, w) == pytest.approx(2.0 * 42 / 60, rel=1e-6)
    assert len(outputs["angularVelocity"]) == 3


# --- IsaacReadWorldPose: test_read_world_pose -------------------------------------------------------------------

def test_read_world_pose_example(tmp_path):
    """Isaac's test: a cube translated to (1, 2, 3) reads translation (1, 2, 3), orientation (0, 0, 0, 1) and scale
    (1, 1, 1) to 3 places."""
    stage = tmp_path / "pose.usda"
    stage.write_text('#usda 1.0\n(\n    upAxis = "Z"\n    metersPerUnit = 1\n)\ndef Xform "World"\n{\n    def Cube "Cube"\n    {\n'
                     '        double3 xformOp:translate = (1, 2, 3)\n'
                     '        uniform token[] xformOpOrder = ["xformOp:translate"]\n    }\n}\n')
    with create_world(stage, time_step=1.0 / 60.0) as world:
        outputs = NodeHarness("isaacsim.core.nodes.IsaacReadWorldPose", {"prim": ["/World/Cube"]},
                              world=world).tick().outputs
    assert outputs["translation"] == pytest.approx((1.0, 2.0, 3.0), abs=1e-3)
    assert outputs["orientation"] == pytest.approx((0.0, 0.0, 0.0, 1.0), abs=1e-3)
    assert outputs["scale"] == pytest.approx((1.0, 1.0, 1.0), abs=1e-3)


# --- OnPhysicsStep: test_physics_step ---------------------------------------------------------------------------

def _grow_on_every_step(cube, attribute):
    """Isaac's graph: on each physics step, attribute <- attribute + 1 (ReadPrimAttribute + ConstantFloat 1 -> Add
    -> WritePrimAttribute)."""
    return [
        {"name": f"step_{cube}", "type": "isaacsim.core.nodes.OnPhysicsStep"},
        {"name": f"read_{cube}", "type": "omni.graph.nodes.ReadPrimAttribute",
         "inputs": {"prim": [f"/{cube}"], "name": attribute}},
        {"name": f"one_{cube}", "type": "omni.graph.nodes.ConstantFloat", "inputs": {"value": 1.0}},
        {"name": f"add_{cube}", "type": "omni.graph.nodes.Add"},
        {"name": f"write_{cube}", "type": "omni.graph.nodes.WritePrimAttribute",
         "inputs": {"prim": [f"/{cube}"], "name": attribute}},
    ], [
        {"src": f"step_{cube}.outputs:step", "dst": f"write_{cube}.inputs:execIn"},
        {"src": f"read_{cube}.outputs:value", "dst": f"add_{cube}.inputs:a"},
        {"src": f"one_{cube}.outputs:value", "dst": f"add_{cube}.inputs:b"},
        {"src": f"add_{cube}.outputs:sum", "dst": f"write_{cube}.inputs:value"},
    ]


@pytest.mark.parametrize("cubes", [("Cube",), ("CubeA", "CubeB")])
def test_physics_step_example_adds_one_on_every_step(tmp_path, cubes):
    """Isaac's test_physics_step_node and _two_nodes: on every physics step each graph adds 1 to its cube's
    attribute, so after n steps it is its start value + n. Isaac grows the cube's size (2 -> 2 + n); graphflow's
    physics world writes only the attributes it simulates (size is not one: a one-line error naming it), so the
    same graph grows a rigid cube's mass instead (2 kg -> 2 + n)."""
    stage = tmp_path / "cubes.usda"
    stage.write_text('#usda 1.0\n' + "".join(
        f'def Cube "{cube}" (prepend apiSchemas = ["PhysicsRigidBodyAPI", "PhysicsMassAPI"])\n'
        f'{{\n    float physics:mass = 2\n    double3 xformOp:translate = ({i * 3}, 0, 0)\n'
        f'    uniform token[] xformOpOrder = ["xformOp:translate"]\n}}\n' for i, cube in enumerate(cubes)))
    nodes, connections = [], []
    for cube in cubes:
        more_nodes, more_connections = _grow_on_every_step(cube, "physics:mass")
        nodes += more_nodes
        connections += more_connections
    with create_world(stage, time_step=1.0 / 60.0) as world:
        graph = GraphHarness({"nodes": nodes, "connections": connections}, world=world)
        for steps in range(1, 11):
            graph.run(1)
            assert [world.get_attribute(f"/{cube}", "physics:mass") for cube in cubes] == [2.0 + steps] * len(cubes)


def test_read_world_pose_reports_the_composed_scale(tmp_path):
    """Isaac decomposes the prim's world matrix, so a cube scaled (4, 1, 1) under a parent scaled 2 reads
    (8, 2, 2); its translation is the parent's scale times its own offset."""
    stage = tmp_path / "scaled.usda"
    stage.write_text('#usda 1.0\n(\n    metersPerUnit = 1\n)\ndef Xform "World"\n{\n'
                     '    double3 xformOp:scale = (2, 2, 2)\n    uniform token[] xformOpOrder = ["xformOp:scale"]\n'
                     '    def Cube "Belt"\n    {\n        double3 xformOp:translate = (0.5, 0, 0)\n'
                     '        double3 xformOp:scale = (4, 1, 1)\n'
                     '        uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:scale"]\n    }\n}\n')
    with create_world(stage, time_step=1.0 / 60.0) as world:
        outputs = NodeHarness("isaacsim.core.nodes.IsaacReadWorldPose", {"prim": ["/World/Belt"]},
                              world=world).compute().outputs
    assert outputs["scale"] == pytest.approx((8.0, 2.0, 2.0), rel=1e-12)
    assert outputs["translation"] == pytest.approx((1.0, 0.0, 0.0), rel=1e-12)


# --- IsaacArticulationController: test_articulation_controller (Isaac's Franka; here the packaged Panda) -----------

PANDA = Path(__file__).resolve().parents[2] / "graphflow" / "assets" / "panda.usda"
ARTICULATION = "isaacsim.core.nodes.IsaacArticulationController"


@pytest.fixture()
def panda():
    """The packaged Panda at 60 Hz, and a way to put Isaac's controller node on it."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")       # the asset's massless frames are reported once: not this test's
        world = create_world(str(PANDA), time_step=1.0 / 60.0)
    with world:
        yield world, (lambda inputs: NodeHarness(ARTICULATION, {"robotPath": "/panda", **inputs}, world=world))


def _tick(node, steps):
    for _ in range(steps):
        node.tick("execIn")


@pytest.mark.parametrize(("inputs", "commanded"), [
    ({"jointNames": ["panda_joint2", "panda_joint3"], "positionCommand": [-1.0, 1.2]}, {1: -1.0, 2: 1.2}),
    ({"jointIndices": [1, 2], "positionCommand": [-1.0, 1.2]}, {1: -1.0, 2: 1.2}),
    ({"positionCommand": [0.0, -1.0, 1.2, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]}, {1: -1.0, 2: 1.2}),
    ({"jointNames": ["panda_joint3"], "positionCommand": [1.7]}, {2: 1.7}),
    ({"jointIndices": [2], "positionCommand": [1.7]}, {2: 1.7})])
def test_articulation_controller_examples_hold_the_commanded_joints(panda, inputs, commanded):
    """Isaac's tests command joints 2 and 3 (by name, by index, as the full 9-wide array) to -1.0 and 1.2, or
    joint 3 alone to 1.7, and read them after 120 steps within 1-3 mrad (10 mrad for the full array), the
    untouched joint 4 far from 1.7. Isaac's tolerances hold for its Franka's drives; the packaged Panda's are
    softer (148 N m/deg on joint 2, converted from pybullet_data's URDF), so under gravity a commanded joint
    settles short of its target (at rest: 1.4 mrad on joint 2, 2.9 on joint 3, 2.6 for joint 3 alone, 4.8 on
    joint 2 when the full array stretches the arm out). Checked: after 120 steps every commanded joint is within
    Isaac's loosest 0.01; at rest (2 s later) within 5 mrad."""
    world, controller = panda
    node = controller(inputs)
    _tick(node, 120)
    positions = world.joint_positions("/panda")
    for index, target in commanded.items():
        assert positions[index] == pytest.approx(target, abs=0.01)
    if 1 not in commanded:
        assert abs(positions[3] - 1.7) > 0.1
    _tick(node, 120)
    positions, velocities = world.joint_positions("/panda"), world.joint_velocities("/panda")
    for index, target in commanded.items():
        assert abs(velocities[index]) < 1e-4
        assert positions[index] == pytest.approx(target, abs=0.005)


def test_articulation_controller_follows_a_changed_command(panda):
    """Isaac's test_joint_indices_different_shape: joint index 2 at 1.7, then commanded 0.5 for 120 more steps:
    it moves (by more than 0.01) and ends within 0.01 of 0.5."""
    world, controller = panda
    node = controller({"jointIndices": [2], "positionCommand": [1.7]})
    _tick(node, 120)
    before = world.joint_positions("/panda")[2]
    node.set_inputs(positionCommand=[0.5])
    _tick(node, 120)
    after = world.joint_positions("/panda")[2]
    assert abs(after - before) > 0.01
    assert after == pytest.approx(0.5, abs=0.01)


def test_articulation_controller_mismatched_command_applies_nothing(panda):
    """Isaac's test: joints [1, 2] with positionCommand [0.1, 0.2] and effortCommand [0.3] is refused whole, the
    error naming effortCommand and the widths; no target is applied, so the arm keeps its authored home pose."""
    world, controller = panda
    node = controller({"jointIndices": [1, 2], "positionCommand": [0.1, 0.2], "effortCommand": [0.3]})
    before = world.joint_positions("/panda")
    with pytest.raises(GraphRuntimeError, match="effortCommand") as error:
        node.tick("execIn")
    for _ in range(60):
        world.step()
    assert "1" in str(error.value) and "2" in str(error.value)
    assert world.joint_positions("/panda") == pytest.approx(before, abs=0.005)


# --- IsaacArticulationState: test_articulation_state ------------------------------------------------------------

PANDA_JOINTS = tuple(f"panda_joint{i}" for i in range(1, 8)) + ("panda_finger_joint1", "panda_finger_joint2")


@pytest.mark.parametrize(("inputs", "picked"), [
    ({"jointNames": ["panda_joint2", "panda_joint3"]}, [1, 2]), ({"jointIndices": [1, 2]}, [1, 2]),
    ({}, list(range(9))), ({"jointNames": ["panda_joint3"]}, [2]), ({"jointIndices": [2]}, [2])])
def test_articulation_state_examples_read_the_chosen_joints(panda, inputs, picked):
    """Isaac's tests read joints 2 and 3 (by name, by index), all 9, or joint 3 alone of its Franka after 60 steps
    while the arm moves, and compare positions, velocities and efforts with the articulation's own to 3 decimals.
    Here the arm is driven (joint 3 towards 1.2) so velocities are not 0. Isaac also outputs one measured joint
    force and torque per joint; graphflow's world does not measure joint reaction wrenches, so those are empty."""
    world, controller = panda
    drive = controller({"jointNames": ["panda_joint3"], "positionCommand": [1.2]})
    _tick(drive, 30)
    outputs = NodeHarness("isaacsim.core.nodes.IsaacArticulationState", {"robotPath": "/panda", **inputs},
                          world=world).compute("execIn").outputs
    assert outputs["jointNames"] == tuple(PANDA_JOINTS[i] for i in picked)
    for output, read in (("jointPositions", world.joint_positions), ("jointVelocities", world.joint_velocities),
                         ("measuredJointEfforts", world.joint_efforts)):
        assert outputs[output] == pytest.approx([read("/panda")[i] for i in picked], abs=1e-3)
    assert abs(outputs["jointVelocities"][picked.index(2)]) > 0.1   # joint 3 is on its way


# --- IsaacJointNameResolver: test_joint_name_resolver (Isaac's Franka; here the packaged Panda) --------------------

def _panda_with_overrides(tmp_path, overrides):
    """The packaged Panda under a layer that authors isaac:nameOverride on some of its joints, as Isaac's test
    does on its Franka."""
    overs = "".join(f'        over "{joint}"\n        {{\n            string isaac:nameOverride = "{name}"\n        }}\n'
                    for joint, name in overrides.items())
    path = tmp_path / "renamed_panda.usda"
    path.write_text(f'#usda 1.0\n(\n    subLayers = [@{PANDA.as_posix()}@]\n)\n\n'
                    f'over "panda"\n{{\n    over "Physics"\n    {{\n{overs}    }}\n}}\n')
    return path


@pytest.mark.parametrize(("overrides", "names", "resolved"), [
    ({}, ["panda_joint2", "panda_joint3"], ("panda_joint2", "panda_joint3")),
    ({"panda_joint2": "custom_joint_2", "panda_joint3": "custom_joint_3"}, ["custom_joint_2", "custom_joint_3"],
     ("panda_joint2", "panda_joint3")),
    ({"panda_joint2": "renamed_joint_2"}, ["renamed_joint_2", "panda_joint3"], ("panda_joint2", "panda_joint3")),
    ({"panda_joint4": "my_j4"}, ["my_j4"], ("panda_joint4",)),
    ({}, ["nonexistent_joint"], ("nonexistent_joint",)),
    ({"panda_joint1": "j1_override", "panda_joint3": "j3_override", "panda_joint5": "j5_override"},
     ["j1_override", "panda_joint2", "j3_override", "panda_joint4", "j5_override"],
     tuple(f"panda_joint{i}" for i in range(1, 6)))])
@pytest.mark.parametrize("by_target", [False, True])
def test_joint_name_resolver_examples(tmp_path, overrides, names, resolved, by_target):
    """Isaac's tests: names that are a joint's isaac:nameOverride come back as the joint's own name, the others
    unchanged (an unknown name passes through), in order; the robot path is echoed, given as robotPath or as
    targetPrim. The resolved names drive the joints they name: each is one of the articulation's DOFs."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        world = create_world(str(_panda_with_overrides(tmp_path, overrides)), time_step=1.0 / 60.0)
    with world:
        robot = {"targetPrim": ["/panda"]} if by_target else {"robotPath": "/panda"}
        outputs = NodeHarness("isaacsim.core.nodes.IsaacJointNameResolver", {**robot, "jointNames": names},
                              world=world).compute("execIn").outputs
        dofs = world.joint_names("/panda")
    assert outputs["jointNames"] == resolved and outputs["robotPath"] == "/panda"
    assert all(name in dofs for name in resolved if name != "nonexistent_joint")


def test_read_world_pose_on_a_centimetre_stage_is_in_metres(tmp_path):
    """The .ogn documents the translation in metres, and graphflow gives metres: a cube 150 cm up reads 1.5.
    Isaac's C++ returns the USD matrix's translation, stage units (150): a graph that scales the output by
    ScaleToFromStageUnit in Isaac would scale it twice here; on metre stages (Isaac's default) both agree."""
    stage = tmp_path / "cm.usda"
    stage.write_text('#usda 1.0\n(\n    metersPerUnit = 0.01\n)\ndef Cube "Cube"\n{\n'
                     '    double3 xformOp:translate = (0, 0, 150)\n    uniform token[] xformOpOrder = ["xformOp:translate"]\n}\n')
    with create_world(stage, time_step=1.0 / 60.0) as world:
        outputs = NodeHarness("isaacsim.core.nodes.IsaacReadWorldPose", {"prim": ["/Cube"]}, world=world).compute().outputs
    assert outputs["translation"] == pytest.approx((0.0, 0.0, 1.5))
