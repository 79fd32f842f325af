"""plain_pybullet: graphs/ur10_pick_place.json against the same pick and place written with raw PyBullet calls.

Baseline (``PlainPickPlace``): no graphflow import at all. The same UR10 numbers
as graphflow's packaged asset (ros-industrial's kinetic ur10 joint chain,
masses and inertias, our suction tool 0.1611 m out of ee_link), written here as
a URDF; PyBullet's own position motors (``POSITION_CONTROL``, the asset's max
forces); PyBullet's IK (``calculateInverseKinematics``) for the suction tip;
suction as a ``JOINT_FIXED`` constraint made when a 10 mm ray from the tip hits
the cube. The same ten phases with Isaac's phase increments and cosine blends,
the same number of ticks, PyBullet stepped at the same internal rate graphflow
uses (its time step, substeps, solver iterations and residual are read off the graphflow
world and passed in). The two runs must put the cube within 5 mm of each other
(checked), so the baseline is doing the same job, not a cheaper one.

graphflow: ``Simulation.step`` of the graph (physics, drives, the surface
gripper's compliant hold and force checks, IK on the kinematic copy, the graph).
Both are interleaved in chunks; CPU time per tick is compared, and the real-time
factor of the graph is reported on the CPU clock and on the wall clock.
"""
from __future__ import annotations

import math
import os
import tempfile
import time

from . import clock, line, paired_ratio
from ._scenes import PICK_PLACE, quiet, require, simulation

CUBE_PATH = "/World/Cube"
CUBE_SIZE = 0.0515
CUBE_MASS = 1000.0 * CUBE_SIZE ** 3                 # the asset's density 1000 kg/m3
CUBE_START = (0.3, 0.3, CUBE_SIZE / 2)
PLACE = (0.7, 0.7, CUBE_SIZE / 2)
OFFSET = (0.0, 0.0, 0.03)                           # the graph's endEffectorOffset
EVENTS_DT = (0.01, 0.0035, 0.01, 1.0, 0.008, 0.005, 0.005, 1.0, 0.01, 0.08)
LIFT_HEIGHT = 0.3
DEFAULT_JOINTS = (-math.pi / 2, -math.pi / 2, -math.pi / 2, -math.pi / 2, math.pi / 2, 0.0)
SUCTION_DOWN = (0.0, math.sqrt(0.5), 0.0, math.sqrt(0.5))     # ee_link +X pointing down (x, y, z, w)
SUCTION_REACH = 0.01                                # the asset's maxGripDistance

