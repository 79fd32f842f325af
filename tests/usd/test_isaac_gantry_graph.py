"""Isaac Sim's own gantry action graph, imported from its USD file and driven by a scripted gamepad.

The shared sample is sublayered by a small wrapper stage that adds what
Isaac's example script creates at run time: ``/World/SurfaceGripper`` on the
nine cone joints with the example's values (reference §8.2). The graph's math
per tick, from the file's wiring: x_joint += -0.05·LeftStickY,
y_joint += -0.05·LeftStickX, z_joint += 0.1·RightStickY - 0.1·RightShoulder,
each drive target clamped to its joint's [lowerLimit, upperLimit]; the face
button toggles the gripper. z_joint grows downwards: the cone centres are at
world z = 1.5 - q_z - 0.15007.
"""
import json
from pathlib import Path
from types import SimpleNamespace

import pytest
from conftest import USDA_SAMPLES as SAMPLES

from graphflow.cli import main
from graphflow.gripper import manager_for
from graphflow.inputs.gamepad import attach_gamepad, gamepad_for, scripted_pad
from graphflow.runtime import Simulation

GANTRY = SAMPLES / "isaacsim_SurfaceGripper_gantry.usda"
GRIPPER = "/World/SurfaceGripper"
BOX = "/World/Boxes/Cube_28"
JOINTS = {axis: f"/World/Joints/{axis}_joint" for axis in "xyz"}
TARGET = "drive:linear:physics:targetPosition"
DT = 1.0 / 60.0
CONE_DROP = 0.15007                 # Gantry_x to the cone centres
BOX_TOP = 1.20                      # Cube_28, top layer
MAX_GRIP_DISTANCE = 0.011


def _stick(delta, gain, ticks):
    """The stick value that moves a drive target by *delta* in *ticks* ticks of gain·value each."""
    return delta / (gain * ticks)


# Drive targets authored in the file: x 0.1, y 0.028, z -0.063. Cube_28 sits at world (0, -0.003);
# x_joint moves the gantry along world Y and y_joint along world X. 0.1 s is 6 ticks at 60 Hz.
PAD_TIMELINE = [
    # over Cube_28: x 0.1 -> -0.003 in 6 ticks, y 0.028 -> 0 in 3 ticks
    ("Left Stick Y Axis", 0.5, _stick(-0.003 - 0.1, -0.05, 6)), ("Left Stick Y Axis", 0.6, 0.0),
    ("Left Stick X Axis", 0.5, _stick(0.0 - 0.028, -0.05, 3)), ("Left Stick X Axis", 0.55, 0.0),
    # lower: z -0.063 -> 0.140, the cone centres 9.9 mm above the box (Isaac's test height)
    ("Right Stick Y Axis", 1.0, _stick(0.140 + 0.063, 0.1, 6)), ("Right Stick Y Axis", 1.1, 0.0),
    ("Face Button Bottom", 4.5, 1.0), ("Face Button Bottom", 4.6, 0.0),               # close
    ("Right Stick Y Axis", 5.0, _stick(-0.2, 0.1, 6)), ("Right Stick Y Axis", 5.1, 0.0),   # raise 0.2 m
    # carry to world (0.25, -0.25): x -0.003 -> -0.25, y 0 -> 0.25 in 30 ticks
    ("Left Stick Y Axis", 7.0, _stick(-0.25 + 0.003, -0.05, 30)), ("Left Stick Y Axis", 7.5, 0.0),
    ("Left Stick X Axis", 7.0, _stick(0.25, -0.05, 30)), ("Left Stick X Axis", 7.5, 0.0),
    # lower 0.3 m to z 0.24: the box's bottom reaches the table (top at 1.0)
    ("Right Stick Y Axis", 9.5, _stick(0.3, 0.1, 6)), ("Right Stick Y Axis", 9.6, 0.0),
    ("Face Button Bottom", 13.0, 1.0), ("Face Button Bottom", 13.1, 0.0),             # release
    ("Right Shoulder", 13.5, 1.0), ("Right Shoulder", 13.7, 0.0),   # up 0.1 m a tick for 12 ticks: clamped
]
RUN_SECONDS = 16.0


