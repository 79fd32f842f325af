"""The seed tutorial's tuned UR10 pick-and-place, written as an Isaac Sim script writes its graph.

Ported to graphflow by changing one import (``import omni.graph.core as og``).
"""
from graphflow.build import og  # was: import omni.graph.core as og

keys = og.Controller.Keys


def create_pick_place_graph(graph_path="/World/PickPlaceGraph"):
    (graph, _nodes, _prims, _lookup) = og.Controller.edit(
        {"graph_path": graph_path, "evaluator_name": "execution"},
        {
            keys.CREATE_NODES: [
                ("on_tick", "omni.graph.action.OnTick"),
                ("gripper", "graphflow.LegacySurfaceGripper"),
                ("cube_pose", "graphflow.ReadPrimPose"),
                ("pick_place", "graphflow.PickPlaceController"),
                ("is_after_close", "omni.graph.nodes.Compare"),
                ("is_after_open", "omni.graph.nodes.Compare"),
                ("after_close", "omni.graph.action.Branch"),
                ("after_open", "omni.graph.action.Branch"),
                ("close_result", "omni.graph.action.Branch"),
                ("open_result", "omni.graph.action.Branch"),
                ("print_gripped", "omni.graph.ui_nodes.PrintText"),
                ("print_missed", "omni.graph.ui_nodes.PrintText"),
                ("print_released", "omni.graph.ui_nodes.PrintText"),
                ("print_still_held", "omni.graph.ui_nodes.PrintText"),
                ("print_finished", "omni.graph.ui_nodes.PrintText"),
                ("stop", "graphflow.StopRun"),
            ],
            keys.CONNECT: [
                ("on_tick.outputs:tick", "gripper.inputs:execIn"),
                ("gripper.outputs:execOut", "pick_place.inputs:execIn"),
                ("gripper.outputs:gripperPrim", "pick_place.inputs:gripperPrim"),
                ("cube_pose.outputs:position", "pick_place.inputs:pickingPosition"),
                ("pick_place.outputs:event", "is_after_close.inputs:a"),
                ("pick_place.outputs:event", "is_after_open.inputs:a"),
                ("is_after_close.outputs:result", "after_close.inputs:condition"),
                ("is_after_open.outputs:result", "after_open.inputs:condition"),
                ("pick_place.outputs:phaseStarted", "after_close.inputs:execIn"),
                ("pick_place.outputs:phaseStarted", "after_open.inputs:execIn"),
                ("gripper.outputs:isClosed", "close_result.inputs:condition"),
                ("gripper.outputs:isClosed", "open_result.inputs:condition"),
                ("after_close.outputs:execTrue", "close_result.inputs:execIn"),
                ("after_open.outputs:execTrue", "open_result.inputs:execIn"),
                ("close_result.outputs:execTrue", "print_gripped.inputs:execIn"),
                ("close_result.outputs:execFalse", "print_missed.inputs:execIn"),
                ("open_result.outputs:execFalse", "print_released.inputs:execIn"),
                ("open_result.outputs:execTrue", "print_still_held.inputs:execIn"),
                ("pick_place.outputs:finished", "print_finished.inputs:execIn"),
                ("print_finished.outputs:execOut", "stop.inputs:execIn"),
            ],
            keys.SET_VALUES: [
                ("gripper.inputs:direction", "x"),
                ("gripper.inputs:endEffectorPrim", "/World/ur10/ee_link"),
                ("gripper.inputs:forceLimit", 50000.0),
                ("gripper.inputs:gripThreshold", 0.02),
                ("gripper.inputs:kd", 10000.0),
                ("gripper.inputs:kp", 10000.0),
                ("gripper.inputs:torqueLimit", 500.0),
                ("gripper.inputs:translate", 0.1611),
                ("cube_pose.inputs:prim", "/World/Cube"),
                ("pick_place.inputs:endEffectorOffset", (0.0, 0.0, 0.03)),
                ("pick_place.inputs:placingPosition", (-0.4, 0.5, 0.05)),
                ("pick_place.inputs:robotPrim", "/World/ur10"),
                ("is_after_close.inputs:b", 4),
                ("is_after_close.inputs:operation", "=="),
                ("is_after_open.inputs:b", 8),
                ("is_after_open.inputs:operation", "=="),
                ("print_gripped.inputs:text", "Gripper CLOSE command issued. Status: SUCCESS (Object Gripped)"),
                ("print_missed.inputs:logLevel", "Warning"),
                ("print_missed.inputs:text", "Gripper CLOSE command issued. Status: FAILURE (Missed Object)"),
                ("print_released.inputs:text", "Gripper OPEN command issued. Status: Object Released"),
                ("print_still_held.inputs:logLevel", "Warning"),
                ("print_still_held.inputs:text", "Gripper OPEN command issued. Status: FAILURE (Object Still Held)"),
                ("print_finished.inputs:text", "Pick and Place routine has finished."),
            ],
        },
    )
    return graph
