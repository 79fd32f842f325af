"""graphflow.PickPlaceSequence: a list of UR10 pick-and-place tasks run one after another, each to a place
position and, optionally, a place yaw.

Task i picks objectPrims[i] where physics says it is and places its centre at
placePositions[i], with PickPlaceController's ten phases and timing. With
placeYaws, the suction tip turns about the vertical while carrying the object
(blended over the move to the place), by the difference between the place yaw
and the object's yaw when it was gripped, so the object lands at that yaw;
yawSymmetry (pi/2 for a cube) lets it take the shortest equivalent turn. The
next task starts in the tick the previous one ends.
"""
import math

from graphflow.poses import quat_from_axis_angle, quat_multiply
from graphflow.spec import Attribute, NodeSpec

from ._pick_place import (
    CLOSE_EVENT,
    COMMON_INPUTS,
    COMMON_OUTPUTS,
    COMMON_STATE,
    DONE,
    MOTION_INPUTS,
    controller_idle,
    events_dt_problems,
    mix,
    new_run,
    run_controller,
)

MOVE_TO_PLACE = 5

SPEC = NodeSpec(
    id="graphflow.PickPlaceSequence",
    version=1,
    description=(
        "Runs pick-and-place tasks in order with the UR10's suction gripper: task i picks objectPrims[i] "
        "at its current position and places its centre at placePositions[i] (PickPlaceController's ten "
        "phases and inputs). placeYaws (radians about +Z, one per task, or empty to keep each object's "
        "yaw) turns the carried object to that yaw; yawSymmetry (radians, 0 = none, pi/2 for a cube) "
        "picks the shortest equivalent turn. taskIndex is the task being run (the task count when "
        "done); 'finished' fires once after the last task."),
    categories=("isaacExamples", "robot"),
    ui_name="Pick and Place Sequence",
    inputs=COMMON_INPUTS + (
        Attribute("objectPrims", "target", description="The objects, in task order"),
        Attribute("placePositions", "double[3][]", description="Where each object's centre goes (m, world)"),
        Attribute("placeYaws", "double[]", default=(), description="Yaw of each placed object (rad); empty: unchanged"),
        Attribute("yawSymmetry", "double", default=0.0, minimum=0.0,
                  description="Turns by this angle look the same (rad; pi/2 for a cube, 0 for none)"),
    ) + MOTION_INPUTS,
    outputs=COMMON_OUTPUTS + (
        Attribute("taskIndex", "int", description="Index of the task being run"),
    ),
    state=COMMON_STATE,
)


def validate(node_name, values):
    problems = events_dt_problems(values.get("eventsDT"))
    objects, places, yaws = values.get("objectPrims"), values.get("placePositions"), values.get("placeYaws")
    if objects is not None and places is not None and len(objects) != len(places):
        problems.append(f"inputs:placePositions: {len(places)} positions for {len(objects)} objectPrims")
    if places is not None and yaws and len(yaws) != len(places):
        problems.append(f"inputs:placeYaws: {len(yaws)} yaws for {len(places)} placePositions")
    return problems


def yaw_of(orientation) -> float:
    """Heading about +Z of a quaternion (x, y, z, w)."""
    x, y, z, w = orientation
    return math.atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))


def shortest_turn(angle: float, symmetry: float) -> float:
    """*angle* wrapped to the turn of least magnitude, modulo *symmetry* (or a full turn)."""
    period = symmetry if symmetry > 0 else 2.0 * math.pi
    return angle - period * round(angle / period)


class _Sequence:
    def __init__(self, db):
        self.objects = db.inputs.objectPrims
        self.places = db.inputs.placePositions
        self.yaws = db.inputs.placeYaws
        if len(self.places) != len(self.objects) or (self.yaws and len(self.yaws) != len(self.objects)):
            db.error(f"inputs:placePositions/placeYaws: {len(self.places)} positions and {len(self.yaws)} yaws "
                     f"for {len(self.objects)} objectPrims")
        self.index = 0
        self.run = new_run(db)
        self.turn = 0.0
        self.orientation = db.inputs.endEffectorOrientation

    @property
    def done(self):
        return self.index >= len(self.objects)

    @property
    def marker(self):
        return (self.index, DONE if self.done else self.run.event)

    def goal(self, db):
        """Object *index*, to its place."""
        return self.objects[self.index], self.places[self.index]

    def step(self, db):
        position, orientation = db.world.prim_pose(self.objects[self.index])
        event, t = self.run.event, self.run.t
        if self.yaws and event <= CLOSE_EVENT:
            self.turn = shortest_turn(self.yaws[self.index] - yaw_of(orientation), db.inputs.yawSymmetry)
        fraction = 0.0 if event < MOVE_TO_PLACE else (mix(t) if event == MOVE_TO_PLACE else 1.0)
        turn = self.turn * fraction if self.yaws else 0.0
        self.orientation = quat_multiply(quat_from_axis_angle((0.0, 0.0, 1.0), turn),
                                         tuple(db.inputs.endEffectorOrientation))
        action = self.run.step(position, self.places[self.index], db.inputs.endEffectorOffset)
        if self.run.done:
            self.index += 1
            self.run = new_run(db)
        return action


# a finished routine, or the latent continuation after this tick's advance: the pulse changes nothing
idle = controller_idle


def compute(db):
    if not db.inputs.objectPrims:
        db.error("inputs:objectPrims: no objects to place")
    reported = run_controller(db, _Sequence)
    db.outputs.taskIndex = reported[0]