def _wrapper_stage(folder: Path) -> Path:
    if not GANTRY.is_file():
        pytest.skip(f"{GANTRY} not present")
    joints = ", ".join(f"</World/Surface_Gripper_Joints/D6Joint{suffix}>"
                       for suffix in [""] + [f"_{index:02d}" for index in range(1, 9)])
    path = folder / "gantry_with_gripper.usda"
    path.write_text(f'''#usda 1.0
(
    defaultPrim = "World"
    metersPerUnit = 1
    upAxis = "Z"
    subLayers = [@{GANTRY.as_posix()}@]
)

over "World"
{{
    def IsaacSurfaceGripper "SurfaceGripper"
    {{
        rel isaac:attachmentPoints = [{joints}]
        float isaac:maxGripDistance = {MAX_GRIP_DISTANCE}
        float isaac:coaxialForceLimit = 0.005
        float isaac:shearForceLimit = 5
        float isaac:retryInterval = 1
    }}
}}
''')
    return path


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    """Import the graph with the CLI, run it headless with the pad timeline, record every tick."""
    folder = tmp_path_factory.mktemp("isaac_gantry")
    stage = _wrapper_stage(folder)
    graph = folder / "gantry_graph.json"
    assert main(["import", str(stage), "-o", str(graph)]) == 0           # every node type is known now
    pad_file = folder / "pad.json"
    pad_file.write_text(json.dumps({"gamepad": [{"element": element, "time": time, "value": value}
                                                for element, time, value in PAD_TIMELINE]}))
    log = []
    printer = SimpleNamespace(on_log=lambda event: log.append((simulation.world.time, event.message)))
    simulation = Simulation.load(graph, listeners=[printer])
    attach_gamepad(simulation.world, scripted_pad(pad_file))
    with simulation:
        world, manager = simulation.world, manager_for(simulation.world)
        names = world.joint_names("/World/Claw_base")
        limits = {axis: (world.get_attribute(path, "physics:lowerLimit"), world.get_attribute(path, "physics:upperLimit"))
                  for axis, path in JOINTS.items()}
        ticks = []
        for _ in range(round(RUN_SECONDS / DT)):
            simulation.step()
            snapshot = gamepad_for(world).snapshot()
            positions = dict(zip(names, world.joint_positions("/World/Claw_base")))
            ticks.append({
                "time": world.time,
                "pad": {element: snapshot.value(0, element) for element in
                        ("Left Stick X Axis", "Left Stick Y Axis", "Right Stick Y Axis", "Right Shoulder")},
                "target": {axis: world.get_attribute(path, TARGET) for axis, path in JOINTS.items()},
                "q": {axis: positions[f"{axis}_joint"] for axis in "xyz"},
                "box": world.prim_pose(BOX)[0],
                "status": manager.get_gripper_status(GRIPPER).token,
                "gripped": list(manager.get_gripped_objects(GRIPPER)),
            })
        box_velocity = world.prim_velocity(BOX)
    return {"ticks": ticks, "limits": limits, "log": log, "box_velocity": box_velocity}


def _at(run, time):
    return run["ticks"][round(time / DT) - 1]


