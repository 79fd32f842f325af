"""studio: what watching a live run in graphflow studio costs, against the same run headless.

Headless: graphs/ur10_pick_place.json as ``graphflow run`` runs it (the checked run, its checks judged,
no recording), ticks per wall-clock second over the first TICKS ticks. Studio: the same graph started
from ``graphflow studio`` (a subprocess) at max speed with one watcher: a websocket client, headless
Chromium showing the page, and the same page not drawn (its root ``display: none``: no layout or
painting, its scripts still take every frame and update the page). A watcher's rate is TICKS over the
wall time from play (the page's click; for the socket, the frame answering play) to the first frame at
TICKS as the watcher receives it: the frame interval and the page's delay count against the studio. Each repeat
measures headless then live (play, then reset for the next): ratio = median over repeats of live /
headless of the same repeat (target >= 0.90 with one browser watching). On a machine shared with
other work the wall-clock ratio is noisy, so each watcher also gives cpu_ratio: headless CPU seconds
per tick / the studio process's (every thread) per tick during the live run, what the server side
costs whatever else runs. With a browser: the CPU Chromium used during the drawn and undrawn runs (CPU-seconds per wall second, of this machine's
cores), and the page's response to input while the pyramid runs live at max speed, from typing into
the palette's search to the filtered list drawn (median and worst of a few, target under 100 ms); and
Chromium's cores while the page watches the pyramid play in real time for a few seconds (watching_1x).
"""
from __future__ import annotations

import json
import os
import shutil
import signal
import statistics
import subprocess
import sys
import time
from dataclasses import dataclass
from urllib.parse import urlsplit

from . import GRAPHS, line
from ._scenes import PICK_PLACE, quiet, require

PYRAMID = GRAPHS / "ur10_pyramid.json"
TICKS = 1100   # pick-and-place stops by itself at tick 1127
REPEATS = 5
QUERIES = ("multiply", "gripper", "keyboard", "compare", "add", "print")


def _headless_rate(ticks: int) -> tuple[float, float]:
    """(ticks per wall second, CPU seconds per tick) of the headless run."""
    from graphflow.document import load_document
    from graphflow.verdicts.checked_run import CheckedRun

    checked = CheckedRun(load_document(PICK_PLACE))
    with quiet():
        checked.preflight()
        simulation = checked.start()
    try:
        started, cpu = time.perf_counter(), time.process_time()
        for _ in range(ticks):
            simulation.step()
        return ticks / (time.perf_counter() - started), (time.process_time() - cpu) / ticks
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
    """Ticks per second from the start (the last sighting of tick 0) to the first frame at *ticks*."""
    first_time = max(at for at, tick in frames if tick == 0)
    last_time, last_tick = next((at, tick) for at, tick in frames if tick >= ticks)
    return last_tick / (last_time - first_time)


class _SocketWatcher:
    """A websocket client taking every frame, and nothing else."""

    def __init__(self, server: _Server, graph):
        from websockets.sync.client import connect

        self.socket = connect(f"ws://127.0.0.1:{server.port}/api/live?path={graph.name}&token={server.token}")
        self._until("start")
        self.socket.send(json.dumps({"command": "speed", "value": None}))

    def _until(self, kind: str) -> dict:
        while (message := json.loads(self.socket.recv(timeout=120)))["type"] != kind:
            pass
        return message

    def play(self, ticks: int) -> list[tuple[float, int]]:
        """Play at max speed until a frame at *ticks*: (arrival time, tick) of every frame."""
        started = time.perf_counter()
        self.socket.send(json.dumps({"command": "play"}))
        while not (message := self._until("frame"))["playing"]:
            started = time.perf_counter()   # frames sent before play was taken
        frames = [(started, 0), (time.perf_counter(), message["tick"])]   # its first frame may have merged ticks into it
        while frames[-1][1] < ticks:
            frames.append((time.perf_counter(), self._until("frame")["tick"]))
        return frames

    def reset(self) -> None:
        # paused first, as the page's watcher does: a run reset while playing plays on, and its frames would be
        # taken for the next repeat's (a run caught between tick TICKS and its end at 1127 was)
        self.socket.send(json.dumps({"command": "pause"}))
        self.socket.send(json.dumps({"command": "reset"}))
        self._until("start")

    def close(self):
        self.socket.close()


