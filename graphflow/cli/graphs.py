"""Commands about graph files: ``validate``, ``import``, ``new``, ``nodes``."""
from __future__ import annotations

import dataclasses
import json
import re
import sys
from pathlib import Path

from graphflow.document import load_document, parse_document, save_document
from graphflow.errors import EXIT_BAD_INPUT, EXIT_OK, BadInput
from graphflow.files import refuse_existing
from graphflow.registry import default_registry

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
_SENTENCE_END = re.compile(r"(?<!\be\.g)(?<!\bi\.e)(?<!\betc)(?<!\bvs)(?<!\.\.)[.!?](?=\s+[^\s.]|\s*$)")


def register(commands) -> None:
    validate = commands.add_parser(
        "validate", help="check graph files and the stages they name without running them; print every problem")
    validate.add_argument("graphs", nargs="+", metavar="GRAPH")
    validate.add_argument("--allow-missing-assets", action="store_true",
                          help="a reference, payload or sublayer of the stage that cannot be opened, and inputs naming "
                               "prims of such layers, are warnings, not errors")
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
    new.add_argument("--stage", metavar="ROBOT",
                     help="also write NAME.usda, a cell around a packaged robot (ur10), and make NAME.json its "
                          "pick-and-place graph with checks")
    new.add_argument("--force", action="store_true", help="overwrite an existing file")
    new.set_defaults(handler=command_new)

    convert = commands.add_parser("import", help="convert an Isaac Sim action graph in a USD file to a graph JSON")
    convert.add_argument("stage", help=".usda / .usd file holding an OmniGraph prim (or asset:NAME)")
    convert.add_argument("-o", "--output", help="graph JSON to write (default: print to stdout)")
    convert.add_argument("--graph", help="prim path of the graph when the stage holds several")
    convert.add_argument("--skip-unknown", action="store_true",
                         help="drop nodes whose type graphflow does not have (and their connections) instead of failing")
    convert.add_argument("--force", action="store_true", help="overwrite an existing output file")
    convert.set_defaults(handler=command_import)


def command_validate(args) -> int:
    from graphflow.usd.opening import missing_layers_refused

    with missing_layers_refused(not args.allow_missing_assets):
        return _validate(args.graphs, args.allow_missing_assets)


def _validate(graphs: list[str], allow_missing_assets: bool) -> int:
    from graphflow.document import GraphError
    from graphflow.validate.preflight import file_problems, parse_stage
    from graphflow.validate.stage_names import deep_validate

    failed = False
    for path in graphs:
        document, problems, warnings_ = _scenario_table(path)   # a table: its graph with the table's checks
        if document is None and not problems:
            try:
                document = load_document(path)
            except GraphError:   # every problem at once: the file's and its stage's
                problems = file_problems(path)
        parsed = None
        if not problems and document.settings.get("stage"):   # read once, then checked for what the graph names
            problems, parsed = parse_stage(str(path), document.settings["stage"], document.base_dir)
        if not problems:
            problems, warnings_ = deep_validate(document, allow_missing_assets=allow_missing_assets, parsed=parsed)
        for problem in warnings_:
            print(f"warning: {problem}", file=sys.stderr)
        for problem in problems:
            print(problem, file=sys.stderr)
        if not problems:
            print(f"{path}: ok")
        failed = failed or bool(problems)
    return EXIT_BAD_INPUT if failed else EXIT_OK


def _scenario_table(path: str):
    """(its graph with the table's checks, [], []) for a scenario table, (None, problems, []) for a table that
    cannot be used, (None, [], []) for any other file."""
    from graphflow.files import FileProblem, read_json
    from graphflow.verdicts.cases import graph_with_checks, is_table, load_table

    try:
        if not is_table(read_json(path)):
            return None, [], []
        cases = load_table(path)
    except FileProblem:
        return None, [], []   # file_problems says what is wrong with it
    except BadInput as error:
        return None, error.lines(), []
    return graph_with_checks(cases[0].graph, cases[0].checks), [], []


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
    from graphflow.catalog.markdown import render_markdown, write_markdown

    if not args.markdown or args.json:
        raise BadInput("nodes: -o/--output writes the Markdown reference: use it with --markdown (and without --json)")
    if not args.output:
        sys.stdout.write(render_markdown())
        return EXIT_OK
    write_markdown(args.output, force=args.force)
    print(f"wrote {args.output}")
    return EXIT_OK


def first_sentence(text: str) -> str:
    """The first sentence of a description, whole (never cut at "e.g." or "..."), without its final period.

    A first sentence that is only a label ("Event source.") says nothing apart from the next one: the
    summary runs on to the first sentence of three words or more.
    """
    end = 0
    for match in _SENTENCE_END.finditer(text):
        sentence, end = text[end:match.start() + 1], match.start() + 1
        if len(sentence.split()) >= 3:
            break
    else:
        end = len(text)
    return " ".join(text[:end].split()).rstrip(".")


def command_new(args) -> int:
    from graphflow.catalog.schema import write_schema
    from graphflow.cli.editing import SCHEMA_FILE

    target = Path(args.name if args.name.endswith(".json") else f"{args.name}.json")
    if args.stage:
        from graphflow.build.starters import write_cell

        stage, _ = write_cell(target, args.stage, force=args.force)
        print(f"wrote {stage}")
    else:
        starter = {"$schema": SCHEMA_FILE, **json.loads(json.dumps(STARTER_GRAPH))}
        save_document(parse_document(starter, str(target)), target, force=args.force)
    print(f"wrote {target}")
    schema = target.parent / SCHEMA_FILE
    if not schema.exists():   # what "$schema" names, for editors; refresh it with graphflow schema -o --force
        write_schema(schema)
        print(f"wrote {schema}")
    return EXIT_OK


def command_import(args) -> int:
    from graphflow.document import dumps
    from graphflow.usd.omnigraph import import_graph
    from graphflow.usd.resolver import resolve_stage

    if args.output:
        refuse_existing(args.output, args.force)
    stage = str(resolve_stage(args.stage, Path.cwd()))
    result = import_graph(stage, graph_path=args.graph, output_path=args.output, skip_unknown=args.skip_unknown)
    from graphflow.validate.stage_names import unset_target_warnings

    unset = [str(dataclasses.replace(problem, file=f"{args.stage}: {result.graph_path}"))   # named as in the USD file
             for problem in unset_target_warnings(result.document)]
    for warning in [*result.warnings, *unset]:
        print(f"warning: {warning}", file=sys.stderr)
    if args.output:
        save_document(result.document, args.output, force=args.force)
        print(f"wrote {args.output}: {len(result.document.nodes)} nodes, {len(result.document.connections)} "
              f"connections from {result.graph_path}")
    else:
        sys.stdout.write(dumps(result.document))
    return EXIT_OK
