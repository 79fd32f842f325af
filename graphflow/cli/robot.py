"""``graphflow robot add FILE.urdf|FILE.xml``: convert a robot with NVIDIA's converter (its own environment,
a separate process), then make it simulatable (``graphflow.robots``): drives, home pose, what is dropped,
optionally flattened to physics only. Exit 2 when the converter is not installed, with how to install it."""
from __future__ import annotations

import shutil
import tempfile
from pathlib import Path

from graphflow.errors import EXIT_OK, BadInput


def register(commands) -> None:
    robot = commands.add_parser("robot", help="bring a URDF or MJCF robot into graphflow")
    actions = robot.add_subparsers(dest="robot_command", required=True, metavar="ACTION")
    add = actions.add_parser("add", help="convert FILE.urdf or an MJCF FILE.xml to a USD asset with drives and a home pose")
    add.add_argument("source", metavar="FILE", help="the robot's .urdf, or its MJCF .xml")
    add.add_argument("-o", "--output", metavar="OUT.usda", help="the asset to write (default: ./FILE's name.usda)")
    add.add_argument("--home", default="", metavar="NAME=VALUE,...",
                     help="home joint values (rad, or m for prismatic joints); default: the MJCF keyframe "
                          "'home', else each joint's range middle")
    add.add_argument("--physics-only", action="store_true",
                     help="flatten to one layer without visual meshes, materials and textures")
    add.add_argument("--suction", metavar="LINK[:TIP]",
                     help="add a suction tool and surface gripper on LINK, its tip TIP m (default 0.1) along +Z")
    add.add_argument("--package", action="append", default=[], metavar="NAME=FOLDER",
                     help="URDF only: where package://NAME/ paths point (repeatable)")
    add.add_argument("--converter", metavar="PATH",
                     help="the converter's executable, or the python of the environment it is installed in")
    add.add_argument("--force", action="store_true", help="overwrite OUT.usda (and its _usd folder)")
    add.set_defaults(handler=command_robot_add)


def command_robot_add(args) -> int:
    from graphflow.files import refuse_existing, write_text
    from graphflow.robots.converters import MJCF, converter_for, find_command, run_converter
    from graphflow.robots.home import parse_home
    from graphflow.robots.post_process import Options, folder_bytes
    from graphflow.robots.sources import read_mjcf

    source = Path(args.source)
    if not source.is_file():
        raise BadInput(f"{source}: no such file")
    converter = converter_for(source)
    options = Options(home=parse_home(args.home), physics_only=args.physics_only)
    if args.suction:
        link, _, tip = args.suction.partition(":")
        options.suction_link = link
        try:
            options.suction_tip = float(tip) if tip else options.suction_tip
        except ValueError:
            raise BadInput(f"--suction: {args.suction!r} is not LINK or LINK:TIP (metres)") from None
    if args.package and converter is MJCF:
        raise BadInput("--package is for URDF files (package:// paths); an MJCF file names its meshes itself")
    packages = []
    for item in args.package:
        name, sep, folder = item.partition("=")
        if not sep or not name or not Path(folder).is_dir():
            raise BadInput(f"--package {item}: not NAME=FOLDER with an existing FOLDER")
        packages.append(f"{name}={Path(folder).resolve()}")
    command = find_command(converter, args.converter)
    output = Path(args.output or f"{source.stem}.usda")
    companion = output.parent / f"{output.stem}_usd"
    refuse_existing(output, args.force)
    if not args.physics_only:
        refuse_existing(companion, args.force, folder=True)
    mjcf = read_mjcf(source) if converter is MJCF else None
    options.provenance = provenance(source, args)
    with tempfile.TemporaryDirectory(prefix="graphflow-robot-") as scratch:
        converted = Path(scratch) / companion.name      # the companion folder, made here until all went well
        main, seconds = run_converter(command, source.resolve(), converted, packages)
        before = folder_bytes(converted)
        print(f"converted {source} with {converter.executable} in {seconds:.2f} s ({before} bytes written)")
        if args.physics_only:
            outcome = _post_process_flat(main, options, mjcf)
            text = outcome.text
        else:
            outcome, text = _post_process_over(main, options, mjcf)
            if companion.exists():
                shutil.rmtree(companion)
            shutil.copytree(converted, companion)
    for line in outcome.lines:
        print(line)
    write_text(output, text, force=True)
    after = len(text.encode("utf-8"))
    kept = f"{after} bytes" if args.physics_only else f"{after} bytes over {companion} ({folder_bytes(companion)} bytes)"
    print(f"wrote {output}: {kept}; converter output {before} bytes")
    return EXIT_OK


def _post_process_flat(main: Path, options, mjcf):
    from pxr import Usd

    from graphflow.robots.post_process import post_process

    return post_process(Usd.Stage.Open(str(main)), options, mjcf)


def _post_process_over(converted: Path, options, mjcf):
    """graphflow's additions in a layer of their own over the converter's (sublayered, left unedited)."""
    from pxr import Sdf, Usd

    from graphflow.robots.post_process import post_process

    base = Sdf.Layer.FindOrOpen(str(converted))
    layer = Sdf.Layer.CreateAnonymous(".usda")
    layer.subLayerPaths.append(str(converted.resolve()))
    for key in ("defaultPrim", "metersPerUnit", "upAxis", "kilogramsPerUnit"):
        if base.pseudoRoot.HasInfo(key):
            layer.pseudoRoot.SetInfo(key, base.pseudoRoot.GetInfo(key))
    layer.documentation = options.provenance
    outcome = post_process(Usd.Stage.Open(layer), options, mjcf)
    relative = f"./{converted.parent.name}/{converted.name}"
    layer.subLayerPaths[0] = relative
    return outcome, layer.ExportToString()


def provenance(source: Path, args) -> str:
    """The layer's doc: the converter and graphflow's options, so the asset says how to make it again."""
    flags = [f"--home {args.home}" if args.home else "", "--physics-only" if args.physics_only else "",
             f"--suction {args.suction}" if args.suction else ""]
    return f"Made from {source.name} by: graphflow robot add {source.name} {' '.join(f for f in flags if f)}".rstrip()
