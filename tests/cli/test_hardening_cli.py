"""Issue 15, classes 4-8: no hang, run-time failures on one line, nothing overwritten, Ctrl-C, tooling edges."""
import json
import math
import os
import re
import signal
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import ROOT

from graphflow import cli
from graphflow.cli import run as cli_run
from graphflow.document import GraphError, load_document, parse_document, save_document
from graphflow.executor import GraphRuntimeError
from graphflow.observe import draw
from graphflow.runtime import Simulation

COUNTER = ROOT / "graphs" / "counter_branch_print.json"
PICK_PLACE = ROOT / "graphs" / "ur10_pick_place.json"
ON_TICK = {"name": "tick", "type": "omni.graph.action.OnTick"}



def failure_line(err: str) -> str:
    """The one line naming the node of a failed run (with its newline); the line after it is the run's summary."""
    lines = err.splitlines()
    assert len(lines) == 2 and lines[1].startswith("graphflow: FAIL "), err
    return lines[0] + "\n"

def graph(**fields) -> dict:
    return {"format": "graphflow", "formatVersion": [1, 0], "nodes": [ON_TICK], **fields}


def write(path: Path, data: dict) -> Path:
    path.write_text(json.dumps(data))
    return path


def run_cli(capsys, *args):
    code = cli.main([str(a) for a in args])
    out, err = capsys.readouterr()
    return code, out, err


def graphflow(*args, env=None, cwd=None):
    return subprocess.run([sys.executable, "-m", "graphflow", *map(str, args)], capture_output=True, text=True,
                          env=env, cwd=cwd)


def files_in(folder: Path) -> list[str]:
    """Every file left in a folder, hidden temporary files included."""
    return sorted(str(p.relative_to(folder)) for p in folder.rglob("*"))


# ---------------------------------------------------------------- 4. no hang

def arm_graph(robot_path_source: dict | None = None, robot_path: str = "/ur10", **arm_inputs) -> dict:
    nodes = [ON_TICK, {"name": "arm", "type": "isaacsim.core.nodes.IsaacArticulationController",
                       "inputs": {"robotPath": robot_path, **arm_inputs}}]
    connections = [{"src": "tick.outputs:tick", "dst": "arm.inputs:execIn"}]
    if robot_path_source is not None:
        nodes.append(robot_path_source)
        connections.append({"src": f"{robot_path_source['name']}.outputs:value", "dst": "arm.inputs:robotPath"})
    return graph(settings={"stage": "asset:ur10.usda"}, nodes=nodes, connections=connections)


def test_relative_robot_path_authored_is_refused_at_load(tmp_path, capsys):
    path = write(tmp_path / "relative.json", arm_graph(robot_path="ur10"))
    code, out, err = run_cli(capsys, "run", path, "--ticks", "3")
    assert (code, out) == (2, "")
    assert err == (f"graphflow: error: {path}: node 'arm': inputs:robotPath: 'ur10' is not an absolute "
                   f"prim path (one starts with '/')\n")


def test_relative_robot_path_computed_at_run_time_fails_fast_naming_the_node(tmp_path, capsys):
    # the value arrives through a connection, so only the world sees it: its prim lookup used to loop forever
    source = {"name": "where", "type": "omni.graph.nodes.ConstantString", "inputs": {"value": "ur10"}}
    path = write(tmp_path / "relative.json", arm_graph(source, robot_path=""))
    code, out, err = run_cli(capsys, "run", path, "--ticks", "3")
    assert (code, out) == (1, "")
    assert failure_line(err) == (f"{path}: run-time failure: node 'arm': isaacsim.core.nodes.IsaacArticulationController failed: "
                   "WorldError: ur10 is not part of an articulation\n")


def test_twenty_thousand_near_miss_types_get_bounded_hints():
    # the "did you mean" search costs about a millisecond per type: only the first 50 unknown types get one
    nodes = [{"name": f"n{i}", "type": f"omni.graph.action.Countr{i}"} for i in range(20_000)]
    with pytest.raises(GraphError) as caught:
        parse_document(graph(nodes=nodes), "big.json")
    problems = caught.value.problems
    assert len(problems) == 20_000
    hinted = [p for p in problems if "did you mean 'omni.graph.action.Counter'" in p.message]
    assert [p.node for p in hinted] == [f"n{i}" for i in range(50)]


