// What the walk leaves on the ground and around the robot: the footsteps as soles (faint until
// they land), the CoM and CoP traces (bright up to the current time), the obstacles with their
// margins (the ones unknown to the planner in amber), the goal with its tolerance, the
// planner's routes (one colour per plan, shown from the instant it was made), and the pushes
// as arrows at the CoM while they act.
import * as THREE from 'three';
import { COLOURS, sampleAt } from './data.js';

const GROUND = 0.003;  // [m] lines on the ground, above the grid

function lineOf(points, colour, options = {}) {
  const geometry = new THREE.BufferGeometry().setFromPoints(points);
  const material = options.dashed
    ? new THREE.LineDashedMaterial({ color: colour, dashSize: 0.06, gapSize: 0.04, transparent: true, opacity: options.opacity ?? 1 })
    : new THREE.LineBasicMaterial({ color: colour, transparent: true, opacity: options.opacity ?? 1 });
  const line = new THREE.Line(geometry, material);
  if (options.dashed) line.computeLineDistances();
  return line;
}

function circlePoints(cx, cy, radius, z, segments = 72) {
  const points = [];
  for (let i = 0; i <= segments; ++i) {
    const a = (2 * Math.PI * i) / segments;
    points.push(new THREE.Vector3(cx + radius * Math.cos(a), cy + radius * Math.sin(a), z));
  }
  return points;
}

