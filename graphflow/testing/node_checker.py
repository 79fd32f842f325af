"""One generic check of a node type, run over every registered type (in the spirit of Gymnasium's env checker).

``check_node_type(node_type, world=None, inputs=None)`` checks, and raises one
``NodeCheckError`` listing every problem it found:

1. the spec is well formed (``spec_problems``): an id, a positive version and a
   description; port names that are unique per group and usable as ``db.inputs.<name>``;
   execution ports without defaults, ranges or tokens and never in state; ranges only
   on numbers, allowed tokens only on tokens and strings, ``minimum <= maximum``; every
   port described; every input and state default coerces to its type and lies within
   its range, length and allowed tokens. An output's initial value is what it holds
   before the first compute (``""`` for a phase name that has not started), so output
   tokens are checked on what a compute writes instead;
2. it computes on its defaults (or on *inputs*) in *world* (a ``ClockWorld`` when
   none is given): once per exec input, each pulsed alone after a reset (once without
   a pulse when it has no exec input), every data output afterwards fitting its type
   and every exec output an ``ExecState``. A node may refuse the inputs, but only
   with a ``GraphRuntimeError`` naming the node that it raised itself (``db.error``)
   or that explains a world refusal (``WorldError``, e.g. "names no stage"); a raw
   ``TypeError``/``KeyError``/... escaping compute is a problem;
3. it resets cleanly: after the computes, resetting the world and the node gives
   back the inputs, outputs, state and latent flag of a fresh instance, and
   computing again gives the same outputs and state (or the same refusal) as the
   first time.

Nodes that read prims are checked twice by the test suite: on a ``ClockWorld``
(where they must refuse clearly) and on a packaged stage with inputs naming its prims
(see tests/testing/test_node_checker.py).
"""
from __future__ import annotations

import keyword
import math
from dataclasses import dataclass
from typing import Any, Mapping

from graphflow.document import GraphError
from graphflow.executor import GraphRuntimeError
from graphflow.registry import Registry, default_registry
from graphflow.spec import Attribute, NodeSpec, NodeType
from graphflow.testing import HARNESS_NODE, NodeHarness
from graphflow.types import SCALAR_KINDS, ExecState, TypeMismatch
from graphflow.world import ClockWorld, World, WorldError

__all__ = ["NodeCheckError", "NodeCheckReport", "check_node_type", "spec_problems"]


class NodeCheckError(AssertionError):
    """A node type failed its check; ``problems`` has one line per finding, each naming the type."""

    def __init__(self, type_id: str, problems: list[str]):
        self.type_id = type_id
        self.problems = tuple(problems)
        super().__init__(f"{type_id}: {len(problems)} problem(s)\n" + "\n".join(f"  {p}" for p in problems))


@dataclass(frozen=True)
class NodeCheckReport:
    """What a passing check did: the world it used, the computes it ran, the refusals it saw."""

    type_id: str
    world: str
    computed: tuple[str, ...]            # the exec input pulsed for each compute ("" for none)
    refusals: Mapping[str, str]          # pulse -> the clear GraphRuntimeError message, when the node refused

    @property
    def refused(self) -> bool:
        return bool(self.refusals)


def check_node_type(node_type: NodeType | str, world: World | None = None,
                    inputs: Mapping[str, Any] | None = None, *, registry: Registry | None = None) -> NodeCheckReport:
    """Check *node_type* (a ``NodeType`` or a registered id); raise ``NodeCheckError`` listing every problem.

    *inputs* are authored input values (default: none, so every input holds its
    default). A given *world* is reset before every compute and left reset.
    """
    if isinstance(node_type, str):
        found = (registry or default_registry()).get(node_type)
        if found is None:
            raise NodeCheckError(node_type, ["not a registered node type"])
        node_type = found
    spec = node_type.spec
    only_this = Registry()   # the type checked alone: works for unregistered types too
    only_this.register(node_type)
    world = world if world is not None else ClockWorld()
    problems = spec_problems(spec)
    report = NodeCheckReport(spec.id, type(world).__name__, (), {})
    try:
        harness = NodeHarness(spec.id, inputs, world=world, registry=only_this)
    except GraphError as error:
        problems += [f"the inputs {dict(inputs or {})} do not load: {p}" for p in error.problems]
    except Exception as error:   # initialize() failing on creation
        problems.append(f"creating an instance raised {type(error).__name__}: {error}")
    else:
        report = _check_computes(harness, spec, problems)
    if problems:
        raise NodeCheckError(spec.id, problems)
    return report


