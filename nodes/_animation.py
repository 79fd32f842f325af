"""The shared ports and latent compute of Kit's maneuver nodes (TranslateTo*, RotateTo*, MoveTo*, ScaleToSize).

Not a node type. An execIn pulse takes the prim's local transform as the start
and the node's goal as the end; every later tick the prim is placed at the
blend alpha = min(speed * t, 1), t the simulated seconds since the pulse, eased
by Kit's ease-in-out curve of degree ``exponent`` (EaseInOut of the Ease node:
(2a)^p / 2, then 1 - (2 - 2a)^p / 2), translation and scale interpolated
linearly, rotation along the shortest arc (slerp). At alpha 1 the prim is at the
goal and ``finished`` fires. A maneuver takes 1/speed seconds whatever the
distance (speed is the blend's rate; Kit's pages call it units per second).
A stop pulse halts the prim where it is and fires ``finished`` (OmniGraph ends
a latent node only by firing its finish). Pulses on execIn while it runs are
ignored. The world places the prim (``World.set_local_transform``): a free or
kinematic body is teleported at rest each tick, any other prim gets its xform
ops for the run. Positions are in stage units, as Kit's are.
"""
import math

from graphflow.poses import IDENTITY_POSE, quat_normalize, relative
from graphflow.spec import Attribute
from graphflow.types import ExecState
from graphflow.world import WorldError
from graphflow_nodes.ease import eased
from graphflow_nodes.scale_to_from_stage_unit import meters_per_unit

EXEC_IN = Attribute("execIn", "execution", description="Starts the maneuver from where the prim is")
EXPONENT = Attribute("exponent", "float", default=2.0,
                     description="Degree of the ease-in-out curve (1 linear, 2 quadratic, 3 cubic, ...)")
SPEED = Attribute("speed", "double", default=1.0, description="Rate of the blend, 1/s: the maneuver takes 1/speed s")
STOP = Attribute("stop", "execution", description="Halts the maneuver where the prim is (finished fires)")
FINISHED = Attribute("finished", "execution", description="Fires when the prim arrives (or the maneuver is stopped)")
PRIM = Attribute("prim", "target", optional=True, description="The prim to move (when usePath is false)")
PRIM_PATH = Attribute("primPath", "path", default="", optional=True, description="The prim to move, when usePath")
USE_PATH = Attribute("usePath", "bool", default=False, description="Move the prim at primPath instead of 'prim'")
SOURCE_PRIM = Attribute("sourcePrim", "target", optional=True,
                        description="The prim to move (when useSourcePath is false)")
SOURCE_PRIM_PATH = Attribute("sourcePrimPath", "path", default="", optional=True,
                             description="The prim to move, when useSourcePath is true")
USE_SOURCE_PATH = Attribute("useSourcePath", "bool", default=False,
                            description="Move the prim at sourcePrimPath instead of 'sourcePrim'")
TARGET_PRIM = Attribute("targetPrim", "target", optional=True,
                        description="The prim to match (when useTargetPath is false)")
TARGET_PRIM_PATH = Attribute("targetPrimPath", "path", default="", optional=True,
                             description="The prim to match, when useTargetPath is true")
USE_TARGET_PATH = Attribute("useTargetPath", "bool", default=False,
                            description="Match the prim at targetPrimPath instead of 'targetPrim'")
ELAPSED = Attribute("elapsed", "double", default=0.0, description="Simulated seconds since the maneuver started")
LAST_FRAME = Attribute("lastFrame", "int", default=-1, description="Tick whose time step was last counted")
MANEUVER = ("The maneuver lasts 1/speed seconds of simulated time whatever the distance, eased in and out with "
            "degree exponent; a stop pulse halts it where it is and fires finished; execIn pulses while it runs "
            "are ignored. A free or kinematic body is teleported at rest each tick (physics takes over on "
            "arrival); any other prim gets its xform ops for the run (the file is untouched, a reset undoes it). "
            "Positions in stage units.")

_EPSILON = 1e-9


def prim_path(db, prim: str = "prim", path: str = "primPath", use_path: str = "usePath") -> str:
    """The prim a port trio names: its path input when the use flag is set, else the first target."""
    inputs = db.inputs
    chosen = getattr(inputs, path) if getattr(inputs, use_path) else (getattr(inputs, prim) or ("",))[0]
    if not chosen:
        db.error(f"no prim given (set inputs:{prim}, or inputs:{use_path} and inputs:{path})")
    return chosen


