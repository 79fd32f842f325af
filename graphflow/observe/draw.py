"""Pictures of graphs: SVG (written by hand), PNG (matplotlib), Mermaid and Graphviz dot text.

The layout reads left to right in execution order: nodes are layered by the
longest exec path from the event sources, and pure (data-only) nodes sit one
column left of their first consumer. Exec edges are thick dark arrows, data
edges thin blue dashed curves, so control flow stands out from data flow.
Every format names every node and edge, so a picture can be checked by text.
"""
from __future__ import annotations

import json
from dataclasses import dataclass, replace
from pathlib import Path
from xml.sax.saxutils import escape, quoteattr

import networkx as nx

from graphflow.document import GraphDocument
from graphflow.model import Connection
from graphflow.registry import Registry, default_registry

FORMATS = ("svg", "png", "mermaid", "dot")
SUFFIX_FORMATS = {".svg": "svg", ".png": "png", ".mmd": "mermaid", ".mermaid": "mermaid", ".dot": "dot", ".gv": "dot"}

CHAR_WIDTH = 6.6          # px per character at the 11 px label font (a fair average for sans-serif)
NAME_CHAR_WIDTH = 7.8     # px per character of the bold 13 px node name
HEADER_HEIGHT = 38
ROW_HEIGHT = 17
BOX_PADDING = 10
PORT_GAP = 24             # px between a box's input and output labels
COLUMN_GAP = 90
ROW_GAP = 26
MARGIN = 24
LEGEND_HEIGHT = 28
LANE_GAP = 12             # px between the lanes that long edges run along
LANE_BEND = 36            # px an edge takes to curve into or out of its lane
VALUE_CHARS = 28          # authored values longer than this are shortened with an ellipsis

EXEC_COLOUR = "#2d2d2d"
DATA_COLOUR = "#2a7bd6"
EVENT_FILL = "#fdf0d5"
EXEC_FILL = "#f3f4f6"
PURE_FILL = "#e8f1fc"


@dataclass(frozen=True)
class Port:
    name: str
    kind: str           # "exec" or "data"
    y: float            # centre of the port's row, picture coordinates (y down)


@dataclass(frozen=True)
class Box:
    name: str
    type_id: str
    role: str                      # "event", "exec" or "pure"
    layer: int
    x: float
    y: float
    width: float
    height: float
    inputs: tuple[Port, ...]       # connected inputs, exec first
    outputs: tuple[Port, ...]      # connected outputs, exec first
    settings: tuple[str, ...]      # authored, unconnected inputs as "name = value"

    @property
    def short_type(self) -> str:
        return self.type_id.rsplit(".", 1)[-1]

    def port(self, side: str, name: str) -> Port:
        return next(p for p in (self.inputs if side == "inputs" else self.outputs) if p.name == name)


@dataclass(frozen=True)
class Edge:
    src: str            # "node.outputs:x"
    dst: str            # "node.inputs:y"
    kind: str           # "exec" or "data"
    start: tuple[float, float]
    end: tuple[float, float]

    @property
    def label(self) -> str:
        return f"{self.src.split(':', 1)[1]} → {self.dst.split(':', 1)[1]}"

    lane: float | None = None    # y of the free lane an edge that would cross boxes runs along

    def segments(self) -> list[tuple]:
        """The route after ``start``: ("C", control1, control2, end) cubic Béziers and ("L", end) lines.

        A direct edge is one S-curve leaving rightwards and arriving from the
        left (looping back when it points left); a laned edge curves into its
        lane, runs along it and curves down or up into its input.
        """
        (x1, y1), (x2, y2) = self.start, self.end
        if self.lane is None:
            reach = max(50.0, abs(x2 - x1) * 0.45)
            return [("C", (x1 + reach, y1), (x2 - reach, y2), self.end)]
        lane = self.lane
        return [("C", (x1 + 0.6 * LANE_BEND, y1), (x1 + 0.4 * LANE_BEND, lane), (x1 + LANE_BEND, lane)),
                ("L", (x2 - LANE_BEND, lane)),
                ("C", (x2 - 0.4 * LANE_BEND, lane), (x2 - 0.6 * LANE_BEND, y2), self.end)]


