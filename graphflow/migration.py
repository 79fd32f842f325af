"""Node type versions: a graph file naming an older ``typeVersion`` of a node type is brought to the current one.

A node type lists the older versions it still reads (``NodeSpec.compatible_versions``: their files
author the same inputs). Loading such a file migrates it in memory and says so in one line per node,
naming the node, the type and the versions; ``graphflow migrate FILE`` writes the migrated file.
Versions a type does not list stay refused by the compiler (one line naming the node).
"""
from __future__ import annotations

import warnings
from dataclasses import replace

from graphflow.model import GraphDocument
from graphflow.registry import Registry, default_registry


class MigrationWarning(UserWarning):
    """A node of a loaded file was migrated to its type's current version (the message is one line)."""


def migrated(document: GraphDocument, registry: Registry | None = None) -> tuple[GraphDocument, list[str]]:
    """*document* with every node of an older compatible typeVersion at its type's version, and one line per change."""
    registry = registry or default_registry()
    nodes, lines = [], []
    for node in document.nodes:
        node_type = registry.get(node.type)
        spec = node_type.spec if node_type is not None else None
        if (spec is None or node.type_version is None or node.type_version >= spec.version
                or node.type_version not in spec.compatible_versions):
            nodes.append(node)
            continue
        lines.append(f"{document.source}: node '{node.name}': {spec.id} typeVersion {node.type_version} -> "
                     f"{spec.version} (version {spec.version} reads the inputs version {node.type_version} "
                     "authored; only the typeVersion changes)")
        nodes.append(replace(node, type_version=spec.version))
    if not lines:
        return document, []
    return replace(document, nodes=tuple(nodes)), lines


def migrate_on_load(document: GraphDocument, registry: Registry | None = None) -> GraphDocument:
    """Migrate a freshly loaded file, one ``MigrationWarning`` line per node changed."""
    document, lines = migrated(document, registry)
    for line in lines:
        warnings.warn(MigrationWarning(line), stacklevel=3)
    return document
