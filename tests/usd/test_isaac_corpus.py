"""The Isaac corpus as tests: every real file, imported, validated and run as a new user would.

``../shared/isaac_corpus`` holds 29 public .usda files from 14 repositories
(README and manifest.json there). For each graph the test runs
``graphflow import`` -> ``graphflow validate`` -> ``graphflow run --ticks 120``
and checks the outcome written down below: it runs (with the lines the import
must print, e.g. a dropped rendering node), or it fails with this line and why.
Physics-only files are loaded with ``graphflow stage`` (their simulation
belongs to the physics tests). Skips cleanly when the folder is absent.
"""
import json
from dataclasses import dataclass

import pytest
from conftest import ISAAC_CORPUS as CORPUS

from graphflow.cli import main

pytestmark = pytest.mark.skipif(not (CORPUS / "manifest.json").is_file(), reason="../shared/isaac_corpus is absent")
TICKS = 120


@dataclass(frozen=True)
class Runs:
    """Imports, validates and runs TICKS ticks (every graph of the file); *lines* must be among the import's lines."""
    lines: tuple[str, ...] = ()


@dataclass(frozen=True)
class Fails:
    """Fails at *stage* ("import" or "run") with a line containing *line*, for the reason *why*."""
    stage: str
    line: str
    why: str


@dataclass(frozen=True)
class Loads:
    """A physics-only file: ``graphflow stage`` loads it (simulating it is the physics tests' business)."""


RENDER = "dropped: needs Kit's RTX renderer (render products do not exist headless)"
RIDGEBACK = ("cannot open https://omniverse-content-production.s3-"
             "us-west-2.amazonaws.com/Assets/Isaac/5.1/Isaac/Robots/Clearpath/RidgebackUr/ridgeback_ur5.usd, "
             "the payload of /World/ridgeback_ur5 in layer ridgeback_robot.usda")
