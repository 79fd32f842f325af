"""Isaac asset URLs: a remap table opens them from a local folder without editing the user's files; what
still cannot be opened is one line naming the layer and the prims lost, and USD's C++ warnings stay quiet."""
import json
import shutil

import pytest
from conftest import CORPUS_FILES, GRAPHS, ROOT

from graphflow.cli import main
from graphflow.usd.errors import StageError
from graphflow.usd.opening import MissingLayerWarning, missing_layers_refused, open_composed

PACKAGED = ROOT / "graphflow" / "assets"
NVIDIA = "https://omniverse-content-production.s3-us-west-2.amazonaws.com/Assets/Isaac/4.5"
UR10_URL = f"{NVIDIA}/Isaac/Robots/UniversalRobots/ur10/ur10.usd"


@pytest.fixture
def mirror(tmp_path):
    """A local copy of 'NVIDIA's assets' made from the packaged UR10 (the layout Isaac's URLs have)."""
    folder = tmp_path / "isaac_mirror"
    robot = folder / "Isaac" / "Robots" / "UniversalRobots" / "ur10" / "ur10.usd"
    robot.parent.mkdir(parents=True)
    shutil.copy(PACKAGED / "ur10.usda", robot)   # text USD under .usd, as NVIDIA's crate files are read
    return folder


@pytest.fixture
def cell(tmp_path):
    """An Isaac-style cell: the packaged pick-and-place stage with its UR10 referenced by NVIDIA's URL,
    the robot in a layer of its own (so the URL sits one local layer down), and the tuned graph on it."""
    project = tmp_path / "project"
    (project / "layers").mkdir(parents=True)
    stage = (PACKAGED / "ur10_pick_place_tuned.usda").read_text()
    (project / "cell.usda").write_text(stage.replace("@./ur10.usda@", "@./layers/robot.usda@"))
    (project / "layers" / "robot.usda").write_text(
        f'#usda 1.0\n(\n    defaultPrim = "ur10"\n)\ndef Xform "ur10" (prepend references = @{UR10_URL}@) {{}}\n')
    graph = json.loads((GRAPHS / "ur10_pick_place_tuned.json").read_text())
    graph["settings"]["stage"] = "cell.usda"
    (project / "cell.json").write_text(json.dumps(graph))
    (project / "graphflow.toml.off").write_text(f'[assets.remap]\n"{NVIDIA}" = "../isaac_mirror"\n')
    return project


def test_without_a_remap_validate_fails_with_one_line_and_no_usd_warnings(cell, capfd):
    assert main(["validate", str(cell / "cell.json")]) == 2
    out, err = capfd.readouterr()
    assert err.splitlines() == [
        f"{cell / 'cell.json'}: settings/stage: {cell / 'cell.usda'}: cannot open {UR10_URL}, the reference of /ur10 in layer robot.usda: prims lost: "
        "everything that reference puts below /ur10 (map its URL prefix to a local folder in graphflow.toml "
        "[assets.remap] or GRAPHFLOW_ASSET_REMAP)"]
    assert "Warning" not in out + err and "_ReportErrors" not in out + err
    assert main(["run", str(cell / "cell.json")]) == 2   # never a run without its robot


def test_allowed_missing_layers_are_a_warning_line_then_the_graph_misses_the_robot(cell, capfd):
    with pytest.warns(MissingLayerWarning) as warned:   # the CLI prints each as one "warning:" line
        assert main(["validate", "--allow-missing-assets", str(cell / "cell.json")]) == 2
    assert str(warned[0].message).startswith(f"{cell / 'cell.usda'}: cannot open {UR10_URL}, the reference of /ur10")
    lines = capfd.readouterr().err.splitlines()
    assert lines[0] == (f"{cell / 'cell.json'}: node 'gripper' input 'inputs:endEffectorPrim': no prim "
                        "/World/ur10/ee_link on the stage (did you mean /World/ur10?)")
    assert len(lines) == 2 and not any("_ReportErrors" in line for line in lines)


@pytest.mark.slow
def test_the_project_remap_runs_the_cell_from_the_local_copy(cell, mirror, capfd):
    (cell / "graphflow.toml.off").rename(cell / "graphflow.toml")
    before = {p: p.read_bytes() for p in cell.rglob("*.usda")}
    stage = open_composed(cell / "cell.usda")
    assert stage.GetPrimAtPath("/World/ur10/ee_link/SurfaceGripper").IsValid()
    assert main(["validate", str(cell / "cell.json")]) == 0
    assert main(["test", str(cell / "cell.json")]) == 0
    assert "PASS" in capfd.readouterr().out
    assert {p: p.read_bytes() for p in cell.rglob("*.usda")} == before   # the user's files are not edited


def test_the_environment_variable_remaps_too_and_wins_over_the_file(cell, mirror, monkeypatch, tmp_path):
    (cell / "graphflow.toml").write_text(f'[assets.remap]\n"{NVIDIA}" = "/nowhere"\n')
    monkeypatch.setenv("GRAPHFLOW_ASSET_REMAP", f"{NVIDIA}={mirror}")
    assert main(["validate", str(cell / "cell.json")]) == 0
    monkeypatch.delenv("GRAPHFLOW_ASSET_REMAP")
    with missing_layers_refused(), pytest.raises(StageError, match=r"remapped by graphflow.toml or "
                                                                   r"GRAPHFLOW_ASSET_REMAP: the file is not"):
        open_composed(cell / "cell.usda")


