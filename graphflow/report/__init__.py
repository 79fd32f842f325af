"""The offline run report: one self-contained HTML file showing a run (``graphflow run --report``).

The page (built from ``frontend/`` into ``bundle/report.html``, so installing
graphflow needs no Node) shows the graph with values on its wires, the 3D scene,
lanes and the verdict on one scrubbable timeline. Python's part is the data:
``build.run_data`` turns a trace (docs/trace.md) plus the graph's layout and
verdict into the JSON the page reads, and ``page.write_report`` embeds it.
"""
from graphflow.report.build import RunInfo, run_data
from graphflow.report.page import render_report, write_report

__all__ = ["RunInfo", "render_report", "run_data", "write_report"]
