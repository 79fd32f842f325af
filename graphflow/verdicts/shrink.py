"""``graphflow shrink SCENARIO --seed S``: the smallest perturbation of a failing randomized episode that
still fails the same way (the same checks fail), printed as a ``graphflow run --set`` line and a table row.

The seed's draws are the starting case; each randomized parameter has a nominal value (the graph's or the
stage's own: the node input as authored or its default, the stage attribute as authored, no pose offset).
First every parameter is tried at its nominal value, one at a time, and dropped when the episode still
fails the same way; then each remaining numeric parameter is bisected between nominal and its current
value (``STEPS`` halvings), keeping the point nearest nominal that still fails. This is plain bisection,
not Hypothesis: Hypothesis shrinks the choice sequence of examples it generated itself, while here the
failing case is given (a seed's draws), every trial is a physics run of about a second, and the order
"fewer parameters, then each nearer nominal" is exactly delta debugging followed by bisection.
"""
from __future__ import annotations

import json
import math
import shlex
from dataclasses import dataclass, replace
from typing import Any, Callable

from graphflow.errors import BadInput

STEPS = 6   # bisection halvings per parameter: within 1/64 of the drawn distance from the boundary


@dataclass(frozen=True)
class Parameter:
    """One randomized parameter: what it sets, its nominal value and its current (failing) value."""

    edit: Any          # the Override or PoseJitter as drawn
    nominal: Any
    value: Any
    base: Any = None   # a pose's authored translate (m): what its offset is added to

    @property
    def name(self) -> str:
        return getattr(self.edit, "target", None) or f"{self.edit.prim}.pose"

    def at(self, fraction: float) -> "Parameter":
        """The parameter *fraction* of the way from nominal to its current value."""
        return replace(self, value=_between(self.nominal, self.value, fraction))

    def as_edit(self):
        from graphflow.variants.overrides import Override, PoseJitter

        if isinstance(self.edit, PoseJitter):
            offset, yaw = self.value
            return PoseJitter(self.edit.prim, tuple(offset), yaw, origin=f"shrunk pose of {self.edit.prim}")
        return Override(self.edit.target, self.value, origin=f"shrunk {self.edit.target}")


def _between(nominal, value, fraction: float):
    if isinstance(value, (list, tuple)):
        return [_between(n, v, fraction) for n, v in zip(nominal, value)]
    if isinstance(value, (int, float)) and not isinstance(value, bool) and isinstance(nominal, (int, float)):
        return nominal + (value - nominal) * fraction
    return value if fraction > 0 else nominal


def _numeric(value) -> bool:
    if isinstance(value, (list, tuple)):
        return all(_numeric(v) for v in value)
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def nominal_value(document, edit) -> Any:
    """What the graph (node input as authored, else its default) or the stage has without the override."""
    from graphflow.registry import default_registry
    from graphflow.variants.overrides import Variant

    owner, name = edit.parts()
    if not edit.on_stage:
        node = document.node(owner)
        node_type = default_registry().get(node.type) if node is not None else None
        attribute = node_type.spec.attribute(f"inputs:{name}") if node_type is not None else None
        if node is None or attribute is None:   # the override applied to this document, so neither happens
            raise ValueError(f"{edit.label}: no input {name!r} on node {owner!r}")
        return node.inputs.get(name, attribute.default)
    stage = Variant(document, ()).open_stage()   # held while its prim is read
    value = stage.GetPrimAtPath(owner).GetAttribute(name).Get()
    return [float(v) for v in value] if hasattr(value, "__len__") else float(value)


def failure_signature(failures: list[str]) -> tuple[str, ...]:
    """Which checks failed (``check N 'label'``), or which node failed: what "failing the same way" compares."""
    signature = []
    for line in failures:
        text = line.split(": ", 1)[1] if ": " in line else line
        signature.append(text.split("': ", 1)[0] + "'" if text.startswith("check ") else text.split(":", 1)[0])
    return tuple(sorted(set(signature)))


