// One scrubbable timeline over every panel: the graph, the scene, the tick's pulses and log, lanes, verdict.
import React, { useCallback, useEffect, useMemo, useRef, useState } from "react";
import GraphView from "./GraphView.jsx";
import SceneView from "./SceneView.jsx";
import Lanes from "./Lanes.jsx";
import NodePanel from "./NodePanel.jsx";
import { formatNumber, indexAt, indexRun, valueAt } from "./data.js";

const SPEEDS = { "1×": 1, "4×": 4, max: Infinity };
const MAX_TICKS_PER_FRAME = 8;

function Header({ run }) {
  const header = run.header;
  const rows = [
    ["graph", header.graph], ["stage", header.stage ?? "none"], ["seed", header.seed],
    ["overrides", header.overrides.length ? header.overrides.join(", ") : "none"],
    ["randomization", Object.keys(header.randomization).length
      ? Object.entries(header.randomization).map(([k, v]) => `${k} = ${JSON.stringify(v)}`).join(", ") : "none"],
    ["run", `${run.ticks} ticks, ${formatNumber(run.times[run.ticks] ?? 0)} s simulated`
      + (header.poseEvery ? `, body poses every ${header.poseEvery} tick(s)` : "")
      + (header.timings ? ", with wall-clock compute times (this file differs from run to run)" : "")],
    ["versions", Object.entries(header.versions).map(([k, v]) => `${k} ${v}`).join(", ")],
  ];
  return (
    <header className="gf-header" data-testid="header">
      <h1>{header.graph}</h1>
      {header.description && <p className="gf-description">{header.description}</p>}
      <dl>{rows.map(([key, value]) => <React.Fragment key={key}><dt>{key}</dt><dd data-field={key}>{String(value)}</dd></React.Fragment>)}</dl>
    </header>
  );
}

function Verdict({ run, onTick }) {
  if (run.checks.length === 0) {
    const why = run.header.judged ? "this graph has no checks" : "not judged: a report made from a trace, or a run whose options changed the scenario";
    return <section className="gf-verdict" data-testid="verdict"><h2>Verdict</h2><p>{why}</p></section>;
  }
  const failed = run.checks.filter((check) => check.passed === false).length;
  return (
    <section className="gf-verdict" data-testid="verdict">
      <h2>Verdict: {failed ? `${failed} of ${run.checks.length} checks failed` : `all ${run.checks.length} checks hold`}</h2>
      <ul>
        {run.checks.map((check) => (
          <li key={check.index} className={check.passed ? "gf-pass" : check.passed === null ? "gf-unjudged" : "gf-fail"}
              data-check={check.index}
              data-passed={String(check.passed)} data-tick={check.tick ?? ""}
              onClick={() => check.tick !== null && onTick(check.tick)}>
            <b>{check.passed ? "PASS" : check.passed === null ? "NOT JUDGED" : "FAIL"}</b> {check.label}
            {check.passed === false && <div className="gf-reason-text">measured {check.measured}; expected {check.expected}
              {check.tick !== null && <> — at tick {check.tick} (t = {formatNumber(check.t)} s)</>}</div>}
          </li>
        ))}
      </ul>
    </section>
  );
}

function TickPanel({ run, index, tick }) {
  const pulses = useMemo(() => {
    const entry = run.pulses.find(([at]) => at === tick);
    return entry ? entry[1] : [];
  }, [run, tick]);
  const logs = run.log.filter(([at]) => at === tick);
  const closeIndex = indexAt(run.rays, tick, (close) => close.tick);
  const close = closeIndex >= 0 ? run.rays[closeIndex] : null;
  return (
    <section className="gf-tick" data-testid="tick-panel">
      <h2>Tick {tick} · t = {formatNumber(run.times[tick] ?? 0)} s</h2>
      <h3>Exec pulses, in order</h3>
      <ol className="gf-pulses" data-testid="pulses">
        {pulses.length === 0 && <li className="gf-none">none</li>}
        {pulses.map((pulse, order) => {
          const [key, state] = pulse.split(":");
          const targets = index.execTargets[key] || [];
          return <li key={order} data-pulse={pulse}>{key}{state ? ` (${state})` : ""} → {targets.length ? targets.join(", ") : "nothing connected"}</li>;
        })}
      </ol>
      {close && (<><h3>Last close: {close.gripper.split("/").pop()} at tick {close.tick}</h3>
        <ul className="gf-rays" data-testid="rays">{close.rays.map((ray) => (
          <li key={ray.point} data-point={ray.point} data-reach={ray.reach} data-hit={ray.hit ? ray.hit.prim : ""}
              data-hit-distance={ray.hit ? ray.hit.distance : ""}>
            {ray.point.split("/").pop()}: reach {(ray.reach * 1000).toFixed(1)} mm;{" "}
            {ray.hit ? `nearest hit ${ray.hit.prim} at ${(ray.hit.distance * 1000).toFixed(1)} mm${ray.hit.distance > ray.reach ? " (beyond reach)" : ""}`
              : "nothing within 1 m"}
          </li>))}</ul></>)}
      {logs.length > 0 && (<><h3>Log</h3><ul className="gf-log">{logs.map(([, node, level, message], i) =>
        <li key={i} className={`gf-log-${level}`}>{node}: {message}</li>)}</ul></>)}
    </section>
  );
}

