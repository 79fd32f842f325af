"""LegacySurfaceGripper across a reset: the node takes up the gripper it authored instead of adding a second one."""
from graphflow.testing import GraphHarness

END_EFFECTOR = "/World/ur10/ee_link"


def _grippers_on_stage(world):
    return sorted(prim.GetPath().pathString for prim in world.stage.Traverse()
                  if prim.GetTypeName() == "IsaacSurfaceGripper")


def test_a_reset_run_uses_the_gripper_the_first_run_authored():
    graph = GraphHarness({
        "settings": {"stage": "asset:ur10_pick_place.usda"},
        "nodes": [{"name": "tick", "type": "omni.graph.action.OnPlaybackTick"},
                  {"name": "legacy", "type": "graphflow.LegacySurfaceGripper",
                   "inputs": {"endEffectorPrim": END_EFFECTOR, "gripThreshold": 0.02}}],
        "connections": [{"src": "tick.outputs:tick", "dst": "legacy.inputs:execIn"}]})
    try:
        graph.run(3)
        authored = graph.output("legacy", "gripperPrim")
        assert authored == (f"{END_EFFECTOR}/SurfaceGripper_01",)   # the stage already has .../SurfaceGripper
        grippers = _grippers_on_stage(graph.world)
        assert grippers == [f"{END_EFFECTOR}/SurfaceGripper", f"{END_EFFECTOR}/SurfaceGripper_01"]
        graph.reset()
        graph.run(3)
        assert graph.output("legacy", "gripperPrim") == authored
        assert _grippers_on_stage(graph.world) == grippers
        assert graph.output("legacy", "isClosed") is False
    finally:
        graph.simulation.close()
