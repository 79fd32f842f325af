"""``graphflow robot add`` with a fake converter (a script that writes a known converted arm), so no
converter is needed: found by --converter, by environment variable or on PATH; the missing-converter
line (exit 2); a failed conversion (exit 1); the two output shapes."""
import math
import os
import subprocess
import sys
import warnings

import pytest

from graphflow.robots.gains import NATURAL_FREQUENCY
from graphflow.usd.physics_import import load_description
from tests.robots.converted import MJCF_SOURCE, URDF_ARM, write_arm
from tests.robots.reference import carried

FAKE = f"""#!{sys.executable}
import pathlib, sys
arguments = sys.argv[1:]
source, output = pathlib.Path(arguments[0]), pathlib.Path(arguments[1])
if "broken" in source.name:
    print("[Error] could not parse the robot: line 3", file=sys.stderr)
    sys.exit(1)
output.mkdir(parents=True)
(output / "arm.usda").write_text({URDF_ARM!r})
(output / "argv.txt").write_text(" ".join(arguments[2:]))
"""


def graphflow(*args, cwd, path=None, env=None):
    environment = {key: value for key, value in os.environ.items()
                   if key not in ("GRAPHFLOW_URDF_CONVERTER", "GRAPHFLOW_MJCF_CONVERTER")}
    environment["PATH"] = path if path is not None else os.path.dirname(sys.executable)
    environment.update(env or {})
    return subprocess.run([sys.executable, "-m", "graphflow", *args], capture_output=True, text=True, cwd=cwd,
                          env=environment)


@pytest.fixture
def cell(tmp_path):
    """A folder with arm.urdf, broken.urdf and bin/urdf_usd_converter (the fake)."""
    (tmp_path / "arm.urdf").write_text("<robot name='arm'/>")
    (tmp_path / "broken.urdf").write_text("<robot name='broken'/>")
    (tmp_path / "meshes").mkdir()
    converter = tmp_path / "bin" / "urdf_usd_converter"
    converter.parent.mkdir()
    converter.write_text(FAKE)
    converter.chmod(0o755)
    return tmp_path


def drives(path):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        description = load_description(str(path))
    return {joint.rsplit("/", 1)[-1]: description.joints[joint].drive for joint in description.joints
            if description.joints[joint].drive is not None}


def test_physics_only_writes_one_layer_with_drives_by_the_rule(cell):
    (cell / "out").mkdir()
    result = graphflow("robot", "add", "arm.urdf", "-o", "out/arm.usda", "--physics-only", "--converter",
                       str(cell / "bin" / "urdf_usd_converter"), "--package", "meshes=meshes", cwd=cell)
    assert result.returncode == 0, result.stderr
    lines = result.stdout.splitlines()
    assert lines[0].startswith("converted arm.urdf with urdf_usd_converter in ")
    assert "dropped: mimic joint /arm/Physics/finger_b_joint (follows finger_a_joint): coupling dropped, " \
           "driven on its own" in lines
    assert lines[-1].startswith("wrote out/arm.usda: ")
    text = (cell / "out" / "arm.usda").read_text()
    assert "subLayers" not in text and "base_visual" not in text
    assert 'doc = "Made from arm.urdf by: graphflow robot add arm.urdf --physics-only"' in text
    shoulder = drives(cell / "out" / "arm.usda")["shoulder"]
    omega = 2 * math.pi * NATURAL_FREQUENCY
    assert shoulder.stiffness == pytest.approx(carried(0.0, math.radians(-30), (0.02, 0.02))[0] * omega ** 2,
                                               rel=1e-5)


def test_the_packages_reach_the_converter_as_absolute_folders(cell):
    graphflow("robot", "add", "arm.urdf", "--converter", str(cell / "bin" / "urdf_usd_converter"),
              "--package", "meshes=meshes", cwd=cell)
    assert (cell / "arm_usd" / "argv.txt").read_text() == f"--package meshes={cell / 'meshes'}"


def test_without_physics_only_the_converters_output_stays_whole_under_an_override_layer(cell):
    """arm.usda sublayers arm_usd/arm.usda (the converter's file, byte for byte) and adds the drives."""
    result = graphflow("robot", "add", "arm.urdf", cwd=cell, path=str(cell / "bin"))
    assert result.returncode == 0, result.stderr
    assert (cell / "arm_usd" / "arm.usda").read_text() == URDF_ARM
    assert "@./arm_usd/arm.usda@" in (cell / "arm.usda").read_text()
    assert set(drives(cell / "arm.usda")) == {"shoulder", "elbow", "finger_a_joint", "finger_b_joint"}
    assert drives(cell / "arm_usd" / "arm.usda") == {}


