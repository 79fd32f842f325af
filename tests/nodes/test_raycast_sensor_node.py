"""IsaacReadRaycastSensor against ray geometry worked by hand on a fake world of boxes."""
import math

import pytest
from pxr import Sdf, Usd

from graphflow.poses import quat_from_axis_angle
from graphflow.testing import NodeHarness
from graphflow.testing.fake_world import FakeWorld

NODE = "isaacsim.sensors.physics.IsaacReadRaycastSensor"


def _world(frame="SENSOR", offsets=None, yaw=0.0):
    """A sensor 1 m above a base box at the origin, turned *yaw* about z, with two rays: along its +x from
    (0, 0.2, 0) and along its -x; a wall (a box with faces at x = 2.5 and 3.5) ahead along world +x."""
    stage = Usd.Stage.CreateInMemory()
    prim = stage.DefinePrim("/World/Base/Sensor", "IsaacRaycastSensor")
    values = {"numRays": (Sdf.ValueTypeNames.UInt, 2), "minRange": (Sdf.ValueTypeNames.Float, 0.4),
              "maxRange": (Sdf.ValueTypeNames.Float, 10.0),
              "rayOrigins": (Sdf.ValueTypeNames.Float3Array, [(0.0, 0.2, 0.0), (0.0, 0.0, 0.0)]),
              "rayDirections": (Sdf.ValueTypeNames.Float3Array, [(2.0, 0.0, 0.0), (-1.0, 0.0, 0.0)]),
              "outputFrameOfReference": (Sdf.ValueTypeNames.Token, frame),
              "reportHitPrimPaths": (Sdf.ValueTypeNames.Bool, True)}
    if offsets is not None:
        values["rayTimeOffsets"] = (Sdf.ValueTypeNames.FloatArray, offsets)
    for name, (kind, value) in values.items():
        prim.CreateAttribute(name, kind).Set(value)
    world = FakeWorld(stage=stage)
    world.add_box("/World/Base", (0.0, 0.0, 0.0), (0.1, 0.1, 0.1))
    world.add_frame("/World/Base/Sensor", "/World/Base",
                    ((0.0, 0.0, 1.0), quat_from_axis_angle((0.0, 0.0, 1.0), yaw)))
    world.add_box("/World/Wall", (3.0, 0.0, 1.0), (0.5, 2.0, 1.0))
    return world


def test_a_ray_reads_the_distance_from_the_sensor_and_a_miss_reads_max_range():
    out = NodeHarness(NODE, {"raycastSensorPrim": ["/World/Base/Sensor"]}, world=_world()).compute("execIn").outputs
    assert out["numRays"] == 2
    assert out["depths"] == pytest.approx((2.5, 10.0))      # the wall face is 2.5 m along +x; nothing behind
    assert out["hitPositions"] == pytest.approx((2.5, 0.2, 0.0, 0.0, 0.0, 0.0))     # sensor frame
    assert out["hitNormals"] == pytest.approx((-1.0, 0.0, 0.0, 0.0, 0.0, 0.0))
    assert out["hitPrimPaths"] == ("/World/Wall", "")
    assert _flat(out["beamOrigins"]) == pytest.approx((0.0, 0.2, 1.0, 0.0, 0.0, 1.0))
    assert _flat(out["beamEndPoints"]) == pytest.approx((2.5, 0.2, 1.0, -10.0, 0.0, 1.0))


def test_a_turned_sensor_reports_in_its_own_frame_unless_asked_for_world():
    """Turned 30 deg: the first ray meets the face x = 2.5 after 2.5 / cos 30 - its origin's x offset."""
    yaw = math.radians(30.0)
    origin = (-0.2 * math.sin(yaw), 0.2 * math.cos(yaw))
    distance = (2.5 - origin[0]) / math.cos(yaw)
    sensor = NodeHarness(NODE, {"raycastSensorPrim": ["/World/Base/Sensor"]},
                         world=_world(yaw=yaw)).compute("execIn").outputs
    assert sensor["depths"][0] == pytest.approx(distance)
    assert sensor["hitPositions"][:3] == pytest.approx((distance, 0.2, 0.0))
    world = NodeHarness(NODE, {"raycastSensorPrim": ["/World/Base/Sensor"]},
                        world=_world("WORLD", yaw=yaw)).compute("execIn").outputs
    assert world["hitPositions"][:3] == pytest.approx((2.5, origin[1] + distance * math.sin(yaw), 1.0))
    assert world["hitNormals"][:3] == pytest.approx((-1.0, 0.0, 0.0))


def test_time_offsets_sweep_the_rays_one_step_window_at_a_time():
    """Offsets 0 and 0.05 s: a 0.05 s sweep, so step 1's window [0, 1/60 s) casts only the first ray; the
    other reads max range from the sensor's own position."""
    world = _world(offsets=[0.0, 0.05])
    world.step()
    out = NodeHarness(NODE, {"raycastSensorPrim": ["/World/Base/Sensor"]}, world=world).compute("execIn").outputs
    assert out["depths"] == pytest.approx((2.5, 10.0))
    assert out["beamEndPoints"][1] == pytest.approx((0.0, 0.0, 1.0))


def _flat(points):
    return tuple(c for point in points for c in point)
