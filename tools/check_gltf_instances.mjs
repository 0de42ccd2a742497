// Opens a GLB with GPU instances (`insula build ... --gltf-instancing gpu`) in CesiumJS the way a
// 3D Tiles user meets it, and checks that the instances are drawn and picked as features of the
// property table: every node with EXT_mesh_gpu_instancing must reach CesiumJS with instance feature
// ids (EXT_instance_features; CesiumJS ignores EXT_mesh_features on a node), and a scan of the
// view must pick at least one feature named like an instanced node. Prints a JSON summary.
// Usage: node tools/check_gltf_instances.mjs FILE.glb [--png OUT.png]
// Exit status 0 when every check passes, 1 otherwise (each failure printed).
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { launchChromium, serveFiles } from './browser_common.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const args = process.argv.slice(2);
const glb = args[0];
const png = args.includes('--png') ? args[args.indexOf('--png') + 1] : null;
if (!glb) {
  console.error('usage: node tools/check_gltf_instances.mjs FILE.glb [--png OUT.png]');
  process.exit(2);
}

// The GLB's JSON chunk (glTF 2.0 §4.4: a 12-byte header, then the JSON chunk's length and type).
function gltf_json(file) {
  const bytes = fs.readFileSync(file);
  return JSON.parse(bytes.subarray(20, 20 + bytes.readUInt32LE(12)).toString('utf8'));
}

const json = gltf_json(glb);
const instanced = (json.nodes || [])
  .filter((node) => node.extensions && node.extensions.EXT_mesh_gpu_instancing)
  .map((node) => node.name);
const has_table = Boolean(json.extensions && json.extensions.EXT_structural_metadata);

// A tileset of the one GLB, placed at 14.39 E, 49.0 N (east-north-up), as a tile's content.
function enu_transform(lon_deg, lat_deg) {
  const lon = (lon_deg * Math.PI) / 180;
  const lat = (lat_deg * Math.PI) / 180;
  const a = 6378137.0;
  const e2 = 6.69437999014e-3;
  const n = a / Math.sqrt(1 - e2 * Math.sin(lat) ** 2);
  const origin = [n * Math.cos(lat) * Math.cos(lon), n * Math.cos(lat) * Math.sin(lon),
                  n * (1 - e2) * Math.sin(lat)];
  const east = [-Math.sin(lon), Math.cos(lon), 0];
  const north = [-Math.sin(lat) * Math.cos(lon), -Math.sin(lat) * Math.sin(lon), Math.cos(lat)];
  const up = [Math.cos(lat) * Math.cos(lon), Math.cos(lat) * Math.sin(lon), Math.sin(lat)];
  return [...east, 0, ...north, 0, ...up, 0, ...origin, 1];  // column-major
}
const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'insula-instances-'));
fs.copyFileSync(glb, path.join(dir, 'content.glb'));
fs.writeFileSync(path.join(dir, 'tileset.json'), JSON.stringify({
  asset: { version: '1.1' },
  geometricError: 100,
  root: {
    boundingVolume: { sphere: [0, 0, 0, 500] },
    geometricError: 0,
    refine: 'ADD',
    transform: enu_transform(14.39, 49.0),
    content: { uri: 'content.glb' },
  },
}));