@dataclass(frozen=True)
class Picture:
    """A laid-out graph: boxes and edges in picture coordinates, ready for any format."""

    title: str
    boxes: tuple[Box, ...]
    edges: tuple[Edge, ...]
    width: float
    height: float

    def box(self, name: str) -> Box:
        return next(b for b in self.boxes if b.name == name)


def format_for(path: str | Path, requested: str | None = None) -> str:
    """The picture format: the one asked for, else the file suffix's; ValueError when neither says."""
    if requested is not None:
        if requested not in FORMATS:
            raise ValueError(f"unknown picture format {requested!r} (choose from {', '.join(FORMATS)})")
        return requested
    suffix = Path(path).suffix.lower()
    if suffix not in SUFFIX_FORMATS:
        raise ValueError(f"{path}: cannot tell the format from the suffix {suffix or '(none)'}; "
                         f"use .svg, .png, .mmd or .dot, or --format")
    return SUFFIX_FORMATS[suffix]


def _short_value(value) -> str:
    text = value if isinstance(value, str) else json.dumps(value, ensure_ascii=False)
    return text if len(text) <= VALUE_CHARS else text[:VALUE_CHARS - 1] + "…"


def layers(document: GraphDocument, registry: Registry | None = None) -> dict[str, int]:
    """Column of every node: longest path from the event sources, then each pure node just left of its first consumer.

    The paths follow exec edges and the data edges into and out of pure nodes
    (loop-closing edges are dropped), so exec chains read left to right and a
    pure node sits between what it reads and what reads it.
    """
    specs = {node.name: (registry or default_registry()).require(node.type).spec for node in document.nodes}
    order = list(specs)
    flow = nx.DiGraph()
    flow.add_nodes_from(order)
    for connection in document.connections:
        destination = specs[connection.dst_node].attribute(connection.dst_attr)
        exec_edge = destination is not None and destination.is_execution
        if exec_edge or specs[connection.src_node].is_pure or specs[connection.dst_node].is_pure:
            flow.add_edge(connection.src_node, connection.dst_node)
    acyclic = _without_back_edges(flow, [name for name in order if specs[name].is_event_source])
    topological = list(nx.lexicographical_topological_sort(acyclic, key=order.index))
    column: dict[str, int] = {}
    for name in topological:
        column[name] = max((column[p] + 1 for p in acyclic.predecessors(name)), default=0)
    for name in reversed(topological):
        consumers = [column[c] for c in acyclic.successors(name)]
        if specs[name].is_pure and consumers:
            column[name] = min(consumers) - 1
    return column


def _without_back_edges(graph: nx.DiGraph, sources: list[str]) -> nx.DiGraph:
    """The exec graph with loop-closing edges removed (depth-first from the event sources, then the rest)."""
    acyclic = nx.DiGraph()
    acyclic.add_nodes_from(graph)
    state: dict[str, int] = {}            # 1 = on the current path, 2 = done
    for root in sources + [n for n in graph if n not in sources]:
        if root in state:
            continue
        stack = [(root, iter(graph.successors(root)))]
        state[root] = 1
        while stack:
            node, successors = stack[-1]
            following = next(successors, None)
            if following is None:
                state[node] = 2
                stack.pop()
            elif state.get(following) != 1:
                acyclic.add_edge(node, following)
                if following not in state:
                    state[following] = 1
                    stack.append((following, iter(graph.successors(following))))
    return acyclic


