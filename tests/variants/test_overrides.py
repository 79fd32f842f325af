"""Overrides (graphflow run --set) and seeded randomization (--randomize FILE --seed N)."""
import json
import math
import subprocess
import sys

import pytest
from conftest import ROOT

from graphflow.document import load_document
from graphflow.variants.overrides import PoseJitter, apply_node_overrides, apply_stage_overrides, parse_set
from graphflow.variants.randomize import (
    Randomization,
    load_randomization,
    variant_for_run,
)

COUNTER = ROOT / "graphs" / "counter_branch_print.json"
TUNED = ROOT / "graphs" / "ur10_pick_place_tuned.json"


def graphflow(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "graphflow", *args], capture_output=True, text=True, cwd=cwd)


def test_node_override_changes_the_run_and_leaves_the_document_alone():
    result = graphflow("run", str(COUNTER), "--set", "at_least_three.b=2")
    assert result.returncode == 0, result.stderr
    assert result.stdout.splitlines() == ["count = 1", "count reached 3: done"]
    document = load_document(COUNTER)
    changed = apply_node_overrides(document, [parse_set("at_least_three.b=5")])
    assert changed.node("at_least_three").inputs["b"] == 5
    assert document.node("at_least_three").inputs["b"] == 3


def test_a_number_typed_for_a_string_input_is_the_text_as_typed():
    document = apply_node_overrides(load_document(COUNTER), [parse_set("print_done.text=007")])
    assert document.node("print_done").inputs["text"] == "007"


@pytest.mark.parametrize("override, message", [
    ("at_least_three.operation=~", "--set at_least_three.operation=~: node 'at_least_three' input 'operation': expected one of"),
    ("at_least_thre.b=2", "--set at_least_thre.b=2: the graph has no node 'at_least_thre' (did you mean 'at_least_three'?)"),
    ("at_least_three.bb=2", "--set at_least_three.bb=2: node 'at_least_three' (omni.graph.nodes.Compare) has no input 'bb' (did you mean 'b'?)"),
    ("at_least_three.a=2", "--set at_least_three.a=2: node 'at_least_three' input 'a' is connected"),
    ("no_equals_sign", "--set no_equals_sign: expected NODE.INPUT=VALUE or /Prim/Path.attribute=VALUE"),
])
def test_bad_node_overrides_exit_2_with_one_line_naming_the_override(override, message):
    result = graphflow("run", str(COUNTER), "--set", override)
    assert result.returncode == 2
    assert result.stdout == ""
    lines = result.stderr.splitlines()
    assert len(lines) == 1 and message in lines[0], lines
    assert "Traceback" not in result.stderr


@pytest.mark.parametrize("override, message", [
    ("/World/Cube.physics:mas=2", "prim /World/Cube has no attribute 'physics:mas' (did you mean 'physics:mass'?)"),
    ("/World/Cub.physics:mass=2", "the stage has no prim /World/Cub (did you mean '/World/Cube'?)"),
    ("/World/Cube.physics:mass=[1,2]", "/World/Cube.physics:mass (float): expected a number, got [1, 2]"),
    ("/World/Cube.physics:mass=-3", "/World/Cube.physics:mass (float): must not be negative"),
    ("/World/Cube.xformOp:translate=[1,2]", "(double3): expected 3 numbers"),
])
def test_bad_stage_overrides_exit_2_naming_the_override(override, message):
    result = graphflow("run", str(TUNED), "--set", override, "--ticks", "1")
    assert result.returncode == 2
    lines = result.stderr.splitlines()
    assert len(lines) == 1 and f"--set {override}: " in lines[0] and message in lines[0], lines


def test_stage_overrides_are_what_the_parsed_stage_has_and_the_file_is_untouched():
    document = load_document(TUNED)
    scenario = variant_for_run(document, ["/World/Cube.physics:mass=2.5", "/World/Cube.xformOp:translate=[0.45, 0.35, 0.025]"], None, 0)
    with scenario.create_world() as world:
        assert world.get_attribute("/World/Cube", "physics:mass") == pytest.approx(2.5)
        assert world.prim_pose("/World/Cube")[0] == pytest.approx((0.45, 0.35, 0.025), abs=1e-7)
        assert world.description.bodies["/World/Cube"].mass.mass == pytest.approx(2.5)
    text = (ROOT / "graphflow" / "assets" / "ur10_pick_place_tuned.usda").read_text()
    assert "float physics:mass = 0.1" in text
    plain = variant_for_run(document, [], None, 0)
    with plain.create_world() as world:
        assert world.get_attribute("/World/Cube", "physics:mass") == pytest.approx(0.1)


def test_pose_jitter_moves_and_yaws_the_prim_about_its_origin():
    document = load_document(TUNED)
    scenario = variant_for_run(document, [], None, 0)
    from graphflow.variants.overrides import Variant

    moved = Variant(scenario.document, (PoseJitter("/World/Cube", (0.01, -0.02, 0.0), 90.0),))
    with moved.create_world() as world:
        position, orientation = world.prim_pose("/World/Cube")
    assert position == pytest.approx((0.41, 0.38, 0.025), abs=1e-7)
    assert orientation == pytest.approx((0.0, 0.0, math.sin(math.pi / 4), math.cos(math.pi / 4)), abs=1e-7)


