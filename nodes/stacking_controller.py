"""graphflow.StackingController: one UR10 pick-and-place after another, building a stack.

As Isaac Sim's StackingController around the UR10 PickPlaceController: cube i
(in cubePrims order) is picked where physics says it is and placed with its
centre at stackPosition + (0, 0, i * cubeHeight); when one pick-and-place is
done the next starts in the same tick.
"""
from graphflow.spec import Attribute, NodeSpec

from ._pick_place import (
    COMMON_INPUTS,
    COMMON_OUTPUTS,
    COMMON_STATE,
    DONE,
    MOTION_INPUTS,
    controller_idle,
    events_dt_problems,
    new_run,
    run_controller,
)

SPEC = NodeSpec(
    id="graphflow.StackingController",
    version=1,
    description=(
        "Stacks the cubes of cubePrims, in order, with the UR10's suction gripper: cube i is "
        "picked at its current position and placed centred at stackPosition + (0, 0, i * "
        "cubeHeight), each with PickPlaceController's ten phases (same inputs and timing). "
        "phaseStarted fires at every phase of every cube; 'finished' fires once after the "
        "last cube. cubeIndex is the cube being handled (the cube count when done). 'failed' fires "
        "once with a reason when a cube was not gripped, dropped, or landed farther than "
        "placeTolerance from its place; 'success' when every cube landed within it."),
    categories=("isaacExamples", "robot"),
    ui_name="Stacking Controller",
    inputs=COMMON_INPUTS + (
        Attribute("cubePrims", "target", description="The cubes, in picking order"),
        Attribute("stackPosition", "double[3]", description="Centre of the bottom cube when placed (m, world)"),
        Attribute("cubeHeight", "double", default=0.05, minimum=0.0, description="Height of one stacked cube (m)"),
    ) + MOTION_INPUTS,
    outputs=COMMON_OUTPUTS + (
        Attribute("cubeIndex", "int", description="Index in cubePrims of the cube being handled"),
    ),
    state=COMMON_STATE,
)


def validate(node_name, values):
    return events_dt_problems(values.get("eventsDT"))


class _Stacking:
    def __init__(self, db):
        self.cubes = db.inputs.cubePrims
        self.index = 0
        self.run = new_run(db)

    @property
    def done(self):
        return self.index >= len(self.cubes)

    @property
    def marker(self):
        return (self.index, DONE if self.done else self.run.event)

    def goal(self, db):
        """Cube *index*, to its place in the stack."""
        base = db.inputs.stackPosition
        return self.cubes[self.index], (base[0], base[1], base[2] + self.index * db.inputs.cubeHeight)

    def step(self, db):
        picking = db.world.prim_pose(self.cubes[self.index])[0]
        base = db.inputs.stackPosition
        placing = (base[0], base[1], base[2] + self.index * db.inputs.cubeHeight)
        action = self.run.step(picking, placing, db.inputs.endEffectorOffset)
        if self.run.done:
            self.index += 1
            self.run = new_run(db)
        return action


# a finished routine, or the latent continuation after this tick's advance: the pulse changes nothing
idle = controller_idle


def compute(db):
    if not db.inputs.cubePrims:
        db.error("inputs:cubePrims: no cubes to stack")
    reported = run_controller(db, _Stacking)
    db.outputs.cubeIndex = reported[0]