_CYLINDER_Y = 'rpy="1.5707963 0 0"'
_CYLINDER_X = 'rpy="0 1.5707963 0"'
# (name, mass, inertia diagonal, centre of mass, collision (shape, size, xyz, rpy)); joints below
_LINKS = (
    ("base_link", 4.0, (0.006106333, 0.006106333, 0.01125), (0, 0, 0), ("cylinder", (0.075, 0.038), (0, 0, 0.019), "")),
    ("shoulder_link", 7.778, (0.031474326, 0.031474326, 0.021875625), (0, 0, 0),
     ("cylinder", (0.075, 0.178), (0, 0, 0), "")),
    ("upper_arm_link", 12.93, (0.421753973, 0.421753973, 0.036365625), (0, -0.045, 0.306),
     ("capsule", (0.06, 0.492), (0, -0.045, 0.306), "")),
    ("forearm_link", 3.87, (0.111069739, 0.111069739, 0.010884375), (0, 0, 0.28615),
     ("capsule", (0.05, 0.4723), (0, 0, 0.28615), "")),
    ("wrist_1_link", 1.96, (0.00510825, 0.00510825, 0.0055125), (0, 0.1149, 0),
     ("cylinder", (0.045, 0.12), (0, 0.1149, 0), _CYLINDER_Y)),
    ("wrist_2_link", 1.96, (0.00510825, 0.00510825, 0.0055125), (0, 0, 0.1157),
     ("cylinder", (0.045, 0.12), (0, 0, 0.1157), "")),
    ("wrist_3_link", 0.202, (0.000117922, 0.000204525, 0.000117922), (0, 0.07695, 0),
     ("cylinder", (0.045, 0.0305), (0, 0.07695, 0), _CYLINDER_Y)),
    ("ee_link", 0.1, (2e-05, 0.000226277, 0.000226277), (0.08, 0, 0),
     ("cylinder", (0.02, 0.15), (0.075, 0, 0), _CYLINDER_X)),
)
# (name, parent, child, xyz, rpy, axis or None for fixed, max effort N m)
_JOINTS = (
    ("shoulder_pan_joint", "base_link", "shoulder_link", (0, 0, 0.1273), (0, 0, 0), "0 0 1", 330.0),
    ("shoulder_lift_joint", "shoulder_link", "upper_arm_link", (0, 0.220941, 0), (0, math.pi / 2, 0), "0 1 0", 330.0),
    ("elbow_joint", "upper_arm_link", "forearm_link", (0, -0.1719, 0.612), (0, 0, 0), "0 1 0", 150.0),
    ("wrist_1_joint", "forearm_link", "wrist_1_link", (0, 0, 0.5723), (0, math.pi / 2, 0), "0 1 0", 54.0),
    ("wrist_2_joint", "wrist_1_link", "wrist_2_link", (0, 0.1149, 0), (0, 0, 0), "0 0 1", 54.0),
    ("wrist_3_joint", "wrist_2_link", "wrist_3_link", (0, 0, 0.1157), (0, 0, 0), "0 1 0", 54.0),
    ("ee_fixed_joint", "wrist_3_link", "ee_link", (0, 0.0922, 0), (0, 0, math.pi / 2), None, 0.0),
    ("tip_joint", "ee_link", "tip_link", (0.1611, 0, 0), (0, 0, 0), None, 0.0),
)


def ur10_urdf() -> str:
    """The UR10 with its suction tip link, as a URDF document."""
    def xyz(values):
        return " ".join(f"{v:.9g}" for v in values)

    parts = ['<?xml version="1.0"?>', '<robot name="ur10">']
    for name, mass, inertia, com, (shape, size, origin, rpy) in _LINKS:
        geometry = (f'<cylinder radius="{size[0]}" length="{size[1]}"/>' if shape == "cylinder"
                    else f'<capsule radius="{size[0]}" length="{size[1]}"/>')
        parts.append(
            f'<link name="{name}"><inertial><origin xyz="{xyz(com)}"/><mass value="{mass}"/>'
            f'<inertia ixx="{inertia[0]}" iyy="{inertia[1]}" izz="{inertia[2]}" ixy="0" ixz="0" iyz="0"/></inertial>'
            f'<collision><origin xyz="{xyz(origin)}" {rpy}/><geometry>{geometry}</geometry></collision></link>')
    parts.append('<link name="tip_link"><inertial><mass value="0.001"/>'
                 '<inertia ixx="1e-9" iyy="1e-9" izz="1e-9" ixy="0" ixz="0" iyz="0"/></inertial></link>')
    for name, parent, child, origin, rpy, axis, effort in _JOINTS:
        kind = "revolute" if axis else "fixed"
        body = (f'<axis xyz="{axis}"/><limit lower="-6.2831853" upper="6.2831853" effort="{effort}" velocity="3.2"/>'
                if axis else "")
        parts.append(f'<joint name="{name}" type="{kind}"><parent link="{parent}"/><child link="{child}"/>'
                     f'<origin xyz="{xyz(origin)}" rpy="{xyz(rpy)}"/>{body}</joint>')
    parts.append("</robot>")
    return "\n".join(parts)


def _mix(t: float) -> float:
    return 0.5 * (1.0 - math.cos(math.pi * t))


