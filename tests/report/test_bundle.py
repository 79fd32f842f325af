"""The page bundle shipped in the package is exactly what frontend/ builds (so nobody ships stale or hand-edited JS)."""
import os
import shutil
import subprocess

import pytest

from .conftest import GRAPHS

ROOT = GRAPHS.parent
FRONTEND = ROOT / "frontend"
BUNDLE = ROOT / "graphflow" / "report" / "bundle" / "report.html"


def test_committed_bundle_is_a_fresh_build_of_the_sources(tmp_path):
    npm = shutil.which("npm")
    if npm is None or shutil.which("node") is None:
        pytest.skip("node and npm are not installed: cannot rebuild frontend/")
    if not (FRONTEND / "node_modules").is_dir():
        pytest.skip("frontend/node_modules is missing: run `npm ci --prefix frontend` (the lockfile pins every package)")
    environment = dict(os.environ, GRAPHFLOW_REPORT_OUT=str(tmp_path / "bundle"))
    build = subprocess.run([npm, "run", "--silent", "build"], cwd=FRONTEND, env=environment,
                           capture_output=True, text=True, timeout=300)
    assert build.returncode == 0, build.stdout + build.stderr
    fresh = (tmp_path / "bundle" / "report.html").read_bytes()
    assert fresh == BUNDLE.read_bytes(), "graphflow/report/bundle/report.html is stale: run `npm run build --prefix frontend`"