export default function App({ run }) {
  const index = useMemo(() => indexRun(run), [run]);
  const [tick, setTickState] = useState(0);
  const [playing, setPlaying] = useState(false);
  const [speed, setSpeed] = useState("1×");
  const [selected, setSelected] = useState(null);
  const [pinned, setPinned] = useState([]);
  const sceneRef = useRef(null);
  const setTick = useCallback((value) => setTickState(Math.max(0, Math.min(run.ticks, Math.round(value)))), [run]);
  const held = useMemo(() => {
    const paths = new Set();
    for (const gripper of Object.values(run.grippers)) for (const path of valueAt(gripper.gripped, tick) || []) paths.add(path);
    return paths;
  }, [run, tick]);

  useEffect(() => {   // playback: 1× follows simulated time, 4× four times faster, max as fast as frames come
    if (!playing) return undefined;
    let frame;
    let last = performance.now();
    let carried = 0;
    const step = (now) => {
      const factor = SPEEDS[speed];
      if (factor === Infinity) carried += MAX_TICKS_PER_FRAME;
      else carried += ((now - last) / 1000) * factor / (run.header.timeStep || 1 / 60);
      last = now;
      const advance = Math.floor(carried);
      carried -= advance;
      setTickState((current) => {
        const next = Math.min(run.ticks, current + advance);
        if (next >= run.ticks) setPlaying(false);
        return next;
      });
      frame = requestAnimationFrame(step);
    };
    frame = requestAnimationFrame(step);
    return () => cancelAnimationFrame(frame);
  }, [playing, speed, run]);

  useEffect(() => {   // keyboard: space play/pause, arrows step (shift: 10), home/end, 1/4/m speed
    const onKey = (event) => {
      if (event.target.tagName === "INPUT" && event.target.type !== "range") return;
      const big = event.shiftKey ? 10 : 1;
      const actions = {
        " ": () => setPlaying((p) => !p), ArrowRight: () => setTickState((t) => Math.min(run.ticks, t + big)),
        ArrowLeft: () => setTickState((t) => Math.max(0, t - big)), Home: () => setTick(0), End: () => setTick(run.ticks),
        1: () => setSpeed("1×"), 4: () => setSpeed("4×"), m: () => setSpeed("max"), Escape: () => setSelected(null),
      };
      const action = actions[event.key];
      if (action) {
        event.preventDefault();
        action();
      }
    };
    window.addEventListener("keydown", onKey);
    return () => window.removeEventListener("keydown", onKey);
  }, [run, setTick]);

  useEffect(() => {   // what tests and scripts read: the shown tick and the rendered scene
    window.graphflowReport = {
      tick: () => tick,
      ticks: run.ticks,
      setTick,
      bodyPosition: (path) => {
        const body = sceneRef.current?.bodies[path];
        return body ? body.group.position.toArray() : null;
      },
      shownRays: () => (sceneRef.current?.shownClose ?? null),
      drawnAt: performance.now(),   // when this tick's panels and scene were drawn (the scrub benchmark)
    };
    document.body.dataset.tick = String(tick);
  }, [tick, setTick, run]);

  return (
    <div className="gf-app">
      <Header run={run} />
      <div className="gf-controls" data-testid="controls">
        <button onClick={() => setTick(tick - 1)} title="previous tick (←)">◀</button>
        <button onClick={() => setPlaying(!playing)} title="play / pause (space)" data-testid="play">{playing ? "❚❚" : "▶"}</button>
        <button onClick={() => setTick(tick + 1)} title="next tick (→)">▶|</button>
        {Object.keys(SPEEDS).map((name) => (
          <button key={name} className={speed === name ? "gf-on" : ""} onClick={() => setSpeed(name)}>{name}</button>
        ))}
        <input type="range" min={0} max={run.ticks} value={tick} onChange={(e) => setTick(Number(e.target.value))}
               data-testid="slider" aria-label="tick" />
        <span className="gf-tick-label" data-testid="tick">tick {tick} / {run.ticks} · {formatNumber(run.times[tick] ?? 0)} s</span>
        <span className="gf-keys">space play · ←/→ step (shift ×10) · home/end · 1/4/m speed</span>
      </div>
      <div className="gf-main">
        <GraphView run={run} index={index} tick={tick} selected={selected} onSelect={setSelected} />
        <SceneView run={run} tick={tick} held={held} onReady={(scene) => { sceneRef.current = scene; }} />
        <aside className="gf-side">
          {selected
            ? <NodePanel run={run} index={index} name={selected} tick={tick} onTick={setTick} onClose={() => setSelected(null)}
                         onPin={(key) => setPinned((list) => (list.includes(key) ? list : [...list, key]))} />
            : <TickPanel run={run} index={index} tick={tick} />}
        </aside>
      </div>
      <Lanes run={run} tick={tick} pinned={pinned} onTick={setTick} onUnpin={(key) => setPinned((l) => l.filter((k) => k !== key))} />
      <Verdict run={run} onTick={setTick} />
    </div>
  );
}
