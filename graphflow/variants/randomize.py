"""Seeded draws: randomized scenarios (``randomize``) and random parameter samples of sweeps.

A randomization is a list of entries (format in docs/sweeps.md), each drawn
from its own stream ``random.Random("graphflow:<seed>:<entry index>")``:

* ``{"set": TARGET, DISTRIBUTION}`` sets a node input or stage attribute (the
  targets of ``graphflow run --set``) to a drawn value;
* ``{"pose": PRIM, "offset": DISTRIBUTION, "yawDegrees": DISTRIBUTION}``
  moves a prim by a drawn offset (m) and turns it about its parent's Z axis.

A DISTRIBUTION is one of ``{"uniform": [low, high]}``, ``{"normal": [mean,
std]}`` (optional ``"clip": [low, high]``), ``{"logUniform": [low, high]}``,
``{"choice": [value, ...]}``; low/high/mean/std may be numbers or equally long
lists (one draw per component). Only ``Random.random()`` and
``statistics.NormalDist.inv_cdf`` are used, so a seed gives the same values in
any process, on any machine, with any Python 3 version (string seeds and
``random()`` are the parts of ``random`` whose sequence Python guarantees);
one entry's stream does not depend on the others, so adding an entry leaves
the other entries' draws unchanged.
"""
from __future__ import annotations

import dataclasses
import json
import logging
import math
import random
from dataclasses import dataclass
from functools import lru_cache
from importlib import resources
from statistics import NormalDist
from typing import Any, Iterable, Mapping, Sequence

from graphflow.files import FileProblem, read_json
from graphflow.model import GraphDocument
from graphflow.poses import as_vec3
from graphflow.variants.overrides import (
    Override,
    OverrideError,
    PoseJitter,
    Variant,
    make_variant,
    parse_set,
)

_log = logging.getLogger("graphflow.randomize")
DISTRIBUTIONS = ("uniform", "normal", "logUniform", "choice")
_STANDARD_NORMAL = NormalDist()


class RandomizationError(OverrideError):
    """A randomization or sweep file that cannot be used; the message is one line naming file and entry."""


@lru_cache(maxsize=1)
def sweep_schema() -> dict:
    """The JSON Schema of sweep files (graphflow/schema/sweep.schema.json); its $defs serve randomization files."""
    text = resources.files("graphflow").joinpath("schema/sweep.schema.json").read_text(encoding="utf-8")
    return json.loads(text)


def schema_problems(data: Any, source: str, definition: str | None = None) -> list[str]:
    """One line per schema violation of *data* (the whole sweep schema, or one of its ``$defs``)."""
    return [line for _path, line in schema_errors(data, source, definition)]


def schema_errors(data: Any, source: str, definition: str | None = None) -> list[tuple[tuple, str]]:
    """(JSON path, line) per schema violation, each with the most telling reason (``_reason``)."""
    import jsonschema

    schema = sweep_schema()
    if definition is not None:
        schema = {"$defs": schema["$defs"], "$ref": f"#/$defs/{definition}"}
    validator = jsonschema.Draft202012Validator(schema)
    found: dict[tuple, list[str]] = {}
    for error in sorted(validator.iter_errors(data), key=lambda e: [str(p) for p in e.absolute_path]):
        path, reason = _explain(error)
        reasons = found.setdefault(path, [])
        if reason not in reasons:
            reasons.append(reason)
    problems: list[tuple[tuple, str]] = []
    for path, reasons in found.items():
        if any(r.startswith("unknown distribution") for r in reasons):   # says more than "needs one of"
            reasons = [r for r in reasons if not r.startswith("needs one of")]
        location = "/".join(str(p) for p in path) or "document"
        problems.extend((path, f"{source}: {location}: {reason}") for reason in reasons)
    return problems


