// The run's data as graphflow.report embeds it, and the look-ups every panel shares.

/** The run data from the page's <script id="graphflow-run" type="application/json">. */
export function readRun(doc = document) {
  const element = doc.getElementById("graphflow-run");
  if (!element) throw new Error("this page holds no graphflow run data");
  return JSON.parse(element.textContent);
}

/** The value of a change list ([[tick, value], ...], ticks ascending) at a tick: the last change at or before it. */
export function valueAt(changes, tick) {
  if (!changes || changes.length === 0 || changes[0][0] > tick) return undefined;
  let low = 0;
  let high = changes.length - 1;
  while (low < high) {
    const middle = (low + high + 1) >> 1;
    if (changes[middle][0] <= tick) low = middle;
    else high = middle - 1;
  }
  return changes[low][1];
}

/** The index of the last entry of a tick-sorted list at or before a tick, or -1. */
export function indexAt(entries, tick, tickOf = (entry) => entry[0]) {
  let low = 0;
  let high = entries.length - 1;
  let found = -1;
  while (low <= high) {
    const middle = (low + high) >> 1;
    if (tickOf(entries[middle]) <= tick) {
      found = middle;
      low = middle + 1;
    } else high = middle - 1;
  }
  return found;
}

/** Short text for a value on a wire: numbers to 4 significant digits, arrays shortened, a bundle by its size. */
export function shortValue(value, limit = 40) {
  const text = isBundle(value) ? bundleSummary(value) : formatValue(value);
  return text.length > limit ? text.slice(0, limit - 1) + "…" : text;
}

/** A bundle as traces write it: {attributes: {name: value, ...}} with children: [...] when it has any. */
export function isBundle(value) {
  if (value === null || typeof value !== "object" || Array.isArray(value)) return false;
  const keys = Object.keys(value);
  return typeof value.attributes === "object" && !Array.isArray(value.attributes)
    && keys.every((key) => key === "attributes" || (key === "children" && Array.isArray(value.children)));
}

export function bundleSummary(value) {
  const count = Object.keys(value.attributes).length;
  const children = value.children ? value.children.length : 0;
  return `{${count} attribute${count === 1 ? "" : "s"}`
    + (children ? `, ${children} child${children === 1 ? "" : "ren"}` : "") + "}";
}

export function formatValue(value) {
  if (value === undefined) return "–";
  if (value === null) return "null";
  if (typeof value === "number") return formatNumber(value);
  if (typeof value === "string") return JSON.stringify(value);
  if (Array.isArray(value)) return "[" + value.map(formatValue).join(", ") + "]";
  if (typeof value === "object") return "{" + Object.entries(value).map(([k, v]) => `${k}: ${formatValue(v)}`).join(", ") + "}";
  return String(value);
}

export function formatNumber(value) {
  if (!Number.isFinite(value)) return String(value);
  if (Number.isInteger(value)) return String(value);
  const magnitude = Math.abs(value);
  if (magnitude !== 0 && (magnitude < 1e-3 || magnitude >= 1e5)) return value.toExponential(3);
  return String(Number(value.toPrecision(4)));
}

/** Derived look-ups built once per run: exec targets of every output, latent spans per node. */
export function indexRun(run) {
  const execTargets = {};
  for (const edge of run.graph.edges) {
    if (edge.kind !== "exec") continue;
    const source = edge.src.replace(".outputs:", ".");
    (execTargets[source] ||= []).push(edge.dst.replace(".inputs:", "."));
  }
  const latent = {};
  for (const [tick, pulses] of run.pulses) {
    for (const pulse of pulses) {
      const [key, state] = pulse.split(":");
      const node = key.slice(0, key.lastIndexOf("."));
      if (state === "latentPush") (latent[node] ||= []).push([tick, "running"]);
      if (state === "latentFinish") (latent[node] ||= []).push([tick, "finished"]);
    }
  }
  const nodeIndex = Object.fromEntries(run.graph.nodes.map((node, index) => [node.name, index]));
  return { execTargets, latent, nodeIndex };
}

/** The tick shown for a time in seconds: the first tick at or after it. */
export function tickAtTime(run, seconds) {
  const index = indexAt(run.times, seconds, (t) => t);
  return Math.min(run.ticks, Math.max(0, index));
}

/** A body's pose at a tick from its samples ([[tick, [x, y, z, qx, qy, qz, qw]], ...]): between two samples
 * the position is interpolated linearly and the rotation along the shorter arc (normalised lerp). */
export function poseAt(track, tick) {
  const index = indexAt(track, tick);
  if (index < 0) return undefined;
  const [start, from] = track[index];
  if (index + 1 >= track.length || start === tick) return from;
  const [end, to] = track[index + 1];
  const f = (tick - start) / (end - start);
  const sign = from[3] * to[3] + from[4] * to[4] + from[5] * to[5] + from[6] * to[6] < 0 ? -1 : 1;
  const pose = from.map((value, i) => value + ((i >= 3 ? sign : 1) * to[i] - value) * f);
  const norm = Math.hypot(pose[3], pose[4], pose[5], pose[6]) || 1;
  for (let i = 3; i < 7; i += 1) pose[i] /= norm;
  return pose;
}
