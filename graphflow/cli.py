"""The ``graphflow`` command.

Exit codes: 0 success; 1 run-time failure (a node failed, a runaway loop);
2 bad input or usage (malformed graph, unknown node type, bad stage, bad
arguments). Errors are one line each on stderr, without a traceback unless
``--log-level debug`` is given.
"""
from __future__ import annotations

import argparse
import contextlib
import json
import logging
import math
import re
import signal
import sys
import threading
import time
import warnings
from pathlib import Path

from . import __version__
from .compiler import MAX_DURATION
from .document import GraphError, load_document, parse_document, save_document
from .executor import GraphRuntimeError, LogEvent
from .files import FileProblem, atomic_output, refuse_existing
from .gamepad import PadSpecError, attach_gamepad, scripted_pad
from .keyboard import KeySpecError, attach_keyboard, scripted_keys
from .registry import default_registry
from .seeding import seed_everything

EXIT_OK, EXIT_RUNTIME, EXIT_BAD_INPUT = 0, 1, 2
EXIT_INTERRUPTED = 130   # 128 + SIGINT, as shells report a Ctrl-C
MAX_SECONDS = MAX_DURATION   # simulated seconds: longer limits are typos (1e308, inf), not runs
EXIT_TRACES_DIFFER = 1   # graphflow trace diff, like diff(1)
PROGRESS_AFTER_SECONDS = 2.0


class BadInput(Exception):
    """Reported as one line with exit code 2."""


class _PrintedLog:
    """Run listener: the graph's log lines, info on stdout, warnings and errors on stderr."""

    @staticmethod
    def on_log(event: LogEvent) -> None:
        if event.level in ("warning", "warn", "error"):
            print(f"{event.level.upper()}: {event.node}: {event.message}", file=sys.stderr)
        else:
            print(event.message, flush=True)


class _Progress:
    """Run listener: a status line on a terminal for runs longer than a few seconds; silent otherwise."""

    def __init__(self, simulation, enabled: bool, limit: int | None = None):
        self.simulation = simulation
        self.enabled = enabled
        self.limit = limit
        self.started = time.perf_counter()
        self.last_shown = 0.0
        self.shown = False
        # the first node with an eventName output (a controller) names the current phase
        self.phase_node = next((node.name for node in simulation.compiled.nodes
                                if node.spec.attribute("outputs:eventName") is not None), None)

    def on_tick(self, _simulation, count: int) -> None:
        if not self.enabled or count % 32:
            return
        now = time.perf_counter()
        elapsed = now - self.started
        if elapsed < PROGRESS_AFTER_SECONDS or now - self.last_shown < 0.25:
            return
        self.last_shown = now
        sys.stderr.write("\r" + self.status(count, self.limit, elapsed))
        sys.stderr.flush()
        self.shown = True

    def status(self, count: int, limit: int | None, elapsed: float) -> str:
        """The status line: simulated time, tick, ticks per wall second and the controller's phase if any."""
        total = f"/{limit}" if limit else ""
        line = f"  t = {self.simulation.world.time:8.3f} s   tick {count}{total}   {count / elapsed:7.0f} ticks/s "
        if self.phase_node is not None:
            line += f"  phase {self.simulation.instance.output(self.phase_node, 'eventName') or '-':<20}"
        return line

    def on_end(self, _simulation, _result) -> None:
        """End the status line (also when the run failed or was interrupted)."""
        if self.shown:
            sys.stderr.write("\n")


class _RealTimePacer:
    """Run listener holding a --gui run to the pace of simulated time (times --speed), so people can watch it.

    Only the display is paced: the simulation never reads the wall clock, so a paced run
    computes exactly what a headless run does.
    """

    def __init__(self, speed: float):
        self.speed = speed
        self.started = time.perf_counter()

    def on_tick(self, simulation, _tick: int) -> None:
        ahead = simulation.world.time / self.speed - (time.perf_counter() - self.started)
        if ahead > 0:
            time.sleep(ahead)


def _load(path: str):
    try:
        return load_document(path)
    except GraphError as error:
        raise BadInput(str(error)) from None


