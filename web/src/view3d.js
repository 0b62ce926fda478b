// three.js view of one session: the skeleton at the current frame coloured by strain,
// bones, a floor grid, the robot TCP (trail + interpolated marker) and the handover point.
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { LineSegments2 } from 'three/examples/jsm/lines/LineSegments2.js';
import { LineSegmentsGeometry } from 'three/examples/jsm/lines/LineSegmentsGeometry.js';
import { LineMaterial } from 'three/examples/jsm/lines/LineMaterial.js';
import { strainRgb } from './colormap.js';
import { frameAtOrBefore } from './data.js';

const FACE = new Set([0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10]);
const HAND = new Set([17, 18, 19, 20, 21, 22]);
const BG = 0x0d1219;

function hasWebGL() {
  try {
    const c = document.createElement('canvas');
    return !!(c.getContext('webgl2') || c.getContext('webgl'));
  } catch {
    return false;
  }
}

export class SkeletonView {
  constructor(container) {
    this.container = container;
    this.session = null;
    this.frame = 0;
    this.time = 0;
    this.renderPending = false;
    this.ok = hasWebGL();
    if (this.ok) {
      this.renderer = new THREE.WebGLRenderer({ antialias: true });
      this.renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
      this.renderer.setClearColor(BG, 1);
      this.canvas = this.renderer.domElement;
    } else {
      // Keep a canvas (tests read data-frame from it) and say why it stays empty.
      this.canvas = document.createElement('canvas');
      const msg = document.createElement('div');
      msg.className = 'view-message';
      msg.textContent = 'The 3D view needs WebGL, which this browser does not provide. The plots below still work.';
      container.appendChild(msg);
    }
    this.canvas.classList.add('view3d');
    this.canvas.setAttribute('data-frame', '0');
    this.canvas.setAttribute('aria-label', '3D view of the operator skeleton');
    container.prepend(this.canvas);
    if (!this.ok) return;

    this.scene = new THREE.Scene();
    this.camera = new THREE.PerspectiveCamera(40, 1, 0.02, 200);
    this.controls = new OrbitControls(this.camera, this.canvas);
    this.controls.addEventListener('change', () => this.requestRender());
    this.scene.add(new THREE.HemisphereLight(0xdfe8f5, 0x2a3340, 2.2));
    const sun = new THREE.DirectionalLight(0xffffff, 1.6);
    sun.position.set(3, -4, 6);
    this.scene.add(sun);
    this.world = new THREE.Group();
    this.scene.add(this.world);

    new ResizeObserver(() => this.resize()).observe(container);
    this.resize();
  }

  resize() {
    if (!this.ok) return;
    const w = Math.max(1, this.container.clientWidth);
    const h = Math.max(1, this.container.clientHeight);
    this.renderer.setSize(w, h);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    if (this.boneMaterial) this.boneMaterial.resolution.set(w, h);
    this.requestRender();
  }

