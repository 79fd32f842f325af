"""``graphflow run GRAPH``: one checked run with the terminal's listeners, traces and recordings."""
from __future__ import annotations

import argparse
import contextlib
import logging
import sys
import time
from pathlib import Path

from graphflow.cli import arguments
from graphflow.cli.watch import add_watch_option
from graphflow.document import load_document
from graphflow.errors import EXIT_BAD_INPUT, EXIT_OK, EXIT_RUN_FAILED, BadInput
from graphflow.files import atomic_output, refuse_existing


def register(commands) -> None:
    run = commands.add_parser("run", help="run a graph (headless unless --gui)")
    run.add_argument("graph", help="graph JSON file")
    run.add_argument("--ticks", type=arguments.positive_int, help="stop after N ticks")
    run.add_argument("--seconds", type=arguments.seconds, help="stop after S simulated seconds")
    run.add_argument("--seed", type=int, help="seed for random number generators (default: the graph's scenario seed, else 0)")
    run.add_argument("--gui", action="store_true", help="open the PyBullet window (paced to real time, see --speed)")
    run.add_argument("--speed", type=arguments.finite_float, default=1.0, metavar="X",
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
    run.add_argument("--mouse", metavar="FILE",
                     help='scripted mouse for OnMouseInput / ReadMouseState nodes: JSON '
                          '{"mouse": [{"element": "Left Button", "time": 1.0, "value": 1}, ...]}')
    run.add_argument("--click", action="append", default=[], metavar="ELEMENT=VALUE@TIME",
                     help='scripted mouse event (repeatable): "Left Button=1@0.5" (down; =0 up), '
                          '"Position=0.25,0.5@1.0" (normalized), "Scroll=0,-1@2"')
    run.add_argument("--topics", metavar="FILE",
                     help='scripted ROS 2 topics for subscriber nodes: JSON {"topics": [{"topic": "/joint_command", '
                          '"time": 0.5, "type": "sensor_msgs/msg/JointState", "message": {...}}, ...]}')
    run.add_argument("--topic", action="append", default=[], metavar="TOPIC@TIME=JSON",
                     help='scripted ROS 2 message (repeatable): \'/cmd_vel@1.0={"linear": {"x": 0.5}}\'')
    run.add_argument("--record-topics", metavar="FILE.mcap",
                     help="write every message ROS 2 publisher nodes publish to an MCAP file (ROS 2 CDR encoding)")
    run.add_argument("--checks", action="store_true",
                     help="evaluate the graph's checks even when --ticks, --seconds, --key(s), --gamepad, --pad, "
                          "--topic(s) or --gui change the run (by default they are evaluated only for the run as written)")
    run.add_argument("--set", action="append", default=[], metavar="TARGET=VALUE",
                     help="override (repeatable): NODE.INPUT=VALUE (a node input) or /Prim/Path.attribute=VALUE "
                          "(a stage attribute, in USD units); VALUE is JSON or a plain string (docs/sweeps.md)")
    run.add_argument("--randomize", metavar="FILE",
                     help="draw the randomize entries of FILE (a sweep file, {\"randomize\": [...]}, or a graph's "
                          "scenario section) from --seed")
    run.add_argument("--log-level", default="warning", choices=["debug", "info", "warning", "error"],
                     help="Python logging level on stderr (default warning)")
    run.add_argument("--trace", metavar="FILE", help="write what happens every tick as JSON Lines (docs/trace.md)")
    run.add_argument("--report", metavar="FILE.html",
                     help="write a self-contained HTML report of the run: graph, scene, lanes, verdict (docs/report.md)")
    run.add_argument("--report-timings", action="store_true",
                     help="put per-node wall-clock compute times in the report (it is then no longer byte-identical)")
    run.add_argument("--record", metavar="FILE", help="record a video: .gif, .mp4 (needs ffmpeg) or a folder of PNG frames")
    run.add_argument("--fps", type=arguments.positive_float, default=15.0, help="video frames per simulated second (default 15)")
    run.add_argument("--force", action="store_true", help="overwrite existing --trace / --record / --report outputs")
    run.add_argument("--size", type=arguments.size, default=(480, 360), metavar="WxH",
                     help="video size in pixels (default 480x360)")
    run.add_argument("--camera-target", type=arguments.point, metavar="X,Y,Z",
                     help="point the camera looks at (default: the scene's centre)")
    run.add_argument("--camera-distance", type=arguments.positive_float, metavar="M",
                     help="camera distance (default: fit the scene)")
    run.add_argument("--camera-yaw", type=arguments.finite_float, default=50.0, metavar="DEG",
                     help="camera yaw in degrees (default 50)")
    run.add_argument("--camera-pitch", type=arguments.finite_float, default=-30.0, metavar="DEG",
                     help="camera pitch in degrees (default -30)")
    add_watch_option(run, "the graph, its stage (and the stage's local layers) or a scripted-input file")
    run.set_defaults(handler=command_run)


def _scripted_inputs(args, document):
    """The run's scripted devices: the options', else (headless) the graph's own scenario section."""
    from graphflow.inputs.gamepad import scripted_pad
    from graphflow.inputs.keyboard import scripted_keys
    from graphflow.inputs.mouse import scripted_mouse
    from graphflow.ros2 import run as ros2_run
    from graphflow.verdicts.checked_run import ScriptedInputs

    keys = scripted_keys(args.keys, args.key)
    pad = scripted_pad(args.gamepad, args.pad)
    mouse = scripted_mouse(args.mouse, args.click)
    topics = ros2_run.check_options(args.topics, args.topic, args.record_topics)
    if not args.gui and keys is None and pad is None and mouse is None and topics is None:
        return ScriptedInputs.of_document(document)   # the scenario's inputs are used whole or not at all
    return ScriptedInputs(keys=keys, pad=pad, topics=topics, mouse=mouse)


def _changed_by_options(args) -> list[str]:
    """The options that make this run differ from the graph's scenario, so its checks do not apply."""
    options = {"--ticks": args.ticks is not None, "--seconds": args.seconds is not None, "--keys": args.keys is not None,
               "--key": bool(args.key), "--gamepad": args.gamepad is not None, "--pad": bool(args.pad),
               "--mouse": args.mouse is not None, "--click": bool(args.click),
               "--topics": args.topics is not None, "--topic": bool(args.topic), "--gui": args.gui}
    return [name for name, given in options.items() if given]


def command_run(args) -> int:
    if not args.watch:
        return run_once(args)
    from graphflow.cli.watch import watch
    from graphflow.watching import Watcher, graph_files

    def files() -> list:
        named = [args.keys, args.gamepad, args.mouse, args.topics, args.randomize]
        return list(dict.fromkeys([*graph_files(args.graph), *(Path(name) for name in named if name)]))

    def after_run(code: int) -> None:
        if code != EXIT_BAD_INPUT:   # the run wrote its outputs: the next run replaces them
            args.force = True

    return watch(lambda: run_once(args), Watcher(files), title=f"graphflow run {args.graph}", after_run=after_run)


def run_once(args) -> int:
    """One ``graphflow run``: exit 0 when it passed, 1 when it failed; bad input raised."""
    from graphflow.observe.terminal import PrintedLog, Progress, RealTimePacer
    from graphflow.variants.randomize import variant_for_run
    from graphflow.verdicts.checked_run import CheckedRun, RunLimits

    document = load_document(args.graph)
    seed = args.seed if args.seed is not None else int(document.scenario.get("seed", 0))
    if args.record:
        _check_recording(args, document)
    if args.trace:
        refuse_existing(args.trace, args.force)
    if args.report:
        refuse_existing(args.report, args.force)
    inputs = _scripted_inputs(args, document)
    variant = variant_for_run(document, args.set, args.randomize, seed)
    changed = _changed_by_options(args)
    checked = CheckedRun(document, source=args.graph, variant=variant, inputs=inputs,
                         limits=RunLimits(args.ticks, args.seconds), evaluate_checks=args.checks or not changed,
                         seed=seed, gui=args.gui, listeners=[PrintedLog()])
    checked.preflight()   # what validate refuses fails here, before the first tick: exit 2, not a failed run
    if args.gui:
        from graphflow.physics.native_output import route_native_stdout_to_stderr

        route_native_stdout_to_stderr()
    # outputs are written to temporary files renamed into place when the run ends (a failed run keeps
    # the ticks before the failure); a Ctrl-C or a broken start removes them: never half-written
    with contextlib.ExitStack() as outputs:
        outputs.callback(checked.close)
        simulation = checked.start()
        if args.record_topics:
            from graphflow.ros2 import run as ros2_run

            recording = ros2_run.attach_topics(simulation.world, None, args.record_topics)
            if recording is not None:
                outputs.push(lambda kind, _error, _trace: recording.abandon() if kind is not None else recording.close())
        trace_stream = _open_trace(args.trace, outputs, args.force) if args.trace else None
        report = _start_report(args, simulation, trace_stream, variant.drawn)
        if trace_stream is not None and report is None:
            from graphflow.observe.recorder import TraceRecorder

            TraceRecorder(simulation, trace_stream, graph=args.graph, randomized=variant.drawn)
        if args.record:
            simulation.world.services.add(_start_recording(args, simulation.world, outputs))
        if args.gui and args.speed > 0:
            simulation.add_listener(RealTimePacer(args.speed))
        simulation.add_listener(Progress(simulation, sys.stdout.isatty(), checked.tick_limit()))
        started = time.perf_counter()
        verdict = checked.run()
        if report is not None:
            _write_report(args, report, checked, seed)
    for line in verdict.failures:
        print(line, file=sys.stderr)
    summary = verdict.summary()
    if document.checks and not len(checked.evaluator) and not verdict.failures:
        summary = (f"done {args.graph}: checks not evaluated, {', '.join(changed)} changed the run "
                   f"(--checks evaluates them) {summary[summary.rindex('('):]}")
    print(f"graphflow: {summary}", file=sys.stderr)
    if verdict.failures:
        return EXIT_RUN_FAILED
    reason = "graph finished" if verdict.stopped_by_graph else "limit reached"
    logging.getLogger("graphflow").info("%s: %d ticks, %.3f s simulated in %.2f s wall (%s)", args.graph,
                                        verdict.ticks, verdict.time, time.perf_counter() - started, reason)
    return EXIT_OK


def _check_recording(args: argparse.Namespace, document) -> None:
    """Refuse a recording that cannot be made before the run starts, not after it ends."""
    if document.settings.get("stage") is None:
        raise BadInput(f"{args.graph}: --record needs a graph with a stage (settings.stage); this one has no scene")
    from graphflow.errors import require_extra
    from graphflow.physics.recorder import check_encoder, video_kind

    kind = video_kind(args.record)
    require_extra(f"--record {args.record}", "viz", "PIL")
    check_encoder(args.record)
    refuse_existing(args.record, args.force, folder=kind == "frames")


def _start_recording(args, world, outputs: contextlib.ExitStack):
    from graphflow.physics.recorder import Camera, VideoRecorder, video_kind

    camera = Camera(args.camera_target, args.camera_distance, args.camera_yaw, args.camera_pitch)
    folder = video_kind(args.record) == "frames"
    temporary = outputs.enter_context(atomic_output(args.record, force=args.force, folder=folder))
    try:
        video = VideoRecorder(world, args.record, fps=args.fps, size=args.size, camera=camera, write_to=temporary)
    except OSError as error:
        raise BadInput(f"{args.record}: cannot write the video: {error.strerror or error}") from None
    outputs.callback(video.close)   # runs before the rename into place (ExitStack unwinds last in, first out)
    return video


def _start_report(args, simulation, trace_stream, randomized=()):
    """The run's report recording (graphflow.report), teed to the --trace file when both are asked for."""
    if not args.report:
        return None
    from graphflow.report.recording import ReportRecording

    return ReportRecording(simulation, args.graph, also_to=trace_stream, timings=args.report_timings,
                           randomized=randomized)


def _write_report(args, report, checked, seed: int) -> None:
    from graphflow.report.recording import drawn_randomization, runtime_failure
    from graphflow.variants.randomize import load_randomization

    drawn = drawn_randomization(load_randomization(args.randomize).draw(seed)) if args.randomize else {}
    report.write(args.report, checked.document, evaluator=checked.evaluator, runtime_failure=runtime_failure(checked),
                 seed=seed, overrides=args.set, randomization=drawn, force=args.force)
    print(f"wrote {args.report}", file=sys.stderr)


def _open_trace(path: str, outputs: contextlib.ExitStack, force: bool):
    temporary = outputs.enter_context(atomic_output(path, force=force))
    try:
        stream = outputs.enter_context(open(temporary, "w", encoding="utf-8", newline="\n"))
    except OSError as error:
        raise BadInput(f"{path}: cannot write the trace: {error.strerror}") from None
    return stream
