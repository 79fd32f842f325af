// The selected node: rename, delete, and its authored inputs with widgets from the spec
// (tokens as menus, numbers with the spec's range, booleans as boxes, anything else as JSON).
import React, { useState } from "react";
import { shortValue } from "../data.js";
import PrimPicker from "./PrimPicker.jsx";
import { useLive } from "./liveStore.js";

/** Inputs that take a value here: not execution or bundle ports, which only connections set. */
const valued = (port) => !port.execution && port.type !== "bundle";

function parsedValue(port, text) {
  if (port.tokens) return text;
  if (/^(u?int|int64|uint64|double|float|half)$/.test(port.type)) return Number(text);
  if (port.type === "string" || port.type === "token" || port.type === "path") return text;
  return JSON.parse(text);
}

function InputWidget({ port, value, onChange }) {
  const shown = value === undefined ? port.default : value;
  const [draft, setDraft] = useState(shown === undefined ? "" : (typeof shown === "string" ? shown : JSON.stringify(shown)));
  const [error, setError] = useState(null);
  if (port.tokens) {
    return (
      <select data-input={port.name} value={shown ?? ""} onChange={(event) => onChange(event.target.value)}>
        {port.tokens.map((token) => <option key={token} value={token}>{token}</option>)}
      </select>
    );
  }
  if (port.type === "bool") {
    return <input type="checkbox" data-input={port.name} checked={Boolean(shown)} onChange={(event) => onChange(event.target.checked)} />;
  }
  const numeric = /^(u?int|int64|uint64|double|float|half)$/.test(port.type);
  const commit = () => {
    try {
      const next = parsedValue(port, draft);
      if (numeric && (Number.isNaN(next) || (port.minimum !== undefined && next < port.minimum)
          || (port.maximum !== undefined && next > port.maximum))) {
        throw new Error(`${port.name} takes a number in [${port.minimum ?? "-∞"}, ${port.maximum ?? "∞"}]`);
      }
      setError(null);
      onChange(next);
    } catch (problem) {
      setError(problem.message);
    }
  };
  return (
    <span>
      <input type={numeric ? "number" : "text"} data-input={port.name} value={draft} min={port.minimum} max={port.maximum}
             onChange={(event) => setDraft(event.target.value)} onBlur={commit}
             onKeyDown={(event) => event.key === "Enter" && commit()} />
      {error && <span className="gf-problem" data-widget-error={port.name}>{error}</span>}
    </span>
  );
}

function LiveValue({ wire }) {   // one output's value, redrawn only when that value changes
  const value = useLive((live) => live?.outputs[wire]);
  return <td data-output={wire}>{shortValue(value)}</td>;
}

function LiveOutputs({ node, type, pinned, onPin }) {
  const ports = type ? type.outputs.filter((port) => !port.execution) : [];
  return (
    <table className="gf-live-outputs" data-testid="live-outputs">
      <tbody>
        {ports.map((port) => {
          const key = `${node.name}.${port.name}`;
          return (
            <tr key={key}>
              <th>{port.name}</th>
              <LiveValue wire={key} />
              <td><button type="button" data-pin={key} disabled={pinned.includes(key)} title="plot it in the lanes"
                          onClick={() => onPin(key)}>pin</button></td>
            </tr>
          );
        })}
      </tbody>
    </table>
  );
}

export default function Inspector({ node, type, problems, onRename, onDelete, onInput, live, pinned, onPin, stagePrims }) {
  const [name, setName] = useState(node.name);
  const mine = problems.filter((problem) => problem.node === node.name);
  const authored = node.inputs || {};
  return (
    <section className="gf-inspector" data-testid="inspector" data-node={node.name}>
      <h2>{node.name} <small>{node.type}</small></h2>
      {type && <p className="gf-description">{type.description}</p>}
      <label>name <input data-field="name" value={name} onChange={(event) => setName(event.target.value)}
                         onBlur={() => name !== node.name && onRename(name)}
                         onKeyDown={(event) => event.key === "Enter" && name !== node.name && onRename(name)} /></label>
      <button type="button" data-action="delete" onClick={onDelete}>delete node</button>
      {mine.filter((problem) => !(type && type.inputs.some((port) => valued(port) && problem.attribute === `inputs:${port.name}`)))
        .map((problem, index) => <div key={index} className="gf-problem">{problem.message}</div>)}
      <table>
        <tbody>
          {(type ? type.inputs.filter(valued) : []).map((port) => (
            <tr key={`${node.name}-${port.name}`} title={`${port.type}: ${port.description}`}>
              <th>{port.name}</th>
              <td>{port.primKind
                ? <PrimPicker name={port.name} value={authored[port.name]} kind={port.primKind} stagePrims={stagePrims}
                              many={port.type.endsWith("[]") || Array.isArray(authored[port.name])}
                              onChange={(value) => onInput(port.name, value)} />
                : <InputWidget port={port} value={authored[port.name]} onChange={(value) => onInput(port.name, value)} />}
                {mine.filter((problem) => problem.attribute === `inputs:${port.name}`).map((problem, index) => (
                  <div key={index} className="gf-problem" data-port-problem={port.name}>{problem.message}</div>))}</td>
            </tr>
          ))}
        </tbody>
      </table>
      {live && <><h3>Outputs, live</h3><LiveOutputs node={node} type={type} pinned={pinned} onPin={onPin} /></>}
    </section>
  );
}