def test_pose_jitter_moves_a_prim_whose_translate_op_has_no_value_yet():
    """An op in xformOpOrder without an authored value sits at the origin; the jitter moves it from there."""
    from pxr import Usd, UsdGeom

    stage = Usd.Stage.CreateInMemory()
    UsdGeom.Xform.Define(stage, "/World/Marker").AddTranslateOp(UsdGeom.XformOp.PrecisionFloat)
    apply_stage_overrides(stage, [PoseJitter("/World/Marker", (0.25, -0.5, 0.125))])
    moved = UsdGeom.Xformable(stage.GetPrimAtPath("/World/Marker")).ComputeLocalToWorldTransform(0)
    assert tuple(moved.ExtractTranslation()) == (0.25, -0.5, 0.125)


@pytest.mark.slow
def test_heavy_cube_drops_under_a_low_force_limit_and_holds_under_a_high_one():
    """The tutorial's first experiment, through overrides: 8 kg (78 N of weight) against 50 N and 200 N."""
    from graphflow.runtime import Simulation

    document = load_document(TUNED)
    errors = {}
    for limit in (50, 200):
        scenario = variant_for_run(document, ["gripper.disableGravity=false", f"gripper.forceLimit={limit}",
                                               "/World/Cube.physics:mass=8"], None, 0)
        with Simulation(scenario.document, world=scenario.create_world()) as simulation:
            result = simulation.run(seconds=30)
            assert result.stopped_by_graph
            errors[limit] = math.dist(simulation.world.prim_pose("/World/Cube")[0], (-0.4, 0.5, 0.025))
    assert errors[50] > 0.5      # dropped on the way: far from the place position
    assert errors[200] < 0.05    # carried all the way (a 2.5 cm drop at the place)


def _randomization(tmp_path, entries):
    path = tmp_path / "scenario.json"
    path.write_text(json.dumps({"randomize": entries}))
    return path


def test_draws_depend_only_on_seed_and_entry(tmp_path):
    jitter = {"pose": "/World/Cube", "offset": {"uniform": [[-0.03, -0.03, 0], [0.03, 0.03, 0]]},
              "yawDegrees": {"normal": [0, 20], "clip": [-45, 45]}}
    mass = {"set": "/World/Cube.physics:mass", "logUniform": [0.05, 2.0]}
    alone = load_randomization(_randomization(tmp_path, [mass]))
    both = load_randomization(_randomization(tmp_path, [mass, jitter]))
    first, second = both.draw(7), both.draw(7)
    assert first == second
    assert both.draw(8) != first
    assert alone.draw(7)[0].value == first[0].value
    for seed in range(50):
        value = both.draw(seed)[0].value
        assert 0.05 <= value <= 2.0
        pose = both.draw(seed)[1]
        assert all(-0.03 <= c <= 0.03 for c in pose.offset[:2]) and pose.offset[2] == 0.0
        assert -45 <= pose.yaw_degrees <= 45


def test_choice_and_uniform_cover_their_range(tmp_path):
    randomization = Randomization(({"set": "gripper.kp", "choice": [1, 2, 3]},), "test")
    assert {randomization.draw(seed)[0].value for seed in range(60)} == {1, 2, 3}


@pytest.mark.parametrize("entry, message", [
    ({"set": "/World/Cube.physics:mass", "logUniform": [0, 1]}, "randomize/0: logUniform: both bounds must be positive"),
    ({"set": "/World/Cube.physics:mass", "uniform": [2, 1]}, "randomize/0: uniform: low must not exceed high"),
    ({"pose": "/World/Cube", "offset": {"uniform": [0, 1]}}, "randomize/0: offset: the bounds must be lists of three"),
    ({"set": "/World/Cube.physics:mass"}, "randomize/0"),
])
def test_bad_randomization_exits_2_naming_file_and_entry(tmp_path, entry, message):
    path = _randomization(tmp_path, [entry])
    result = graphflow("run", str(TUNED), "--randomize", str(path), "--ticks", "1")
    assert result.returncode == 2
    lines = result.stderr.splitlines()
    assert len(lines) == 1 and str(path) in lines[0] and message in lines[0], lines


def test_same_seed_gives_a_byte_identical_trace_in_two_processes(tmp_path):
    path = _randomization(tmp_path, [
        {"pose": "/World/Cube", "offset": {"uniform": [[-0.03, -0.03, 0], [0.03, 0.03, 0]]}, "yawDegrees": {"uniform": [-30, 30]}},
        {"set": "/World/Cube.physics:mass", "logUniform": [0.05, 0.5]},
        {"set": "gripper.gripThreshold", "uniform": [0.015, 0.025]}])
    traces = []
    for name, seed in (("a", "3"), ("b", "3"), ("c", "4")):
        trace = tmp_path / f"{name}.jsonl"
        result = graphflow("run", str(TUNED), "--randomize", str(path), "--seed", seed, "--ticks", "240",
                           "--trace", str(trace))
        assert result.returncode == 0, result.stderr
        traces.append(trace.read_bytes())
    assert traces[0] == traces[1]
    assert traces[0] != traces[2]