@pytest.mark.parametrize("option, value, reason", [
    ("--seconds", "inf", "expected a finite number, got 'inf'"),
    ("--seconds", "nan", "expected a finite number, got 'nan'"),
    ("--seconds", "1e308", "expected at most 1e+07 simulated seconds, got '1e308'"),
    ("--ticks", "abc", "expected a positive integer, got 'abc'"),
    ("--fps", "inf", "expected a finite number, got 'inf'"),
    ("--speed", "nan", "expected a finite number, got 'nan'"),
])
def test_usage_errors_name_the_option(option, value, reason, capsys):
    with pytest.raises(SystemExit) as caught:
        cli.main(["run", str(COUNTER), option, value])
    assert caught.value.code == 2
    assert capsys.readouterr().err.splitlines()[-1] == f"graphflow run: error: argument {option}: {reason}"


def test_stage_simulate_huge_is_a_usage_error(capsys):
    with pytest.raises(SystemExit) as caught:
        cli.main(["stage", "asset:ur10.usda", "--simulate", "1e308"])
    assert caught.value.code == 2
    assert "argument --simulate: expected at most 1e+07 simulated seconds" in capsys.readouterr().err


# ---------------------------------------------------------------- 5. run-time failures

def test_infinite_joint_target_computed_at_run_time_exits_1_naming_the_node(tmp_path, capsys):
    # 1e308 * 10 overflows to infinity inside the graph; it must never reach the drives
    data = arm_graph()
    data["nodes"] += [
        {"name": "big", "type": "omni.graph.nodes.ConstantDouble", "inputs": {"value": 1e308}},
        {"name": "times", "type": "omni.graph.nodes.Multiply", "inputs": {"b": 10.0}},
        {"name": "targets", "type": "omni.graph.nodes.ConstructArray",
         "inputs": {"arraySize": 6, "arrayType": "double[]", "input1": 0.0, "input2": 0.0, "input3": 0.0,
                    "input4": 0.0, "input5": 0.0}}]
    data["connections"] += [
        {"src": "big.outputs:value", "dst": "times.inputs:a"},
        {"src": "times.outputs:product", "dst": "targets.inputs:input0"},
        {"src": "targets.outputs:array", "dst": "arm.inputs:positionCommand"}]
    path = write(tmp_path / "overflow.json", data)
    code, out, err = run_cli(capsys, "run", path, "--ticks", "3")
    assert (code, out) == (1, "")
    assert failure_line(err) == (f"{path}: run-time failure: node 'arm': inputs:positionCommand [inf, 0.0, 0.0, 0.0, 0.0, 0.0] "
                   "holds an infinite target; no command applied (targets must be finite; NaN leaves a joint alone)\n")


def test_nan_joint_target_still_leaves_that_joint_alone():
    document = parse_document(arm_graph(), "g.json")
    with Simulation(document) as simulation:
        before = simulation.world.joint_positions("/ur10")
        simulation.instance.set_input("arm", "positionCommand", (math.nan,) * 6)
        simulation.run(ticks=5)
        after = simulation.world.joint_positions("/ur10")
    assert max(abs(a - b) for a, b in zip(before, after)) < 1e-3   # radians: held where they were


def test_read_prim_attribute_with_empty_name_exits_1_naming_the_node(tmp_path, capsys):
    path = write(tmp_path / "read.json", graph(
        settings={"stage": "asset:ur10_pick_place.usda"},
        nodes=[ON_TICK, {"name": "say", "type": "omni.graph.ui_nodes.PrintText"},
               {"name": "read", "type": "omni.graph.nodes.ReadPrimAttribute", "inputs": {"prim": "/World/Cube", "name": ""}}],
        connections=[{"src": "tick.outputs:tick", "dst": "say.inputs:execIn"},
                     {"src": "read.outputs:value", "dst": "say.inputs:text"}]))
    code, out, err = run_cli(capsys, "run", path, "--ticks", "2")
    assert (code, out) == (1, "")
    assert failure_line(err) == f"{path}: run-time failure: node 'read': no attribute name: inputs:name is empty\n"