def _explain(error) -> tuple[tuple, str]:
    """(where, the real reason) of a schema error: for a ``oneOf`` (a randomize entry is a ``set`` or a ``pose``
    entry; a distribution is one of four), the reason of the alternative the value was meant to be."""
    where = tuple(error.absolute_path)
    if error.validator == "additionalProperties" and set(DISTRIBUTIONS) <= set(error.schema.get("properties", {})):
        unknown = sorted(set(error.instance) - set(error.schema["properties"]))
        return where, (f"unknown distribution {', '.join(map(repr, unknown))} "
                       f"(one of {', '.join(DISTRIBUTIONS)}, with an optional clip)")
    if error.validator != "oneOf":
        return where, error.message
    alternatives = error.schema["oneOf"]
    if not error.context and isinstance(error.instance, dict):
        given = [key for branch in alternatives for key in branch.get("required", ()) if key in error.instance]
        return where, f"gives {' and '.join(map(repr, given))}; use only one of them"
    by_branch: dict[int, list] = {}
    for sub in error.context:
        by_branch.setdefault(sub.relative_schema_path[0], []).append(sub)
    meant = [errors for errors in by_branch.values()
             if not any(e.validator in ("required", "type") and not e.relative_path for e in errors)]
    if len(meant) != 1 and not isinstance(error.instance, dict):
        return where, error.message
    if len(meant) != 1:
        keys = [key for branch in alternatives for key in branch.get("required", ())]
        return where, f"needs one of {', '.join(map(repr, keys))}"
    return _explain(max(meant[0], key=lambda e: (len(e.absolute_path), e.validator == "additionalProperties")))


def stream(*key) -> random.Random:
    """An independent, reproducible stream for a key (seed, entry index, ...)."""
    return random.Random("graphflow:" + ":".join(str(part) for part in key))


def _uniform_open(rng: random.Random) -> float:
    """A uniform draw in (0, 1): ``random()`` can return exactly 0, which the normal quantile refuses."""
    u = rng.random()
    return u if u > 0.0 else 2.0 ** -54


def draw(distribution: Mapping[str, Any], rng: random.Random):
    """One value of a distribution (a number, a list for vector parameters, or a chosen JSON value)."""
    if "choice" in distribution:
        options = distribution["choice"]
        return options[min(int(rng.random() * len(options)), len(options) - 1)]
    kind = next(k for k in ("uniform", "normal", "logUniform") if k in distribution)
    first, second = distribution[kind]
    vector = isinstance(first, list)
    pairs = list(zip(first, second)) if vector else [(first, second)]
    values = []
    for a, b in pairs:
        if kind == "uniform":
            value = a + (b - a) * rng.random()
        elif kind == "logUniform":
            value = math.exp(math.log(a) + (math.log(b) - math.log(a)) * rng.random())
        else:
            value = a + b * _STANDARD_NORMAL.inv_cdf(_uniform_open(rng))
        values.append(value)
    if "clip" in distribution:
        low, high = distribution["clip"]
        values = [min(max(v, low), high) for v in values]
    return values if vector else values[0]


def distribution_problems(distribution: Mapping[str, Any]) -> str | None:
    """What the schema cannot say about a distribution: list lengths and positive log bounds."""
    kind = next((k for k in ("uniform", "normal", "logUniform") if k in distribution), None)
    if kind is None:
        return None
    first, second = distribution[kind]
    if isinstance(first, list) != isinstance(second, list) or (
            isinstance(first, list) and len(first) != len(second)):
        return f"{kind}: both bounds must be numbers or lists of the same length"
    flat = (first + second) if isinstance(first, list) else [first, second]
    if kind == "logUniform" and not all(v > 0 for v in flat):
        return "logUniform: both bounds must be positive"
    if kind == "uniform" and any(a > b for a, b in zip(*(([first], [second]) if not isinstance(first, list)
                                                       else (first, second)))):
        return "uniform: low must not exceed high"
    if kind == "normal":
        stds = second if isinstance(second, list) else [second]
        if any(s < 0 for s in stds):
            return "normal: the standard deviation must not be negative"
    return None


def _distribution_of(entry: Mapping[str, Any]) -> dict:
    return {k: v for k, v in entry.items() if k in DISTRIBUTIONS or k == "clip"}


@dataclass(frozen=True)
class Randomization:
    """Randomize entries as authored; ``draw(seed)`` gives the overrides of one episode."""

    entries: tuple
    source: str = "<randomize>"

    def draw(self, seed: int) -> list[Override | PoseJitter]:
        edits: list[Override | PoseJitter] = []
        for index, entry in enumerate(self.entries):
            rng = stream(seed, index)
            origin = f"{self.source}: randomize/{index} (seed {seed})"
            if "set" in entry:
                edits.append(Override(entry["set"], _plain(draw(_distribution_of(entry), rng)), origin=origin))
                continue
            offset = draw(entry["offset"], rng) if "offset" in entry else [0.0, 0.0, 0.0]
            yaw = draw(entry["yawDegrees"], rng) if "yawDegrees" in entry else 0.0
            edits.append(PoseJitter(entry["pose"], as_vec3(float(v) for v in offset), float(yaw), origin=origin))
        return edits

    @property
    def targets(self) -> list[str]:
        return [entry.get("set") or f"{entry['pose']}.pose" for entry in self.entries]


