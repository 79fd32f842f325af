"""studio: what watching a live run in graphflow studio costs, against the same run headless.

Headless: graphs/ur10_pick_place.json as ``graphflow run`` runs it (the checked run, no recording),
ticks per wall-clock second over the first TICKS ticks. Studio: the same graph started from
``graphflow studio`` (a subprocess) at max speed with one page watching the frames (headless
Chromium, or a websocket client when there is no browser or with --quick), ticks per second
between the first frame and the one that reaches TICKS. ratio = studio / headless (target >= 0.90:
the live run keeps 90 % of the headless rate). Wall clock on both sides (the studio's run is on
another thread of another process). With a browser: the page's response to input while the
pyramid runs live at max speed, from typing into the palette's search to the filtered list drawn
(median and worst of a few, target under 100 ms).
"""
from __future__ import annotations

import json
import shutil
import signal
import statistics
import subprocess
import sys
import time
from urllib.parse import urlsplit

from . import GRAPHS, line
from ._scenes import PICK_PLACE, quiet, require

PYRAMID = GRAPHS / "ur10_pyramid.json"
TICKS = 900   # pick-and-place stops by itself near tick 1200
QUERIES = ("multiply", "gripper", "keyboard", "compare", "add", "print")


def _headless_rate(ticks: int) -> float:
    from graphflow.document import load_document
    from graphflow.verdicts.checked_run import CheckedRun, RunLimits

    checked = CheckedRun(load_document(PICK_PLACE), limits=RunLimits(ticks=ticks), evaluate_checks=False)
    with quiet():
        checked.preflight()
        simulation = checked.start()
    try:
        started = time.perf_counter()
        for _ in range(ticks):
            simulation.step()
        return ticks / (time.perf_counter() - started)
    finally:
        checked.close()


class _Server:
    def __init__(self, graph):
        self.process = subprocess.Popen([sys.executable, "-m", "graphflow", "studio", str(graph), "--no-browser"],
                                        stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
        self.url = self.process.stdout.readline().split(" at ", 1)[1].strip()
        parts = urlsplit(self.url)
        self.port, self.token = parts.port, parts.query.split("=", 1)[1]

    def close(self):
        self.process.send_signal(signal.SIGINT)
        self.process.wait(timeout=30)
        self.process.stdout.close()


def _rate_of_frames(frames: list[tuple[float, int]], ticks: int) -> float:
    first_time, first_tick = frames[0]
    last_time, last_tick = next((at, tick) for at, tick in frames if tick >= ticks)
    return (last_tick - first_tick) / (last_time - first_time)


def _socket_rate(server: _Server, graph, ticks: int) -> float:
    from websockets.sync.client import connect

    with connect(f"ws://127.0.0.1:{server.port}/api/live?path={graph.name}&token={server.token}") as socket:
        while json.loads(socket.recv(timeout=120))["type"] != "start":
            pass
        socket.send(json.dumps({"command": "speed", "value": None}))
        frames = [(time.perf_counter(), 0)]   # from sending play to receiving the frame past TICKS: the page's view
        socket.send(json.dumps({"command": "play"}))
        while frames[-1][1] < ticks:
            message = json.loads(socket.recv(timeout=120))
            if message["type"] == "frame" and message["tick"] > 0:
                frames.append((time.perf_counter(), message["tick"]))
        socket.send(json.dumps({"command": "pause"}))
    return _rate_of_frames(frames, ticks)


def _open_live(browser, server: _Server):
    page = browser.new_page(viewport={"width": 1600, "height": 1000})
    page.goto(server.url)
    page.wait_for_selector("body[data-studio=ready]", timeout=60000)
    page.click("[data-action=live]")
    page.wait_for_selector("[data-testid=live-bar]", timeout=60000)
    page.select_option("[data-field=speed]", "null")
    return page


def _page_rate(browser, server: _Server, ticks: int) -> float:
    page = _open_live(browser, server)
    frames = page.evaluate("""async (ticks) => {
        const bar = () => document.querySelector('[data-testid=live-bar]');
        const seen = [[performance.now() / 1000, Number(bar().dataset.tick)]];
        document.querySelector('[data-action=play]').click();
        await new Promise((resolve) => {
          new MutationObserver(() => {
            const tick = Number(bar().dataset.tick);
            if (seen[seen.length - 1][1] !== tick) seen.push([performance.now() / 1000, tick]);
            if (tick >= ticks) resolve();
          }).observe(bar(), { attributes: true });
        });
        document.querySelector('[data-action=pause]').click();
        return seen;
    }""", ticks)
    page.close()
    return _rate_of_frames([tuple(frame) for frame in frames], ticks)


def _input_latency(browser) -> list[float]:
    """Milliseconds from typing into the palette's search to the filtered list drawn, while the pyramid runs."""
    server = _Server(PYRAMID)
    try:
        page = _open_live(browser, server)
        page.click("[data-action=play]")
        page.wait_for_function("Number(document.querySelector('[data-testid=live-bar]').dataset.tick) > 60", timeout=120000)
        times = page.evaluate("""async (queries) => {
            const input = document.querySelector('[data-testid=palette] input');
            const setter = Object.getOwnPropertyDescriptor(HTMLInputElement.prototype, 'value').set;
            const times = [];
            for (const query of queries) {
              const started = performance.now();
              setter.call(input, query);
              input.dispatchEvent(new Event('input', { bubbles: true }));
              while (!Array.from(document.querySelectorAll('[data-testid=palette] li')).every(
                       (item) => item.innerText.toLowerCase().includes(query) || item.title.toLowerCase().includes(query)))
                await new Promise((resolve) => setTimeout(resolve, 0));
              await new Promise((resolve) => requestAnimationFrame(() => resolve()));
              times.push(performance.now() - started);
            }
            return times;
        }""", list(QUERIES))
        page.close()
        return times
    finally:
        server.close()


def _browser():
    try:
        from playwright.sync_api import sync_playwright
    except ImportError:
        return None
    executable = shutil.which("chromium") or shutil.which("chromium-browser")
    return (sync_playwright, executable) if executable else None


def run(quick: bool = False) -> str:
    require(PICK_PLACE)
    ticks = 120 if quick else TICKS
    headless = _headless_rate(ticks)
    found = None if quick else _browser()
    figures = {"headless": f"{headless:.0f}ticks/s"}
    server = _Server(PICK_PLACE)
    try:
        if found is None:
            live = _socket_rate(server, PICK_PLACE, ticks)
            watcher = "a websocket client"
        else:
            sync_playwright, executable = found
            with sync_playwright() as playwright:
                browser = playwright.chromium.launch(executable_path=executable, args=["--use-gl=angle", "--use-angle=swiftshader"])
                try:
                    live = _page_rate(browser, server, ticks)
                    if PYRAMID.exists():
                        latency = _input_latency(browser)
                        figures.update(input_median=f"{statistics.median(latency):.1f}ms", input_worst=f"{max(latency):.1f}ms")
                finally:
                    browser.close()
            watcher = "headless Chromium"
    finally:
        server.close()
    figures["studio"] = f"{live:.0f}ticks/s"
    print(f"studio: pick-and-place, {ticks} ticks at max speed, headless {headless:.0f} ticks/s vs live in the studio "
          f"watched by {watcher} {live:.0f} ticks/s (targets: ratio >= 0.90, input to visible change < 100 ms)")
    return line("studio", live / headless, **figures)
