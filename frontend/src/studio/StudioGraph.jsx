// The graph being edited, in React Flow: one handle per port of the node's spec, connections only
// between ports whose types the runtime lets connect (palette.connects is graphflow.types.can_connect),
// problems marked on the node and port they name, live values on the wires and computed nodes lit. The
// nodes and edges handed to React Flow change only with the graph: a live frame redraws the labels and
// highlights that read a changed value (liveStore.js), and React Flow lays nothing out again.
import React, { memo, useEffect, useMemo, useRef, useState } from "react";
import { BaseEdge, Background, Controls, EdgeLabelRenderer, Handle, Position, ReactFlow, applyNodeChanges, getBezierPath } from "@xyflow/react";
import { formatValue, shortValue } from "../data.js";
import { useLive } from "./liveStore.js";

const ROW = 18;
const TOP = 40;

const EditNode = memo(function EditNode({ data }) {
  const { node, type, problems, selected } = data;
  const computed = useLive((live) => Boolean(live?.computed.has(node.name)));
  const inputs = type ? type.inputs : [];
  const outputs = type ? type.outputs : [];
  const flagged = new Set(problems.map((problem) => problem.attribute));
  const classes = ["gf-node", "gf-edit-node"];
  if (problems.length) classes.push("gf-has-problem");
  if (computed) classes.push("gf-computed");
  if (selected) classes.push("gf-selected");
  return (
    <div className={classes.join(" ")} data-node={node.name} data-problems={problems.length}
         data-computed={computed ? "true" : "false"}
         style={{ height: TOP + ROW * Math.max(inputs.length, outputs.length, 1) + 6 }}
         title={problems.map((problem) => problem.message).join("\n")}>
      <div className="gf-node-name">{node.name}</div>
      <div className="gf-node-type">{type ? type.uiName : `unknown type ${node.type}`}</div>
      {inputs.map((port, row) => (
        <React.Fragment key={`i-${port.name}`}>
          <Handle type="target" position={Position.Left} id={port.name} style={{ top: TOP + ROW * row + 8 }}
                  className={port.execution ? "gf-handle-exec" : "gf-handle-data"} data-port={`inputs:${port.name}`} />
          <span className={`gf-port gf-port-in${flagged.has(`inputs:${port.name}`) ? " gf-port-problem" : ""}`}
                data-port-label={`inputs:${port.name}`} style={{ top: TOP + ROW * row }}>{port.name}</span>
        </React.Fragment>
      ))}
      {outputs.map((port, row) => (
        <React.Fragment key={`o-${port.name}`}>
          <Handle type="source" position={Position.Right} id={port.name} style={{ top: TOP + ROW * row + 8 }}
                  className={port.execution ? "gf-handle-exec" : "gf-handle-data"} data-port={`outputs:${port.name}`} />
          <span className={`gf-port gf-port-out${flagged.has(`outputs:${port.name}`) ? " gf-port-problem" : ""}`}
                style={{ top: TOP + ROW * row }}>{port.name}</span>
        </React.Fragment>
      ))}
    </div>
  );
});

function WireValue({ wire, x, y }) {   // redrawn only when this wire's value changes
  const value = useLive((live) => live?.outputs[wire]);
  if (value === undefined) return null;
  return (
    <EdgeLabelRenderer>
      <div className="gf-wire-value nodrag nopan" data-wire={wire} data-value={JSON.stringify(value)}
           title={`${wire} = ${formatValue(value)}`}
           style={{ transform: `translate(-50%, -50%) translate(${x}px, ${y}px)` }}>
        {shortValue(value, 30)}
      </div>
    </EdgeLabelRenderer>
  );
}

function LiveEdge({ id, sourceX, sourceY, targetX, targetY, sourcePosition, targetPosition, data, style }) {
  const [path, labelX, labelY] = getBezierPath({ sourceX, sourceY, sourcePosition, targetX, targetY, targetPosition });
  return (
    <>
      <BaseEdge id={id} path={path} style={style} />
      <WireValue wire={data.wire} x={labelX} y={labelY} />
    </>
  );
}

const nodeTypes = { edit: EditNode };
const edgeTypes = { live: LiveEdge };

export default function StudioGraph({ graph, typesById, problems, positions, selected, onSelect, onMove,
                                      onNodesChange, onConnect, onDisconnect }) {
  // after an edit, a node is rebuilt (and redrawn) only when something it shows changed
  const previous = useRef({});
  const derived = useMemo(() => graph.nodes.map((node) => {
    const data = { node, type: typesById[node.type], problems: problems.filter((problem) => problem.node === node.name),
                   selected: selected === node.name };
    const position = positions[node.name] || { x: 0, y: 0 };
    const last = previous.current[node.name];
    if (last && last.position === position && Object.keys(data).every((key) => key === "problems"
        ? last.data.problems.length === data.problems.length && last.data.problems.every((p, i) => p === data.problems[i])
        : last.data[key] === data[key])) return last;
    return (previous.current[node.name] = { id: node.name, type: "edit", position, data });
  }), [graph, typesById, problems, positions, selected]);
  // React Flow measures nodes through change events: keep its measurements, take everything else from the graph
  const [nodes, setNodes] = useState([]);
  useEffect(() => setNodes((current) => {
    const measured = Object.fromEntries(current.map((node) => [node.id, node.measured]));
    const kept = Object.fromEntries(current.map((node) => [node.id, node]));
    return derived.map((node) => (kept[node.id] && kept[node.id].data === node.data && kept[node.id].position === node.position
      ? kept[node.id] : { ...node, measured: measured[node.id] }));
  }), [derived]);
  const changed = (changes) => {
    setNodes((current) => applyNodeChanges(changes, current));
    onNodesChange(changes);
  };
  const edges = useMemo(() => (graph.connections || []).map((connection) => {
    const [source, sourcePort] = connection.src.split(".outputs:");
    const [target, targetPort] = connection.dst.split(".inputs:");
    return { id: `${connection.src}->${connection.dst}`, source, target, sourceHandle: sourcePort, targetHandle: targetPort,
             type: "live", data: { wire: `${source}.${sourcePort}` } };
  }), [graph]);
  return (
    <div className="gf-graph gf-studio-graph" data-testid="graph">
      <ReactFlow nodes={nodes} edges={edges} nodeTypes={nodeTypes} edgeTypes={edgeTypes} fitView minZoom={0.1} proOptions={{ hideAttribution: true }}
                 onNodeClick={(_event, node) => onSelect(node.id)}
                 onNodeDragStop={(_event, node) => onMove(node.id, node.position)}
                 onNodesChange={changed} onConnect={onConnect}
                 onEdgesDelete={(deleted) => deleted.forEach((edge) => onDisconnect(edge.id))}
                 deleteKeyCode={null}>
        <Background gap={24} size={1} />
        <Controls showInteractive={false} />
      </ReactFlow>
    </div>
  );
}
