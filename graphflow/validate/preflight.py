"""What a command checks before it starts, so ``validate`` refuses exactly what ``run`` would.

``file_problems(path)`` is ``run``'s load without the physics world: the graph
file (strict JSON, schema, semantics) and its stage, read with usd-core by the
same ``load_description`` that builds a world, so a stage ``run`` refuses
(missing, unreadable, negative mass, zero-size collider, non-finite transform)
is refused by ``validate`` with the same lines. Every problem is listed, of
every kind, in one pass.
"""
from __future__ import annotations

import os
import warnings
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from graphflow.document import GraphDocument, GraphError, Problem, load_document
from graphflow.files import FileProblem, read_json


@dataclass(frozen=True)
class ParsedStage:
    """A stage opened and parsed once by the preflight, handed on to the world built for the same run."""

    usd_stage: Any
    description: Any


def parse_stage(source: str, stage: str, base_dir: str | os.PathLike, *,
                quiet: bool = True) -> tuple[list[Problem], ParsedStage | None]:
    """Open and parse *stage* (a ``settings.stage`` value of the file *source*): (problems, the parsed stage).

    *quiet* keeps the parser's unsupported-prim warnings to itself (``validate``); a run shows them, once. A layer
    that cannot be opened is always said.
    """
    from graphflow.usd.errors import StageError
    from graphflow.usd.physics_import import load_description, open_stage
    from graphflow.usd.resolver import resolve_stage

    try:
        usd_stage, _label = open_stage(resolve_stage(stage, base_dir))   # a missing layer is said either way
        with warnings.catch_warnings():
            if quiet:
                warnings.simplefilter("ignore")    # unsupported prims are simulated without; not a problem
            description = load_description(usd_stage)
    except StageError as error:
        return stage_error_problems(source, error), None
    return [], ParsedStage(usd_stage, description)


def stage_problems(source: str, stage: str, base_dir: str | os.PathLike) -> list[Problem]:
    """The problems ``run`` would find loading *stage* (a ``settings.stage`` value of the file *source*)."""
    return parse_stage(source, stage, base_dir)[0]


def stage_error_problems(source: str, error) -> list[Problem]:
    """A ``StageError`` as problems of the graph file that names the stage."""
    return [Problem(source, f"settings/stage: {line}") for line in error.problems]


def file_problems(path: str | os.PathLike) -> list[Problem]:
    """Every problem ``run`` would report loading the graph file *path*, before its first tick."""
    source = str(path)
    try:
        document: GraphDocument | None = load_document(path)
        problems: list[Problem] = []
    except GraphError as error:
        document, problems = None, list(error.problems)
    if document is not None:
        stage, base_dir = document.settings.get("stage"), document.base_dir
    else:
        stage, base_dir = _authored_stage(path), Path(path).resolve().parent
    if isinstance(stage, str) and stage and not any(p.path[:2] == ("settings", "stage") for p in problems):
        problems.extend(stage_problems(source, stage, base_dir))
    return problems


def _authored_stage(path) -> str | None:
    """``settings.stage`` of a file that did not validate, when it can still be read."""
    try:
        data = read_json(path)
    except FileProblem:
        return None
    settings = data.get("settings") if isinstance(data, dict) else None
    return settings.get("stage") if isinstance(settings, dict) else None


def document_problems(document: GraphDocument, *, quiet: bool = True) -> tuple[list[Problem], ParsedStage | None]:
    """What ``validate`` refuses in a loaded document (its stage, then what it names there), and the stage as
    parsed: ``run``'s preflight, which hands the parsed stage to its world so the stage is read once."""
    from graphflow.validate.stage_names import deep_validate

    stage, parsed = document.settings.get("stage"), None
    if isinstance(stage, str) and stage:
        problems, parsed = parse_stage(document.source, stage, document.base_dir, quiet=quiet)
        if problems:
            return problems, None
    # inputs naming prims of layers the import could not open do not stop a run: their node fails at its first compute
    return deep_validate(document, allow_missing_assets=True, parsed=parsed)[0], parsed