  setSession(session) {
    this.session = session;
    if (!this.ok) return;
    for (const c of [...this.world.children]) {
      this.world.remove(c);
      c.traverse((o) => {
        if (o.geometry) o.geometry.dispose();
        if (o.material) o.material.dispose();
      });
    }
    const s = session;
    const up = new THREE.Vector3(...s.up);
    this.camera.up.copy(up);

    // Bounds over the recording (every few frames), robust to the odd far-off landmark a
    // degraded triangulation can produce: the 2nd..98th percentile per axis.
    const box = new THREE.Box3();
    const v = new THREE.Vector3();
    const xs = [], ys = [], zs = [], ups = [];
    const stride = Math.max(1, Math.floor(s.n / 300));
    for (let i = 0; i < s.n; i += stride) {
      const p = s.positions[i];
      for (let k = 0; k < s.nl; k++) {
        if (Number.isNaN(p[3 * k])) continue;
        xs.push(p[3 * k]);
        ys.push(p[3 * k + 1]);
        zs.push(p[3 * k + 2]);
        ups.push(p[3 * k] * up.x + p[3 * k + 1] * up.y + p[3 * k + 2] * up.z);
      }
    }
    const q = (a, f) => a[Math.min(a.length - 1, Math.max(0, Math.round(f * (a.length - 1))))];
    for (const a of [xs, ys, zs, ups]) a.sort((m, n) => m - n);
    let minUp = Infinity;
    if (xs.length) {
      box.set(new THREE.Vector3(q(xs, 0.02), q(ys, 0.02), q(zs, 0.02)), new THREE.Vector3(q(xs, 0.98), q(ys, 0.98), q(zs, 0.98)));
      minUp = q(ups, 0.01);
    }
    const bodyBox = box.clone();
    if (s.tcp) for (const q of s.tcp.positions) box.expandByPoint(v.set(...q));
    if (s.handover) box.expandByPoint(v.set(...s.handover));
    if (box.isEmpty()) box.set(new THREE.Vector3(-1, -1, 0), new THREE.Vector3(1, 1, 2));
    if (!Number.isFinite(minUp)) minUp = box.min.dot(up);
    const center = box.getCenter(new THREE.Vector3());
    const radius = Math.max(0.8, box.getSize(new THREE.Vector3()).length() / 2);

    // Horizontal basis (a, b) perpendicular to up.
    const a = new THREE.Vector3(1, 0, 0).projectOnPlane(up);
    if (a.lengthSq() < 1e-6) a.set(0, 1, 0).projectOnPlane(up);
    a.normalize();
    const b = new THREE.Vector3().crossVectors(up, a).normalize();

    // Floor grid at the lowest landmark, centred under the scene.
    const size = Math.max(3, Math.ceil(radius * 2.6));
    const grid = new THREE.GridHelper(size, size * 4, 0x3a4a5f, 0x222d3a);
    grid.quaternion.setFromUnitVectors(new THREE.Vector3(0, 1, 0), up);
    const floorCenter = center.clone().projectOnPlane(up).addScaledVector(up, minUp);
    grid.position.copy(floorCenter);
    this.world.add(grid);
    const axes = new THREE.AxesHelper(0.25);
    axes.position.copy(new THREE.Vector3().projectOnPlane(up).addScaledVector(up, minUp + 0.002));
    this.world.add(axes);

    // Landmarks.
    const sphere = new THREE.SphereGeometry(1, 20, 14);
    this.spheres = [];
    for (let k = 0; k < s.nl; k++) {
      const m = new THREE.Mesh(sphere, new THREE.MeshStandardMaterial({ roughness: 0.45, metalness: 0.0 }));
      const r = FACE.has(k) ? 0.011 : HAND.has(k) ? 0.012 : 0.022;
      m.scale.setScalar(r);
      m.visible = false;
      this.spheres.push(m);
      this.world.add(m);
    }
    // Bones: screen-space wide lines, coloured by their end landmarks' strain.
    this.boneGeometry = new LineSegmentsGeometry();
    this.bonePos = new Float32Array(Math.max(1, s.bones.length) * 6);
    this.boneCol = new Float32Array(Math.max(1, s.bones.length) * 6);
    this.boneGeometry.setPositions(this.bonePos);
    this.boneGeometry.setColors(this.boneCol);
    this.boneMaterial = new LineMaterial({ linewidth: 3.5, vertexColors: true, worldUnits: false });
    this.boneMaterial.resolution.set(this.container.clientWidth || 1, this.container.clientHeight || 1);
    this.bones = new LineSegments2(this.boneGeometry, this.boneMaterial);
    this.bones.frustumCulled = false;
    this.world.add(this.bones);

    // Robot TCP: the whole path faint, the trail up to now bright, a marker at now.
    this.tcpTrail = null;
    this.tcpMarker = null;
    if (s.tcp) {
      const flat = new Float32Array(s.tcp.positions.flat());
      const full = new THREE.BufferGeometry();
      full.setAttribute('position', new THREE.BufferAttribute(flat, 3));
      this.world.add(new THREE.Line(full, new THREE.LineBasicMaterial({ color: 0xffb020, transparent: true, opacity: 0.22 })));
      const trail = new THREE.BufferGeometry();
      trail.setAttribute('position', new THREE.BufferAttribute(flat.slice(), 3));
      this.tcpTrail = new THREE.Line(trail, new THREE.LineBasicMaterial({ color: 0xffb020 }));
      this.tcpTrail.frustumCulled = false;
      this.world.add(this.tcpTrail);
      this.tcpMarker = new THREE.Mesh(sphere, new THREE.MeshStandardMaterial({ color: 0xffb020, emissive: 0x553300, roughness: 0.3 }));
      this.tcpMarker.scale.setScalar(0.03);
      this.world.add(this.tcpMarker);
    }
    if (s.handover) {
      const g = new THREE.Group();
      const core = new THREE.Mesh(sphere, new THREE.MeshStandardMaterial({ color: 0x38d39f, emissive: 0x0b3a2a }));
      core.scale.setScalar(0.015);
      g.add(core);
      const ring = new THREE.Mesh(new THREE.TorusGeometry(0.05, 0.004, 8, 40), new THREE.MeshBasicMaterial({ color: 0x38d39f }));
      ring.quaternion.setFromUnitVectors(new THREE.Vector3(0, 0, 1), up);
      g.add(ring);
      g.position.set(...s.handover);
      this.world.add(g);
    }

    // Camera: in front of and to the right of the operator, looking at the body.
    const target = bodyBox.isEmpty() ? center : bodyBox.getCenter(new THREE.Vector3()).lerp(center, 0.35);
    const dir = new THREE.Vector3().addScaledVector(a, 0.62).addScaledVector(b, -0.72).addScaledVector(up, 0.32).normalize();
    // Far enough that the sphere around everything fits the narrower field of view.
    const vfov = (this.camera.fov * Math.PI) / 180;
    const hfov = 2 * Math.atan(Math.tan(vfov / 2) * Math.max(0.5, this.camera.aspect || 1));
    const fit = Math.min(vfov, hfov) / 2;
    this.camera.position.copy(target).addScaledVector(dir, (radius * 0.9) / Math.sin(fit));
    this.camera.near = 0.01;
    this.camera.far = radius * 40;
    this.camera.updateProjectionMatrix();
    this.controls.target.copy(target);
    this.controls.update();
    this.requestRender();
  }

