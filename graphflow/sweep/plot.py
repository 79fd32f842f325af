"""``graphflow sweep plot DIR``: a success map over two parameters, or success rate against one.

Reads the results folder of ``graphflow sweep`` (``sweep.json`` and
``episodes.jsonl``), so it works on a finished, interrupted or running sweep.
The map colours each (x, y) grid cell by its success rate (or, with
``--metric``, by the median of a metric) and writes the rate and n in it; the
curve draws the rate with its 95 % Wilson interval against x, one line per y
value. matplotlib (the ``viz`` extra) draws them with the Agg backend.
"""
from __future__ import annotations

import json
import math
import re
from pathlib import Path

from graphflow.errors import require_extra
from graphflow.files import FileProblem, loads_strict, read_json
from graphflow.sweep.definition import EPISODES_JSONL, MANIFEST, Sweep, SweepError
from graphflow.sweep.results import (
    is_finite_number,
    median_or_none,
    shown_value,
    wilson_interval,
)


def read_results(folder: str) -> tuple[Sweep, list[dict]]:
    path = Path(folder)
    manifest = path / MANIFEST
    if not manifest.exists():
        raise SweepError(f"{folder}: not a sweep results folder (no {MANIFEST}; graphflow sweep --out writes one)")
    try:
        identity = read_json(manifest)["identity"]
    except (FileProblem, KeyError, TypeError) as error:
        raise SweepError(f"{manifest}: unreadable ({error})") from None
    sweep = Sweep(identity["sweep"], str(manifest), identity["graph"], "<graph>")
    records = []
    jsonl = path / EPISODES_JSONL
    if jsonl.exists():
        for line in jsonl.read_text(encoding="utf-8").splitlines():
            try:
                records.append(loads_strict(line, str(jsonl)))
            except FileProblem:
                continue   # a line cut short by an interruption
    if not records:
        raise SweepError(f"{folder}: no finished episodes yet")
    return sweep, records


def _axis_values(records, name):
    values = []
    for record in records:
        value = record["parameters"].get(name)
        if value not in values:
            values.append(value)
    if all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in values):
        values.sort()
    return values


def _key(value) -> str:
    return json.dumps(value, sort_keys=True)


def plot_command(args) -> int:
    if not args.results:
        raise SweepError("graphflow sweep plot DIR -o FILE: name the results folder")
    if not args.output:
        raise SweepError("graphflow sweep plot: -o FILE is required (.png, .svg or .pdf)")
    if Path(args.output).exists() and not args.force:
        raise SweepError(f"{args.output}: already exists; not overwriting it (use --force)")
    sweep, records = read_results(args.results)
    names = sweep.parameter_names
    if not names:
        raise SweepError(f"{args.results}: the sweep has no parameters to plot against (no grid or samples)")
    x = args.x or names[0]
    y = args.y or (next((n for n in names if n != x), None))
    for name in (x, y):
        if name is not None and name not in names:
            raise SweepError(f"{args.results}: no parameter {name!r}; the sweep has {', '.join(names)}")
    if args.metric is not None and args.metric not in sweep.metric_names:
        raise SweepError(f"{args.results}: no metric {args.metric!r}; the sweep has "
                         f"{', '.join(sweep.metric_names) or 'none'}")
    kind = args.kind or ("map" if y is not None else "curve")
    if kind == "map" and y is None:
        raise SweepError(f"{args.results}: a map needs two parameters; the sweep has only {x}")
    require_extra("graphflow sweep plot", "viz", "matplotlib")
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure

    figure = Figure(figsize=(7.5, 5.5), dpi=110)
    axes = figure.add_subplot()
    if kind == "map":
        _draw_map(figure, axes, records, x, y, args.metric)
    else:
        _draw_curve(axes, records, x, y, args.metric)
    title = re.split(r"(?<=[.?!])\s", sweep.data.get("description", ""))[0] or Path(args.results).name
    figure.suptitle(title if len(title) < 90 else title[:87] + "...", fontsize=9)
    figure.tight_layout()
    try:
        figure.savefig(args.output)
    except (OSError, ValueError) as error:
        raise SweepError(f"{args.output}: cannot write the plot: {error}") from None
    print(f"wrote {args.output}")
    return 0


