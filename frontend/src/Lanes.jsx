// Lanes under one time axis: controller phases, gripper status (reasons at changes), held objects,
// constraint force against its limits, pinned values, and the failed checks marked where they failed.
import React, { useMemo } from "react";
import { formatValue, shortValue } from "./data.js";

const WIDTH = 1000;
const LANE = 26;
const PLOT = 60;
const PALETTE = ["#cfe3fa", "#fde2c2", "#d8f0d2", "#f4d3e6", "#e4dcf7", "#fbf3c0", "#d0ecec", "#f6d6cf"];
const STATUS = { Open: "#e5e7eb", Closing: "#fde68a", Closed: "#86efac" };

function spans(changes, ticks) {
  const result = [];
  changes.forEach(([tick, value], index) => {
    const end = index + 1 < changes.length ? changes[index + 1][0] : ticks;
    if (end > tick || index === changes.length - 1) result.push({ start: tick, end: Math.max(end, tick + 1), value });
  });
  return result;
}

function laneText(value, limit) {
  const text = typeof value === "string" ? value : shortValue(value, limit);
  return text.length > limit ? text.slice(0, Math.max(1, limit - 1)) + "…" : text;
}

function SpanLane({ label, changes, ticks, colour, testid }) {
  const colours = {};
  return (
    <g data-testid={testid}>
      {spans(changes, ticks).map((span) => {
        const key = formatValue(span.value);
        colours[key] ||= colour ? colour(span.value) : PALETTE[Object.keys(colours).length % PALETTE.length];
        const x = (span.start / ticks) * WIDTH;
        const width = Math.max(0.5, ((span.end - span.start) / ticks) * WIDTH);
        return (
          <g key={span.start}>
            <rect x={x} y={2} width={width} height={LANE - 4} fill={colours[key]} stroke="#fff" strokeWidth="0.5">
              <title>{`${label}: ${laneText(span.value, 200)} (ticks ${span.start}–${span.end})`}</title>
            </rect>
            {width > 40 && <text x={x + 3} y={LANE / 2 + 4} className="gf-lane-text">{laneText(span.value, Math.floor(width / 6))}</text>}
          </g>
        );
      })}
    </g>
  );
}

function PlotLane({ changes, ticks, limits = [] }) {
  const numeric = changes.filter(([, value]) => typeof value === "number" && Number.isFinite(value));
  const peak = Math.max(1e-9, ...numeric.map(([, v]) => Math.abs(v)));
  // a limit far above the values would flatten them: it is drawn only when within 3x the peak, else named
  const shown = [];
  for (const limit of limits) {
    const same = shown.find((other) => other.value === limit.value);
    if (same) same.name += ` / ${limit.name}`;
    else shown.push({ ...limit });
  }
  const maximum = Math.max(peak, ...shown.filter((l) => l.value <= 3 * peak).map((l) => l.value)) * 1.05;
  const minimum = Math.min(0, ...numeric.map(([, v]) => v));
  const y = (value) => PLOT - 3 - ((value - minimum) / (maximum - minimum)) * (PLOT - 8);
  let points = "";
  changes.forEach(([tick, value], index) => {
    if (typeof value !== "number" || !Number.isFinite(value)) return;
    const x = (tick / ticks) * WIDTH;
    const previous = index > 0 ? changes[index - 1][1] : null;
    if (typeof previous === "number" && Number.isFinite(previous)) points += `${x},${y(previous)} `;
    points += `${x},${y(value)} `;
  });
  const offScale = shown.filter((limit) => limit.value > maximum);
  return (
    <g>
      <polyline points={points} fill="none" stroke="#2a7bd6" strokeWidth="1.2" vectorEffect="non-scaling-stroke" />
      {shown.filter((limit) => limit.value <= maximum).map((limit) => (
        <g key={limit.name}>
          <line x1={0} x2={WIDTH} y1={y(limit.value)} y2={y(limit.value)} stroke="#d64545" strokeDasharray="6 4"
                vectorEffect="non-scaling-stroke" />
          <text x={WIDTH - 4} y={y(limit.value) - 2} textAnchor="end" className="gf-lane-text gf-limit">
            {`${limit.name} limit ${formatValue(limit.value)}`}
          </text>
        </g>
      ))}
      <text x={4} y={10} className="gf-lane-text">{numeric.length ? `peak ${formatValue(peak)}` : "nothing held"}
        {offScale.length > 0 && `; ${offScale.map((l) => `${l.name} limit ${formatValue(l.value)}`).join(", ")} (off scale)`}</text>
    </g>
  );
}

const nodeOf = (key) => key.slice(0, key.lastIndexOf("."));   // "node.port" -> node

