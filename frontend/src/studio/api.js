// The studio server's API: every request carries the session token (graphflow/studio/guard.py checks it).

export function studioConfig(doc = document) {
  const element = doc.getElementById("graphflow-studio");
  return element ? JSON.parse(element.textContent) : null;
}

export async function call(config, method, path, body) {
  const response = await fetch(path, {
    method,
    headers: { "X-Graphflow-Token": config.token, ...(body ? { "Content-Type": "application/json" } : {}) },
    body: body ? JSON.stringify(body) : undefined,
  });
  const answer = await response.json();
  return { ...answer, http: response.status };
}

export function liveSocket(config, path) {
  const url = new URL("/api/live", window.location.href);
  url.protocol = url.protocol === "https:" ? "wss:" : "ws:";
  url.search = new URLSearchParams({ token: config.token, path }).toString();
  return new WebSocket(url);
}

/** A node name not yet in the graph: the type's short name, then _2, _3, ... */
export function freeName(nodes, typeId) {
  const base = typeId.split(".").pop().replace(/[^A-Za-z0-9_]/g, "_").replace(/^([A-Z])/, (c) => c.toLowerCase());
  const taken = new Set(nodes.map((node) => node.name));
  if (!taken.has(base)) return base;
  for (let index = 2; ; index += 1) if (!taken.has(`${base}_${index}`)) return `${base}_${index}`;
}
