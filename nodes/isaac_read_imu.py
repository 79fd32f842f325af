"""isaacsim.sensors.physics.IsaacReadIMU: an IMU from the physics of the body it sits on.

Linear acceleration is the change of the prim's world velocity over the last
physics step minus gravity (an IMU at rest reads +9.81 m/s^2 up, as Isaac's
with readGravity), and angular velocity is the prim's; both are given in the
IMU prim's own frame. The first compute after a reset has no previous
velocity and reports zero acceleration (plus gravity).
"""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState
from graphflow.world import WorldError, on_nearest_ancestor

from ._ros2 import rotate_into

SPEC = NodeSpec(
    id="isaacsim.sensors.physics.IsaacReadIMU",
    version=1,
    aliases=("omni.isaac.isaac_sensor.IsaacReadIMU", "omni.isaac.sensor.IsaacReadIMU"),
    description=(
        "On execIn, reads the IMU at imuPrim (a rigid body or a prim carried by one): linear acceleration "
        "(m/s^2, with gravity when readGravity) and angular velocity (rad/s) in the IMU frame, and its world "
        "orientation (x, y, z, w)."),
    categories=("isaacSensor",),
    ui_name="Isaac Read IMU Node",
    inputs=(
        Attribute("execIn", "execution", description="Read the sensor"),
        Attribute("imuPrim", "target", description="The IMU prim"),
        Attribute("readGravity", "bool", default=True, description="Include gravity in the acceleration"),
        Attribute("useLatestData", "bool", default=False,
                  description="Ignored (deprecated in Isaac too): every reading is the latest physics step's"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires after the reading"),
        Attribute("linAcc", "vectord[3]", description="Linear acceleration in the IMU frame, m/s^2"),
        Attribute("angVel", "vectord[3]", description="Angular velocity in the IMU frame, rad/s"),
        Attribute("orientation", "quatd[4]", default=(0.0, 0.0, 0.0, 1.0), description="World orientation (x, y, z, w)"),
        Attribute("sensorTime", "float", description="Simulated time of the reading, s"),
    ),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    if not db.inputs.imuPrim:
        db.error("inputs:imuPrim is not set: no IMU to read")
    path = db.inputs.imuPrim[0]
    try:
        position, orientation = db.world.prim_pose(path)
        linear, angular = _velocity_at(db, path, position)
        gravity = db.world.gravity() if db.inputs.readGravity else (0.0, 0.0, 0.0)
    except WorldError as error:
        db.error(f"inputs:imuPrim: {error}")
    previous = db.internal.get("velocity")
    step = db.world.step_index - db.internal.get("step", db.world.step_index)
    if previous is None or step <= 0:
        acceleration = (0.0, 0.0, 0.0)
    else:
        elapsed = step * db.world.time_step
        acceleration = tuple((now - before) / elapsed for now, before in zip(linear, previous))
    db.internal["velocity"], db.internal["step"] = tuple(linear), db.world.step_index
    proper = tuple(a - g for a, g in zip(acceleration, gravity))
    db.outputs.linAcc = rotate_into(orientation, proper)
    db.outputs.angVel = rotate_into(orientation, angular)
    db.outputs.orientation = tuple(float(c) for c in orientation)
    db.outputs.sensorTime = float(db.time)
    db.outputs.execOut = ExecState.ENABLED


def _velocity_at(db, path: str, position):
    """World velocity of the point *position* carried by *path*'s body (the nearest ancestor that is a body)."""
    body, (linear, angular) = on_nearest_ancestor(path, db.world.prim_velocity)
    origin = db.world.prim_pose(body)[0]
    r = tuple(p - o for p, o in zip(position, origin))
    carried = (angular[1] * r[2] - angular[2] * r[1], angular[2] * r[0] - angular[0] * r[2],
               angular[0] * r[1] - angular[1] * r[0])
    return tuple(v + c for v, c in zip(linear, carried)), tuple(angular)
