// The studio page: palette, editable graph, inspector, save with conflicts shown, and the live run.
// The browser never judges a graph: every edit is sent to /api/check (graphflow validate's own checks).
import React, { useCallback, useEffect, useMemo, useRef, useState } from "react";
import { call, freeName, liveSocket } from "./api.js";
import Palette from "./Palette.jsx";
import Inspector from "./Inspector.jsx";
import StudioGraph from "./StudioGraph.jsx";
import { LiveBar, LivePanel } from "./Live.jsx";
import LiveScene from "./LiveScene.jsx";
import { startView, withFrame } from "./liveView.js";
import { LiveContext, liveStore, withMessage } from "./liveStore.js";
import { ChecksEditor, SettingsEditor, VariablesEditor, problemsAt } from "./DocumentEditors.jsx";

const TABS = ["node", "variables", "checks", "settings"];
const SECTIONS = { variables: ["variables"], checks: ["checks"], settings: ["settings", "scenario"] };
import "./studio.css";

// While a run plays, the page draws its frames at most 10 times a second (the server sends up to 30): without a
// GPU, Chromium composites every drawn frame in software, ~15 ms of a core each on this 2-core machine, whatever
// changed (measured: 0.78 cores drawing 30 a second, 0.42 drawing 10). Frames within INPUT_MS of a key or pad
// change, the frame answering a command, and any frame of a run not playing (paused, stepped, ended) are drawn
// at once. At max speed (or above 4x) a frame is a progress snapshot, hundreds of ticks after the last, not
// animation: the page draws 4 a second then, leaving the core to the run (max speed asks for the run's rate).
const SHOW_MS = 100;
const FAST_SHOW_MS = 250;
const INPUT_MS = 300;
const showEvery = (state) => (state && (state.speed === null || state.speed > 4) ? FAST_SHOW_MS : SHOW_MS);

function portType(typesById, graph, nodeName, group, port) {
  const node = graph.nodes.find((entry) => entry.name === nodeName);
  const type = node && typesById[node.type];
  const found = type && type[group].find((entry) => entry.name === port);
  return found ? found.type : null;
}

function startPositions(graph, layout) {
  const saved = (graph.ui && graph.ui.positions) || {};
  const positions = {};
  graph.nodes.forEach((node, index) => {
    const at = saved[node.name] || (layout && layout[node.name]);
    positions[node.name] = at ? { x: at[0], y: at[1] } : { x: 40 + 260 * (index % 5), y: 40 + 160 * Math.floor(index / 5) };
  });
  return positions;
}

