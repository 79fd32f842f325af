"""Issue 20's contradictions, each as a user meets it: one checked run, one reader, one writer, one exit rule."""
import json
import os
import subprocess
import sys

from conftest import ROOT

from graphflow import cli

from .counter_graphs import counter_scenario


def run_cli(capsys, *args):
    code = cli.main([str(a) for a in args])
    out, err = capsys.readouterr()
    return code, out, err


def test_graphflow_test_reports_a_malformed_scenario_as_an_error_not_a_pass(tmp_path, capsys):
    (tmp_path / "ok.json").write_text(json.dumps(counter_scenario()))
    (tmp_path / "broken.json").write_text('{"format": "graphflow", "nodes": [')   # cut short
    (tmp_path / "notes.json").write_text('{"owner": "not a graph"}')              # not a graph: not a test
    code, out, _err = run_cli(capsys, "test", tmp_path, "-j", "1")
    lines = out.splitlines()
    assert code == 2
    assert lines[0] == f"ERROR {tmp_path / 'broken.json'}: {tmp_path / 'broken.json'}: malformed JSON at line 1 column 35: Expecting value"
    assert lines[1].startswith(f"PASS {tmp_path / 'ok.json'}: 1 check holds")
    assert lines[-1] == "1 passed, 1 failed"


def test_a_graph_that_looks_like_a_scenario_and_does_not_load_is_an_error(tmp_path, capsys):
    graph = counter_scenario()
    graph["nodes"][1]["type"] = "omni.graph.action.Countr"
    (tmp_path / "typo.json").write_text(json.dumps(graph))
    code, out, _err = run_cli(capsys, "test", tmp_path)
    assert code == 2
    assert out.splitlines()[0].startswith(f"ERROR {tmp_path / 'typo.json'}: ")
    assert "omni.graph.action.Countr" in out.splitlines()[0]


def test_pytest_plugin_reports_a_malformed_scenario_as_a_collection_error(tmp_path):
    (tmp_path / "ok.json").write_text(json.dumps(counter_scenario()))
    (tmp_path / "broken.json").write_text('{"format": "graphflow", "nodes": [')
    result = subprocess.run([sys.executable, "-m", "pytest", "-p", "no:cacheprovider", "-q", "--graphflow-scenarios",
                             str(tmp_path)], capture_output=True, text=True, cwd=tmp_path)
    assert result.returncode != 0
    assert "ERROR" in result.stdout and "broken.json" in result.stdout and "malformed JSON at line 1" in result.stdout


def test_a_misspelled_check_target_fails_run_before_the_first_tick(tmp_path, capsys):
    graph = json.loads((ROOT / "graphs" / "ur10_pick_place.json").read_text())
    graph["settings"]["stage"] = "asset:ur10_pick_place.usda"
    position_checks = [c for c in graph["checks"] if "prim" in c]
    position_checks[0]["prim"] = "/World/Cueb"
    path = tmp_path / "typo.json"
    path.write_text(json.dumps(graph))
    code, out, err = run_cli(capsys, "run", path, "--trace", tmp_path / "run.jsonl")
    assert code == 2 and out == ""
    assert err == (f"graphflow: error: {path}: checks[1] (position): no prim /World/Cueb on the stage "
                   "(did you mean /World/Cube?)\n")
    assert not (tmp_path / "run.jsonl").exists()   # refused before anything ran or was written


def test_a_sweep_file_is_read_as_strictly_as_a_graph(tmp_path, capsys):
    sweep = tmp_path / "sweep.json"
    sweep.write_text('{"format": "graphflow-sweep", "formatVersion": [1, 0], "graph": "g.json", "seconds": NaN}')
    code, _out, err = run_cli(capsys, "sweep", sweep)
    assert code == 2
    assert err == (f"graphflow: error: {sweep}: invalid JSON at line 1 column 86 (seconds): "
                   "NaN is not a JSON value (RFC 8259 has no NaN or Infinity)\n")
    sweep.write_text('{"seeds": 2, "seeds": 100}')
    assert run_cli(capsys, "sweep", sweep)[::2] == (2, f"graphflow: error: {sweep}: invalid JSON at line 1 column 14 (seeds): "
                                                            "duplicate key \"seeds\" in one object\n")