def test_the_environment_variable_names_the_converter_and_home_is_taken(cell):
    result = graphflow("robot", "add", "arm.urdf", "--physics-only", "--home", "shoulder=0.5", cwd=cell,
                       env={"GRAPHFLOW_URDF_CONVERTER": str(cell / "bin" / "urdf_usd_converter")})
    assert result.returncode == 0, result.stderr
    assert drives(cell / "arm.usda")["shoulder"].target_position == pytest.approx(0.5, abs=1e-6)


def test_a_missing_converter_is_one_line_saying_how_to_install_it_in_its_own_environment(cell):
    result = graphflow("robot", "add", "arm.urdf", cwd=cell)
    assert result.returncode == 2
    assert result.stderr.splitlines() == [
        "graphflow: error: urdf-usd-converter is not installed (it needs its own environment, apart from graphflow's): "
        "python3 -m venv ~/.graphflow-converters && ~/.graphflow-converters/bin/pip install urdf-usd-converter, "
        "then put ~/.graphflow-converters/bin on PATH or set "
        "GRAPHFLOW_URDF_CONVERTER=~/.graphflow-converters/bin/urdf_usd_converter"]
    assert not (cell / "arm.usda").exists()


@pytest.mark.parametrize("args, line", [
    (["robot.stl"], "robot.stl: no such file"),
    (["arm.urdf", "--converter", "nowhere/python"], "--converter: nowhere/python is not an executable file; "),
    (["arm.urdf", "--home", "shoulder"], "--home: 'shoulder' is not NAME=VALUE (a joint name and radians or metres)"),
    (["arm.urdf", "--package", "meshes"], "--package meshes: not NAME=FOLDER with an existing FOLDER"),
    (["arm.xml", "--package", "meshes=meshes"], "--package is for URDF files (package:// paths); an MJCF file names"),
])
def test_bad_input_is_one_line_and_exit_2(cell, args, line):
    (cell / "arm.xml").write_text(MJCF_SOURCE)
    result = graphflow("robot", "add", *args, cwd=cell, path=str(cell / "bin"))
    assert result.returncode == 2
    assert len(result.stderr.splitlines()) == 1 and result.stderr.startswith("graphflow: error: " + line)


def test_an_existing_output_needs_force(cell):
    (cell / "arm.usda").write_text("mine")
    result = graphflow("robot", "add", "arm.urdf", "--physics-only", cwd=cell, path=str(cell / "bin"))
    assert result.returncode == 2 and "arm.usda" in result.stderr and "--force" in result.stderr
    assert (cell / "arm.usda").read_text() == "mine"


def test_a_failed_conversion_is_exit_1_with_the_converters_last_line(cell):
    result = graphflow("robot", "add", "broken.urdf", cwd=cell, path=str(cell / "bin"))
    assert result.returncode == 1
    assert result.stderr.splitlines() == [
        f"graphflow: run-time error: urdf_usd_converter could not convert {cell / 'broken.urdf'}: "
        "[Error] could not parse the robot: line 3"]


def test_an_mjcf_file_goes_to_the_mujoco_converter_and_its_keyframe_and_sensors_are_read(cell, tmp_path_factory):
    """The fake mujoco_usd_converter writes the arm with the MJCF parts; graphflow reads arm.xml itself for
    what the USD lost: the keyframe "home" sets the pose, the sensor and the other keyframe are listed."""
    made = tmp_path_factory.mktemp("mjcf")
    write_arm(made / "arm.usda", mjcf=True)
    (cell / "arm.xml").write_text(MJCF_SOURCE)
    fake = cell / "bin" / "mujoco_usd_converter"
    fake.write_text(f"#!{sys.executable}\nimport shutil, sys\nshutil.copytree({str(made)!r}, sys.argv[2])\n")
    fake.chmod(0o755)
    result = graphflow("robot", "add", "arm.xml", "--physics-only", cwd=cell, path=str(cell / "bin"))
    assert result.returncode == 0, result.stderr
    lines = result.stdout.splitlines()
    assert "dropped: sensor shoulder_pos (jointpos): dropped (graphflow reads joint and body state through its " \
           "own nodes)" in lines
    assert any(line.startswith("drive shoulder: k 400 N m/rad, d 20 N m s/rad (MjcActuator shoulder_act), max 50 N m; "
                               "home 17.19 deg (keyframe home)") for line in lines)
    assert drives(cell / "arm.usda")["elbow"].target_position == pytest.approx(-0.6, abs=1e-6)


def test_a_failed_post_processing_leaves_nothing_behind(cell):
    """A home outside a joint's range is refused after the conversion ran: no OUT.usda, no OUT_usd folder."""
    result = graphflow("robot", "add", "arm.urdf", "--home", "elbow=1.5", cwd=cell, path=str(cell / "bin"))
    assert result.returncode == 2
    assert result.stderr.splitlines()[-1] == "graphflow: error: home of elbow: 1.5 is outside its range [-2.0944, 1.0472]"
    assert not (cell / "arm.usda").exists() and not (cell / "arm_usd").exists()
