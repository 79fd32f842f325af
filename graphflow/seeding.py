"""Seeding a run: Python's generator at once, numpy's when (and only if) something imports ``numpy.random``."""
from __future__ import annotations

import random
import sys
from importlib.machinery import ModuleSpec
from typing import Any

_run_seed = 0


def seed_everything(seed: int) -> None:
    """Seed Python's and (when a graph imports it) numpy's global generators, as ``graphflow run --seed`` does."""
    global _run_seed
    _run_seed = seed
    random.seed(seed)
    _seed_numpy(seed)


class _SeedNumpyOnImport:
    """Seeds numpy's global generator right after ``numpy.random`` is first imported.

    ``--seed`` must seed numpy for graphs that use it, but importing numpy only
    to seed it costs a core-node graph a good part of its start-up time. A
    meta-path finder that wraps the real loader makes the seeding happen when
    (and only if) something imports ``numpy.random``: no code can draw from it
    before the seed.
    """

    def __init__(self, seed: int):
        self.seed = seed

    def find_spec(self, fullname: str, path: object = None, target: object = None) -> ModuleSpec | None:
        if fullname != "numpy.random":
            return None
        sys.meta_path.remove(self)
        import importlib.util

        spec = importlib.util.find_spec(fullname)
        if spec is not None and spec.loader is not None:
            exec_module, seed = spec.loader.exec_module, self.seed

            def exec_and_seed(module: Any) -> None:
                exec_module(module)
                module.seed(seed)

            spec.loader.exec_module = exec_and_seed  # type: ignore[method-assign]  # seeding as numpy.random loads
        return spec


def run_seed() -> int:
    """The seed of the current run (``--seed``; 0 until one is given): nodes that draw numbers derive theirs from it."""
    return _run_seed


def _seed_numpy(seed: int) -> None:
    random_module = sys.modules.get("numpy.random")
    if random_module is not None:
        random_module.seed(seed)
    elif not any(isinstance(finder, _SeedNumpyOnImport) for finder in sys.meta_path):
        sys.meta_path.insert(0, _SeedNumpyOnImport(seed))
    else:
        next(f for f in sys.meta_path if isinstance(f, _SeedNumpyOnImport)).seed = seed
