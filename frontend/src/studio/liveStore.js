// The live run's latest state, kept outside React's state: a frame (up to 30 a second) replaces it, and
// only the components whose slice of it changed redraw (a wire's label, a node's highlight, the live
// bar), not the page, the palette or React Flow's graph. Profiling the page while pick-and-place ran at
// max speed showed each frame re-rendering the whole studio and React Flow's every node and edge.
import { createContext, useContext, useSyncExternalStore } from "react";

export function liveStore(showEveryMs) {   // showEveryMs(state): the least time between drawings
  let state = null;
  let shownAt = -Infinity;
  let timer = null;
  const listeners = new Set();
  const show = () => {
    timer = null;
    shownAt = performance.now();
    listeners.forEach((listener) => listener());
  };
  return {
    get: () => state,
    /** The new state; drawn now when *urgent* or when the last drawing is showEveryMs old, else when it is. */
    set(next, urgent = true) {
      state = next;
      const wait = urgent ? 0 : shownAt + showEveryMs(next) - performance.now();
      if (wait <= 0) {
        clearTimeout(timer);
        show();
      } else if (timer === null) timer = setTimeout(show, wait);
    },
    subscribe(listener) {
      listeners.add(listener);
      return () => listeners.delete(listener);
    },
  };
}

export const LiveContext = createContext(null);

/** The part of the live state *select* picks (null before a live run); the caller redraws when it changes (===). */
export function useLive(select) {
  const store = useContext(LiveContext);
  return useSyncExternalStore(store.subscribe, () => select(store.get()));
}

export const NO_LIVE = { outputs: {}, computed: new Set(), grippers: {}, log: [], tick: 0, time: 0, playing: false, speed: 1 };
const MAX_LOG = 300;

/** The live state after one server message; parts the message leaves alone keep their identity (no redraw). */
export function withMessage(current, message, { reportPath, tracePath, view }) {
  const base = current || { ...NO_LIVE, reportPath, tracePath };
  if (message.type === "start") {
    const outputs = Object.fromEntries(Object.entries(message.run.outputs).map(([key, changes]) => [key, changes.at(-1)[1]]));
    return { ...NO_LIVE, reportPath, tracePath, speed: base.speed, outputs, limit: message.limit, view };
  }
  if (message.type === "error") return { ...base, notice: message.message };
  if (message.type === "saved") return { ...base, notice: `saved ${message.path}` };
  let grippers = base.grippers;
  if (Object.keys(message.grippers).length) {
    grippers = { ...grippers };
    Object.entries(message.grippers).forEach(([path, fields]) => { grippers[path] = { ...grippers[path], ...fields }; });
  }
  const sameComputed = message.computed.length === base.computed.size && message.computed.every((name) => base.computed.has(name));
  return {
    ...base, grippers, tick: message.tick, time: message.time, playing: message.playing, speed: message.speed,
    outputs: Object.keys(message.outputs).length ? { ...base.outputs, ...message.outputs } : base.outputs,
    computed: sameComputed ? base.computed : new Set(message.computed),
    ended: message.ended, log: message.log.length ? [...base.log, ...message.log].slice(-MAX_LOG) : base.log, view,
  };
}