def test_drive_targets_integrate_the_sticks_within_the_joint_limits(run):
    ticks, limits = run["ticks"], run["limits"]
    previous = {"x": 0.1, "y": 0.028, "z": -0.063}                     # authored in the file
    for tick in ticks:
        pad = tick["pad"]
        moved = {"x": previous["x"] - 0.05 * pad["Left Stick Y Axis"],
                 "y": previous["y"] - 0.05 * pad["Left Stick X Axis"],
                 "z": previous["z"] + 0.1 * pad["Right Stick Y Axis"] - 0.1 * pad["Right Shoulder"]}
        for axis, value in moved.items():
            low, high = limits[axis]
            assert tick["target"][axis] == pytest.approx(min(max(value, low), high), abs=1e-6), (tick["time"], axis)
            assert low - 1e-3 <= tick["q"][axis] <= high + 1e-3
        previous = tick["target"]
    assert _at(run, 4.5)["target"] == pytest.approx({"x": -0.003, "y": 0.0, "z": 0.140}, abs=1e-6)
    assert _at(run, 9.0)["target"] == pytest.approx({"x": -0.25, "y": 0.25, "z": -0.06}, abs=1e-6)
    assert _at(run, 12.0)["target"]["z"] == pytest.approx(0.24, abs=1e-6)
    assert ticks[-1]["target"]["z"] == pytest.approx(limits["z"][0], abs=1e-6)     # held at -0.4574 by Max
    assert limits["z"] == pytest.approx((-0.4574, 0.2579), abs=1e-4)


def test_the_joints_follow_their_targets(run):
    assert _at(run, 4.5)["q"] == pytest.approx({"x": -0.003, "y": 0.0, "z": 0.140}, abs=1e-3)
    assert _at(run, 9.0)["q"] == pytest.approx({"x": -0.25, "y": 0.25, "z": -0.06}, abs=6e-3)
    # the Z drive (k = 800 N/m, d = 500 N s/m) closes the last millimetres with its time constant
    # d / k = 0.63 s: 2.4 mm short at 12.5 s, 0.8 mm at 13 s (the old drive law damped it 0.4x as much)
    assert _at(run, 12.5)["q"]["z"] == pytest.approx(0.24, abs=3e-3)
    assert _at(run, 16.0)["q"]["z"] < -0.35                                # rising towards the clamped target


def test_face_button_grips_cube_28_within_reach(run):
    before, after = _at(run, 4.5 - DT), _at(run, 5.0)
    cone_height = 1.5 - before["q"]["z"] - CONE_DROP
    assert 0 < cone_height - BOX_TOP < MAX_GRIP_DISTANCE                  # 10.4 mm above the box
    assert before["status"] == "Open"
    assert _at(run, 4.5)["status"] == "Closed"
    assert after["gripped"] == [BOX]
    carried = [tick for tick in run["ticks"] if 5.0 <= tick["time"] < 13.0]
    assert all(tick["status"] == "Closed" and tick["gripped"] == [BOX] for tick in carried)


def test_the_box_rises_and_travels_with_the_gantry(run):
    grip, lifted, carried = _at(run, 4.5), _at(run, 7.0), _at(run, 9.0)
    assert grip["box"][2] == pytest.approx(1.15, abs=1e-3)
    rise = lifted["box"][2] - grip["box"][2]
    assert rise == pytest.approx(grip["q"]["z"] - lifted["q"]["z"], abs=2e-3)    # 0.187 m: with the gantry
    assert rise > 0.18
    assert carried["box"][:2] == pytest.approx((0.25, -0.25), abs=2e-3)   # world X follows y_joint, Y x_joint


def test_released_box_rests_at_its_new_place(run):
    end = run["ticks"][-1]
    assert _at(run, 13.0)["status"] == "Open" and end["gripped"] == []
    assert end["box"] == pytest.approx((0.25, -0.25, 1.05), abs=2e-3)     # on the table (top at 1.0)
    linear, angular = run["box_velocity"]
    assert max(map(abs, linear)) < 1e-3 and max(map(abs, angular)) < 1e-2
    assert _at(run, 16.0)["q"]["z"] - _at(run, 13.0)["q"]["z"] < -0.5     # the gantry went up without it


def test_screen_text_is_logged_once(run):
    assert run["log"] == [(pytest.approx(DT), "Use Gamepad to control Gantry (left stick: X/Y, Right Stick: "
                                               "Up/down; Face down button: Open/Close)")]
