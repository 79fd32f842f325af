// The live run's 3D scene and lanes: the report's SceneView and Lanes fed from the live frames.
import React, { useCallback, useDeferredValue, useEffect, useMemo, useState } from "react";
import SceneView from "../SceneView.jsx";
import Lanes from "../Lanes.jsx";
import { heldNow, worthShowing } from "./liveView.js";
import { useLive } from "./liveStore.js";
import { formatValue, valueAt } from "../data.js";

// A lane clicked while live: its value at the tick clicked (a live run cannot jump back; the report can)
function Picked({ picked }) {
  if (!picked) return <div className="gf-lane-pick gf-none">click a lane: its value at that tick, its node selected</div>;
  const { lane, tick } = picked;
  const value = valueAt(lane.changes, tick);
  const reason = lane.reasons ? valueAt(lane.reasons, tick) : undefined;
  return (
    <div className="gf-lane-pick" data-testid="lane-pick" data-lane={lane.id} data-tick={tick} data-value={JSON.stringify(value ?? null)}>
      tick {tick} · {lane.label}: {typeof value === "string" ? value : formatValue(value)}{reason ? ` (${reason})` : ""}
    </div>
  );
}

function SceneAndLanes({ view, pinned, onUnpin, onReady, onSelectLane }) {
  const held = useMemo(() => heldNow(view), [view]);
  const [picked, setPicked] = useState(null);
  const pick = useCallback((lane, tick) => {
    if (!lane) return;
    setPicked({ lane, tick });
    onSelectLane(lane);
  }, [onSelectLane]);
  useEffect(() => {   // after SceneView's own effects (a child's run first): the scene now shows this tick
    document.body.dataset.sceneTick = String(view.ticks);
  }, [view]);
  return (
    <div className="gf-live-scene" data-testid="live-scene" data-tick={view.ticks}>
      <SceneView run={view} tick={view.ticks} held={held} onReady={onReady} live />
      <div className="gf-live-lanes">
        <Picked picked={picked} />
        <Lanes run={view} tick={view.ticks} pinned={pinned} onUnpin={onUnpin} onPick={pick} />
      </div>
    </div>
  );
}

// memo: redrawn when the view changes (at most 10 times a second while a run plays), not on every frame;
// deferred: the frame's bar, wires and highlights are drawn first, the scene and lanes (the costly part) after
export default React.memo(function LiveScene({ pinned, onUnpin, onReady, onSelectLane }) {
  const view = useDeferredValue(useLive((live) => live?.view));
  if (!view || !worthShowing(view, pinned)) return null;
  return <SceneAndLanes view={view} pinned={pinned} onUnpin={onUnpin} onReady={onReady} onSelectLane={onSelectLane} />;
});