NVIDIA = "https://omniverse-content-production.s3-us-west-2.amazonaws.com/Assets/Isaac/"
URL_HINT = "(map its URL prefix to a local folder in graphflow.toml [assets.remap] or GRAPHFLOW_ASSET_REMAP)"
EXPECTED = {
    # NVIDIA's example script creates the gripper prim at run time: the file alone has none (pressing the button
    # fails, below; tests/usd/test_isaac_gantry_graph.py adds the gripper with a wrapper stage and grips)
    "g01_isaacsim_gantry": Fails(
        "validate", "node 'surface_gripper' input 'inputs:SurfaceGripper': no prim /World/SurfaceGripper on the stage",
        "NVIDIA's example script makes the gripper prim at run time; validate names the missing prim"),
    "g02_isaacsim_rename_node_type": Runs(),
    "g03_vla_ur5e_ros2": Fails(
        "validate", "cannot open /home/sheil/Development/VLA_Arm_Controller/urdf/ur5e_with_gripper/ur5e_with_gripper.usd, "
        "the reference of /World/ur5e in layer ur5e_from_urdf_script.usda: prims lost: everything that reference puts "
        "below /World/ur5e",
        "the UR5e is the author's local file, not in the repository"),
    "g04_krabby_crab_simple": Runs(),
    "g05_spot_diffdrive_ros2": Fails(
        "validate", f"cannot open {NVIDIA}5.1/Isaac/Robots/BostonDynamics/spot/spot.usd, the reference of /World/spot "
        f"in layer test_action_graph1.usda: prims lost: everything that reference puts below /World/spot {URL_HINT}",
        "the Spot is an online NVIDIA asset: the graph would run without its robot"),
    "g06_ridgeback_velocity": Fails("validate", RIDGEBACK, "the Ridgeback is an online NVIDIA asset"),
    "g07_ridgeback_ros2_twist": Fails("validate", RIDGEBACK, "the Ridgeback is an online NVIDIA asset"),
    "g08_ridgeback_sensors_ros2": Fails(
        "validate", f"cannot open {NVIDIA}5.1/Isaac/Robots/Clearpath/RidgebackUr/ridgeback_ur5.usd, the payload of "
        "/World/ridgeback_ur5 in layer ridgeback_robot.usda", "the Ridgeback is an online NVIDIA asset"),
    "g09_hospital_ros2_clock": Fails(
        "validate", f"cannot open {NVIDIA}5.1/Isaac/Samples/ROS2/Robots/Nova_Carter_ROS.usd, the payload of "
        "/World/Nova_Carter_ROS_1, /World/Nova_Carter_ROS_2, /World/Nova_Carter_ROS_3 in layer hospital_experiment.usda",
        "the hospital and its Nova Carters are online NVIDIA assets"),
    "g10_office_ros2_clock": Fails(
        "validate", "isaacsim_assets/Assets/Isaac/5.1/Isaac/Environments/Office/office.usd, the payload of /World/office",
        "the office and its Nova Carters are the author's local copy of NVIDIA's assets"),
    "g11_newton_ant_multi_sdg": Runs(),
    "g12_ogn_articulation_controller": Runs(),
    "g13_ogn_on_physics_step": Runs(),
    "g14_ogn_surface_gripper_v1": Runs((
        "v1 SurfaceGripper input 'GripThreshold' mapped to graphflow.LegacySurfaceGripper 'gripThreshold'",
        "v1 SurfaceGripper input 'ForceLimit' mapped to graphflow.LegacySurfaceGripper 'forceLimit' = 1000000.0",
        "v1 SurfaceGripper input 'TorqueLimit' mapped to graphflow.LegacySurfaceGripper 'torqueLimit' = 1000000.0",
        "v1 SurfaceGripper input 'BendAngle' mapped to graphflow.LegacySurfaceGripper 'bendAngle' = 7.5 deg -> 0.1308996938995747 rad",
        "v1 SurfaceGripper input 'Stiffness' mapped to graphflow.LegacySurfaceGripper 'kp' = 10000.0",
        "v1 SurfaceGripper input 'Damping' mapped to graphflow.LegacySurfaceGripper 'kd' = 1000.0",
        "v1 SurfaceGripper input 'DisableGravity' mapped to graphflow.LegacySurfaceGripper 'disableGravity' = True",
        "v1 SurfaceGripper input 'RetryClose' = False not mapped: graphflow's legacy gripper closes once per command")),
    "g15_ogn_gripper_controller": Runs(),
    "g16_ogn_conveyor": Runs(),
    "g17_ogn_pick_place_controller": Runs((
        "old PickPlaceController input 'robotModel' = '' mapped: the controller drives the UR10",
        "old PickPlaceController input 'usePath' = False mapped: no robot given; set robotPrim",
        "old PickPlaceController input 'robotPrimPath' = '' mapped: no robot given; set robotPrim")),
    "g18_ogn_differential_controller": Runs(),
    "g19_robotiq_gripper_ros2": Runs(),   # no robot in its controller: fails on the first /isaac_gripper_state (below)
    "g20_lite6_ros2_joint_states": Fails(
        "run", "node 'PublisherJointState': inputs:targetPrim is not set and no Isaac Read Joint State arrays are connected: nothing to publish",
        "a layer meant to be sublayered into the Lite6 asset, which fills in the robot targets"),
    "g21_finsrov_ros2": Runs((
        "node 'Pose': message field inputs header:frame_id, pose:covariance gathered into 'inputs:messageFields'",
        "node 'Dvl': message field inputs header:frame_id, twist:covariance gathered into 'inputs:messageFields'")),
    "p01_krabby_crab_hex": Loads(),
    "p02_newton_ant": Loads(),
    "p03_newton_humanoid": Loads(),
    "p04_newton_cartpole": Loads(),
    "p05_newton_mesh_articulation": Loads(),
    "p06_robotiq_2f85": Fails(
        "load", "cannot open /work/shared/isaac_corpus/files/robotiq__isaacsim_assets/geometry/geometry.usda, a sublayer "
        "of layer Robotiq_2F85_newton.usda: prims lost: every prim that layer defines"[len("cannot open /work/shared"):],
        "its geometry sublayer is not in the repository"),
    "p07_food_tray": Loads(),
    "p08_franka_isaac50": Fails(
        "load", f"cannot open {NVIDIA}5.0/Isaac/Robots/FrankaRobotics/FrankaPanda/Props/panda_hand.usd, the reference of "
        "/panda/panda_hand/geometry in layer franka.usda", "its link meshes are online NVIDIA assets"),
}


