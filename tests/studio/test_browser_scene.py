"""The studio's live run in headless Chromium: the report's 3D scene and lanes, fed from the live frames."""
import json
import re
import shutil

import pytest
from report.browser import browser

from graphflow.observe.trace import read_trace

from .conftest import GRAPHS, Studio
from .test_browser import open_studio

CUBE = "/World/Cube"
GRIPPER = "/World/ur10/ee_link/SurfaceGripper"
PINNED = "pick_place.event"
PHASE = "pick_place.eventName"


def value_at(trace, key, tick):
    """An output's value at a tick: its last change at or before it (tick 0: the header's value)."""
    value = trace.header["outputs"][key]
    for record in trace.ticks:
        if record["tick"] > tick:
            break
        value = record.get("outputs", {}).get(key, value)
    return value


@pytest.fixture
def pick_place(tmp_path):
    shutil.copy(GRAPHS / "ur10_pick_place.json", tmp_path / "ur10_pick_place.json")
    server = Studio(tmp_path, "ur10_pick_place.json")
    yield server
    server.stop()


def cube_position(page):
    return page.evaluate(f"window.graphflowStudio.bodyPosition({CUBE!r})")


def test_a_live_run_moves_the_cube_in_the_scene_and_draws_the_gripper_lanes(pick_place):
    with browser() as chromium:
        page = open_studio(chromium, pick_place)
        page.click("[data-action=live]")
        page.wait_for_selector("[data-testid=live-scene] canvas")
        page.wait_for_function(f"window.graphflowStudio.bodyPosition({CUBE!r}) !== null")
        start = cube_position(page)
        page.click(".react-flow__node[data-id='pick_place']")
        page.click(f"[data-pin='{PINNED}']")   # the controller's phase index, plotted in a lane as it runs
        # real time (the page's default): the lift comes 10 s in and the run ends 9 s later, ample time to pause
        # and step to a tick the trace samples however slowly this page is polled on a busy machine
        page.click("[data-action=play]")
        # lifted 5 cm off the table in the rendered scene: the gripper picked it up
        page.wait_for_function(f"window.graphflowStudio.bodyPosition({CUBE!r})[2] > {start[2] + 0.05}", timeout=180000)
        page.click("[data-action=pause]")
        page.wait_for_selector("[data-testid=live-bar][data-playing=false]")
        tick = int(page.get_attribute("[data-testid=live-bar]", "data-tick"))
        while tick % 4:   # the trace samples poses every 4th tick: compare there
            page.click("[data-action=step]")
            tick += 1
            page.wait_for_selector(f"[data-testid=live-bar][data-tick='{tick}']")
        page.wait_for_selector(f"body[data-scene-tick='{tick}']")   # the scene's bodies are placed for this tick
        shown = cube_position(page)
        pinned = page.evaluate(f"window.graphflowStudio.live.view.outputs[{PINNED!r}]")
        assert PINNED in page.inner_text("[data-testid=lanes]")
        status_titles = page.locator(f"[data-testid='status:{GRIPPER}'] title").all_text_contents()
        shown_rays = page.evaluate("window.graphflowStudio.shownRays()")
        assert page.is_visible("[data-testid=focus-rays]")
        # a lane clicked while live: its node selected, its value at the tick clicked shown
        page.click(".react-flow__node[data-id='cube_pose']")
        page.click(f"[data-testid='status:{GRIPPER}']")
        page.wait_for_selector("[data-testid=inspector][data-node=gripper]")
        status_pick = page.get_attribute(f"[data-testid=lane-pick][data-lane='status:{GRIPPER}']", "data-tick"), \
            page.get_attribute("[data-testid=lane-pick]", "data-value")
        page.click(f"[data-testid='phase:{PHASE}']")
        page.wait_for_selector("[data-testid=inspector][data-node=pick_place]")
        phase_pick = page.get_attribute(f"[data-testid=lane-pick][data-lane='phase:{PHASE}']", "data-tick"), \
            page.get_attribute("[data-testid=lane-pick]", "data-value")
        page.click("[data-action=save-trace]")
        page.wait_for_function("document.querySelector('[data-testid=live-notice]')?.innerText.startsWith('saved')")
        assert not page.errors, page.errors
    trace = read_trace(pick_place.folder / "ur10_pick_place.live.jsonl")
    samples = [record["poses"][CUBE] for record in trace.ticks if CUBE in record.get("poses", {}) and record["tick"] <= tick]
    assert shown == pytest.approx(samples[-1][:3], abs=1e-5)   # the scene shows the run's pose at that tick
    assert len({value for _tick, value in pinned}) > 1, pinned   # the phase changed while it ran
    assert all(value == value_at(trace, PINNED, at) for at, value in pinned), pinned
    closed_tick = next(record["tick"] for record in trace.ticks
                       if record.get("grippers", {}).get(GRIPPER, {}).get("status") == "Closed")
    closed_spans = [title for title in status_titles if title.startswith(f"{GRIPPER.split('/')[-1]} status: Closed")]
    assert closed_spans, status_titles
    assert re.search(rf"\(ticks {closed_tick}–", closed_spans[0]), (closed_spans, closed_tick)
    closes = [(record["tick"], record["rays"][GRIPPER]) for record in trace.ticks if GRIPPER in record.get("rays", {})]
    close_tick, close = [(at, close) for at, close in closes if at <= tick][-1]
    assert shown_rays == {"tick": close_tick, "gripper": GRIPPER, "rays": close["rays"]}   # the gripper's rays drawn live
    assert shown_rays["rays"][0]["hit"]["prim"] == CUBE
    statuses = [(record["tick"], record["grippers"][GRIPPER]["status"]) for record in trace.ticks
                if "status" in record.get("grippers", {}).get(GRIPPER, {})]
    at = int(status_pick[0])
    assert json.loads(status_pick[1]) == [status for changed, status in statuses if changed <= at][-1]
    at = int(phase_pick[0])
    assert json.loads(phase_pick[1]) == value_at(trace, PHASE, at)