def test_usd_errors_reach_the_user_without_internal_names():
    from graphflow.messages import usd_message

    raw = ("\n\tError in 'pxrInternal_v0_26_11__pxrReserved__::UsdStage::_GetDefiningSpecType' at line 5492 in file "
           "/opt/USD/pxr/usd/usd/stage.cpp : 'Failed verification: ' !propName.IsEmpty() ''")
    assert usd_message(raw) == "Failed verification: ' !propName.IsEmpty()"
    assert usd_message("plain\nmessage") == "plain message"


# ---------------------------------------------------------------- 6. nothing overwritten, umask

def test_draw_refuses_an_existing_picture_unless_forced(tmp_path, capsys):
    picture = tmp_path / "graph.svg"
    picture.write_text("mine\n")
    code, _out, err = run_cli(capsys, "draw", COUNTER, "-o", picture)
    assert code == 2 and picture.read_text() == "mine\n"
    assert err == f"graphflow: error: {picture}: already exists; not overwriting it (use --force)\n"
    assert run_cli(capsys, "draw", COUNTER, "-o", picture, "--force")[0] == 0
    assert picture.read_text().startswith("<svg")
    assert files_in(tmp_path) == ["graph.svg"]


def test_plot_refuses_an_existing_image_unless_forced(tmp_path, capsys):
    trace = tmp_path / "run.jsonl"
    assert run_cli(capsys, "run", COUNTER, "--trace", trace)[0] == 0
    image = tmp_path / "run.svg"
    image.write_text("mine\n")
    code, _out, err = run_cli(capsys, "plot", trace, "-o", image)
    assert code == 2 and image.read_text() == "mine\n"
    assert "already exists; not overwriting it (use --force)" in err
    assert run_cli(capsys, "plot", trace, "-o", image, "--force")[0] == 0
    assert "<svg" in image.read_text()


def test_run_refuses_an_existing_trace_before_running(tmp_path, capsys):
    trace = tmp_path / "run.jsonl"
    trace.write_text("precious\n")
    code, out, err = run_cli(capsys, "run", COUNTER, "--trace", trace)
    assert (code, out, trace.read_text()) == (2, "", "precious\n")   # not a single tick ran
    assert err == f"graphflow: error: {trace}: already exists; not overwriting it (use --force)\n"
    assert run_cli(capsys, "run", COUNTER, "--trace", trace, "--force")[0] == 0
    assert json.loads(trace.read_text().splitlines()[0])["format"] == "graphflow-trace"


@pytest.mark.parametrize("target", ["video.gif", "frames/"])
def test_run_refuses_an_existing_recording_before_loading_the_stage(tmp_path, capsys, target):
    path = tmp_path / target
    if target.endswith("/"):
        path.mkdir()
        (path / "tick_000000.png").write_bytes(b"mine")
        kept, message = path / "tick_000000.png", "folder already holds files; not overwriting them (use --force)"
    else:
        path.write_bytes(b"mine")
        kept, message = path, "already exists; not overwriting it (use --force)"
    code, out, err = run_cli(capsys, "run", PICK_PLACE, "--ticks", "2", "--record", str(tmp_path / target))
    assert (code, out, kept.read_bytes()) == (2, "", b"mine")
    assert err.endswith(f"{message}\n") and err.count("\n") == 1


