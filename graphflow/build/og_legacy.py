"""Isaac 4.x's Surface Gripper node (v1, ``omni.isaac.surface_gripper.SurfaceGripper``) in og compat scripts.

``graphflow import`` maps a v1 node of a ``.usda`` file onto ``graphflow.LegacySurfaceGripper`` and, for its
Close/Open pins, a current SurfaceGripper node commanding the gripper the legacy node creates
(``graphflow.usd.node_mapping``); a script's ``og.Controller.edit`` gets the same mapping here. The 4.x id
only ever named v1 (the prim-based v2 came with Isaac 5 under ``isaacsim.robot.surface_gripper``).
"""
from __future__ import annotations

from typing import Any, Callable

from graphflow.build.graph import Graph, NodeHandle
from graphflow.usd.node_mapping import (
    COMMAND_NODE_SUFFIX,
    LEGACY_GRIPPER_ID,
    SURFACE_GRIPPER_IDS,
    legacy_gripper_command_node,
    legacy_gripper_renames,
    map_legacy_surface_gripper,
)

V1_ID = SURFACE_GRIPPER_IDS[1]   # omni.isaac.surface_gripper.SurfaceGripper


def create(graph: Graph, name: str, warn: Callable[[str], None]) -> NodeHandle:
    """The legacy gripper node standing for a v1 SurfaceGripper named *name*."""
    warn(f"node '{name}' ({V1_ID}): Isaac 4.x's Surface Gripper (v1) built as {LEGACY_GRIPPER_ID}")
    return graph.node(name, LEGACY_GRIPPER_ID)


def endpoint(graph: Graph, node: str, port: str, warn: Callable[[str], None]) -> str:
    """Where a v1 port (``inputs:Close``, ``outputs:Closed``...) of *node* is in the mapped graph."""
    mapped = legacy_gripper_renames(node).get((node, port))
    if mapped is None:
        return f"{node}.{port}"
    command = f"{node}{COMMAND_NODE_SUFFIX}"
    if mapped.startswith(command) and graph.document.node(command) is None:
        notes: list[str] = []
        entry, link = legacy_gripper_command_node(node, f"node '{node}'", notes)
        graph.node(entry["name"], entry["type"])
        graph.connect(link["src"], link["dst"])
        for note in notes:
            warn(note)
    return mapped


def values(node: str, authored: dict[str, Any], warn: Callable[[str], None]) -> dict[str, Any]:
    """v1 input values (``ParentRigidBody``, ``GripThreshold``...) as the legacy gripper's inputs, one line each."""
    plain = {name: [value] if name == "ParentRigidBody" and isinstance(value, str) else value
             for name, value in authored.items()}
    notes: list[str] = []
    mapped = map_legacy_surface_gripper(node, plain, f"node '{node}'", notes)
    for note in notes:
        warn(note)
    return mapped
