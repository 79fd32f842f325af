"""Loading the demo graphs for the physics benchmarks (not a benchmark: the underscore keeps it out of NAMES)."""
from __future__ import annotations

import contextlib
import io
from pathlib import Path

from . import GRAPHS, Skip

PICK_PLACE = GRAPHS / "ur10_pick_place.json"
STACKING = GRAPHS / "ur10_stacking.json"
GANTRY = GRAPHS / "gantry_keyboard.json"
GANTRY_KEYS = GRAPHS / "gantry_keyboard.keys.json"


def require(path: Path) -> Path:
    if not path.exists():
        raise Skip(f"{path.relative_to(GRAPHS.parent)} not found")
    return path


@contextlib.contextmanager
def quiet():
    """Silence what a world prints on creation (PyBullet's build banner goes to C stdout)."""
    import os
    import sys

    sys.stdout.flush()
    saved = os.dup(1)
    try:
        with open(os.devnull, "w") as null:
            os.dup2(null.fileno(), 1)
            with contextlib.redirect_stdout(io.StringIO()):
                yield
    finally:
        sys.stdout.flush()
        _flush_c_stdio()
        os.dup2(saved, 1)
        os.close(saved)


def _flush_c_stdio() -> None:
    try:
        import ctypes

        ctypes.CDLL(None).fflush(None)
    except (OSError, AttributeError):
        pass


def simulation(path: Path, keys: Path | None = None):
    """A Simulation of the graph at *path* (its stage on PyBullet), with a scripted keyboard if *keys* is given."""
    from graphflow.document import load_document
    from graphflow.runtime import Simulation

    with quiet():
        sim = Simulation(load_document(require(path)))
    if keys is not None:
        attach_keys(sim.world, keys)
    return sim


def bare_world(path: Path, keys: Path | None = None):
    """The world the graph at *path* runs against, with no graph."""
    from graphflow.document import load_document
    from graphflow.runtime import create_world_for

    with quiet():
        world = create_world_for(load_document(require(path)))
    if keys is not None:
        attach_keys(world, keys)
    return world


def attach_keys(world, keys: Path) -> None:
    from graphflow.inputs.keyboard import attach_keyboard, scripted_keys

    attach_keyboard(world, scripted_keys(require(keys)))