def layout(document: GraphDocument, registry: Registry | None = None) -> Picture:
    """Place every node and route every connection (see the module docstring for the rules)."""
    registry = registry or default_registry()
    specs = {node.name: registry.require(node.type).spec for node in document.nodes}
    column = layers(document, registry)
    connected_inputs: dict[str, list[str]] = {name: [] for name in specs}
    connected_outputs: dict[str, list[str]] = {name: [] for name in specs}
    for connection in document.connections:
        for table, node_name, attr in ((connected_outputs, connection.src_node, connection.src_attr),
                                       (connected_inputs, connection.dst_node, connection.dst_attr)):
            name = attr.split(":", 1)[1]
            if name not in table[node_name]:
                table[node_name].append(name)

    def ordered(node: str, names: list[str], group: str) -> list[str]:
        declared = [a.name for a in getattr(specs[node], group)]
        execution = {a.name for a in getattr(specs[node], group) if a.is_execution}
        return sorted(names, key=lambda n: (n not in execution,
                                            declared.index(n) if n in declared else len(declared)))

    sizes, contents = {}, {}
    for node in document.nodes:
        inputs = ordered(node.name, connected_inputs[node.name], "inputs")
        outputs = ordered(node.name, connected_outputs[node.name], "outputs")
        settings = tuple(f"{key} = {_short_value(value)}" for key, value in node.inputs.items() if key not in inputs)
        rows = max(len(inputs), len(outputs)) + len(settings)
        port_width = (max((len(n) for n in inputs), default=0) + max((len(n) for n in outputs), default=0)) * CHAR_WIDTH
        width = max(len(node.name) * NAME_CHAR_WIDTH, len(node.type.rsplit(".", 1)[-1]) * CHAR_WIDTH,
                    port_width + PORT_GAP, max((len(s) for s in settings), default=0) * CHAR_WIDTH) + 2 * BOX_PADDING
        sizes[node.name] = (max(width, 110.0), HEADER_HEIGHT + rows * ROW_HEIGHT + 6)
        contents[node.name] = (inputs, outputs, settings)

    columns: dict[int, list[str]] = {}
    for node in document.nodes:
        columns.setdefault(column[node.name], []).append(node.name)
    _order_columns(columns, document)

    # exec nodes in a band on top, pure nodes in a band below: exec edges then never run behind data nodes
    bands = {c: ([n for n in names if not specs[n].is_pure], [n for n in names if specs[n].is_pure])
             for c, names in columns.items()}

    def stacked_height(names):
        return sum(sizes[n][1] for n in names) + ROW_GAP * max(0, len(names) - 1)

    exec_band = max((stacked_height(e) for e, _ in bands.values()), default=0)
    data_band = max((stacked_height(p) for _, p in bands.values()), default=0)
    data_top = MARGIN + exec_band + (1.5 * ROW_GAP if exec_band and data_band else 0)
    column_width = {c: max(sizes[n][0] for n in names) for c, names in columns.items()}
    boxes: dict[str, Box] = {}
    x: float = MARGIN
    for c in sorted(columns):
        for names, top, band in ((bands[c][0], MARGIN, exec_band), (bands[c][1], data_top, data_band)):
            y = top + (band - stacked_height(names)) / 2
            for name in names:
                boxes[name] = _box(name, specs[name], c, x, y, column_width[c],
                                   sizes[name][1], contents[name])
                y += sizes[name][1] + ROW_GAP
        x += column_width[c] + COLUMN_GAP
    total_height = data_top + data_band - MARGIN if data_band else exec_band

    # edges that would run behind boxes of the columns they skip take a lane: exec above, data below
    blocked: dict[str, list[Connection]] = {"exec": [], "data": []}
    for connection in document.connections:
        source, target = boxes[connection.src_node], boxes[connection.dst_node]
        y1 = source.port("outputs", connection.src_attr.split(":", 1)[1]).y
        in_port = target.port("inputs", connection.dst_attr.split(":", 1)[1])
        low, high = min(y1, in_port.y) - ROW_HEIGHT / 2, max(y1, in_port.y) + ROW_HEIGHT / 2
        if any(source.layer < box.layer < target.layer and box.y < high and box.y + box.height > low
               for box in boxes.values()):
            blocked[in_port.kind].append(connection)
    top_lanes = len(blocked["exec"]) * LANE_GAP
    bottom = MARGIN + top_lanes + total_height + LANE_GAP / 2
    lanes: dict[Connection, float] = {c: MARGIN + i * LANE_GAP for i, c in enumerate(blocked["exec"])}
    lanes.update({c: bottom + (i + 0.5) * LANE_GAP for i, c in enumerate(blocked["data"])})
    boxes = {name: _shifted(box, top_lanes) for name, box in boxes.items()}
    edges = []
    for connection in document.connections:
        source, target = boxes[connection.src_node], boxes[connection.dst_node]
        out_port = source.port("outputs", connection.src_attr.split(":", 1)[1])
        in_port = target.port("inputs", connection.dst_attr.split(":", 1)[1])
        edges.append(Edge(connection.src, connection.dst, "exec" if in_port.kind == "exec" else "data",
                          (source.x + source.width, out_port.y), (target.x, in_port.y), lanes.get(connection)))
    title = Path(document.source).stem if document.source != "<graph>" else "graph"
    height = total_height + top_lanes + len(blocked["data"]) * LANE_GAP + 2 * MARGIN + LEGEND_HEIGHT
    return Picture(title, tuple(boxes[n.name] for n in document.nodes), tuple(edges), x - COLUMN_GAP + MARGIN, height)


