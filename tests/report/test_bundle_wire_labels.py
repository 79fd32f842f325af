"""A bundle on a wire (report and studio) is labelled by its size, as the trace writes it (frontend/src/data.js)."""
import json
import shutil
import subprocess

import pytest

from graphflow.bundles import Bundle, BundleAttribute
from graphflow.observe.trace import to_json_value

from .conftest import GRAPHS

DATA_JS = GRAPHS.parent / "frontend" / "src" / "data.js"


def _labels(values):
    node = shutil.which("node")
    if node is None:
        pytest.skip("node is not installed: cannot run frontend/src/data.js")
    script = (f"import {{ shortValue }} from {json.dumps(DATA_JS.as_uri())};\n"
              f"console.log(JSON.stringify({json.dumps(values)}.map((v) => shortValue(v))));")
    run = subprocess.run([node, "--input-type=module", "-e", script], capture_output=True, text=True, timeout=60)
    assert run.returncode == 0, run.stderr
    return json.loads(run.stdout)


def test_bundles_show_their_attribute_and_child_counts_and_other_objects_their_content():
    prim = Bundle.of_prim("/World/Cube", "Cube", (BundleAttribute("size", "double", 0.2),))
    values = [to_json_value(prim), to_json_value(Bundle((), (prim, prim))), to_json_value(Bundle()),
              {"offset": [1, 2, 3]}]
    assert _labels(values) == ["{3 attributes}", "{0 attributes, 2 children}", "{0 attributes}", "{offset: [1, 2, 3]}"]
