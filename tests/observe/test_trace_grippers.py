"""Issue 26: the trace's gripper list is the grippers the graph uses (docs/trace.md).

A packaged gripper on the stage that no node and no check names is left out, header and ticks; a
LegacySurfaceGripper node's own gripper is in the header from the start, at the path it then authors.
"""
import json
import math

from conftest import ROOT

from graphflow import cli

PACKAGED = "/World/ur10/ee_link/SurfaceGripper"        # on ur10_pick_place_tuned.usda, unused by the tuned graph
LEGACY_OWN = "/World/ur10/ee_link/SurfaceGripper_01"    # the next free path under the end effector


def trace_of(tmp_path, graph, *options) -> list[dict]:
    trace = tmp_path / "run.jsonl"
    assert cli.main(["run", str(ROOT / "graphs" / graph), "--trace", str(trace), *options]) in (0, 1)
    return [json.loads(line) for line in trace.read_text(encoding="utf-8").splitlines()]


def test_the_tuned_graph_lists_its_legacy_gripper_and_not_the_packaged_one(tmp_path, capsys):
    header, *ticks = trace_of(tmp_path, "ur10_pick_place_tuned.json", "--seconds", "9")
    assert header["grippers"] == [LEGACY_OWN]
    in_ticks = {path for record in ticks for path in record.get("grippers", {})}
    assert in_ticks == {LEGACY_OWN}                   # the one the node authored is the one announced
    statuses = [record["grippers"][LEGACY_OWN].get("status") for record in ticks
                if "status" in record.get("grippers", {}).get(LEGACY_OWN, {})]
    assert "Closed" in statuses                       # and it is the gripper that picks the cube up by 9 s


def test_a_graph_that_names_the_packaged_gripper_still_lists_it(tmp_path, capsys):
    header, *_ticks = trace_of(tmp_path, "ur10_pick_place.json", "--ticks", "2")
    assert header["grippers"] == [PACKAGED]


def test_the_traced_force_is_the_holds_force_read_afresh_on_every_held_tick():
    """The sampled force reuses what the gripper's own limit check read on that physics step (a run report samples
    every tick); it is, to the last bit, the force the world reports for the hold when asked directly."""
    from graphflow.document import load_document
    from graphflow.observe.trace import sample_grippers, surface_gripper_manager
    from graphflow.runtime import Simulation

    simulation = Simulation(load_document(ROOT / "graphs" / "ur10_pick_place.json"))
    world, held = simulation.world, 0
    try:
        for _ in range(700):
            simulation.step()
            sample = sample_grippers(world).get(PACKAGED)
            if sample is None or not sample.gripped:
                continue
            component = surface_gripper_manager(world).component(PACKAGED)
            direct = [math.sqrt(sum(c * c for c in world.attachments.force_on_gripper(handle, True)))
                      for handle in component.handles.values()]
            assert sample.force == max(direct)
            held += 1
    finally:
        simulation.close()
    assert held > 100      # the cube is held from about tick 450 on