export function laneList(run, pinned) {
  const lanes = [];
  for (const key of run.phases) {
    if (run.outputs[key]) lanes.push({ id: `phase:${key}`, label: `phase ${key}`, kind: "span", changes: run.outputs[key],
                                         node: nodeOf(key) });
  }
  for (const [path, gripper] of Object.entries(run.grippers)) {
    const name = path.split("/").pop();
    if (gripper.status) lanes.push({ id: `status:${path}`, label: `${name} status`, kind: "status", changes: gripper.status, reasons: gripper.reason || [],
                                    gripper: path });
    if (gripper.gripped) lanes.push({ id: `held:${path}`, label: `${name} holds`, kind: "span", gripper: path,
                                      changes: gripper.gripped.map(([t, v]) => [t, v && v.length ? v.join(", ") : "nothing"]) });
    if (gripper.force) lanes.push({ id: `force:${path}`, label: `${name} force (N)`, kind: "plot", changes: gripper.force, gripper: path,
                                    limits: run.limits[path] || [] });
  }
  for (const key of pinned) {
    const changes = run.outputs[key] || [];
    const numeric = changes.some(([, value]) => typeof value === "number");
    lanes.push({ id: `pin:${key}`, label: `📌 ${key}`, kind: numeric ? "plot" : "span", changes, pin: key, node: nodeOf(key) });
  }
  return lanes;
}

/** The lane drawn at *y* (px from the top of the plot), given each lane's height, or null between lanes. */
function laneAt(lanes, heights, y) {
  let top = 0;
  for (let index = 0; index < lanes.length; index += 1) {
    if (y >= top && y < top + heights[index]) return lanes[index];
    top += heights[index] + 4;
  }
  return null;
}

// onTick(tick): a click jumps there (the report); onPick(lane, tick), when given, is told the lane clicked too
// (a live run cannot jump back: the studio selects the lane's node and shows the lane's value at that tick)
export default function Lanes({ run, tick, pinned, onTick, onUnpin, onPick }) {
  const lanes = useMemo(() => laneList(run, pinned), [run, pinned]);
  const ticks = Math.max(1, run.ticks);
  const failures = run.checks.filter((check) => check.passed === false && check.tick !== null);
  const heights = lanes.map((lane) => (lane.kind === "plot" ? PLOT : LANE));
  const total = heights.reduce((a, b) => a + b + 4, 0);
  const jump = (event) => {
    const box = event.currentTarget.getBoundingClientRect();
    const at = Math.round(((event.clientX - box.left) / box.width) * ticks);
    if (onPick) onPick(laneAt(lanes, heights, ((event.clientY - box.top) / box.height) * total), at);
    else onTick(at);
  };
  let top = 0;
  if (lanes.length === 0 && failures.length === 0) {
    return <div className="gf-lanes gf-none" data-testid="lanes">no lanes: this run has no controller or gripper; pin an output (📌 in a node's panel) to plot it here</div>;
  }
  return (
    <div className="gf-lanes" data-testid="lanes">
      <div className="gf-lane-labels">
        {lanes.map((lane, index) => (
          <div key={lane.id} style={{ height: heights[index] + 4 }} className="gf-lane-label">
            {lane.label}
            {lane.pin && <button className="gf-unpin" title="unpin" onClick={() => onUnpin(lane.pin)}>×</button>}
          </div>
        ))}
      </div>
      <svg viewBox={`0 0 ${WIDTH} ${total}`} preserveAspectRatio="none" style={{ height: total }} onClick={jump}
           className="gf-lane-plot">
        {lanes.map((lane, index) => {
          const y = top;
          top += heights[index] + 4;
          return (
            <g key={lane.id} transform={`translate(0 ${y})`}>
              {lane.kind === "plot" ? (
                <PlotLane changes={lane.changes} ticks={ticks} limits={lane.limits} />
              ) : (
                <SpanLane label={lane.label} changes={lane.changes} ticks={ticks} testid={lane.id}
                          colour={lane.kind === "status" ? (value) => STATUS[value] || "#e5e7eb" : null} />
              )}
              {lane.kind === "status" && lane.reasons.filter(([, reason]) => reason).map(([at, reason]) => (
                <g key={`r${at}`} className="gf-reason" data-tick={at}>
                  <circle cx={(at / ticks) * WIDTH} cy={LANE / 2} r={4} fill="#b91c1c" />
                  <title>{`tick ${at}: ${reason}`}</title>
                </g>
              ))}
            </g>
          );
        })}
        {failures.map((check) => (
          <line key={`f${check.index}`} x1={(check.tick / ticks) * WIDTH} x2={(check.tick / ticks) * WIDTH} y1={0} y2={total}
                stroke="#dc2626" strokeWidth="2" vectorEffect="non-scaling-stroke" className="gf-failure-mark"
                data-check={check.index} data-tick={check.tick} />
        ))}
        <line x1={(tick / ticks) * WIDTH} x2={(tick / ticks) * WIDTH} y1={0} y2={total} stroke="#111827"
              strokeWidth="1.5" vectorEffect="non-scaling-stroke" />
      </svg>
    </div>
  );
}