def _shifted(box: Box, down: float) -> Box:
    if not down:
        return box
    return replace(box, y=box.y + down, inputs=tuple(replace(p, y=p.y + down) for p in box.inputs),
                   outputs=tuple(replace(p, y=p.y + down) for p in box.outputs))


def _box(name: str, spec, layer: int, x: float, y: float, width: float, height: float,
         content: tuple[list[str], list[str], tuple[str, ...]]) -> Box:
    inputs, outputs, settings = content

    def ports(names, group):
        return tuple(Port(n, "exec" if spec.attribute(f"{group}:{n}").is_execution else "data",
                          y + HEADER_HEIGHT + (i + 0.5) * ROW_HEIGHT) for i, n in enumerate(names))

    role = "event" if spec.is_event_source else "pure" if spec.is_pure else "exec"
    return Box(name, spec.id, role, layer, x, y, width, height, ports(inputs, "inputs"), ports(outputs, "outputs"),
               settings)


def _order_columns(columns: dict[int, list[str]], document: GraphDocument, sweeps: int = 4) -> None:
    """Order nodes inside each column by the mean rank of their neighbours (fewer crossings), document order first."""
    neighbours: dict[str, set[str]] = {n.name: set() for n in document.nodes}
    for connection in document.connections:
        neighbours[connection.src_node].add(connection.dst_node)
        neighbours[connection.dst_node].add(connection.src_node)
    document_index = {n.name: i for i, n in enumerate(document.nodes)}
    where = {name: c for c, names in columns.items() for name in names}
    for sweep in range(sweeps):
        rank = {name: i / max(1, len(names) - 1) for names in columns.values() for i, name in enumerate(names)}
        for c in sorted(columns, reverse=bool(sweep % 2)):
            def key(name):
                others = [rank[o] for o in neighbours[name] if where[o] != c]
                return (sum(others) / len(others) if others else rank[name], document_index[name])
            columns[c].sort(key=key)


# ---------------------------------------------------------------- SVG

