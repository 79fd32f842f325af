"""A diverging simulation is a run-time error naming the body and the tick; what the importer cannot
represent is named on one line by `graphflow stage` and by `graphflow run` (issue 12 item 5)."""
import json
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import CORPUS_FILES

from graphflow.physics import create_world
from graphflow.physics.health import NonFiniteState

HUMANOID = CORPUS_FILES / "newton-physics__newton" / "humanoid.usda"

# a ball thrown at an infinite speed: its pose is not finite after the first step
DIVERGING = '''#usda 1.0
(
    upAxis = "Z"
    metersPerUnit = 1
)
def Sphere "Ball" (
    prepend apiSchemas = ["PhysicsRigidBodyAPI", "PhysicsCollisionAPI"]
)
{
    double radius = 0.05
    vector3f physics:velocity = (inf, 0, 0)
}
def Sphere "Calm" (
    prepend apiSchemas = ["PhysicsRigidBodyAPI", "PhysicsCollisionAPI"]
)
{
    double radius = 0.05
    double3 xformOp:translate = (1, 0, 0)
    uniform token[] xformOpOrder = ["xformOp:translate"]
}
'''


def graphflow(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "graphflow", *args], capture_output=True, text=True, cwd=cwd)


def tick_graph(folder: Path, stage: Path) -> Path:
    graph = folder / "graph.json"
    graph.write_text(json.dumps({"format": "graphflow", "formatVersion": [1, 0],
                                 "settings": {"stage": str(stage), "duration": 0.1},
                                 "nodes": [{"name": "tick", "type": "omni.graph.action.OnTick"}], "connections": []}))
    return graph


def test_a_non_finite_body_stops_the_world_naming_it_and_the_step(tmp_path):
    stage = tmp_path / "diverging.usda"
    stage.write_text(DIVERGING)
    with create_world(stage) as world:
        with pytest.raises(NonFiniteState, match=r"^/Ball: pose or velocity is not finite after physics step 1 "):
            world.step()


def test_run_exits_1_on_a_diverging_stage_with_one_line(tmp_path):
    stage = tmp_path / "diverging.usda"
    stage.write_text(DIVERGING)
    result = graphflow("run", str(tick_graph(tmp_path, stage)))
    assert result.returncode == 1
    failure, summary = result.stderr.strip().splitlines()     # the line naming the body, then the run's summary
    assert failure == (f"{tmp_path / 'graph.json'}: run-time failure: /Ball: pose or velocity is not finite after physics step 1 "
                       "(t = 0.01667 s): the simulation diverged")
    assert summary.startswith("graphflow: FAIL ")


def test_stage_and_run_name_what_the_world_cannot_hold_one_line_each(tmp_path):
    if not HUMANOID.is_file():
        pytest.skip(f"{HUMANOID} is not available")
    stage = graphflow("stage", str(HUMANOID))
    assert stage.returncode == 0
    assert "  /nv_humanoid/joints/left_thigh: a d6 joint inside an articulation is not simulated" in \
        stage.stdout.splitlines()
    run = graphflow("run", str(tick_graph(tmp_path, HUMANOID)))
    assert run.returncode == 0
    warnings = [line for line in run.stderr.splitlines() if line.startswith("warning: ")]
    assert "warning: /nv_humanoid/joints/left_thigh: a d6 joint inside an articulation is not simulated" in warnings
    others = [line for line in run.stderr.splitlines() if line.strip() and line not in warnings
              and not line.startswith("Warning: The rigid body")]     # usd-core's own notes
    assert len(others) == 1 and others[0].startswith("graphflow: done ")   # every other line is one warning
