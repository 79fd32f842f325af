"""graphflow.LegacySurfaceGripper: the tutorials' SurfaceGripper class, set up and updated from a graph.

Isaac's tutorials tune the suction gripper through the legacy Python class
(``SurfaceGripper(end_effector_prim_path, translate, direction, grip_threshold,
force_limit, torque_limit, bend_angle, kp, kd, disable_gravity)``); graphflow has
that class as ``graphflow.gripper.legacy.SurfaceGripper``. This node builds it
on the first execIn and calls its ``update()`` on every execIn after (a grip
broken by a force or torque limit then opens the gripper, as the tutorials'
per-step update does). ``gripperPrim`` is the IsaacSurfaceGripper prim the class
authored, for the controllers and the SurfaceGripper node to command.
"""
import math

from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

SPEC = NodeSpec(
    id="graphflow.LegacySurfaceGripper",
    version=1,
    description=(
        "Creates the legacy tutorial gripper on endEffectorPrim on the first execIn (the ray along "
        "the end effector's +X from 'translate' along 'direction'; gripThreshold reach; forceLimit "
        "and torqueLimit break the grip; kp/kd stiffness and damping of the attachment; bendAngle "
        "radians of bending; disableGravity on held objects) and updates it on every execIn. Outputs "
        "the IsaacSurfaceGripper prim it made and whether it is closed."),
    categories=("isaacSurfaceGripper",),
    ui_name="Legacy Surface Gripper",
    inputs=(
        Attribute("execIn", "execution", description="Create on the first pulse, update on every pulse"),
        Attribute("endEffectorPrim", "target", description="The rigid body the gripper is mounted on"),
        Attribute("translate", "double", default=0.0, description="Offset of the suction point (m)"),
        Attribute("direction", "token", default="x", allowed_tokens=("x", "y", "z"),
                  description="End-effector axis the offset runs along"),
        Attribute("gripThreshold", "double", default=0.01, minimum=0.0, description="Reach of the ray (m)"),
        Attribute("forceLimit", "double", default=1.0e6, minimum=0.0, description="Break force (N)"),
        Attribute("torqueLimit", "double", default=1.0e4, minimum=0.0, description="Break torque (N m)"),
        Attribute("bendAngle", "double", default=math.pi / 24, minimum=0.0, description="Allowed bending (rad)"),
        Attribute("kp", "double", default=1.0e2, minimum=0.0, description="Attachment stiffness"),
        Attribute("kd", "double", default=1.0e2, minimum=0.0, description="Attachment damping"),
        Attribute("disableGravity", "bool", default=True, description="No gravity on held objects"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires after the create or update"),
        Attribute("gripperPrim", "target", description="The IsaacSurfaceGripper prim the class created"),
        Attribute("isClosed", "bool", description="The gripper is closed"),
    ),
)


class _LegacyGrippers:
    """The grippers these nodes made in one world, by node and settings (a service of the world).

    The gripper a node authored stays on the stage across a world reset, as a
    tutorial script keeps its SurfaceGripper object and calls ``post_reset()``;
    after a reset a node takes up a gripper it made before instead of authoring
    a second one on the same end effector. Until the next reset each gripper
    serves one node instance.
    """

    def __init__(self):
        self.made: dict[tuple, list] = {}
        self.taken: set[int] = set()     # ids of the grippers handed out since the last reset

    def after_step(self, dt: float) -> None:
        pass

    def reset(self) -> None:
        self.taken.clear()   # the grippers' status itself is reset by the surface-gripper manager

    def take(self, key: tuple, make):
        for gripper in self.made.get(key, ()):
            if id(gripper) not in self.taken:
                self.taken.add(id(gripper))
                gripper.post_reset()
                return gripper
        gripper = make()
        self.made.setdefault(key, []).append(gripper)
        self.taken.add(id(gripper))
        return gripper


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    gripper = db.internal.get("gripper")
    if gripper is None:
        key = (db.node_name,) + tuple(getattr(db.inputs, a.name) for a in SPEC.inputs if not a.is_execution)
        grippers = db.world.services.require(_LegacyGrippers, _LegacyGrippers)
        gripper = db.internal["gripper"] = grippers.take(key, lambda: _create(db))
    else:
        gripper.update()
    db.outputs.gripperPrim = (gripper.gripper_path,)
    db.outputs.isClosed = gripper.is_closed()
    db.outputs.execOut = ExecState.ENABLED


def _create(db):
    from graphflow.gripper.legacy import SurfaceGripper

    if not db.inputs.endEffectorPrim:
        db.error("inputs:endEffectorPrim: no end effector given")
    if getattr(db.world, "stage", None) is None:   # a ClockWorld or an empty physics world
        db.error("inputs:endEffectorPrim: this graph names no stage to mount the gripper on")
    gripper = SurfaceGripper(
        db.inputs.endEffectorPrim[0], translate=db.inputs.translate, direction=db.inputs.direction,
        grip_threshold=db.inputs.gripThreshold, force_limit=db.inputs.forceLimit,
        torque_limit=db.inputs.torqueLimit, bend_angle=db.inputs.bendAngle, kp=db.inputs.kp, kd=db.inputs.kd,
        disable_gravity=db.inputs.disableGravity)
    try:
        gripper.initialize(db.world)
    except ValueError as error:
        db.error(str(error))
    return gripper
