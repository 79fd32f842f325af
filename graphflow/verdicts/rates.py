"""Pass rates over seeds: a scenario run as N randomized episodes, gated on a confidence bound.

A scenario whose ``scenario`` section declares ``"seeds": N`` (or any scenario under ``graphflow test
--seeds N``) runs N episodes, seed ``s0 .. s0+N-1`` (``s0``: the scenario's ``seed``, default 0), each
with the scenario's ``randomize`` entries (the format of sweeps, docs/sweeps.md) drawn from its seed.
The episodes run on the sweep launchers (``graphflow.sweep.scenario_rates``: ``LocalPool``, or ``RayPool``
with ``--ray``): each worker loads the stage once and resets it between episodes. This module is the
statistics and the verdict; the sweep package, above this one, runs the episodes. The scenario passes
when the lower bound of the two-sided Wilson interval at ``confidence`` (default 0.95) is at least
``minPassRate``:
``47/50 passed, 95 % CI [0.84, 0.98], gate 0.80: PASS``. All N episodes always run (no early stop),
so the counts are those of the N seeds named.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from statistics import NormalDist

from graphflow.files import read_json

DEFAULT_GATE = 0.8          # the gate of a rate scenario that declares none (graphflow test --min-pass-rate)
DEFAULT_CONFIDENCE = 0.95
WILSON_Z = 1.959963984540054   # the 97.5 % quantile of the standard normal: a two-sided 95 % interval


def wilson_interval(successes: int, n: int, z: float = WILSON_Z) -> tuple[float, float]:
    """Wilson score interval of a binomial proportion (good at 0 %, 100 % and small n, unlike p ± z·se)."""
    if n == 0:
        return (0.0, 1.0)
    p = successes / n
    denominator = 1 + z * z / n
    centre = (p + z * z / (2 * n)) / denominator
    half = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / denominator
    return (max(0.0, centre - half), min(1.0, centre + half))


def z_for(confidence: float) -> float:
    """The normal quantile of a two-sided interval at *confidence* (0.95 -> 1.96)."""
    return NormalDist().inv_cdf(0.5 + confidence / 2)


@dataclass(frozen=True)
class RatePlan:
    """What a rate scenario runs: its seeds, its gate, its confidence."""

    path: str
    seeds: list[int]
    gate: float
    confidence: float


def rate_plan(path: str, data: dict, seeds: int | None = None, gate: float | None = None) -> RatePlan | None:
    """The plan of a scenario file's data; None when it is a single run (no seeds declared or given)."""
    scenario = data.get("scenario", {})
    count = seeds if seeds is not None else scenario.get("seeds")
    if count is None:
        return None
    start = int(scenario.get("seed", 0))
    declared = scenario.get("minPassRate")
    return RatePlan(path, list(range(start, start + int(count))),
                    float(declared if declared is not None else gate if gate is not None else DEFAULT_GATE),
                    float(scenario.get("confidence", DEFAULT_CONFIDENCE)))


@dataclass
class RateVerdict:
    """The verdict of N episodes: counts, interval, gate; the failing seeds with reasons and re-run commands."""

    path: str
    plan: RatePlan
    records: list[dict]
    expect_failure: tuple[str, ...] = ()

    @property
    def runs(self) -> int:
        return len(self.records)

    @property
    def successes(self) -> int:
        return sum(1 for record in self.records if record["passed"])

    def interval(self) -> tuple[float, float]:
        return wilson_interval(self.successes, self.runs, z_for(self.plan.confidence))

    @property
    def gate_passed(self) -> bool:
        return self.interval()[0] >= self.plan.gate

    def rate_line(self) -> str:
        low, high = self.interval()
        return (f"{self.successes}/{self.runs} passed, {self.plan.confidence * 100:g} % CI [{low:.2f}, {high:.2f}], "
                f"gate {self.plan.gate:.2f}: {'PASS' if self.gate_passed else 'FAIL'}")

    @property
    def failures(self) -> list[str]:
        """The rate line when the gate fails, then one line per failing seed: reason and re-run command."""
        lines = [] if self.gate_passed else [f"{self.path}: {self.rate_line()}"]
        for record in sorted(self.records, key=lambda r: r["seed"]):
            if not record["passed"]:
                reason = record["failures"][0] if record["failures"] else "failed"
                reason = reason.removeprefix(f"{self.path}: ")
                lines += [f"seed {record['seed']}: {reason}", f"  re-run: {record['replay']}"]
        return lines

    @property
    def passed(self) -> bool:
        if not self.expect_failure:
            return self.gate_passed
        text = "\n".join(self.failures)
        return not self.gate_passed and all(expected in text for expected in self.expect_failure)

    def verdict_line(self) -> str:
        status = ("XFAIL" if self.passed else "FAIL") if self.expect_failure else ("PASS" if self.passed else "FAIL")
        line = f"{status} {self.path}: {self.rate_line()}"
        if self.expect_failure and not self.passed:
            line += f" (expected to fail with {', '.join(map(repr, self.expect_failure))})"
        return line

    def properties(self) -> dict[str, str]:
        """JUnit properties of the test case."""
        low, high = self.interval()
        return {"runs": str(self.runs), "passed": str(self.successes), "rate": f"{self.successes / max(1, self.runs):.4f}",
                "confidence": f"{self.plan.confidence:g}", "interval_low": f"{low:.4f}", "interval_high": f"{high:.4f}",
                "gate": f"{self.plan.gate:g}", "seeds": f"{self.plan.seeds[0]}..{self.plan.seeds[-1]}"}


def randomized_edits(path: str, seed: int) -> list:
    """The edits the scenario's randomization draws for *seed* (what an episode of that seed ran with)."""
    from graphflow.variants.randomize import parse_randomization

    entries = read_json(path).get("scenario", {}).get("randomize", [])
    return list(parse_randomization(entries, path).draw(seed))

