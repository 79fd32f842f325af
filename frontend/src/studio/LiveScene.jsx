// The live run's 3D scene and lanes: the report's SceneView and Lanes fed from the live frames.
import React, { useEffect, useMemo } from "react";
import SceneView from "../SceneView.jsx";
import Lanes from "../Lanes.jsx";
import { heldNow, worthShowing } from "./liveView.js";
import { useLive } from "./liveStore.js";

function SceneAndLanes({ view, pinned, onUnpin, onReady }) {
  const held = useMemo(() => heldNow(view), [view]);
  useEffect(() => {   // after SceneView's own effects (a child's run first): the scene now shows this tick
    document.body.dataset.sceneTick = String(view.ticks);
  }, [view]);
  return (
    <div className="gf-live-scene" data-testid="live-scene" data-tick={view.ticks}>
      <SceneView run={view} tick={view.ticks} held={held} onReady={onReady} live />
      <div className="gf-live-lanes">
        <Lanes run={view} tick={view.ticks} pinned={pinned} onTick={() => {}} onUnpin={onUnpin} />
      </div>
    </div>
  );
}

// memo: redrawn when the view changes (at most 10 times a second while a run plays), not on every frame
export default React.memo(function LiveScene({ pinned, onUnpin, onReady }) {
  const view = useLive((live) => live?.view);
  if (!view || !worthShowing(view, pinned)) return null;
  return <SceneAndLanes view={view} pinned={pinned} onUnpin={onUnpin} onReady={onReady} />;
});