def command_run(args) -> int:
    from .checks import CheckEvaluator
    from .runtime import Simulation
    from .scenario import ScenarioResult, run_seconds, scripted_inputs

    document = _load(args.graph)
    seed = args.seed if args.seed is not None else int(document.scenario.get("seed", 0))
    seed_everything(seed)
    if args.record:
        _check_recording(args, document)
    if args.trace:
        _refuse_existing(args.trace, args.force)
    try:
        keys = scripted_keys(args.keys, args.key)
        pad = scripted_pad(args.gamepad, args.pad)
        if not args.gui and keys is None and pad is None:   # the graph's own scripted inputs (its scenario)
            keys, pad = scripted_inputs(document)
        topics = _ros2_run().check_options(args.topics, args.topic, args.record_topics)
    except (KeySpecError, PadSpecError, *_ros2_run().RunOptionError) as error:
        raise BadInput(str(error)) from None
    if args.gui:
        from .physics.native_output import route_native_stdout_to_stderr

        route_native_stdout_to_stderr()
    from .usd.errors import StageError

    try:
        from .randomize import scenario_for_run

        scenario = scenario_for_run(document, args.set, args.randomize, seed)
        document = scenario.document
        simulation = Simulation(document, world=scenario.create_world(gui=args.gui), listeners=[_PrintedLog()])
    except StageError as error:
        from .preflight import stage_error_problems

        raise BadInput("\n".join(str(p) for p in stage_error_problems(args.graph, error))) from None
    except (ValueError, OSError) as error:
        raise BadInput(f"{args.graph}: {error}") from None
    changed = _scenario_changes(args)
    evaluator = CheckEvaluator(document if args.checks or not changed else None)
    seconds = run_seconds(document, evaluator, args.ticks, args.seconds)
    verdict = ScenarioResult(args.graph, len(evaluator))
    # outputs are written to temporary files renamed into place when the run ends (a failed run keeps
    # the ticks before the failure); a Ctrl-C or a broken start removes them: never half-written
    with contextlib.ExitStack() as outputs:
        outputs.callback(simulation.close)
        if keys is not None:
            attach_keyboard(simulation.world, keys)
        if pad is not None:
            attach_gamepad(simulation.world, pad)
        topic_recording = _ros2_run().attach_topics(simulation.world, topics, args.record_topics)
        if topic_recording is not None:
            outputs.push(lambda kind, _error, _trace: topic_recording.abandon() if kind is not None
                         else topic_recording.close())
        simulation.add_listener(evaluator)
        if args.trace:
            _open_trace(args.trace, simulation, args.graph, outputs, args.force)
        if args.record:
            simulation.world.services.add(_start_recording(args, simulation.world, outputs))
        if args.gui and args.speed > 0:
            simulation.add_listener(_RealTimePacer(args.speed))
        simulation.add_listener(_Progress(simulation, sys.stdout.isatty(),
                                          simulation.tick_limit(ticks=args.ticks, seconds=seconds)))
        started = time.perf_counter()
        try:
            result = simulation.run(ticks=args.ticks, seconds=seconds)
            verdict.failures.extend(str(failure) for failure in evaluator.finish(simulation, result))
            verdict.ticks, verdict.time = result.ticks, result.time
        except GraphRuntimeError as error:
            if args.log_level == "debug" or isinstance(error.__cause__, BrokenPipeError):
                raise   # main() shows the traceback / ends quietly when the reader of our output has gone
            result = None
            verdict.failures.append(f"graphflow: run-time error: {error}")
            verdict.ticks, verdict.time = simulation.instance.tick_count, simulation.world.time
    for line in verdict.failures:
        print(line, file=sys.stderr)
    summary = verdict.summary()
    if document.checks and not len(evaluator) and not verdict.failures:
        summary = (f"done {args.graph}: checks not evaluated, {', '.join(changed)} changed the run "
                   f"(--checks evaluates them) {summary[summary.rindex('('):]}")
    print(f"graphflow: {summary}", file=sys.stderr)
    if verdict.failures:
        return EXIT_RUNTIME
    wall = time.perf_counter() - started
    reason = "graph finished" if result.stopped_by_graph else "limit reached"
    logging.getLogger("graphflow").info("%s: %d ticks, %.3f s simulated in %.2f s wall (%s)",
                                        args.graph, result.ticks, result.time, wall, reason)
    return EXIT_OK


def _ros2_run():
    """graphflow.ros2.run, imported when a run is set up (not for the other commands)."""
    from .ros2 import run

    return run