def test_junit_and_generated_docs_follow_the_umask(tmp_path, capsys, monkeypatch):
    (tmp_path / "ok.json").write_text(json.dumps(counter_scenario()))
    monkeypatch.chdir(tmp_path)
    previous = os.umask(0o027)
    try:
        assert run_cli(capsys, "test", "ok.json", "--junit", "junit.xml")[0] == 0
        assert run_cli(capsys, "nodes", "--markdown", "-o", "nodes.md")[0] == 0
    finally:
        os.umask(previous)
    assert {name: (tmp_path / name).stat().st_mode & 0o777 for name in ("junit.xml", "nodes.md")} == \
        {"junit.xml": 0o640, "nodes.md": 0o640}   # the umask's mode, not mkstemp's 0600


def test_validate_imports_no_pybullet():
    code = ("import sys; from graphflow.cli import main; code = main(['validate', 'graphs/ur10_pick_place.json']); "
            "sys.exit(3 if 'pybullet' in sys.modules else code)")
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT)
    assert result.returncode == 0, result.stderr
    assert result.stdout == "graphs/ur10_pick_place.json: ok\n"


def test_every_missing_extra_is_bad_input_with_its_install_line(tmp_path):
    """With the extras' modules hidden, each feature exits 2 with one line saying which extra to install."""
    hide = ("import sys, importlib.abc\n"
            "class Hide(importlib.abc.MetaPathFinder):\n"
            "    def find_spec(self, name, path, target=None):\n"
            "        if name.split('.')[0] in ('mcap', 'mcap_ros2', 'matplotlib', 'PIL', 'ray'):\n"
            "            raise ImportError(name)\n"
            "sys.meta_path.insert(0, Hide())\n"
            "from graphflow.cli import main\nsys.exit(main(sys.argv[1:]))\n")
    graph = ROOT / "graphs" / "counter_branch_print.json"
    cases = {("run", str(graph), "--record-topics", str(tmp_path / "t.mcap")): "ros",
             ("draw", str(graph), "-o", str(tmp_path / "g.png")): "viz"}
    for args, extra in cases.items():
        result = subprocess.run([sys.executable, "-c", hide, *args], capture_output=True, text=True, cwd=ROOT)
        assert result.returncode == 2, result.stderr
        assert result.stderr.count("\n") == 1 and f"pip install 'graphflow[{extra}]'" in result.stderr



def test_a_run_reads_its_stage_once_so_each_warning_is_printed_once(tmp_path):
    """The preflight's parse is handed to the world: usd-core's warnings about the stage appear once, not per read."""
    (tmp_path / "scene.usda").write_text('''#usda 1.0
(
    upAxis = "Z"
    metersPerUnit = 1
)
def PhysicsScene "physicsScene" {}
def Xform "Ghost" (prepend apiSchemas = ["PhysicsRigidBodyAPI"])
{
    double3 xformOp:translate = (0, 0, 1)
    uniform token[] xformOpOrder = ["xformOp:translate"]
}
''')
    graph = {"format": "graphflow", "formatVersion": [1, 0], "settings": {"stage": "scene.usda", "duration": 0.05},
             "nodes": [{"name": "tick", "type": "omni.graph.action.OnTick"}]}
    (tmp_path / "graph.json").write_text(json.dumps(graph))
    result = subprocess.run([sys.executable, "-m", "graphflow", "run", str(tmp_path / "graph.json")],
                            capture_output=True, text=True, cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    lines = [line for line in result.stderr.splitlines() if line.strip()]
    assert any("/Ghost" in line for line in lines), lines      # the stage's own problem is said...
    assert len(lines) == len(set(lines)), lines                # ...and every line once
