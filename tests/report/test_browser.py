"""What a person sees when they open a report in a real browser (headless Chromium): names, values, motion, verdict."""
import json
import math

import pytest

from graphflow.observe.trace import read_trace

from .browser import browser, open_report, show_tick

CUBE = "/World/Cube"


@pytest.fixture(scope="module")
def chromium():
    with browser() as running:
        yield running


def trace_value(trace, key, tick):
    value = trace.header["outputs"][key]
    for record in trace.ticks:
        if record["tick"] > tick:
            break
        value = record.get("outputs", {}).get(key, value)
    return value


def test_every_node_is_shown_by_name(chromium, pick_place_run):
    page = open_report(chromium, pick_place_run["report"])
    names = set(read_trace(pick_place_run["trace"]).header["nodes"])
    shown = {element.inner_text() for element in page.locator(".gf-node .gf-node-name").all()}
    assert shown == names
    page.close()


def test_the_picking_position_wire_shows_the_traced_value_at_tick_500(chromium, pick_place_run):
    page = open_report(chromium, pick_place_run["report"])
    show_tick(page, 500)
    label = page.locator('[data-wire="cube_pose.position"]')
    label.wait_for()
    assert label.count() == 1
    expected = trace_value(read_trace(pick_place_run["trace"]), "cube_pose.position", 500)
    assert json.loads(label.get_attribute("data-value")) == expected
    shown = [float(text) for text in label.inner_text().strip("[]").split(", ")]   # 4 significant digits
    assert all(math.isclose(a, b, rel_tol=1e-3, abs_tol=1e-6) for a, b in zip(shown, expected))
    page.close()


def test_the_rendered_cube_moves_with_the_run(chromium, pick_place_run):
    """The cube rests at (0.3, 0.3) at tick 100 and has been carried away by tick 800: the scene and its pixels change."""
    page = open_report(chromium, pick_place_run["report"])
    scene = page.locator('[data-testid="scene"] canvas')
    show_tick(page, 100)
    before, before_pixels = page.evaluate(f"window.graphflowReport.bodyPosition('{CUBE}')"), scene.screenshot()
    show_tick(page, 800)
    after, after_pixels = page.evaluate(f"window.graphflowReport.bodyPosition('{CUBE}')"), scene.screenshot()
    assert math.dist(before[:2], (0.3, 0.3)) < 1e-3
    assert math.dist(before, after) > 0.1
    assert before_pixels != after_pixels
    page.close()


def test_the_failing_check_is_marked_at_its_time_with_its_reason(chromium, pick_misses_run):
    page = open_report(chromium, pick_misses_run["report"])
    ticks = read_trace(pick_misses_run["trace"]).ticks[-1]["tick"]
    held = page.locator('.gf-verdict li[data-check="0"]')
    assert held.get_attribute("data-passed") == "false"
    text = held.inner_text()
    assert text.startswith("FAIL") and "holding nothing at t = 9.500 s" in text and "nearest hit /World/Cube" in text
    mark = page.locator('.gf-failure-mark[data-check="0"]')
    assert int(mark.get_attribute("data-tick")) == 570            # 9.5 s at 60 ticks a second
    plot = page.locator(".gf-lane-plot").bounding_box()
    line = mark.bounding_box()
    assert abs((line["x"] + line["width"] / 2 - plot["x"]) / plot["width"] - 570 / ticks) < 0.01
    held.click()                                                   # a click jumps there
    page.wait_for_function("document.body.dataset.tick === '570'")
    assert "tick 570" in page.locator('[data-testid="tick"]').inner_text()
    page.close()


def test_the_gripper_ray_and_its_nearest_hit_are_shown_on_the_close(chromium, pick_misses_run):
    trace = read_trace(pick_misses_run["trace"])
    close = next(record["tick"] for record in trace.ticks if "rays" in record)
    page = open_report(chromium, pick_misses_run["report"])
    show_tick(page, close - 1)
    assert page.evaluate("window.graphflowReport.shownRays()") is None
    show_tick(page, close)
    ray = page.locator('[data-testid="rays"] li')
    assert ray.count() == 1
    text = ray.inner_text()
    assert "reach 9.0 mm" in text and "nearest hit /World/Cube at 23." in text and "beyond reach" in text
    shown = page.evaluate("window.graphflowReport.shownRays()")
    assert shown["tick"] == close and shown["rays"][0]["hit"]["prim"] == CUBE
    page.close()


def test_keys_step_and_play(chromium, pick_place_run):
    page = open_report(chromium, pick_place_run["report"])
    show_tick(page, 10)
    page.keyboard.press("ArrowRight")
    page.wait_for_function("document.body.dataset.tick === '11'")
    page.keyboard.press("Shift+ArrowLeft")
    page.wait_for_function("document.body.dataset.tick === '1'")
    page.keyboard.press("m")
    page.keyboard.press(" ")
    page.wait_for_function("Number(document.body.dataset.tick) > 30")
    page.keyboard.press(" ")
    page.close()


def test_clicking_a_node_shows_its_outputs_over_time(chromium, pick_place_run):
    page = open_report(chromium, pick_place_run["report"])
    show_tick(page, 500)
    page.locator('.gf-node[data-node="pick_place"]').click()
    panel = page.locator('[data-testid="node-panel"]')
    assert panel.get_attribute("data-node") == "pick_place"
    phase = panel.locator('[data-output="pick_place.eventName"]')
    expected = trace_value(read_trace(pick_place_run["trace"]), "pick_place.eventName", 500)
    assert f'eventName = "{expected}"' in phase.inner_text()
    assert "computed 500 time(s) up to tick 500" in panel.inner_text()
    page.close()
