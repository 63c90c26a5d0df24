// The walking robot: its URDF (urdf-loader) posed by the replayed configuration `q` of each
// sample (base position, base quaternion w x y z, then the joints, named by the dataset's
// `names`), or, for a run that was not replayed, a simple figure: the two soles at the feet's
// poses, the CoM as a ball on a pelvis and legs drawn from the hips to the ankles.
import * as THREE from 'three';
import URDFLoader from 'urdf-loader';

const ANKLE_HEIGHT = 0.105;  // [m] HRP-2's ankle above its sole (robots/hrp2/make_urdf.py)

// A soft dark disc on the ground under the robot: the cue of where it stands that a shadow
// map would give, for one textured quad (shadow maps with antialiasing took headless
// Chromium's software renderer from 10.7 to 2.9 frames per second on this page).
function blobShadow(scene) {
  const size = 64;
  const canvas = document.createElement('canvas');
  canvas.width = canvas.height = size;
  const g = canvas.getContext('2d');
  const gradient = g.createRadialGradient(size / 2, size / 2, 0, size / 2, size / 2, size / 2);
  gradient.addColorStop(0, 'rgba(15,23,42,0.45)');
  gradient.addColorStop(1, 'rgba(15,23,42,0)');
  g.fillStyle = gradient;
  g.fillRect(0, 0, size, size);
  const disc = new THREE.Mesh(new THREE.PlaneGeometry(0.7, 0.55),
    new THREE.MeshBasicMaterial({ map: new THREE.CanvasTexture(canvas), transparent: true, depthWrite: false }));
  disc.renderOrder = -1;
  scene.add(disc);
  return disc;
}

export class UrdfRobot {
  constructor(scene, urdfText, names, q, nq) {
    const loader = new URDFLoader();
    loader.parseCollision = false;
    this.robot = loader.parse(urdfText);
    // Lambert shading: cheaper than the loader's Phong materials for a software renderer
    // (headless Chromium's SwiftShader), which the page must keep above 30 frames per second.
    this.robot.traverse((object) => {
      if (object.isMesh && object.material) {
        const { color } = object.material;
        object.material = new THREE.MeshLambertMaterial({ color });
      }
    });
    scene.add(this.robot);
    this.shadow = blobShadow(scene);
    this.q = q;
    this.nq = nq;
    this.base = ['base_x', 'base_y', 'base_z', 'base_qw', 'base_qx', 'base_qy', 'base_qz']
      .map((name) => names.indexOf(name));
    if (this.base.some((index) => index < 0)) throw new Error('q has no base_x ... base_qz columns');
    // Each joint column with the URDF joint it drives (columns the URDF does not know are left).
    this.joints = [];
    names.forEach((name, column) => {
      const joint = this.robot.joints[name];
      if (joint && joint.jointType !== 'fixed') this.joints.push([column, joint]);
    });
  }

  show(sample) {
    const row = sample * this.nq;
    const q = this.q;
    const [x, y, z, w, qx, qy, qz] = this.base.map((column) => q[row + column]);
    this.robot.position.set(x, y, z);
    this.shadow.position.set(x, y, 0.0015);
    this.robot.quaternion.set(qx, qy, qz, w).normalize();
    for (const [column, joint] of this.joints) joint.setJointValue(q[row + column]);
    this.robot.updateMatrixWorld(true);
  }

  get object() { return this.robot; }

  set visible(value) { this.robot.visible = value; }
}

// A bone between two points: a cylinder of unit height scaled and turned onto the segment.
class Bone {
  constructor(group, radius, material) {
    this.mesh = new THREE.Mesh(new THREE.CylinderGeometry(radius, radius, 1, 12), material);
    this.mesh.castShadow = true;
    group.add(this.mesh);
  }

  place(from, to) {
    const direction = to.clone().sub(from);
    const length = direction.length();
    this.mesh.position.copy(from).addScaledVector(direction, 0.5);
    this.mesh.scale.set(1, Math.max(length, 1e-6), 1);
    this.mesh.quaternion.setFromUnitVectors(new THREE.Vector3(0, 1, 0), direction.normalize());
  }
}

export class SimpleFigure {
  constructor(scene, walk) {
    this.walk = walk;
    this.group = new THREE.Group();
    scene.add(this.group);
    const body = new THREE.MeshLambertMaterial({ color: '#e8ecf2' });
    const dark = new THREE.MeshLambertMaterial({ color: '#38507a' });
    const sole = (colour) => {
      const mesh = new THREE.Mesh(new THREE.BoxGeometry(walk.footLength, walk.footWidth, 0.03),
        new THREE.MeshLambertMaterial({ color: colour }));
      mesh.castShadow = true;
      this.group.add(mesh);
      return mesh;
    };
    this.leftSole = sole('#3b82c4');
    this.rightSole = sole('#c84a4a');
    this.com = new THREE.Mesh(new THREE.SphereGeometry(0.055, 24, 16),
      new THREE.MeshLambertMaterial({ color: '#111111' }));
    this.pelvis = new THREE.Mesh(new THREE.BoxGeometry(0.12, 0.22, 0.1), dark);
    this.torso = new THREE.Mesh(new THREE.BoxGeometry(0.2, 0.3, 0.38), body);
    this.head = new THREE.Mesh(new THREE.SphereGeometry(0.09, 20, 14), body);
    for (const mesh of [this.com, this.pelvis, this.torso, this.head]) {
      mesh.castShadow = true;
      this.group.add(mesh);
    }
    this.legs = [new Bone(this.group, 0.035, body), new Bone(this.group, 0.035, body)];
    this.shadow = blobShadow(this.group);
  }

  show(sample) {
    const w = this.walk;
    const com = new THREE.Vector3(w.com[3 * sample], w.com[3 * sample + 1], w.com[3 * sample + 2]);
    const yaw = w.waistYaw.length ? w.waistYaw[sample] : 0;
    const turn = new THREE.Quaternion().setFromAxisAngle(new THREE.Vector3(0, 0, 1), yaw);
    this.com.position.copy(com);
    this.shadow.position.set(com.x, com.y, 0.0015);
    this.shadow.rotation.z = yaw;
    this.pelvis.position.copy(com).add(new THREE.Vector3(0, 0, -0.06));
    this.pelvis.quaternion.copy(turn);
    this.torso.position.copy(com).add(new THREE.Vector3(0, 0, 0.26));
    this.torso.quaternion.copy(turn);
    this.head.position.copy(com).add(new THREE.Vector3(0, 0, 0.58));
    const feet = [[w.leftFoot, this.leftSole, 1], [w.rightFoot, this.rightSole, -1]];
    feet.forEach(([foot, mesh, side], leg) => {
      const [x, y, z, footYaw] = foot.subarray(4 * sample, 4 * sample + 4);
      mesh.position.set(x, y, z + 0.015);
      mesh.rotation.set(0, 0, footYaw);
      const hip = new THREE.Vector3(0, side * 0.06, -0.08).applyQuaternion(turn).add(com);
      this.legs[leg].place(hip, new THREE.Vector3(x, y, z + ANKLE_HEIGHT));
    });
  }

  get object() { return this.group; }

  set visible(value) { this.group.visible = value; }
}