class _PageWatcher:
    """The studio page in headless Chromium, live; *hidden*: not drawn (headless Chromium has no tab to hide it behind)."""

    def __init__(self, browser, server: _Server, *, hidden: bool = False):
        self.page = _open_live(browser, server)
        if hidden:
            self.page.add_style_tag(content="#root { display: none !important; }")

    def play(self, ticks: int) -> list[tuple[float, int]]:
        """Click play, watch the live bar's tick until *ticks*: (time, tick) of every change seen."""
        frames = self.page.evaluate("""async (ticks) => {
            const bar = () => document.querySelector('[data-testid=live-bar]');
            const seen = [[performance.now() / 1000, 0]];
            document.querySelector('[data-action=play]').click();
            await new Promise((resolve) => {
              new MutationObserver((records, observer) => {
                const tick = Number(bar().dataset.tick);
                if (!seen.length || seen[seen.length - 1][1] !== tick) seen.push([performance.now() / 1000, tick]);
                if (tick >= ticks) { observer.disconnect(); resolve(); }
              }).observe(bar(), { attributes: true });
            });
            document.querySelector('[data-action=pause]').click();
            return seen;
        }""", ticks)
        return [tuple(frame) for frame in frames]

    def reset(self) -> None:
        self.page.evaluate("document.querySelector('[data-action=reset]').click()")   # clickable undrawn too
        self.page.wait_for_function("document.querySelector('[data-testid=live-bar]').dataset.tick === '0'", polling=50,
                                    timeout=60000)

    def close(self):
        self.page.close()


def _open_live(browser, server: _Server):
    page = browser.new_page(viewport={"width": 1600, "height": 1000})
    page.goto(server.url)
    page.wait_for_selector("body[data-studio=ready]", timeout=60000)
    page.click("[data-action=live]")
    page.wait_for_selector("[data-testid=live-bar]", timeout=60000)
    page.select_option("[data-field=speed]", "null")
    return page


def _cpu_seconds(pid) -> float:
    """User + system CPU seconds of process *pid* so far (every thread)."""
    with open(f"/proc/{pid}/stat", encoding="ascii") as stat:
        fields = stat.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def _descends_from(pid: str, ancestor: int) -> bool:
    while pid not in ("0", "1"):
        with open(f"/proc/{pid}/stat", encoding="ascii") as stat:
            pid = stat.read().rsplit(")", 1)[1].split()[1]
        if int(pid) == ancestor:
            return True
    return False


def _chromium_cpu_seconds() -> float:
    """User + system CPU seconds of this benchmark's Chromium processes (the browser, GPU, renderers)."""
    total = 0.0
    for pid in filter(str.isdigit, os.listdir("/proc")):
        try:
            if "chrom" not in os.path.basename(os.path.realpath(f"/proc/{pid}/exe")) or not _descends_from(pid, os.getpid()):
                continue
            total += _cpu_seconds(pid)
        except OSError:
            continue
    return total


@dataclass
class _Measured:
    """Medians over the repeats: live / headless wall rates, live ticks/s, headless / studio CPU per tick, Chromium's cores."""

    ratio: float
    rate: float
    cpu_ratio: float
    chromium_cores: float | None


def _measure(watcher, server: _Server, ticks: int, repeats: int, browser: bool = False) -> _Measured:
    ratios, rates, cpu_ratios, cores = [], [], [], []
    for _ in range(repeats):
        headless, headless_cpu = _headless_rate(ticks)
        server_cpu, chromium, started = _cpu_seconds(server.process.pid), _chromium_cpu_seconds() if browser else 0.0, \
            time.perf_counter()
        frames = watcher.play(ticks)
        wall, reached = time.perf_counter() - started, frames[-1][1]
        studio_cpu = (_cpu_seconds(server.process.pid) - server_cpu) / reached
        if browser:
            cores.append((_chromium_cpu_seconds() - chromium) / wall)
        watcher.reset()
        live = _rate_of_frames(frames, ticks)
        ratios.append(live / headless)
        rates.append(live)
        cpu_ratios.append(headless_cpu / studio_cpu)
    return _Measured(statistics.median(ratios), statistics.median(rates), statistics.median(cpu_ratios),
                     statistics.median(cores) if cores else None)


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