class PlainPickPlace:
    """The pick and place with raw PyBullet calls only, one ``step()`` per graph tick."""

    def __init__(self, time_step: float, substeps: int, solver_iterations: int, solver_residual: float):
        import pybullet
        from pybullet_utils.bullet_client import BulletClient

        self.p = pybullet
        self.time_step, self.substeps, self.solver_iterations = time_step, substeps, solver_iterations
        self.solver_residual = solver_residual
        self.client = BulletClient(pybullet.DIRECT)
        handle, self._urdf = tempfile.mkstemp(suffix=".urdf", prefix="plain-ur10-")
        with os.fdopen(handle, "w") as urdf:
            urdf.write(ur10_urdf())
        self.reset()

    def reset(self) -> None:
        p, client = self.p, self.client
        client.resetSimulation()
        client.setPhysicsEngineParameter(fixedTimeStep=self.time_step / self.substeps, numSubSteps=0,
                                         numSolverIterations=self.solver_iterations, deterministicOverlappingPairs=1,
                                         solverResidualThreshold=self.solver_residual)
        client.setGravity(0, 0, -9.81)
        ground = client.createCollisionShape(p.GEOM_BOX, halfExtents=[25, 25, 0.5])
        client.createMultiBody(0, ground, -1, [0, 0, -0.5])
        cube_shape = client.createCollisionShape(p.GEOM_BOX, halfExtents=[CUBE_SIZE / 2] * 3)
        self.cube = client.createMultiBody(CUBE_MASS, cube_shape, -1, CUBE_START)
        self.arm = client.loadURDF(self._urdf, useFixedBase=True, flags=p.URDF_USE_INERTIA_FROM_FILE)
        self.joints = [i for i in range(client.getNumJoints(self.arm))
                       if client.getJointInfo(self.arm, i)[2] == p.JOINT_REVOLUTE]
        self.tip = client.getNumJoints(self.arm) - 1
        self.max_forces = [client.getJointInfo(self.arm, i)[10] for i in self.joints]
        for index, position in zip(self.joints, DEFAULT_JOINTS):
            client.resetJointState(self.arm, index, position)
        self.targets = list(DEFAULT_JOINTS)
        self._drive()
        self.event, self.t, self.pick, self.grip, self.ticks = 0, 0.0, CUBE_START, None, 0

    def _drive(self) -> None:
        self.client.setJointMotorControlArray(self.arm, self.joints, self.p.POSITION_CONTROL,
                                              targetPositions=self.targets, forces=self.max_forces)

    def _move_tip(self, tip) -> None:
        solution = self.client.calculateInverseKinematics(self.arm, self.tip, tip, SUCTION_DOWN,
                                                          maxNumIterations=50, residualThreshold=1e-5)
        self.targets = list(solution[:len(self.joints)])
        self._drive()

    def _close(self) -> None:
        client = self.client
        state = client.getLinkState(self.arm, self.tip, computeForwardKinematics=1)
        position, orientation = state[4], state[5]
        axis = client.getMatrixFromQuaternion(orientation)[0::3]        # tip +X in world
        end = [position[i] + axis[i] * SUCTION_REACH for i in range(3)]
        hit = client.rayTest(position, end)[0]
        if hit[0] != self.cube:
            return
        cube_position, cube_orientation = client.getBasePositionAndOrientation(self.cube)
        com = client.getLinkState(self.arm, self.tip)[0:2]
        inverse = client.invertTransform(*com)
        frame = client.multiplyTransforms(*inverse, cube_position, cube_orientation)
        self.grip = client.createConstraint(self.arm, self.tip, self.cube, -1, self.p.JOINT_FIXED, [0, 0, 0],
                                            frame[0], [0, 0, 0], frame[1])

    def step(self) -> None:
        for _ in range(self.substeps):
            self.client.stepSimulation()
        self.ticks += 1
        if self.event >= len(EVENTS_DT):
            return
        event, t = self.event, self.t
        if event == 3:
            self._close()
        elif event == 7:
            if self.grip is not None:
                self.client.removeConstraint(self.grip)
                self.grip = None
        elif event != 2:
            if event in (0, 1):
                self.pick = self.client.getBasePositionAndOrientation(self.cube)[0]
            a = _mix(t)
            alpha = 0.0 if event < 5 else (a if event == 5 else 1.0)
            x = (1 - alpha) * self.pick[0] + alpha * PLACE[0]
            y = (1 - alpha) * self.pick[1] + alpha * PLACE[1]
            h0, h1 = self.pick[2], LIFT_HEIGHT
            z = {0: h1, 1: (1 - a) * h1 + a * h0, 4: (1 - a) * h0 + a * h1, 5: h1,
                 6: (1 - a) * h1 + a * PLACE[2], 8: (1 - a) * PLACE[2] + a * h1, 9: h1}[event]
            self._move_tip((x + OFFSET[0], y + OFFSET[1], z + OFFSET[2]))
        self.t = t + EVENTS_DT[event]
        if self.t >= 1.0:
            self.event, self.t = event + 1, 0.0

    def cube_position(self):
        return self.client.getBasePositionAndOrientation(self.cube)[0]

    def close(self) -> None:
        self.client.disconnect()
        os.unlink(self._urdf)


