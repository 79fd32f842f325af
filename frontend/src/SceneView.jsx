// The stage in three.js: every body's collision shapes at its pose at the scrubbed tick, held objects
// marked, and on a close each attachment point's ray (its reach) and the nearest surface along it.
import React, { useEffect, useRef } from "react";
import * as THREE from "three";
import { OrbitControls } from "three/examples/jsm/controls/OrbitControls.js";
import { ConvexGeometry } from "three/examples/jsm/geometries/ConvexGeometry.js";
import { indexAt, poseAt } from "./data.js";

const COLOURS = { static: 0x9aa3ad, kinematic: 0x6d8fd6, dynamic: 0xe09a3e, link: 0xb8c2cc };
const HELD_COLOUR = 0x2fb36b;
const REACH_COLOUR = 0x1f9d55;
const BEYOND_COLOUR = 0xd64545;

function turnedToAxis(geometry, axis) {
  // three.js builds capsules, cylinders and cones along +Y; USD names the axis
  if (axis === "Z") geometry.rotateX(Math.PI / 2);
  else if (axis === "X") geometry.rotateZ(-Math.PI / 2);
  return geometry;
}

function shapeGeometry(shape) {
  switch (shape.kind) {
    case "box": {
      const [x, y, z] = shape.halfExtents;
      return new THREE.BoxGeometry(2 * x, 2 * y, 2 * z);
    }
    case "sphere":
      return new THREE.SphereGeometry(shape.radius, 24, 16);
    case "capsule":
      return turnedToAxis(new THREE.CapsuleGeometry(shape.radius, 2 * shape.halfHeight, 8, 16), shape.axis);
    case "cylinder":
      return turnedToAxis(new THREE.CylinderGeometry(shape.radius, shape.radius, 2 * shape.halfHeight, 24), shape.axis);
    case "cone":
      return turnedToAxis(new THREE.ConeGeometry(shape.radius, 2 * shape.halfHeight, 24), shape.axis);
    case "plane": {
      const geometry = new THREE.PlaneGeometry(6, 6);
      if (shape.axis === "X") geometry.rotateY(Math.PI / 2);
      else if (shape.axis === "Y") geometry.rotateX(-Math.PI / 2);
      return geometry;
    }
    case "convex_mesh":
      return new ConvexGeometry(shape.points.map(([x, y, z]) => new THREE.Vector3(x, y, z)));
    case "triangle_mesh": {
      const geometry = new THREE.BufferGeometry();
      geometry.setAttribute("position", new THREE.Float32BufferAttribute(shape.points.flat(), 3));
      geometry.setIndex(shape.triangles.flat());
      geometry.computeVertexNormals();
      return geometry;
    }
    default:
      return null;
  }
}

/** Place an object; whether that moved it (a scene redraws only when something in it changed). */
function setPose(object, pose) {
  const { position: p, quaternion: q } = object;
  if (p.x === pose[0] && p.y === pose[1] && p.z === pose[2] && q.x === pose[3] && q.y === pose[4] && q.z === pose[5]
      && q.w === pose[6]) return false;
  p.set(pose[0], pose[1], pose[2]);
  q.set(pose[3], pose[4], pose[5], pose[6]);
  return true;
}

function buildScene(run) {
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0xf4f6f8);
  scene.add(new THREE.HemisphereLight(0xffffff, 0x8090a0, 2.2));
  const sun = new THREE.DirectionalLight(0xffffff, 1.6);
  sun.position.set(2, -3, 5);
  scene.add(sun);
  const bodies = {};
  const articulated = new Set(run.scene.links || []);
  for (const body of run.scene.bodies) {
    const group = new THREE.Group();
    group.name = body.path;
    const colour = articulated.has(body.path) ? COLOURS.link : COLOURS[body.kind] ?? COLOURS.static;
    const material = new THREE.MeshLambertMaterial({ color: colour, 
                                                      side: THREE.DoubleSide });
    for (const shape of body.shapes) {
      const geometry = shapeGeometry(shape);
      if (!geometry) continue;
      const mesh = new THREE.Mesh(geometry, shape.kind === "plane"
        ? new THREE.MeshLambertMaterial({ color: 0xdfe3e8 }) : material);
      mesh.name = shape.path;
      setPose(mesh, shape.pose);
      group.add(mesh);
    }
    setPose(group, body.pose);
    scene.add(group);
    bodies[body.path] = { group, material, colour };
  }
  const grid = new THREE.GridHelper(4, 40, 0xb0b8c0, 0xd0d6dc);
  grid.rotateX(Math.PI / 2);
  grid.position.z = 0.0005;
  scene.add(grid);
  const rays = new THREE.Group();
  scene.add(rays);
  return { scene, bodies, rays };
}

// Rays are drawn with the bodies' material kind (MeshLambertMaterial, double-sided): no new shader program to
// compile when the first close is shown (software WebGL takes a second per program).
function marker(colour) {
  return new THREE.MeshLambertMaterial({ color: colour, emissive: colour, emissiveIntensity: 0.6, side: THREE.DoubleSide });
}

function rod(from, to, radius, material) {
  const length = from.distanceTo(to);
  const mesh = new THREE.Mesh(new THREE.CylinderGeometry(radius, radius, Math.max(length, 1e-6), 8), material);
  mesh.position.copy(from).add(to).multiplyScalar(0.5);
  mesh.quaternion.setFromUnitVectors(new THREE.Vector3(0, 1, 0), to.clone().sub(from).normalize());
  return mesh;
}

function dot(at, radius, material) {
  const mesh = new THREE.Mesh(new THREE.SphereGeometry(radius, 12, 8), material);
  mesh.position.copy(at);
  return mesh;
}

