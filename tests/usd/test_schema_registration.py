"""The Isaac surface-gripper schema is known to usd-core whichever of pxr and graphflow is imported first."""
import subprocess
import sys

import pytest

CHECK = ("s = Usd.Stage.CreateInMemory(); g = s.DefinePrim('/G', 'IsaacSurfaceGripper');"
         "print(g.IsA(Usd.Typed), round(g.GetAttribute('isaac:maxGripDistance').Get(), 4))")


@pytest.mark.parametrize("imports", ["import graphflow; from pxr import Usd", "from pxr import Usd; import graphflow"])
def test_schema_fallbacks_apply_in_either_import_order(imports):
    output = subprocess.run([sys.executable, "-c", f"{imports}; {CHECK}"], capture_output=True, text=True, check=True)
    assert output.stdout.split() == ["True", "0.01"]