  /** Show frame i of the current session. */
  setFrame(i) {
    this.frame = i;
    const s = this.session;
    this.time = s && s.n ? s.t[i] : 0;
    this.requestRender();
  }

  requestRender() {
    if (this.renderPending) return;
    this.renderPending = true;
    requestAnimationFrame(() => {
      this.renderPending = false;
      this.render();
    });
  }

  render() {
    const s = this.session;
    if (this.ok && s) {
      const color = new THREE.Color();
      if (s.n) {
        const p = s.positions[this.frame];
        const st = s.strain[this.frame];
        for (let k = 0; k < s.nl; k++) {
          const m = this.spheres[k];
          if (Number.isNaN(p[3 * k])) { m.visible = false; continue; }
          m.visible = true;
          m.position.set(p[3 * k], p[3 * k + 1], p[3 * k + 2]);
          const [r, g, b] = strainRgb(st[k]);
          m.material.color.setRGB(r / 255, g / 255, b / 255, THREE.SRGBColorSpace);
        }
        s.bones.forEach(([i0, i1], j) => {
          const ok = !Number.isNaN(p[3 * i0]) && !Number.isNaN(p[3 * i1]);
          for (let e = 0; e < 2; e++) {
            const k = e ? i1 : i0;
            for (let c = 0; c < 3; c++) this.bonePos[6 * j + 3 * e + c] = ok ? p[3 * k + c] : 0;
            const [r, g, b] = strainRgb(st[k]);
            color.setRGB(r / 255, g / 255, b / 255, THREE.SRGBColorSpace);
            this.boneCol[6 * j + 3 * e] = color.r;
            this.boneCol[6 * j + 3 * e + 1] = color.g;
            this.boneCol[6 * j + 3 * e + 2] = color.b;
          }
        });
        this.boneGeometry.attributes.instanceStart.data.needsUpdate = true;
        this.boneGeometry.attributes.instanceColorStart.data.needsUpdate = true;
      } else {
        for (const m of this.spheres) m.visible = false;
      }
      if (s.tcp && this.tcpMarker) {
        const tt = s.tcp.t;
        const now = this.time;
        const j = frameAtOrBefore(tt, now);
        let q = s.tcp.positions[j];
        if (now > tt[j] && j + 1 < tt.length) {
          const f = (now - tt[j]) / (tt[j + 1] - tt[j]);
          const q1 = s.tcp.positions[j + 1];
          q = [0, 1, 2].map((c) => q[c] + (q1[c] - q[c]) * f);
        }
        this.tcpMarker.position.set(...q);
        this.tcpTrail.geometry.setDrawRange(0, now >= tt[0] ? j + 1 : 0);
      }
      this.renderer.render(this.scene, this.camera);
    }
    this.canvas.setAttribute('data-frame', String(this.frame));
  }
}
