"""The pick-and-place phase machine and the exec handling shared by
PickPlaceController and StackingController. Not a node type (the leading underscore keeps the
registry away).

Phases, heights and xy interpolation are Isaac Sim's PickPlaceController
(reference §5.1): ``t`` grows by ``events_dt[event]`` on every call (every
tick), the phase ends when ``t >= 1``; heights and xy blend with
``mix(t) = (1 - cos(pi t)) / 2``. Targets are for the suction tip.
"""
from __future__ import annotations

import math

from graphflow.spec import Attribute
from graphflow.types import ExecState
from graphflow.world import WorldError
from graphflow_nodes._arm import Arm

UR10_EVENTS_DT = (0.01, 0.0035, 0.01, 1.0, 0.008, 0.005, 0.005, 1.0, 0.01, 0.08)
PHASE_COUNT = 10
DONE = PHASE_COUNT
# Isaac's phase 9 "moves towards the old xy" with alpha 1, i.e. holds above the place: named for what it does
EVENT_NAMES = ("move_above_pick", "descend", "settle", "gripper_close", "lift", "move_to_place",
               "descend_to_place", "gripper_open", "lift_after_place", "hold_above_place", "done")
CLOSE_EVENT, OPEN_EVENT, SETTLE_EVENT = 3, 7, 2
LIFT_EVENT = 4               # lift: the grip may still begin (a retried close), then must hold
CARRY_EVENTS = (5, 6)        # move_to_place, descend_to_place: the object must be held throughout
LAST_EVENT = 9               # hold_above_place: when it ends, the object rests where it was put
DEFAULT_PLACE_TOLERANCE = 0.02
DEFAULT_INITIAL_HEIGHT = 0.3
# graphflow.kinematics.SUCTION_DOWN (the attachment frame's +X, the suction axis, pointing down), written out so
# that loading the node registry does not load the IK solver: Arm imports it on first use
SUCTION_DOWN = (0.0, math.sqrt(0.5), 0.0, math.sqrt(0.5))


def mix(t: float) -> float:
    return 0.5 * (1.0 - math.cos(math.pi * t))


def tip_height(event: int, t: float, h0: float, h1: float, place_z: float) -> float:
    """Height of the tool target in each moving phase (Isaac's _get_target_hs)."""
    a = mix(max(0.0, t))
    return {0: h1, 1: (1 - a) * h1 + a * h0, 3: h0, 4: (1 - a) * h0 + a * h1, 5: h1,
            6: (1 - a) * h1 + a * place_z, 7: place_z, 8: (1 - a) * place_z + a * h1, 9: h1}[event]


def tip_xy(event: int, t: float, pick_xy, place_xy) -> tuple[float, float]:
    """xy of the tool target: at the pick until phase 5 blends to the place (Isaac's _get_alpha)."""
    alpha = 0.0 if event < 5 else (mix(t) if event == 5 else 1.0)
    return ((1 - alpha) * pick_xy[0] + alpha * place_xy[0], (1 - alpha) * pick_xy[1] + alpha * place_xy[1])


def advance(event: int, t: float, events_dt) -> tuple[int, float]:
    """One call's worth of progress: t += dt of the phase; the next phase starts at t = 0 once t >= 1."""
    t += events_dt[event]
    if t >= 1.0:
        return event + 1, 0.0
    return event, t


def events_dt_problems(values) -> list[str]:
    """Load-time check of an authored eventsDT (Isaac raises unless there are exactly 10 values)."""
    if values is None:
        return []
    if not isinstance(values, (list, tuple)) or len(values) != PHASE_COUNT:
        count = len(values) if isinstance(values, (list, tuple)) else "no"
        return [f"inputs:eventsDT needs exactly {PHASE_COUNT} phase increments, got {count}"]
    bad = [v for v in values if not isinstance(v, (int, float)) or isinstance(v, bool) or not v > 0]
    if bad:
        return [f"inputs:eventsDT values must be positive (each phase must end), got {bad[0]!r}"]
    return []


class PickPlaceRun:
    """One pick and place: the phase machine, with the pick xy and height latched in phases 0 and 1."""

    def __init__(self, events_dt, initial_height: float):
        self.events_dt = tuple(events_dt)
        self.h1 = initial_height
        self.event = 0
        self.t = 0.0
        self.pick = (0.0, 0.0, 0.0)

    @property
    def done(self) -> bool:
        return self.event >= PHASE_COUNT

    def step(self, picking, placing, offset):
        """This call's action, then advance: ("move", tip xyz) | ("hold", None) | ("close"/"open", None)."""
        event = self.event
        if event == SETTLE_EVENT:
            action = ("hold", None)
        elif event == CLOSE_EVENT:
            action = ("close", None)
        elif event == OPEN_EVENT:
            action = ("open", None)
        else:
            if event in (0, 1):
                self.pick = tuple(picking)
            x, y = tip_xy(event, self.t, self.pick, placing)
            z = tip_height(event, self.t, self.pick[2], self.h1, placing[2])
            action = ("move", (x + offset[0], y + offset[1], z + offset[2]))
        self.event, self.t = advance(event, self.t, self.events_dt)
        return action


