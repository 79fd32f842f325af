// The graph as `graphflow draw` lays it out (positions come from graphflow.draw.layout), in React Flow:
// every data wire labelled with its value at the scrubbed tick, nodes that computed on it highlighted.
import React, { memo, useMemo } from "react";
import { BaseEdge, EdgeLabelRenderer, Handle, Position, ReactFlow, Background, Controls, getBezierPath } from "@xyflow/react";
import { formatValue, shortValue, valueAt } from "./data.js";

const GraphNode = memo(function GraphNode({ data }) {
  const { node, computed, selected, latent, timing } = data;
  const rowTop = (port) => port.y - node.y;
  const classes = ["gf-node", `gf-role-${node.role}`];
  if (computed) classes.push("gf-computed");
  if (selected) classes.push("gf-selected");
  return (
    <div className={classes.join(" ")} style={{ width: node.width, height: node.height }}
         data-node={node.name} data-computed={computed ? "true" : "false"}>
      <div className="gf-node-name">{node.name}</div>
      <div className="gf-node-type">{node.type.split(".").pop()}{latent ? ` · ${latent}` : ""}{timing ? ` · ${timing}` : ""}</div>
      {node.inputs.map((port) => (
        <React.Fragment key={`i-${port.name}`}>
          <Handle type="target" position={Position.Left} id={port.name} className={`gf-handle-${port.kind}`}
                  style={{ top: rowTop(port) }} isConnectable={false} />
          <span className="gf-port gf-port-in" style={{ top: rowTop(port) - 7 }}>{port.name}</span>
        </React.Fragment>
      ))}
      {node.outputs.map((port) => (
        <React.Fragment key={`o-${port.name}`}>
          <Handle type="source" position={Position.Right} id={port.name} className={`gf-handle-${port.kind}`}
                  style={{ top: rowTop(port) }} isConnectable={false} />
          <span className="gf-port gf-port-out" style={{ top: rowTop(port) - 7 }}>{port.name}</span>
        </React.Fragment>
      ))}
      {node.settings.length > 0 && (
        <div className="gf-settings" style={{ top: node.settingsTop }}>
          {node.settings.map((line) => <div key={line}>{line}</div>)}
        </div>
      )}
    </div>
  );
});

function ValueEdge({ id, sourceX, sourceY, targetX, targetY, sourcePosition, targetPosition, data, markerEnd, style }) {
  const [path, labelX, labelY] = getBezierPath({ sourceX, sourceY, sourcePosition, targetX, targetY, targetPosition });
  return (
    <>
      <BaseEdge id={id} path={path} markerEnd={markerEnd} style={style} />
      {data.kind === "data" && (
        <EdgeLabelRenderer>
          <div className="gf-wire-value nodrag nopan" data-wire={data.wire} data-value={JSON.stringify(data.value ?? null)}
               title={`${data.wire} = ${formatValue(data.value)}`}
               style={{ transform: `translate(-50%, -50%) translate(${labelX}px, ${labelY}px)` }}>
            {shortValue(data.value, 34)}
          </div>
        </EdgeLabelRenderer>
      )}
    </>
  );
}

const nodeTypes = { graphflow: GraphNode };
const edgeTypes = { value: ValueEdge };

export default function GraphView({ run, index, tick, selected, onSelect }) {
  const computedNow = useMemo(() => new Set(run.computed[tick] || []), [run, tick]);
  const nodes = useMemo(() => run.graph.nodes.map((node, nodeIndex) => {
    const latentSpans = index.latent[node.name];
    const latent = latentSpans ? valueAt(latentSpans, tick) : undefined;
    const timing = run.timings && run.timings[node.name]
      ? `${(1e6 * run.timings[node.name].seconds / Math.max(1, run.timings[node.name].computes)).toFixed(1)} µs`
      : null;
    return {
      id: node.name, type: "graphflow", position: { x: node.x, y: node.y }, draggable: false,
      data: { node, computed: computedNow.has(nodeIndex), selected: selected === node.name, latent, timing },
    };
  }), [run, index, tick, computedNow, selected]);
  const edges = useMemo(() => run.graph.edges.map((edge) => {
    const [source, sourcePort] = edge.src.split(".outputs:");
    const [target, targetPort] = edge.dst.split(".inputs:");
    const wire = `${source}.${sourcePort}`;
    return {
      id: `${edge.src}->${edge.dst}`, source, target, sourceHandle: sourcePort, targetHandle: targetPort,
      type: "value", className: `gf-edge-${edge.kind}`,
      data: { kind: edge.kind, wire, value: edge.kind === "data" ? valueAt(run.outputs[wire], tick) : undefined },
    };
  }), [run, tick]);
  return (
    <div className="gf-graph" data-testid="graph">
      <ReactFlow nodes={nodes} edges={edges} nodeTypes={nodeTypes} edgeTypes={edgeTypes} fitView minZoom={0.1}
                 nodesConnectable={false} elementsSelectable={false} proOptions={{ hideAttribution: true }}
                 onNodeClick={(_event, node) => onSelect(node.id)}>
        <Background gap={24} size={1} />
        <Controls showInteractive={false} />
      </ReactFlow>
    </div>
  );
}