# ---------------------------------------------------------------- the spec


def spec_problems(spec: NodeSpec) -> list[str]:
    """Everything wrong with a spec as a declaration (no instance needed)."""
    problems = []
    if not spec.id or any(c.isspace() for c in spec.id):
        problems.append(f"id {spec.id!r} is empty or has white space")
    if not isinstance(spec.version, int) or isinstance(spec.version, bool) or spec.version < 1:
        problems.append(f"version {spec.version!r} is not a positive integer")
    if any(v == spec.version for v in spec.compatible_versions):
        problems.append(f"compatible_versions repeats the version {spec.version}")
    if spec.id in spec.aliases:
        problems.append("an alias repeats the id")
    if not spec.description.strip():
        problems.append("no description")
    if any(not category.strip() for category in spec.categories):
        problems.append("an empty category")
    for group, attributes in (("inputs", spec.inputs), ("outputs", spec.outputs), ("state", spec.state)):
        seen = set()
        for attribute in attributes:
            name = f"{group}:{attribute.name}"
            if attribute.name in seen:
                problems.append(f"{name} is declared twice")
            seen.add(attribute.name)
            problems += [f"{name}: {p}" for p in _attribute_problems(attribute, group)]
    return problems


def _attribute_problems(attribute: Attribute, group: str) -> list[str]:
    problems = []
    if not attribute.name.isidentifier() or keyword.iskeyword(attribute.name):
        problems.append("the name is not usable as db.<group>.<name>")
    if not attribute.description.strip():
        problems.append("no description")
    attr_type = attribute.attr_type
    if attr_type.is_execution:
        if group == "state":
            problems.append("state cannot be an execution attribute")
        if (attribute.default is not None or attribute.allowed_tokens or attribute.length is not None
                or attribute.minimum is not None or attribute.maximum is not None):
            problems.append("an execution attribute takes no default, range, length or tokens")
        return problems
    numeric = SCALAR_KINDS.get(attr_type.base) in ("int", "uint", "real")
    if (attribute.minimum is not None or attribute.maximum is not None) and not numeric:
        problems.append(f"a range on the non-numeric type {attr_type.name}")
    if (attribute.minimum is not None and attribute.maximum is not None
            and not attribute.minimum <= attribute.maximum):
        problems.append(f"minimum {attribute.minimum} is above maximum {attribute.maximum}")
    if attribute.allowed_tokens:
        if SCALAR_KINDS.get(attr_type.base) != "str":
            problems.append(f"allowed tokens on the non-text type {attr_type.name}")
        if len(set(attribute.allowed_tokens)) != len(attribute.allowed_tokens):
            problems.append("an allowed token is listed twice")
    if attribute.length is not None and not attr_type.is_array:
        problems.append(f"a required length on the non-array type {attr_type.name}")
    try:
        initial = attribute.initial_value()
    except TypeMismatch as error:
        return problems + [f"the default {attribute.default!r} does not fit its type: {error}"]
    if group != "outputs":
        try:
            attribute.check(initial)
        except TypeMismatch as error:
            problems.append(f"the default {initial!r} is out of bounds: {error}")
    return problems


# ---------------------------------------------------------------- computing and resetting


def _check_computes(harness: NodeHarness, spec: NodeSpec, problems: list[str]) -> NodeCheckReport:
    pulses = tuple(a.name for a in spec.exec_inputs) or ("",)
    harness.world.reset()
    harness.reset()
    fresh = _snapshot(harness)
    first = {}
    for pulse in pulses:
        harness.world.reset()
        harness.reset()
        first[pulse] = _compute(harness, spec, pulse, problems)
    harness.world.reset()
    harness.reset()
    if not _same(_snapshot(harness), fresh):
        problems.append(f"reset does not restore a fresh instance: {_difference(fresh, _snapshot(harness))}")
    again = _compute(harness, spec, pulses[0], [])
    if not _same(again, first[pulses[0]]):
        problems.append(f"after a reset, computing ({_pulse_text(pulses[0])}) gives something else: "
                        f"{_difference(first[pulses[0]], again)}")
    refusals = {pulse: outcome["refused"] for pulse, outcome in first.items() if "refused" in outcome}
    return NodeCheckReport(spec.id, type(harness.world).__name__, pulses, refusals)