export default function Studio({ config }) {
  const [palette, setPalette] = useState(null);
  const [forms, setForms] = useState(null);
  const [tab, setTab] = useState("node");
  const [stagePrims, setStagePrims] = useState(null);   // {stage, prims} or {stage, error}
  const [stages, setStages] = useState([]);             // what settings.stage may name (packaged assets, the folder's stages)
  const [file, setFile] = useState(null);           // {path, data, revision}
  const [problems, setProblems] = useState([]);
  const [positions, setPositions] = useState({});
  const [selected, setSelected] = useState(null);
  const [notice, setNotice] = useState(null);
  const [conflict, setConflict] = useState(null);
  const [live, setLive] = useState(false);       // a live run was started (its state is in liveNow, not here)
  const liveNow = useMemo(() => liveStore(showEvery), []);
  const [dirty, setDirty] = useState(false);   // edits not saved: a change on disk is then a conflict, not a reload
  const watched = useRef(null);
  const socket = useRef(null);
  const checkCount = useRef(0);
  const [pinned, setPinned] = useState([]);   // outputs plotted in the live lanes
  const pinnedNow = useRef(pinned);
  pinnedNow.current = pinned;
  const view = useRef(null);                  // the live run as the scene and lanes read it (liveView.js)
  const scene = useRef(null);
  const inputAt = useRef(-Infinity);   // when the page last sent a key or pad change: the frames after it are drawn at once
  const commanded = useRef(false);     // a command was sent: the next frame (its answer) is drawn at once
  const sceneReady = useCallback((built) => { scene.current = built; }, []);
  const unpin = useCallback((key) => setPinned((list) => list.filter((item) => item !== key)), []);
  const nodes = file && file.data.nodes;
  const selectLane = useCallback((lane) => {   // a lane's node: its own (phase, pin) or the gripper node naming its gripper
    const naming = nodes.filter((node) => JSON.stringify(node.inputs || {}).includes(JSON.stringify(lane.gripper)));
    const name = lane.node ?? (naming.find((node) => /gripper/i.test(node.type)) ?? naming[0])?.name;
    if (!name) return;
    setSelected(name);
    setTab("node");
  }, [nodes]);

  const load = useCallback(() => call(config, "GET", `/api/graph?path=${encodeURIComponent(config.file)}`).then((opened) => {
    if (opened.http !== 200) return setNotice(opened.error);
    setFile({ path: opened.path, data: opened.data, revision: opened.revision });
    setProblems(opened.problems);
    setPositions(startPositions(opened.data, opened.layout));
    setDirty(false);
  }), [config]);

  useEffect(() => {
    call(config, "GET", "/api/palette").then(setPalette);
    call(config, "GET", "/api/forms").then(setForms);
    if (config.file) load();
  }, [config, load]);

  useEffect(() => {   // watch: the graph or its stage changed on disk -> reload it and re-run a live run
    if (!file) return undefined;
    const timer = setInterval(async () => {
      const now = await call(config, "GET", `/api/revision?path=${encodeURIComponent(file.path)}`);
      const stageChanged = watched.current !== null && watched.current !== now.stage;
      watched.current = now.stage;
      document.body.dataset.watchPolls = String(Number(document.body.dataset.watchPolls || 0) + 1);   // for tests
      const graphChanged = now.revision !== file.revision;
      if (!graphChanged && !stageChanged) return;
      if (graphChanged && dirty) return setNotice("the file changed on disk; saving will show the difference");
      if (graphChanged) await load();
      setNotice(`reloaded: ${graphChanged ? "the graph" : "its stage"} changed on disk`);
      if (socket.current && socket.current.readyState === WebSocket.OPEN) socket.current.send(JSON.stringify({ command: "reset" }));
    }, 1000);
    return () => clearInterval(timer);
  }, [config, file, dirty, load]);

  const stage = file && file.data && file.data.settings ? file.data.settings.stage : undefined;
  useEffect(() => {   // the stage's prims, for the target pickers: read again when settings.stage changes
    if (!file || typeof stage !== "string" || !stage) return setStagePrims(null);
    let current = true;
    call(config, "GET", `/api/prims?path=${encodeURIComponent(file.path)}&stage=${encodeURIComponent(stage)}`).then((answer) => {
      if (current) setStagePrims(answer.http === 200 ? answer : { stage, error: answer.error });
    });
    return () => { current = false; };
  }, [config, file && file.path, stage]);

  const opened = file && file.path;
  useEffect(() => {
    if (opened) call(config, "GET", `/api/stages?path=${encodeURIComponent(opened)}`).then((answer) => setStages(answer.stages || []));
  }, [config, opened]);

  const typesById = useMemo(() => Object.fromEntries((palette ? palette.types : []).map((type) => [type.id, type])), [palette]);

  const edit = useCallback((change) => {
    const data = change(structuredClone(file.data));
    setFile({ ...file, data });
    setDirty(true);
    const count = ++checkCount.current;
    call(config, "POST", "/api/check", { path: file.path, data }).then((checked) => {
      if (count === checkCount.current) setProblems(checked.problems || [{ message: checked.error }]);
    });
  }, [config, file]);

  const addNode = useCallback((type) => {
    const name = freeName(file.data.nodes, type.id);
    setPositions((now) => ({ ...now, [name]: { x: 60, y: 60 + 30 * file.data.nodes.length } }));
    setSelected(name);
    edit((data) => {
      data.nodes.push({ name, type: type.id });
      return data;
    });
  }, [file, edit]);

  const compatible = useCallback((connection) => {
    const source = portType(typesById, file.data, connection.source, "outputs", connection.sourceHandle);
    const target = portType(typesById, file.data, connection.target, "inputs", connection.targetHandle);
    return { source, target, ok: Boolean(source && target && palette.connects[source]?.includes(target)) };
  }, [typesById, file, palette]);

  const connect = useCallback((connection) => {
    const src = `${connection.source}.outputs:${connection.sourceHandle}`;
    const dst = `${connection.target}.inputs:${connection.targetHandle}`;
    const types = compatible(connection);
    if (!types.ok) {
      setNotice(`type error: ${src} (${types.source}) cannot feed ${dst} (${types.target})`);
      return false;
    }
    setNotice(null);
    edit((data) => {
      data.connections = [...(data.connections || []), { src, dst }];
      return data;
    });
    return true;
  }, [compatible, edit]);

  const save = useCallback(async (options = {}) => {
    const path = options.path || file.path;
    const answer = await call(config, "POST", "/api/save", { path, data: file.data,
      revision: options.path ? null : file.revision, replaceValid: Boolean(options.replaceValid) });
    setConflict(answer.http === 409 ? answer : null);
    if (answer.http === 200) {
      if (!options.path) {
        setFile((current) => ({ ...current, revision: answer.revision }));
        setDirty(false);
      }
      setNotice(`saved ${path}${answer.problems.length ? " (a draft: it does not validate)" : ""}`);
    } else if (answer.http !== 409) setNotice(answer.error);
    else setNotice(answer.status === "conflict" ? "not saved: the file changed on disk since it was opened"
      : "not saved: this graph does not validate and would replace a valid file");
  }, [config, file]);

  const send = useCallback((message) => {
    if (message.command) commanded.current = true;
    else inputAt.current = performance.now();
    if (socket.current && socket.current.readyState === WebSocket.OPEN) socket.current.send(JSON.stringify(message));
  }, []);

  const startLive = useCallback(() => {
    if (socket.current) socket.current.close();
    const ws = liveSocket(config, file.path);
    socket.current = ws;
    const stem = file.path.replace(/\.json$/, "");
    const reportPath = `${stem}.report.html`;
    const tracePath = `${stem}.live.jsonl`;
    ws.onmessage = (event) => {
      const message = JSON.parse(event.data);
      if (message.type === "start") view.current = startView(message.run);
      if (message.type === "frame" && view.current) view.current = withFrame(view.current, message, pinnedNow.current);
      const urgent = message.type !== "frame" || !message.playing || commanded.current
        || performance.now() - inputAt.current < INPUT_MS;
      if (message.type === "frame") commanded.current = false;
      liveNow.set(withMessage(liveNow.get(), message, { reportPath, tracePath, view: view.current }), urgent);
    };
    ws.onclose = () => liveNow.get() && liveNow.set({ ...liveNow.get(), notice: "live run closed" });
    setLive(true);
  }, [config, file, liveNow]);

  useEffect(() => {   // keys go to the live run (OnKeyboardInput), except while typing in a field
    if (!live) return undefined;
    const handler = (down) => (event) => {
      if (event.repeat || ["INPUT", "SELECT", "TEXTAREA"].includes(event.target.tagName)) return;
      send({ key: event.code, down });
      event.preventDefault();
    };
    const press = handler(true);
    const release = handler(false);
    window.addEventListener("keydown", press);
    window.addEventListener("keyup", release);
    return () => { window.removeEventListener("keydown", press); window.removeEventListener("keyup", release); };
  }, [live, send]);

  useEffect(() => () => socket.current && socket.current.close(), []);

  useEffect(() => {   // what a browser test drives and reads
    window.graphflowStudio = { file, problems, connect, save, startLive, send, get live() { return liveNow.get(); },
      bodyPosition: (path) => scene.current?.bodies[path]?.group.position.toArray() ?? null,
      shownRays: () => scene.current?.shownClose ?? null };
    document.body.dataset.studio = file ? "ready" : "loading";
  }, [file, problems, liveNow, connect, save, startLive, send]);

  if (!palette || !forms || !file) return <div className="gf-studio" data-testid="studio">{notice || "loading…"}</div>;
  const node = file.data.nodes.find((entry) => entry.name === selected);
  const placed = (problem) => Object.values(SECTIONS).flat().some((section) => problemsAt([problem], section).length);
  const graphProblems = problems.filter((problem) => !problem.node && !placed(problem));
  const tabProblems = (name) => (SECTIONS[name] || []).reduce((count, section) => count + problemsAt(problems, section).length, 0);
  return (
    <LiveContext.Provider value={liveNow}>
    <div className="gf-studio" data-testid="studio">
      <header className="gf-studio-bar">
        <b>{file.path}</b>
        <button type="button" data-action="save" onClick={() => save()}>save</button>
        <button type="button" data-action="live" onClick={startLive}>run live</button>
        <span data-testid="problem-count" data-count={problems.length}>
          {problems.length ? `${problems.length} problem(s)` : "valid"}</span>
        {notice && <span className="gf-notice" data-testid="notice">{notice}</span>}
      </header>
      {conflict && (
        <section className="gf-conflict" data-testid="conflict" data-kind={conflict.status}>
          {conflict.status === "conflict"
            ? <><h2>The file changed on disk since you opened it</h2><pre>{conflict.difference}</pre></>
            : <><h2>This graph does not validate; the file on disk does</h2>
                <button type="button" data-action="replace-valid" onClick={() => save({ replaceValid: true })}>replace it anyway</button>
                <button type="button" data-action="save-draft" onClick={() => save({ path: file.path.replace(/\.json$/, "") + ".draft.json" })}>
                  save as a draft beside it</button></>}
        </section>
      )}
      {live && <LiveBar send={send} />}
      <div className="gf-studio-main">
        <Palette types={palette.types} onAdd={addNode} />
        <StudioGraph graph={file.data} typesById={typesById} problems={problems} positions={positions}
                     selected={selected} onSelect={(name) => { setSelected(name); if (name) setTab("node"); }}
                     onNodesChange={(changes) => setPositions((now) => {
                       const next = { ...now };
                       changes.forEach((change) => { if (change.type === "position" && change.position) next[change.id] = change.position; });
                       return next;
                     })}
                     onMove={(name, at) => edit((data) => {
                       data.ui = { ...(data.ui || {}), positions: { ...((data.ui || {}).positions || {}), [name]: [Math.round(at.x), Math.round(at.y)] } };
                       return data;
                     })}
                     onConnect={connect}
                     onDisconnect={(id) => edit((data) => {
                       data.connections = data.connections.filter((entry) => `${entry.src}->${entry.dst}` !== id);
                       return data;
                     })} />
        <aside className="gf-side">
          {graphProblems.map((problem, index) => <div key={index} className="gf-problem">{problem.message}</div>)}
          <nav className="gf-tabs" data-testid="tabs">
            {TABS.map((name) => (
              <button type="button" key={name} data-tab={name} className={tab === name ? "gf-on" : ""} onClick={() => setTab(name)}>
                {name}{tabProblems(name) ? ` (${tabProblems(name)})` : ""}</button>))}
          </nav>
          {tab === "variables" && <VariablesEditor data={file.data} types={Object.keys(palette.connects)} problems={problems} edit={edit} />}
          {tab === "checks" && <ChecksEditor data={file.data} forms={forms} problems={problems} stagePrims={stagePrims} edit={edit} />}
          {tab === "settings" && <SettingsEditor data={file.data} forms={forms} problems={problems} stages={stages} edit={edit} />}
          {tab === "node" && !node && <p className="gf-description">select a node to edit it</p>}
          {tab === "node" && node && <Inspector key={node.name} node={node} type={typesById[node.type]} problems={problems}
                              live={live} pinned={pinned} stagePrims={stagePrims}
                              onPin={(key) => setPinned((list) => (list.includes(key) ? list : [...list, key]))}
                              onRename={(name) => { edit((data) => renamed(data, node.name, name)); setSelected(name); }}
                              onDelete={() => { edit((data) => deleted(data, node.name)); setSelected(null); }}
                              onInput={(port, value) => edit((data) => {
                                const entry = data.nodes.find((item) => item.name === node.name);
                                entry.inputs = { ...(entry.inputs || {}), [port]: value };
                                return data;
                              })} />}
          {live && <LivePanel send={send} />}
        </aside>
      </div>
      {live && <LiveScene pinned={pinned} onReady={sceneReady} onUnpin={unpin} onSelectLane={selectLane} />}
    </div>
    </LiveContext.Provider>
  );
}

function renamed(data, from, to) {
  const swap = (end) => (end.startsWith(`${from}.`) ? to + end.slice(from.length) : end);
  data.nodes.forEach((node) => { if (node.name === from) node.name = to; });
  data.connections = (data.connections || []).map((entry) => ({ src: swap(entry.src), dst: swap(entry.dst) }));
  return data;
}

function deleted(data, name) {
  data.nodes = data.nodes.filter((node) => node.name !== name);
  data.connections = (data.connections || []).filter((entry) => !entry.src.startsWith(`${name}.`) && !entry.dst.startsWith(`${name}.`));
  return data;
}
