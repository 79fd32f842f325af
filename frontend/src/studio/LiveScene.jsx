// The live run's 3D scene and lanes: the report's SceneView and Lanes fed from the live frames.
import React, { useEffect, useMemo } from "react";
import SceneView from "../SceneView.jsx";
import Lanes from "../Lanes.jsx";
import { heldNow } from "./liveView.js";

// memo: the page redraws on every frame (wire values); the scene and lanes only when their view changes
export default React.memo(function LiveScene({ view, pinned, onUnpin, onReady }) {
  const held = useMemo(() => heldNow(view), [view]);
  useEffect(() => {   // after SceneView's own effects (a child's run first): the scene now shows this tick
    document.body.dataset.sceneTick = String(view.ticks);
  }, [view]);
  return (
    <div className="gf-live-scene" data-testid="live-scene" data-tick={view.ticks}>
      <SceneView run={view} tick={view.ticks} held={held} onReady={onReady} />
      <div className="gf-live-lanes">
        <Lanes run={view} tick={view.ticks} pinned={pinned} onTick={() => {}} onUnpin={onUnpin} />
      </div>
    </div>
  );
});
