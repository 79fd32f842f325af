"""A live run's trace and report, made when the page saves them, by running the graph again with the same input.

The live run records nothing per tick (recording cost it a fifth of its rate, and the records of an
hour-long keyboard session grow without end). A run is deterministic: the same graph, seed and input
timeline give a bit-identical trace, so the trace of ticks 1..N of a live run is the trace of a fresh
checked run, fed the browser's keys, pad and mouse as the scripted timelines they were delivered as, stepped N
ticks with the report's recorder. A live run that ended is replayed as ``graphflow run`` runs it (to
its own end, its checks judged by the checked run itself), so its report carries the same verdict.

The live run does not wait for its replay (``save_in_background``): the replay runs in a process of its
own, on the other core, while the live run goes on (in the live run's thread it paused the run ~0.5 s
for pick-and-place, the replay taking as long as the ticks so far).
"""
from __future__ import annotations

import contextlib
import threading
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Callable

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


def save_in_background(inputs: LiveInputs, what: str, path: Path, *, ticks: int, ended: bool,
                       done: Callable[[str | None], None]):
    """``save_replayed`` in a fresh process; ``done(None)`` once the file is written, ``done(reason)`` when it is not.

    Spawned, not forked: the studio's process has threads (the server's loop, live runs) and PyBullet
    clients that a fork would copy half-way. The graph goes over as its JSON (a loaded document holds
    read-only mappings, which do not pickle) and is checked again there. Returns the process, which
    the live run stops if it closes first.
    """
    import multiprocessing

    context = multiprocessing.get_context("spawn")
    receiving, sending = context.Pipe(duplex=False)
    document = inputs.document
    process = context.Process(target=_replay_in_child, daemon=True, name=f"graphflow-save-{path.name}",
                              args=(sending, document.to_json(), document.source, inputs.source, inputs.keys,
                                    inputs.pad, inputs.mouse, what, str(path), ticks, ended))
    process.start()
    sending.close()

    def wait() -> None:
        try:
            outcome = receiving.recv()
        except EOFError:   # the process ended without a word: stopped by the live run's close, or killed
            outcome = "the replay stopped before the file was written"
        process.join()
        done(outcome)

    threading.Thread(target=wait, name=f"graphflow-save-wait-{path.name}", daemon=True).start()
    return process


def _replay_in_child(sending, data: dict, document_source: str, source: str, keys, pad, mouse, what: str,
                     path: str, ticks: int, ended: bool) -> None:
    """The spawned process: rebuild the graph, replay, write; send None, or why not."""
    import signal

    from graphflow.document import parse_document
    from graphflow.errors import GraphflowError

    signal.signal(signal.SIGINT, signal.SIG_IGN)   # a Ctrl-C is the studio's to handle: it stops this process
    try:
        inputs = LiveInputs(parse_document(data, document_source), source, keys, pad, mouse)
        save_replayed(inputs, what, Path(path), ticks=ticks, ended=ended)
        sending.send(None)
    except GraphflowError as error:   # the stage went from disk since the run started, the folder is read-only...
        sending.send(str(error))
    except Exception as error:   # a bug: said to the page, as the live run's own failures are
        sending.send(f"internal error: {error!r}")
