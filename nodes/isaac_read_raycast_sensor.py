"""isaacsim.sensors.physics.IsaacReadRaycastSensor: the rays of an IsaacRaycastSensor prim, cast each reading.

As Isaac's sensor: the prim's numRays, rayOrigins and rayDirections (sensor
frame), minRange, maxRange, rayTimeOffsets, outputFrameOfReference and
reportHitPrimPaths are read once. Each ray starts minRange along its direction
and reaches maxRange; a miss reads maxRange. With time offsets the rays sweep:
a reading casts only the rays whose offset falls in the last step of the
period max(offsets), each from the sensor pose extrapolated by the body's
velocity over its offset.
"""
import math

from graphflow.poses import quat_conjugate, quat_normalize, quat_rotate
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState
from graphflow.world import WorldError

SPEC = NodeSpec(
    id="isaacsim.sensors.physics.IsaacReadRaycastSensor",
    version=1,
    description=(
        "On execIn, casts the rays of the IsaacRaycastSensor prim raycastSensorPrim: per ray the depth (maxRange "
        "on a miss), hit position and normal (flat x, y, z lists, in the sensor frame unless "
        "outputFrameOfReference is WORLD), hit prim (when reportHitPrimPaths) and world-frame beam origin "
        "and end point. execOut fires when the sensor gave a reading (not while it is disabled)."),
    categories=("isaacPhysicsSensor",),
    ui_name="Isaac Read Raycast Sensor Node",
    inputs=(
        Attribute("execIn", "execution", description="Read the sensor"),
        Attribute("raycastSensorPrim", "target", description="The IsaacRaycastSensor prim"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires when the sensor has data"),
        Attribute("sensorTime", "float", default=0.0, description="Simulated time of the reading, s"),
        Attribute("depths", "float[]", description="Per ray: distance to the hit, maxRange on a miss"),
        Attribute("hitPositions", "float[]", description="Per ray x, y, z of the hit (0 on a miss)"),
        Attribute("hitNormals", "float[]", description="Per ray x, y, z of the surface normal (0 on a miss)"),
        Attribute("hitPrimPaths", "token[]", description="Per ray the prim hit (empty unless reportHitPrimPaths)"),
        Attribute("numRays", "uint", default=0, description="Number of rays"),
        Attribute("beamOrigins", "pointf[3][]", default=(), description="Per ray world origin"),
        Attribute("beamEndPoints", "pointf[3][]", default=(), description="Per ray world hit or max-range end"),
    ),
)


def _config(db, path: str) -> dict:
    """The sensor prim's schema attributes (Isaac reads them once per run)."""
    stage = db.world.stage
    if stage is None:
        db.error("this graph names no stage, so there is no raycast sensor prim to read")
    prim = stage.GetPrimAtPath(path)
    if not prim:
        db.error(f"inputs:raycastSensorPrim: no prim {path} on the stage")

    def value(name, default):
        attribute = prim.GetAttribute(name)
        authored = attribute.Get() if attribute else None
        return default if authored is None else authored

    count = int(value("numRays", 1))
    origins = [tuple(map(float, o)) for o in value("rayOrigins", [])]
    directions = [tuple(map(float, d)) for d in value("rayDirections", [])]
    offsets = [float(t) for t in value("rayTimeOffsets", [])]
    near, far = float(value("minRange", 0.4)), float(value("maxRange", 100.0))
    where = f"inputs:raycastSensorPrim: {path}"
    if count <= 0:
        db.error(f"{where}: numRays must be > 0, got {count}")
    if near >= far:
        db.error(f"{where}: minRange {near} is not below maxRange {far}")
    for name, items in (("rayOrigins", origins), ("rayDirections", directions)):
        if len(items) != count:
            db.error(f"{where}: {name} has {len(items)} entries for numRays {count}")
    if offsets and len(offsets) != count:
        db.error(f"{where}: rayTimeOffsets has {len(offsets)} entries for numRays {count}")
    units = []
    for d in directions:
        length = math.sqrt(sum(c * c for c in d))
        units.append(tuple(c / length for c in d) if length > 1e-9 else (1.0, 0.0, 0.0))
    return {"count": count, "origins": origins, "directions": units, "offsets": offsets, "near": near, "far": far,
            "enabled": bool(value("enabled", True)), "world_frame": value("outputFrameOfReference", "") == "WORLD",
            "paths": bool(value("reportHitPrimPaths", False)), "period": max(offsets, default=0.0)}


def _active(config, step: int, dt: float):
    """Per ray: whether it fires in this reading (every ray without a sweep)."""
    period = config["period"]
    if period <= 0.0:
        return [True] * config["count"]
    end = math.fmod(step * dt, period)
    start, wrapped = end - dt, False
    if start < 0.0:
        start, wrapped = start + period, True
    offsets = config["offsets"]
    return [(t >= start or t < end) if wrapped else (start <= t < end) for t in offsets]


def _extrapolated(position, orientation, linear, angular, offset):
    """The sensor pose *offset* seconds on at the body's velocity (Isaac's first-order step of the rotation)."""
    if abs(offset) <= 1e-9 or not any(linear) and not any(angular):
        return position, orientation
    wx, wy, wz = (0.5 * w * offset for w in angular)
    x, y, z, w = orientation
    turned = (x + wx * w + wy * z - wz * y, y - wx * z + wy * w + wz * x, z + wx * y - wy * x + wz * w,
              w - wx * x - wy * y - wz * z)
    return tuple(p + v * offset for p, v in zip(position, linear)), quat_normalize(turned)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    if not db.inputs.raycastSensorPrim:
        db.error("inputs:raycastSensorPrim is not set: no sensor to read")
    path = db.inputs.raycastSensorPrim[0]
    config = db.internal.get("config") or db.internal.setdefault("config", _config(db, path))
    if not config["enabled"]:
        db.log(f"{path}: the raycast sensor is disabled (enabled = false): no reading", "warning")
        return
    try:
        position, orientation = db.world.prim_pose(path)
        linear, angular = db.world.prim_velocity(path) if config["offsets"] else ((0.0,) * 3, (0.0,) * 3)
        readings = [_ray(db, config, i, position, orientation, linear, angular) if active
                    else _idle(config, position)
                    for i, active in enumerate(_active(config, db.world.step_index, db.time_step))]
    except WorldError as error:
        db.error(f"inputs:raycastSensorPrim: {path}: {error}")
    outputs = db.outputs
    outputs.depths = tuple(r[0] for r in readings)
    outputs.hitPositions = tuple(c for r in readings for c in r[1])
    outputs.hitNormals = tuple(c for r in readings for c in r[2])
    outputs.hitPrimPaths = tuple(r[3] for r in readings)
    outputs.beamOrigins = tuple(r[4] for r in readings)
    outputs.beamEndPoints = tuple(r[5] for r in readings)
    outputs.numRays = config["count"]
    outputs.sensorTime = float(db.time)
    outputs.execOut = ExecState.ENABLED


def _idle(config, position):
    """A ray outside this reading's sweep window: Isaac's blank values."""
    return config["far"], (0.0, 0.0, 0.0), (0.0, 0.0, 0.0), "", tuple(position), tuple(position)


def _ray(db, config, i, position, orientation, linear, angular):
    offset = config["offsets"][i] if config["offsets"] else 0.0
    ray_position, ray_orientation = _extrapolated(position, orientation, linear, angular, offset)
    origin = tuple(p + c for p, c in zip(ray_position, quat_rotate(ray_orientation, config["origins"][i])))
    direction = quat_rotate(ray_orientation, config["directions"][i])
    near, far = config["near"], config["far"]
    start = tuple(o + near * d for o, d in zip(origin, direction))
    hit = db.world.raycast(start, direction, far - near)
    if hit is None:
        end = tuple(o + far * d for o, d in zip(origin, direction))
        return far, (0.0, 0.0, 0.0), (0.0, 0.0, 0.0), "", origin, end
    point, normal = tuple(hit.position), tuple(hit.normal)
    if not config["world_frame"]:
        inverse = quat_conjugate(ray_orientation)
        point = quat_rotate(inverse, tuple(p - c for p, c in zip(point, ray_position)))
        normal = quat_rotate(inverse, normal)
    return (hit.distance + near, point, normal, hit.prim_path if config["paths"] else "", origin,
            tuple(hit.position))