@dataclass
class Shrunk:
    """The result: the seed's parameters, the smallest failing ones, the failure kept, the runs it took."""

    path: str
    seed: int
    drawn: list[Parameter]
    kept: list[Parameter]
    signature: tuple[str, ...]
    runs: int

    def overrides(self) -> dict[str, Any]:
        """The kept parameters as ``--set`` targets and values (a pose offset becomes its absolute translate)."""
        values = {}
        for parameter in self.kept:
            if parameter.base is not None:
                values[f"{parameter.edit.prim}.xformOp:translate"] = [b + o for b, o in zip(parameter.base, parameter.value[0])]
            else:
                values[parameter.name] = parameter.value
        return values

    def notes(self) -> list[str]:
        """What ``--set`` cannot say: a pose's remaining yaw."""
        return [f"{p.edit.prim} also turned {p.value[1]:.6g} deg about its parent's Z (no --set for a yaw)"
                for p in self.kept if p.base is not None and p.value[1] != 0]

    def command(self) -> str:
        arguments = [part for target, value in self.overrides().items()
                     for part in ("--set", f"{target}={json.dumps(value)}")]
        return shlex.join(["graphflow", "run", self.path, "--seed", str(self.seed), *arguments])

    def table_row(self) -> dict:
        """A case for a scenario table (``graphflow-cases``) that expects this failure."""
        import re

        pattern = re.sub(r"([.^$*+?{}\[\]\\|()])", r"\\\1", self.signature[0])   # the first failed check, literally
        return {"name": f"shrunk from seed {self.seed}", "set": self.overrides(), "seed": self.seed,
                "expect": {"fail": pattern}}


def shrink(path: str, seed: int, report: Callable[[str], None] = print) -> Shrunk:
    """Shrink the failing episode *seed* of the rate scenario at *path* (BadInput when it does not fail)."""
    from graphflow.document import load_document
    from graphflow.variants.overrides import Override, PoseJitter, make_variant
    from graphflow.verdicts.checked_run import CheckedRun, ScriptedInputs
    from graphflow.verdicts.rates import randomized_edits

    document = load_document(path)
    edits = randomized_edits(path, seed)
    if not edits:
        raise BadInput(f"{path}: scenario.randomize draws nothing: there is no perturbation to shrink")
    parameters = []
    for edit in edits:
        if isinstance(edit, PoseJitter):
            parameters.append(Parameter(edit, [[0.0, 0.0, 0.0], 0.0], [list(edit.offset), edit.yaw_degrees],
                                        base=nominal_value(document, Override(f"{edit.prim}.xformOp:translate", None))))
        else:
            parameters.append(Parameter(edit, nominal_value(document, edit), edit.value))
    runs = 0

    def failures_with(candidate: list[Parameter]) -> tuple[str, ...]:
        nonlocal runs
        runs += 1
        checked = CheckedRun(document, source=path, variant=make_variant(document, [p.as_edit() for p in candidate]),
                             inputs=ScriptedInputs.of_document(document), seed=seed)
        try:
            return failure_signature(checked.run().failures)
        finally:
            checked.close()

    signature = failures_with(parameters)
    if not signature:
        raise BadInput(f"{path}: seed {seed} passes: there is no failure to shrink")
    report(f"seed {seed} fails {', '.join(signature)} with {len(parameters)} randomized parameters")
    kept = list(parameters)
    for parameter in parameters:   # fewer parameters: drop each one that is not needed for the failure
        trial = [p for p in kept if p is not parameter]
        if failures_with(trial) == signature:
            kept = trial
            report(f"  {parameter.name}: not needed (nominal {json.dumps(parameter.nominal)})")
    for index, parameter in enumerate(kept):   # each nearer nominal: bisect the fraction of its perturbation
        if not _numeric(parameter.value):
            continue
        low, high = 0.0, 1.0   # low passes (or fails otherwise), high fails the same way
        for _ in range(STEPS):
            middle = (low + high) / 2
            trial = kept[:index] + [parameter.at(middle)] + kept[index + 1:]
            low, high = (low, middle) if failures_with(trial) == signature else (middle, high)
        kept[index] = parameter.at(high)
        report(f"  {parameter.name}: {_shown(parameter.value)} -> {_shown(kept[index].value)} "
               f"(nominal {_shown(parameter.nominal)}, {high:.0%} of the drawn perturbation)")
    return Shrunk(path, seed, parameters, kept, signature, runs)


def _shown(value) -> str:
    if isinstance(value, float):
        return f"{value:.6g}" if math.isfinite(value) else str(value)
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_shown(v) for v in value) + "]"
    return json.dumps(value)