def test_a_broken_project_file_is_one_line(cell, capsys):
    (cell / "graphflow.toml").write_text("[assets.remap\n")
    assert main(["stage", str(cell / "cell.usda")]) == 2
    assert capsys.readouterr().err.startswith(f"graphflow stage: {cell / 'graphflow.toml'}: ")


SPOT = CORPUS_FILES / "BarbaraRatto__isaac-projects" / "test_action_graph1.usda"


@pytest.mark.skipif(not SPOT.is_file(), reason="../shared/isaac_corpus is absent")
def test_a_corpus_file_whose_robot_is_an_nvidia_url_runs_from_a_local_copy(tmp_path, monkeypatch, capsys):
    """Its Spot is 5.1/Isaac/Robots/BostonDynamics/spot/spot.usd: the copy stands in for it (a UR10 here)."""
    mirror = tmp_path / "mirror"
    spot = mirror / "Isaac" / "Robots" / "BostonDynamics" / "spot" / "spot.usd"
    spot.parent.mkdir(parents=True)
    shutil.copy(PACKAGED / "ur10.usda", spot)
    graph = tmp_path / "spot.json"
    assert main(["import", str(SPOT), "-o", str(graph)]) == 0
    assert main(["validate", str(graph)]) == 2
    assert "cannot open https://omniverse-content-production.s3-us-west-2.amazonaws.com/Assets/Isaac/5.1/Isaac/" \
           "Robots/BostonDynamics/spot/spot.usd" in capsys.readouterr().err
    monkeypatch.setenv("GRAPHFLOW_ASSET_REMAP", f"https://omniverse-content-production.s3-us-west-2.amazonaws.com/"
                                                f"Assets/Isaac/5.1={mirror}")
    assert open_composed(SPOT).GetPrimAtPath("/World/spot/ee_link").IsValid()
    assert main(["validate", str(graph)]) == 0
    assert main(["run", str(graph), "--ticks", "120"]) == 0
    assert json.loads(graph.read_text())["settings"]["stage"].endswith("test_action_graph1.usda")


def test_the_longest_prefix_wins_and_omniverse_urls_map_too(tmp_path, monkeypatch):
    from graphflow.usd.remap import remap_table

    monkeypatch.setenv("GRAPHFLOW_ASSET_REMAP", f"omniverse://localhost/NVIDIA/Assets={tmp_path / 'all'};"
                                                f"omniverse://localhost/NVIDIA/Assets/Isaac/4.5={tmp_path / 'isaac'}")
    table = remap_table(tmp_path)
    assert table.apply("omniverse://localhost/NVIDIA/Assets/Isaac/4.5/Isaac/Robots/ur10.usd") == \
        str(tmp_path / "isaac" / "Isaac" / "Robots" / "ur10.usd")
    assert table.apply("omniverse://localhost/NVIDIA/Assets/Skies/sky.hdr") == str(tmp_path / "all" / "Skies" / "sky.hdr")
    assert table.apply("https://example.com/x.usd") is None
    monkeypatch.setenv("GRAPHFLOW_ASSET_REMAP", "omniverse://localhost/NVIDIA")
    with pytest.raises(StageError, match="GRAPHFLOW_ASSET_REMAP: 'omniverse://localhost/NVIDIA' is not PREFIX=FOLDER"):
        remap_table(tmp_path)


def test_a_sublayer_by_url_is_remapped_and_the_relative_paths_beside_it_still_resolve(tmp_path, mirror, monkeypatch):
    environment = mirror / "Isaac" / "Environments" / "floor.usda"
    environment.parent.mkdir(parents=True)
    environment.write_text('#usda 1.0\ndef Xform "World"\n{\n    def Cube "Floor"\n    {\n    }\n}\n')
    project = tmp_path / "cell"
    (project / "parts").mkdir(parents=True)
    (project / "parts" / "arm.usda").write_text(f'#usda 1.0\n(\n    defaultPrim = "ur10"\n)\n'
                                                f'def Xform "ur10" (prepend references = @{UR10_URL}@) {{}}\n')
    (project / "cell.usda").write_text(f'#usda 1.0\n(\n    subLayers = [@{NVIDIA}/Isaac/Environments/floor.usda@]\n)\n'
                                       'over "World"\n{\n    def Xform "arm" (prepend references = @./parts/arm.usda@)\n'
                                       '    {\n    }\n}\n')
    monkeypatch.setenv("GRAPHFLOW_ASSET_REMAP", f"{NVIDIA}={mirror}")
    with missing_layers_refused():
        stage = open_composed(project / "cell.usda")
    assert stage.GetPrimAtPath("/World/Floor").IsValid()
    assert stage.GetPrimAtPath("/World/arm/ee_link/SurfaceGripper").IsValid()
