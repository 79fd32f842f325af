"""graphflow: OmniGraph-style action graphs for robot manipulation, on PyBullet."""
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