def _entries():
    if not (CORPUS / "manifest.json").is_file():
        return []
    return json.loads((CORPUS / "manifest.json").read_text())["entries"]


def _run_entry(entry, tmp_path, capsys):
    """The entry's outcome: ("runs", import lines) or ("fails at STAGE", the error lines)."""
    main_file = CORPUS / "files" / entry["main"]
    if not entry["contents"]["graphs"]:
        code = main(["stage", str(main_file)])
        return ("loads" if code == 0 else "fails at load", capsys.readouterr().err)
    lines = []
    for index, graph in enumerate(entry["contents"]["graphs"]):
        output = tmp_path / f"graph{index}.json"
        code = main(["import", str(main_file), "--graph", graph["path"], "-o", str(output)])
        err = capsys.readouterr().err
        lines.extend(err.splitlines())
        if code != 0:
            return "fails at import", err
        if main(["validate", str(output)]) != 0:
            return "fails at validate", capsys.readouterr().err
        lines.extend(line for line in capsys.readouterr().err.splitlines() if line.startswith("warning: "))
        if main(["run", str(output), "--ticks", str(TICKS)]) != 0:
            return "fails at run", capsys.readouterr().err
        capsys.readouterr()
    return "runs", "\n".join(lines)


@pytest.mark.slow
@pytest.mark.parametrize("entry", _entries(), ids=lambda entry: entry["id"])
def test_corpus_file_has_its_written_down_outcome(entry, tmp_path, capsys):
    expected = EXPECTED[entry["id"]]
    outcome, text = _run_entry(entry, tmp_path, capsys)
    if isinstance(expected, Fails):
        assert outcome == f"fails at {expected.stage}", text
        assert expected.line in text
        lines = [line for line in text.splitlines() if line.strip()]
        assert len(lines) <= 2 or all("cannot open" in line for line in lines)   # one line (per node input, per layer)
    elif isinstance(expected, Loads):
        assert outcome == "loads", text
    else:
        assert outcome == "runs", text
        for line in expected.lines:
            assert line in text


def test_every_corpus_entry_has_a_written_down_outcome_and_enough_run():
    ids = [entry["id"] for entry in _entries()]
    assert sorted(ids) == sorted(EXPECTED) and len(ids) == 29
    runnable = [name for name, outcome in EXPECTED.items() if not isinstance(outcome, Fails)]
    assert len(runnable) + len(RUN_WITHOUT_THEIR_LAYERS) >= 24


# blocked only by layers that cannot be opened: they run (or load) when told to do without them (the lines the import prints)
RUN_WITHOUT_THEIR_LAYERS = {
    "g05_spot_diffdrive_ros2": (),
    "g08_ridgeback_sensors_ros2": (
        f"node 'RenderProduct' (isaacsim.core.nodes.IsaacCreateRenderProduct): {RENDER}",
        "node 'RGBPublish' (isaacsim.ros2.bridge.ROS2CameraHelper): dropped: publishes rendered camera images",
        "node 'CameraInfoPublish' (isaacsim.ros2.bridge.ROS2CameraInfoHelper): dropped:",
        "node 'LaserScanPublish' (isaacsim.ros2.bridge.ROS2RtxLidarHelper): dropped: publishes RTX lidar scans"),
    "g09_hospital_ros2_clock": (),
    "g10_office_ros2_clock": (),
    "p06_robotiq_2f85": (),
    "p08_franka_isaac50": (),
}


@pytest.mark.slow
@pytest.mark.parametrize("entry", [e for e in _entries() if e["id"] in RUN_WITHOUT_THEIR_LAYERS],
                         ids=lambda entry: entry["id"])
