"""graphflow.PickPlaceController: Isaac Sim's UR10 pick-and-place controller as one latent node.

It drives the arm itself (UR10 IK on a kinematic copy, joint targets through
the world's articulation API) and the surface gripper through the world's
gripper manager; ``jointTargets`` shows what it sent. One advance per tick:
the first compute of a tick (from execIn, or the latent re-compute) moves the
phase machine, so pulsing execIn every tick does not double the speed.
"""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

from ._pick_place import (DEFAULT_INITIAL_HEIGHT, DONE, EVENT_NAMES, PHASE_COUNT, SUCTION_DOWN, UR10_EVENTS_DT,
                          PickPlaceRun, UR10Arm, events_dt_problems, gripper_manager)

SPEC = NodeSpec(
    id="graphflow.PickPlaceController",
    version=1,
    aliases=("omni.isaac.examples_nodes.IsaacPickPlaceController",),
    description=(
        "Picks an object at pickingPosition with the UR10's suction gripper and places it at "
        "placingPosition, in Isaac Sim's ten phases (move above, descend, settle, close, lift, "
        "move, descend, open, lift, hold). Targets are for the suction tip: xy and height of "
        "each phase plus endEffectorOffset, at endEffectorOrientation. Phase i lasts until "
        "eventsDT[i] summed once per tick reaches 1 (UR10 defaults: 1126 ticks). The first "
        "execIn starts it (finished goes latent); it then advances every tick until done, when "
        "'finished' fires once. The pick xy and height are latched while phases 0 and 1 run. "
        "pause/resume hold and continue; reset restarts from phase 0 (a finished controller "
        "then waits for execIn)."),
    categories=("isaacExamples", "robot"),
    ui_name="Pick and Place Controller",
    inputs=(
        Attribute("execIn", "execution", description="Starts the routine (and ticks it)"),
        Attribute("reset", "execution", description="Back to phase 0"),
        Attribute("pause", "execution", description="Stop advancing; the arm holds its targets"),
        Attribute("resume", "execution", description="Continue after a pause"),
        Attribute("robotPrim", "target", description="The UR10 articulation root"),
        Attribute("gripperPrim", "target", description="The IsaacSurfaceGripper prim on the UR10"),
        Attribute("pickingPosition", "double[3]", description="Where the object is (m, world)"),
        Attribute("placingPosition", "double[3]", description="Where the object goes (m, world)"),
        Attribute("endEffectorOffset", "double[3]", default=(0.0, 0.0, 0.02),
                  description="Added to every tip target (m)"),
        Attribute("endEffectorOrientation", "quatd[4]", default=SUCTION_DOWN,
                  description="Tip orientation (x, y, z, w), world; default: suction axis down"),
        Attribute("eventsDT", "double[]", default=UR10_EVENTS_DT,
                  description="Per-tick phase increments, exactly 10 values"),
        Attribute("endEffectorInitialHeight", "double", default=DEFAULT_INITIAL_HEIGHT,
                  description="Travel height h1 of the tip (m)"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires on every tick the controller advanced"),
        Attribute("phaseStarted", "execution", description="Fires when a phase begins (and once at done)"),
        Attribute("finished", "execution", description="Latent: pushed on start, finishes when done"),
        Attribute("event", "int", description="Current phase 0..9; 10 when done"),
        Attribute("eventName", "token", allowed_tokens=EVENT_NAMES, description="Name of the current phase"),
        Attribute("isDone", "bool", description="True once all ten phases ran"),
        Attribute("jointTargets", "double[]", description="UR10 joint position targets last sent (rad)"),
    ),
    state=(
        Attribute("running", "bool", default=False, description="Started and not yet finished"),
        Attribute("paused", "bool", default=False, description="Paused by the pause input"),
        Attribute("lastFrame", "int", default=-1, description="Tick of the last advance"),
        Attribute("reportedEvent", "int", default=-1, description="Phase of the last advance (-1 before the first)"),
    ),
)


def validate(node_name, values):
    return events_dt_problems(values.get("eventsDT"))


def compute(db):
    run = db.internal.get("run")
    if run is None or db.inputs.reset == ExecState.ENABLED:
        run = db.internal["run"] = PickPlaceRun(db.inputs.eventsDT, db.inputs.endEffectorInitialHeight)
        db.state.paused = False
        db.state.reportedEvent = -1
    if db.inputs.pause == ExecState.ENABLED:
        db.state.paused = True
    if db.inputs.resume == ExecState.ENABLED:
        db.state.paused = False
    if db.inputs.execIn == ExecState.ENABLED and not db.state.running and not run.done:
        if len(run.events_dt) != PHASE_COUNT:
            db.error(f"inputs:eventsDT needs exactly {PHASE_COUNT} values, got {len(run.events_dt)}")
        db.state.running = True
        db.outputs.finished = ExecState.LATENT_PUSH
    if db.state.running and not db.state.paused and db.frame != db.state.lastFrame:
        db.state.lastFrame = db.frame
        _advance(db, run)
    event = db.state.reportedEvent if db.state.reportedEvent >= 0 else run.event
    db.outputs.event = event
    db.outputs.eventName = EVENT_NAMES[event]
    db.outputs.isDone = event == DONE


def _advance(db, run):
    db.outputs.execOut = ExecState.ENABLED
    if run.event != db.state.reportedEvent:
        db.state.reportedEvent = run.event
        db.outputs.phaseStarted = ExecState.ENABLED
    if run.done:
        db.state.running = False
        db.outputs.finished = ExecState.LATENT_FINISH
        return
    robot, gripper = _targets(db)
    arm = db.internal.get("arm")
    if arm is None or arm.robot_path != robot:
        arm = db.internal["arm"] = UR10Arm(db.world, robot)
    kind, tip = run.step(db.inputs.pickingPosition, db.inputs.placingPosition, db.inputs.endEffectorOffset)
    perform(db, arm, gripper, kind, tip, db.inputs.endEffectorOrientation)


def perform(db, arm, gripper, kind, tip, orientation):
    """Carry out one phase-machine action: move the tip, close or open the gripper, or hold."""
    if kind == "move":
        try:
            db.outputs.jointTargets = arm.move_tip(tip, orientation)
        except ValueError as error:
            db.error(str(error))
    elif kind in ("close", "open"):
        manager = gripper_manager(db.world)
        done = manager.close_gripper(gripper) if kind == "close" else manager.open_gripper(gripper)
        if not done:
            db.error(f"inputs:gripperPrim: no surface gripper at {gripper}")
    if not db.outputs.jointTargets:
        db.outputs.jointTargets = arm.solution


def _targets(db):
    if not db.inputs.robotPrim:
        db.error("inputs:robotPrim: no robot given")
    if not db.inputs.gripperPrim:
        db.error("inputs:gripperPrim: no surface gripper given")
    return db.inputs.robotPrim[0], db.inputs.gripperPrim[0]