def _scenario_changes(args) -> list[str]:
    """The options that make this run differ from the graph's scenario, so its checks do not apply."""
    options = {"--ticks": args.ticks is not None, "--seconds": args.seconds is not None, "--keys": args.keys is not None,
               "--key": bool(args.key), "--gamepad": args.gamepad is not None, "--pad": bool(args.pad),
               "--gui": args.gui}
    return [name for name, given in options.items() if given]


def _check_recording(args, document) -> None:
    """Refuse a recording that cannot be made before the run starts, not after it ends."""
    if document.settings.get("stage") is None:
        raise BadInput(f"{args.graph}: --record needs a graph with a stage (settings.stage); this one has no scene")
    from .physics.recorder import RecordingError, check_encoder, video_kind
    from .preflight import require_viz

    try:
        kind = video_kind(args.record)
        require_viz(f"--record {args.record}", "PIL")
        check_encoder(args.record)
    except RecordingError as error:
        raise BadInput(str(error)) from None
    _refuse_existing(args.record, args.force, folder=kind == "frames")


def _refuse_existing(path: str, force: bool, folder: bool = False) -> None:
    try:
        refuse_existing(path, force, folder=folder)
    except FileProblem as error:
        raise BadInput(str(error)) from None


def _start_recording(args, world, outputs: contextlib.ExitStack):
    from .physics.recorder import Camera, RecordingError, VideoRecorder, video_kind

    camera = Camera(args.camera_target, args.camera_distance, args.camera_yaw, args.camera_pitch)
    folder = video_kind(args.record) == "frames"
    try:
        temporary = outputs.enter_context(atomic_output(args.record, force=args.force, folder=folder))
        video = VideoRecorder(world, args.record, fps=args.fps, size=args.size, camera=camera, write_to=temporary)
    except RecordingError as error:
        raise BadInput(str(error)) from None
    except OSError as error:
        raise BadInput(f"{args.record}: cannot write the video: {error.strerror or error}") from None
    outputs.callback(video.close)   # runs before the rename into place (ExitStack unwinds last in, first out)
    return video


def _size(text: str) -> tuple[int, int]:
    width, _, height = text.lower().partition("x")
    if not (width.isdigit() and height.isdigit()) or int(width) < 16 or int(height) < 16:
        raise argparse.ArgumentTypeError(f"expected WIDTHxHEIGHT in pixels, at least 16x16, got {text}")
    return int(width), int(height)


def _point(text: str) -> tuple[float, float, float]:
    try:
        values = tuple(float(v) for v in text.split(","))
    except ValueError:
        values = ()
    if len(values) != 3:
        raise argparse.ArgumentTypeError(f"expected X,Y,Z in metres, got {text}")
    return values


def _open_trace(path: str, simulation, graph: str, outputs: contextlib.ExitStack, force: bool):
    from .trace import TraceRecorder

    try:
        temporary = outputs.enter_context(atomic_output(path, force=force))
        stream = outputs.enter_context(open(temporary, "w", encoding="utf-8", newline="\n"))
    except OSError as error:
        raise BadInput(f"{path}: cannot write the trace: {error.strerror}") from None
    TraceRecorder(simulation, stream, graph=graph)
    return stream


def command_trace_diff(args) -> int:
    from .trace import TraceError, first_difference, read_trace

    try:
        left, right = read_trace(args.left), read_trace(args.right)
    except TraceError as error:
        raise BadInput(str(error)) from None
    difference = first_difference(left, right)
    if difference is None:
        print(f"traces are identical ({len(left.ticks)} ticks)")
        return EXIT_OK
    print(difference.describe(args.left, args.right))
    return EXIT_TRACES_DIFFER


def command_draw(args) -> int:
    from . import draw

    document = _load(args.graph)
    try:
        picture_format = draw.format_for(args.output, args.format)
    except ValueError as error:
        raise BadInput(str(error)) from None
    if picture_format == "png":
        from .preflight import require_viz

        require_viz("draw --format png", "matplotlib")
    try:
        with atomic_output(args.output, force=args.force) as temporary:
            draw.write(draw.layout(document), temporary, picture_format)
    except OSError as error:
        raise BadInput(f"{args.output}: cannot write the picture: {error.strerror or error}") from None
    print(f"wrote {args.output}")
    return EXIT_OK


