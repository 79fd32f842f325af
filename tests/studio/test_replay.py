"""Saving a live run replays it in a fresh world (in a process of its own); the live run draws the same random numbers as if it had not."""
import random

from graphflow.document import load_document
from graphflow.inputs.gamepad import ScriptedPad
from graphflow.inputs.keyboard import ScriptedKeys
from graphflow.observe.trace import read_trace
from graphflow.studio.replay import LiveInputs, save_replayed

from .conftest import GRAPHS


def test_a_save_between_two_draws_leaves_the_live_runs_random_sequence_alone(tmp_path):
    random.seed(11)
    expected = [random.random() for _ in range(3)]
    random.seed(11)
    drawn = [random.random()]
    inputs = LiveInputs(load_document(GRAPHS / "counter_branch_print.json"), "counter.json", ScriptedKeys([]), ScriptedPad([]))
    save_replayed(inputs, "saveTrace", tmp_path / "part.jsonl", ticks=2, ended=False)   # the replay seeds the generators
    drawn += [random.random(), random.random()]
    assert drawn == expected
    trace = read_trace(tmp_path / "part.jsonl")
    assert [record["tick"] for record in trace.ticks] == [1, 2]


def test_a_save_that_cannot_be_written_says_why(tmp_path):
    """The background replay's failure comes back as a reason (the page shows it), not as a dead process."""
    import threading

    from graphflow.studio.replay import save_in_background

    outcome, finished = [], threading.Event()
    inputs = LiveInputs(load_document(GRAPHS / "counter_branch_print.json"), "counter.json", ScriptedKeys([]), ScriptedPad([]))
    save_in_background(inputs, "saveTrace", tmp_path / "no such folder" / "part.jsonl", ticks=2, ended=False,
                       done=lambda failure: (outcome.append(failure), finished.set()))
    assert finished.wait(timeout=120)
    assert outcome[0] and "part.jsonl" in outcome[0], outcome
    finished.clear()
    save_in_background(inputs, "saveTrace", tmp_path / "part.jsonl", ticks=2, ended=False,
                       done=lambda failure: (outcome.append(failure), finished.set()))
    assert finished.wait(timeout=120)
    assert outcome[1] is None
    assert [record["tick"] for record in read_trace(tmp_path / "part.jsonl").ticks] == [1, 2]
