"""The trace's scene section (version 2): shapes, poses, computed nodes and rays, checked against the stage's facts."""
import json
import math

from graphflow.observe.trace import read_trace

CUBE = "/World/Cube"
CUBE_HALF = 0.0515 / 2      # the stage's cube: 5.15 cm a side (NVIDIA's pick-and-place demo)


def test_header_describes_the_cube_as_the_stage_builds_it(pick_place_run):
    scene = read_trace(pick_place_run["trace"]).header["scene"]
    cube = next(body for body in scene["bodies"] if body["path"] == CUBE)
    assert cube["kind"] == "dynamic"
    (shape,) = cube["shapes"]
    assert shape["kind"] == "box"
    assert shape["halfExtents"] == [CUBE_HALF] * 3 or all(math.isclose(h, CUBE_HALF, rel_tol=1e-6)
                                                          for h in shape["halfExtents"])
    assert scene["upAxis"] == "Z"
    assert any("/World/ur10" in link for link in scene["links"])   # the robot's links are named as such


def test_cube_poses_follow_the_pick_and_place(pick_place_run):
    """The cube starts resting at (0.3, 0.3) and ends where the graph places it, (0.7, 0.7), resting on its face."""
    trace = read_trace(pick_place_run["trace"])
    start = next(b for b in trace.header["scene"]["bodies"] if b["path"] == CUBE)["pose"]
    last = [record["poses"][CUBE] for record in trace.ticks if CUBE in record.get("poses", {})][-1]
    assert math.dist(start[:3], (0.3, 0.3, CUBE_HALF)) < 1e-3
    assert math.dist(last[:3], (0.7, 0.7, CUBE_HALF)) < 5e-3
    assert math.isclose(math.sqrt(sum(q * q for q in last[3:])), 1.0, rel_tol=1e-9)   # a unit quaternion


def test_poses_are_sampled_at_the_rate_the_header_names(pick_place_run):
    trace = read_trace(pick_place_run["trace"])
    every = trace.header["scene"]["poseEvery"]
    sampled = [record["tick"] for record in trace.ticks if "poses" in record]
    assert every >= 1 and sampled and all(tick % every == 0 for tick in sampled)


def test_computed_lists_the_nodes_that_ran(pick_place_run):
    """OnTick computes every tick; the pure ReadPrimPose computes only when the controller pulls it."""
    trace = read_trace(pick_place_run["trace"])
    assert all("on_tick" in record["computed"] for record in trace.ticks)
    nodes = list(trace.header["nodes"])
    for record in trace.ticks:
        assert record["computed"] == sorted(record["computed"], key=nodes.index)   # document order


def test_a_missed_close_records_the_ray_and_the_cube_beyond_its_reach(pick_misses_run):
    """pick_misses' tip stops 23.5 mm above the cube (its description) with a 9 mm reach: the ray says so."""
    trace = read_trace(pick_misses_run["trace"])
    closes = [(record["tick"], record["rays"]) for record in trace.ticks if "rays" in record]
    assert len(closes) == 1
    tick, rays = closes[0]
    (close,) = rays.values()
    (ray,) = close["rays"]
    assert math.isclose(ray["reach"], 0.009, abs_tol=1e-6)
    assert ray["hit"]["prim"] == CUBE
    assert abs(ray["hit"]["distance"] - 0.0235) < 0.5e-3
    assert ray["direction"][2] < -0.999                      # straight down
    cube_top = CUBE_HALF * 2
    assert abs(ray["origin"][2] - ray["hit"]["distance"] - cube_top) < 1e-3   # the hit is on the cube's top face
    status = [record["grippers"][path]["status"] for record in trace.ticks if record["tick"] == tick
              for path in record.get("grippers", {}) if "status" in record["grippers"][path]]
    assert status == ["Closing"]


def test_old_version_1_traces_are_still_read(tmp_path):
    old = tmp_path / "old.jsonl"
    header = {"format": "graphflow-trace", "version": 1, "graph": "g.json", "description": "", "stage": None,
              "timeStep": 0.5, "nodes": {}, "outputs": {}, "phases": [], "grippers": [], "versions": {}}
    old.write_text(json.dumps(header) + "\n" + json.dumps({"tick": 1, "t": 0.5}) + "\n")
    trace = read_trace(old)
    assert trace.header["version"] == 1 and [r["tick"] for r in trace.ticks] == [1]
