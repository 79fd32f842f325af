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

from graphflow.spec import NodeType

ENTRY_POINT_GROUP = "graphflow.nodes"
log = logging.getLogger(__name__)


class Registry:
    """Node types by id, with legacy aliases (``omni.isaac.*`` ids mapping to current ones)."""

    def __init__(self):
        self._types: dict[str, NodeType] = {}
        self._aliases: dict[str, str] = {}
        self._suggestions: dict[str, str | None] = {}

    def register(self, node_type: NodeType) -> None:
        spec = node_type.spec
        if spec.id in self._types and self._types[spec.id].module != node_type.module:
            raise ValueError(f"node type {spec.id!r} is defined twice: in {self._types[spec.id].module} and {node_type.module}")
        self._types[spec.id] = node_type
        for alias in spec.aliases:
            self._aliases[alias] = spec.id
        self._suggestions.clear()

    def register_module(self, module: ModuleType) -> bool:
        """Register a node module; returns False when the module declares no node type."""
        spec, compute = getattr(module, "SPEC", None), getattr(module, "compute", None)
        if spec is None or compute is None:
            return False
        self.register(NodeType(spec=spec, compute=compute,
                               initialize=getattr(module, "initialize", None),
                               validate=getattr(module, "validate", None),
                               idle=getattr(module, "idle", None),
                               module=module.__name__))
        return True

    def register_package(self, package: ModuleType, on_error=None) -> None:
        """Register every public module of a package (modules starting with ``_`` are helpers).

        With *on_error* (third-party packages), a module that fails to import or register is
        passed to ``on_error(module_name, error)`` and skipped instead of failing the whole package.
        """
        for info in sorted(pkgutil.iter_modules(package.__path__), key=lambda i: i.name):
            if info.name.startswith("_"):
                continue
            name = f"{package.__name__}.{info.name}"
            if on_error is None:
                self.register_module(importlib.import_module(name))
                continue
            try:
                self.register_module(importlib.import_module(name))
            except Exception as error:
                on_error(name, error)

    def resolve_id(self, type_id: str) -> str | None:
        if type_id in self._types:
            return type_id
        return self._aliases.get(type_id)

    def get(self, type_id: str) -> NodeType | None:
        resolved = self.resolve_id(type_id)
        return self._types.get(resolved) if resolved else None

    def require(self, type_id: str) -> NodeType:
        """The node type of a document already checked against this registry: a miss is a wrong registry."""
        node_type = self.get(type_id)
        if node_type is None:
            raise KeyError(f"node type '{type_id}' is not in this registry")
        return node_type

    def suggest(self, type_id: str) -> str | None:
        """The closest known id, for 'did you mean' hints (remembered: a file repeats its misspellings)."""
        if type_id not in self._suggestions:
            matches = difflib.get_close_matches(type_id, list(self._types) + list(self._aliases), n=1, cutoff=0.6)
            self._suggestions[type_id] = matches[0] if matches else None
        return self._suggestions[type_id]

    def types(self) -> list[NodeType]:
        return [self._types[i] for i in sorted(self._types)]


def _load_entry_point(registry: Registry, entry_point) -> None:
    """Register a third-party node package; whatever is broken in it is a warning naming the package
    and module, and the built-ins (and the package's other modules) keep working."""
    package = getattr(getattr(entry_point, "dist", None), "name", None) or getattr(entry_point, "name", entry_point.value)

    def skip(module: str, error: Exception) -> None:
        reason = " ".join(f"{type(error).__name__}: {error}".split())
        log.warning("node package %s: module %s skipped: %s", package, module, reason)

    try:
        loaded = entry_point.load()
    except Exception as error:  # a broken plug-in must not take the built-ins down with it
        skip(entry_point.value, error)
        return
    if isinstance(loaded, ModuleType) and hasattr(loaded, "__path__") and not hasattr(loaded, "SPEC"):
        registry.register_package(loaded, on_error=skip)
    elif isinstance(loaded, ModuleType):
        try:
            registry.register_module(loaded)
        except Exception as error:
            skip(loaded.__name__, error)
    else:
        log.warning("node package %s: entry point %s is not a node module or package", package, entry_point.value)


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
