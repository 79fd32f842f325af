"""Contacts at the stage's own rate (60 Hz): drops, resting cubes and a pyramid, on Plane and box grounds.

The scenes are USD stages loaded through graphflow's importer, as a user's would be.
"""
import math

import pytest
from pxr import Gf, Usd, UsdGeom, UsdPhysics

from graphflow.physics import create_world

RATE = 60.0
DROP_HEIGHT = 0.15
CUBES = [(0.04, 0.1), (0.04, 3.0), (0.07, 0.1), (0.07, 3.0), (0.05, 1.0)]   # edge (m), mass (kg)


def cube_stage(ground, cubes, rate=RATE):
    """A stage at *rate* Hz with a ground ("plane": a UsdGeom.Plane collider; "box": a static cube)
    and dynamic cubes [(path, edge, mass, (x, y, z))]."""
    stage = Usd.Stage.CreateInMemory()
    UsdGeom.SetStageUpAxis(stage, UsdGeom.Tokens.z)
    UsdGeom.SetStageMetersPerUnit(stage, 1.0)
    UsdGeom.Xform.Define(stage, "/World")
    scene = UsdPhysics.Scene.Define(stage, "/World/PhysicsScene")
    scene.GetPrim().CreateAttribute("physxScene:timeStepsPerSecond", Sdf_uint()).Set(int(rate))
    if ground == "plane":
        plane = UsdGeom.Plane.Define(stage, "/World/Ground")
        plane.CreateAxisAttr("Z")
        UsdPhysics.CollisionAPI.Apply(plane.GetPrim())
    else:
        box = UsdGeom.Cube.Define(stage, "/World/Ground")
        box.CreateSizeAttr(1.0)
        box.AddTranslateOp().Set(Gf.Vec3d(0, 0, -0.5))
        box.AddScaleOp().Set(Gf.Vec3f(10, 10, 1))
        UsdPhysics.CollisionAPI.Apply(box.GetPrim())
    for path, edge, mass, position in cubes:
        cube = UsdGeom.Cube.Define(stage, path)
        cube.CreateSizeAttr(edge)
        cube.AddTranslateOp().Set(Gf.Vec3d(*position))
        UsdPhysics.RigidBodyAPI.Apply(cube.GetPrim())
        UsdPhysics.CollisionAPI.Apply(cube.GetPrim())
        UsdPhysics.MassAPI.Apply(cube.GetPrim()).CreateMassAttr(mass)
    return stage


def Sdf_uint():
    from pxr import Sdf

    return Sdf.ValueTypeNames.UInt


def tilt_degrees(orientation):
    return math.degrees(2.0 * math.acos(min(1.0, abs(orientation[3]))))


def angle_between_degrees(q, r):
    dot = abs(sum(a * b for a, b in zip(q, r)))
    return math.degrees(2.0 * math.acos(min(1.0, dot)))


def drop(ground, edge, mass):
    """(worst penetration in m, time from impact to rest in s) of a cube dropped flat from 0.15 m."""
    stage = cube_stage(ground, [("/World/Cube", edge, mass, (0.0, 0.0, DROP_HEIGHT + edge / 2))])
    with create_world(stage) as world:
        assert world.time_step == pytest.approx(1 / RATE) and world.substeps == 4
        worst, impact, rest = 0.0, None, None
        for _ in range(int(1.5 * RATE)):
            world.step()
            position, orientation = world.prim_pose("/World/Cube")
            speed = math.sqrt(sum(v * v for v in world.prim_velocity("/World/Cube")[0]))
            worst = max(worst, edge / 2 - position[2])
            if impact is None and position[2] < edge / 2 + 1e-3:
                impact = world.time
            at_rest = abs(position[2] - edge / 2) < 0.5e-3 and tilt_degrees(orientation) < 1.0 and speed < 1e-3
            if impact is not None:
                rest = (rest if rest is not None else world.time - impact) if at_rest else None
    return worst, rest