def command_plot(args) -> int:
    from .preflight import require_viz

    require_viz("plot", "matplotlib")
    from .plot import write_timeline
    from .trace import TraceError, read_trace

    try:
        trace = read_trace(args.trace)
    except TraceError as error:
        raise BadInput(str(error)) from None
    _refuse_existing(args.output, args.force)
    try:
        with atomic_output(args.output, force=args.force) as temporary:
            drawn = write_timeline(trace, temporary)
    except FileProblem:
        raise
    except (OSError, ValueError) as error:
        raise BadInput(f"{args.output}: cannot write the plot: {error}") from None
    for note in drawn.notes:
        print(f"note: {note}")
    print(f"wrote {args.output}")
    return EXIT_OK


def command_test(args) -> int:
    from .suite import NoScenarios, command_test as run_tests

    try:
        return run_tests(args)
    except (NoScenarios, FileExistsError) as error:
        raise BadInput(str(error)) from None


def command_validate(args) -> int:
    from .deep_validate import deep_validate
    from .preflight import file_problems

    failed = False
    for path in args.graphs:
        problems, warnings_ = file_problems(path), []
        if not problems:   # the graph and its stage load: check what the graph names on that stage
            problems, warnings_ = deep_validate(load_document(path), allow_missing_assets=args.allow_missing_assets)
        for problem in warnings_:
            print(f"warning: {problem}", file=sys.stderr)
        for problem in problems:
            print(problem, file=sys.stderr)
        if not problems:
            print(f"{path}: ok")
        failed = failed or bool(problems)
    return EXIT_BAD_INPUT if failed else EXIT_OK


def command_nodes(args) -> int:
    if args.markdown or args.output:
        return _write_node_docs(args)
    types = default_registry().types()
    if args.json:
        print(json.dumps([t.spec.to_json() for t in types], indent=2))
        return EXIT_OK
    width = max(len(t.spec.id) for t in types)
    for node_type in types:
        summary = first_sentence(node_type.spec.description)
        print(f"{node_type.spec.id:<{width}}  v{node_type.spec.version}  {summary}")
    return EXIT_OK


def _write_node_docs(args) -> int:
    from .nodedocs import render_markdown, write_markdown

    if not args.markdown or args.json:
        raise BadInput("nodes: -o/--output writes the Markdown reference: use it with --markdown (and without --json)")
    if not args.output:
        sys.stdout.write(render_markdown())
        return EXIT_OK
    try:
        write_markdown(args.output, force=args.force)
    except FileExistsError as error:
        raise BadInput(str(error)) from None
    except OSError as error:
        raise BadInput(f"{args.output}: cannot write: {error.strerror or error}") from None
    print(f"wrote {args.output}")
    return EXIT_OK


_SENTENCE_END = re.compile(r"(?<!\be\.g)(?<!\bi\.e)(?<!\betc)(?<!\bvs)(?<!\.\.)[.!?](?=\s+[^\s.]|\s*$)")


def first_sentence(text: str) -> str:
    """The first sentence of a description, whole (never cut at "e.g." or "..."), without its final period."""
    match = _SENTENCE_END.search(text)
    sentence = text[:match.start() + 1] if match else text
    return " ".join(sentence.split()).rstrip(".")


STARTER_GRAPH = {
    "format": "graphflow",
    "formatVersion": [1, 0],
    "description": "Starter graph: counts ticks and prints every tick's count until 1 s of simulated time.",
    "settings": {"duration": 1.0, "evaluator": "execution", "timeStep": 0.1},
    "nodes": [
        {"name": "on_tick", "type": "omni.graph.action.OnTick"},
        {"name": "counter", "type": "omni.graph.action.Counter"},
        {"name": "format_count", "type": "graphflow.FormatText", "inputs": {"format": "tick {value}"}},
        {"name": "print", "type": "omni.graph.ui_nodes.PrintText"},
    ],
    "connections": [
        {"src": "on_tick.outputs:tick", "dst": "counter.inputs:execIn"},
        {"src": "counter.outputs:execOut", "dst": "print.inputs:execIn"},
        {"src": "counter.outputs:count", "dst": "format_count.inputs:value"},
        {"src": "format_count.outputs:text", "dst": "print.inputs:text"},
    ],
}


def command_new(args) -> int:
    target = Path(args.name if args.name.endswith(".json") else f"{args.name}.json")
    save_document(parse_document(json.loads(json.dumps(STARTER_GRAPH)), str(target)), target, force=args.force)
    print(f"wrote {target}")
    return EXIT_OK


