// The live run as the report's scene and lanes read it: the start message's run data, grown frame by frame.
// Frames carry the poses of the bodies that moved, each close's rays, every phase and gripper status change with its tick
// (graphflow/studio/frame_scene.py); pinned outputs are sampled once a frame. The lists grow in place (the
// scene keeps its three.js objects); each frame gives a new top-level object so the panels redraw.

export function startView(run) {
  return { ...run, ticks: 0, pins: {} };
}

function appendAfter(list, entries) {
  for (const entry of entries) if (list.length === 0 || list[list.length - 1][0] < entry[0]) list.push(entry);
}

export function withFrame(view, frame, pinned) {
  const { scene, lanes } = frame;   // frame_scene.py's parts: poses that moved, every lane change with its tick
  for (const [path, sample] of Object.entries(scene.poses)) appendAfter(view.poses[path] ||= [], [sample]);
  view.rays.push(...scene.rays);   // each close's rays: the scene draws the last one's, as the report does
  for (const [gripper, limits] of Object.entries(scene.limits)) {
    view.limits[gripper] = Object.entries(limits).map(([name, value]) => ({ name, value }));
  }
  for (const [key, changes] of Object.entries(lanes.phases)) appendAfter(view.outputs[key] ||= [], changes);
  for (const [path, fields] of Object.entries(lanes.grippers)) {
    const series = (view.grippers[path] ||= {});
    for (const [name, changes] of Object.entries(fields)) appendAfter(series[name] ||= [], changes);
  }
  for (const key of pinned) {
    if (key in frame.outputs && !view.phases.includes(key)) appendAfter(view.outputs[key] ||= [], [[frame.tick, frame.outputs[key]]]);
  }
  return { ...view, ticks: frame.tick };
}

/** The objects the grippers hold at the view's last tick. */
export function heldNow(view) {
  const held = new Set();
  for (const gripper of Object.values(view.grippers)) {
    const gripped = gripper.gripped;
    if (gripped && gripped.length) for (const path of gripped[gripped.length - 1][1] || []) held.add(path);
  }
  return held;
}

/** Whether a live run has anything for the scene and lanes: a stage's bodies, a controller, a gripper, a pin. */
export function worthShowing(view, pinned) {
  return view.scene.bodies.length > 0 || view.phases.length > 0 || Object.keys(view.grippers).length > 0 || pinned.length > 0;
}