// The outline grown by `margin` (the Minkowski sum with a disc), as the convex hull of the
// vertices' discs: obstacles are convex.
function grownOutline(outline, margin) {
  const points = [];
  for (const [x, y] of outline) {
    for (let i = 0; i < 24; ++i) {
      const a = (2 * Math.PI * i) / 24;
      points.push([x + margin * Math.cos(a), y + margin * Math.sin(a)]);
    }
  }
  points.sort((p, q) => p[0] - q[0] || p[1] - q[1]);
  const cross = (o, a, b) => (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
  const half = (list) => {
    const hull = [];
    for (const p of list) {
      while (hull.length >= 2 && cross(hull[hull.length - 2], hull[hull.length - 1], p) <= 0) hull.pop();
      hull.push(p);
    }
    hull.pop();
    return hull;
  };
  return half(points).concat(half(points.slice().reverse()));
}

export class WalkMarkers {
  constructor(scene, walk) {
    this.walk = walk;
    this.group = new THREE.Group();
    scene.add(this.group);
    this.addSoles();
    this.addTraces();
    this.addObstacles();
    this.addGoal();
    this.addRoutes();
    this.addPushes();
  }

  // Every sole in one instanced mesh and every outline in one line set: two draw calls for
  // the footsteps, whatever their number (a software renderer pays for each call). A sole is
  // pale until it lands, then deeper (its instance colour).
  addSoles() {
    const w = this.walk;
    const steps = w.footsteps;
    const plane = new THREE.PlaneGeometry(w.footLength, w.footWidth);
    this.soleMesh = new THREE.InstancedMesh(plane,
      new THREE.MeshBasicMaterial({ transparent: true, opacity: 0.55, depthWrite: false }), Math.max(1, steps.length));
    this.soleMesh.count = steps.length;
    const outline = [];
    const matrix = new THREE.Matrix4();
    const corners = [[0.5, 0.5], [-0.5, 0.5], [-0.5, -0.5], [0.5, -0.5]];
    steps.forEach(([, x, y, yaw, side], i) => {
      matrix.makeRotationZ(yaw).setPosition(x, y, 0.002);
      this.soleMesh.setMatrixAt(i, matrix);
      const c = new THREE.Color(side === 1 ? COLOURS.left : COLOURS.right);
      const points = corners.map(([a, b]) => new THREE.Vector3(
        x + Math.cos(yaw) * a * w.footLength - Math.sin(yaw) * b * w.footWidth,
        y + Math.sin(yaw) * a * w.footLength + Math.cos(yaw) * b * w.footWidth, 0.003));
      for (let k = 0; k < 4; ++k) outline.push(points[k], points[(k + 1) % 4], c, c);
    });
    const positions = [];
    const colours = [];
    for (let k = 0; k < outline.length; k += 4) {
      positions.push(outline[k].x, outline[k].y, outline[k].z, outline[k + 1].x, outline[k + 1].y, outline[k + 1].z);
      colours.push(outline[k + 2].r, outline[k + 2].g, outline[k + 2].b, outline[k + 3].r, outline[k + 3].g, outline[k + 3].b);
    }
    const edges = new THREE.BufferGeometry();
    edges.setAttribute('position', new THREE.Float32BufferAttribute(positions, 3));
    edges.setAttribute('color', new THREE.Float32BufferAttribute(colours, 3));
    this.group.add(this.soleMesh, new THREE.LineSegments(edges, new THREE.LineBasicMaterial({ vertexColors: true })));
    this.soleColours = steps.map(([, , , , side]) => new THREE.Color(side === 1 ? COLOURS.left : COLOURS.right));
    this.soleLanded = steps.map(() => null);
    this.soleLandings = steps.map(([landing]) => landing);
  }

  showSoles(t) {
    const pale = new THREE.Color('#ffffff');
    let changed = false;
    this.soleLandings.forEach((landing, i) => {
      const landed = landing <= t;
      if (this.soleLanded[i] === landed) return;
      this.soleLanded[i] = landed;
      this.soleMesh.setColorAt(i, landed ? this.soleColours[i] : this.soleColours[i].clone().lerp(pale, 0.75));
      changed = true;
    });
    if (changed) this.soleMesh.instanceColor.needsUpdate = true;
  }

  addTraces() {
    const w = this.walk;
    const n = w.time.length;
    const com = [];
    const cop = [];
    for (let i = 0; i < n; ++i) {
      com.push(new THREE.Vector3(w.com[3 * i], w.com[3 * i + 1], w.com[3 * i + 2]));
      cop.push(new THREE.Vector3(w.cop[2 * i], w.cop[2 * i + 1], GROUND));
    }
    // The whole path faint, the part walked so far bright (drawRange follows the time).
    this.group.add(lineOf(com, COLOURS.com, { opacity: 0.18 }));
    this.group.add(lineOf(cop, COLOURS.cop, { opacity: 0.25 }));
    this.comTrace = lineOf(com, COLOURS.com);
    this.copTrace = lineOf(cop, COLOURS.cop);
    // The CoM projected on the ground: the walk read from above.
    this.comShadow = lineOf(com.map((p) => new THREE.Vector3(p.x, p.y, GROUND)), '#334155', { opacity: 0.5 });
    this.group.add(this.comTrace, this.copTrace, this.comShadow);
    this.copMarker = new THREE.Mesh(new THREE.CylinderGeometry(0.022, 0.022, 0.006, 20),
      new THREE.MeshBasicMaterial({ color: COLOURS.cop }));
    this.copMarker.rotation.x = Math.PI / 2;
    this.group.add(this.copMarker);
  }

  addObstacles() {
    for (const obstacle of this.walk.obstacles) {
      const colour = obstacle.known ? COLOURS.obstacle : COLOURS.unknownObstacle;
      const material = new THREE.MeshLambertMaterial({ color: colour, transparent: !obstacle.known, opacity: obstacle.known ? 1 : 0.85 });
      const height = 0.45;
      let mesh;
      if (obstacle.type === 'circle') {
        mesh = new THREE.Mesh(new THREE.CylinderGeometry(obstacle.radius, obstacle.radius, height, 48), material);
        mesh.rotation.x = Math.PI / 2;
        mesh.position.set(obstacle.center[0], obstacle.center[1], height / 2);
      } else {
        const shape = new THREE.Shape(obstacle.outline.map(([x, y]) => new THREE.Vector2(x, y)));
        mesh = new THREE.Mesh(new THREE.ExtrudeGeometry(shape, { depth: height, bevelEnabled: false }), material);
      }
      mesh.castShadow = true;
      mesh.receiveShadow = true;
      this.group.add(mesh);
      if (obstacle.margin > 0) {
        const points = obstacle.type === 'circle'
          ? circlePoints(obstacle.center[0], obstacle.center[1], obstacle.radius + obstacle.margin, GROUND)
          : grownOutline(obstacle.outline, obstacle.margin).map(([x, y]) => new THREE.Vector3(x, y, GROUND));
        if (obstacle.type !== 'circle') points.push(points[0].clone());
        this.group.add(lineOf(points, colour, { dashed: true }));
        const fill = new THREE.Mesh(new THREE.ShapeGeometry(new THREE.Shape(points.map((p) => new THREE.Vector2(p.x, p.y)))),
          new THREE.MeshBasicMaterial({ color: colour, transparent: true, opacity: 0.12, depthWrite: false }));
        fill.position.z = GROUND / 2;
        this.group.add(fill);
      }
    }
  }

  addGoal() {
    const goal = this.walk.goal;
    if (!goal) return;
    const ring = lineOf(circlePoints(goal.x, goal.y, Math.max(goal.tolerance, 0.02), GROUND), '#a16207');
    this.group.add(ring);
    const disc = new THREE.Mesh(new THREE.CircleGeometry(Math.max(goal.tolerance, 0.02), 48),
      new THREE.MeshBasicMaterial({ color: COLOURS.goal, transparent: true, opacity: 0.35, depthWrite: false }));
    disc.position.set(goal.x, goal.y, GROUND / 2);
    this.group.add(disc);
    const pole = new THREE.Mesh(new THREE.CylinderGeometry(0.01, 0.01, 0.9, 8),
      new THREE.MeshLambertMaterial({ color: '#57534e' }));
    pole.rotation.x = Math.PI / 2;
    pole.position.set(goal.x, goal.y, 0.45);
    const flag = new THREE.Mesh(new THREE.BoxGeometry(0.22, 0.004, 0.14),
      new THREE.MeshLambertMaterial({ color: COLOURS.goal }));
    flag.position.set(goal.x + 0.11, goal.y, 0.82);
    this.group.add(pole, flag);
    if (Number.isFinite(goal.yaw)) {
      const arrow = new THREE.ArrowHelper(new THREE.Vector3(Math.cos(goal.yaw), Math.sin(goal.yaw), 0),
        new THREE.Vector3(goal.x, goal.y, 0.01), 0.35, '#a16207', 0.1, 0.06);
      this.group.add(arrow);
    }
  }

  addRoutes() {
    this.routes = this.walk.plans.map((plan, index) => {
      const colour = COLOURS.route[index % COLOURS.route.length];
      const points = plan.route.map(([x, y]) => new THREE.Vector3(x, y, 0.012 + 0.004 * index));
      const group = new THREE.Group();
      const material = new THREE.MeshBasicMaterial({ color: colour, transparent: true, depthWrite: false });
      if (points.length >= 2) {
        // A ribbon 3 cm wide on the ground (WebGL draws lines one pixel wide), dashed for a
        // replan, and a dot at each waypoint.
        for (let k = 1; k < points.length; ++k) {
          const from = points[k - 1];
          const to = points[k];
          const length = from.distanceTo(to);
          const dashes = index > 0 ? Math.max(1, Math.floor(length / 0.12)) : 1;
          for (let d = 0; d < dashes; ++d) {
            const a = index > 0 ? d / dashes : 0;
            const b = index > 0 ? (d + 0.6) / dashes : 1;
            const piece = new THREE.Mesh(new THREE.PlaneGeometry(length * (b - a), 0.03), material);
            piece.position.copy(from).lerp(to, (a + b) / 2);
            piece.rotation.z = Math.atan2(to.y - from.y, to.x - from.x);
            group.add(piece);
          }
        }
        for (const p of points) {
          const dot = new THREE.Mesh(new THREE.CircleGeometry(0.035, 16), material);
          dot.position.copy(p);
          group.add(dot);
        }
      }
      this.group.add(group);
      return { time: plan.time, group, material, next: Infinity };
    });
    // A route is bright from its plan to the next one, faint afterwards.
    for (let i = 0; i + 1 < this.routes.length; ++i) this.routes[i].next = this.routes[i + 1].time;
  }

  // A push: a solid arrow (drawn over the robot) pointing along the force and ending at the
  // CoM while it acts, its length growing with the force.
  addPushes() {
    const material = new THREE.MeshBasicMaterial({ color: COLOURS.push, depthTest: false, transparent: true, opacity: 0.9 });
    this.pushes = this.walk.pushes.map((push) => {
      const magnitude = Math.hypot(push.force[0], push.force[1]);
      const length = Math.min(1.2, 0.3 + magnitude / 250);  // 0.3 m + 1 m per 250 N
      const direction = new THREE.Vector3(push.force[0], push.force[1], 0).normalize();
      const arrow = new THREE.Group();
      const head = 0.12;
      const shaft = new THREE.Mesh(new THREE.CylinderGeometry(0.018, 0.018, length - head, 12), material);
      shaft.position.y = (length - head) / 2;
      const cone = new THREE.Mesh(new THREE.ConeGeometry(0.05, head, 16), material);
      cone.position.y = length - head / 2;
      arrow.add(shaft, cone);
      arrow.quaternion.setFromUnitVectors(new THREE.Vector3(0, 1, 0), direction);
      arrow.renderOrder = 10;
      shaft.renderOrder = cone.renderOrder = 10;
      arrow.visible = false;
      this.group.add(arrow);
      return { ...push, arrow, direction, length };
    });
  }

  show(sample, t) {
    const w = this.walk;
    this.comTrace.geometry.setDrawRange(0, sample + 1);
    this.copTrace.geometry.setDrawRange(0, sample + 1);
    this.comShadow.geometry.setDrawRange(0, sample + 1);
    this.copMarker.position.set(w.cop[2 * sample], w.cop[2 * sample + 1], GROUND + 0.002);
    this.showSoles(t);
    for (const route of this.routes) {
      route.group.visible = route.time <= t + 1e-9;
      route.material.opacity = t < route.next ? 1 : 0.3;
    }
    for (const push of this.pushes) {
      const acting = t >= push.t && t < push.t + push.duration + 0.25;  // shown a little longer
      push.arrow.visible = acting;
      if (acting) {
        // The arrow ends at the CoM, pointing along the force.
        const i = sampleAt(w.time, t);
        const com = new THREE.Vector3(w.com[3 * i], w.com[3 * i + 1], w.com[3 * i + 2]);
        push.arrow.position.copy(com.addScaledVector(push.direction, -push.length));
      }
    }
  }
}
