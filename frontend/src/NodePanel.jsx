// A clicked node: its inputs (wire or authored value), outputs and state at the tick, and over time.
import React from "react";
import { formatValue, indexAt, shortValue, valueAt } from "./data.js";

const HISTORY = 12;

function History({ changes, tick, onTick }) {
  if (!changes) return null;
  const at = indexAt(changes, tick);
  const start = Math.max(0, at - HISTORY + 2);
  return (
    <ul className="gf-history">
      {changes.slice(start, start + HISTORY).map(([when, value], offset) => (
        <li key={when} className={start + offset === at ? "gf-now" : ""} onClick={() => onTick(when)}>
          tick {when}: {shortValue(value, 60)}
        </li>
      ))}
      {changes.length > start + HISTORY && <li className="gf-none">… {changes.length - start - HISTORY} later changes</li>}
    </ul>
  );
}

export default function NodePanel({ run, index, name, tick, onTick, onClose, onPin }) {
  const node = run.graph.nodes[index.nodeIndex[name]];
  const nodeIndex = index.nodeIndex[name];
  const incoming = Object.fromEntries(run.graph.edges.filter((e) => e.dst.startsWith(`${name}.inputs:`))
    .map((e) => [e.dst.split(".inputs:")[1], e.src.replace(".outputs:", ".")]));
  const outputs = Object.keys(run.outputs).filter((key) => key.startsWith(`${name}.`) && !key.slice(name.length + 1).includes("."));
  let computes = 0;
  const computedTicks = [];
  for (let t = 0; t <= tick; t += 1) {
    if ((run.computed[t] || []).includes(nodeIndex)) {
      computes += 1;
      computedTicks.push(t);
    }
  }
  const latent = index.latent[name];
  const timing = run.timings?.[name];
  return (
    <section className="gf-node-panel" data-testid="node-panel" data-node={name}>
      <h2>{name} <button onClick={onClose} title="close (Esc)">×</button></h2>
      <p className="gf-type">{node.type}</p>
      <p>computed {computes} time(s) up to tick {tick}{computedTicks.length ? `, last at tick ${computedTicks[computedTicks.length - 1]}` : ""}
        {(run.computed[tick] || []).includes(nodeIndex) ? " (computed this tick)" : ""}</p>
      {latent && <p>latent state: <b>{valueAt(latent, tick) ?? "not started"}</b></p>}
      {timing && <p>compute time: {(timing.seconds * 1e3).toFixed(2)} ms in {timing.computes} computes (wall clock)</p>}
      <h3>Inputs</h3>
      <ul className="gf-ports">
        {node.inputs.filter((p) => p.kind === "data").map((port) => (
          <li key={port.name}><b>{port.name}</b> ← {incoming[port.name]}: {formatValue(valueAt(run.outputs[incoming[port.name]], tick))}
            <History changes={run.outputs[incoming[port.name]]} tick={tick} onTick={onTick} /></li>
        ))}
        {node.settings.map((line) => <li key={line}>{line} (authored)</li>)}
      </ul>
      <h3>Outputs</h3>
      <ul className="gf-ports">
        {outputs.map((key) => (
          <li key={key} data-output={key}><b>{key.slice(name.length + 1)}</b> = {shortValue(valueAt(run.outputs[key], tick), 80)}
            <button className="gf-pin" onClick={() => onPin(key)} title="pin as a lane">📌</button>
            <History changes={run.outputs[key]} tick={tick} onTick={onTick} /></li>
        ))}
      </ul>
    </section>
  );
}
