"""isaacsim.robot.wheeled_robots.HolonomicRobotUsdSetup: a mecanum robot's wheel geometry, read from its USD.

Isaac's holonomic example graphs feed HolonomicController from this node instead
of typing the numbers in. As Isaac, the wheels are the prims under robotPrim
(depth first) that have the ``isaacmecanumwheel:angle`` attribute: revolute
joints that also carry ``isaacmecanumwheel:radius``. Each wheel's frame is its
joint's body0 frame (``physics:localPos0`` / ``localRot0`` on the body0 prim's
world transform); the wheel axis is the last joint's ``physics:axis``, the up
axis the stage's.

Where this differs from Isaac, on purpose: positions and radii are in metres
(Isaac passes stage units through; the same numbers on a metre stage), and
positions are expressed in the centre-of-mass prim's frame (Isaac subtracts
world positions, which is the same while the robot is unrotated, as when its
examples read it). The stage is read as authored, once per (robot, com) pair
in a run, so the setup does not drift with the simulation.
"""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="isaacsim.robot.wheeled_robots.HolonomicRobotUsdSetup",
    version=1,
    aliases=("omni.isaac.wheeled_robots.HolonomicRobotUsdSetup",),
    description=(
        "Reads a mecanum robot's wheels from the stage for HolonomicController: the joints under the robot "
        "prim with Isaac's isaacmecanumwheel:angle and :radius attributes, their positions (m) and "
        "orientations (w, x, y, z) in the centre-of-mass prim's frame (the robot prim when comPrim is "
        "unset), the last joint's axis and the stage's up axis."),
    categories=("isaacWheeledRobots",),
    ui_name="Usd Setup Holonomic Robot",
    inputs=(
        Attribute("robotPrim", "target", optional=True,
                  description="The robot's articulation root prim (when usePath is false)"),
        Attribute("comPrim", "target", optional=True,
                  description="The centre-of-mass frame prim (default: the robot prim)"),
        Attribute("usePath", "bool", default=False, description="Read robotPrimPath and comPrimPath instead"),
        Attribute("robotPrimPath", "token", default="", description="The robot prim's path (when usePath)"),
        Attribute("comPrimPath", "token", default="", description="The centre-of-mass prim's path (when usePath)"),
    ),
    outputs=(
        Attribute("wheelRadius", "double[]", description="Wheel radii, m"),
        Attribute("wheelPositions", "double[3][]", description="Wheel positions in the centre-of-mass frame, m"),
        Attribute("wheelOrientations", "double[4][]",
                  description="Wheel joint frames in the centre-of-mass frame, quaternions (w, x, y, z)"),
        Attribute("mecanumAngles", "double[]", description="Roller angles, degrees, as authored"),
        Attribute("wheelAxis", "double[3]", description="The wheels' rotation axis in their joint frame"),
        Attribute("upAxis", "double[3]", description="The stage's up axis"),
        Attribute("wheelDofNames", "token[]", description="The wheel joints' names"),
    ),
)

_OUTPUTS = ("wheelRadius", "wheelPositions", "wheelOrientations", "mecanumAngles", "wheelAxis", "upAxis",
            "wheelDofNames")


def compute(db):
    robot, com = _paths(db)
    stage = db.world.stage
    if stage is None:
        db.error("this graph names no stage, so there is no robot to read")
    setup = db.internal.get((robot, com))
    if setup is None:
        from graphflow_nodes._mecanum import MecanumSetupError, read_mecanum_setup

        try:
            setup = read_mecanum_setup(stage, robot, com)
        except MecanumSetupError as error:
            db.error(str(error))
        db.internal[(robot, com)] = setup
    for name, value in zip(_OUTPUTS, setup):
        setattr(db.outputs, name, value)


def _paths(db) -> tuple[str, str]:
    inputs = db.inputs
    if inputs.usePath:
        robot, com = inputs.robotPrimPath, inputs.comPrimPath
    else:
        robot = inputs.robotPrim[0] if inputs.robotPrim else ""
        com = inputs.comPrim[0] if inputs.comPrim else ""
    if not robot:
        db.error("no robot prim: set inputs:robotPrim (or usePath and inputs:robotPrimPath)")
    return robot, com or robot
