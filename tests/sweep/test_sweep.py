"""graphflow sweep: episodes, records, summaries, resume, Ctrl-C, worker crashes, pool against Ray."""
import csv
import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest
from conftest import ROOT

from graphflow.sweep.definition import load_sweep
from graphflow.sweep.launchers import LocalPool
from graphflow.sweep.results import wilson_interval
from graphflow.sweep.session import run_sweep

COUNTER = ROOT / "graphs" / "counter_branch_print.json"
TUNED = ROOT / "graphs" / "ur10_pick_place_tuned.json"


def graphflow(*args, cwd=None, **options):
    return subprocess.run([sys.executable, "-m", "graphflow", *args], capture_output=True, text=True,
                          cwd=cwd, **options)


def write_sweep(folder: Path, **fields) -> Path:
    data = {"format": "graphflow-sweep", "formatVersion": [1, 0], "graph": str(COUNTER), **fields}
    path = folder / "sweep.json"
    path.write_text(json.dumps(data))
    return path


def records(folder: Path) -> list[dict]:
    return [json.loads(line) for line in (folder / "episodes.jsonl").read_text().splitlines()]


def comparable(rows: list[dict]) -> dict:
    """Records by key without the wall-clock time (the one field that may differ between runs)."""
    return {row["key"]: {k: v for k, v in row.items() if k != "wall"} for row in rows}


def test_counter_sweep_records_every_episode_with_its_parameters_and_metrics(tmp_path):
    """The counter graph stops after b ticks of 0.5 s: time to finish = b x 0.5 s (b >= 1).

    Its own check (it stops by itself by 2 s) is part of every episode's verdict: b = 5 finishes at 2.5 s and fails.
    """
    sweep = write_sweep(tmp_path, grid={"at_least_three.b": [1, 2, 5]}, seeds=2,
                        metrics=[{"name": "time_to_finish", "timeToFinish": {}}])
    result = graphflow("sweep", str(sweep), "--out", str(tmp_path / "out"), "-j", "2")
    assert result.returncode == 0, result.stderr
    rows = records(tmp_path / "out")
    assert sorted(r["key"] for r in rows) == ["p0-s0", "p0-s1", "p1-s0", "p1-s1", "p2-s0", "p2-s1"]
    for row in rows:
        b = row["parameters"]["at_least_three.b"]
        assert row["metrics"]["time_to_finish"] == pytest.approx(0.5 * b)
        assert row["finished"]
        if b < 5:
            assert row["passed"] and row["failures"] == []
        else:
            assert not row["passed"]
            assert row["failures"] == [f"{COUNTER}: check 1 'graph stops by itself by 2 s': measured stopped at "
                                       "t = 2.500 s; expected the graph stops by itself (StopRun) by t = 2 s"]
    with open(tmp_path / "out" / "episodes.csv", newline="") as stream:
        table = list(csv.DictReader(stream))
    assert len(table) == 6 and {float(r["time_to_finish"]) for r in table} == {0.5, 1.0, 2.5}
    summary = json.loads((tmp_path / "out" / "summary.json").read_text())
    assert [(s["parameters"]["at_least_three.b"], s["n"], s["passed"]) for s in summary] == [(1, 2, 2), (2, 2, 2), (5, 2, 0)]
    assert "4/6 episodes passed" in result.stdout


def test_a_metric_that_cannot_be_measured_fails_the_episode_and_says_why(tmp_path):
    sweep = write_sweep(tmp_path, grid={"at_least_three.b": [2, 50]}, ticks=10,
                        metrics=[{"name": "time_to_finish", "timeToFinish": {}}])
    assert graphflow("sweep", str(sweep), "--out", str(tmp_path / "out"), "-j", "1").returncode == 0
    by_b = {r["parameters"]["at_least_three.b"]: r for r in records(tmp_path / "out")}
    assert by_b[2]["passed"]
    assert not by_b[50]["passed"]
    assert by_b[50]["failures"][-1] == "metric time_to_finish: not measured (the graph did not finish within 5.000 s)"
    assert "'graph stops by itself by 2 s': measured still running" in by_b[50]["failures"][0]