def _compute(harness: NodeHarness, spec: NodeSpec, pulse: str, problems: list[str]) -> dict:
    """One tick with *pulse* enabled; the outcome (values or the refusal); problems appended."""
    where = f"computing ({_pulse_text(pulse)})"
    inputs_before = harness.database.inputs.as_dict()
    try:
        harness.tick(*((pulse,) if pulse else ()))
    except GraphRuntimeError as error:
        if error.node != HARNESS_NODE:
            problems.append(f"{where}: the error does not name the node: {error}")
        cause = error.__cause__
        if cause is not None and not isinstance(cause, (WorldError, GraphRuntimeError)):
            problems.append(f"{where}: a raw {type(cause).__name__} escaped compute "
                            f"(refuse with db.error naming the attribute): {cause}")
        return {"refused": str(error)}
    except Exception as error:
        problems.append(f"{where}: raised {type(error).__name__} instead of a GraphRuntimeError: {error}")
        return {"refused": repr(error)}
    database = harness.database
    for group, declared, values in (("outputs", spec.outputs, database.outputs), ("state", spec.state, database.state),
                                    ("inputs", spec.inputs, database.inputs)):
        undeclared = sorted(set(values.as_dict()) - {a.name for a in declared})
        if undeclared:
            problems.append(f"{where}: compute set undeclared {group} {', '.join(undeclared)}")
    changed = [a.name for a in spec.inputs if not a.is_execution
               and not _same(getattr(database.inputs, a.name, None), inputs_before.get(a.name))]
    if changed:
        problems.append(f"{where}: compute changed its own inputs {', '.join(changed)}")
    outputs = database.outputs.as_dict()
    for attribute in spec.outputs:
        value = outputs.get(attribute.name)
        problem = _output_problem(attribute, value)
        if problem:
            problems.append(f"{where}: outputs:{attribute.name} = {value!r}: {problem}")
    return _snapshot(harness)


def _output_problem(attribute: Attribute, value) -> str | None:
    if attribute.is_execution:
        return None if isinstance(value, ExecState) else "an exec output must hold an ExecState"
    if _mutable(value):
        return "values flow along connections uncopied, so they must be immutable (tuples, not lists)"
    try:
        coerced = attribute.attr_type.coerce(value)
    except TypeMismatch as error:
        return str(error)
    if attribute.allowed_tokens and coerced not in attribute.allowed_tokens and coerced != attribute.initial_value():
        return f"not one of its allowed tokens {attribute.allowed_tokens}"
    return None


def _mutable(value) -> bool:
    if isinstance(value, (list, dict, set, bytearray)):
        return True
    return isinstance(value, tuple) and any(_mutable(item) for item in value)


def _snapshot(harness: NodeHarness) -> dict:
    database = harness.database
    return {"inputs": database.inputs.as_dict(), "outputs": database.outputs.as_dict(),
            "state": database.state.as_dict(), "latent": harness.is_latent}


def _same(left, right) -> bool:
    """Equality that holds NaN equal to NaN (a reset must give NaN back where NaN was)."""
    if isinstance(left, float) and isinstance(right, float):
        return left == right or (math.isnan(left) and math.isnan(right))
    if isinstance(left, (tuple, list)) and isinstance(right, (tuple, list)):
        return len(left) == len(right) and all(_same(a, b) for a, b in zip(left, right))
    if isinstance(left, dict) and isinstance(right, dict):
        return left.keys() == right.keys() and all(_same(left[k], right[k]) for k in left)
    return type(left) is type(right) and left == right


def _difference(expected: dict, got: dict) -> str:
    for key in sorted(set(expected) | set(got)):
        if key not in expected or key not in got:
            return f"{key} {'missing' if key not in got else 'unexpected'}"
        if isinstance(expected[key], dict) and isinstance(got[key], dict):
            for name in sorted(set(expected[key]) | set(got[key])):
                if not _same(expected[key].get(name), got[key].get(name)):
                    return f"{key}:{name} is {got[key].get(name)!r}, expected {expected[key].get(name)!r}"
        elif not _same(expected[key], got[key]):
            return f"{key} is {got[key]!r}, expected {expected[key]!r}"
    return "no difference shown"


def _pulse_text(pulse: str) -> str:
    return f"inputs:{pulse} pulsed" if pulse else "no pulse"
