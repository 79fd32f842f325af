"""A sweep's results folder (episodes.jsonl, episodes.csv, summary tables) and the success statistics."""
from __future__ import annotations

import csv
import io
import json
import math
from pathlib import Path
from typing import Sequence

from graphflow.files import FileProblem, loads_strict, read_json, write_text
from graphflow.sweep.definition import (
    EPISODES_CSV,
    EPISODES_JSONL,
    MANIFEST,
    SUMMARY_CSV,
    SUMMARY_JSON,
    Sweep,
    SweepError,
)
from graphflow.verdicts.rates import wilson_interval

# ------------------------------------------------------------------ results folder

class ResultsFolder:
    """``--out DIR``: the manifest, and the episode tables appended one whole line per finished episode."""

    def __init__(self, path: Path, sweep: Sweep):
        self.path = path
        self.sweep = sweep
        self.columns = (["episode", "key", "point", "seed"] + sweep.parameter_names
                        + ["passed", "failures"] + sweep.metric_names + ["warnings", "ticks", "time", "finished", "wall"])

    @property
    def jsonl(self) -> Path:
        return self.path / EPISODES_JSONL

    def existing(self) -> bool:
        return (self.path / MANIFEST).exists() or self.jsonl.exists()

    def start(self, *, resume: bool, force: bool) -> list[dict]:
        """Prepare the folder; return the records it already has (when resuming)."""
        if self.path.exists() and not self.path.is_dir():
            raise SweepError(f"{self.path}: exists and is not a folder")
        if self.existing() and not (resume or force):
            raise SweepError(f"{self.path}: already holds sweep results; --resume finishes them, "
                             "--force starts over, or choose another --out")
        self.path.mkdir(parents=True, exist_ok=True)
        manifest = self.path / MANIFEST
        if resume and self.existing():
            if not manifest.exists():
                raise SweepError(f"{manifest}: missing, so the results cannot be matched to the sweep; use --force")
            try:
                stored = read_json(manifest)
            except FileProblem as error:
                raise SweepError(f"{manifest}: unreadable ({error}); use --force") from None
            if stored.get("identity") != json.loads(json.dumps(self.sweep.identity())):
                raise SweepError(f"{self.path}: was started with a different sweep or graph; "
                                 "--force starts over, or choose another --out")
            records = self._read_records()
            _write_atomically(self.path / EPISODES_CSV, self._csv_text(records, header=True))
            return records
        for name in (EPISODES_JSONL, EPISODES_CSV, SUMMARY_CSV, SUMMARY_JSON):
            (self.path / name).unlink(missing_ok=True)
        _write_atomically(manifest, json.dumps({"format": "graphflow-sweep-results", "formatVersion": [1, 0],
                                                "source": self.sweep.source, "identity": self.sweep.identity()},
                                               indent=2) + "\n")   # key order kept: it orders grid points
        _write_atomically(self.path / EPISODES_CSV, self._csv_text([], header=True))
        return []

    def _read_records(self) -> list[dict]:
        """Whole lines only: a line cut short by a crash is dropped (and its episode runs again)."""
        if not self.jsonl.exists():
            return []
        data = self.jsonl.read_bytes()
        whole = data[: data.rfind(b"\n") + 1]
        if len(whole) != len(data):
            with open(self.jsonl, "r+b") as stream:
                stream.truncate(len(whole))
        records = []
        for line in whole.decode("utf-8").splitlines():
            try:
                records.append(loads_strict(line, str(self.jsonl)))
            except FileProblem:
                continue
        return records

    def _csv_text(self, records: Sequence[dict], *, header: bool) -> str:
        buffer = io.StringIO()
        writer = csv.writer(buffer, lineterminator="\n")
        if header:
            writer.writerow(self.columns)
        for record in records:
            writer.writerow([_cell(value) for value in self._row(record)])
        return buffer.getvalue()

    def _row(self, record: dict) -> list:
        parameters, metrics = record["parameters"], record["metrics"]
        return ([record["episode"], record["key"], record["point"], record["seed"]]
                + [parameters.get(name) for name in self.sweep.parameter_names]
                + [record["passed"], " | ".join(record["failures"])]
                + [metrics.get(name) for name in self.sweep.metric_names]
                + [" | ".join(record.get("warnings", [])), record["ticks"], record["time"], record["finished"], record["wall"]])

    def append(self, record: dict) -> None:
        """One whole line to each table, each written with a single write on an append-mode file."""
        for path, text in ((self.jsonl, json.dumps(record, sort_keys=True) + "\n"),
                           (self.path / EPISODES_CSV, self._csv_text([record], header=False))):
            with open(path, "a", encoding="utf-8", newline="") as stream:
                stream.write(text)
                stream.flush()