def test_wilson_interval_matches_the_textbook_values():
    # 8 of 10: centre (0.8 + z^2/20) / (1 + z^2/10), half-width from the score formula
    low, high = wilson_interval(8, 10)
    assert (low, high) == pytest.approx((0.4902, 0.9433), abs=1e-4)
    assert wilson_interval(0, 20)[0] == 0.0 and wilson_interval(0, 20)[1] == pytest.approx(0.1611, abs=1e-4)
    assert wilson_interval(20, 20) == pytest.approx((0.8389, 1.0), abs=1e-4)


def test_grid_and_samples_combine_and_samples_are_seeded(tmp_path):
    sweep_path = write_sweep(tmp_path, grid={"at_least_three.b": [1, 2]},
                             samples={"count": 3, "seed": 4, "parameters": {"print_done.text": {"choice": ["x", "y", "z"]}}},
                             seeds={"start": 10, "count": 2})
    sweep = load_sweep(str(sweep_path))
    points = sweep.points()
    assert len(points) == 6 and len(sweep.episodes()) == 12
    assert [p["at_least_three.b"] for p in points] == [1, 1, 1, 2, 2, 2]
    assert [p["print_done.text"] for p in points[:3]] == [p["print_done.text"] for p in points[3:]]
    assert load_sweep(str(sweep_path)).points() == points
    assert sweep.seeds() == [10, 11]


@pytest.mark.parametrize("fields, message", [
    ({"grid": {"at_least_three.bb": [1]}}, "has no input 'bb'"),
    ({"grid": {"at_least_three.b": [1]}, "randomize": [{"set": "at_least_three.b", "uniform": [1, 2]}]},
     "at_least_three.b is both swept"),
    ({"grid": {"at_least_three": [1]}}, "grid"),
    ({"seeds": 0}, "seeds"),
    ({"metrics": [{"name": "err", "positionError": {"prim": "/World/Cube", "target": [0, 0, 0]}}]},
     "metrics/0 (err): positionError needs a graph with a stage"),
])
def test_bad_sweeps_exit_2_with_one_line(tmp_path, fields, message):
    sweep = write_sweep(tmp_path, **fields)
    result = graphflow("sweep", str(sweep), "--out", str(tmp_path / "out"))
    assert result.returncode == 2
    lines = result.stderr.splitlines()
    assert len(lines) == 1 and message in lines[0], lines
    assert not (tmp_path / "out").exists()


def test_a_folder_with_results_is_never_overwritten_without_force_or_resume(tmp_path):
    sweep = write_sweep(tmp_path, grid={"at_least_three.b": [1, 2]})
    out = tmp_path / "out"
    assert graphflow("sweep", str(sweep), "--out", str(out), "-j", "1").returncode == 0
    again = graphflow("sweep", str(sweep), "--out", str(out), "-j", "1")
    assert again.returncode == 2 and "already holds sweep results" in again.stderr
    write_sweep(tmp_path, grid={"at_least_three.b": [1, 3]})
    changed = graphflow("sweep", str(sweep), "--out", str(out), "--resume")
    assert changed.returncode == 2 and "different sweep or graph" in changed.stderr
    forced = graphflow("sweep", str(sweep), "--out", str(out), "--force", "-j", "1")
    assert forced.returncode == 0
    assert sorted(r["parameters"]["at_least_three.b"] for r in records(out)) == [1, 3]


def test_resume_runs_only_missing_episodes_and_drops_a_torn_line(tmp_path):
    sweep = write_sweep(tmp_path, grid={"at_least_three.b": [1, 2, 3, 4]})
    out = tmp_path / "out"
    assert graphflow("sweep", str(sweep), "--out", str(out), "-j", "1").returncode == 0
    lines = (out / "episodes.jsonl").read_text().splitlines(keepends=True)
    # as if interrupted: two episodes done, the third cut off mid-line
    (out / "episodes.jsonl").write_text("".join(lines[:2]) + lines[2][:25])
    resumed = graphflow("sweep", str(sweep), "--out", str(out), "--resume", "-j", "1")
    assert resumed.returncode == 0, resumed.stderr
    assert "2 already done, 2 to run" in resumed.stdout
    rows = records(out)
    assert sorted(r["key"] for r in rows) == ["p0-s0", "p1-s0", "p2-s0", "p3-s0"]
    assert rows[:2] == [json.loads(line) for line in lines[:2]]
    with open(out / "episodes.csv", newline="") as stream:
        assert len(list(csv.DictReader(stream))) == 4
    finished = graphflow("sweep", str(sweep), "--out", str(out), "--resume")
    assert finished.returncode == 0 and "4 already done, 0 to run" in finished.stdout
    assert len(records(out)) == 4