def gripper_manager(world):
    """The world's surface-gripper manager (a service of the world, created on first use from its stage)."""
    from graphflow.gripper.manager import SurfaceGripperManager, manager_for

    if world.services.get(SurfaceGripperManager) is None and getattr(world, "stage", None) is None:
        raise WorldError("this graph names no stage, so there is no surface gripper to command")
    return manager_for(world)


# -- ports and exec handling common to both controllers ------------------------------------------

COMMON_INPUTS = (
    Attribute("execIn", "execution", description="Starts the routine (and ticks it)"),
    Attribute("reset", "execution", description="Back to the start"),
    Attribute("pause", "execution", description="Stop advancing; the arm holds its targets"),
    Attribute("resume", "execution", description="Continue after a pause"),
    Attribute("robotPrim", "target", description="The arm's articulation root (the UR10, or any arm whose chain leads to the gripper)"),
    Attribute("gripperPrim", "target", description="The IsaacSurfaceGripper prim on the arm; its attachment point is the IK's tool frame"),
)
MOTION_INPUTS = (
    Attribute("endEffectorOffset", "double[3]", default=(0.0, 0.0, 0.02), description="Added to every tip target (m)"),
    Attribute("endEffectorOrientation", "quatd[4]", default=SUCTION_DOWN,
              description="Tip orientation (x, y, z, w), world; default: suction axis down"),
    Attribute("eventsDT", "double[]", default=UR10_EVENTS_DT, description="Per-tick phase increments, exactly 10 values"),
    Attribute("endEffectorInitialHeight", "double", default=DEFAULT_INITIAL_HEIGHT,
              description="Travel height h1 of the tip (m)"),
    Attribute("placeTolerance", "double", default=DEFAULT_PLACE_TOLERANCE, minimum=0.0,
              description="Largest horizontal distance (m) of a placed object from its target for 'success'"),
)
COMMON_OUTPUTS = (
    Attribute("execOut", "execution", description="Fires on every tick the controller advanced"),
    Attribute("phaseStarted", "execution", description="Fires when a phase begins (and once at done)"),
    Attribute("finished", "execution", description="Latent: pushed on start, finishes when done"),
    Attribute("event", "int", description="Current phase 0..9; 10 when done"),
    Attribute("eventName", "token", allowed_tokens=EVENT_NAMES, description="Name of the current phase"),
    Attribute("isDone", "bool", description="True once the routine is complete"),
    Attribute("jointTargets", "double[]", description="Arm joint position targets last sent (rad), base to tool"),
    Attribute("success", "execution",
              description="Fires once, when the last object was placed within placeTolerance and nothing failed"),
    Attribute("failed", "execution",
              description="Fires once, when the routine first goes wrong: the gripper never closed on the object, "
                          "the object dropped while carried, or it was placed farther than placeTolerance"),
    Attribute("reason", "string", description="What succeeded or failed, with the gripper's reason or the distance"),
)
COMMON_STATE = (
    Attribute("running", "bool", default=False, description="Started and not yet finished"),
    Attribute("paused", "bool", default=False, description="Paused by the pause input"),
    Attribute("lastFrame", "int", default=-1, description="Tick of the last advance"),
)


def run_controller(db, make_routine):
    """Exec semantics of both controllers; *make_routine(db)* builds the phase plan on first use and on reset.

    A routine has ``done``, ``marker`` (a tuple ending in the phase about to run) and ``step(db)``
    returning the phase machine's action. One advance per tick, whoever computes the node first.
    """
    routine = db.internal.get("routine")
    if routine is None or db.inputs.reset == ExecState.ENABLED:
        routine = db.internal["routine"] = make_routine(db)
        db.internal["reported"] = None
        db.internal["verdict"] = Verdict()
        db.outputs.reason = ""
        db.state.paused = False
    if db.inputs.pause == ExecState.ENABLED:
        db.state.paused = True
    if db.inputs.resume == ExecState.ENABLED:
        db.state.paused = False
    if db.inputs.execIn == ExecState.ENABLED and not db.state.running and not routine.done:
        db.state.running = True
        db.outputs.finished = ExecState.LATENT_PUSH
    if db.state.running and not db.state.paused and db.frame != db.state.lastFrame:
        db.state.lastFrame = db.frame
        before = routine.marker
        goal = None if routine.done else routine.goal(db)
        _advance(db, routine)
        if goal is not None:
            _judge(db, routine, before, goal)
    reported = db.internal["reported"] or routine.marker
    db.outputs.event = reported[-1]
    db.outputs.eventName = EVENT_NAMES[reported[-1]]
    db.outputs.isDone = reported[-1] == DONE
    return reported