def _cell(value):
    if isinstance(value, (list, dict)):
        return json.dumps(value)
    if value is None:
        return ""
    return value


def _write_atomically(path: Path, text: str) -> None:
    """The folder's own tables are replaced whole (the folder was claimed with --force or --resume)."""
    write_text(path, text, force=True)


# ------------------------------------------------------------------ summary

def summarize(sweep: Sweep, records: Sequence[dict]) -> list[dict]:
    """Per parameter point: n, passed, success rate with its 95 % Wilson interval, metric medians."""
    by_point: dict[int, list[dict]] = {}
    for record in records:
        by_point.setdefault(record["point"], []).append(record)
    rows = []
    points = sweep.points()
    for point in sorted(by_point):
        group = by_point[point]
        passed = sum(1 for r in group if r["passed"])
        low, high = wilson_interval(passed, len(group))
        medians = {}
        for name in sweep.metric_names:
            values = sorted(r["metrics"].get(name) for r in group if is_finite_number(r["metrics"].get(name)))
            medians[name] = median_or_none(values)
        rows.append({"point": point, "parameters": points[point] if point < len(points) else group[0]["parameters"],
                     "n": len(group), "passed": passed, "rate": passed / len(group),
                     "low": low, "high": high, "medians": medians})
    return rows


def is_finite_number(value) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)


def median_or_none(values: Sequence[float]) -> float | None:
    if not values:
        return None
    middle = len(values) // 2
    return values[middle] if len(values) % 2 else (values[middle - 1] + values[middle]) / 2


def summary_lines(sweep: Sweep, rows: Sequence[dict]) -> list[str]:
    names = sweep.parameter_names
    header = [*names, "n", "passed", "rate", "95 % interval", *[f"median {m}" for m in sweep.metric_names]]
    table = [header]
    for row in rows:
        table.append([*[shown_value(row["parameters"].get(name)) for name in names], str(row["n"]), str(row["passed"]),
                      f"{row['rate']:.0%}", f"{row['low']:.0%}-{row['high']:.0%}",
                      *[shown_value(row["medians"][m]) for m in sweep.metric_names]])
    widths = [max(len(line[i]) for line in table) for i in range(len(header))]
    return ["  ".join(cell.rjust(width) for cell, width in zip(line, widths)) for line in table]


def shown_value(value) -> str:
    if value is None:
        return "-"
    if isinstance(value, float):
        return f"{value:.4g}"
    return json.dumps(value) if isinstance(value, (list, dict)) else str(value)


def write_summary(folder: ResultsFolder, rows: Sequence[dict]) -> None:
    sweep = folder.sweep
    _write_atomically(folder.path / SUMMARY_JSON, json.dumps(rows, indent=2, sort_keys=True) + "\n")
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(["point", *sweep.parameter_names, "n", "passed", "rate", "low95", "high95",
                     *[f"median_{m}" for m in sweep.metric_names]])
    for row in rows:
        writer.writerow([row["point"], *[_cell(row["parameters"].get(n)) for n in sweep.parameter_names], row["n"],
                         row["passed"], row["rate"], row["low"], row["high"],
                         *[_cell(row["medians"][m]) for m in sweep.metric_names]])
    _write_atomically(folder.path / SUMMARY_CSV, buffer.getvalue())
