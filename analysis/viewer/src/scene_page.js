// The page of one run: the 3-D scene (robot, footsteps, traces, obstacles, goal, routes,
// pushes), the player under it and the linked plots below, all following one time.
import * as THREE from 'three';
import { COLOURS, element, floats, format, highest, lowest, sampleAt, uint8s } from './data.js';
import { Player, parseFragment } from './player.js';
import { SceneView } from './scene_view.js';
import { SimpleFigure, UrdfRobot } from './robot_figure.js';
import { WalkMarkers } from './walk_markers.js';
import { PlanPreview, decodePreview } from './plan_preview.js';
import { buildTimePlots } from './time_plots.js';

// The run's arrays decoded, with names the views use.
function decodeWalk(data) {
  const walk = {
    time: floats(data.time),
    com: floats(data.com),
    cop: floats(data.cop),
    leftFoot: floats(data.left_foot),
    rightFoot: floats(data.right_foot),
    waistYaw: floats(data.waist_yaw),
    support: uint8s(data.support),
    zmpMultibody: floats(data.zmp_multibody),
    footLength: data.foot.length,
    footWidth: data.foot.width,
    footsteps: data.footsteps,
    obstacles: data.obstacles,
    goal: data.goal,
    plans: data.plans,
    pushes: data.pushes,
    mpc: { time: floats(data.mpc.time), solveTime: floats(data.mpc.solve_time), status: uint8s(data.mpc.status) },
    preview: decodePreview(data.preview),
  };
  if (!walk.time.length) throw new Error('the run has no samples');
  return walk;
}

// [xmin, xmax, ymin, ymax] of what is drawn on the ground.
function extentOf(walk) {
  let xs = [];
  let ys = [];
  for (let i = 0; i < walk.time.length; i += 10) { xs.push(walk.com[3 * i]); ys.push(walk.com[3 * i + 1]); }
  for (const o of walk.obstacles) for (const [x, y] of o.outline.length ? o.outline : [[o.center[0] - o.radius, o.center[1] - o.radius], [o.center[0] + o.radius, o.center[1] + o.radius]]) { xs.push(x); ys.push(y); }
  if (walk.goal) { xs.push(walk.goal.x); ys.push(walk.goal.y); }
  return [lowest(xs), highest(xs), lowest(ys), highest(ys)];
}

function legendItem(colour, text, shape = 'line') {
  return element('div', { class: 'legend-item' }, [element('span', { class: 'key ' + shape, style: `--c:${colour}` }), text]);
}

function buildLegend(walk, hasRobot) {
  const items = [
    legendItem(COLOURS.com, 'CoM (ground: its projection)'),
    legendItem(COLOURS.cop, 'CoP'),
    legendItem(COLOURS.left, 'left sole', 'box'),
    legendItem(COLOURS.right, 'right sole', 'box'),
  ];
  if (walk.obstacles.length) items.push(legendItem(COLOURS.obstacle, 'obstacle, dashed: margin', 'box'));
  if (walk.obstacles.some((o) => !o.known)) items.push(legendItem(COLOURS.unknownObstacle, 'unknown to the planner until sensed', 'box'));
  walk.plans.forEach((plan, i) => {
    if (plan.route.length >= 2) items.push(legendItem(COLOURS.route[i % COLOURS.route.length], `route ${i + 1} (${plan.trigger}, t = ${format(plan.time, 3)} s)`));
  });
  if (walk.goal) items.push(legendItem(COLOURS.goal, 'goal and its tolerance', 'dot'));
  if (walk.preview) items.push(legendItem(COLOURS.preview, 'NMPC preview at this time: predicted CoM, ghost steps'));
  if (walk.pushes.length) items.push(legendItem(COLOURS.push, `push${walk.pushes.length > 1 ? 'es' : ''} (arrow at the CoM while it acts)`));
  if (!hasRobot) items.push(element('div', { class: 'legend-note', text: 'not replayed: the feet and the CoM as a simple figure (wpg run --replay for the robot)' }));
  return element('div', { class: 'legend' }, items);
}

