"""``graphflow new NAME --stage ROBOT``: a starter cell around a packaged robot, ready to change.

The cell is two files: ``NAME.usda``, a stage of its own that references the robot through the
asset roots (``@graphflow/ur10.usda@``, the suction tool and its surface-gripper prim included)
beside a ground plane and a cube, and ``NAME.json``, a pick-and-place graph on it built with
``graphflow.build`` whose checks say where the cube must end. ``graphflow test NAME.json`` passes
as written; the user then moves the cube, the place position and the checks together.
"""
from __future__ import annotations

from pathlib import Path

from graphflow.build.graph import SCHEMA_REFERENCE, Graph
from graphflow.errors import BadInput
from graphflow.files import refuse_existing, write_text
from graphflow.usd.asset_roots import OWN_DIRECTORY

GRIPPER = "/World/ur10/ee_link/SurfaceGripper"
CUBE_SIDE = 0.0515                         # m, the cube of NVIDIA's UR10 pick-and-place demo
PICK = (0.3, 0.3, CUBE_SIDE / 2)           # where it rests
PLACE = (0.7, 0.7, CUBE_SIDE / 2)          # where the graph puts it
PHASE_STEPS = [0.01, 0.0035, 0.01, 1.0, 0.008, 0.005, 0.005, 1.0, 0.01, 0.08]   # the demo's events_dt
CARRY_PHASE = 5                            # the controller's phase that carries the cube


def ur10_stage() -> str:
    """The packaged pick-and-place stage, its robot referenced through the asset roots instead of beside it."""
    text = (OWN_DIRECTORY / "ur10_pick_place.usda").read_text(encoding="utf-8")
    if "@./ur10.usda@" not in text:
        raise AssertionError("ur10_pick_place.usda no longer references @./ur10.usda@")
    return text.replace("@./ur10.usda@", "@graphflow/ur10.usda@")


def ur10_pick_place(stage: str, source: str = "<graph>") -> Graph:
    """The pick-and-place graph on a UR10 cell: phases printed, a check that the carry starts gripped."""
    graph = Graph(description=(
        f"Starter UR10 cell: the suction gripper picks the {CUBE_SIDE} m cube at {PICK[:2]} and places it at "
        f"{PLACE}. Move the cube on the stage, placingPosition here and the checks together."),
        settings={"duration": 30.0, "evaluator": "execution", "stage": stage}, schema=SCHEMA_REFERENCE,
        source=source)
    tick = graph.node("on_tick", "omni.graph.action.OnTick")
    cube = graph.node("cube_pose", "graphflow.ReadPrimPose", prim="/World/Cube")
    pick_place = graph.node("pick_place", "graphflow.PickPlaceController", robotPrim="/World/ur10",
                            gripperPrim=GRIPPER, placingPosition=PLACE, endEffectorOffset=(0.0, 0.0, 0.03),
                            eventsDT=PHASE_STEPS)
    gripper = graph.node("gripper", "isaacsim.robot.surface_gripper.SurfaceGripper", SurfaceGripper=GRIPPER)
    report = graph.node("phase_report", "omni.graph.nodes.ConstructArray", arraySize=3)
    text = graph.node("phase_text", "graphflow.FormatText", format="phase {value[0]} {value[1]}: gripper {value[2]}")
    show = graph.node("print_phase", "omni.graph.ui_nodes.PrintText")
    done = graph.node("print_done", "omni.graph.ui_nodes.PrintText", text="pick and place done")
    stop = graph.node("stop", "graphflow.StopRun")
    carrying = graph.node("is_carry_phase", "omni.graph.nodes.Compare", b=CARRY_PHASE, operation="==")
    when_carry = graph.node("when_carry_starts", "omni.graph.action.Branch")
    holding = graph.node("holding_for_carry", "graphflow.Assert",
                         message="the gripper is Closed when the carry to the place starts")
    for src, dst in (
        (tick.outputs.tick, pick_place.inputs.execIn),
        (cube.outputs.position, pick_place.inputs.pickingPosition),
        (pick_place.outputs.event, report.inputs.input0),
        (pick_place.outputs.eventName, report.inputs.input1),
        (gripper.outputs.status, report.inputs.input2),
        (report.outputs.array, text.inputs.value),
        (text.outputs.text, show.inputs.text),
        (pick_place.outputs.phaseStarted, gripper.inputs.execIn),
        (gripper.outputs.execOut, show.inputs.execIn),
        (pick_place.outputs.finished, done.inputs.execIn),
        (done.outputs.execOut, stop.inputs.execIn),
        (pick_place.outputs.event, carrying.inputs.a),
        (carrying.outputs.result, when_carry.inputs.condition),
        (show.outputs.execOut, when_carry.inputs.execIn),
        (when_carry.outputs.execTrue, holding.inputs.execIn),
        (gripper.outputs.isClosed, holding.inputs.condition),
    ):
        graph.connect(src, dst)
    graph.check("position", name="cube placed", prim="/World/Cube", position=PLACE, tolerance=0.005)
    graph.check("upright", prim="/World/Cube", within=2.0)
    graph.check("gripperStatus", gripper=GRIPPER, status="Open")
    graph.check("finite")
    graph.check("stopsBy", time=20.0)
    return graph


STARTERS = {"ur10": (ur10_stage, ur10_pick_place)}


def write_cell(graph_path: Path, robot: str, *, force: bool = False) -> tuple[Path, Path]:
    """Write the starter stage and graph for *robot* (refusing to overwrite either without *force*)."""
    if robot not in STARTERS:
        raise BadInput(f"new --stage: no starter cell for {robot!r} (starters: {', '.join(sorted(STARTERS))})")
    stage_text, build = STARTERS[robot]
    stage_path = graph_path.with_suffix(".usda")
    for target in (graph_path, stage_path):
        refuse_existing(target, force)
    graph = build(stage_path.name, str(graph_path))   # the stage path is relative to the graph's folder
    write_text(stage_path, stage_text(), force=force)
    graph.save(graph_path, force=force)
    return stage_path, graph_path
