"""The studio in headless Chromium (as the report's browser tests): edit and save a graph, drive the gantry live."""
import json
import shutil
import subprocess
import sys

import pytest
from report.browser import browser

from graphflow.observe.trace import read_trace

from .conftest import GRAPHS, Studio


def open_studio(chromium, studio, size=(1600, 1000)):
    page = chromium.new_page(viewport={"width": size[0], "height": size[1]})
    errors = []
    page.on("pageerror", lambda error: errors.append(str(error)))
    page.goto(studio.url)
    page.wait_for_selector("body[data-studio=ready]", timeout=30000)
    page.wait_for_selector(".react-flow__edge", timeout=30000)
    page.errors = errors
    return page


def add_from_palette(page, query, type_id):
    page.fill("[data-testid=palette] input", query)
    page.click(f"[data-testid=palette] li[data-type='{type_id}'] button")


def drag_connection(page, source, output, target, input_):
    handle = page.locator(f".react-flow__node[data-id='{source}'] [data-port='outputs:{output}']")
    handle.drag_to(page.locator(f".react-flow__node[data-id='{target}'] [data-port='inputs:{input_}']"))


def test_edit_connect_set_an_input_see_a_type_error_and_save_a_file_that_validates(studio, studio_folder):
    with browser() as chromium:
        page = open_studio(chromium, studio)
        add_from_palette(page, "multiply", "omni.graph.nodes.Multiply")
        page.wait_for_selector(".react-flow__node[data-id='multiply']")
        page.locator(".react-flow__node[data-id='multiply']").drag_to(page.locator(".react-flow__pane"),
                                                                        target_position={"x": 700, "y": 80})
        drag_connection(page, "counter", "count", "multiply", "a")
        page.wait_for_function("window.graphflowStudio.file.data.connections.some(c => c.dst === 'multiply.inputs:a')")
        page.click(".react-flow__node[data-id='multiply']")
        page.fill("[data-testid=inspector] input[data-input=b]", "2")
        page.press("[data-testid=inspector] input[data-input=b]", "Enter")
        page.wait_for_selector("[data-testid=problem-count][data-count='0']")
        drag_connection(page, "counter", "count", "branch", "execIn")   # int into an execution input
        notice = page.locator("[data-testid=notice]")
        assert "type error" in notice.inner_text() and "execution" in notice.inner_text()
        page.click("[data-action=save]")
        page.wait_for_function("document.querySelector('[data-testid=notice]')?.innerText.startsWith('saved')")
        assert not page.errors, page.errors
    saved = studio_folder / "counter.json"
    data = json.loads(saved.read_text())
    multiply = next(node for node in data["nodes"] if node["name"] == "multiply")
    assert multiply["inputs"] == {"b": 2}
    assert {"src": "counter.outputs:count", "dst": "multiply.inputs:a"} in data["connections"]
    assert not any(c["dst"] == "branch.inputs:execIn" and c["src"] == "counter.outputs:count" for c in data["connections"])
    validated = subprocess.run([sys.executable, "-m", "graphflow", "validate", str(saved)], capture_output=True, text=True)
    assert validated.returncode == 0, validated.stdout + validated.stderr


def test_a_problem_is_marked_on_the_node_and_port_it_names(studio):
    with browser() as chromium:
        page = open_studio(chromium, studio)
        page.click(".react-flow__node[data-id='at_least_three']")
        page.fill("[data-testid=inspector] input[data-field=name]", "counter")   # a name already taken
        page.press("[data-testid=inspector] input[data-field=name]", "Enter")
        page.wait_for_selector("[data-testid=problem-count]:not([data-count='0'])")
        assert page.locator(".gf-has-problem").count() >= 1