def _wait_for_records(path: Path, count: int, process) -> None:
    deadline = time.monotonic() + 60
    while time.monotonic() < deadline and process.poll() is None:
        if path.exists() and path.read_text().count("\n") >= count:
            return
        time.sleep(0.05)
    raise AssertionError(f"{path} never had {count} records")


def test_ctrl_c_keeps_finished_episodes_and_resume_finishes_the_rest(tmp_path):
    # three quick episodes, then one of 250000 ticks (seconds of work)
    sweep = write_sweep(tmp_path, grid={"at_least_three.b": [1, 2, 3, 250000]}, ticks=300000)
    out = tmp_path / "out"
    process = subprocess.Popen([sys.executable, "-m", "graphflow", "sweep", str(sweep), "--out", str(out), "-j", "1"],
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    _wait_for_records(out / "episodes.jsonl", 3, process)
    process.send_signal(signal.SIGINT)
    _stdout, stderr = process.communicate(timeout=60)
    assert process.returncode == 130   # Ctrl-C is 130 everywhere (run, test, sweep)
    assert "interrupted: 3 of 4 episodes kept" in stderr and "--resume" in stderr
    assert "Traceback" not in stderr
    assert [r["key"] for r in records(out)] == ["p0-s0", "p1-s0", "p2-s0"]
    resumed = graphflow("sweep", str(sweep), "--out", str(out), "--resume", "-j", "1")
    assert resumed.returncode == 0, resumed.stderr
    assert "3 already done, 1 to run" in resumed.stdout
    assert [r["key"] for r in records(out)] == ["p0-s0", "p1-s0", "p2-s0", "p3-s0"]


def test_a_worker_that_dies_fails_its_episode_and_the_sweep_goes_on(tmp_path):
    sweep = load_sweep(str(write_sweep(tmp_path, grid={"at_least_three.b": [100000000, 1, 2, 3, 4]}, ticks=200000000)))
    pool = LocalPool(sweep, jobs=2)
    results = []
    killed = False
    for record in pool.run(sweep.episodes()):
        results.append(record)
        if not killed:
            busy = next(w for w in pool.workers if w["episode"] is not None and w["episode"].index == 0)
            os.kill(busy["process"].pid, signal.SIGKILL)
            killed = True
    by_key = {r["key"]: r for r in results}
    assert sorted(by_key) == ["p0-s0", "p1-s0", "p2-s0", "p3-s0", "p4-s0"]
    assert by_key["p0-s0"]["failures"] == ["worker crashed (killed by SIGKILL)"] and not by_key["p0-s0"]["passed"]
    assert all(by_key[k]["passed"] for k in ("p1-s0", "p2-s0", "p3-s0", "p4-s0"))


@pytest.mark.slow
def test_randomized_ur10_episodes_are_the_same_on_one_or_two_workers_and_in_any_order(tmp_path):
    """Worker reuse (reset vs rebuild, episode order) never changes a record."""
    sweep_path = tmp_path / "ur10.json"
    sweep_path.write_text(json.dumps({
        "format": "graphflow-sweep", "formatVersion": [1, 0], "graph": str(TUNED),
        "set": {"gripper.disableGravity": False},
        "grid": {"gripper.forceLimit": [20, 160], "/World/Cube.physics:mass": [4]},
        "randomize": [{"pose": "/World/Cube", "offset": {"uniform": [[-0.01, -0.01, 0], [0.01, 0.01, 0]]},
                       "yawDegrees": {"uniform": [-10, 10]}}],
        "seeds": 2,
        "metrics": [{"name": "place_error", "positionError": {"prim": "/World/Cube", "target": [-0.4, 0.5, 0.025], "axes": "xy"}},
                    {"name": "peak_grip_force", "gripForce": {}}]}))
    one = tmp_path / "one"
    assert run_sweep(str(sweep_path), out=str(one), jobs=1, echo=lambda *a, **k: None) == 0
    two = tmp_path / "two"
    assert run_sweep(str(sweep_path), out=str(two), jobs=2, echo=lambda *a, **k: None) == 0
    assert comparable(records(one)) == comparable(records(two))
    by_key = comparable(records(one))
    # 4 kg (39 N of weight plus the arm's accelerations): 20 N breaks on the way, 160 N carries it
    assert by_key["p0-s0"]["metrics"]["place_error"] > 0.5 and by_key["p1-s0"]["metrics"]["place_error"] < 0.02
    assert by_key["p1-s0"]["metrics"]["peak_grip_force"] > 39.2
    assert any("Constraint is Broken" in w for w in by_key["p0-s0"]["warnings"]) or by_key["p0-s0"]["metrics"]["peak_grip_force"] > 20


def test_ray_refuses_cleanly_when_it_is_not_installed(tmp_path):
    sweep = write_sweep(tmp_path, grid={"at_least_three.b": [1]})
    code = "import sys; sys.modules['ray'] = None; from graphflow.cli import main; sys.exit(main())"
    result = subprocess.run([sys.executable, "-c", code, "sweep", str(sweep), "--out", str(tmp_path / "out"), "--ray"],
                            capture_output=True, text=True)
    assert result.returncode == 2
    assert result.stderr.strip() == "graphflow: error: --ray needs the 'ray' extra (Ray): pip install 'graphflow[ray]'"


@pytest.mark.slow
def test_ray_gives_the_same_records_as_the_pool(tmp_path):
    pytest.importorskip("ray")
    sweep = write_sweep(tmp_path, grid={"at_least_three.b": [1, 2, 3]}, seeds=2,
                        metrics=[{"name": "time_to_finish", "timeToFinish": {}}])
    assert run_sweep(str(sweep), out=str(tmp_path / "pool"), jobs=2, echo=lambda *a, **k: None) == 0
    assert run_sweep(str(sweep), out=str(tmp_path / "ray"), jobs=2, use_ray=True, echo=lambda *a, **k: None) == 0
    assert comparable(records(tmp_path / "pool")) == comparable(records(tmp_path / "ray"))


@pytest.mark.slow
def test_a_ray_actor_that_dies_fails_only_the_episode_it_was_running(tmp_path):
    """The long episode 0 runs with episode 1 queued behind it on the same actor: killing the actor fails
    episode 0 only; episode 1 runs again elsewhere and passes."""
    ray = pytest.importorskip("ray")
    from graphflow.sweep.launchers import RayPool

    sweep = load_sweep(str(write_sweep(tmp_path, grid={"at_least_three.b": [100000000, 1, 2, 3, 4]}, ticks=200000000)))
    pool = RayPool(sweep, 2, None)
    results = []
    for record in pool.run(sweep.episodes()):
        results.append(record)
        if len(results) == 1:
            busy = next(w for w in pool.actors if w["queue"] and w["queue"][0][1].index == 0)
            assert [episode.index for _reference, episode in busy["queue"]] == [0, 1]
            ray.kill(busy["actor"])
    by_key = {r["key"]: r for r in results}
    assert sorted(by_key) == ["p0-s0", "p1-s0", "p2-s0", "p3-s0", "p4-s0"]
    assert by_key["p0-s0"]["failures"][0].startswith("worker crashed (") and not by_key["p0-s0"]["passed"]
    assert all(by_key[k]["passed"] for k in ("p1-s0", "p2-s0", "p3-s0", "p4-s0"))


def test_plot_writes_a_success_map_and_refuses_without_matplotlib(tmp_path):
    pytest.importorskip("matplotlib")
    sweep = write_sweep(tmp_path, grid={"at_least_three.b": [1, 2], "print_done.text": ["a", "b"]})
    out = tmp_path / "out"
    assert graphflow("sweep", str(sweep), "--out", str(out), "-j", "1").returncode == 0
    picture = tmp_path / "map.png"
    result = graphflow("sweep", "plot", str(out), "-o", str(picture))
    assert result.returncode == 0, result.stderr
    assert picture.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    curve = graphflow("sweep", "plot", str(out), "-o", str(tmp_path / "curve.svg"), "--kind", "curve")
    assert curve.returncode == 0 and "<svg" in (tmp_path / "curve.svg").read_text()
    code = "import sys; sys.modules['matplotlib'] = None; from graphflow.cli import main; sys.exit(main())"
    bare = subprocess.run([sys.executable, "-c", code, "sweep", "plot", str(out), "-o", str(tmp_path / "x.png")],
                          capture_output=True, text=True)
    assert bare.returncode == 2
    assert bare.stderr.strip() == "graphflow: error: graphflow sweep plot needs the 'viz' extra (matplotlib and Pillow): pip install 'graphflow[viz]'"


@pytest.mark.slow
def test_a_soft_underdamped_hold_rings_and_a_stiff_one_does_not(tmp_path):
    """The tutorial's second experiment in two episodes of the shipped sweep's graph: kp 100, kd 1 against kp 1e5, kd 1e4."""
    from graphflow.sweep.episode import EpisodeRunner

    sweep = load_sweep(str(ROOT / "sweeps" / "hold_stiffness_damping.json"))
    runner = EpisodeRunner(sweep)
    try:
        by_gains = {}
        for episode in sweep.episodes():
            gains = (episode.parameters["gripper.kp"], episode.parameters["gripper.kd"])
            if gains in ((100, 1), (100000, 10000)):
                by_gains[gains] = runner.run(episode)["metrics"]
    finally:
        runner.close()
    soft, stiff = by_gains[(100, 1)], by_gains[(100000, 10000)]
    assert soft["hold_jitter"] > 0.1          # m/s: the 1 kg cube bounces on a 100 N/m spring
    assert stiff["hold_jitter"] < 0.001
    assert soft["peak_grip_force"] > 5 * stiff["peak_grip_force"]
    assert stiff["place_error"] < 0.005


def test_the_replay_command_runs_the_episode_alone(tmp_path):
    sweep = write_sweep(tmp_path, grid={"at_least_three.b": [2]}, seeds={"start": 5, "count": 1},
                        randomize=[{"set": "print_done.text", "choice": ["one", "two", "three"]}])
    out = tmp_path / "out"
    assert graphflow("sweep", str(sweep), "--out", str(out), "-j", "1").returncode == 0
    record = records(out)[0]
    command = record["replay"].split()
    assert command[:2] == ["graphflow", "run"] and "--seed" in command and "5" in command
    alone = graphflow(*command[1:])
    assert alone.returncode == 0, alone.stderr
    assert alone.stdout.splitlines() == ["count = 1", record["randomized"]["print_done.text"]]


@pytest.mark.slow
def test_an_episode_in_a_busy_worker_equals_its_replay_in_a_fresh_run():
    """Session-layer reuse in a worker gives exactly the world `graphflow run --set ... --randomize --seed` builds."""
    import math

    from graphflow.document import load_document
    from graphflow.runtime import Simulation
    from graphflow.sweep.episode import EpisodeRunner
    from graphflow.variants.randomize import variant_for_run

    sweep = load_sweep(str(ROOT / "sweeps" / "force_limit_mass.json"))
    episodes = sweep.episodes()
    runner = EpisodeRunner(sweep)
    try:
        runner.run(episodes[17])
        record = runner.run(episodes[8])
    finally:
        runner.close()
    command = sweep.replay_command(episodes[8])
    sets = [command[i + 1] for i, word in enumerate(command) if word == "--set"]
    scenario = variant_for_run(load_document(sweep.graph_source), sets, sweep.source, episodes[8].seed)
    with Simulation(scenario.document, world=scenario.create_world()) as simulation:
        result = simulation.run(seconds=sweep.limits()["seconds"])
        position = simulation.world.prim_pose("/World/Cube")[0]
    assert result.ticks == record["ticks"]
    # the metric's own formula (math.dist rounds differently in the last bit)
    assert math.sqrt((position[0] + 0.4) ** 2 + (position[1] - 0.5) ** 2) == record["metrics"]["place_error"]
