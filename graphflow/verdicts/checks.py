"""Checks: what must be true of a run, stated in the graph document's ``checks`` section (docs/checks.md).

A ``CheckEvaluator`` is a per-tick run listener: ``on_tick(simulation, tick)`` after every
tick (physics step plus graph evaluation), ``finish(result)`` once the run has
ended. Every check that does not hold becomes one ``CheckFailure`` line naming
the file, the check, the measured value and the expected value. The evaluator
only reads the world (poses, the surface-gripper manager) and node outputs; it
never changes the run, so a checked run computes exactly what an unchecked one does.
"""
from __future__ import annotations

import io
import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Iterable, Mapping

END = "end"
AXIS_INDEX = {"x": 0, "y": 1, "z": 2}
LOCAL_AXES = {"X": (1.0, 0.0, 0.0), "Y": (0.0, 1.0, 0.0), "Z": (0.0, 0.0, 1.0)}


@dataclass(frozen=True)
class CheckFailure:
    """One check that did not hold: printed as one line."""

    file: str
    check: str
    measured: str
    expected: str

    def __str__(self) -> str:
        return f"{self.file}: check {self.check}: measured {self.measured}; expected {self.expected}"


def _point(values) -> str:
    return "(" + ", ".join(f"{v:.4f}" for v in values) + ")"


def _mm(metres: float) -> str:
    return f"{metres * 1000:.1f} mm"


def _when(at) -> str:
    return "at the end" if at == END else f"at t = {at:g} s"


def _gripper_manager(world):
    from graphflow.observe.trace import surface_gripper_manager

    return surface_gripper_manager(world)


def gripper_reason(world, path: str) -> str:
    """Why the gripper at *path* last failed to close or let go ('' when it has no reason to give)."""
    manager = _gripper_manager(world)
    component = getattr(manager, "components", {}).get(path) if manager is not None else None
    return getattr(component, "reason", "") if component is not None else ""


def _gripper_state(world, path: str) -> tuple[str, tuple[str, ...]] | None:
    """(status token, gripped objects) of the gripper at *path*, None when the run has no such gripper."""
    manager = _gripper_manager(world)
    if manager is None or path not in getattr(manager, "components", {}):
        return None
    status = manager.get_gripper_status(path)
    return getattr(status, "token", str(status)), tuple(manager.get_gripped_objects(path))


def _is_finite(value: Any) -> bool:
    if isinstance(value, bool):
        return True
    if isinstance(value, float):
        return math.isfinite(value)
    if isinstance(value, (tuple, list)):
        return all(_is_finite(v) for v in value)
    return True


class _Check:
    """Base: ``tick(world, instance)`` after every tick, ``verdict(world, result)`` -> failure or None."""

    at: Any = END

    def __init__(self, spec: Mapping[str, Any], index: int):
        self.spec = spec
        self.label = spec.get("name") or self.describe()
        self.index = index
        self.measured = False                       # a timed check took its measurement
        self.measurement: str | None = None         # what it measured then (None: it held)

    def describe(self) -> str:
        raise NotImplementedError

    def due(self, time: float, time_step: float) -> bool:
        """A timed check measures on the first tick at or after its time."""
        return self.at != END and not self.measured and time >= float(self.at) - time_step / 2

    def tick(self, world, instance) -> None:
        if self.due(world.time, world.time_step):
            self.measured, self.measurement = True, self.measure(world)

    def verdict(self, world, result) -> tuple[str, str] | None:
        """(measured, expected) when the check failed."""
        if self.at == END:
            measured = self.measure(world)
        elif not self.measured:
            return f"the run ended at t = {result.time:.3f} s", f"{self.expectation()} {_when(self.at)}"
        else:
            measured = self.measurement
        return None if measured is None else (measured, f"{self.expectation()} {_when(self.at)}")

    def measure(self, world) -> str | None:
        """None when the check holds now, else what was measured."""
        raise NotImplementedError

    def expectation(self) -> str:
        raise NotImplementedError

    def prims(self) -> Iterable[str]:
        return ()


class PositionCheck(_Check):
    def __init__(self, spec, index):
        self.prim = spec["prim"]
        self.target = tuple(float(v) for v in spec["position"])
        self.tolerance = float(spec["tolerance"])
        self.axes = spec.get("axes", "xyz")
        self.at = spec.get("at", END)
        super().__init__(spec, index)

    def describe(self):
        return f"position of {self.prim} {_when(self.at)}"

    def measure(self, world):
        try:
            position = world.prim_pose(self.prim)[0]
        except Exception as error:   # a prim the world does not have: the measurement says so
            return f"no pose for {self.prim}: {error}"
        distance = math.sqrt(sum((position[AXIS_INDEX[a]] - self.target[AXIS_INDEX[a]]) ** 2 for a in self.axes))
        if distance <= self.tolerance:
            return None
        which = "" if self.axes == "xyz" else f" in {self.axes}"
        return f"{_point(position)}, {_mm(distance)}{which} from {_point(self.target)}"

    def expectation(self):
        which = "" if self.axes == "xyz" else f" in {self.axes}"
        return f"within {_mm(self.tolerance)}{which} of {_point(self.target)}"

    def prims(self):
        return (self.prim,)


