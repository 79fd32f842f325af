"""Finds node types: the built-in ``graphflow_nodes`` package and third-party packages.

Third-party packages declare an entry point in the group ``graphflow.nodes``
that loads a node module (``SPEC`` + ``compute``) or a package of them. A graph
file only ever names registered type ids, so loading a graph never imports
code the file names.
"""
from __future__ import annotations

import difflib
import importlib
import logging
import pkgutil
from importlib.metadata import entry_points
from types import ModuleType

from .spec import NodeType

ENTRY_POINT_GROUP = "graphflow.nodes"
log = logging.getLogger(__name__)


class Registry:
    """Node types by id, with legacy aliases (``omni.isaac.*`` ids mapping to current ones)."""

    def __init__(self):
        self._types: dict[str, NodeType] = {}
        self._aliases: dict[str, str] = {}

    def register(self, node_type: NodeType) -> None:
        spec = node_type.spec
        if spec.id in self._types and self._types[spec.id].module != node_type.module:
            raise ValueError(f"node type {spec.id!r} is defined twice: in {self._types[spec.id].module} and {node_type.module}")
        self._types[spec.id] = node_type
        for alias in spec.aliases:
            self._aliases[alias] = spec.id

    def register_module(self, module: ModuleType) -> bool:
        """Register a node module; returns False when the module declares no node type."""
        spec, compute = getattr(module, "SPEC", None), getattr(module, "compute", None)
        if spec is None or compute is None:
            return False
        self.register(NodeType(spec=spec, compute=compute,
                               initialize=getattr(module, "initialize", None),
                               validate=getattr(module, "validate", None),
                               module=module.__name__))
        return True

    def register_package(self, package: ModuleType) -> None:
        """Register every public module of a package (modules starting with ``_`` are helpers)."""
        for info in sorted(pkgutil.iter_modules(package.__path__), key=lambda i: i.name):
            if info.name.startswith("_"):
                continue
            self.register_module(importlib.import_module(f"{package.__name__}.{info.name}"))

    def resolve_id(self, type_id: str) -> str | None:
        if type_id in self._types:
            return type_id
        return self._aliases.get(type_id)

    def get(self, type_id: str) -> NodeType | None:
        resolved = self.resolve_id(type_id)
        return self._types.get(resolved) if resolved else None

    def suggest(self, type_id: str) -> str | None:
        """The closest known id, for 'did you mean' hints."""
        matches = difflib.get_close_matches(type_id, list(self._types) + list(self._aliases), n=1, cutoff=0.6)
        return matches[0] if matches else None

    def types(self) -> list[NodeType]:
        return [self._types[i] for i in sorted(self._types)]


def _load_entry_point(registry: Registry, entry_point) -> None:
    try:
        loaded = entry_point.load()
    except Exception as error:  # a broken plug-in must not take the built-ins down with it
        log.warning("node package %s could not be loaded: %s", entry_point.value, error)
        return
    if isinstance(loaded, ModuleType) and hasattr(loaded, "__path__") and not hasattr(loaded, "SPEC"):
        registry.register_package(loaded)
    elif isinstance(loaded, ModuleType):
        registry.register_module(loaded)
    else:
        log.warning("entry point %s is not a node module or package", entry_point.value)


_default: Registry | None = None


def default_registry() -> Registry:
    """The process-wide registry: built-in nodes plus installed node packages."""
    global _default
    if _default is None:
        registry = Registry()
        import graphflow_nodes

        registry.register_package(graphflow_nodes)
        for entry_point in entry_points(group=ENTRY_POINT_GROUP):
            _load_entry_point(registry, entry_point)
        _default = registry
    return _default
