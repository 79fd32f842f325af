"""docs/nodes.md, generated from the registered node specs (as OmniGraph generates node docs from .ogn files).

The specs are the one place a node's ports are declared, so the reference
page is rendered from them and never edited by hand:
``graphflow nodes --markdown -o docs/nodes.md --force`` rewrites it, and a test
fails when the page and the specs disagree.
"""
from __future__ import annotations

import json
import os
import re
from pathlib import Path

from graphflow.files import write_text
from graphflow.registry import Registry, default_registry
from graphflow.spec import Attribute, NodeSpec, NodeType

REGENERATE_COMMAND = "graphflow nodes --markdown -o docs/nodes.md --force"
TOKENS_IN_TABLE = 12     # longer token lists go below the table


def render_markdown(registry: Registry | None = None) -> str:
    """The whole reference page: an index, then one section per node type, ordered by id."""
    types = (registry or default_registry()).types()
    lines = [
        "# Node types",
        "",
        f"<!-- Generated from the node specs by `{REGENERATE_COMMAND}`; do not edit by hand. -->",
        "",
        f"{len(types)} node types. Ports are `inputs:`, `outputs:` and `state:` attributes; an unset input "
        "holds its default (the type's zero when none is declared: 0, false, \"\", an empty array). "
        "Execution ports carry pulses, not values. Quaternions are (x, y, z, w); lengths in metres, "
        "angles in radians unless a port says otherwise.",
        "",
        "| node type | name | version | kind |",
        "|---|---|---|---|",
    ]
    for node_type in types:
        spec = node_type.spec
        lines.append(f"| [{spec.id}](#{_anchor(spec.id)}) | {_cell(spec.ui_name)} | {spec.version} | {_kind(spec)} |")
    from graphflow.usd.libraries import render_coverage

    lines += [""] + render_coverage(registry or default_registry())
    for node_type in types:
        lines += [""] + _section(node_type)
    return "\n".join(lines) + "\n"


def _section(node_type: NodeType) -> list[str]:
    spec = node_type.spec
    facts = [f"version {spec.version}", _kind(spec)]
    if spec.ui_name:
        facts.insert(0, f"**{spec.ui_name}**")
    if spec.categories:
        facts.append("categories " + ", ".join(f"`{c}`" for c in spec.categories))
    facts.append(f"module `{node_type.module}`")
    lines = [f"## {spec.id}", "", " · ".join(facts), ""]
    if spec.aliases:
        lines += ["Also loads as " + ", ".join(f"`{a}`" for a in spec.aliases) + ".", ""]
    if spec.compatible_versions:
        lines += ["Files of typeVersion " + ", ".join(str(v) for v in spec.compatible_versions)
                  + f" load as version {spec.version}.", ""]
    lines += [_text(spec.description), ""]
    ports = [(group, a) for group, attributes in (("inputs", spec.inputs), ("outputs", spec.outputs),
                                                  ("state", spec.state)) for a in attributes]
    if not ports:
        return lines + ["No ports."]
    lines += ["| port | type | default | range / allowed | description |", "|---|---|---|---|---|"]
    long_lists = []
    for group, attribute in ports:
        name = f"{group}:{attribute.name}"
        bounds = _bounds(attribute)
        if len(attribute.allowed_tokens) > TOKENS_IN_TABLE:
            long_lists.append((name, attribute.allowed_tokens))
            bounds = f"one of {len(attribute.allowed_tokens)} tokens (below)"
        description = attribute.description + (" (optional)" if attribute.optional else "")
        lines.append(f"| `{name}` | `{attribute.type}` | {_cell(_default(attribute))} | {_cell(bounds)} | "
                     f"{_cell(_text(description))} |")
    for name, tokens in long_lists:
        lines += ["", f"`{name}` is one of: " + ", ".join(f"`{t}`" for t in tokens) + "."]
    return lines


def _kind(spec: NodeSpec) -> str:
    if spec.is_event_source:
        return "event source"
    return "pure (computed when pulled)" if spec.is_pure else "exec"


def _default(attribute: Attribute) -> str:
    if attribute.is_execution:
        return ""
    if attribute.attr_type.is_bundle:
        return "empty bundle"
    if attribute.attr_type.is_any and attribute.default is None:
        return "unset"
    value = attribute.initial_value()
    return f"`{json.dumps(_plain(value), ensure_ascii=False)}`"


def _bounds(attribute: Attribute) -> str:
    parts = []
    if attribute.minimum is not None and attribute.maximum is not None:
        parts.append(f"{attribute.minimum:g} to {attribute.maximum:g}")
    elif attribute.minimum is not None:
        parts.append(f">= {attribute.minimum:g}")
    elif attribute.maximum is not None:
        parts.append(f"<= {attribute.maximum:g}")
    if attribute.length is not None:
        parts.append(f"exactly {attribute.length} values")
    if attribute.allowed_tokens:
        parts.append(", ".join(f"`{t}`" for t in attribute.allowed_tokens))
    return "; ".join(parts)


def _plain(value):
    if isinstance(value, tuple):
        return [_plain(v) for v in value]
    return value


def _text(text: str) -> str:
    """Prose as Markdown shows it: '<' escaped so 'a <operation> b' is not taken for an HTML tag."""
    return text.replace("<", "&lt;")


def _cell(text: str) -> str:
    """Table-safe text: one line, pipes escaped (backticked code keeps its '<')."""
    return " ".join(text.split()).replace("|", "\\|")


def _anchor(title: str) -> str:
    """The anchor GitHub gives a heading: lower case, punctuation dropped, spaces to hyphens."""
    return re.sub(r"[^\w\- ]", "", title.lower()).replace(" ", "-")


def write_markdown(path: str | os.PathLike, registry: Registry | None = None, *, force: bool = False) -> Path:
    """Write the page to *path* through the atomic writer; an existing file is replaced only with *force*."""
    write_text(path, render_markdown(registry), force=force)
    return Path(path)
