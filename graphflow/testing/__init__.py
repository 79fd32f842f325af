"""Testing nodes and graphs with pytest: harnesses, a fake world, the generic node checker.

``ExecState`` and ``ClockWorld`` are re-exported because node tests assert exec states and tick a bare clock.
"""
from graphflow.testing.harness import (
    HARNESS_NODE,
    ComputeResult,
    GraphHarness,
    NodeHarness,
)
from graphflow.types import ExecState
from graphflow.world import ClockWorld

__all__ = ["HARNESS_NODE", "ClockWorld", "ComputeResult", "ExecState", "GraphHarness", "NodeHarness"]
