"""report: what the run report costs (graphflow run --report), against the same run without one.

Recording: graphs/ur10_pick_place.json run whole as ``graphflow run`` runs it (the
checked run: its checks judged every tick and at the end) with the report's recording
(the version-2 trace kept in memory: outputs, pulses, computed nodes, every moving
body's pose every 4th tick) and without, fresh simulations, interleaved rounds, CPU
time; the ratio is recorded / plain (target at most 1.10). ``bare_ratio`` is the same
for the bare simulation, nothing judged (a smaller denominator). The recording captures
each tick during the run and encodes the records when they are read, so the
encoding is timed too (``encode``) and ``with_encoding`` is (recorded run +
encoding) / plain: what the whole trace costs. Then the report is written from a
recording (CPU seconds, encoding included, target under 1 s) and its size measured
(target under 3 MB), and the same for ur10_pyramid's 6,757 ticks (under 10 MB;
skipped with --quick). In headless Chromium, when one is installed, each of
``PAGE_LOADS`` fresh browsers (one with --quick) opens the file once: wall-clock seconds until the page
is interactive (median and worst; target under 2 s), and beside it what the
browser's first WebGL context alone takes (software GL: SwiftShader), timed on an
empty page of another fresh browser; then the median, 95th percentile and worst
time of a scrub step, from setting a tick to the panels and scene being drawn for
it (target under 50 ms).
"""
from __future__ import annotations

import gc
import os
import shutil
import statistics
import tempfile
import time
from pathlib import Path

from . import GRAPHS, clock, line, paired_ratio
from ._scenes import PICK_PLACE, quiet, require

PYRAMID = GRAPHS / "ur10_pyramid.json"
SCRUB_STEPS = 40
PAGE_LOADS = 3      # fresh browsers, each opening the report once


def _timed_run(path: Path, recorded: bool, ticks: int | None, checked: bool = True):
    """(CPU seconds of the run, CPU seconds encoding its recorded records (0 without), recording, document).

    *checked*: the run as ``graphflow run`` makes it (``CheckedRun``: preflight, world, its checks judged
    every tick and at the end); else the bare simulation, nothing judged."""
    from graphflow.document import load_document
    from graphflow.report.recording import ReportRecording
    from graphflow.runtime import Simulation
    from graphflow.seeding import seed_everything
    from graphflow.verdicts.checked_run import CheckedRun, RunLimits

    document = load_document(str(path))
    run_checked = CheckedRun(document, limits=RunLimits(ticks=ticks)) if checked else None
    with quiet():
        if run_checked is not None:
            run_checked.preflight()
            sim = run_checked.start()
        else:
            seed_everything(int(document.scenario.get("seed", 0)))
            sim = Simulation(document)
    recording = ReportRecording(sim, str(path)) if recorded else None
    gc.collect()   # the previous run's garbage is collected now, not on this run's clock
    try:
        started = clock()
        if run_checked is not None:
            run_checked.run()
        else:
            sim.run(ticks=ticks, seconds=None if ticks else document.settings.get("duration"))
        ran = clock() - started
        if recording is None:
            return ran, 0.0, recording, document
        started = clock()
        _records = recording.records   # reading them encodes the captured ticks
        return ran, clock() - started, recording, document
    finally:
        sim.close()


def _report(path: Path, ticks: int | None, folder: Path) -> tuple[float, float]:
    """CPU seconds to write the report of one recorded run, and its size in MB."""
    _seconds, _encoding, recording, document = _timed_run(path, True, ticks)
    target = folder / f"{path.stem}.html"
    started = clock()
    recording.write(target, document, force=True)
    return clock() - started, target.stat().st_size / 1e6


def _page_figures(report: Path, loads: int) -> dict[str, float] | None:
    """Interactive seconds (median, worst), first WebGL context seconds, scrub step ms (median, p95, worst); None
    without a browser."""
    try:
        from playwright.sync_api import sync_playwright
    except ImportError:
        print("report: playwright is not installed; page figures skipped")
        return None
    executable = shutil.which("chromium") or shutil.which("chromium-browser")
    if executable is None:
        print("report: no Chromium installed (apt-get install chromium); page figures skipped")
        return None
    interactive, first_gl, steps = [], [], []
    with sync_playwright() as playwright:
        for _load in range(loads):
            first_gl.append(_first_gl_context(playwright, executable))
            seconds, scrubbed = _open_and_scrub(playwright, executable, report)
            interactive.append(seconds)
            steps.extend(scrubbed)
    ordered = sorted(steps)
    return {"interactive": statistics.median(interactive), "interactive_worst": max(interactive),
            "first_gl": statistics.median(first_gl), "scrub_median": statistics.median(steps),
            "scrub_p95": ordered[int(0.95 * (len(ordered) - 1))], "scrub_worst": ordered[-1]}


