"""Commands for authoring a cell: ``schema`` (JSON Schema with every node type), ``migrate`` and ``assets``."""
from __future__ import annotations

import sys
import warnings

from graphflow.errors import EXIT_OK

SCHEMA_FILE = "graphflow.schema.json"   # the "$schema" graphflow new and graphflow.build write


def register(commands) -> None:
    schema = commands.add_parser(
        "schema", help="write the JSON Schema of graph files with every registered node type and its inputs")
    schema.add_argument("-o", "--output", metavar="FILE", help="write it to FILE atomically (default: stdout)")
    schema.add_argument("--python", action="store_true",
                        help="write typed node handles for graphflow.build instead (a Python module for editors)")
    schema.add_argument("--force", action="store_true", help="overwrite an existing FILE")
    schema.set_defaults(handler=command_schema)

    migrate = commands.add_parser(
        "migrate", help="rewrite a graph file whose nodes name older typeVersions with the current ones")
    migrate.add_argument("graph", metavar="GRAPH")
    migrate.add_argument("-o", "--output", metavar="FILE", help="write the migrated graph to FILE instead of GRAPH")
    migrate.add_argument("--force", action="store_true", help="overwrite an existing --output FILE")
    migrate.set_defaults(handler=command_migrate)
    register_assets(commands)


def command_schema(args) -> int:
    import json

    from graphflow.catalog.schema import graph_schema, write_schema

    if args.python:
        from graphflow.catalog.typed_handles import python_module, write_python_module

        if args.output:
            write_python_module(args.output, force=args.force)
            print(f"wrote {args.output}")
        else:
            sys.stdout.write(python_module())
        return EXIT_OK
    if args.output:
        write_schema(args.output, force=args.force)
        print(f"wrote {args.output}")
    else:
        sys.stdout.write(json.dumps(graph_schema(), indent=2, sort_keys=True) + "\n")
    return EXIT_OK


def command_migrate(args) -> int:
    from graphflow.document import load_document, save_document
    from graphflow.migration import MigrationWarning

    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", MigrationWarning)
        document = load_document(args.graph)
    lines = [str(warning.message) for warning in caught if issubclass(warning.category, MigrationWarning)]
    for line in lines:
        print(line)
    if not lines and not args.output:
        print(f"{args.graph}: nothing to migrate (every node is at its type's version)")
        return EXIT_OK
    target = args.output or args.graph
    save_document(document, target, force=args.force or not args.output)
    print(f"wrote {target}")
    return EXIT_OK


def register_assets(commands) -> None:
    assets = commands.add_parser("assets", help="list the asset roots stages can reference (@graphflow/ur10.usda@)")
    assets.add_argument("--json", action="store_true", help="print one JSON object: root name -> folder and files")
    assets.add_argument("--link", metavar="FOLDER",
                        help="put a link per root in FOLDER, for other USD tools (usdview, Kit): "
                             "PXR_AR_DEFAULT_SEARCH_PATH=FOLDER")
    assets.add_argument("--force", action="store_true", help="with --link: replace entries that are not links")
    assets.set_defaults(handler=command_assets)


def command_assets(args) -> int:
    import json
    from pathlib import Path

    from graphflow.usd.asset_roots import asset_roots, link_roots

    if args.link:
        for entry in link_roots(Path(args.link), force=args.force):
            print(f"linked {entry} -> {asset_roots()[entry.name]}")
        print(f"export PXR_AR_DEFAULT_SEARCH_PATH={Path(args.link).resolve()}")
        return EXIT_OK
    roots = {name: {"folder": str(folder), "files": sorted(p.name for p in folder.glob("*.usd*"))}
             for name, folder in asset_roots().items()}
    if args.json:
        print(json.dumps(roots, indent=2))
        return EXIT_OK
    for name, root in roots.items():
        print(f"{name}/  {root['folder']}")
        for file in root["files"]:
            print(f"  @{name}/{file}@")
    return EXIT_OK
