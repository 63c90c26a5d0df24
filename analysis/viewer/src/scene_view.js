// The 3-D view: a WebGL renderer, a camera orbiting a target (z up, as the datasets' world
// frame: x forward, y left), lights, the ground and its grid. Renders on demand: a frame is
// drawn when something changed (the player asks for one every animation frame while playing).
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';

export class SceneView {
  constructor(container, extent) {
    this.container = container;
    this.renderer = new THREE.WebGLRenderer({ antialias: false });
    // Render scale: the device's pixel ratio (at most 2), lowered while frames come slower than
    // 30 per second (adapt(): a software renderer such as headless Chromium's SwiftShader draws
    // every pixel on the CPU), raised again when they come fast.
    this.maxScale = Math.min(window.devicePixelRatio || 1, 2);
    this.scale = this.maxScale;
    this.frameMs = 16;
    this.framesSinceChange = 0;
    this.renderer.setPixelRatio(this.scale);
    this.renderer.shadowMap.enabled = false;
    this.renderer.shadowMap.type = THREE.PCFShadowMap;
    container.append(this.renderer.domElement);

    this.scene = new THREE.Scene();
    this.scene.background = new THREE.Color('#dfe6ee');

    this.camera = new THREE.PerspectiveCamera(40, 1, 0.02, 200);
    this.camera.up.set(0, 0, 1);
    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.enableDamping = false;
    this.controls.addEventListener('change', () => this.requestRender());

    this.scene.add(new THREE.HemisphereLight('#ffffff', '#8d8470', 1.6));
    const sun = new THREE.DirectionalLight('#ffffff', 1.8);
    sun.position.set(-3, -4, 8);
    sun.castShadow = true;
    sun.shadow.mapSize.set(2048, 2048);
    const reach = 4;
    Object.assign(sun.shadow.camera, { left: -reach, right: reach, top: reach, bottom: -reach, near: 0.5, far: 30 });
    this.sun = sun;
    this.scene.add(sun, sun.target);

    this.addGround(extent);
    this.follow = true;
    this.needsRender = true;
    this.resize();
    window.addEventListener('resize', () => this.resize());
  }

  // A floor covering the walk's extent [xmin, xmax, ymin, ymax] and a 0.5 m grid on it.
  addGround(extent) {
    const [xmin, xmax, ymin, ymax] = extent;
    const margin = 3;
    const cx = 0.5 * (xmin + xmax);
    const cy = 0.5 * (ymin + ymax);
    const size = Math.max(xmax - xmin, ymax - ymin) + 2 * margin;
    const half = Math.ceil(size / 2);
    const floor = new THREE.Mesh(new THREE.PlaneGeometry(2 * half + 40, 2 * half + 40),
      new THREE.MeshBasicMaterial({ color: '#c9ced6' }));
    floor.position.set(Math.round(cx), Math.round(cy), -0.002);
    floor.receiveShadow = true;
    this.scene.add(floor);
    const grid = new THREE.GridHelper(2 * half, 4 * half, '#8b95a3', '#aab2bd');
    grid.rotation.x = Math.PI / 2;
    grid.position.set(Math.round(cx), Math.round(cy), -0.001);
    grid.material.transparent = true;
    grid.material.opacity = 0.55;
    this.scene.add(grid);
    this.camera.position.set(cx - 2.6, cy - 3.4, 2.2);
    this.controls.target.set(cx, cy, 0.6);
    this.controls.update();
  }

  // Places the camera behind-left of `point` looking at it (the robot at the start).
  lookAt(point) {
    this.camera.position.set(point.x + 3.0, point.y - 4.3, 1.8);
    this.controls.target.set(point.x + 0.5, point.y, 0.5);
    this.controls.update();
    this.lastFollowed = point.clone();
    this.requestRender();
  }

  // Keeps the target on the robot: the camera moves with it, the user's orbit is kept.
  followPoint(point) {
    if (!this.follow) return;
    if (this.lastFollowed) {
      const delta = point.clone().sub(this.lastFollowed);
      delta.z = 0;
      this.camera.position.add(delta);
      this.controls.target.add(delta);
      this.controls.update();
    }
    this.lastFollowed = point.clone();
    this.sun.position.set(point.x - 3, point.y - 4, 8);
    this.sun.target.position.set(point.x, point.y, 0);
  }

  resize() {
    const width = Math.max(1, this.container.clientWidth);
    const height = Math.max(1, this.container.clientHeight);
    this.renderer.setSize(width, height, false);
    this.renderer.domElement.style.width = width + 'px';
    this.renderer.domElement.style.height = height + 'px';
    this.camera.aspect = width / height;
    this.camera.updateProjectionMatrix();
    this.requestRender();
  }

  requestRender() { this.needsRender = true; }

  // Called with the interval between two animation frames while the walk plays.
  adapt(intervalMs) {
    this.frameMs += 0.1 * (Math.min(intervalMs, 200) - this.frameMs);
    if (++this.framesSinceChange < 20) return;
    let scale = this.scale;
    if (this.frameMs > 30 && scale > 0.45) scale = Math.max(0.45, scale * 0.8);
    else if (this.frameMs < 14 && scale < this.maxScale) scale = Math.min(this.maxScale, scale * 1.25);
    if (scale !== this.scale) {
      this.scale = scale;
      this.framesSinceChange = 0;
      this.renderer.setPixelRatio(scale);
      this.resize();
    }
  }

  renderIfNeeded() {
    if (!this.needsRender) return false;
    this.needsRender = false;
    this.renderer.render(this.scene, this.camera);
    return true;
  }
}