const page_html = `<!doctype html><html><head><meta charset="utf-8">
<script>window.CESIUM_BASE_URL = '/cesium/';</script>
<link href="/cesium/Widgets/widgets.css" rel="stylesheet"><script src="/cesium/Cesium.js"></script>
<style>html,body,#view{margin:0;width:800px;height:600px;overflow:hidden}</style></head><body>
<div id="view"></div><script>
(async () => {
  const r = { instanced: [], picked: {} };
  try {
    const viewer = new Cesium.Viewer('view', { baseLayer: false, geocoder: false,
      terrainProvider: new Cesium.EllipsoidTerrainProvider(), baseLayerPicker: false,
      homeButton: false, sceneModePicker: false, navigationHelpButton: false, animation: false,
      timeline: false, fullscreenButton: false, infoBox: false, selectionIndicator: false,
      contextOptions: { webgl: { preserveDrawingBuffer: true } } });
    const scene = viewer.scene;
    scene.skyAtmosphere.show = false;
    scene.skyBox.show = false;
    scene.fog.enabled = false;
    const tileset = await Cesium.Cesium3DTileset.fromUrl('/tileset/tileset.json',
                                                         { maximumScreenSpaceError: 1 });
    tileset.tileFailed.addEventListener((e) => (r.failed = (r.failed || []).concat(e.message)));
    scene.primitives.add(tileset);
    const settle = async () => {
      for (let settled = 0; settled < 10;) {
        await new Promise((done) => requestAnimationFrame(done));
        settled = tileset.tilesLoaded ? settled + 1 : 0;
      }
    };
    await viewer.zoomTo(tileset);
    await settle();
    const model = tileset.root.content._model;
    const sphere = model.boundingSphere;
    await viewer.zoomTo(tileset, new Cesium.HeadingPitchRange(0.6, -0.35, 2.2 * sphere.radius));
    await settle();
    for (const node of model.sceneGraph._runtimeNodes) {
      if (!node || !node.node.instances) continue;
      r.instanced.push({ name: node.node.name,
                         feature_ids: node.node.instances.featureIds.map((f) => f.label ?? f.positionalLabel) });
    }
    // Every 20 pixels of the view: which feature (its property table row and name) is there.
    for (let x = 10; x < 800; x += 20) {
      for (let y = 10; y < 600; y += 20) {
        const picked = scene.pick(new Cesium.Cartesian2(x, y));
        if (!(picked instanceof Cesium.Cesium3DTileFeature)) continue;
        const name = String(picked.getProperty('part_name'));
        r.picked[name] = (r.picked[name] || 0) + 1;
      }
    }
  } catch (e) {
    r.error = String((e && e.stack) || e);
  }
  window.result = r;
})();
</script></body></html>`;

const server = await serveFiles({
  mounts: { '/cesium/': path.join(here, 'node_modules/cesium/Build/Cesium'), '/tileset/': dir },
  pages: { '/index.html': page_html },
});
const browser = await launchChromium({ width: 800, height: 600 });
let result;
try {
  await browser.page.route('**/*', (route) =>
    route.request().url().startsWith(server.origin) ? route.continue() : route.abort());
  await browser.page.goto(server.origin + '/index.html');
  await browser.page.waitForFunction(() => window.result !== undefined, null, { timeout: 180000 });
  result = await browser.page.evaluate(() => window.result);
  if (png) await browser.page.screenshot({ path: png });
} finally {
  await browser.close();
  await server.close();
  fs.rmSync(dir, { recursive: true, force: true });
}

const failures = [];
if (result.error) failures.push(`CesiumJS: ${result.error}`);
if (result.failed) failures.push(`tile failed: ${result.failed.join('; ')}`);
if (instanced.length === 0) failures.push('the GLB has no node with EXT_mesh_gpu_instancing');
if (result.instanced.length !== instanced.length) {
  failures.push(`CesiumJS instanced ${result.instanced.length} nodes, the GLB has ${instanced.length}`);
}
for (const node of result.instanced) {
  if (has_table && node.feature_ids.length === 0) {
    failures.push(`instances of ${node.name} reach CesiumJS without feature ids`);
  }
}
const picked_instances = Object.keys(result.picked).filter((name) => instanced.includes(name));
if (has_table && picked_instances.length === 0) {
  failures.push(`no pick found a feature of an instanced node (${instanced.join(', ')})`);
}
console.log(JSON.stringify({ instanced: result.instanced, picked: result.picked, picked_instances }));
for (const failure of failures) console.error(`check_gltf_instances: ${failure}`);
process.exit(failures.length === 0 ? 0 : 1);