def command_stage(args) -> int:
    from .cli_stage import run_stage_command

    return run_stage_command(args.stage, as_json=args.json, simulate_seconds=args.simulate)


def command_import(args) -> int:
    from .document import dumps
    from .usd.omnigraph import ImportProblem, import_graph

    if args.output:
        _refuse_existing(args.output, args.force)
    try:
        result = import_graph(args.stage, graph_path=args.graph, output_path=args.output, skip_unknown=args.skip_unknown)
    except ImportProblem as error:
        for line in error.problems:
            print(line, file=sys.stderr)
        return EXIT_BAD_INPUT
    except GraphError as error:
        for problem in error.problems:
            print(problem, file=sys.stderr)
        return EXIT_BAD_INPUT
    for warning in result.warnings:
        print(f"warning: {warning}", file=sys.stderr)
    if args.output:
        save_document(result.document, args.output, force=args.force)
        print(f"wrote {args.output}: {len(result.document.nodes)} nodes, {len(result.document.connections)} connections from {result.graph_path}")
    else:
        sys.stdout.write(dumps(result.document))
    return EXIT_OK


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="graphflow", description="Run, check and inspect graphflow action graphs.")
    parser.add_argument("--version", action="version", version=f"graphflow {__version__}")
    commands = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")

    run = commands.add_parser("run", help="run a graph (headless unless --gui)")
    run.add_argument("graph", help="graph JSON file")
    run.add_argument("--ticks", type=_positive_int, help="stop after N ticks")
    run.add_argument("--seconds", type=_seconds, help="stop after S simulated seconds")
    run.add_argument("--seed", type=int, help="seed for random number generators (default: the graph's scenario seed, else 0)")
    run.add_argument("--gui", action="store_true", help="open the PyBullet window (paced to real time, see --speed)")
    run.add_argument("--speed", type=_finite_float, default=1.0, metavar="X",
                     help="with --gui: run at X times real time (default 1; 0 = as fast as possible)")
    run.add_argument("--keys", metavar="FILE",
                     help='scripted keyboard for OnKeyboardInput nodes: JSON {"keys": ["A@1.5", "Up@2-3", ...]}')
    run.add_argument("--key", action="append", default=[], metavar="KEY@TIME",
                     help="scripted key (repeatable): A@1.5 tap, A@1.5:down, A@1.5:up, Up@1.0-2.5 held; "
                          "replaces the PyBullet window's keys")
    run.add_argument("--gamepad", metavar="FILE",
                     help='scripted gamepad for OnGamepadInput / ReadGamepadState nodes: JSON '
                          '{"gamepad": [{"element": "Right Stick Y Axis", "time": 1.0, "value": -1.0}, ...]}')
    run.add_argument("--pad", action="append", default=[], metavar="ELEMENT=VALUE@TIME",
                     help='scripted gamepad element (repeatable), held until changed: "Left Stick X Axis=0.5@1.0", '
                          '"Face Button Bottom=1@3"; "1:..." for pad 1')
    run.add_argument("--topics", metavar="FILE",
                     help='scripted ROS 2 topics for subscriber nodes: JSON {"topics": [{"topic": "/joint_command", '
                          '"time": 0.5, "type": "sensor_msgs/msg/JointState", "message": {...}}, ...]}')
    run.add_argument("--topic", action="append", default=[], metavar="TOPIC@TIME=JSON",
                     help='scripted ROS 2 message (repeatable): \'/cmd_vel@1.0={"linear": {"x": 0.5}}\'')
    run.add_argument("--record-topics", metavar="FILE.mcap",
                     help="write every message ROS 2 publisher nodes publish to an MCAP file (ROS 2 CDR encoding)")
    run.add_argument("--checks", action="store_true",
                     help="evaluate the graph's checks even when --ticks, --seconds, --key(s), --gamepad, --pad or --gui "
                          "change the run (by default they are evaluated only for the run as written)")
    run.add_argument("--set", action="append", default=[], metavar="TARGET=VALUE",
                     help="override (repeatable): NODE.INPUT=VALUE (a node input) or /Prim/Path.attribute=VALUE "
                          "(a stage attribute, in USD units); VALUE is JSON or a plain string (docs/sweeps.md)")
    run.add_argument("--randomize", metavar="FILE",
                     help="draw the randomize entries of FILE (a sweep file or {\"randomize\": [...]}) from --seed")
    run.add_argument("--log-level", default="warning", choices=["debug", "info", "warning", "error"],
                     help="Python logging level on stderr (default warning)")
    run.add_argument("--trace", metavar="FILE", help="write what happens every tick as JSON Lines (docs/trace.md)")
    run.add_argument("--record", metavar="FILE", help="record a video: .gif, .mp4 (needs ffmpeg) or a folder of PNG frames")
    run.add_argument("--fps", type=_positive_float, default=15.0, help="video frames per simulated second (default 15)")
    run.add_argument("--force", action="store_true", help="overwrite existing --trace / --record outputs")
    run.add_argument("--size", type=_size, default=(480, 360), metavar="WxH", help="video size in pixels (default 480x360)")
    run.add_argument("--camera-target", type=_point, metavar="X,Y,Z", help="point the camera looks at (default: the scene's centre)")
    run.add_argument("--camera-distance", type=_positive_float, metavar="M", help="camera distance (default: fit the scene)")
    run.add_argument("--camera-yaw", type=_finite_float, default=50.0, metavar="DEG", help="camera yaw in degrees (default 50)")
    run.add_argument("--camera-pitch", type=_finite_float, default=-30.0, metavar="DEG", help="camera pitch in degrees (default -30)")
    run.set_defaults(handler=command_run)

    trace = commands.add_parser("trace", help="work with run traces (graphflow run --trace)")
    trace_commands = trace.add_subparsers(dest="trace_command", required=True, metavar="TRACE_COMMAND")
    trace_diff = trace_commands.add_parser(
        "diff", help="print the first tick and field where two traces differ (exit 0 identical, 1 different)")
    trace_diff.add_argument("left", metavar="A", help="trace file")
    trace_diff.add_argument("right", metavar="B", help="trace file")
    trace_diff.set_defaults(handler=command_trace_diff)

    test = commands.add_parser("test", help="run every graph with checks under the paths; one line each, then 'N passed, M failed'")
    test.add_argument("paths", nargs="+", metavar="PATH", help="graph files or folders (searched recursively)")
    test.add_argument("-j", "--jobs", type=_positive_int, metavar="N", help="processes at once (default: as many as cores)")
    test.add_argument("--junit", metavar="FILE", help="write a JUnit XML report")
    test.add_argument("--traces", metavar="DIR", help="folder for failing scenarios' traces (default: a new temporary folder)")
    test.add_argument("--force", action="store_true", help="overwrite an existing --junit file")
    test.set_defaults(handler=command_test)

    validate = commands.add_parser(
        "validate", help="check graph files and the stages they name without running them; print every problem")
    validate.add_argument("graphs", nargs="+", metavar="GRAPH")
    validate.add_argument("--allow-missing-assets", action="store_true",
                          help="report inputs naming prims of layers the import could not open as warnings, not errors")
    validate.set_defaults(handler=command_validate)

    nodes = commands.add_parser("nodes", help="list the registered node types")
    nodes.add_argument("--json", action="store_true", help="print every node spec as JSON")
    nodes.add_argument("--markdown", action="store_true",
                       help="print the node reference page (docs/nodes.md) generated from the specs")
    nodes.add_argument("-o", "--output", metavar="FILE", help="with --markdown: write the page to FILE atomically")
    nodes.add_argument("--force", action="store_true", help="overwrite an existing --output file")
    nodes.set_defaults(handler=command_nodes)

    new = commands.add_parser("new", help="write a starter graph")
    new.add_argument("name", help="file name (.json is added if missing)")
    new.add_argument("--force", action="store_true", help="overwrite an existing file")
    new.set_defaults(handler=command_new)

    stage = commands.add_parser("stage", help="show what the importer makes of a USD stage")
    stage.add_argument("stage", help=".usda / .usd file")
    stage.add_argument("--json", action="store_true", help="print one JSON object")
    stage.add_argument("--simulate", type=_seconds, metavar="SECONDS",
                       help="step the stage with drives at their targets and report how far bodies moved")
    stage.set_defaults(handler=command_stage)

    convert = commands.add_parser("import", help="convert an Isaac Sim action graph in a USD file to a graph JSON")
    convert.add_argument("stage", help=".usda / .usd file holding an OmniGraph prim")
    convert.add_argument("-o", "--output", help="graph JSON to write (default: print to stdout)")
    convert.add_argument("--graph", help="prim path of the graph when the stage holds several")
    convert.add_argument("--skip-unknown", action="store_true",
                         help="drop nodes whose type graphflow does not have (and their connections) instead of failing")
    convert.add_argument("--force", action="store_true", help="overwrite an existing output file")
    convert.set_defaults(handler=command_import)

    draw = commands.add_parser("draw", help="draw a graph: nodes, exec and data edges, left to right in execution order")
    draw.add_argument("graph", help="graph JSON file")
    draw.add_argument("-o", "--output", required=True, metavar="FILE", help="picture file (.svg, .png, .mmd, .dot)")
    draw.add_argument("--format", choices=["svg", "png", "mermaid", "dot"], help="picture format (default: from the suffix)")
    draw.add_argument("--force", action="store_true", help="overwrite an existing picture")
    draw.set_defaults(handler=command_draw)

    plot = commands.add_parser("plot", help="plot a run trace: controller phase, gripper status, held height, force")
    plot.add_argument("trace", help="trace file written by graphflow run --trace")
    plot.add_argument("-o", "--output", required=True, metavar="FILE", help="image file (.png, .svg or .pdf)")
    plot.add_argument("--force", action="store_true", help="overwrite an existing image")
    plot.set_defaults(handler=command_plot)

    from .sweep import add_sweep_parser
    from .sweep_plot import plot_command

    add_sweep_parser(commands, plot_command)
    return parser


