"""Unit-testing nodes and small graphs with pytest.

``NodeHarness`` evaluates one node type with chosen inputs, exec pulses and
state; ``GraphHarness`` runs a small graph for N ticks. Both run the real
executor, so a node behaves here exactly as in ``graphflow run``.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Mapping

from graphflow.compiler import compile
from graphflow.document import (
    FORMAT_NAME,
    FORMAT_VERSION,
    GraphDocument,
    parse_document,
)
from graphflow.executor import GraphInstance
from graphflow.registry import Registry
from graphflow.runtime import Simulation
from graphflow.types import ExecState
from graphflow.world import DEFAULT_TIME_STEP, ClockWorld, World

HARNESS_NODE = "node"


@dataclass(frozen=True)
class ComputeResult:
    """Outputs and exec-output states right after one compute."""

    outputs: Mapping[str, Any]
    exec_states: Mapping[str, ExecState]

    @property
    def fired(self) -> set[str]:
        """Exec outputs left in any state but DISABLED."""
        return {name for name, state in self.exec_states.items() if state != ExecState.DISABLED}


class NodeHarness:
    """One node of a given type, computed on demand (pulses name the exec inputs that fire)."""

    def __init__(self, type_id: str, inputs: Mapping[str, Any] | None = None, *,
                 world: World | None = None, time_step: float = DEFAULT_TIME_STEP,
                 type_version: int | None = None, registry: Registry | None = None):
        node: dict[str, Any] = {"name": HARNESS_NODE, "type": type_id, "inputs": dict(inputs or {})}
        if type_version is not None:
            node["typeVersion"] = type_version
        document = parse_document(_complete({"nodes": [node]}), source=f"<harness {type_id}>", registry=registry)
        self.world = world if world is not None else ClockWorld(time_step)
        self.instance: GraphInstance = GraphInstance(compile(document, registry), self.world)
        self.database = self.instance.database(HARNESS_NODE)

    @property
    def state(self):
        return self.database.state

    @property
    def outputs(self):
        return self.database.outputs

    @property
    def is_latent(self) -> bool:
        return self.database.is_latent

    @property
    def logs(self) -> list[str]:
        return [event.message for event in self.instance.events]

    def set_inputs(self, **inputs) -> None:
        for name, value in inputs.items():
            self.instance.set_input(HARNESS_NODE, name, value)

    def compute(self, *pulses: str, **inputs) -> ComputeResult:
        """Set inputs, then compute once with the named exec inputs enabled."""
        self.set_inputs(**inputs)
        self.instance.compute_node(HARNESS_NODE, tuple(pulses))
        return self._result()

    def tick(self, *pulses: str, **inputs) -> ComputeResult:
        """Advance the world one step (and the tick counter), then compute."""
        self.world.step()
        self.instance.tick_count += 1
        return self.compute(*pulses, **inputs)

    def reset(self) -> None:
        self.instance.reset()

    def _result(self) -> ComputeResult:
        spec = self.database.spec
        values = self.database.outputs.as_dict()
        exec_names = {a.name for a in spec.exec_outputs}
        return ComputeResult(
            outputs={k: v for k, v in values.items() if k not in exec_names},
            exec_states={k: ExecState(values[k]) for k in exec_names})


class GraphHarness:
    """A small graph from a dict (``format`` keys optional), run tick by tick."""

    def __init__(self, graph: Mapping[str, Any] | GraphDocument, *, world: World | None = None,
                 registry: Registry | None = None, source: str = "<test graph>"):
        document = graph if isinstance(graph, GraphDocument) else parse_document(_complete(dict(graph)), source, registry)
        self.simulation = Simulation(document, world=world, registry=registry)

    @property
    def instance(self) -> GraphInstance:
        return self.simulation.instance

    @property
    def world(self) -> World:
        return self.simulation.world

    def run(self, ticks: int = 1):
        return self.simulation.run(ticks=ticks)

    def output(self, node: str, name: str):
        return self.instance.output(node, name)

    def state(self, node: str):
        return self.instance.database(node).state

    @property
    def logs(self) -> list[str]:
        return [event.message for event in self.instance.events]

    @property
    def compute_counts(self) -> dict[str, int]:
        return {node.name: self.instance.compute_counts[node.index] for node in self.instance.compiled.nodes}

    def reset(self) -> None:
        self.simulation.reset()


def _complete(graph: dict) -> dict:
    graph.setdefault("format", FORMAT_NAME)
    graph.setdefault("formatVersion", list(FORMAT_VERSION))
    return graph


__all__ = ["ComputeResult", "ExecState", "GraphHarness", "NodeHarness", "ClockWorld"]
