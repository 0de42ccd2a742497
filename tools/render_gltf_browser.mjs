#!/usr/bin/env node
// Renders a glTF binary (.glb) or an OBJ (with its .mtl and textures beside it) in a real browser:
// Debian's chromium driven by npm playwright-core, three.js's GLTFLoader or OBJLoader + MTLLoader
// and WebGL (SwiftShader, no GPU), as a user opening the model in a three.js viewer sees it. Writes
// a PNG screenshot and prints one JSON line: the canvas size, how many of its pixels are mostly
// red, green, blue, white-ish or background (so a test can tell a textured model from an
// untextured one), and the model's bounding box in three.js's frame (Y up).
// Usage: node tools/render_gltf_browser.mjs MODEL.glb|MODEL.obj OUT.png [view]
//   view: front (default; looking at glTF -Z, Insula's +Y: a façade facing -Y) or top.
// Environment: INSULA_CHROMIUM (default /usr/bin/chromium). Exit status 0 on success, 1 when the
// browser or the model fails, 2 on usage error. Nothing is downloaded: pages come from this folder.
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { content_types, launchChromium } from './browser_common.mjs';

const [model, out, view = 'front'] = process.argv.slice(2);
if (!model || !out || !['front', 'top'].includes(view)) {
  console.error('usage: render_gltf_browser.mjs MODEL.glb|MODEL.obj OUT.png [front|top]');
  process.exit(2);
}
const is_obj = model.toLowerCase().endsWith('.obj');
const folder = path.dirname(path.resolve(model));
const mtl = path.join(folder, path.basename(model, path.extname(model)) + '.mtl');
const here = path.dirname(fileURLToPath(import.meta.url));
const three = path.join(here, 'node_modules', 'three');
const origin = 'http://insula.invalid';
const size = 512;

const page_html = `<!doctype html><html><head><style>body{margin:0;background:#000}</style>
<script type="importmap">{"imports":{"three":"${origin}/three/build/three.module.js",
"three/addons/":"${origin}/three/examples/jsm/"}}</script></head><body>
<script type="module">
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { OBJLoader } from 'three/addons/loaders/OBJLoader.js';
import { MTLLoader } from 'three/addons/loaders/MTLLoader.js';
import { MeshoptDecoder } from 'three/addons/libs/meshopt_decoder.module.js';
try {
  const renderer = new THREE.WebGLRenderer({ antialias: false, preserveDrawingBuffer: true });
  renderer.setPixelRatio(1);
  renderer.setSize(${size}, ${size});
  renderer.setClearColor(0x000000, 1);
  document.body.appendChild(renderer.domElement);
  const scene = new THREE.Scene();
  scene.add(new THREE.AmbientLight(0xffffff, 1.5));
  const sun = new THREE.DirectionalLight(0xffffff, 1.5);
  sun.position.set(0.3, 0.5, 1);
  scene.add(sun);
  let gltf;
  if (${is_obj}) {
    const loader = new OBJLoader();
    const materials = await new MTLLoader().setPath('${origin}/files/').loadAsync('model.mtl');
    materials.preload();
    loader.setMaterials(materials);
    gltf = { scene: await loader.loadAsync('${origin}/model.obj') };
  } else {
    // EXT_meshopt_compression (insula --compress) needs the decoder; other files ignore it.
    gltf = await new GLTFLoader().setMeshoptDecoder(MeshoptDecoder).loadAsync('${origin}/model.glb');
  }
  scene.add(gltf.scene);
  const box = new THREE.Box3().setFromObject(gltf.scene);
  const centre = box.getCenter(new THREE.Vector3());
  const extent = box.getSize(new THREE.Vector3());
  const half = Math.max(extent.x, extent.y, extent.z) * 0.55;
  const camera = new THREE.OrthographicCamera(-half, half, half, -half, 0.01, 1e5);
  const distance = Math.max(extent.x, extent.y, extent.z) * 4 + 10;
  if ('${view}' === 'top') {
    camera.position.set(centre.x, centre.y + distance, centre.z);
    camera.up.set(0, 0, -1);
  } else {
    camera.position.set(centre.x, centre.y, centre.z + distance);
  }
  camera.lookAt(centre);
  renderer.render(scene, camera);
  const gl = renderer.getContext();
  const pixels = new Uint8Array(${size} * ${size} * 4);
  gl.readPixels(0, 0, ${size}, ${size}, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
  const counts = { red: 0, green: 0, blue: 0, light: 0, background: 0, other: 0 };
  for (let i = 0; i < pixels.length; i += 4) {
    const [r, g, b] = [pixels[i], pixels[i + 1], pixels[i + 2]];
    if (r + g + b < 30) counts.background++;
    else if (r > 120 && g < 90 && b < 90) counts.red++;
    else if (g > 120 && r < 90 && b < 90) counts.green++;
    else if (b > 120 && r < 90 && g < 90) counts.blue++;
    else if (r > 150 && g > 150 && b > 150) counts.light++;
    else counts.other++;
  }
  const textures = [];
  gltf.scene.traverse((o) => {
    if (o.material && o.material.map) textures.push(o.material.map.image ? o.material.map.image.width : 0);
  });
  window.insulaResult = { width: ${size}, height: ${size}, counts, textured_meshes: textures.length,
                          min: box.min.toArray(), max: box.max.toArray() };
} catch (error) {
  window.insulaResult = { error: String(error && error.stack || error) };
}
</script></body></html>`;

let browser;
let status = 0;
try {
  browser = await launchChromium({ width: size, height: size });
  const { page } = browser;
  // Every request is answered from this machine; anything else is refused.
  await page.route('**/*', (route) => {
    const url = new URL(route.request().url());
    if (url.origin !== origin) return route.abort();
    let file;
    if (url.pathname === '/index.html') return route.fulfill({ contentType: 'text/html', body: page_html });
    if (url.pathname === '/model.glb' || url.pathname === '/model.obj') file = path.resolve(model);
    else if (url.pathname === '/files/model.mtl') file = mtl;
    else if (url.pathname.startsWith('/files/')) {
      file = path.join(folder, decodeURIComponent(url.pathname.slice(7)));  // the OBJ's textures
    } else if (url.pathname.startsWith('/three/')) file = path.join(three, url.pathname.slice(7));
    const allowed = file && (file === path.resolve(model) || file === mtl ||
                             file.startsWith(folder + path.sep) || file.startsWith(three));
    if (!allowed || !fs.existsSync(file)) return route.abort();
    return route.fulfill({ contentType: content_types[path.extname(file)] || 'application/octet-stream',
                           body: fs.readFileSync(file) });
  });
  await page.goto(`${origin}/index.html`);
  await page.waitForFunction(() => window.insulaResult !== undefined, null, { timeout: 60000 });
  const result = await page.evaluate(() => window.insulaResult);
  if (result.error) {
    console.log(JSON.stringify(result));
    status = 1;
  } else {
    await page.screenshot({ path: out });
    console.log(JSON.stringify(result));
  }
} catch (error) {
  console.error(`render_gltf_browser: ${error.message}`);
  status = 1;
} finally {
  if (browser) await browser.close();
}
process.exit(status);