def controller_idle(db) -> bool:
    """The controllers' ``idle``: no reset, pause or resume pulse, and the routine either advanced already this
    tick (the latent continuation after the tick's pulse) or is finished. Such a pulse changes no output, so
    the executor skips it: a finished controller pulsed every tick costs a dispatch, not its pulls and compute."""
    routine = db.internal.get("routine")
    if routine is None:
        return False
    inputs = db.inputs
    if inputs.reset == ExecState.ENABLED or inputs.pause == ExecState.ENABLED or inputs.resume == ExecState.ENABLED:
        return False
    return db.frame == db.state.lastFrame or (routine.done and not db.state.running)


def _advance(db, routine):
    db.outputs.execOut = ExecState.ENABLED
    if routine.marker != db.internal["reported"]:
        db.internal["reported"] = routine.marker
        db.outputs.phaseStarted = ExecState.ENABLED
    if routine.done:
        db.state.running = False
        db.outputs.finished = ExecState.LATENT_FINISH
        return
    if not db.inputs.robotPrim:
        db.error("inputs:robotPrim: no robot given")
    if not db.inputs.gripperPrim:
        db.error("inputs:gripperPrim: no surface gripper given")
    robot, gripper = db.inputs.robotPrim[0], db.inputs.gripperPrim[0]
    arm = db.internal.get("arm")
    if arm is None or arm.robot_path != robot:
        try:
            arm = db.internal["arm"] = Arm(db.world, robot, gripper)
        except ValueError as error:
            db.error(f"inputs:robotPrim: {error}")
    kind, tip = routine.step(db)
    if kind == "move":
        try:   # a routine may turn the tip itself (PickPlaceSequence's place yaws)
            arm.move_tip(tip, getattr(routine, "orientation", db.inputs.endEffectorOrientation))
        except ValueError as error:
            db.error(str(error))
    elif kind in ("close", "open"):
        manager = gripper_manager(db.world)
        commanded = manager.close_gripper(gripper) if kind == "close" else manager.open_gripper(gripper)
        if not commanded:
            db.error(f"inputs:gripperPrim: no surface gripper at {gripper}")
    db.outputs.jointTargets = arm.solution


class Verdict:
    """How the routine is going: the object being carried, the placements so far, whether it failed."""

    def __init__(self):
        self.carried: str | None = None
        self.placed: list[str] = []
        self.failed = False


def _gripper_view(db):
    """(gripped objects, status token, reason) of the controller's gripper."""
    manager = gripper_manager(db.world)
    path = db.inputs.gripperPrim[0]
    status = manager.get_gripper_status(path)
    return (tuple(manager.get_gripped_objects(path)), getattr(status, "token", str(status)),
            getattr(manager.component(path), "reason", ""))


def _judge(db, routine, before, goal):
    """After an advance: check the phase that just ran; fire failed once, or success after the last placement.

    *before* is the routine's marker before the advance (its last entry the phase that ran), *goal* the
    (object or None for 'whatever is held', place position) of the pick that ran.
    """
    verdict = db.internal["verdict"]
    if verdict.failed:
        return
    event = before[-1]
    wanted, place = goal
    if event == LIFT_EVENT or event in CARRY_EVENTS:
        gripped, status, reason = _gripper_view(db)
        if verdict.carried is None:
            held = wanted if wanted in gripped else (gripped[0] if gripped and wanted is None else None)
            if held is None and event in CARRY_EVENTS:   # the lift may still see a retried close grip
                why = reason or f"status {status}"
                return _fail(db, verdict, f"the gripper never closed on {wanted or 'an object'}: {why}")
            verdict.carried = held
        elif verdict.carried not in gripped:
            why = reason or f"gripper {status}"
            return _fail(db, verdict, f"{verdict.carried} dropped during {EVENT_NAMES[event]} at t = {db.time:.3f} s: {why}")
    if event == LAST_EVENT and routine.marker != before and verdict.carried is not None:
        obj = verdict.carried
        verdict.carried = None
        position = db.world.prim_pose(obj)[0]
        distance = math.hypot(position[0] - place[0], position[1] - place[1])
        placed = f"placed {obj} {distance * 1000:.1f} mm from the target"
        if distance > db.inputs.placeTolerance:
            return _fail(db, verdict, f"{placed} (tolerance {db.inputs.placeTolerance * 1000:.1f} mm)")
        verdict.placed.append(placed)
        db.outputs.reason = "; ".join(verdict.placed)
        if routine.done:
            db.outputs.success = ExecState.ENABLED


def _fail(db, verdict, reason: str) -> None:
    verdict.failed = True
    db.outputs.reason = reason
    db.outputs.failed = ExecState.ENABLED


def new_run(db) -> PickPlaceRun:
    """A phase machine from the node's eventsDT and travel height (checked again here: they may be connected)."""
    events_dt = db.inputs.eventsDT
    problems = events_dt_problems(list(events_dt))
    if problems:
        db.error(problems[0])
    return PickPlaceRun(events_dt, db.inputs.endEffectorInitialHeight)