function rayObjects(close) {
  const group = new THREE.Group();
  const reachMaterial = marker(REACH_COLOUR);
  const beyondMaterial = marker(BEYOND_COLOUR);
  for (const ray of close.rays) {
    if (!ray.origin) continue;
    const origin = new THREE.Vector3(...ray.origin);
    const direction = new THREE.Vector3(...ray.direction);
    const reachEnd = origin.clone().addScaledVector(direction, ray.reach);
    group.add(dot(origin, 0.004, reachMaterial));
    group.add(rod(origin, reachEnd, 0.0012, reachMaterial));
    if (ray.hit) {
      const hitPoint = origin.clone().addScaledVector(direction, ray.hit.distance);
      const beyond = ray.hit.distance > ray.reach;
      if (beyond) group.add(rod(reachEnd, hitPoint, 0.0006, beyondMaterial));
      group.add(dot(hitPoint, 0.004, beyond ? beyondMaterial : reachMaterial));
    }
  }
  return group;
}

/** The frame that shows the moving bodies: centred on them, far enough to see them all. */
function frameCamera(camera, controls, run) {
  const box = new THREE.Box3();
  for (const body of run.scene.bodies) {
    if (body.kind === "static" && !(run.scene.links || []).includes(body.path)) continue;
    box.expandByPoint(new THREE.Vector3(body.pose[0], body.pose[1], body.pose[2]));
  }
  if (box.isEmpty()) box.set(new THREE.Vector3(-0.5, -0.5, 0), new THREE.Vector3(0.5, 0.5, 0.5));
  const centre = box.getCenter(new THREE.Vector3());
  const size = Math.max(0.6, box.getSize(new THREE.Vector3()).length());
  camera.position.set(centre.x + 1.1 * size, centre.y - 1.3 * size, centre.z + 0.9 * size);
  controls.target.copy(centre);
  controls.update();
}

// live: a scene redrawn while a run plays; no multisampling then (Chromium without a GPU draws it in software,
// where 4x antialiasing is most of a redraw's cost)
export default function SceneView({ run, tick, held, onReady, live = false }) {
  const mount = useRef(null);
  const state = useRef(null);

  useEffect(() => {
    const element = mount.current;
    const renderer = new THREE.WebGLRenderer({ antialias: !live, preserveDrawingBuffer: true });
    renderer.setPixelRatio(1);
    element.appendChild(renderer.domElement);
    const camera = new THREE.PerspectiveCamera(45, 1, 0.01, 100);
    camera.up.set(0, 0, 1);
    const controls = new OrbitControls(camera, renderer.domElement);
    const built = buildScene(run);
    const render = () => renderer.render(built.scene, camera);
    const resize = () => {
      const { clientWidth, clientHeight } = element;
      renderer.setSize(Math.max(clientWidth, 1), Math.max(clientHeight, 1), false);
      camera.aspect = Math.max(clientWidth, 1) / Math.max(clientHeight, 1);
      camera.updateProjectionMatrix();
      render();
    };
    frameCamera(camera, controls, run);
    controls.addEventListener("change", render);
    const observer = new ResizeObserver(resize);
    observer.observe(element);
    const focus = (point, distance) => {   // look closely at a point (a gripper's rays are millimetres long)
      const target = new THREE.Vector3(...point);
      camera.position.copy(target).add(new THREE.Vector3(0.6, -0.8, 0.45).multiplyScalar(distance));
      controls.target.copy(target);
      controls.update();
    };
    state.current = { ...built, camera, renderer, render, focus, shownClose: null };
    resize();
    onReady?.(state.current);
    return () => {
      observer.disconnect();
      controls.dispose();
      renderer.dispose();
      element.removeChild(renderer.domElement);
      state.current = null;
    };
  }, [run.scene]);   // the scene is built once per stage; a live run grows its poses, not its scene

  useEffect(() => {
    const current = state.current;
    if (!current) return;
    let changed = false;
    for (const [path, track] of Object.entries(run.poses)) {
      const pose = poseAt(track, tick);
      if (pose && current.bodies[path] && setPose(current.bodies[path].group, pose)) changed = true;
    }
    for (const [path, body] of Object.entries(current.bodies)) {
      const colour = held.has(path) ? HELD_COLOUR : body.colour;
      if (body.material.color.getHex() !== colour) {
        body.material.color.setHex(colour);
        changed = true;
      }
    }
    const closeIndex = indexAt(run.rays, tick, (close) => close.tick);
    const close = closeIndex >= 0 ? run.rays[closeIndex] : null;
    if (close !== current.shownClose) {
      current.rays.clear();
      if (close) current.rays.add(rayObjects(close));
      current.shownClose = close;
      changed = true;
    }
    if (changed) current.render();   // software WebGL: a redraw of an unchanged scene costs as much as any other
  }, [run, tick, held]);

  const focusRays = () => {
    const close = state.current?.shownClose;
    const ray = close?.rays.find((r) => r.origin);
    if (ray) state.current.focus(ray.origin, 0.12);
  };
  const closeShown = indexAt(run.rays, tick, (close) => close.tick) >= 0;
  return (
    <div className="gf-scene-box">
      <div className="gf-scene" ref={mount} data-testid="scene" />
      {run.scene.bodies.length === 0 && <div className="gf-no-scene">no scene: this run has no stage (or its trace predates scene data)</div>}
      {closeShown && <button className="gf-focus" onClick={focusRays} data-testid="focus-rays">zoom to the gripper's rays</button>}
    </div>
  );
}
