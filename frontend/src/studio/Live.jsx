// The live run's controls (play, pause, step, reset, speed, save as report), its gripper fields and verdict,
// and the on-screen gamepad: pad 0's D-pad, face buttons and left stick, for the gamepad nodes.
import React, { memo } from "react";
import { useLive } from "./liveStore.js";

const SPEEDS = [["1×", 1], ["4×", 4], ["max", null]];
const NONE = {};
const NO_LINES = [];
const BUTTONS = ["D-Pad Up", "D-Pad Down", "D-Pad Left", "D-Pad Right", "Face Button Bottom", "Face Button Right"];

export function LiveBar({ send }) {
  const live = useLive((state) => state);   // the bar shows the tick: it is the one part redrawn on every frame
  if (!live) return null;
  return (
    <div className="gf-live-bar" data-testid="live-bar" data-tick={live.tick} data-playing={String(live.playing)}>
      <button type="button" data-action="play" onClick={() => send({ command: "play" })}>play</button>
      <button type="button" data-action="pause" onClick={() => send({ command: "pause" })}>pause</button>
      <button type="button" data-action="step" onClick={() => send({ command: "step" })}>step</button>
      <button type="button" data-action="reset" onClick={() => send({ command: "reset" })}>reset</button>
      <select aria-label="speed" data-field="speed" value={String(live.speed)}
              onChange={(event) => send({ command: "speed", value: event.target.value === "null" ? null : Number(event.target.value) })}>
        {SPEEDS.map(([label, value]) => <option key={label} value={String(value)}>{label}</option>)}
      </select>
      <span className="gf-live-tick">tick {live.tick} · t = {live.time.toFixed(3)} s</span>
      <button type="button" data-action="save-report" onClick={() => send({ command: "saveReport", path: live.reportPath })}>
        save as report</button>
      <button type="button" data-action="save-trace" onClick={() => send({ command: "saveTrace", path: live.tracePath })}>
        save trace</button>
      {live.notice && <span className="gf-notice" data-testid="live-notice">{live.notice}</span>}
    </div>
  );
}

function Grippers() {
  const grippers = useLive((live) => live?.grippers ?? NONE);
  return Object.entries(grippers).map(([path, fields]) => (
    <dl key={path} data-gripper={path}>
      <dt>{path}</dt>
      {Object.entries(fields).filter(([, value]) => typeof value !== "object").map(([field, value]) => (
        <dd key={field} data-gripper-field={field}>{field}: {String(value)}</dd>))}
    </dl>
  ));
}

function Verdict() {
  const ended = useLive((live) => live?.ended);
  if (!ended) return null;
  return (
    <p data-testid="live-verdict" data-passed={String(ended.passed)}>
      {ended.passed ? `run ended: all ${ended.checks} checks hold` : `run ended: ${ended.failures.join("; ")}`}
    </p>
  );
}

function Log() {
  const log = useLive((live) => live?.log ?? NO_LINES);
  return <pre className="gf-live-log" data-testid="live-log">{log.map((line) => line.join(" ")).join("\n")}</pre>;
}

// memo: the panel itself never changes while a run plays; its grippers, verdict and log redraw on their own
export const LivePanel = memo(function LivePanel({ send }) {
  const pad = (element, value) => send({ pad: element, value });
  return (
    <section className="gf-live-panel" data-testid="live-panel">
      <h2>Grippers</h2>
      <Grippers />
      <Verdict />
      <h2>Gamepad (pad 0)</h2>
      <div className="gf-pad">
        {BUTTONS.map((element) => (
          <button type="button" key={element} data-pad={element}
                  onPointerDown={() => pad(element, 1)} onPointerUp={() => pad(element, 0)}
                  onPointerLeave={(event) => event.buttons && pad(element, 0)}>{element}</button>
        ))}
        {["Left Stick X Axis", "Left Stick Y Axis"].map((element) => (
          <label key={element}>{element}
            <input type="range" min={-1} max={1} step={0.05} defaultValue={0} data-pad={element}
                   onChange={(event) => pad(element, Number(event.target.value))} />
          </label>
        ))}
      </div>
      <h2>Log</h2>
      <Log />
    </section>
  );
});