def run_maneuver(db, path_of, goal_of) -> None:
    """The latent compute: ``path_of(db)`` names the prim, ``goal_of(db, start)`` gives the goal transform
    (translation m, orientation (x, y, z, w), scale) from the start transform, both read at the execIn pulse."""
    inputs = db.inputs
    if db.is_latent:
        if inputs.stop == ExecState.ENABLED:
            db.outputs.finished = ExecState.LATENT_FINISH
            return
        if inputs.execIn == ExecState.ENABLED:
            return
        if db.frame != db.state.lastFrame:
            db.state.lastFrame = db.frame
            db.state.elapsed += db.time_step
        _advance(db)
        return
    if inputs.execIn != ExecState.ENABLED:
        return
    if not inputs.speed > 0:
        db.error(f"inputs:speed must be > 0 (the blend's rate, 1/s), got {inputs.speed}")
    if not inputs.exponent > 0:
        db.error(f"inputs:exponent must be > 0 (the ease curve's degree), got {inputs.exponent}")
    path = path_of(db)
    try:
        start = db.world.local_transform(path)
        goal = goal_of(db, start)
    except WorldError as error:
        db.error(f"{path}: {error}")
    db.internal["maneuver"] = (path, start, goal)
    db.state.elapsed = 0.0
    db.state.lastFrame = db.frame
    db.outputs.finished = ExecState.LATENT_PUSH


def _advance(db) -> None:
    path, start, goal = db.internal["maneuver"]
    alpha = min(db.state.elapsed * db.inputs.speed, 1.0)
    arrived = alpha >= 1.0 - _EPSILON
    f = 1.0 if arrived else eased("EaseInOut", alpha, db.inputs.exponent)
    translation = tuple(a + (b - a) * f for a, b in zip(start[0], goal[0]))
    scale = tuple(a + (b - a) * f for a, b in zip(start[2], goal[2]))
    try:
        db.world.set_local_transform(path, translation, slerp(start[1], goal[1], f), scale)
    except WorldError as error:
        db.error(f"{path}: {error}")
    if arrived:
        db.outputs.finished = ExecState.LATENT_FINISH


def slerp(a, b, f: float):
    """The (x, y, z, w) rotation a fraction f of the shortest arc from a to b."""
    dot = sum(p * q for p, q in zip(a, b))
    if dot < 0.0:
        b, dot = tuple(-c for c in b), -dot
    if dot > 1.0 - 1e-12:
        return quat_normalize(tuple(p + (q - p) * f for p, q in zip(a, b)))
    angle = math.acos(min(dot, 1.0))
    wa, wb = math.sin((1.0 - f) * angle) / math.sin(angle), math.sin(f * angle) / math.sin(angle)
    return quat_normalize(tuple(wa * p + wb * q for p, q in zip(a, b)))


def stage_units(db, vector) -> tuple:
    """A stage-unit vector in metres."""
    units = meters_per_unit(db.world)
    return tuple(float(c) * units for c in vector)


def euler_xyz_quaternion(degrees) -> tuple[float, float, float, float]:
    """The (x, y, z, w) rotation of USD's rotateXYZ (degrees): about X first, then Y, then Z."""
    x, y, z = (math.radians(float(c)) / 2.0 for c in degrees)
    cx, sx, cy, sy, cz, sz = math.cos(x), math.sin(x), math.cos(y), math.sin(y), math.cos(z), math.sin(z)
    # q = qz * qy * qx
    return quat_normalize((sx * cy * cz - cx * sy * sz, cx * sy * cz + sx * cy * sz,
                           cx * cy * sz - sx * sy * cz, cx * cy * cz + sx * sy * sz))


def source_prim(db) -> str:
    """The *ToTarget nodes' prim to move (sourcePrim, or sourcePrimPath when useSourcePath)."""
    return prim_path(db, "sourcePrim", "sourcePrimPath", "useSourcePath")


def target_goal(db):
    """(target prim, its world pose as a local pose of the source prim: in the source's parent frame)."""
    source, target = source_prim(db), prim_path(db, "targetPrim", "targetPrimPath", "useTargetPath")
    parent = source.rsplit("/", 1)[0]
    parent_pose = IDENTITY_POSE
    if parent:
        try:
            parent_pose = db.world.prim_pose(parent)
        except WorldError:
            pass
    return target, relative(parent_pose, db.world.prim_pose(target))
