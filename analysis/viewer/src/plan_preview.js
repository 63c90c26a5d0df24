// The NMPC's preview at the time shown (the plan of the last iteration at or before it,
// mpc/plan/ of the dataset): the CoM it predicted over its horizon, drawn from the CoM at that
// iteration at the CoM's height and on the ground, and the steps it previewed as ghost soles
// (outlined, see-through) where it planned to land them. What the robot then did is the walk
// itself: the gap between the two is what the receding horizon re-planned.
import * as THREE from 'three';
import { COLOURS, floats, sampleAt, uint8s } from './data.js';

const GROUND = 0.004;  // [m] above the walk's traces

// The page's `preview` object decoded (null when the run has no plan).
export function decodePreview(data) {
  if (!data) return null;
  const preview = {
    samples: data.samples,
    steps: data.steps,
    time: floats(data.time),
    count: uint8s(data.count),
    com: floats(data.com),
    step: floats(data.step),
    side: uint8s(data.side),
  };
  return preview.time.length ? preview : null;
}

export class PlanPreview {
  constructor(scene, walk, preview) {
    this.walk = walk;
    this.preview = preview;
    this.group = new THREE.Group();
    scene.add(this.group);
    const n = preview.samples + 1;  // the iteration's CoM, then its previewed samples
    const line = (opacity) => {
      const geometry = new THREE.BufferGeometry();
      geometry.setAttribute('position', new THREE.BufferAttribute(new Float32Array(3 * n), 3));
      return new THREE.Line(geometry, new THREE.LineDashedMaterial({
        color: COLOURS.preview, dashSize: 0.04, gapSize: 0.025, transparent: true, opacity }));
    };
    this.comLine = line(1);
    this.groundLine = line(0.6);
    // A disc on the ground at every previewed sample (a line is one pixel wide in WebGL).
    this.dots = new THREE.InstancedMesh(new THREE.CircleGeometry(0.018, 12),
      new THREE.MeshBasicMaterial({ color: COLOURS.preview, depthWrite: false }), n);
    this.group.add(this.comLine, this.groundLine, this.dots);
    // One ghost sole per previewed step, in the preview's colour (the walk's own soles, pale
    // until they land, lie under them where the plan held), its outline in the foot's.
    const plane = new THREE.PlaneGeometry(walk.footLength, walk.footWidth);
    const edges = new THREE.EdgesGeometry(plane);
    this.soles = [];
    for (let s = 0; s < preview.steps; ++s) {
      const fill = new THREE.Mesh(plane, new THREE.MeshBasicMaterial({
        color: COLOURS.preview, transparent: true, opacity: 0.45, depthWrite: false }));
      const outline = new THREE.LineSegments(edges, new THREE.LineBasicMaterial());
      const sole = new THREE.Group();
      sole.add(fill, outline);
      sole.visible = false;
      this.group.add(sole);
      this.soles.push({ sole, outline });
    }
    this.shownSteps = 0;
    this.iterationTime = NaN;
  }

  set visible(on) { this.group.visible = on; }

  // The plan of the last iteration at or before `t` (walk sample `sample` for the CoM's height).
  show(sample, t) {
    const p = this.preview;
    const i = sampleAt(p.time, t);
    this.iterationTime = p.time[i];
    const w = this.walk;
    const start = sampleAt(w.time, p.time[i]);
    const height = w.com[3 * sample + 2];
    const count = Math.min(p.count[i], p.samples);
    const air = this.comLine.geometry.attributes.position;
    const ground = this.groundLine.geometry.attributes.position;
    air.setXYZ(0, w.com[3 * start], w.com[3 * start + 1], height);
    ground.setXYZ(0, w.com[3 * start], w.com[3 * start + 1], GROUND);
    for (let j = 0; j < count; ++j) {
      const x = p.com[(i * p.samples + j) * 2];
      const y = p.com[(i * p.samples + j) * 2 + 1];
      air.setXYZ(j + 1, x, y, height);
      ground.setXYZ(j + 1, x, y, GROUND);
    }
    air.needsUpdate = ground.needsUpdate = true;
    const matrix = new THREE.Matrix4();
    for (let j = 0; j <= count; ++j) {
      matrix.makeTranslation(ground.getX(j), ground.getY(j), GROUND);
      this.dots.setMatrixAt(j, matrix);
    }
    this.dots.count = count + 1;
    this.dots.instanceMatrix.needsUpdate = true;
    this.dots.computeBoundingSphere();
    for (const l of [this.comLine, this.groundLine]) {
      l.geometry.setDrawRange(0, count + 1);
      l.geometry.computeBoundingSphere();
      l.computeLineDistances();
    }
    // A previewed step lands within the horizon when its landing time is > 0 (0: standing);
    // the ones already landed at `t` are on the ground as real soles.
    this.shownSteps = 0;
    this.soles.forEach(({ sole, outline }, s) => {
      const k = (i * p.steps + s) * 4;
      const landing = p.step[k];
      sole.visible = count > 0 && landing > t;
      if (!sole.visible) return;
      ++this.shownSteps;
      sole.position.set(p.step[k + 1], p.step[k + 2], GROUND);
      sole.rotation.set(0, 0, p.step[k + 3]);
      outline.material.color.set(p.side[i * p.steps + s] === 1 ? COLOURS.left : COLOURS.right);
    });
  }
}
