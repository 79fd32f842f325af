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

import json
import math
import random
from dataclasses import dataclass
from functools import lru_cache
from importlib import resources
from statistics import NormalDist
from typing import Any, Mapping, Sequence

from graphflow.files import FileProblem, read_json
from graphflow.model import GraphDocument
from graphflow.variants.overrides import (
    Override,
    OverrideError,
    PoseJitter,
    Variant,
    make_variant,
    parse_set,
)

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
    import jsonschema

    schema = sweep_schema()
    if definition is not None:
        schema = {"$defs": schema["$defs"], "$ref": f"#/$defs/{definition}"}
    validator = jsonschema.Draft202012Validator(schema)
    problems = []
    for error in sorted(validator.iter_errors(data), key=lambda e: [str(p) for p in e.absolute_path]):
        location = "/".join(str(p) for p in error.absolute_path) or "document"
        problems.append(f"{source}: {location}: {_short(error)}")
    return problems


def _short(error) -> str:
    """The most specific message of a schema error (oneOf/anyOf errors name their best sub-error)."""
    if error.context:
        best = min(error.context, key=lambda e: (-len(e.absolute_path), len(e.message)))
        return best.message
    return error.message


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
            edits.append(PoseJitter(entry["pose"], tuple(float(v) for v in offset), float(yaw), origin=origin))
        return edits

    @property
    def targets(self) -> list[str]:
        return [entry.get("set") or f"{entry['pose']}.pose" for entry in self.entries]


def _plain(value):
    return [float(v) if isinstance(v, float) else v for v in value] if isinstance(value, list) else value


def parse_randomization(entries: Sequence[Mapping[str, Any]], source: str) -> Randomization:
    """Check entries the schema already accepted: distributions, targets, offsets of three."""
    for index, entry in enumerate(entries):
        where = f"{source}: randomize/{index}"
        distributions = [("", _distribution_of(entry))] if "set" in entry else [
            (f"{key}: ", entry[key]) for key in ("offset", "yawDegrees") if key in entry]
        for prefix, distribution in distributions:
            problem = distribution_problems(distribution)
            if problem:
                raise RandomizationError(f"{where}: {prefix}{problem}")
        if "set" in entry:
            try:
                Override(entry["set"], None, origin=where).parts()
            except OverrideError as error:
                raise RandomizationError(str(error)) from None
        if "offset" in entry and "choice" not in entry["offset"]:
            kind = next(k for k in ("uniform", "normal", "logUniform") if k in entry["offset"])
            if not (isinstance(entry["offset"][kind][0], list) and len(entry["offset"][kind][0]) == 3):
                raise RandomizationError(f"{where}: offset: the bounds must be lists of three numbers (x, y, z in m)")
    return Randomization(tuple(entries), source)


def load_randomization(path: str) -> Randomization:
    """The ``randomize`` list of a sweep file, of a file holding only ``{"randomize": [...]}``, or of a graph's
    ``scenario`` section (a rate scenario's episodes re-run with ``--randomize`` naming the graph itself)."""
    try:
        data = read_json(path)
    except FileProblem as error:
        raise RandomizationError(str(error)) from None
    except json.JSONDecodeError as error:
        raise RandomizationError(f"{path}: malformed JSON at line {error.lineno} column {error.colno}: {error.msg}") from None
    if isinstance(data, dict) and data.get("format") == "graphflow":
        data = {"randomize": data.get("scenario", {}).get("randomize", [])}
    problems = schema_problems(data, path, "randomizationFile")
    if problems:
        raise RandomizationError(problems[0])
    return parse_randomization(data["randomize"], path)


def variant_for_run(document: GraphDocument, set_texts: Sequence[str], randomize_file: str | None,
                     seed: int) -> Variant:
    """What ``graphflow run --set ... [--randomize FILE --seed N]`` runs; raises OverrideError.

    Node overrides are checked here; stage edits when ``Variant.create_world`` opens the stage.
    """
    edits: list = [parse_set(text) for text in set_texts]
    if randomize_file is not None:
        edits.extend(load_randomization(randomize_file).draw(seed))
    return make_variant(document, edits)
