"""Frames waiting for a slow page merge into one that says what both said; other messages keep their order."""
import asyncio

from graphflow.studio.frames import Outbox, merge_frames


def frame(tick, **fields):
    return {"type": "frame", "tick": tick, "playing": True, "outputs": {}, "computed": [], "grippers": {},
            "log": [], **fields}


def test_two_frames_merge_into_the_newer_state_with_the_changes_and_log_lines_of_both():
    older = frame(3, outputs={"a.x": 1.0, "b.y": 2.0}, computed=["b", "a"], grippers={"/g": {"status": "Open", "force": None}},
                  log=[[2, "a", "info", "one"]])
    newer = frame(5, outputs={"a.x": 4.0}, computed=["c"], grippers={"/g": {"status": "Closing"}}, log=[[5, "c", "info", "two"]],
                  playing=False)
    merged = merge_frames(older, newer)
    assert merged["tick"] == 5 and merged["playing"] is False
    assert merged["outputs"] == {"a.x": 4.0, "b.y": 2.0}
    assert merged["computed"] == ["a", "b", "c"]
    assert merged["grippers"] == {"/g": {"status": "Closing", "force": None}}
    assert merged["log"] == [[2, "a", "info", "one"], [5, "c", "info", "two"]]
    assert older["grippers"] == {"/g": {"status": "Open", "force": None}}   # the frames merged are left as they were


def test_a_socket_behind_gets_one_merged_frame_and_every_other_message_in_order():
    async def scenario():
        outbox = Outbox()
        for message in (frame(1, outputs={"a.x": 1}), frame(2, outputs={"b.y": 2}), {"type": "start"},
                        frame(0), {"type": "saved"}, frame(3, outputs={"a.x": 3}), frame(4)):
            outbox.put(message)
        assert len(outbox) == 5
        return [await outbox.take() for _ in range(5)]

    taken = asyncio.run(scenario())
    assert [(m["type"], m.get("tick")) for m in taken] == [("frame", 2), ("start", None), ("frame", 0), ("saved", None),
                                                            ("frame", 4)]
    assert taken[0]["outputs"] == {"a.x": 1, "b.y": 2} and taken[4]["outputs"] == {"a.x": 3}


def test_a_frame_sampled_now_says_what_the_trace_of_the_ticks_since_the_last_one_says():
    """The sampler reads the latest state only; the trace recorded tick by tick of the same run is the reference."""
    from graphflow.document import load_document
    from graphflow.observe.recorder import TraceRecorder
    from graphflow.observe.trace import sample_grippers
    from graphflow.runtime import Simulation
    from graphflow.studio.frames import FrameSampler

    from .conftest import GRAPHS

    simulation = Simulation(load_document(GRAPHS / "counter_branch_print.json"))
    records: list = []
    TraceRecorder(simulation, None, records=records)
    sampler = FrameSampler(simulation)
    state = dict(records[0]["outputs"])   # every output's value as the trace says, tick after tick
    try:
        for ticks in (1, 3, 5):
            before, start = dict(state), len(records)
            for _ in range(ticks):
                simulation.step()
            since = records[start:]
            for record in since:
                state.update(record.get("outputs", {}))
            sampled = sampler.frame(sample_grippers(simulation.world))
            assert sampled["outputs"] == {key: value for key, value in state.items() if before[key] != value}
            assert sampled["outputs"]   # the counter counts
            assert sampled["computed"] == sorted({name for record in since for name in record.get("computed", ())})
            assert sampled["computed"]
            assert sampled["log"] == [[record["tick"], line["node"], line["level"], line["message"]]
                                      for record in since for line in record.get("log", ())]
            assert sampled["log"]
    finally:
        simulation.close()