def _plain(value):
    return [float(v) if isinstance(v, float) else v for v in value] if isinstance(value, list) else value


def parse_randomization(entries: Sequence[Mapping[str, Any]], source: str) -> Randomization:
    """Check entries the schema already accepted: distributions, targets, offsets of three; every problem at once."""
    problems = randomization_problems(entries, source)
    if problems:
        raise RandomizationError("\n".join(problems))
    return Randomization(tuple(entries), source)


def randomization_problems(entries: Sequence[Any], source: str, skip: Iterable[int] = ()) -> list[str]:
    """One line per problem the schema cannot see in *entries* (those in *skip* already failed the schema)."""
    skipped = set(skip)
    return [problem for index, entry in enumerate(entries)
            if index not in skipped and isinstance(entry, Mapping)
            for problem in entry_problems(entry, f"{source}: randomize/{index}")]


def entry_problems(entry: Mapping[str, Any], where: str) -> list[str]:
    """The problems of one schema-valid randomize entry, each line starting with *where*."""
    problems: list[str] = []
    distributions = [("", _distribution_of(entry))] if "set" in entry else [
        (f"{key}: ", entry[key]) for key in ("offset", "yawDegrees") if key in entry]
    problems.extend(f"{where}: {prefix}{problem}" for prefix, distribution in distributions
                    if (problem := distribution_problems(distribution)))
    if "set" in entry:
        try:
            Override(entry["set"], None, origin=where).parts()
        except OverrideError as error:
            problems.append(str(error))
    if "offset" in entry and "choice" not in entry["offset"]:
        kind = next(k for k in ("uniform", "normal", "logUniform") if k in entry["offset"])
        if not (isinstance(entry["offset"][kind][0], list) and len(entry["offset"][kind][0]) == 3):
            problems.append(f"{where}: offset: the bounds must be lists of three numbers (x, y, z in m)")
    return problems


def load_randomization(path: str) -> Randomization:
    """The ``randomize`` list of a sweep file, of a file holding only ``{"randomize": [...]}``, or of a graph's
    ``scenario`` section (a rate scenario's episodes re-run with ``--randomize`` naming the graph itself)."""
    try:
        data = read_json(path)
    except FileProblem as error:
        raise RandomizationError(str(error)) from None
    if isinstance(data, dict) and data.get("format") == "graphflow":
        data = {"randomize": data.get("scenario", {}).get("randomize", [])}
    errors = schema_errors(data, path, "randomizationFile")
    entries = data.get("randomize") if isinstance(data, dict) else None
    problems = [line for _path, line in errors]
    if isinstance(entries, list):
        broken = {p[1] for p, _line in errors if len(p) >= 2 and p[0] == "randomize"}
        problems += randomization_problems(entries, path, skip=broken)
    if problems:
        raise RandomizationError("\n".join(problems))
    return Randomization(tuple(entries or ()), path)


def variant_for_run(document: GraphDocument, set_texts: Sequence[str], randomize_file: str | None,
                     seed: int) -> Variant:
    """What ``graphflow run --set ... [--randomize FILE --seed N]`` runs; raises OverrideError.

    Node overrides are checked here; stage edits when ``Variant.create_world`` opens the stage. What
    the randomization drew is logged (``--log-level info``) and kept for the trace header.
    """
    edits: list = [parse_set(text) for text in set_texts]
    drawn: list = []
    if randomize_file is not None:
        draws = load_randomization(randomize_file).draw(seed)
        edits.extend(draws)
        drawn = [drawn_record(edit) for edit in draws]
        for record in drawn:
            _log.info("%s: seed %d drew %s", randomize_file, seed, json.dumps(record))
    return dataclasses.replace(make_variant(document, edits), drawn=tuple(drawn))


def drawn_record(edit: Override | PoseJitter) -> dict:
    """A drawn value as JSON: ``{"set": TARGET, "value": V}`` or ``{"pose": PRIM, "offset": [...], "yawDegrees": D}``."""
    if isinstance(edit, PoseJitter):
        return {"pose": edit.prim, "offset": list(edit.offset), "yawDegrees": edit.yaw_degrees}
    return {"set": edit.target, "value": edit.value}
