// Every registered node type, searchable by id, UI name and category; a click adds one to the graph.
import React, { useMemo, useState } from "react";

export default function Palette({ types, onAdd }) {
  const [query, setQuery] = useState("");
  const shown = useMemo(() => {
    const words = query.toLowerCase().split(/\s+/).filter(Boolean);
    return types.filter((type) => {
      const text = `${type.id} ${type.uiName} ${type.categories.join(" ")}`.toLowerCase();
      return words.every((word) => text.includes(word));
    });
  }, [types, query]);
  return (
    <aside className="gf-palette" data-testid="palette">
      <input type="search" placeholder="search node types" value={query} aria-label="search node types"
             onChange={(event) => setQuery(event.target.value)} />
      <ul>
        {shown.slice(0, 200).map((type) => (
          <li key={type.id} data-type={type.id} title={type.description}>
            <button type="button" onClick={() => onAdd(type)}>
              <b>{type.uiName}</b> <span className="gf-palette-id">{type.id}</span>
              {type.categories.length > 0 && <span className="gf-palette-cat">{type.categories.join(", ")}</span>}
            </button>
          </li>
        ))}
      </ul>
    </aside>
  );
}
