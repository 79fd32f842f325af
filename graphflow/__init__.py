"""graphflow: OmniGraph-style action graphs for robot manipulation, on PyBullet."""
try:   # the graphflow command: from its first instruction a Ctrl-C is an interrupt (graphflow.errors)
    from graphflow.errors import defer_interrupts as _defer_interrupts

    _defer_interrupts()
except KeyboardInterrupt:    # before the handler was in place
    from graphflow.errors import is_the_command as _is_the_command
    from graphflow.errors import note_interrupt as _note_interrupt

    if not _is_the_command():
        raise
    _note_interrupt()
import os as _os
import sys as _sys

__version__ = "0.1.0"

# usd-core builds its schema registry once, from the plugins known when the first stage is
# made; a plugin registered later is ignored. So the Isaac surface-gripper schema is announced
# at import time: through PXR_PLUGINPATH_NAME when pxr is not loaded yet (no pxr import, so
# `import graphflow` stays cheap), or registered directly when the caller imported pxr first.
_ISAAC_SCHEMA = _os.path.join(_os.path.dirname(_os.path.abspath(__file__)), "gripper", "schema")
if "pxr" in _sys.modules:
    from pxr import Plug as _Plug

    _Plug.Registry().RegisterPlugins(_ISAAC_SCHEMA)
else:
    _paths = [p for p in _os.environ.get("PXR_PLUGINPATH_NAME", "").split(_os.pathsep) if p]
    if _ISAAC_SCHEMA not in _paths:
        _os.environ["PXR_PLUGINPATH_NAME"] = _os.pathsep.join([*_paths, _ISAAC_SCHEMA])


# The public API: what a user scripts against. Names resolve on first use (PEP 562), so ``import graphflow``
# stays cheap and never loads numpy, usd-core or PyBullet before a graph needs them.
_EXPORTS = {
    "load_document": "graphflow.document", "parse_document": "graphflow.document", "save_document": "graphflow.document",
    "GraphDocument": "graphflow.model", "compile": "graphflow.compiler", "CompiledGraph": "graphflow.compiled",
    "GraphInstance": "graphflow.executor", "Simulation": "graphflow.runtime", "create_world": "graphflow.runtime",
    "World": "graphflow.world", "NodeSpec": "graphflow.spec", "Attribute": "graphflow.spec",
    "NodeDb": "graphflow.node_api", "NodeModule": "graphflow.node_api",
    "CheckedRun": "graphflow.verdicts.checked_run", "Verdict": "graphflow.verdicts.checked_run",
    "run_checked": "graphflow.verdicts.checked_run",
    "NodeHarness": "graphflow.testing", "GraphHarness": "graphflow.testing",
    "GraphflowError": "graphflow.errors", "BadInput": "graphflow.errors", "RunFailure": "graphflow.errors",
}
__all__ = sorted(_EXPORTS)


def __getattr__(name: str):
    module = _EXPORTS.get(name)
    if module is None:
        raise AttributeError(f"module 'graphflow' has no attribute {name!r}")
    import importlib

    return getattr(importlib.import_module(module), name)
