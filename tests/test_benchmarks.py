"""The benchmarks run (``python -m benchmarks --quick``): each prints its final line in the agreed format.

Benchmarks are not timed tests: these tests never judge a figure, they only
check that every benchmark works and reports positive numbers.
"""
import math
import re
import subprocess
import sys

import pytest
from conftest import ROOT

sys.path.insert(0, str(ROOT))

from benchmarks import NAMES  # noqa: E402  (the benchmarks package lives at the repository root)

RESULT = re.compile(r"^(?P<name>\w+): ratio=(?P<ratio>\d+\.\d\d)(?P<figures>(?: [A-Za-z_0-9]+=\S+)*)$")
FIGURE = re.compile(r"^(?P<key>[A-Za-z_0-9]+)=(?P<number>[+-]?\d+(?:\.\d+)?)(?P<unit>[A-Za-z/%]*)$")
SKIPPED = re.compile(r"^(?P<name>\w+): skipped \((?P<reason>.+)\)$")
MAY_SKIP = {"pick_place_overhead", "realtime"}   # they need demo graphs other work provides


@pytest.fixture(scope="module")
def final_lines():
    result = subprocess.run([sys.executable, "-m", "benchmarks", "--quick"], cwd=ROOT,
                            capture_output=True, text=True, timeout=120)
    assert result.returncode == 0, result.stderr
    lines = {}
    for text in result.stdout.splitlines():
        match = RESULT.match(text) or SKIPPED.match(text)
        if match:
            lines[match["name"]] = text
    return lines


@pytest.mark.parametrize("name", NAMES)
def test_benchmark_prints_its_final_line_with_positive_figures(final_lines, name):
    assert name in final_lines, f"no final line for {name}"
    text = final_lines[name]
    skipped = SKIPPED.match(text)
    if skipped:
        assert name in MAY_SKIP and "not found" in skipped["reason"], text
        return
    match = RESULT.match(text)
    assert float(match["ratio"]) > 0, text
    figures = match["figures"].split()
    assert figures, f"{name} reports no unit figures: {text}"
    for figure in figures:
        parsed = FIGURE.match(figure)
        assert parsed, f"{figure!r} is not key=NUMBERunit in {text}"
        number = float(parsed["number"])
        assert math.isfinite(number), text
        if parsed["number"][0] not in "+-":    # explicitly signed figures are deltas (e.g. memory growth)
            assert number > 0, text


def test_unknown_benchmark_is_a_usage_error():
    result = subprocess.run([sys.executable, "-m", "benchmarks", "nonsense"], cwd=ROOT, capture_output=True, text=True)
    assert result.returncode == 2 and "unknown benchmark" in result.stderr


def test_plain_pybullet_baseline_does_the_whole_pick_and_place():
    """The raw-PyBullet baseline is the same job, not a cheaper one: it carries the cube to the place target."""
    from benchmarks.plain_pybullet import CUBE_START, PLACE, PlainPickPlace

    plain = PlainPickPlace(time_step=1 / 60, substeps=1, solver_iterations=50, solver_residual=3e-7)
    try:
        lifted = 0.0
        for _ in range(1127):                     # the graph's tick count
            plain.step()
            lifted = max(lifted, plain.cube_position()[2])
        final = plain.cube_position()
    finally:
        plain.close()
    assert lifted > CUBE_START[2] + 0.2                               # it was carried, not pushed
    assert math.dist(final[:2], PLACE[:2]) < 0.005                    # set down within 5 mm of the target
    assert final[2] == pytest.approx(PLACE[2], abs=0.002)
