// The studio's 3D view: a built GLB (Y up, as Insula writes it) lit from above, orbit, pan and
// zoom with the mouse, fitted to the model at each build; a click names the object under it and
// lists its attributes (the glTF node's extras).
import * as THREE from 'three';
import { GLTFLoader } from 'three/examples/jsm/loaders/GLTFLoader.js';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { featureRow, readPropertyTable } from './features.js';

const maxModelLights = 8;

export class Viewport {
  constructor(canvas, onPick) {
    this.canvas = canvas;
    this.renderer = new THREE.WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
    // The cut: everything above a horizontal plane is hidden (Y up), to look into the storeys.
    this.cutPlane = new THREE.Plane(new THREE.Vector3(0, -1, 0), Infinity);
    this.renderer.clippingPlanes = [this.cutPlane];
    this.cutFraction = 1;
    this.roofsShown = true;
    this.furnitureShown = true;
    this.scene = new THREE.Scene();
    this.scene.background = new THREE.Color(0xdfe6ec);
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x8a8f80, 2.2));
    const sun = new THREE.DirectionalLight(0xffffff, 1.6);
    sun.position.set(0.5, 1, 0.8);
    this.scene.add(sun);
    this.camera = new THREE.PerspectiveCamera(45, 1, 0.1, 100000);
    this.camera.position.set(40, 30, 40);
    this.controls = new OrbitControls(this.camera, canvas);
    this.controls.addEventListener('change', () => this.render());
    this.model = null;
    this.fitted = false;
    this.loader = new GLTFLoader();
    this.raycaster = new THREE.Raycaster();
    canvas.addEventListener('click', (event) => onPick(this.pick(event)));
    new ResizeObserver(() => this.resize()).observe(canvas);
    this.resize();
  }

  resize() {
    const { clientWidth: w, clientHeight: h } = this.canvas;
    if (w === 0 || h === 0) return;
    this.renderer.setSize(w, h, false);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.render();
  }

  render() {
    this.renderer.render(this.scene, this.camera);
  }

  // Shows the GLB `bytes` in place of the last model; the first model is fitted to the view, later
  // ones keep the user's camera. Returns the number of meshes shown.
  async show(bytes) {
    const gltf = await this.loader.parseAsync(bytes, '');
    this.table = readPropertyTable(bytes);
    if (this.model) {
      this.scene.remove(this.model);
      this.model.traverse((o) => {
        if (o.geometry) o.geometry.dispose();
      });
    }
    this.model = gltf.scene;
    // A graph's lamps come as glTF punctual lights: three.js shades every light in every
    // fragment, so a city's hundreds would stall the view. The first few are kept.
    const lights = [];
    this.model.traverse((o) => { if (o.isLight) lights.push(o); });
    for (const light of lights.slice(maxModelLights)) light.removeFromParent();
    this.lightsDropped = Math.max(0, lights.length - maxModelLights);
    this.scene.add(this.model);
    let meshes = 0;
    this.model.traverse((o) => { if (o.isMesh) ++meshes; });
    // A model that moved away from the last one (another lot, a footprint elsewhere) is fitted
    // again: the user's camera would look at nothing.
    const bounds = new THREE.Box3().setFromObject(this.model);
    if (!this.fitted || (this.bounds && !this.bounds.isEmpty() && !bounds.isEmpty() && !bounds.intersectsBox(this.bounds))) {
      this.fit();
    }
    this.bounds = bounds;
    this.fade(Boolean(this.probe));
    this.showRoofs(this.roofsShown);
    this.showFurniture(this.furnitureShown);
    this.cut(this.cutFraction);
    return meshes;
  }

  // Shows or hides the roofs: the meshes of materials named as roofs (the semantic class
  // RoofSurface that mass models and .bldg buildings use, a CGA material named "roof ...").
  showRoofs(shown) {
    this.roofsShown = shown;
    if (!this.model) return;
    this.model.traverse((o) => {
      if (o.isMesh && o.material && /roof/i.test(o.material.name || '')) o.visible = shown;
    });
    this.render();
  }

  // Shows or hides furniture (parts of kind Furniture: what component programs place in rooms,
  // seed 001 §4.5): a node of its own (a placed instance) by its extras, and in a building's
  // merged mesh the triangles whose feature id's row says so (the index without them).
  showFurniture(shown) {
    this.furnitureShown = shown;
    if (!this.model) return;
    const kinds = this.table && this.table.columns.kind;
    const merged = kinds && kinds.includes('Furniture'); // else no merged mesh holds any
    this.model.traverse((o) => {
      if (o.userData && o.userData.kind === 'Furniture') {
        o.visible = shown;
        return;
      }
      const ids = o.isMesh && merged && o.geometry.attributes._feature_id_0;
      if (!ids || (shown && !o.geometry.userData.fullIndex)) return;
      const geometry = o.geometry;
      if (!geometry.userData.fullIndex) {
        geometry.userData.fullIndex = geometry.index
          ? geometry.index.array
          : Uint32Array.from({ length: ids.count }, (_, i) => i);
      }
      const full = geometry.userData.fullIndex;
      const kept = [];
      for (let t = 0; t + 2 < full.length; t += 3) {
        if (shown || kinds[Math.round(ids.getX(full[t]))] !== 'Furniture') kept.push(full[t], full[t + 1], full[t + 2]);
      }
      geometry.setIndex(kept);
    });
    this.render();
  }

  // Shows the GLB `bytes` (what one graph node made: the graph editor's selection) over the model
  // in one strong colour, the model faded around it; null takes it away. Returns its meshes.
  async highlight(bytes) {
    // A later call (another node, or none) wins over one still reading its model.
    const call = (this.highlightCalls = (this.highlightCalls || 0) + 1);
    if (this.probe) {
      this.scene.remove(this.probe);
      this.probe.traverse((o) => { if (o.geometry) o.geometry.dispose(); });
      this.probe = null;
    }
    this.fade(bytes !== null);
    if (bytes === null) {
      this.render();
      return 0;
    }
    const gltf = await this.loader.parseAsync(bytes, '');
    if (call !== this.highlightCalls) {
      gltf.scene.traverse((o) => { if (o.geometry) o.geometry.dispose(); });
      return 0;
    }
    this.probe = gltf.scene;
    // Drawn over the faded model's coplanar faces (the node's output is often part of it).
    const material = new THREE.MeshStandardMaterial({ color: 0xff7a00, emissive: 0x662200, roughness: 0.6,
                                                      polygonOffset: true, polygonOffsetFactor: -2, polygonOffsetUnits: -2,
                                                      side: THREE.DoubleSide });
    let meshes = 0;
    this.probe.traverse((o) => {
      if (o.isLight) o.visible = false;
      if (!o.isMesh) return;
      o.material = material;
      ++meshes;
    });
    this.scene.add(this.probe);
    this.render();
    return meshes;
  }

  // The model's materials see-through (and not hiding what lies behind) while something is
  // highlighted; their own again after.
  fade(faded) {
    if (!this.model) return;
    this.model.traverse((o) => {
      if (!o.isMesh) return;
      for (const m of Array.isArray(o.material) ? o.material : [o.material]) {
        if (m.userData.own === undefined) m.userData.own = { opacity: m.opacity, transparent: m.transparent, depthWrite: m.depthWrite };
        const own = m.userData.own;
        m.opacity = faded ? Math.min(own.opacity, 0.25) : own.opacity;
        m.transparent = faded || own.transparent;
        m.depthWrite = faded ? false : own.depthWrite;
        m.needsUpdate = true;
      }
    });
  }

  // Hides what stands above `fraction` of the model's height (1: nothing hidden).
  cut(fraction) {
    this.cutFraction = fraction;
    const b = this.bounds;
    this.cutPlane.constant = fraction >= 1 || !b || b.isEmpty()
      ? Infinity
      : b.min.y + fraction * (b.max.y - b.min.y);
    this.render();
  }

  fit() {
    const box = new THREE.Box3().setFromObject(this.model);
    if (box.isEmpty()) return;
    const centre = box.getCenter(new THREE.Vector3());
    const radius = box.getSize(new THREE.Vector3()).length() / 2;
    // The narrower of the vertical and horizontal fields of view must hold the model's sphere.
    const vertical = (this.camera.fov * Math.PI) / 180;
    const horizontal = 2 * Math.atan(Math.tan(vertical / 2) * this.camera.aspect);
    const distance = radius / Math.sin(Math.min(vertical, horizontal) / 2);
    this.camera.position.copy(centre).add(new THREE.Vector3(0.8, 0.6, 1).normalize().multiplyScalar(distance));
    this.camera.near = Math.max(0.01, distance / 1000);
    this.camera.far = distance * 20;
    this.camera.updateProjectionMatrix();
    this.controls.target.copy(centre);
    this.controls.update();
    this.fitted = true;
  }

  // The name and attributes of the object under the mouse, or ''.
  pick(event) {
    if (!this.model) return '';
    const rect = this.canvas.getBoundingClientRect();
    const pointer = new THREE.Vector2(((event.clientX - rect.left) / rect.width) * 2 - 1,
                                      -((event.clientY - rect.top) / rect.height) * 2 + 1);
    this.raycaster.setFromCamera(pointer, this.camera);
    // The first hit that is shown: not hidden (roofs, furniture) and not above the cut.
    const shown = (o) => {
      for (; o; o = o.parent) if (!o.visible) return false;
      return true;
    };
    const hit = this.raycaster.intersectObject(this.model, true)
      .find((h) => shown(h.object) && h.point.y <= this.cutPlane.constant);
    if (!hit) return '';
    // A merged mesh (one for the whole scene): the part under the mouse is its feature id's row.
    const ids = hit.object.geometry.attributes._feature_id_0;
    if (ids && this.table && hit.face) {
      const row = featureRow(this.table, Math.round(ids.getX(hit.face.a)));
      const lines = [`${row.building_id || row.part_name || 'part'}`];
      for (const [key, value] of Object.entries(row)) lines.push(`${key}: ${JSON.stringify(value)}`);
      return lines.join('\n');
    }
    let node = hit.object;
    while (node && !node.name && node.parent) node = node.parent;
    const lines = [node.name || '(unnamed)'];
    for (let o = node; o; o = o.parent) {
      for (const [key, value] of Object.entries(o.userData || {})) lines.push(`${key}: ${JSON.stringify(value)}`);
    }
    if (hit.object.material && hit.object.material.name) lines.push(`material: ${hit.object.material.name}`);
    return lines.join('\n');
  }
}