def test_files_blocked_only_by_missing_layers_run_when_allowed(entry, tmp_path, capsys, monkeypatch):
    monkeypatch.setenv("GRAPHFLOW_ALLOW_MISSING_ASSETS", "1")
    outcome, text = _run_entry(entry, tmp_path, capsys)
    assert outcome == ("runs" if entry["contents"]["graphs"] else "loads"), text
    for line in RUN_WITHOUT_THEIR_LAYERS[entry["id"]]:
        assert line in text


def test_robotiq_graph_without_a_robot_fails_on_its_first_joint_command(tmp_path, capsys):
    stage = CORPUS / "files" / "pastoriomarco__isaac_sim_custom_examples" / "robotiq_action_graph.usda"
    graph = tmp_path / "robotiq.json"
    assert main(["import", str(stage), "-o", str(graph)]) == 0
    code = main(["run", str(graph), "--ticks", "30",
                 "--topic", '/isaac_gripper_state@0.25={"name": ["finger_joint"], "position": [0.4]}'])
    assert code == 1
    assert "node 'articulation_controller'" in capsys.readouterr().err


def test_gantry_without_its_gripper_prim_is_refused_before_the_first_tick(tmp_path, capsys):
    """The stage defines no /World/SurfaceGripper: run refuses it as validate does (exit 2, did-you-mean), not at tick 12."""
    stage = CORPUS / "files" / "isaac-sim__IsaacSim" / "SurfaceGripper_gantry.usda"
    graph = tmp_path / "gantry.json"
    assert main(["import", str(stage), "-o", str(graph)]) == 0
    capsys.readouterr()
    assert main(["run", str(graph), "--ticks", "30", "--pad", "Face Button Bottom=1@0.2"]) == 2
    assert capsys.readouterr().err == (f"graphflow: error: {graph}: node 'surface_gripper' input 'inputs:SurfaceGripper': "
                                       "no prim /World/SurfaceGripper on the stage (did you mean /World/Surface_Gripper_Joints?)\n")


def test_ridgeback_extended_input_takes_kits_stored_value_over_the_sublayers_empty_token(tmp_path, capsys):
    """ridgeback_robot.usda authors input0 = "" over the stage's ConstructArray; Kit reads the stored 1.0."""
    wrapper = tmp_path / "ridgeback_with_robot.usda"
    wrapper.write_text(f'''#usda 1.0
(
    subLayers = [@{CORPUS / "files" / "cezarioa__isaac-projects" / "ridgebacl_stage.usda"}@]
)

def Xform "Robot"
{{
}}

over "Graphs"
{{
    over "Velocity_Controller"
    {{
        over "ArticulationController"
        {{
            rel inputs:targetPrim = </Robot>
        }}
    }}
}}
''')
    graph = tmp_path / "ridgeback.json"
    assert main(["import", str(wrapper), "--graph", "/Graphs/Velocity_Controller", "-o", str(graph)]) == 0
    nodes = {node["name"]: node for node in json.loads(graph.read_text())["nodes"]}
    assert nodes["JointCommandArray"]["inputs"]["input0"] == 1.0
    assert nodes["JointNameArray"]["inputs"]["input0"] == "dummy_base_prismatic_x_joint"


def test_lite6_layer_without_its_robot_targets_is_warned_before_it_fails_at_run(tmp_path, capsys):
    """Issue 26: the unset targetPrim that fails at the first tick is a warning of import and validate."""
    entry = next(e for e in _entries() if e["id"] == "g20_lite6_ros2_joint_states")
    output = tmp_path / "graph.json"
    assert main(["import", str(CORPUS / "files" / entry["main"]), "--graph", entry["contents"]["graphs"][0]["path"],
                 "-o", str(output)]) == 0
    assert "node 'PublisherJointState' input 'inputs:targetPrim': required target is unset" in capsys.readouterr().err
    assert main(["validate", str(output)]) == 0
    assert "node 'PublisherJointState' input 'inputs:targetPrim': required target is unset" in capsys.readouterr().err