def to_svg(picture: Picture) -> str:
    """A standalone SVG: ``<g class="node" data-name data-type>`` per node, ``<path class="edge exec|data" data-src data-dst>`` per edge."""
    width, height = round(picture.width), round(picture.height)
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" viewBox="0 0 {width} {height}" '
           f'font-family="Helvetica, Arial, sans-serif" font-size="11">',
           f"<title>{escape(picture.title)}</title>",
           "<defs>",
           f'<marker id="exec-arrow" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="7" markerHeight="7" orient="auto">'
           f'<path d="M0,0 L10,5 L0,10 z" fill="{EXEC_COLOUR}"/></marker>',
           f'<marker id="data-dot" viewBox="0 0 10 10" refX="5" refY="5" markerWidth="5" markerHeight="5">'
           f'<circle cx="5" cy="5" r="4" fill="{DATA_COLOUR}"/></marker>',
           "</defs>",
           '<rect width="100%" height="100%" fill="white"/>',
           '<g class="edges" fill="none">']
    for edge in picture.edges:
        style = (f'stroke="{EXEC_COLOUR}" stroke-width="2.2" marker-end="url(#exec-arrow)"' if edge.kind == "exec" else
                 f'stroke="{DATA_COLOUR}" stroke-width="1.4" stroke-dasharray="5 3" marker-end="url(#data-dot)"')
        out.append(f'<path class="edge {edge.kind}" data-src={quoteattr(edge.src)} data-dst={quoteattr(edge.dst)} '
                   f'd="{_svg_route(edge)}" {style}><title>{escape(edge.src)} → {escape(edge.dst)}</title></path>')
    out.append("</g>")
    out.append('<g class="nodes">')
    fills = {"event": EVENT_FILL, "exec": EXEC_FILL, "pure": PURE_FILL}
    for box in picture.boxes:
        x, y, w = box.x, box.y, box.width
        out.append(f'<g class="node {box.role}" id={quoteattr("node-" + box.name)} data-name={quoteattr(box.name)} '
                   f'data-type={quoteattr(box.type_id)}>')
        out.append(f"<title>{escape(box.name)} ({escape(box.type_id)})</title>")
        out.append(f'<rect x="{_n(x)}" y="{_n(y)}" width="{_n(w)}" height="{_n(box.height)}" rx="7" '
                   f'fill="{fills[box.role]}" stroke="#8a8f98" stroke-width="1"/>')
        out.append(f'<text class="name" x="{_n(x + BOX_PADDING)}" y="{_n(y + 16)}" font-size="13" font-weight="bold" '
                   f'fill="#111">{escape(box.name)}</text>')
        out.append(f'<text class="type" x="{_n(x + BOX_PADDING)}" y="{_n(y + 30)}" fill="#6b7280">{escape(box.short_type)}</text>')
        out.append(f'<line x1="{_n(x)}" y1="{_n(y + HEADER_HEIGHT - 3)}" x2="{_n(x + w)}" y2="{_n(y + HEADER_HEIGHT - 3)}" '
                   f'stroke="#d1d5db"/>')
        for port in box.inputs:
            out.append(_svg_port(x, port, "start", x + BOX_PADDING))
        for port in box.outputs:
            out.append(_svg_port(x + w, port, "end", x + w - BOX_PADDING))
        settings_top = y + HEADER_HEIGHT + max(len(box.inputs), len(box.outputs)) * ROW_HEIGHT
        for i, setting in enumerate(box.settings):
            out.append(f'<text class="setting" x="{_n(x + BOX_PADDING)}" y="{_n(settings_top + (i + 0.5) * ROW_HEIGHT + 4)}" '
                       f'fill="#374151" font-style="italic">{escape(setting)}</text>')
        out.append("</g>")
    out.append("</g>")
    legend_y = picture.height - MARGIN / 2 - 8
    out.append(f'<g class="legend" transform="translate({MARGIN},{_n(legend_y)})">'
               f'<path d="M0,0 L34,0" stroke="{EXEC_COLOUR}" stroke-width="2.2" marker-end="url(#exec-arrow)"/>'
               f'<text x="42" y="4">execution</text>'
               f'<path d="M120,0 L154,0" stroke="{DATA_COLOUR}" stroke-width="1.4" stroke-dasharray="5 3" '
               f'marker-end="url(#data-dot)"/><text x="162" y="4">data</text></g>')
    out.append("</svg>")
    return "\n".join(out) + "\n"


def _svg_route(edge: Edge) -> str:
    parts = [f"M{_n(edge.start[0])},{_n(edge.start[1])}"]
    for kind, *points in edge.segments():
        parts.append(kind + " ".join(f"{_n(x)},{_n(y)}" for x, y in points))
    return " ".join(parts)


