"""A live run's trace and report, made when the page saves them, by running the graph again with the same input.

The live run records nothing per tick (recording cost it a fifth of its rate, and the records of an
hour-long keyboard session grow without end). A run is deterministic: the same graph, seed and input
timeline give a bit-identical trace, so the trace of ticks 1..N of a live run is the trace of a fresh
checked run, fed the browser's keys and pad as the scripted timelines they were delivered as, stepped N
ticks with the report's recorder. A live run that ended is replayed as ``graphflow run`` runs it (to
its own end, its checks judged by the checked run itself), so its report carries the same verdict.
"""
from __future__ import annotations

import contextlib
from dataclasses import dataclass, replace
from pathlib import Path

from graphflow.document import GraphDocument


@contextlib.contextmanager
def generators_kept():
    """The replay seeds the global generators as every run does; the live run it interrupts keeps its own draws."""
    import random
    import sys

    python = random.getstate()
    numpy_random = sys.modules.get("numpy.random")
    numpy_state = numpy_random.get_state() if numpy_random is not None else None
    try:
        yield
    finally:
        random.setstate(python)
        if numpy_random is not None:
            numpy_random.set_state(numpy_state)


@dataclass(frozen=True)
class LiveInputs:
    """What a live run was fed: the graph as loaded, and the browser's key, pad and mouse timelines so far."""

    document: GraphDocument
    source: str
    keys: object   # graphflow.inputs.keyboard.ScriptedKeys
    pad: object    # graphflow.inputs.gamepad.ScriptedPad
    mouse: object = None   # graphflow.inputs.mouse.ScriptedMouse


def save_replayed(inputs: LiveInputs, what: str, path: Path, *, ticks: int, ended: bool) -> None:
    """Write the trace (``saveTrace``, .jsonl) or the report (``saveReport``, .html) of the live run's *ticks* ticks."""
    from graphflow.files import write_text
    from graphflow.observe.trace import dumps_record
    from graphflow.report.recording import ReportRecording, runtime_failure
    from graphflow.verdicts.checked_run import CheckedRun, ScriptedInputs

    document = inputs.document
    scripted = replace(ScriptedInputs.of_document(document), keys=inputs.keys, pad=inputs.pad, mouse=inputs.mouse)
    checked = CheckedRun(document, source=inputs.source, inputs=scripted)
    with contextlib.ExitStack() as closing:
        closing.enter_context(generators_kept())
        closing.callback(checked.close)
        checked.preflight()
        simulation = checked.start()
        recording = ReportRecording(simulation, inputs.source)
        if ended:
            checked.run()
        else:
            for _ in range(ticks):
                simulation.step()
    if what == "saveTrace":
        write_text(path, "".join(dumps_record(record) + "\n" for record in recording.records), force=True)
    else:
        recording.write(path, document, evaluator=checked.evaluator if ended else None,
                        runtime_failure=runtime_failure(checked) if ended else None, seed=checked.seed, force=True)
