"""report: what the run report costs (graphflow run --report), against the same run without one.

Recording: graphs/ur10_pick_place.json run whole with the report's recording
(the version-2 trace kept in memory: outputs, pulses, computed nodes, every moving
body's pose every tick) and without, fresh simulations, interleaved rounds, CPU
time; the ratio is recorded / plain (target at most 1.10). Then the report is
written from that recording (CPU seconds, target under 1 s) and its size measured
(target under 3 MB), and the same for ur10_pyramid's 6,757 ticks (under 10 MB;
skipped with --quick). In headless Chromium, when one is installed: wall-clock
seconds from opening the file until the page is interactive (target under 2 s)
and the median, 95th percentile and worst time of a scrub step, from setting a tick to the
panels and scene being drawn for it (target under 50 ms).
"""
from __future__ import annotations

import shutil
import statistics
import tempfile
import time
from pathlib import Path

from . import GRAPHS, clock, line, paired_ratio
from ._scenes import PICK_PLACE, quiet, require

PYRAMID = GRAPHS / "ur10_pyramid.json"
SCRUB_STEPS = 40


def _simulation(path: Path, recorded: bool):
    from graphflow.document import load_document
    from graphflow.report.recording import ReportRecording
    from graphflow.runtime import Simulation
    from graphflow.seeding import seed_everything

    document = load_document(str(path))
    seed_everything(int(document.scenario.get("seed", 0)))
    with quiet():
        sim = Simulation(document)
    recording = ReportRecording(sim, str(path)) if recorded else None
    return sim, recording, document


def _timed_run(path: Path, recorded: bool, ticks: int | None):
    sim, recording, document = _simulation(path, recorded)
    try:
        started = clock()
        sim.run(ticks=ticks, seconds=None if ticks else document.settings.get("duration"))
        return clock() - started, recording, document
    finally:
        sim.close()


def _report(path: Path, ticks: int | None, folder: Path) -> tuple[float, float]:
    """CPU seconds to write the report of one recorded run, and its size in MB."""
    _seconds, recording, document = _timed_run(path, True, ticks)
    target = folder / f"{path.stem}.html"
    started = clock()
    recording.write(target, document, force=True)
    return clock() - started, target.stat().st_size / 1e6


def _page_figures(report: Path) -> dict[str, float] | None:
    """(seconds until interactive, median and worst scrub step in ms) in headless Chromium, or None without one."""
    try:
        from playwright.sync_api import sync_playwright
    except ImportError:
        print("report: playwright is not installed; page figures skipped")
        return None
    executable = shutil.which("chromium") or shutil.which("chromium-browser")
    if executable is None:
        print("report: no Chromium installed (apt-get install chromium); page figures skipped")
        return None
    with sync_playwright() as playwright:
        browser = playwright.chromium.launch(executable_path=executable,
                                             args=["--use-gl=angle", "--use-angle=swiftshader", "--enable-unsafe-swiftshader"])
        try:
            page = browser.new_page(viewport={"width": 1600, "height": 1000})
            page.goto("about:blank")   # the browser is up, as a person's is when they open the file
            started = time.perf_counter()
            page.goto(report.resolve().as_uri())
            page.wait_for_function("window.graphflowReport !== undefined", timeout=30000, polling=5)
            interactive = time.perf_counter() - started
            steps = page.evaluate("""async (count) => {
                const report = window.graphflowReport, times = [];
                for (let i = 1; i <= count; i += 1) {
                  const tick = 1 + ((i * 7919) % report.ticks);   // spread over the run, never the same twice in a row
                  if (String(tick) === document.body.dataset.tick) continue;
                  const started = performance.now();
                  window.graphflowReport.setTick(tick);
                  while (document.body.dataset.tick !== String(tick)) await new Promise((r) => setTimeout(r, 0));
                  times.push(window.graphflowReport.drawnAt - started);
                }
                return times;
            }""", SCRUB_STEPS)
        finally:
            browser.close()
    ordered = sorted(steps)
    return {"interactive": interactive, "scrub_median": statistics.median(steps),
            "scrub_p95": ordered[int(0.95 * (len(ordered) - 1))], "scrub_worst": ordered[-1]}


def run(quick: bool = False) -> str:
    require(PICK_PLACE)
    ticks, rounds = (60, 2) if quick else (None, 5)
    samples: dict[str, list[float]] = {"recorded": [], "plain": []}
    for index in range(rounds):
        for recorded in ((True, False) if index % 2 == 0 else (False, True)):
            samples["recorded" if recorded else "plain"].append(_timed_run(PICK_PLACE, recorded, ticks)[0])
    ratio = paired_ratio(samples["recorded"], samples["plain"])
    figures = {}
    with tempfile.TemporaryDirectory(prefix="graphflow-report-bench-") as folder:
        write, size = _report(PICK_PLACE, ticks, Path(folder))
        figures.update(write=f"{write:.3f}s", size=f"{size:.2f}MB")
        if not quick and PYRAMID.exists():
            pyramid_write, pyramid_size = _report(PYRAMID, None, Path(folder))
            figures.update(pyramid_write=f"{pyramid_write:.3f}s", pyramid_size=f"{pyramid_size:.2f}MB")
        page = _page_figures(Path(folder) / f"{PICK_PLACE.stem}.html")
    if page is not None:
        figures.update(interactive=f"{page['interactive']:.2f}s", scrub=f"{page['scrub_median']:.1f}ms",
                       scrub_p95=f"{page['scrub_p95']:.1f}ms", scrub_worst=f"{page['scrub_worst']:.1f}ms")
    print(f"report: pick-and-place {'60 ticks' if quick else 'whole run'} x {rounds} rounds, recorded "
          f"{statistics.median(samples['recorded']):.2f} s vs plain {statistics.median(samples['plain']):.2f} s CPU "
          f"(targets: ratio <= 1.10, write < 1 s, < 3 MB, pyramid < 10 MB, interactive < 2 s, scrub step < 50 ms)")
    return line("report", ratio, **figures)