# argparse reports a type function's ArgumentTypeError as "argument --option: message"
def _positive_int(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        value = 0
    if value <= 0:
        raise argparse.ArgumentTypeError(f"expected a positive integer, got {text!r}")
    return value


def _finite_float(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not math.isfinite(value):
        raise argparse.ArgumentTypeError(f"expected a finite number, got {text!r}")
    return value


def _positive_float(text: str) -> float:
    value = _finite_float(text)
    if not value > 0:
        raise argparse.ArgumentTypeError(f"expected a positive number, got {text!r}")
    return value


def _seconds(text: str) -> float:
    value = _positive_float(text)
    if value > MAX_SECONDS:
        raise argparse.ArgumentTypeError(f"expected at most {MAX_SECONDS:g} simulated seconds, got {text!r}")
    return value


def _one_line_warning(message, category, filename, lineno, line=None) -> str:
    return f"warning: {message}\n"


def _interrupt(_signal_number, _frame):
    raise KeyboardInterrupt


def main(argv: list[str] | None = None) -> int:
    on_main_thread = threading.current_thread() is threading.main_thread()
    # `kill` cleans up like Ctrl-C: no half-written outputs
    previous_handler = signal.signal(signal.SIGTERM, _interrupt) if on_main_thread else None
    previous_format = warnings.formatwarning
    try:
        return _main(argv)
    except KeyboardInterrupt:   # Ctrl-C at any moment: outputs in progress were removed on the way out
        print("graphflow: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED
    finally:
        warnings.formatwarning = previous_format
        if previous_handler is not None:
            signal.signal(signal.SIGTERM, previous_handler)


def _main(argv: list[str] | None) -> int:
    args = build_parser().parse_args(argv)
    level = getattr(args, "log_level", "warning")
    logging.basicConfig(level=level.upper(), format="%(levelname)s %(name)s: %(message)s", stream=sys.stderr)
    warnings.formatwarning = _one_line_warning
    debug = level == "debug"
    from .preflight import MissingExtra

    try:
        return args.handler(args)
    except BrokenPipeError:  # output piped into head & co.: not an error
        sys.stderr.close()
        return EXIT_OK
    except (BadInput, FileProblem, MissingExtra) as error:
        for line in str(error).splitlines():
            print(f"graphflow: error: {line}", file=sys.stderr)
        return EXIT_BAD_INPUT
    except GraphRuntimeError as error:
        if isinstance(error.__cause__, BrokenPipeError):   # a print node's reader (head) has gone: done
            sys.stderr.close()
            return EXIT_OK
        if debug:
            raise
        print(f"graphflow: run-time error: {error}", file=sys.stderr)
        return EXIT_RUNTIME
    except Exception as error:  # last resort: one line, never a traceback unless debugging
        if debug:
            raise
        print(f"graphflow: unexpected error: {type(error).__name__}: {error}", file=sys.stderr)
        return EXIT_RUNTIME


if __name__ == "__main__":
    sys.exit(main())
