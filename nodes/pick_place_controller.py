"""graphflow.PickPlaceController: Isaac Sim's UR10 pick-and-place controller as one latent node.

It drives the arm itself (IK on a kinematic copy of the chain from the robot's base to its gripper,
the UR10's or any converted arm's; joint targets through
the world's articulation API) and the surface gripper through the world's
gripper manager; ``jointTargets`` shows what it sent. One advance per tick:
the first compute of a tick (from execIn, or the latent re-compute) moves the
phase machine, so pulsing execIn every tick does not double the speed.
"""
from graphflow.spec import Attribute, NodeSpec

from ._pick_place import (
    COMMON_INPUTS,
    COMMON_OUTPUTS,
    COMMON_STATE,
    MOTION_INPUTS,
    controller_idle,
    events_dt_problems,
    new_run,
    run_controller,
)

SPEC = NodeSpec(
    id="graphflow.PickPlaceController",
    version=1,
    aliases=("omni.isaac.examples_nodes.IsaacPickPlaceController",),
    description=(
        "Picks an object at pickingPosition with the arm's suction gripper (the UR10's, or any arm's whose "
        "joints lead from robotPrim to gripperPrim) and places it at "
        "placingPosition, in Isaac Sim's ten phases (move above, descend, settle, close, lift, "
        "move, descend, open, lift, hold). Targets are for the suction tip: xy and height of "
        "each phase plus endEffectorOffset, at endEffectorOrientation. Phase i lasts until "
        "eventsDT[i] summed once per tick reaches 1 (UR10 defaults: 1126 ticks). The first "
        "execIn starts it (finished goes latent); it then advances every tick until done, when "
        "'finished' fires once. The pick xy and height are latched while phases 0 and 1 run. "
        "pause/resume hold and continue; reset restarts from phase 0 (a finished controller "
        "then waits for execIn). 'failed' fires once with a reason when the gripper never closed on "
        "the object (with the gripper's reason), the object dropped while carried, or it landed "
        "farther than placeTolerance (horizontally) from placingPosition; 'success' fires when it "
        "landed within it."),
    categories=("isaacExamples", "robot"),
    ui_name="Pick and Place Controller",
    inputs=COMMON_INPUTS + (
        Attribute("pickingPosition", "double[3]", description="Where the object is (m, world)"),
        Attribute("placingPosition", "double[3]", description="Where the object goes (m, world)"),
    ) + MOTION_INPUTS,
    outputs=COMMON_OUTPUTS,
    state=COMMON_STATE,
)


def validate(node_name, values):
    return events_dt_problems(values.get("eventsDT"))


class _PickPlace:
    def __init__(self, db):
        self.run = new_run(db)

    @property
    def done(self):
        return self.run.done

    @property
    def marker(self):
        return (self.run.event,)

    def goal(self, db):
        """Whatever the gripper picks, to placingPosition."""
        return None, db.inputs.placingPosition

    def step(self, db):
        return self.run.step(db.inputs.pickingPosition, db.inputs.placingPosition, db.inputs.endEffectorOffset)


# a finished routine, or the latent continuation after this tick's advance: the pulse changes nothing
idle = controller_idle


def compute(db):
    run_controller(db, _PickPlace)
