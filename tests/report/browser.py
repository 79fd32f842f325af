"""Headless Chromium for the report tests (Debian's chromium driven by Playwright), or a skip naming what is missing."""
import shutil
from contextlib import contextmanager

import pytest

CHROMIUM_NAMES = ("chromium", "chromium-browser", "google-chrome")


def chromium_path() -> str:
    for name in CHROMIUM_NAMES:
        found = shutil.which(name)
        if found:
            return found
    pytest.skip("no Chromium installed: apt-get install -y chromium (Debian) to run the browser tests")


@contextmanager
def browser():
    """A Chromium with software WebGL (SwiftShader), so three.js renders on machines without a GPU."""
    try:
        from playwright.sync_api import sync_playwright
    except ImportError:
        pytest.skip("playwright is not installed: pip install -e '.[test]'")
    executable = chromium_path()
    with sync_playwright() as playwright:
        chromium = playwright.chromium.launch(executable_path=executable,
                                              args=["--use-gl=angle", "--use-angle=swiftshader", "--enable-unsafe-swiftshader"])
        try:
            yield chromium
        finally:
            chromium.close()


def open_report(chromium, path, size=(1600, 1000)):
    """A page showing the report, once its scripts have run (window.graphflowReport is set)."""
    page = chromium.new_page(viewport={"width": size[0], "height": size[1]})
    errors = []
    page.on("pageerror", lambda error: errors.append(str(error)))
    page.goto(path.resolve().as_uri())
    page.wait_for_function("window.graphflowReport !== undefined", timeout=30000)
    page.wait_for_selector(".react-flow__edge", timeout=30000)   # React Flow draws edges once it measured the nodes
    assert not errors, errors
    return page


def show_tick(page, tick: int) -> None:
    page.evaluate(f"window.graphflowReport.setTick({tick})")
    page.wait_for_function(f"document.body.dataset.tick === '{tick}'")
