"""The studio's target picker and its variables, checks and settings editors, in headless Chromium."""
import json
import shutil
import subprocess
import sys

import pytest
from report.browser import browser

from graphflow.document import dumps, load_document

from .conftest import GRAPHS, Studio
from .test_browser import open_studio


def validate(path):
    return subprocess.run([sys.executable, "-m", "graphflow", "validate", str(path)], capture_output=True, text=True)


@pytest.fixture
def pick_place(tmp_path):
    """A copy of the pick-and-place graph whose controller names the cube as its robot (not an articulation)."""
    data = json.loads((GRAPHS / "ur10_pick_place.json").read_text())
    controller = next(node for node in data["nodes"] if node["name"] == "pick_place")
    controller["inputs"]["robotPrim"] = "/World/Cube"
    (tmp_path / "pick.json").write_text(json.dumps(data, indent=2))
    server = Studio(tmp_path, "pick.json")
    yield server
    server.stop()


def saved(page):
    page.click("[data-action=save]")
    page.wait_for_function("document.querySelector('[data-testid=notice]')?.innerText.startsWith('saved')")


def test_a_target_is_picked_from_the_stage_prims_of_its_kind_and_saved(pick_place):
    with browser() as chromium:
        page = open_studio(chromium, pick_place)
        page.click(".react-flow__node[data-id='pick_place']")
        problem = page.wait_for_selector("[data-port-problem=robotPrim]")
        assert "not part of an articulation" in problem.inner_text()
        page.wait_for_selector("select[data-picker=robotPrim] option[value='/World/ur10']", state="attached")
        offered = page.eval_on_selector_all("select[data-picker=robotPrim] option", "options => options.map(o => o.value)")
        assert offered == ["", "/World/ur10"]   # the stage's only articulation; not its links, not the cube
        grippers = page.eval_on_selector_all("select[data-picker=gripperPrim] option", "options => options.map(o => o.value)")
        assert grippers == ["", "/World/ur10/ee_link/SurfaceGripper"]
        page.select_option("select[data-picker=robotPrim]", "/World/ur10")
        page.wait_for_selector("[data-testid=problem-count][data-count='0']")
        saved(page)
        assert not page.errors, page.errors
    path = pick_place.folder / "pick.json"
    controller = next(node for node in json.loads(path.read_text())["nodes"] if node["name"] == "pick_place")
    assert controller["inputs"]["robotPrim"] == "/World/ur10"
    assert validate(path).returncode == 0, validate(path).stdout


def test_a_variable_and_a_check_added_in_the_editors_are_saved_and_validate(tmp_path):
    shutil.copy(GRAPHS / "ur10_pick_place.json", tmp_path / "pick.json")
    server = Studio(tmp_path, "pick.json")
    try:
        with browser() as chromium:
            page = open_studio(chromium, server)
            page.click("[data-tab=variables]")
            page.click("[data-action=add-variable]")
            row = "[data-testid=variables-editor] [data-variable='0']"
            page.fill(f"{row} [data-field=variable-type]", "doubel")
            page.press(f"{row} [data-field=variable-type]", "Enter")
            error = page.wait_for_selector("[data-problem=variable-0]")
            assert "unknown attribute type 'doubel'" in error.inner_text()
            assert "variables (1)" in page.inner_text("[data-tab=variables]")
            page.fill(f"{row} [data-field=variable-type]", "double")
            page.press(f"{row} [data-field=variable-type]", "Enter")
            page.fill(f"{row} [data-field=variable-default]", "0.25")
            page.press(f"{row} [data-field=variable-default]", "Enter")
            page.wait_for_selector("[data-testid=problem-count][data-count='0']")

            page.click("[data-tab=checks]")
            page.select_option("[data-field=new-check]", "upright")
            page.click("[data-action=add-check]")
            item = "[data-testid=checks-editor] [data-check-item='6']"
            assert "'prim' is a required property" in page.wait_for_selector("[data-problem=check-6]").inner_text()
            page.select_option(f"{item} select[data-picker=check-6-prim]", "/World/Cube")
            page.fill(f"{item} [data-field=check-within]", "5")
            page.press(f"{item} [data-field=check-within]", "Enter")
            page.wait_for_selector("[data-testid=problem-count][data-count='0']")
            saved(page)
            assert not page.errors, page.errors
    finally:
        server.stop()
    path = tmp_path / "pick.json"
    data = json.loads(path.read_text())
    assert data["variables"] == [{"default": 0.25, "name": "variable1", "type": "double"}]
    assert data["checks"][-1] == {"check": "upright", "prim": "/World/Cube", "within": 5}
    assert validate(path).returncode == 0, validate(path).stdout
    assert path.read_text() == dumps(load_document(path))   # load -> save -> load is byte-identical


def test_a_bad_setting_shows_its_problem_beside_the_setting(studio):
    with browser() as chromium:
        page = open_studio(chromium, studio)
        page.click("[data-tab=settings]")
        page.fill("[data-field=setting-timeStep]", "-1")
        page.press("[data-field=setting-timeStep]", "Enter")
        problem = page.wait_for_selector("[data-problem=setting-timeStep]")
        assert "timeStep" in problem.inner_text() and "-1" in problem.inner_text()
        page.fill("[data-field=setting-timeStep]", "0.25")
        page.press("[data-field=setting-timeStep]", "Enter")
        page.wait_for_selector("[data-testid=problem-count][data-count='0']")
        assert "physics rate 4.0 Hz" in page.inner_text("[data-setting=timeStep]")
