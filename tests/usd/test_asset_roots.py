"""Packaged robots from any stage: @graphflow/...@ composes in USD itself, packages add asset roots by
entry point, and graphflow new --stage ur10 writes a cell that passes its checks as written."""
import json
import logging
import os
import subprocess
import sys

import pytest
from conftest import ROOT

from graphflow.cli import main
from graphflow.usd import asset_roots as roots
from graphflow.usd.opening import open_composed

PACKAGED = ROOT / "graphflow" / "assets"
CELL = '''#usda 1.0
(
    defaultPrim = "World"
    metersPerUnit = 1
    upAxis = "Z"
)
def Xform "World"
{
    def Xform "arm" (prepend references = @ASSET@) {}
}
'''


def prim_paths(stage, under: str) -> list[str]:
    return sorted(str(p.GetPath())[len(under):] for p in stage.Traverse() if str(p.GetPath()).startswith(under + "/"))


def test_a_user_stage_composes_the_packaged_ur10_by_its_asset_path(tmp_path, monkeypatch):
    from pxr import Usd

    stage_file = tmp_path / "deep" / "cell.usda"
    stage_file.parent.mkdir()
    stage_file.write_text(CELL.replace("ASSET", "graphflow/ur10.usda"))
    monkeypatch.chdir(tmp_path)   # neither the stage's folder nor the package's
    composed = open_composed(stage_file)
    packaged = Usd.Stage.Open(str(PACKAGED / "ur10.usda"))
    arm = prim_paths(composed, "/World/arm")
    assert arm == prim_paths(packaged, "/ur10") and "/ee_link/SurfaceGripper" in arm and len(arm) > 20
    # and USD itself resolves it (the search path is installed for any Usd.Stage.Open in the process)
    assert prim_paths(Usd.Stage.Open(str(stage_file)), "/World/arm") == arm


