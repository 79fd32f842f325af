"""Building graphs in Python: ``Graph`` (each call checked by the compiler) and ``og`` (Isaac's ``og.Controller.edit``).

::

    from graphflow.build import Graph

    graph = Graph(settings={"stage": "asset:ur10_pick_place.usda"})
    tick = graph.node("tick", "omni.graph.action.OnTick")
    count = graph.node("count", "omni.graph.action.Counter")
    graph.connect(tick.outputs.tick, count.inputs.execIn)   # or "tick.outputs:tick", "count.inputs:execIn"
    graph.save("counter.json")
"""
from graphflow.build import og
from graphflow.build.graph import SCHEMA_REFERENCE, Graph, NodeHandle, Port, Ports

__all__ = ["Graph", "NodeHandle", "Port", "Ports", "SCHEMA_REFERENCE", "og"]
