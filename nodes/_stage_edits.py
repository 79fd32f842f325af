"""What the variant, relationship and material nodes share: their prim ports and calls to the world's stage edits.

The world does the editing (``World.set_variant_selection``, ``write_stage_values``, ...; see
``graphflow.usd.stage_edits``): every edit goes to the run's own layer, is dropped when the world resets, and
is refused, rolled back, when it would change what is simulated. Kit's ``layerIdentifier`` (which layer of
the open stage to author in) has no counterpart: a graphflow run never writes a file.
"""
from __future__ import annotations

from typing import Any, Callable

from graphflow.node_api import NodeDb
from graphflow.spec import Attribute
from graphflow.world import WorldError

VARIANT_CATEGORIES = ("graph:action", "sceneGraph", "variants")
LAYER_HELP = "Kit's USD layer to author in (no effect: a run's edits go to its own layer, dropped on reset)"
LAYER_IDENTIFIER = Attribute("layerIdentifier", "token", default="", description=LAYER_HELP)
PRIM = Attribute("prim", "target", description="The prim with the variantSet")
VARIANT_SET_NAME = Attribute("variantSetName", "token", default="", description="The variantSet name")
# Kit's earlier version-2 readers also took the prim by path
USE_PATH = Attribute("usePath", "bool", default=False, description="Use primPath instead of prim")
PRIM_PATH = Attribute("primPath", "token", default="", optional=True, description="The prim's path when usePath is true")


def target_prim(db: NodeDb) -> str:
    """The one prim a node names: primPath when the node has usePath and it is set, else the 'prim' target."""
    if getattr(db.inputs, "usePath", False):
        path = db.inputs.primPath
    else:
        targets = db.inputs.prim or ()
        if len(targets) > 1:
            db.error(f"inputs:prim must name one prim, got {len(targets)}")
        path = targets[0] if targets else ""
    if not path:
        db.error("no prim given: inputs:prim is empty")
    return path


def prim_or_path(db: NodeDb, target: str, path: str) -> str:
    """A target input that takes priority over a path input (Kit's material nodes)."""
    targets = getattr(db.inputs, target) or ()
    chosen = targets[0] if targets else getattr(db.inputs, path)
    if not chosen:
        db.error(f"no prim given: set inputs:{target} or inputs:{path}")
    return str(chosen)


def on_world(db: NodeDb, call: Callable[..., Any], *args) -> Any:
    """``call(*args)`` on the world, a refusal ending the run with the node's one line."""
    try:
        return call(*args)
    except WorldError as error:
        db.error(str(error))


def write_bindings(db: NodeDb, bindings: dict[str, tuple[str, ...]]) -> None:
    """Author the material bindings a variant makes (targets by relationship path) as run-time opinions: a
    purpose-less one binds through UsdShade (which applies MaterialBindingAPI), others set their targets."""
    for relationship_path, targets in bindings.items():
        owner, name = relationship_path.rsplit(".", 1)
        if name == "material:binding" and len(targets) == 1:
            on_world(db, db.world.bind_material, owner, targets[0])
        else:
            on_world(db, db.world.set_relationship_targets, owner, name, targets)