def _svg_port(edge_x: float, port: Port, anchor: str, text_x: float) -> str:
    if port.kind == "exec":
        marker = (f'<path d="M{_n(edge_x - 4)},{_n(port.y - 4)} L{_n(edge_x + 4)},{_n(port.y)} '
                  f'L{_n(edge_x - 4)},{_n(port.y + 4)} z" fill="{EXEC_COLOUR}"/>')
    else:
        marker = f'<circle cx="{_n(edge_x)}" cy="{_n(port.y)}" r="3.5" fill="{DATA_COLOUR}"/>'
    return marker + (f'<text class="port {port.kind}" x="{_n(text_x)}" y="{_n(port.y + 4)}" text-anchor="{anchor}" '
                     f'fill="#1f2937">{escape(port.name)}</text>')


def _n(value: float) -> str:
    return f"{value:.1f}".rstrip("0").rstrip(".")


# ---------------------------------------------------------------- Mermaid and dot

def to_mermaid(picture: Picture) -> str:
    """A Mermaid flowchart: ``==>`` exec edges, ``-.->`` data edges, nodes in layout order."""
    ids = {box.name: f"n{i}" for i, box in enumerate(picture.boxes)}
    lines = ["flowchart LR"]
    for box in sorted(picture.boxes, key=lambda b: (b.layer, b.y)):
        label = "<br/>".join([f"<b>{box.name}</b>", box.short_type, *box.settings]).replace('"', "#quot;")
        lines.append(f'  {ids[box.name]}["{label}"]:::{box.role}')
    for edge in picture.edges:
        arrow = "==>" if edge.kind == "exec" else "-.->"
        label = edge.label.replace('"', "#quot;")
        lines.append(f'  {ids[edge.src.split(".", 1)[0]]} {arrow}|"{label}"| {ids[edge.dst.split(".", 1)[0]]}')
    lines += [f"  classDef event fill:{EVENT_FILL},stroke:#8a8f98",
              f"  classDef exec fill:{EXEC_FILL},stroke:#8a8f98",
              f"  classDef pure fill:{PURE_FILL},stroke:#8a8f98"]
    return "\n".join(lines) + "\n"


def _dot_quote(text: str) -> str:
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n") + '"'


def to_dot(picture: Picture) -> str:
    """A Graphviz digraph (rankdir LR, one rank per column): bold exec edges, dashed blue data edges."""
    fills = {"event": EVENT_FILL, "exec": EXEC_FILL, "pure": PURE_FILL}
    lines = [f"digraph {_dot_quote(picture.title)} {{",
             "  rankdir=LR;",
             '  node [shape=box, style="rounded,filled", fontname="Helvetica", fontsize=11];',
             '  edge [fontname="Helvetica", fontsize=9];']
    for box in picture.boxes:
        label = "\n".join([box.name, box.short_type, *box.settings])
        lines.append(f"  {_dot_quote(box.name)} [label={_dot_quote(label)}, fillcolor={_dot_quote(fills[box.role])}, "
                     f"tooltip={_dot_quote(box.type_id)}];")
    for edge in picture.edges:
        style = (f'style=bold, color="{EXEC_COLOUR}", penwidth=2' if edge.kind == "exec"
                 else f'style=dashed, color="{DATA_COLOUR}", fontcolor="{DATA_COLOUR}"')
        lines.append(f"  {_dot_quote(edge.src.split('.', 1)[0])} -> {_dot_quote(edge.dst.split('.', 1)[0])} "
                     f"[label={_dot_quote(edge.label)}, {style}];")
    for layer in sorted({box.layer for box in picture.boxes}):
        members = " ".join(_dot_quote(b.name) + ";" for b in picture.boxes if b.layer == layer)
        lines.append(f"  {{ rank=same; {members} }}")
    lines.append("}")
    return "\n".join(lines) + "\n"


# ---------------------------------------------------------------- PNG