class UprightCheck(_Check):
    def __init__(self, spec, index):
        self.prim = spec["prim"]
        self.within = float(spec["within"])
        self.axis = spec.get("axis", "Z")
        self.at = spec.get("at", END)
        super().__init__(spec, index)

    def describe(self):
        return f"upright {self.prim} {_when(self.at)}"

    def measure(self, world):
        from graphflow.poses import quat_rotate

        try:
            orientation = world.prim_pose(self.prim)[1]
        except Exception as error:
            return f"no pose for {self.prim}: {error}"
        up = quat_rotate(orientation, LOCAL_AXES[self.axis])
        tilt = math.degrees(math.acos(max(-1.0, min(1.0, up[2] / math.sqrt(sum(c * c for c in up))))))
        return None if tilt <= self.within else f"its {self.axis} axis {tilt:.1f} deg from vertical"

    def expectation(self):
        return f"its {self.axis} axis within {self.within:g} deg of vertical"

    def prims(self):
        return (self.prim,)


class GripperStatusCheck(_Check):
    def __init__(self, spec, index):
        self.gripper = spec["gripper"]
        self.status = spec["status"]
        self.at = spec.get("at", END)
        super().__init__(spec, index)

    def describe(self):
        return f"gripper {self.gripper} {self.status} {_when(self.at)}"

    def measure(self, world):
        state = _gripper_state(world, self.gripper)
        if state is None:
            return f"no surface gripper at {self.gripper} in this run"
        if state[0] == self.status:
            return None
        reason = gripper_reason(world, self.gripper)
        return f"status {state[0]}" + (f" ({reason})" if reason else "")

    def expectation(self):
        return f"status {self.status}"


class HeldCheck(_Check):
    """Every tick from ``from`` to ``to`` the gripper holds the object (any object when none is named)."""

    def __init__(self, spec, index):
        self.gripper = spec["gripper"]
        self.object = spec.get("object")
        self.start = float(spec["from"])
        self.end = spec.get("to", END)
        self.first_miss: str | None = None
        self.checked_ticks = 0
        super().__init__(spec, index)

    def describe(self):
        what = self.object or "an object"
        until = "the end" if self.end == END else f"{self.end:g} s"
        return f"{self.gripper} holds {what} from {self.start:g} s to {until}"

    def tick(self, world, instance):
        time, half = world.time, world.time_step / 2
        if self.first_miss is not None or time < self.start - half or (self.end != END and time > float(self.end) + half):
            return
        self.checked_ticks += 1
        state = _gripper_state(world, self.gripper)
        if state is None:
            self.first_miss = f"no surface gripper at {self.gripper} in this run"
            return
        status, gripped = state
        if (self.object in gripped) if self.object else bool(gripped):
            return
        reason = gripper_reason(world, self.gripper)
        held = f"holding {', '.join(gripped)}" if gripped else "holding nothing"
        self.first_miss = (f"{held} at t = {time:.3f} s (gripper {status}" + (f": {reason}" if reason else "") + ")")

    def verdict(self, world, result):
        expected = f"{self.object or 'an object'} held throughout"
        if self.first_miss is not None:
            return self.first_miss, expected
        if self.end != END and result.time < float(self.end) - world.time_step / 2:
            return f"the run ended at t = {result.time:.3f} s", expected + f" until {self.end:g} s"
        if self.checked_ticks == 0:
            return f"the run ended at t = {result.time:.3f} s, before {self.start:g} s", expected
        return None


class FiniteCheck(_Check):
    """Every node output and the pose of every prim the checks name stay finite, every tick."""

    def __init__(self, spec, index, other_prims: Iterable[str] = ()):
        self.extra_prims = tuple(spec.get("prims", ()))
        self.watched = tuple(dict.fromkeys(self.extra_prims + tuple(other_prims)))
        self.first_bad: str | None = None
        super().__init__(spec, index)

    def describe(self):
        return "nothing non-finite"

    def tick(self, world, instance):
        if self.first_bad is not None:
            return
        for node in instance.compiled.nodes:
            for name, value in instance.database(node.name).outputs.__dict__.items():
                if not _is_finite(value):
                    self.first_bad = f"node '{node.name}' output '{name}' = {value!r} at t = {world.time:.3f} s"
                    return
        for prim in self.watched:
            try:
                pose = world.prim_pose(prim)
            except Exception:
                continue   # a missing prim is the position or upright check's failure, not this one's
            if not (_is_finite(tuple(pose[0])) and _is_finite(tuple(pose[1]))):
                self.first_bad = f"pose of {prim} = {pose!r} at t = {world.time:.3f} s"
                return

    def verdict(self, world, result):
        return None if self.first_bad is None else (self.first_bad, "every output and pose finite")