def run(quick: bool = False) -> str:
    require(PICK_PLACE)
    sim = simulation(PICK_PLACE)
    world = sim.world
    with quiet():
        plain = PlainPickPlace(world.time_step, world.substeps, world.solver_iterations, world.solver_residual)
    limit, repetitions, chunk = (30, 1, 10) if quick else (None, 3, 25)
    try:
        ticks = sim.run(ticks=limit).ticks               # the graph stops itself when the routine is done
        samples = {"graphflow": [], "plain": []}
        steps = {"graphflow": sim.step, "plain": plain.step}
        wall = {"graphflow": 0.0, "plain": 0.0}
        for _ in range(repetitions):
            sim.reset()
            plain.reset()
            for start in range(0, ticks, chunk):
                count = min(chunk, ticks - start)
                order = ("graphflow", "plain") if (start // chunk) % 2 else ("plain", "graphflow")
                for name in order:
                    step = steps[name]
                    started, started_wall = clock(), time.perf_counter()
                    for _ in range(count):
                        step()
                    samples[name].append(clock() - started)
                    wall[name] += time.perf_counter() - started_wall
        graph_cube, plain_cube = world.prim_pose(CUBE_PATH)[0], plain.cube_position()
        miss = max(abs(a - b) for a, b in zip(graph_cube, plain_cube))
        if not quick and miss > 0.005:
            raise AssertionError(f"the plain script did not do what the graph did: cube at "
                                 f"{tuple(round(c, 4) for c in plain_cube)}, graph {tuple(round(c, 4) for c in graph_cube)}")
    finally:
        sim.close()
        plain.close()
    total = ticks * repetitions
    per_tick = {name: sum(values) / total * 1e6 for name, values in samples.items()}
    simulated = total * world.time_step
    print(f"plain_pybullet: {ticks} ticks x {repetitions}, {world.substeps} substep(s) of "
          f"{world.time_step / world.substeps * 1000:.3f} ms, {world.solver_iterations} solver iterations; "
          f"cubes {miss * 1000:.2f} mm apart; real time graphflow {simulated / sum(samples['graphflow']):.0f}x CPU, "
          f"{simulated / wall['graphflow']:.0f}x wall; plain {simulated / sum(samples['plain']):.0f}x CPU, "
          f"{simulated / wall['plain']:.0f}x wall")
    return line("plain_pybullet", paired_ratio(samples["graphflow"], samples["plain"]),
                graphflow=f"{per_tick['graphflow']:.1f}us/tick", plain=f"{per_tick['plain']:.1f}us/tick",
                realtime_cpu=f"{simulated / sum(samples['graphflow']):.0f}x",
                realtime_wall=f"{simulated / wall['graphflow']:.0f}x", ticks=f"{ticks}")