@pytest.mark.parametrize("ground", ["plane", "box"])
def test_a_dropped_cube_barely_penetrates_and_rests_quickly(ground):
    """Measured: 3.2 mm worst, at rest 0.217 s after impact, every size and mass, both grounds
    (at one step per tick and PyBullet's plane shape: 20-41 mm, 1-2 s, some never at rest)."""
    for edge, mass in CUBES:
        penetration, rest = drop(ground, edge, mass)
        assert penetration < 5e-3, (edge, mass, penetration)
        assert rest is not None and rest <= 0.3, (edge, mass, rest)


def pyramid(edge=0.04):
    """A 3-2-1 pyramid of cubes (a small gap between neighbours) and two lone cubes."""
    cubes = []
    for row, count in enumerate((3, 2, 1)):
        for index in range(count):
            x = (index - (count - 1) / 2) * (edge + 0.002)
            cubes.append((f"/World/P{row}{index}", edge, 0.1, (x, 0.0, edge / 2 + row * edge)))
    cubes.append(("/World/Lone0", 0.05, 1.0, (0.3, 0.0, 0.025)))
    cubes.append(("/World/Lone1", 0.07, 3.0, (-0.3, 0.0, 0.035)))
    return cubes


@pytest.mark.slow
@pytest.mark.parametrize("ground", ["plane", "box"])
def test_resting_cubes_and_a_pyramid_stay_put_for_60_s(ground):
    """Measured: pyramid blocks within 0.066 mm of where they were placed, lone cubes 0.013 mm and
    0.0074 deg, both grounds (one step per tick, no friction anchor: 12 mm box, 220 mm plane)."""
    cubes = pyramid()
    with create_world(cube_stage(ground, cubes)) as world:
        start = {path: (position, (0.0, 0.0, 0.0, 1.0)) for path, _edge, _mass, position in cubes}
        for _ in range(int(60 * RATE)):
            world.step()
        for path, *_ in cubes:
            position, orientation = world.prim_pose(path)
            moved = math.dist(position, start[path][0])
            if path.startswith("/World/Lone"):
                assert moved < 0.5e-3, (path, moved)
                assert angle_between_degrees(orientation, start[path][1]) < 0.5, path
            else:
                assert moved < 1e-3, (path, moved)


def test_substeps_follow_the_stage_rate_and_settings_override_them(tmp_path):
    """At most 1/240 s per PyBullet step: 4 at 60 Hz, 2 at 120 Hz, 1 at 240 Hz; settings.substeps wins."""
    import json

    from graphflow.document import load_document
    from graphflow.runtime import create_world_for

    for rate, substeps in ((60, 4), (120, 2), (240, 1)):
        with create_world(cube_stage("box", [], rate=rate)) as world:
            assert (world.time_step, world.substeps) == (pytest.approx(1 / rate), substeps)
    authored = cube_stage("box", [])          # kept alive while its layer is exported
    authored.GetRootLayer().Export(str(tmp_path / "stage.usda"))
    graph = tmp_path / "graph.json"
    graph.write_text(json.dumps({"format": "graphflow", "formatVersion": [1, 0],
                                 "settings": {"stage": "stage.usda", "substeps": 2}, "nodes": [], "connections": []}))
    world = create_world_for(load_document(graph))
    try:
        assert world.substeps == 2
    finally:
        world.close()


def test_authored_solver_iteration_counts_raise_or_clamp_pybullets_one_count():
    stage = cube_stage("box", [("/World/Cube", 0.05, 1.0, (0.0, 0.0, 0.025))])
    with create_world(stage) as world:
        assert world.solver_iterations == 50
    stage.GetPrimAtPath("/World/Cube").CreateAttribute("physxRigidBody:solverPositionIterationCount",
                                                       Sdf_uint()).Set(64)
    with create_world(stage) as world:
        assert world.solver_iterations == 64
    stage.GetPrimAtPath("/World/PhysicsScene").CreateAttribute("physxScene:maxPositionIterationCount",
                                                               Sdf_uint()).Set(32)
    with create_world(stage) as world:
        assert world.solver_iterations == 32
