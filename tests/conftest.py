"""Where the tests find the repository and the shared test data (``../shared`` beside the checkout), located once.

Tests import these names (``from conftest import SHARED``). Anything under ``SHARED`` may be absent
(a checkout without it): tests that need it skip, naming what is missing.
"""
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent           # the repository
GRAPHS = ROOT / "graphs"
SHARED = ROOT.parent / "shared"
USDA_SAMPLES = SHARED / "usda_samples"                   # Isaac's gantry scene with its surface-gripper graph, ...
ISAAC_CORPUS = SHARED / "isaac_corpus"                   # real .usda files made with Isaac Sim (manifest.json)
CORPUS_FILES = ISAAC_CORPUS / "files"
ISAAC_GANTRY = USDA_SAMPLES / "isaacsim_SurfaceGripper_gantry.usda"