def figure(picture: Picture):
    """The picture as a matplotlib Figure (same geometry as the SVG; 1 px = 1/100 in)."""
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure
    from matplotlib.patches import FancyBboxPatch, PathPatch
    from matplotlib.path import Path as CurvePath

    fig = Figure(figsize=(picture.width / 100, picture.height / 100), dpi=100)
    axes = fig.add_axes((0, 0, 1, 1))
    axes.set_xlim(0, picture.width)
    axes.set_ylim(picture.height, 0)
    axes.axis("off")
    points_per_px = 72 / 100
    for edge in picture.edges:
        vertices, codes = [edge.start], [CurvePath.MOVETO]
        for kind, *points in edge.segments():
            vertices += points
            codes += [CurvePath.CURVE4] * 3 if kind == "C" else [CurvePath.LINETO]
        path = CurvePath(vertices, codes)
        exec_edge = edge.kind == "exec"
        axes.add_patch(PathPatch(path, fill=False, edgecolor=EXEC_COLOUR if exec_edge else DATA_COLOUR,
                                 linewidth=(2.2 if exec_edge else 1.4) * points_per_px,
                                 linestyle="-" if exec_edge else (0, (5, 3)), gid=f"{edge.src}->{edge.dst}"))
        axes.plot(*edge.end, marker=">" if exec_edge else "o", markersize=5 if exec_edge else 3.5,
                  color=EXEC_COLOUR if exec_edge else DATA_COLOUR)
    fills = {"event": EVENT_FILL, "exec": EXEC_FILL, "pure": PURE_FILL}
    font = 11 * points_per_px
    for box in picture.boxes:
        axes.add_patch(FancyBboxPatch((box.x, box.y), box.width, box.height, boxstyle="round,pad=0,rounding_size=7",
                                      facecolor=fills[box.role], edgecolor="#8a8f98", linewidth=0.8, gid=box.name))
        axes.text(box.x + BOX_PADDING, box.y + 16, box.name, fontsize=13 * points_per_px, fontweight="bold",
                  va="baseline", color="#111")
        axes.text(box.x + BOX_PADDING, box.y + 30, box.short_type, fontsize=font, va="baseline", color="#6b7280")
        for port in box.inputs:
            axes.text(box.x + BOX_PADDING, port.y + 4, port.name, fontsize=font, va="baseline", ha="left")
        for port in box.outputs:
            axes.text(box.x + box.width - BOX_PADDING, port.y + 4, port.name, fontsize=font, va="baseline", ha="right")
        settings_top = box.y + HEADER_HEIGHT + max(len(box.inputs), len(box.outputs)) * ROW_HEIGHT
        for i, setting in enumerate(box.settings):
            axes.text(box.x + BOX_PADDING, settings_top + (i + 0.5) * ROW_HEIGHT + 4, setting, fontsize=font,
                      va="baseline", style="italic", color="#374151")
    legend_y = picture.height - MARGIN / 2 - 8
    axes.plot([MARGIN, MARGIN + 34], [legend_y] * 2, color=EXEC_COLOUR, linewidth=2.2 * points_per_px)
    axes.plot(MARGIN + 34, legend_y, marker=">", markersize=5, color=EXEC_COLOUR)
    axes.text(MARGIN + 42, legend_y + 4, "execution", fontsize=font, va="baseline")
    axes.plot([MARGIN + 120, MARGIN + 154], [legend_y] * 2, color=DATA_COLOUR, linewidth=1.4 * points_per_px,
              linestyle=(0, (5, 3)))
    axes.plot(MARGIN + 154, legend_y, marker="o", markersize=3.5, color=DATA_COLOUR)
    axes.text(MARGIN + 162, legend_y + 4, "data", fontsize=font, va="baseline")
    return fig


def write(picture: Picture, path: str | Path, picture_format: str) -> None:
    """Write the picture in one of FORMATS (PNG at 2x for sharp text)."""
    if picture_format == "png":
        figure(picture).savefig(path, dpi=200, facecolor="white")
        return
    text = {"svg": to_svg, "mermaid": to_mermaid, "dot": to_dot}[picture_format](picture)
    Path(path).write_text(text, encoding="utf-8")