def test_written_files_follow_the_umask(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    previous = os.umask(0o027)
    try:
        assert run_cli(capsys, "new", "starter")[0] == 0
        assert run_cli(capsys, "run", "starter.json", "--trace", "run.jsonl")[0] == 0
        assert run_cli(capsys, "draw", "starter.json", "-o", "starter.mmd")[0] == 0
    finally:
        os.umask(previous)
    modes = {name: (tmp_path / name).stat().st_mode & 0o777 for name in ("starter.json", "run.jsonl", "starter.mmd")}
    assert modes == {"starter.json": 0o640, "run.jsonl": 0o640, "starter.mmd": 0o640}   # not mkstemp's 0600


def test_failed_run_keeps_the_ticks_before_the_failure(tmp_path, capsys):
    looping = write(tmp_path / "loop.json", graph(
        settings={"stepBudget": 50},
        nodes=[ON_TICK, {"name": "counter", "type": "omni.graph.action.Counter"},
               {"name": "again", "type": "omni.graph.action.Counter"}],
        connections=[{"src": "tick.outputs:tick", "dst": "counter.inputs:execIn"},
                     {"src": "counter.outputs:execOut", "dst": "again.inputs:execIn"},
                     {"src": "again.outputs:execOut", "dst": "counter.inputs:execIn"}]))
    trace = tmp_path / "loop.jsonl"
    code, _out, err = run_cli(capsys, "run", looping, "--trace", trace)
    assert code == 1 and "runaway execution loop" in failure_line(err)
    assert len(trace.read_text().splitlines()) == 1   # the header; tick 1 failed and is not written
    assert files_in(tmp_path) == ["loop.json", "loop.jsonl"]


def test_save_document_refuses_to_overwrite_without_force(tmp_path):
    document = load_document(COUNTER)
    target = tmp_path / "copy.json"
    save_document(document, target, force=False)
    with pytest.raises(ValueError, match="already exists"):
        save_document(document, target, force=False)
    save_document(document, target)   # library default: saving over your own file is fine


# ---------------------------------------------------------------- 7. Ctrl-C

def test_ctrl_c_while_running_removes_the_trace_and_exits_130(tmp_path, capsys, monkeypatch):
    real_step, ticks = Simulation.step, []

    def step_then_interrupt(simulation):
        real_step(simulation)
        ticks.append(1)
        if len(ticks) == 2:
            raise KeyboardInterrupt

    monkeypatch.setattr(Simulation, "step", step_then_interrupt)
    code, _out, err = run_cli(capsys, "run", COUNTER, "--trace", tmp_path / "run.jsonl")
    assert (code, err) == (130, "graphflow: interrupted\n")
    assert files_in(tmp_path) == []   # no trace, no temporary file


def test_ctrl_c_while_loading_exits_130(capsys, monkeypatch):
    def interrupted(_path, registry=None):
        raise KeyboardInterrupt

    monkeypatch.setattr(cli_run, "load_document", interrupted)
    assert run_cli(capsys, "run", COUNTER)[::2] == (130, "graphflow: interrupted\n")


def test_ctrl_c_while_writing_leaves_no_half_written_file(tmp_path, capsys, monkeypatch):
    real_write = draw.write

    def write_then_interrupt(picture, path, picture_format):
        real_write(picture, path, picture_format)   # the whole picture is in the temporary file...
        raise KeyboardInterrupt                      # ...and the user presses Ctrl-C before the rename

    monkeypatch.setattr(draw, "write", write_then_interrupt)
    code, _out, err = run_cli(capsys, "draw", COUNTER, "-o", tmp_path / "graph.svg")
    assert (code, err, files_in(tmp_path)) == (130, "graphflow: interrupted\n", [])


def test_ctrl_c_while_importing_the_command_exits_130(capsys, monkeypatch):
    import graphflow.__main__ as entry

    def interrupted():
        raise KeyboardInterrupt

    monkeypatch.setattr(cli, "main", interrupted)
    assert entry.main() == 130
    assert capsys.readouterr().err == "graphflow: interrupted\n"


def test_real_sigint_during_a_run(tmp_path):
    endless = write(tmp_path / "endless.json", graph(
        settings={"timeStep": 0.01},
        nodes=[ON_TICK, {"name": "say", "type": "omni.graph.ui_nodes.PrintText", "inputs": {"text": "tick"}}],
        connections=[{"src": "tick.outputs:tick", "dst": "say.inputs:execIn"}]))
    process = subprocess.Popen([sys.executable, "-m", "graphflow", "run", str(endless), "--seconds", "1e6",
                                "--trace", str(tmp_path / "run.jsonl")],
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    assert process.stdout.readline() == "tick\n"   # running: the first tick has printed
    process.send_signal(signal.SIGINT)
    _out, err = process.communicate(timeout=60)
    assert (process.returncode, err) == (130, "graphflow: interrupted\n")
    assert files_in(tmp_path) == ["endless.json"]


# ---------------------------------------------------------------- 8. tooling edges

def test_broken_third_party_node_package_is_a_warning_and_builtins_keep_working(tmp_path):
    info = tmp_path / "acme_nodes-0.1.dist-info"
    info.mkdir()
    (info / "METADATA").write_text("Metadata-Version: 2.1\nName: acme-nodes\nVersion: 0.1\n")
    (info / "entry_points.txt").write_text("[graphflow.nodes]\nacme = acme_nodes\n")
    package = tmp_path / "acme_nodes"
    package.mkdir()
    (package / "__init__.py").write_text("")
    (package / "broken.py").write_text("import a_module_nobody_installed\n")
    (package / "copycat.py").write_text(
        "from graphflow.spec import NodeSpec\n"
        "SPEC = NodeSpec(id='omni.graph.action.Counter', version=1, description='A second Counter.')\n"
        "def compute(db):\n    pass\n")
    (package / "teleport.py").write_text(
        "from graphflow.spec import NodeSpec\n"
        "SPEC = NodeSpec(id='acme.Teleport', version=1, description='Moves nothing.')\n"
        "def compute(db):\n    pass\n")
    env = {**os.environ, "PYTHONPATH": str(tmp_path)}
    listed = graphflow("nodes", env=env)
    assert listed.returncode == 0
    names = [line.split()[0] for line in listed.stdout.splitlines()]
    assert "acme.Teleport" in names and "omni.graph.action.Counter" in names
    assert listed.stderr.splitlines() == [
        "WARNING graphflow.registry: node package acme-nodes: module acme_nodes.broken skipped: "
        "ModuleNotFoundError: No module named 'a_module_nobody_installed'",
        "WARNING graphflow.registry: node package acme-nodes: module acme_nodes.copycat skipped: "
        "ValueError: node type 'omni.graph.action.Counter' is defined twice: in graphflow_nodes.counter "
        "and acme_nodes.copycat"]
    ran = graphflow("run", COUNTER, env=env)
    assert (ran.returncode, ran.stdout) == (0, "count = 1\ncount = 2\ncount reached 3: done\n")


def test_without_the_viz_extra_each_command_names_it(tmp_path):
    hidden = tmp_path / "no_viz"
    hidden.mkdir()
    for module in ("matplotlib", "PIL"):   # as if not installed
        (hidden / f"{module}.py").write_text(f"raise ModuleNotFoundError(\"No module named '{module}'\", name='{module}')\n")
    trace = tmp_path / "run.jsonl"
    assert graphflow("run", COUNTER, "--trace", trace).returncode == 0
    env = {**os.environ, "PYTHONPATH": str(hidden)}
    for args in (("plot", trace, "-o", tmp_path / "run.png"),
                 ("draw", COUNTER, "-o", tmp_path / "graph.png"),
                 ("run", PICK_PLACE, "--record", tmp_path / "run.gif")):
        result = graphflow(*args, env=env)
        assert result.returncode == 2, result.stderr
        assert result.stderr.count("\n") == 1 and "pip install 'graphflow[viz]'" in result.stderr
    assert files_in(tmp_path) == ["no_viz", "no_viz/PIL.py", "no_viz/matplotlib.py", "run.jsonl"]


def test_trace_diff_of_one_graph_spelled_two_ways_is_identical(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(ROOT)
    assert run_cli(capsys, "run", "graphs/counter_branch_print.json", "--trace", tmp_path / "a.jsonl")[0] == 0
    assert run_cli(capsys, "run", "./graphs/counter_branch_print.json", "--trace", tmp_path / "b.jsonl")[0] == 0
    code, out, _err = run_cli(capsys, "trace", "diff", tmp_path / "a.jsonl", tmp_path / "b.jsonl")
    assert (code, out) == (0, "traces are identical (3 ticks)\n")


def test_nodes_shows_whole_first_sentences(capsys):
    from graphflow.registry import default_registry

    code, out, _err = run_cli(capsys, "nodes")
    assert code == 0
    summaries = {line.split()[0]: re.split(r"\s+v\d+\s+", line, maxsplit=1)[1] for line in out.splitlines()}
    for node_type in default_registry().types():
        summary, description = summaries[node_type.spec.id], " ".join(node_type.spec.description.split())
        assert description.startswith(summary)
        rest = description[len(summary):]
        assert rest == "" or re.match(r"[.!?](\s|$)", rest), (node_type.spec.id, summary)
    assert summaries["omni.graph.action.FlipFlop"] == "Alternates: the 1st, 3rd, 5th ... execIn pulse fires 'a', the 2nd, 4th ... fires 'b'"
    assert summaries["graphflow.ReadPrimPose"].endswith("(e.g. an end-effector frame)")


OMNIGRAPH_WITH_A_BAD_VALUE = """#usda 1.0
def Xform "World"
{
    def OmniGraph "ActionGraph"
    {
        token evaluator:type = "execution"
        def OmniGraphNode "tick"
        {
            custom token node:type = "omni.graph.action.OnTick"
        }
        def OmniGraphNode "say"
        {
            custom token node:type = "omni.graph.ui_nodes.PrintText"
            custom int inputs:text = 5
        }
    }
}
"""


def test_import_errors_name_the_usda_file_position_node_and_attribute(tmp_path, capsys):
    broken = tmp_path / "broken.usda"
    broken.write_text('#usda 1.0\ndef Xform "World" {\n  def Cube "C" { double size = \n}\n')
    code, _out, err = run_cli(capsys, "import", broken)
    assert code == 2
    assert err == f"graphflow: error: {broken}: not a USD stage ({broken}:3:18: Expected }} at 'double size = ' in </World/C>)\n"
    assert "pxrInternal" not in err
    stage = tmp_path / "graph.usda"
    stage.write_text(OMNIGRAPH_WITH_A_BAD_VALUE)
    code, _out, err = run_cli(capsys, "import", stage, "-o", tmp_path / "graph.json")
    assert (code, err) == (2, f"graphflow: error: {stage}: node 'say' input 'inputs:text': expected string, got 5\n")
    assert not (tmp_path / "graph.json").exists()


def test_saving_into_another_folder_rebases_the_relative_stage(tmp_path):
    (tmp_path / "scenes").mkdir()
    (tmp_path / "scenes" / "table.usda").write_text('#usda 1.0\ndef Xform "World" {}\n')
    original = write(tmp_path / "graph.json", graph(settings={"stage": "scenes/table.usda"}))
    (tmp_path / "elsewhere" / "deeper").mkdir(parents=True)
    moved = tmp_path / "elsewhere" / "deeper" / "graph.json"
    save_document(load_document(original), moved)
    document = load_document(moved)
    assert document.settings["stage"] == "../../scenes/table.usda"
    assert (document.base_dir / document.settings["stage"]).resolve() == (tmp_path / "scenes" / "table.usda")
    save_document(load_document(original), tmp_path / "same.json")   # same folder: as authored
    assert load_document(tmp_path / "same.json").settings["stage"] == "scenes/table.usda"


def test_gif_frame_times_keep_the_requested_rate():
    from graphflow.physics.recorder import gif_frame_durations

    durations = gif_frame_durations(15, 15.0)   # GIF counts in centiseconds: 66.7 ms is 70, 70, 60, ...
    assert sum(durations) == 1000 and set(durations) == {60, 70}
    assert gif_frame_durations(4, 10.0) == [100, 100, 100, 100]


@pytest.mark.slow
def test_recorded_gif_plays_at_fps(tmp_path, capsys):
    from PIL import Image

    video = tmp_path / "run.gif"
    assert run_cli(capsys, "run", PICK_PLACE, "--ticks", "60", "--record", video, "--fps", "15")[0] == 0
    with Image.open(video) as gif:
        durations = []
        for index in range(gif.n_frames):
            gif.seek(index)
            durations.append(gif.info["duration"])
    # the first state, then every 4th tick of 60 at 60 Hz: 16 frames of 66.7 ms, GIF time being centiseconds;
    # Pillow merges frames that do not change (the arm holding still above the cube) into one longer frame
    assert durations[:8] == [70, 60, 70, 70, 60, 70, 70, 60]
    assert sum(durations) == round(16 * 1000 / 15, -1)   # 1070 ms: 15 fps to the nearest centisecond
    assert video.stat().st_mode & 0o777 == 0o666 & ~_umask()


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def test_readme_first_graph_does_what_its_description_says(tmp_path, capsys):
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    example = json.loads(re.search(r"```json\n(.*?)```", readme, re.S).group(1))
    assert example["description"].startswith("Count ticks; print the count until it reaches the variable limit (3)")
    path = write(tmp_path / "example.json", example)
    code, out, err = run_cli(capsys, "run", path)
    assert (code, out) == (0, "count = 1\ncount = 2\ncount = 3\n")
    assert err == f"graphflow: done {path}: no checks (3 ticks, 1.500 s simulated)\n"   # the summary line


def test_runtime_error_message_is_one_line_even_with_newlines_in_it():
    assert str(GraphRuntimeError("first\nsecond", "node")) == "node 'node': first\\nsecond"


@pytest.mark.parametrize("args", [
    ("run", COUNTER, "--keys", "{bad}"),
    ("run", COUNTER, "--gamepad", "{bad}"),
    ("trace", "diff", "{bad}", "{bad}"),
    ("plot", "{bad}", "-o", "{out}"),
])
def test_every_json_input_is_read_strictly(tmp_path, capsys, args):
    # scripted keys, gamepad timelines and traces go through the same reader as graph files
    bad = tmp_path / "bad.json"
    bad.write_text('{"keys": ["A@1"], "keys": [], "gamepad": []}')
    argv = [str(a).format(bad=bad, out=tmp_path / "out.png") for a in args]
    code, _out, err = run_cli(capsys, *argv)
    assert code == 2
    assert err.count("\n") == 1 and str(bad) in err
    if args[0] == "run":
        assert 'duplicate key "keys"' in err
    if os.path.exists("/dev/zero"):
        code, _out, err = run_cli(capsys, *[a.replace(str(bad), "/dev/zero") for a in argv])
        assert (code, err.count("\n")) == (2, 1) and "/dev/zero: not a regular file" in err


def test_output_piped_into_a_reader_that_stops_early_is_not_an_error(tmp_path):
    printer = write(tmp_path / "printer.json", graph(
        settings={"timeStep": 0.01},
        nodes=[ON_TICK, {"name": "say", "type": "omni.graph.ui_nodes.PrintText", "inputs": {"text": "hi"}}],
        connections=[{"src": "tick.outputs:tick", "dst": "say.inputs:execIn"}]))
    process = subprocess.Popen([sys.executable, "-m", "graphflow", "run", str(printer), "--seconds", "1e6"],
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    assert process.stdout.readline() == "hi\n"
    process.stdout.close()   # like `| head -1`
    assert process.wait(timeout=60) == 0
    assert process.stderr.read() == ""


def test_format_text_field_width_cannot_print_gigabytes(tmp_path, capsys):
    # '{value:999999999}' used to build a 1 GB line every tick (3 GB of memory, seconds per tick)
    def format_graph(format_input: dict) -> dict:
        return graph(nodes=[ON_TICK, {"name": "text", "type": "graphflow.FormatText", "inputs": {"value": 1, **format_input}},
                            {"name": "say", "type": "omni.graph.ui_nodes.PrintText"},
                            {"name": "spec", "type": "omni.graph.nodes.ConstantString", "inputs": {"value": "{value:999999999}"}}],
                     connections=[{"src": "tick.outputs:tick", "dst": "say.inputs:execIn"},
                                  {"src": "text.outputs:text", "dst": "say.inputs:text"}]
                     + ([] if format_input else [{"src": "spec.outputs:value", "dst": "text.inputs:format"}]))
    authored = write(tmp_path / "authored.json", format_graph({"format": "{value:999999999}"}))
    code, out, err = run_cli(capsys, "run", authored, "--ticks", "2")
    assert (code, out) == (2, "")
    assert err == (f"graphflow: error: {authored}: node 'text': inputs:format: field width or precision '999999999' "
                   f"is more than 1000 characters (or set from a value)\n")
    computed = write(tmp_path / "computed.json", format_graph({}))
    code, out, err = run_cli(capsys, "run", computed, "--ticks", "2")
    assert (code, out) == (1, "")
    assert err.startswith(f"{computed}: run-time failure: node 'text': inputs:format: field width or precision")
    wide_enough = write(tmp_path / "fine.json", format_graph({"format": "[{value:>8.3f}]"}))
    assert run_cli(capsys, "run", wide_enough, "--ticks", "1")[:2] == (0, "[   1.000]\n")


def test_squaring_a_variable_every_tick_stops_at_64_bits(tmp_path, capsys):
    # 3, 9, 81, ... : Python's ints never overflow, so this used to grow to millions of digits and stall
    squaring = write(tmp_path / "square.json", graph(
        variables=[{"name": "x", "type": "any", "default": 3}],
        nodes=[ON_TICK, {"name": "read", "type": "omni.graph.core.ReadVariable", "inputs": {"variableName": "x"}},
               {"name": "square", "type": "omni.graph.nodes.Multiply"},
               {"name": "write", "type": "omni.graph.core.WriteVariable", "inputs": {"variableName": "x"}}],
        connections=[{"src": "tick.outputs:tick", "dst": "write.inputs:execIn"},
                     {"src": "read.outputs:value", "dst": "square.inputs:a"},
                     {"src": "read.outputs:value", "dst": "square.inputs:b"},
                     {"src": "square.outputs:product", "dst": "write.inputs:value"}]))
    code, out, err = run_cli(capsys, "run", squaring, "--ticks", "100")
    assert (code, out) == (1, "")
    # tick 6 holds 3**32 (51 bits); its square needs 102
    assert failure_line(err) == (f"{squaring}: run-time failure: node 'square': integer overflow: the product of 51-bit and 51-bit "
                   "integers does not fit 64 bits\n")


def test_text_doubling_every_tick_stops_at_a_million_characters(tmp_path, capsys):
    doubling = write(tmp_path / "double.json", graph(
        variables=[{"name": "x", "type": "string", "default": "ab"}],
        nodes=[ON_TICK, {"name": "read", "type": "omni.graph.core.ReadVariable", "inputs": {"variableName": "x"}},
               {"name": "twice", "type": "graphflow.FormatText", "inputs": {"format": "{value}{value}"}},
               {"name": "write", "type": "omni.graph.core.WriteVariable", "inputs": {"variableName": "x"}}],
        connections=[{"src": "tick.outputs:tick", "dst": "write.inputs:execIn"},
                     {"src": "read.outputs:value", "dst": "twice.inputs:value"},
                     {"src": "twice.outputs:text", "dst": "write.inputs:value"}]))
    code, out, err = run_cli(capsys, "run", doubling, "--ticks", "100")
    assert (code, out) == (1, "")
    assert failure_line(err) == (f"{doubling}: run-time failure: node 'twice': outputs:text would be 1048576 characters, "
                   "more than 1000000\n")   # 2 * 2**19: tick 19


def test_a_value_fed_back_into_itself_stops_at_16_levels(tmp_path, capsys):
    # x = (x, x) every tick: cheap to build (shared), but a trace or print of it doubles every tick
    nesting = write(tmp_path / "nest.json", graph(
        variables=[{"name": "x", "type": "any", "default": 1}],
        nodes=[ON_TICK, {"name": "read", "type": "omni.graph.core.ReadVariable", "inputs": {"variableName": "x"}},
               {"name": "pair", "type": "omni.graph.nodes.ConstructArray", "inputs": {"arraySize": 2}},
               {"name": "write", "type": "omni.graph.core.WriteVariable", "inputs": {"variableName": "x"}}],
        connections=[{"src": "tick.outputs:tick", "dst": "write.inputs:execIn"},
                     {"src": "read.outputs:value", "dst": "pair.inputs:input0"},
                     {"src": "read.outputs:value", "dst": "pair.inputs:input1"},
                     {"src": "pair.outputs:array", "dst": "write.inputs:value"}]))
    trace = tmp_path / "nest.jsonl"
    code, out, err = run_cli(capsys, "run", nesting, "--ticks", "100", "--trace", trace)
    assert (code, out) == (1, "")
    assert failure_line(err) == f"{nesting}: run-time failure: node 'write': variable 'x': value nests more than 16 levels deep\n"
    assert len(trace.read_text().splitlines()) == 1 + 16   # header and ticks 1-16; tick 17 would nest 17 deep