def test_a_second_tab_saving_the_same_file_gets_the_conflict_and_its_difference(studio, studio_folder):
    with browser() as chromium:
        first, second = open_studio(chromium, studio), open_studio(chromium, studio)
        for page, name in ((first, "first"), (second, "second")):
            page.click(".react-flow__node[data-id='format_count']")
            page.fill("[data-testid=inspector] input[data-field=name]", f"format_{name}")
            page.press("[data-testid=inspector] input[data-field=name]", "Enter")
            page.wait_for_selector("[data-testid=problem-count][data-count='0']")
        first.click("[data-action=save]")
        first.wait_for_function("document.querySelector('[data-testid=notice]')?.innerText.startsWith('saved')")
        second.click("[data-action=save]")
        conflict = second.wait_for_selector("[data-testid=conflict]")
        text = conflict.inner_text()
        assert "changed on disk" in text and "format_first" in text and "format_second" in text
    assert "format_first" in (studio_folder / "counter.json").read_text()


@pytest.fixture
def gantry(tmp_path):
    for name in ("gantry_keyboard.json", "gantry_keyboard.keys.json"):
        shutil.copy(GRAPHS / name, tmp_path / name)
    server = Studio(tmp_path, "gantry_keyboard.json")
    yield server
    server.stop()


def step(page, ticks):
    for _ in range(ticks):
        now = int(page.get_attribute("[data-testid=live-bar]", "data-tick"))
        page.click("[data-action=step]")
        page.wait_for_selector(f"[data-testid=live-bar][data-tick='{now + 1}']")


def wire_value(page, wire):
    return json.loads(page.get_attribute(f"[data-wire='{wire}']", "data-value"))


def test_keys_pressed_in_the_page_drive_the_gantry_live(gantry):
    with browser() as chromium:
        page = open_studio(chromium, gantry)
        page.click("[data-action=live]")
        page.wait_for_selector("[data-testid=live-bar]")
        step(page, 5)
        y_start = wire_value(page, "y_target.value")
        page.keyboard.down("ArrowUp")
        step(page, 10)
        page.keyboard.up("ArrowUp")
        step(page, 3)
        y_now = wire_value(page, "y_target.value")
        assert y_now - y_start == pytest.approx(10 * 0.005, abs=1e-12)   # 5 mm of target per tick held
        page.keyboard.press("KeyA")
        step(page, 5)
        status = page.inner_text("[data-gripper-field=status]")
        assert "Clos" in status, status
        page.click("[data-action=save-trace]")
        page.wait_for_function("document.querySelector('[data-testid=live-notice]')?.innerText.startsWith('saved')")
        assert not page.errors, page.errors
    trace = read_trace(gantry.folder / "gantry_keyboard.live.jsonl")
    assert [value for _t, value in trace.series("y_target.value")][-1] == y_now
    statuses = {value for path in trace.gripper_paths for _t, value in trace.gripper_series(path, "status")}
    assert statuses & {"Closing", "Closed"}


def test_the_page_reloads_the_graph_when_it_changes_on_disk(studio, studio_folder):
    with browser() as chromium:
        page = open_studio(chromium, studio)
        page.wait_for_selector("body[data-watch-polls]")   # one watch poll has seen the file as opened
        path = studio_folder / "counter.json"
        data = json.loads(path.read_text())
        data["nodes"].append({"name": "added_on_disk", "type": "omni.graph.nodes.Add"})
        path.write_text(json.dumps(data, indent=2))
        page.wait_for_selector(".react-flow__node[data-id='added_on_disk']", timeout=30000)
        assert "reloaded" in page.inner_text("[data-testid=notice]")


def test_the_report_mode_of_the_shared_bundle_requests_nothing_from_the_network(tmp_path):
    """The bundle holds the studio's API calls too; opened as a report it must still load nothing."""
    report = tmp_path / "counter.html"
    made = subprocess.run([sys.executable, "-m", "graphflow", "run", str(GRAPHS / "counter_branch_print.json"),
                           "--report", str(report)], capture_output=True, text=True)
    assert made.returncode == 0, made.stderr
    with browser() as chromium:
        page = chromium.new_page()
        requested = []
        page.on("request", lambda request: requested.append(request.url))
        page.goto(report.as_uri())
        page.wait_for_function("window.graphflowReport !== undefined", timeout=30000)
        page.wait_for_selector(".react-flow__edge", timeout=30000)
    assert [url for url in requested if not url.startswith(("file:", "data:", "blob:"))] == []