export function scenePage(app, data) {
  const walk = decodeWalk(data);
  const viewport = element('div', { class: 'viewport' });
  const controls = element('div', { class: 'controls' });
  const plots = element('div', { class: 'plots' });
  const status = element('div', { class: 'hud' });
  document.body.classList.add('run-page');
  app.append(element('div', { class: 'scene-page' }, [viewport, controls, plots]));

  const view = new SceneView(viewport, extentOf(walk));
  let figure;
  const q = data.q ? floats(data.q.values) : null;
  if (q && data.urdf) {
    figure = new UrdfRobot(view.scene, data.urdf, data.q.names, q, data.q.names.length);
  } else {
    figure = new SimpleFigure(view.scene, walk);
  }
  const markers = new WalkMarkers(view.scene, walk);
  const preview = walk.preview ? new PlanPreview(view.scene, walk, walk.preview) : null;
  viewport.append(buildLegend(walk, !!(q && data.urdf)), status);

  const follow = element('label', { class: 'toggle' }, [element('input', { type: 'checkbox', checked: '' }), 'follow']);
  follow.firstChild.addEventListener('change', () => { view.follow = follow.firstChild.checked; });
  if (parseFragment(window.location.hash).follow === '0') {
    view.follow = false;
    follow.firstChild.checked = false;
  }
  // The preview's toggle (#preview=0 in the URL: off).
  const previewToggle = element('label', { class: 'toggle' }, [element('input', { type: 'checkbox', checked: '' }), 'preview']);
  if (preview) {
    const box = previewToggle.firstChild;
    box.addEventListener('change', () => { preview.visible = box.checked; view.requestRender(); });
    if (parseFragment(window.location.hash).preview === '0') {
      box.checked = false;
      preview.visible = false;
    }
  }
  const pushTimes = walk.pushes.map((p) => p.t);
  const supportNames = ['double support', 'left support', 'right support'];
  let plotList = [];
  const showTime = (t, text = true) => {
    const i = sampleAt(walk.time, t);
    figure.show(i);
    markers.show(i, t);
    if (preview) preview.show(i, t);
    view.followPoint(new THREE.Vector3(walk.com[3 * i], walk.com[3 * i + 1], 0));
    const pushing = walk.pushes.some((p) => t >= p.t && t < p.t + p.duration);
    if (text) status.textContent = `${supportNames[walk.support[i]] || ''}${pushing ? ' · pushed' : ''}`;
    if (text) for (const plot of plotList) plot.setCursor(t, false, text);
    view.requestRender();
  };
  const start = walk.time[0];
  const end = walk.time[walk.time.length - 1];
  // What tests (and scripts) read from the page: ready after the first frame drawn while paused
  // (a page opened with #t=... is paused at once; one that plays publishes when it stops), the
  // time shown, and the robot's box on the screen [x0, y0, x1, y1] in CSS pixels.
  const box = new THREE.Box3();
  const publish = () => {
    const canvas = view.renderer.domElement.getBoundingClientRect();
    box.setFromObject(figure.object);
    const corners = [];
    for (const x of [box.min.x, box.max.x]) for (const y of [box.min.y, box.max.y]) for (const z of [box.min.z, box.max.z]) {
      const p = new THREE.Vector3(x, y, z).project(view.camera);
      corners.push([canvas.left + (p.x + 1) / 2 * canvas.width, canvas.top + (1 - p.y) / 2 * canvas.height]);
    }
    const xs = corners.map((c) => c[0]);
    const ys = corners.map((c) => c[1]);
    document.body.dataset.robotBox = [lowest(xs), lowest(ys), highest(xs), highest(ys)].map((v) => v.toFixed(1)).join(',');
    document.body.dataset.wpgTime = player.t.toFixed(4);
    // The plan shown: its iteration's time and the ghost steps drawn ("" without a plan).
    document.body.dataset.wpgPreview = preview ? `${preview.iterationTime.toFixed(4)},${preview.shownSteps}` : '';
    document.body.dataset.wpgReady = '1';
  };
  const render = () => {
    const drawn = view.renderIfNeeded();
    if (drawn && !player.playing) publish();
    return drawn;
  };
  const player = new Player(controls, start, end, showTime, render, (interval) => view.adapt(interval));
  player.scale = () => view.scale;
  controls.append(follow);
  if (preview) controls.append(previewToggle);
  if (pushTimes.length) {
    controls.append(element('span', { class: 'jumps' }, [
      'pushes:',
      ...pushTimes.map((t) => element('button', { class: 'link', text: format(t, 3) + ' s', onclick: () => { player.pause(); player.seek(t); } })),
    ]));
  }
  plotList = buildTimePlots(plots, walk, (t) => { player.pause(); player.seek(t); });
  showTime(start);
  view.lookAt(new THREE.Vector3(walk.com[0], walk.com[1], 0));
  player.run();
}
