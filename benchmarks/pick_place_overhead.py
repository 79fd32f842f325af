"""pick_place_overhead: graphs/ur10_pick_place.json against the same control written as a plain script.

graphflow: the graph run by ``Simulation`` until it stops itself. Baseline: a
for loop over the same number of physics steps of the same world (the same
stage loaded by graphflow.physics, the same surface-gripper service), doing
inline what the graph's nodes do each tick: read the cube pose, advance the
same phase machine (``graphflow_nodes._pick_place.PickPlaceRun``), solve the
same UR10 IK and send the joint targets (``Arm``), command the gripper, and
on each phase change read the gripper status and format the phase line. The
two runs must end with the cube in the same place (checked). Both reset their
world between repetitions; only the stepping loops are timed.
"""
from __future__ import annotations

import logging

from . import clock, line, paired_ratio
from ._scenes import PICK_PLACE, bare_world, require, simulation

CUBE = "/World/Cube"
log = logging.getLogger("graphflow.graph")


class InlineScript:
    """The baseline: the graph's per-tick work written out by hand, one ``step()`` per tick."""

    def __init__(self, world, inputs):
        from graphflow_nodes._arm import Arm
        from graphflow_nodes._pick_place import DEFAULT_INITIAL_HEIGHT, EVENT_NAMES, gripper_manager

        self.world = world
        self._event_names, self._arm_type, self._manager_for = EVENT_NAMES, Arm, gripper_manager
        self._height = DEFAULT_INITIAL_HEIGHT
        self.robot, self.gripper = inputs.robotPrim[0], inputs.gripperPrim[0]
        self.placing, self.offset = tuple(inputs.placingPosition), tuple(inputs.endEffectorOffset)
        self.orientation = tuple(inputs.endEffectorOrientation)
        self.events_dt = tuple(inputs.eventsDT)
        self.reset()

    def reset(self) -> None:
        from graphflow_nodes._pick_place import PickPlaceRun

        self.world.reset()
        self.routine = PickPlaceRun(self.events_dt, self._height)
        self.arm = self.manager = self.reported = None

    def step(self) -> None:
        world, routine = self.world, self.routine
        world.step()
        position, _orientation = world.prim_pose(CUBE)
        picking = tuple(float(c) for c in position)
        if self.reported != routine.event:      # a phase begins: report it with the gripper status
            self.reported = routine.event
            self.manager = self.manager or self._manager_for(world)
            status = self.manager.component(self.gripper).status.token
            log.info("phase %s %s: gripper %s", self.reported, self._event_names[self.reported], status)
        if routine.done:
            return
        self.arm = self.arm or self._arm_type(world, self.robot, self.gripper)
        kind, tip = routine.step(picking, self.placing, self.offset)
        if kind == "move":
            self.arm.move_tip(tip, self.orientation)
        elif kind == "close":
            self.manager.close_gripper(self.gripper)
        elif kind == "open":
            self.manager.open_gripper(self.gripper)


def run(quick: bool = False) -> str:
    require(PICK_PLACE)
    sim = simulation(PICK_PLACE)
    world = bare_world(PICK_PLACE)
    limit, repetitions, chunk = (20, 1, 10) if quick else (None, 3, 25)
    try:
        ticks = sim.run(ticks=limit).ticks          # how many ticks the graph takes (it stops itself)
        script = InlineScript(world, sim.instance.database("pick_place").inputs)   # the node's (coerced) inputs
        candidates = {"graphflow": sim.step, "baseline": script.step}
        samples = {"graphflow": [], "baseline": []}
        for _ in range(repetitions):              # both sides advance in lockstep, chunk by chunk
            sim.reset()
            script.reset()
            for start in range(0, ticks, chunk):
                count = min(chunk, ticks - start)
                order = ("graphflow", "baseline") if (start // chunk) % 2 else ("baseline", "graphflow")
                for name in order:
                    step = candidates[name]
                    started = clock()
                    for _ in range(count):
                        step()
                    samples[name].append(clock() - started)
        graph_times, script_times = samples["graphflow"], samples["baseline"]
        graph_cube, script_cube = sim.world.prim_pose(CUBE)[0], world.prim_pose(CUBE)[0]
        if max(abs(a - b) for a, b in zip(graph_cube, script_cube)) > 1e-6:
            raise AssertionError(f"the script did not do what the graph did: cube at {script_cube}, graph {graph_cube}")
    finally:
        sim.close()
        world.close()
    total = ticks * repetitions
    per_tick = {"graphflow": sum(graph_times) / total * 1e6, "baseline": sum(script_times) / total * 1e6}
    print(f"pick_place_overhead: {ticks} ticks x {repetitions} repetitions, interleaved in chunks of {chunk} ticks; "
          f"graph overhead {per_tick['graphflow'] - per_tick['baseline']:.1f} µs/tick (CPU time)")
    return line("pick_place_overhead", paired_ratio(graph_times, script_times),
                graphflow=f"{per_tick['graphflow']:.1f}us/tick", baseline=f"{per_tick['baseline']:.1f}us/tick",
                ticks=f"{ticks}")