def test_graphflow_stage_and_assets_accept_the_asset_spelling(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    assert main(["stage", "@graphflow/ur10.usda@", "--json"]) == 0
    report = json.loads(capsys.readouterr().out)
    assert report["stage"] == str(PACKAGED / "ur10.usda") and len(report["surface_grippers"]) == 1
    assert main(["assets", "--json"]) == 0
    listed = json.loads(capsys.readouterr().out)
    assert listed["graphflow"]["folder"] == str(PACKAGED) and "ur10.usda" in listed["graphflow"]["files"]


def test_a_graph_naming_a_packaged_stage_by_asset_path_validates_from_anywhere(tmp_path, monkeypatch, capsys):
    from graphflow.build import Graph

    graph = Graph.load(ROOT / "graphs" / "ur10_pick_place_tuned.json")
    graph.setting("stage", "graphflow/ur10_pick_place_tuned.usda")
    (tmp_path / "a").mkdir()
    saved = graph.save(tmp_path / "a" / "b.json")
    assert json.loads(saved.read_text())["settings"]["stage"] == "graphflow/ur10_pick_place_tuned.usda"  # not rebased
    monkeypatch.chdir(tmp_path)
    assert main(["validate", str(saved)]) == 0


@pytest.fixture
def acme_package(tmp_path, monkeypatch):
    """An installed package 'acme-robots' whose entry point registers the asset root 'acme'."""
    site = tmp_path / "site"
    (site / "acme_robots").mkdir(parents=True)
    (site / "acme_robots" / "__init__.py").write_text("")
    (site / "acme_robots" / "arm.usda").write_text((PACKAGED / "ur10.usda").read_text())
    info = site / "acme_robots-1.0.dist-info"
    info.mkdir()
    (info / "METADATA").write_text("Metadata-Version: 2.1\nName: acme-robots\nVersion: 1.0\n")
    (info / "entry_points.txt").write_text("[graphflow.assets]\nacme = acme_robots\nbroken = acme_robots.missing\n")
    monkeypatch.syspath_prepend(str(site))
    for cached in (roots.asset_roots, roots.search_folder, roots.install_search_path):
        cached.cache_clear()
    yield site / "acme_robots"
    sys.modules.pop("acme_robots", None)
    for cached in (roots.asset_roots, roots.search_folder, roots.install_search_path):
        cached.cache_clear()


def test_packages_register_asset_roots_by_entry_point(acme_package, tmp_path, caplog, capsys):
    caplog.set_level(logging.WARNING, logger="graphflow.usd.asset_roots")   # graphflow test quiets graphflow's loggers
    assert roots.asset_roots()["acme"] == acme_package
    assert "asset root broken (acme_robots.missing) skipped: ModuleNotFoundError" in caplog.text
    stage_file = tmp_path / "cell.usda"
    stage_file.write_text(CELL.replace("ASSET", "acme/arm.usda"))
    assert "/ee_link/SurfaceGripper" in prim_paths(open_composed(stage_file), "/World/arm")
    assert main(["assets"]) == 0
    assert "  @acme/arm.usda@" in capsys.readouterr().out.splitlines()


def test_an_entry_point_naming_a_built_in_module_is_skipped_with_the_reason(acme_package, caplog):
    (acme_package.parent / "acme_robots-1.0.dist-info" / "entry_points.txt").write_text(
        "[graphflow.assets]\nacme = acme_robots\nbuiltin = sys\n")
    caplog.set_level(logging.WARNING, logger="graphflow.usd.asset_roots")
    assert "builtin" not in roots.asset_roots()
    assert "asset root builtin (sys) skipped: StageError: module sys has no file, so no folder of assets" in caplog.text
    assert roots.asset_roots()["acme"] == acme_package     # the other package's root still comes through


@pytest.mark.slow
def test_new_stage_ur10_writes_a_cell_that_passes_its_checks_as_written(tmp_path, monkeypatch, capsys):
    (tmp_path / "project").mkdir()
    monkeypatch.chdir(tmp_path / "project")
    assert main(["new", "cell", "--stage", "ur10"]) == 0
    assert capsys.readouterr().out.splitlines() == ["wrote cell.usda", "wrote cell.json", "wrote graphflow.schema.json"]
    assert "@graphflow/ur10.usda@" in (tmp_path / "project" / "cell.usda").read_text()
    monkeypatch.chdir(tmp_path)   # test it from another folder, as a CI job would
    assert main(["validate", "project/cell.json"]) == 0
    assert main(["test", "project/cell.json"]) == 0
    out = capsys.readouterr().out
    assert "PASS project/cell.json: 5 checks hold" in out
    assert main(["new", "project/cell", "--stage", "ur10"]) == 2   # never overwrites the user's cell
    assert main(["new", "project/other", "--stage", "panda"]) == 2
    assert "no starter cell for 'panda' (starters: ur10)" in capsys.readouterr().err


def test_assets_link_makes_a_search_path_other_usd_tools_use(tmp_path, capsys):
    folder = tmp_path / "usd-search"
    assert main(["assets", "--link", str(folder)]) == 0
    assert capsys.readouterr().out.splitlines()[-1] == f"export PXR_AR_DEFAULT_SEARCH_PATH={folder}"
    stage_file = tmp_path / "cell.usda"
    stage_file.write_text(CELL.replace("ASSET", "graphflow/ur10.usda"))
    # a fresh process that never imports graphflow: plain usd-core with the environment variable
    script = (f"from pxr import Usd; s = Usd.Stage.Open({str(stage_file)!r}); "
              "print(s.GetPrimAtPath('/World/arm/ee_link/SurfaceGripper').IsValid())")
    result = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                            env={**os.environ, "PXR_AR_DEFAULT_SEARCH_PATH": str(folder)})
    assert result.stdout.strip() == "True", result.stderr
    (folder / "graphflow").unlink()
    (folder / "graphflow").mkdir()
    assert main(["assets", "--link", str(folder)]) == 2
    assert "exists and is not a link; not replacing it (use --force)" in capsys.readouterr().err
    assert main(["assets", "--link", str(folder), "--force"]) == 0
