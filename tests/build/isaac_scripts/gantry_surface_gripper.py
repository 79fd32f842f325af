"""Isaac Sim's gantry surface-gripper graph, written as Isaac's example scripts build their graphs.

The gamepad gantry of ``SurfaceGripper_gantry.usda`` on the keyboard: a key toggles the surface
gripper, arrow and page keys move the three prismatic joints 5 mm of drive target per tick, each
target clamped to its joint's limits with Min/Max nodes. Ported to graphflow by changing one import.
"""
from graphflow.build import og  # was: import omni.graph.core as og

keys = og.Controller.Keys

AXES = {  # joint: (key moving it +, key moving it -), as in the gamepad graph's bindings
    "y": ("Up", "Down"),
    "x": ("Left", "Right"),
    "z": ("PageDown", "PageUp"),
}
STEP = 0.005  # m of drive target per tick while a key is held
TARGET = "drive:linear:physics:targetPosition"


def create_gantry_graph(graph_path="/World/GantryGraph"):
    nodes = [("key_toggle", "omni.graph.action.OnKeyboardInput"),
             ("key_stop", "omni.graph.action.OnKeyboardInput")]
    values = [("key_toggle.inputs:keyIn", "A"), ("key_stop.inputs:keyIn", "Escape")]
    for axis, (plus, minus) in AXES.items():
        nodes += [(f"key_{axis}_plus", "omni.graph.action.OnKeyboardInput"),
                  (f"key_{axis}_minus", "omni.graph.action.OnKeyboardInput")]
        values += [(f"key_{axis}_plus.inputs:keyIn", plus), (f"key_{axis}_minus.inputs:keyIn", minus)]
    nodes += [
        ("on_tick", "omni.graph.action.OnTick"),
        ("gripper", "isaacsim.robot.surface_gripper.SurfaceGripper"),
        ("gripper_text", "graphflow.FormatText"),
        ("print_gripper", "omni.graph.ui_nodes.PrintText"),
        ("print_stop", "omni.graph.ui_nodes.PrintText"),
        ("stop", "graphflow.StopRun"),
    ]
    values += [
        ("gripper.inputs:SurfaceGripper", "/World/SurfaceGripper"),
        ("gripper_text.inputs:format", "gripper {value}"),
        ("print_stop.inputs:text", "Escape: stopping"),
    ]
    connections = [
        ("key_toggle.outputs:pressed", "gripper.inputs:Toggle"),
        ("gripper.outputs:status", "gripper_text.inputs:value"),
        ("gripper_text.outputs:text", "print_gripper.inputs:text"),
        ("gripper.outputs:execOut", "print_gripper.inputs:execIn"),
        ("key_stop.outputs:pressed", "print_stop.inputs:execIn"),
        ("print_stop.outputs:execOut", "stop.inputs:execIn"),
    ]
    for axis in AXES:
        joint = f"/World/Joints/{axis}_joint"
        nodes += [
            (f"{axis}_target", "omni.graph.nodes.ReadPrimAttribute"),
            (f"{axis}_lower", "omni.graph.nodes.ReadPrimAttribute"),
            (f"{axis}_upper", "omni.graph.nodes.ReadPrimAttribute"),
            (f"{axis}_plus_held", "omni.graph.nodes.ToDouble"),
            (f"{axis}_minus_held", "omni.graph.nodes.ToDouble"),
            (f"{axis}_direction", "omni.graph.nodes.Subtract"),
            (f"{axis}_step", "omni.graph.nodes.Multiply"),
            (f"{axis}_moved", "omni.graph.nodes.Add"),
            (f"{axis}_below_upper", "omni.graph.nodes.Minimum"),
            (f"{axis}_clamped", "omni.graph.nodes.Maximum"),
            (f"{axis}_write", "omni.graph.nodes.WritePrimAttribute"),
        ]
        for node, attribute in (("target", TARGET), ("lower", "physics:lowerLimit"),
                                ("upper", "physics:upperLimit"), ("write", TARGET)):
            values += [(f"{axis}_{node}.inputs:prim", joint), (f"{axis}_{node}.inputs:name", attribute)]
        values.append((f"{axis}_step.inputs:b", STEP))
        connections += [
            (f"key_{axis}_plus.outputs:isPressed", f"{axis}_plus_held.inputs:value"),
            (f"key_{axis}_minus.outputs:isPressed", f"{axis}_minus_held.inputs:value"),
            (f"{axis}_plus_held.outputs:converted", f"{axis}_direction.inputs:a"),
            (f"{axis}_minus_held.outputs:converted", f"{axis}_direction.inputs:b"),
            (f"{axis}_direction.outputs:difference", f"{axis}_step.inputs:a"),
            (f"{axis}_target.outputs:value", f"{axis}_moved.inputs:a"),
            (f"{axis}_step.outputs:product", f"{axis}_moved.inputs:b"),
            (f"{axis}_moved.outputs:sum", f"{axis}_below_upper.inputs:a"),
            (f"{axis}_upper.outputs:value", f"{axis}_below_upper.inputs:b"),
            (f"{axis}_below_upper.outputs:minimum", f"{axis}_clamped.inputs:a"),
            (f"{axis}_lower.outputs:value", f"{axis}_clamped.inputs:b"),
            (f"{axis}_clamped.outputs:maximum", f"{axis}_write.inputs:value"),
            ("on_tick.outputs:tick", f"{axis}_write.inputs:execIn"),
        ]
    (graph, _nodes, _prims, _lookup) = og.Controller.edit(
        {"graph_path": graph_path, "evaluator_name": "execution"},
        {keys.CREATE_NODES: nodes, keys.CONNECT: connections, keys.SET_VALUES: values},
    )
    return graph