def _watching_cores(browser, seconds: float = 3.0) -> float:
    """Chromium's cores while the drawn page watches the pyramid play live in real time (frames at their steady
    rate, every panel busy): what watching costs per second, less at the mercy of other load than a wall ratio."""
    server = _Server(PYRAMID)
    try:
        page = _open_live(browser, server)
        page.select_option("[data-field=speed]", "1")
        page.click("[data-action=play]")
        page.wait_for_function("Number(document.querySelector('[data-testid=live-bar]').dataset.tick) > 60", timeout=120000)
        cpu, started = _chromium_cpu_seconds(), time.perf_counter()
        time.sleep(seconds)
        cores = (_chromium_cpu_seconds() - cpu) / (time.perf_counter() - started)
        page.close()
        return cores
    finally:
        server.close()


def _browser():
    try:
        from playwright.sync_api import sync_playwright
    except ImportError:
        return None
    executable = shutil.which("chromium") or shutil.which("chromium-browser")
    return (sync_playwright, executable) if executable else None


def _with_browser(found, server: _Server, ticks: int, repeats: int, figures: dict) -> float:
    sync_playwright, executable = found
    with sync_playwright() as playwright:
        browser = playwright.chromium.launch(executable_path=executable, args=["--use-gl=angle", "--use-angle=swiftshader"])
        try:
            for hidden in (False, True):
                watcher = _PageWatcher(browser, server, hidden=hidden)
                try:
                    measured = _measure(watcher, server, ticks, repeats, browser=True)
                finally:
                    watcher.close()
                name = "undrawn" if hidden else "page"
                figures.update({f"{name}_ratio": f"{measured.ratio:.2f}", name: f"{measured.rate:.0f}ticks/s",
                                f"{name}_cpu_ratio": f"{measured.cpu_ratio:.2f}",
                                f"{name}_chromium": f"{measured.chromium_cores:.2f}cores"})
                if not hidden:
                    visible = measured.ratio
            if PYRAMID.exists():
                latency = _input_latency(browser)
                figures.update(input_median=f"{statistics.median(latency):.1f}ms", input_worst=f"{max(latency):.1f}ms",
                               watching_1x=f"{_watching_cores(browser):.2f}cores")
        finally:
            browser.close()
    return visible


def run(quick: bool = False) -> str:
    require(PICK_PLACE)
    ticks, repeats = (120, 1) if quick else (TICKS, REPEATS)
    found = None if quick else _browser()
    figures: dict[str, str] = {}
    server = _Server(PICK_PLACE)
    try:
        watcher = _SocketWatcher(server, PICK_PLACE)
        try:
            measured = _measure(watcher, server, ticks, repeats)
        finally:
            watcher.close()
        figures.update(socket_ratio=f"{measured.ratio:.2f}", socket=f"{measured.rate:.0f}ticks/s",
                       socket_cpu_ratio=f"{measured.cpu_ratio:.2f}")
        ratio = _with_browser(found, server, ticks, repeats, figures) if found is not None else measured.ratio
    finally:
        server.close()
    headless, _cpu = _headless_rate(ticks)
    figures = {"headless": f"{headless:.0f}ticks/s", **figures}
    watcher_name = "headless Chromium" if found is not None else "a websocket client"
    print(f"studio: pick-and-place, {ticks} ticks at max speed, median of {repeats} repeats; ratio = live in the studio "
          f"watched by {watcher_name} / headless, wall clock (targets: ratio >= 0.90, input to visible change < 100 ms); "
          "cpu_ratio = headless CPU per tick / the studio process's CPU per tick")
    return line("studio", ratio, **figures)
