"""With NVIDIA's urdf-usd-converter installed in its own environment (on PATH or named by
$GRAPHFLOW_URDF_CONVERTER), ``graphflow robot add`` remakes the packaged Panda from pybullet_data's
panda.urdf with the command its doc records: the same bodies, masses, joints and drives. Skipped without it."""
import os
import shutil
import subprocess
import sys
import warnings

import pytest
from conftest import ROOT

from graphflow.usd.physics_import import load_description

CONVERTER = os.environ.get("GRAPHFLOW_URDF_CONVERTER") or shutil.which("urdf_usd_converter")
pytestmark = pytest.mark.skipif(CONVERTER is None, reason="urdf-usd-converter is not installed (its own environment)")
SHIPPED = ROOT / "graphflow" / "assets" / "panda.usda"


def physics(path):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        description = load_description(str(path))
    bodies = {path: (body.mass.mass, body.mass.center_of_mass, len(body.shapes)) for path, body in description.bodies.items()}
    joints = {path: (joint.kind, joint.body0, joint.body1, joint.lower, joint.upper, joint.drive)
              for path, joint in description.joints.items()}
    return bodies, joints


def test_robot_add_remakes_the_packaged_panda(tmp_path):
    import pybullet_data

    folder = os.path.join(pybullet_data.getDataPath(), "franka_panda")
    recorded = next(line for line in SHIPPED.read_text().splitlines() if line.strip().startswith("doc = "))
    arguments = recorded.split("graphflow robot add ", 1)[1].rstrip('"').split()
    result = subprocess.run([sys.executable, "-m", "graphflow", "robot", "add", *arguments, "--package",
                             "meshes=meshes", "--converter", CONVERTER, "-o", str(tmp_path / "panda.usda")],
                            capture_output=True, text=True, cwd=folder)
    assert result.returncode == 0, result.stderr
    assert physics(tmp_path / "panda.usda") == physics(SHIPPED)
