// A prim input: the path as text, and a menu of the stage's prims of the kind the port or check names
// (surface gripper, articulation, rigid body...; GET /api/prims reads them from the graph's stage).
import React, { useEffect, useState } from "react";

const ANY = "prim";

/** The prims a picker offers for a kind: those of that kind, or every prim for "prim" (bodies and xforms first). */
export function primsOfKind(prims, kind) {
  if (!prims) return [];
  if (kind && kind !== ANY) return prims.filter((prim) => prim.kinds.includes(kind));
  const rank = (prim) => (prim.kinds.includes("rigid body") || prim.kinds.includes("articulation") ? 0 : prim.kinds.length ? 1 : 2);
  return [...prims].sort((a, b) => rank(a) - rank(b));
}

function shownText(value) {
  if (value === undefined || value === null) return "";
  return Array.isArray(value) ? value.join(", ") : String(value);
}

function valueOf(text, many) {
  const paths = text.split(",").map((part) => part.trim()).filter(Boolean);
  return many ? paths : paths.join(",");
}

export default function PrimPicker({ name, value, kind, stagePrims, many = false, onChange }) {
  const [draft, setDraft] = useState(shownText(value));
  useEffect(() => setDraft(shownText(value)), [value]);
  const offered = primsOfKind(stagePrims && stagePrims.prims, kind);
  const pick = (path) => {
    if (!path) return;
    const next = many ? [...new Set([...(Array.isArray(value) ? value : value ? [value] : []), path])] : path;
    setDraft(shownText(next));
    onChange(next);
  };
  return (
    <span className="gf-prim-picker" data-prim-input={name} data-kind={kind || ANY}>
      <input type="text" value={draft} placeholder={`a ${kind || ANY} path`} data-input={name}
             onChange={(event) => setDraft(event.target.value)}
             onBlur={() => draft !== shownText(value) && onChange(valueOf(draft, many))}
             onKeyDown={(event) => event.key === "Enter" && onChange(valueOf(draft, many))} />
      <select data-picker={name} value="" title={stagePrims?.error || `the stage's ${kind || ANY}s`}
              onChange={(event) => pick(event.target.value)} disabled={!offered.length}>
        <option value="">{stagePrims?.error ? "no stage prims" : offered.length ? `pick a ${kind || ANY}…` : `no ${kind || ANY} on the stage`}</option>
        {offered.map((prim) => (
          <option key={prim.path} value={prim.path}>{prim.path}{prim.type ? ` (${prim.type})` : ""}</option>
        ))}
      </select>
    </span>
  );
}
