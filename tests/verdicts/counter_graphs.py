"""The small scenario the verdict tests share: a counter that stops itself, judged by a stopsBy check."""


def counter_scenario(stop_at: int = 3, **scenario) -> dict:
    """Counts 0.5 s ticks and stops at *stop_at*; must stop by 2 s."""
    return {"format": "graphflow", "formatVersion": [1, 0], "settings": {"timeStep": 0.5, "duration": 10.0},
            "nodes": [{"name": "tick", "type": "omni.graph.action.OnTick"},
                      {"name": "counter", "type": "omni.graph.action.Counter"},
                      {"name": "enough", "type": "omni.graph.nodes.Compare", "inputs": {"b": stop_at, "operation": ">="}},
                      {"name": "branch", "type": "omni.graph.action.Branch"},
                      {"name": "stop", "type": "graphflow.StopRun"}],
            "connections": [{"src": "tick.outputs:tick", "dst": "counter.inputs:execIn"},
                            {"src": "counter.outputs:count", "dst": "enough.inputs:a"},
                            {"src": "counter.outputs:execOut", "dst": "branch.inputs:execIn"},
                            {"src": "enough.outputs:result", "dst": "branch.inputs:condition"},
                            {"src": "branch.outputs:execTrue", "dst": "stop.inputs:execIn"}],
            "checks": [{"check": "stopsBy", "time": 2.0}], **({"scenario": scenario} if scenario else {})}