def _groups(records, names):
    groups: dict[tuple, list[dict]] = {}
    for record in records:
        groups.setdefault(tuple(_key(record["parameters"].get(n)) for n in names), []).append(record)
    return groups


def _draw_map(figure, axes, records, x, y, metric):
    import numpy

    xs, ys = _axis_values(records, x), _axis_values(records, y)
    groups = _groups(records, (x, y))
    grid = numpy.full((len(ys), len(xs)), numpy.nan)
    labels = {}
    for (kx, ky), group in groups.items():
        column = [_key(v) for v in xs].index(kx)
        row = [_key(v) for v in ys].index(ky)
        if metric is None:
            passed = sum(1 for r in group if r["passed"])
            grid[row, column] = passed / len(group)
            labels[row, column] = f"{passed / len(group):.0%}\nn={len(group)}"
        else:
            value = median_or_none(sorted(r["metrics"][metric] for r in group if is_finite_number(r["metrics"].get(metric))))
            grid[row, column] = math.nan if value is None else value
            labels[row, column] = f"{shown_value(value)}\nn={len(group)}"
    if metric is None:
        image = axes.imshow(grid, origin="lower", cmap="RdYlGn", vmin=0.0, vmax=1.0, aspect="auto")
        figure.colorbar(image, ax=axes, label="success rate")
    else:
        positive = grid[numpy.isfinite(grid) & (grid > 0)]
        norm = None
        if positive.size and positive.max() / positive.min() > 100:
            from matplotlib.colors import LogNorm

            norm = LogNorm(vmin=positive.min(), vmax=positive.max())
        image = axes.imshow(grid, origin="lower", cmap="viridis_r", aspect="auto", norm=norm)
        figure.colorbar(image, ax=axes, label=f"median {metric}")
    for (row, column), text in labels.items():
        value = grid[row, column]
        red, green, blue, _alpha = image.cmap(image.norm(value)) if numpy.isfinite(value) else (1, 1, 1, 1)
        dark = 0.299 * red + 0.587 * green + 0.114 * blue < 0.5
        axes.text(column, row, text, ha="center", va="center", fontsize=7, color="white" if dark else "black")
    axes.set_xticks(range(len(xs)), [shown_value(v) for v in xs])
    axes.set_yticks(range(len(ys)), [shown_value(v) for v in ys])
    axes.set_xlabel(x)
    axes.set_ylabel(y)


def _draw_curve(axes, records, x, y, metric):
    xs = _axis_values(records, x)
    numeric = all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in xs)
    lines = _axis_values(records, y) if y is not None else [None]
    for line in lines:
        positions, values, lows, highs = [], [], [], []
        for index, value in enumerate(xs):
            group = [r for r in records if _key(r["parameters"].get(x)) == _key(value)
                     and (y is None or _key(r["parameters"].get(y)) == _key(line))]
            if not group:
                continue
            positions.append(value if numeric else index)
            if metric is None:
                passed = sum(1 for r in group if r["passed"])
                low, high = wilson_interval(passed, len(group))
                rate = passed / len(group)
                values.append(rate)
                lows.append(rate - low)
                highs.append(high - rate)
            else:
                median = median_or_none(sorted(r["metrics"][metric] for r in group if is_finite_number(r["metrics"].get(metric))))
                values.append(math.nan if median is None else median)
        label = None if y is None else f"{y} = {shown_value(line)}"
        if metric is None:
            axes.errorbar(positions, values, yerr=[lows, highs], marker="o", capsize=3, label=label)
        else:
            axes.plot(positions, values, marker="o", label=label)
    if numeric and all(v > 0 for v in xs) and max(xs) / min(xs) > 20:
        axes.set_xscale("log")
    if not numeric:
        axes.set_xticks(range(len(xs)), [shown_value(v) for v in xs])
    axes.set_xlabel(x)
    axes.set_ylabel("success rate (95 % interval)" if metric is None else f"median {metric}")
    if metric is None:
        axes.set_ylim(-0.05, 1.05)
    if y is not None:
        axes.legend(fontsize=7)
    axes.grid(alpha=0.3)