def _browser(playwright, executable):
    return playwright.chromium.launch(executable_path=executable,
                                      args=["--use-gl=angle", "--use-angle=swiftshader", "--enable-unsafe-swiftshader"])


def _first_gl_context(playwright, executable) -> float:
    """Seconds a fresh browser takes to make its first WebGL 2 context (on an empty page): the scene pays it."""
    browser = _browser(playwright, executable)
    try:
        page = browser.new_page()
        page.goto("about:blank")
        return page.evaluate("""() => {
            const started = performance.now();
            const gl = document.createElement("canvas").getContext("webgl2", { antialias: true });
            gl.finish();
            return (performance.now() - started) / 1000;
        }""")
    finally:
        browser.close()


def _open_and_scrub(playwright, executable, report: Path) -> tuple[float, list[float]]:
    browser = _browser(playwright, executable)
    try:
        # the browser is up, as a person's is when they open the file, and the report is this tab's first
        # document (navigating from about:blank first, Chrome tears that page's compositor down a second
        # later: with software GL that blocked the report for 0.3-0.6 s in about two loads of five)
        page = browser.new_page(viewport={"width": 1600, "height": 1000})
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
    return interactive, steps


def run(quick: bool = False) -> str:
    require(PICK_PLACE)
    ticks, rounds = (60, 2) if quick else (None, 9)
    samples: dict[str, list[float]] = {"recorded": [], "plain": [], "encode": [], "bare_recorded": [], "bare": []}
    for index in range(rounds):
        for recorded in ((True, False) if index % 2 == 0 else (False, True)):
            seconds, encoding, _recording, _document = _timed_run(PICK_PLACE, recorded, ticks)
            samples["recorded" if recorded else "plain"].append(seconds)
            if recorded:
                samples["encode"].append(encoding)
            bare, _encoding, _recording, _document = _timed_run(PICK_PLACE, recorded, ticks, checked=False)
            samples["bare_recorded" if recorded else "bare"].append(bare)
    ratio = paired_ratio(samples["recorded"], samples["plain"])
    whole = [run + encode for run, encode in zip(samples["recorded"], samples["encode"])]
    figures = {"with_encoding": f"{paired_ratio(whole, samples['plain']):.2f}",
               "bare_ratio": f"{paired_ratio(samples['bare_recorded'], samples['bare']):.2f}",
               "encode": f"{statistics.median(samples['encode']):.3f}s"}
    with tempfile.TemporaryDirectory(prefix="graphflow-report-bench-") as folder:
        write, size = _report(PICK_PLACE, ticks, Path(folder))
        figures.update(write=f"{write:.3f}s", size=f"{size:.2f}MB")
        if not quick and PYRAMID.exists():
            pyramid_write, pyramid_size = _report(PYRAMID, None, Path(folder))
            figures.update(pyramid_write=f"{pyramid_write:.3f}s", pyramid_size=f"{pyramid_size:.2f}MB")
        page = _page_figures(Path(folder) / f"{PICK_PLACE.stem}.html", 1 if quick else PAGE_LOADS)
    if page is not None:
        figures.update(interactive=f"{page['interactive']:.2f}s", interactive_worst=f"{page['interactive_worst']:.2f}s",
                       first_gl=f"{page['first_gl']:.2f}s", scrub=f"{page['scrub_median']:.1f}ms",
                       scrub_p95=f"{page['scrub_p95']:.1f}ms", scrub_worst=f"{page['scrub_worst']:.1f}ms")
    print(f"report: pick-and-place {'60 ticks' if quick else 'whole run'} x {rounds} rounds, recorded "
          f"{statistics.median(samples['recorded']):.3f} s (+ {statistics.median(samples['encode']):.3f} s encoding "
          f"the records) vs plain {statistics.median(samples['plain']):.3f} s CPU, load average "
          f"{os.getloadavg()[0]:.1f} (targets: ratio <= 1.10, write < 1 s, < 3 MB, pyramid < 10 MB, "
          f"interactive < 2 s, scrub step < 50 ms)")
    return line("report", ratio, **figures)