class StopsByCheck(_Check):
    def __init__(self, spec, index):
        self.time = float(spec["time"])
        super().__init__(spec, index)

    def describe(self):
        return f"graph stops by itself by {self.time:g} s"

    def verdict(self, world, result):
        expected = f"the graph stops by itself (StopRun) by t = {self.time:g} s"
        if result.stopped_by_graph and result.time <= self.time + world.time_step / 2:
            return None
        if result.stopped_by_graph:
            return f"stopped at t = {result.time:.3f} s", expected
        return f"still running when the run ended at t = {result.time:.3f} s", expected


class MatchesTraceCheck(_Check):
    """The run's trace stays within tolerance of a committed golden trace (docs/trace.md); ``--update-golden``
    rewrites the golden file from this run instead. Needs a run of its own (not a sweep's reused world)."""

    def __init__(self, spec, index, base_dir: Path):
        from graphflow.observe.trace_tolerance import read_tolerances, tolerances_from

        self.golden = Path(base_dir) / spec["trace"]
        tolerance = spec.get("tolerance")
        self.tolerances = (read_tolerances(tolerance, base_dir) if isinstance(tolerance, str)
                           else tolerances_from(tolerance, f"matchesTrace {spec['trace']}: tolerance"))
        self.recorded: io.StringIO | None = None
        self.update = False
        super().__init__(spec, index)

    def describe(self):
        return f"trace matches {self.spec['trace']}"

    def attach(self, simulation, source: str, update: bool) -> None:
        """Record this run's trace in memory from its first tick."""
        from graphflow.observe.recorder import TraceRecorder

        self.recorded, self.update = io.StringIO(), update
        TraceRecorder(simulation, self.recorded, graph=source)

    def verdict(self, world, result):
        from graphflow.files import write_text
        from graphflow.observe.trace import TraceError, parse_trace, read_trace
        from graphflow.observe.trace_tolerance import tolerant_difference

        expected = f"within tolerance of the golden trace {self.spec['trace']}"
        if self.recorded is None:
            return "no trace recorded (this run reused another's world)", expected
        if self.update:
            self.golden.parent.mkdir(parents=True, exist_ok=True)
            write_text(self.golden, self.recorded.getvalue(), force=True)
            return None
        try:
            golden = read_trace(self.golden)
        except TraceError as error:
            return f"no golden trace ({error}; graphflow test --update-golden writes it)", expected
        divergence = tolerant_difference(golden, parse_trace(self.recorded.getvalue()), self.tolerances)
        return None if divergence is None else (divergence.one_line(), expected)


CHECK_TYPES = {"position": PositionCheck, "upright": UprightCheck, "gripperStatus": GripperStatusCheck,
               "held": HeldCheck, "stopsBy": StopsByCheck}


def build_checks(specs: Iterable[Mapping[str, Any]], base_dir: Path = Path(".")) -> list[_Check]:
    specs = list(specs)
    checks: list[_Check] = []
    for index, spec in enumerate(specs):
        if spec["check"] == "matchesTrace":
            checks.append(MatchesTraceCheck(spec, index, base_dir))
        elif spec["check"] != "finite":
            checks.append(CHECK_TYPES[spec["check"]](spec, index))
    named = [prim for check in checks for prim in check.prims()]
    for index, spec in enumerate(specs):
        if spec["check"] == "finite":
            checks.insert(index, FiniteCheck(spec, index, named))
    return checks


class CheckEvaluator:
    """Evaluates a document's checks over one run: a run listener (``on_tick``), then ``finish(simulation, result)``."""

    def __init__(self, document):
        """*document* None: a run whose checks do not apply (an evaluator with no checks)."""
        self.source = document.source if document is not None else "<graph>"
        self.checks = build_checks(document.checks if document is not None else (),
                                   document.base_dir if document is not None else Path("."))
        self.failures: list[CheckFailure] | None = None

    def attach(self, simulation, source: str, *, update_golden: bool = False) -> None:
        """Give checks that record the run (matchesTrace) the simulation, before its first tick."""
        for check in self.checks:
            if isinstance(check, MatchesTraceCheck):
                check.attach(simulation, source, update_golden)

    def __len__(self) -> int:
        return len(self.checks)

    def time_limit(self) -> float | None:
        """The earliest stopsBy time: running past it cannot change that check's verdict."""
        times = [check.time for check in self.checks if isinstance(check, StopsByCheck)]
        return min(times) if times else None

    def on_tick(self, simulation, _tick: int) -> None:
        world, instance = simulation.world, simulation.instance
        for check in self.checks:
            check.tick(world, instance)

    def finish(self, simulation, result) -> list[CheckFailure]:
        """The failed checks, in document order (empty when every check holds)."""
        failures = []
        for check in self.checks:
            verdict = check.verdict(simulation.world, result)
            if verdict is not None:
                failures.append(CheckFailure(self.source, f"{check.index + 1} '{check.label}'", *verdict))
        self.failures = failures
        return failures
