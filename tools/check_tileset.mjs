#!/usr/bin/env node
// Checks a 3D Tiles 1.1 tileset the way its users open it, in three passes:
//  1. structure, in node: tileset.json parses, asset.version "1.1", every tile has a valid
//     boundingVolume and a geometricError >= 0 that is not above its parent's, every child region
//     lies inside its parent's (1e-9 rad, 1 mm), transforms are affine 4x4, every content uri
//     exists (external tilesets are followed) and every glTF content has 0 errors in the Khronos
//     glTF validator (npm gltf-validator);
//  2. loaders.gl (@loaders.gl/3d-tiles Tiles3DLoader, @loaders.gl/tiles Tileset3D) in node,
//     traversed with a web-mercator viewport looking straight down at the tileset's centre until
//     loaded: tiles selected and loaded, every loaded content parsed as glTF;
//  3. CesiumJS (tools/node_modules/cesium) in Debian's chromium (playwright-core, SwiftShader
//     WebGL), offline: a Viewer with no imagery, ellipsoid terrain and maximumScreenSpaceError 1
//     zooms to the tileset and waits for all tiles: tiles loaded, features (sum of
//     content.featuresLength), the root bounding sphere's centre as lon/lat/height, the feature
//     picked nearest the canvas centre with its properties; tile failures, page or console
//     errors, HTTP 404s under the tileset, and a content whose bounding sphere (Cesium's) has its
//     centre outside its tile's region or is larger than the region's sphere fail the check, and
//     so does a tileset with contents of which loaders.gl or Cesium loaded none.
//     Warnings (stderr, not failures): loaders.gl reading empty strings or all-zero feature ids
//     (its EXT_structural_metadata / EXT_mesh_features decoding runs before meshopt's).
// Every file comes from a local HTTP server on 127.0.0.1 (tools/browser_common.mjs); any other
// request is refused.
// Usage: node tools/check_tileset.mjs DIR/tileset.json [--png OUT.png] [--expect-features N]
//            [--lonlat LON,LAT [--tolerance-m M]] [--timeout SECONDS]
//   --expect-features N  fail unless Cesium's loaded features sum to N
//   --lonlat LON,LAT     fail unless the root bounding sphere's centre lies within M metres
//                        (great circle, default 100) of LON,LAT (degrees)
//   --png OUT.png        screenshot of Cesium's view
//   --timeout SECONDS    per pass (loaders.gl, Cesium), default 120
// Prints one JSON line on stdout: {"tiles","features","center":[lon,lat,h],"loadersgl":{...},
// "picked":{...},"structure":{...},"seconds"}. Each failure goes to stderr as
// "check_tileset: FAIL ...". Exit status 0 when every check passes, 1 on any failure, 2 on usage.
// Environment: INSULA_CHROMIUM (default /usr/bin/chromium).
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import validator from 'gltf-validator';
import { load } from '@loaders.gl/core';
import { Tiles3DLoader } from '@loaders.gl/3d-tiles';
import { Tileset3D } from '@loaders.gl/tiles';
import { WebMercatorViewport } from '@math.gl/web-mercator';
import { Matrix4, Vector3 } from '@math.gl/core';
import { launchChromium, serveFiles } from './browser_common.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const usage = 'usage: check_tileset.mjs DIR/tileset.json [--png OUT.png] [--expect-features N] ' +
              '[--lonlat LON,LAT [--tolerance-m M]] [--timeout SECONDS]';

function usageError(message) {
  console.error(`check_tileset: ${message}\n${usage}`);
  process.exit(2);
}

function parseArgs(argv) {
  const options = { png: null, expectFeatures: null, lonlat: null, toleranceM: 100, timeoutS: 120 };
  let tileset = null;
  for (let i = 0; i < argv.length; ++i) {
    const arg = argv[i];
    const value = () => {
      if (i + 1 >= argv.length) usageError(`${arg} needs a value`);
      return argv[++i];
    };
    const number = (text, what) => {
      const n = Number(text);
      if (text.trim() === '' || !Number.isFinite(n)) usageError(`${what}: not a number: ${text}`);
      return n;
    };
    if (arg === '--png') options.png = value();
    else if (arg === '--expect-features') {
      options.expectFeatures = number(value(), arg);
      if (!Number.isInteger(options.expectFeatures) || options.expectFeatures < 0) {
        usageError('--expect-features needs a whole number >= 0');
      }
    } else if (arg === '--lonlat') {
      const parts = value().split(',');
      if (parts.length !== 2) usageError('--lonlat needs LON,LAT in degrees');
      options.lonlat = parts.map((p) => number(p, '--lonlat'));
      if (Math.abs(options.lonlat[0]) > 180 || Math.abs(options.lonlat[1]) > 90) {
        usageError('--lonlat out of range');
      }
    } else if (arg === '--tolerance-m') {
      options.toleranceM = number(value(), arg);
      if (options.toleranceM < 0) usageError('--tolerance-m must be >= 0');
    } else if (arg === '--timeout') {
      options.timeoutS = number(value(), arg);
      if (options.timeoutS <= 0) usageError('--timeout must be > 0');
    } else if (arg === '-h' || arg === '--help') {
      console.log(usage);
      process.exit(0);
    } else if (arg.startsWith('-')) usageError(`unknown option ${arg}`);
    else if (tileset === null) tileset = arg;
    else usageError(`more than one tileset: ${arg}`);
  }
  if (tileset === null) usageError('no tileset given');
  return { tileset: path.resolve(tileset), options };
}

const failures = [];
const warnings = [];
function fail(message) {
  failures.push(message);
  console.error(`check_tileset: FAIL ${message}`);
}
function warn(message) {
  warnings.push(message);
  console.error(`check_tileset: warning: ${message}`);
}

// ---------------------------------------------------------------------------------------------
// 1. Structure

const finite = (a, n) => Array.isArray(a) && a.length === n && a.every((x) => Number.isFinite(x));

function checkBoundingVolume(volume, where) {
  if (!volume || typeof volume !== 'object') {
    fail(`${where}: no boundingVolume`);
    return null;
  }
  const kinds = ['region', 'box', 'sphere'].filter((k) => volume[k] !== undefined);
  if (kinds.length === 0) {
    fail(`${where}: boundingVolume has no region, box or sphere`);
    return null;
  }
  if (volume.region !== undefined) {
    const r = volume.region;
    if (!finite(r, 6)) {
      fail(`${where}: boundingVolume.region is not 6 numbers`);
      return null;
    }
    const [west, south, east, north, minH, maxH] = r;
    const pi = Math.PI + 1e-12;
    if (Math.abs(west) > pi || Math.abs(east) > pi) fail(`${where}: region west/east outside [-pi, pi] (degrees instead of radians?)`);
    if (Math.abs(south) > pi / 2 || Math.abs(north) > pi / 2) fail(`${where}: region south/north outside [-pi/2, pi/2]`);
    if (south > north) fail(`${where}: region south ${south} > north ${north}`);
    if (minH > maxH) fail(`${where}: region minimum height ${minH} > maximum ${maxH}`);
  }
  if (volume.box !== undefined && !finite(volume.box, 12)) fail(`${where}: boundingVolume.box is not 12 numbers`);
  if (volume.sphere !== undefined && (!finite(volume.sphere, 4) || volume.sphere[3] < 0)) {
    fail(`${where}: boundingVolume.sphere is not [x, y, z, radius >= 0]`);
  }
  return volume.region !== undefined && finite(volume.region, 6) ? volume.region : null;
}

// A longitude's and a region's eastward distance from west, in [0, 2 pi): a region across the
// antimeridian (west > east) is as wide as any other.
function eastOf(longitude, west) {
  const turn = 2 * Math.PI;
  return ((longitude - west) % turn + turn) % turn;
}

function regionInside(child, parent) {
  const eps = 1e-9;  // radians, about 6 mm
  const epsH = 1e-3;  // metres
  const parentWidth = eastOf(parent[2], parent[0]);
  const start = eastOf(child[0], parent[0] - eps) - eps;
  return start + eastOf(child[2], child[0]) <= parentWidth + eps &&
         child[1] >= parent[1] - eps && child[3] <= parent[3] + eps &&
         child[4] >= parent[4] - epsH && child[5] <= parent[5] + epsH;
}

async function validateGlb(file, where, structure) {
  let report;
  try {
    report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)), {
      uri: path.basename(file),
      maxIssues: 1000,
      externalResourceFunction: (uri) => new Promise((resolve, reject) => {
        const resolved = path.resolve(path.dirname(file), decodeURIComponent(uri));
        fs.readFile(resolved, (error, data) => (error ? reject(error.toString()) : resolve(data)));
      }),
    });
  } catch (error) {
    fail(`${where}: ${path.basename(file)} is not a glTF asset: ${error}`);
    structure.gltf_errors += 1;
    return;
  }
  const issues = report.issues;
  structure.gltf_files += 1;
  structure.gltf_errors += issues.numErrors;
  structure.gltf_warnings += issues.numWarnings;
  for (const message of issues.messages) {
    if (message.severity === 0) {
      fail(`${where}: glTF validator: ${message.code} at ${message.pointer ?? '?'}: ${message.message}`);
    } else if (message.severity === 1) {
      structure.gltf_warning_codes[message.code] = (structure.gltf_warning_codes[message.code] || 0) + 1;
    }
  }
  for (const extension of report.info?.extensionsUsed || []) structure.extensions.add(extension);
}

async function checkStructure(tilesetFile) {
  const structure = { tiles: 0, leaves: 0, contents: 0, gltf_files: 0, gltf_errors: 0,
                      gltf_warnings: 0, gltf_warning_codes: {}, extensions: new Set(),
                      max_depth: 0 };
  const visitedTilesets = new Set();

  async function checkTilesetFile(file, parentTile, parentWhere, depth) {
    const where0 = path.relative(path.dirname(tilesetFile), file) || path.basename(file);
    if (visitedTilesets.has(file)) {
      fail(`${where0}: external tileset cycle`);
      return null;
    }
    visitedTilesets.add(file);
    let json;
    try {
      json = JSON.parse(fs.readFileSync(file, 'utf8'));
    } catch (error) {
      fail(`${where0}: does not parse: ${error.message}`);
      return null;
    }
    if (!json.asset || json.asset.version !== '1.1') {
      fail(`${where0}: asset.version is ${JSON.stringify(json.asset?.version)}, not "1.1"`);
    }
    if (!Number.isFinite(json.geometricError) || json.geometricError < 0) {
      fail(`${where0}: top-level geometricError missing or < 0`);
    }
    if (!json.root || typeof json.root !== 'object') {
      fail(`${where0}: no root tile`);
      return json;
    }
    if (parentTile === null && json.root.refine !== 'ADD' && json.root.refine !== 'REPLACE') {
      fail(`${where0}: root.refine must be "ADD" or "REPLACE"`);
    }
    if (Number.isFinite(json.geometricError) && Number.isFinite(json.root.geometricError) &&
        json.root.geometricError > json.geometricError) {
      fail(`${where0}: root geometricError ${json.root.geometricError} > tileset's ${json.geometricError}`);
    }
    await checkTile(json.root, parentTile, `${where0}:root`, path.dirname(file), depth);
    return json;
  }

  async function checkContent(content, tile, where, base, depth) {
    if (!content || typeof content.uri !== 'string') {
      fail(`${where}: content without uri`);
      return;
    }
    structure.contents += 1;
    if (content.boundingVolume !== undefined) checkBoundingVolume(content.boundingVolume, `${where}.content`);
    if (/^[a-z][a-z0-9+.-]*:/i.test(content.uri)) {
      fail(`${where}: content uri ${content.uri} is not relative`);
      return;
    }
    const file = path.resolve(base, decodeURIComponent(content.uri.split(/[?#]/)[0]));
    if (!fs.existsSync(file)) {
      fail(`${where}: content ${content.uri} does not exist (${file})`);
      return;
    }
    const ext = path.extname(file).toLowerCase();
    if (ext === '.glb' || ext === '.gltf') await validateGlb(file, `${where} ${content.uri}`, structure);
    else if (ext === '.json') await checkTilesetFile(file, tile, where, depth + 1);
    else warn(`${where}: content ${content.uri}: not glTF, not validated`);
  }

  async function checkTile(tile, parent, where, base, depth) {
    structure.tiles += 1;
    structure.max_depth = Math.max(structure.max_depth, depth);
    const region = checkBoundingVolume(tile.boundingVolume, where);
    tile.__region = region;
    if (!Number.isFinite(tile.geometricError) || tile.geometricError < 0) {
      fail(`${where}: geometricError ${JSON.stringify(tile.geometricError)} is not a number >= 0`);
    } else if (parent && Number.isFinite(parent.geometricError) && tile.geometricError > parent.geometricError) {
      fail(`${where}: geometricError ${tile.geometricError} > its parent's ${parent.geometricError}`);
    }
    if (tile.refine !== undefined && tile.refine !== 'ADD' && tile.refine !== 'REPLACE') {
      fail(`${where}: refine ${JSON.stringify(tile.refine)} is not "ADD" or "REPLACE"`);
    }
    if (tile.transform !== undefined) {
      const m = tile.transform;
      if (!finite(m, 16)) fail(`${where}: transform is not 16 numbers`);
      else if (m[3] !== 0 || m[7] !== 0 || m[11] !== 0 || m[15] !== 1) {
        fail(`${where}: transform's last row is not [0, 0, 0, 1] (row-major instead of column-major?)`);
      }
    }
    if (parent && parent.__region && region && !regionInside(region, parent.__region)) {
      const deg = (r) => r.slice(0, 4).map((x) => (x * 180 / Math.PI).toFixed(7)).concat(r.slice(4)).join(', ');
      fail(`${where}: region [${deg(region)}] (degrees) is not inside its parent's [${deg(parent.__region)}]`);
    }
    if (tile.implicitTiling !== undefined) warn(`${where}: implicit tiling is not checked`);
    const contents = [];
    if (tile.content !== undefined) contents.push(tile.content);
    if (Array.isArray(tile.contents)) contents.push(...tile.contents);
    for (const content of contents) await checkContent(content, tile, where, base, depth);
    const children = tile.children ?? [];
    if (!Array.isArray(children)) {
      fail(`${where}: children is not an array`);
      return;
    }
    if (children.length === 0) structure.leaves += 1;
    for (let i = 0; i < children.length; ++i) {
      await checkTile(children[i], tile, `${where}/${i}`, base, depth + 1);
    }
  }

  const json = await checkTilesetFile(tilesetFile, null, '', 0);
  return { json, structure: { ...structure, extensions: [...structure.extensions].sort() } };
}

// ---------------------------------------------------------------------------------------------
// 2. loaders.gl

// @math.gl/web-mercator's viewport lacks what Tileset3D reads from deck.gl's (id, camera
// position/direction/up in common space, frustum planes); added here as getters (it is frozen).
class TilesViewport extends WebMercatorViewport {
  get id() { return 'check_tileset'; }
  get viewInverse() { return new Matrix4(this.viewMatrix).invert(); }
  get cameraPosition() {
    const m = this.viewInverse;
    return [m[12], m[13], m[14]];
  }
  get cameraDirection() { return new Vector3(this.viewInverse.transformAsVector([0, 0, -1])).normalize(); }
  get cameraUp() { return new Vector3(this.viewInverse.transformAsVector([0, 1, 0])).normalize(); }
  getFrustumPlanes() {
    const m = this.viewProjectionMatrix;
    const plane = (a, b, c, d) => {
      const l = Math.hypot(a, b, c);
      return { distance: d / l, normal: new Vector3(-a / l, -b / l, -c / l) };
    };
    return {
      left: plane(m[3] + m[0], m[7] + m[4], m[11] + m[8], m[15] + m[12]),
      right: plane(m[3] - m[0], m[7] - m[4], m[11] - m[8], m[15] - m[12]),
      bottom: plane(m[3] + m[1], m[7] + m[5], m[11] + m[9], m[15] + m[13]),
      top: plane(m[3] - m[1], m[7] - m[5], m[11] - m[9], m[15] - m[13]),
      near: plane(m[3] + m[2], m[7] + m[6], m[11] + m[10], m[15] + m[14]),
      far: plane(m[3] - m[2], m[7] - m[6], m[11] - m[10], m[15] - m[14]),
    };
  }
}

async function checkLoadersGl(url, timeoutS) {
  const result = { tiles: 0, selected: 0, features: 0, extensions: [] };
  const errors = [];
  const extensions = new Set();
  let json;
  try {
    json = await load(url, Tiles3DLoader);
  } catch (error) {
    fail(`loaders.gl: tileset does not load: ${error.message}`);
    return result;
  }
  const loaded = [];
  const tileset = new Tileset3D(json, {
    maximumScreenSpaceError: 1,
    loadOptions: { '3d-tiles': { loadGLTF: true } },
    onTileLoad: (tile) => loaded.push(tile),
    onTileError: (tile, message, tileUrl) => errors.push(`${tileUrl || tile?.contentUrl}: ${message}`),
  });
  const [longitude, latitude] = tileset.cartographicCenter || [0, 0];
  const viewport = new TilesViewport({ width: 800, height: 600, longitude, latitude,
                                       zoom: tileset.zoom, pitch: 0, bearing: 0 });
  const deadline = Date.now() + timeoutS * 1000;
  let settled = 0;
  while (Date.now() < deadline) {
    tileset.selectTiles([viewport]);
    await new Promise((resolve) => setTimeout(resolve, 50));
    settled = tileset.isLoaded() ? settled + 1 : 0;
    if (settled >= 5) break;
  }
  if (settled < 5) fail(`loaders.gl: tileset not loaded after ${timeoutS} s`);
  for (const error of errors) fail(`loaders.gl: tile failed: ${error}`);
  result.selected = tileset.selectedTiles.length;
  result.tiles = loaded.length;
  for (const tile of loaded) {
    const gltf = tile.content?.gltf;
    const name = tile.contentUrl || tile.id;
    if (!gltf || !Array.isArray(gltf.meshes)) {
      fail(`loaders.gl: ${name}: content did not parse as glTF (type ${tile.content?.type})`);
      continue;
    }
    for (const e of [...(gltf.extensionsUsed || []), ...(gltf.extensionsRemoved || [])]) extensions.add(e);
    for (const mesh of gltf.meshes) {
      for (const primitive of mesh.primitives || []) {
        const position = primitive.attributes?.POSITION;
        if (!position || !position.value || position.value.length === 0) {
          fail(`loaders.gl: ${name}: mesh ${mesh.name ?? '?'} has no decoded POSITION`);
        }
      }
    }
    const tables = gltf.extensions?.EXT_structural_metadata?.propertyTables || [];
    if (tables.length > 0) result.features += tables[0].count || 0;
    let ids = 0;
    let nonzero = 0;
    for (const mesh of gltf.meshes) {
      for (const primitive of mesh.primitives || []) {
        for (const set of primitive.extensions?.EXT_mesh_features?.featureIds || []) {
          for (const id of set.data || []) {
            ++ids;
            if (id !== 0) ++nonzero;
          }
        }
      }
    }
    if (ids > 0 && nonzero === 0 && (tables[0]?.count || 0) > 1) {
      warn(`loaders.gl: ${name}: every feature id is 0 though the property table has ` +
           `${tables[0].count} rows (loaders.gl reads EXT_mesh_features before undoing ` +
           'EXT_meshopt_compression of its buffer views?)');
    }
    for (const table of tables) {
      for (const [property, column] of Object.entries(table.properties || {})) {
        const data = column?.data;
        if (Array.isArray(data) && data.length > 0 && data.every((v) => v === '')) {
          warn(`loaders.gl: ${name}: property table ${table.name ?? '?'}: every ${property} string ` +
               'is empty (loaders.gl reads EXT_structural_metadata before undoing ' +
               'EXT_meshopt_compression of its buffer views?)');
        }
      }
    }
  }
  result.extensions = [...extensions].sort();
  tileset.destroy?.();
  return result;
}

// ---------------------------------------------------------------------------------------------
// 3. CesiumJS in chromium

const cesiumPage = (tilesetUrl, width, height) => `<!doctype html><html><head><meta charset="utf-8">
<script>window.CESIUM_BASE_URL = '/cesium/';</script>
<link href="/cesium/Widgets/widgets.css" rel="stylesheet">
<script src="/cesium/Cesium.js"></script>
<style>html,body,#view{margin:0;padding:0;width:${width}px;height:${height}px;overflow:hidden}</style>
</head><body><div id="view"></div><script>
(async () => {
  const result = { failed: [], events: { load: 0, unload: 0 }, seconds: {} };
  let mark = performance.now();
  const lap = (name) => {
    result.seconds[name] = Math.round(performance.now() - mark) / 1000;
    mark = performance.now();
  };
  const frames = (n) => new Promise((resolve) => {
    const step = () => (--n <= 0 ? resolve() : requestAnimationFrame(step));
    requestAnimationFrame(step);
  });
  try {
    const viewer = new Cesium.Viewer('view', {
      baseLayer: false, terrainProvider: new Cesium.EllipsoidTerrainProvider(),
      geocoder: false, baseLayerPicker: false, homeButton: false, sceneModePicker: false,
      navigationHelpButton: false, animation: false, timeline: false, fullscreenButton: false,
      infoBox: false, selectionIndicator: false, requestRenderMode: false,
      contextOptions: { webgl: { preserveDrawingBuffer: true } },
    });
    window.viewer = viewer;
    lap('viewer');
    // SwiftShader draws on the CPU: leave out the effects that cost most per frame.
    const scene = viewer.scene;
    scene.globe.baseColor = Cesium.Color.fromCssColorString('#4a5d3a');
    scene.globe.showGroundAtmosphere = false;
    scene.skyAtmosphere.show = false;
    scene.skyBox.show = false;
    scene.sun.show = false;
    scene.moon.show = false;
    scene.fog.enabled = false;
    scene.highDynamicRange = false;
    scene.postProcessStages.fxaa.enabled = false;
    const tileset = await Cesium.Cesium3DTileset.fromUrl(${JSON.stringify(tilesetUrl)},
                                                         { maximumScreenSpaceError: 1 });
    tileset.tileLoad.addEventListener(() => ++result.events.load);
    tileset.tileUnload.addEventListener(() => ++result.events.unload);
    tileset.tileFailed.addEventListener((e) => result.failed.push(e.url + ': ' + e.message));
    viewer.scene.primitives.add(tileset);
    lap('tileset_json');
    // The whole root sphere in view from the south at 45 degrees (zoomTo's own range crops it).
    const sphere = tileset.root.boundingSphere;
    await viewer.zoomTo(tileset, new Cesium.HeadingPitchRange(0, -Math.PI / 4, sphere.radius * 2.4));
    // Light from behind the camera, whatever the time of day.
    viewer.scene.light = new Cesium.DirectionalLight({
      direction: Cesium.Cartesian3.clone(viewer.camera.directionWC) });
    // Loaded when Cesium reports nothing pending or processing for 10 frames in a row.
    let settled = 0;
    result.frames = 0;
    while (settled < 10) {
      await frames(1);
      ++result.frames;
      settled = tileset.tilesLoaded ? settled + 1 : 0;
    }
    lap('tiles_loaded');
    let tiles = 0, features = 0;
    const walk = (tile) => {
      if (tile.contentReady && !tile.hasEmptyContent && !tile.hasTilesetContent) {
        ++tiles;
        features += tile.content.featuresLength;
      }
      for (const child of tile.children) walk(child);
    };
    walk(tileset.root);
    // Every feature's properties, read back through Cesium's metadata (not the picking).
    result.properties = {};
    result.emptyStrings = [];
    const readFeatures = (tile) => {
      if (tile.contentReady && !tile.hasEmptyContent && !tile.hasTilesetContent) {
        const content = tile.content;
        const empty = {};
        for (let i = 0; i < content.featuresLength; ++i) {
          const feature = content.getFeature(i);
          for (const id of feature.getPropertyIds()) {
            const value = feature.getProperty(id);
            result.properties[id] = (result.properties[id] || 0) + 1;
            if (typeof value === 'string') empty[id] = (empty[id] ?? true) && value === '';
          }
        }
        for (const [id, all] of Object.entries(empty)) {
          if (all) result.emptyStrings.push(content.url + ': ' + id);
        }
      }
      for (const child of tile.children) readFeatures(child);
    };
    readFeatures(tileset.root);
    // Each glTF content's bounding sphere (Cesium's, from accessor min/max, node and tile
    // transforms) against its tile's region: the centre inside (1 m slack), the radius no larger
    // than the region's sphere. Catches a wrong transform or a region too small for its content.
    result.contentChecked = 0;
    result.contentOutside = [];
    const checkContentVolume = (tile) => {
      const region = tile.boundingVolume && tile.boundingVolume.rectangle;
      const model = tile.contentReady && !tile.hasEmptyContent && tile.content && tile.content._model;
      if (region && model && model.boundingSphere) {
        ++result.contentChecked;
        const sphere = model.boundingSphere;
        const c = Cesium.Cartographic.fromCartesian(sphere.center);
        const slack = 1 / 6378137;
        const r = region;
        const bv = tile.boundingVolume;
        const turn = 2 * Math.PI;  // longitudes east of r.west (a region may cross the antimeridian)
        const lonSlack = slack / Math.cos(c.latitude);
        const east = (lon) => ((lon - (r.west - lonSlack)) % turn + turn) % turn;
        const inside = east(c.longitude) <= east(r.east) + lonSlack &&
          c.latitude >= r.south - slack && c.latitude <= r.north + slack &&
          c.height >= bv.minimumHeight - 1 && c.height <= bv.maximumHeight + 1;
        const limit = tile.boundingSphere.radius + 1;
        const deg = (x) => Cesium.Math.toDegrees(x).toFixed(7);
        if (!inside) {
          result.contentOutside.push(content_name(tile) + ': content centre ' + deg(c.longitude) + ', ' +
            deg(c.latitude) + ', ' + c.height.toFixed(1) + ' m lies outside the tile region [' +
            [r.west, r.south, r.east, r.north].map(deg).join(', ') + ', ' + bv.minimumHeight + ', ' +
            bv.maximumHeight + ']');
        } else if (sphere.radius > limit) {
          result.contentOutside.push(content_name(tile) + ': content bounding sphere radius ' +
            sphere.radius.toFixed(1) + ' m exceeds the ' + limit.toFixed(1) + ' m of the tile region sphere');
        }
      }
      for (const child of tile.children) checkContentVolume(child);
    };
    const content_name = (tile) => (tile.content && tile.content.url || '?').replace(location.origin, '');
    checkContentVolume(tileset.root);
    result.tiles = tiles;
    result.features = features;
    const c = Cesium.Cartographic.fromCartesian(tileset.root.boundingSphere.center);
    result.center = [Cesium.Math.toDegrees(c.longitude), Cesium.Math.toDegrees(c.latitude), c.height];
    result.radius = tileset.root.boundingSphere.radius;
    // The feature nearest the canvas centre (a spiral of probes).
    const canvas = viewer.scene.canvas;
    result.picked = null;
    outer: for (let ring = 0; ring <= 12; ++ring) {
      for (let i = -ring; i <= ring; ++i) {
        for (let j = -ring; j <= ring; ++j) {
          if (Math.max(Math.abs(i), Math.abs(j)) !== ring) continue;
          const x = canvas.clientWidth / 2 + i * 16, y = canvas.clientHeight / 2 + j * 16;
          const picked = viewer.scene.pick(new Cesium.Cartesian2(x, y));
          if (picked instanceof Cesium.Cesium3DTileFeature) {
            const properties = {};
            for (const id of picked.getPropertyIds()) properties[id] = picked.getProperty(id);
            result.picked = { x, y, featureId: picked.featureId, properties };
            break outer;
          }
        }
      }
    }
    lap('pick');
    await frames(5);
  } catch (error) {
    result.error = String(error && error.stack || error);
  }
  window.insulaResult = result;
})();
</script></body></html>`;

async function checkCesium(tilesetFile, options) {
  const width = 800;
  const height = 600;
  const cesium = path.join(here, 'node_modules', 'cesium', 'Build', 'Cesium');
  if (!fs.existsSync(path.join(cesium, 'Cesium.js'))) {
    fail(`Cesium: ${cesium}/Cesium.js missing (cd tools && npm ci)`);
    return null;
  }
  const tilesetUrl = `/tileset/${encodeURIComponent(path.basename(tilesetFile))}`;
  const server = await serveFiles({
    mounts: { '/cesium/': cesium, '/tileset/': path.dirname(tilesetFile) },
    pages: { '/index.html': cesiumPage(tilesetUrl, width, height) },
  });
  let browser;
  const pageErrors = [];
  const blocked = [];
  try {
    browser = await launchChromium({ width, height });
    const { page } = browser;
    // A page error before the result (a script that does not run) ends the wait at once.
    let pageFailed;
    const failedEarly = new Promise((resolve, reject) => { pageFailed = reject; });
    failedEarly.catch(() => {});
    page.on('pageerror', (error) => {
      pageErrors.push(`page error: ${error.message}`);
      pageFailed(new Error(`page error before the result: ${error.message}`));
    });
    page.on('console', (message) => {
      if (message.type() === 'error') pageErrors.push(`console error: ${message.text()}`);
    });
    // Only the local server answers; anything else (Cesium ion, imagery) is refused and reported.
    await page.route('**/*', (route) => {
      const url = route.request().url();
      if (url.startsWith(server.origin + '/') || url.startsWith('data:') || url.startsWith('blob:')) {
        return route.continue();
      }
      blocked.push(url);
      return route.abort();
    });
    await page.goto(`${server.origin}/index.html`);
    await Promise.race([
      page.waitForFunction(() => window.insulaResult !== undefined, null,
                           { timeout: options.timeoutS * 1000 }),
      failedEarly]);
    const result = await page.evaluate(() => window.insulaResult);
    if (options.png) await page.screenshot({ path: options.png });
    if (result.error) fail(`Cesium: ${result.error}`);
    for (const failure of result.failed || []) fail(`Cesium: tile failed: ${failure}`);
    for (const column of result.emptyStrings || []) warn(`Cesium: every feature's ${column} is an empty string`);
    for (const message of result.contentOutside || []) fail(`Cesium: ${message}`);
    for (const error of pageErrors) fail(`Cesium: ${error}`);
    for (const entry of server.log) {
      if (entry.status !== 200 && entry.url.startsWith('/tileset/')) fail(`Cesium: HTTP ${entry.status} for ${entry.url}`);
    }
    for (const url of blocked) warn(`Cesium: refused a request off this machine: ${url}`);
    return result;
  } catch (error) {
    fail(`Cesium: ${error.message.split('\n')[0]}`);
    for (const message of pageErrors) fail(`Cesium: ${message}`);
    return null;
  } finally {
    if (browser) await browser.close();
    await server.close();
  }
}

// ---------------------------------------------------------------------------------------------

function greatCircleMetres([lon1, lat1], [lon2, lat2]) {
  const r = Math.PI / 180;
  const dLat = (lat2 - lat1) * r;
  const dLon = (lon2 - lon1) * r;
  const a = Math.sin(dLat / 2) ** 2 + Math.cos(lat1 * r) * Math.cos(lat2 * r) * Math.sin(dLon / 2) ** 2;
  return 2 * 6371008.8 * Math.asin(Math.min(1, Math.sqrt(a)));
}

async function main() {
  const started = Date.now();
  const { tileset, options } = parseArgs(process.argv.slice(2));
  const summary = { ok: false, tiles: null, features: null, center: null, loadersgl: null,
                    picked: null, structure: null };
  if (!fs.existsSync(tileset)) {
    fail(`${tileset} does not exist`);
  } else {
    let t = Date.now();
    const seconds = () => {
      const s = (Date.now() - t) / 1000;
      t = Date.now();
      return Number(s.toFixed(1));
    };
    summary.timing = {};
    const { json, structure } = await checkStructure(tileset);
    summary.structure = structure;
    summary.timing.structure = seconds();
    if (json && json.root) {
      const server = await serveFiles({ mounts: { '/tileset/': path.dirname(tileset) } });
      try {
        summary.loadersgl = await checkLoadersGl(
          `${server.origin}/tileset/${encodeURIComponent(path.basename(tileset))}`, options.timeoutS);
      } finally {
        await server.close();
      }
      summary.timing.loadersgl = seconds();
      const cesium = await checkCesium(tileset, options);
      summary.timing.cesium = seconds();
      if (cesium) {
        summary.tiles = cesium.tiles ?? null;
        summary.features = cesium.features ?? null;
        summary.center = cesium.center ? [Number(cesium.center[0].toFixed(7)),
                                          Number(cesium.center[1].toFixed(7)),
                                          Number(cesium.center[2].toFixed(2))] : null;
        summary.picked = cesium.picked ?? null;
        summary.cesium = { tile_load_events: cesium.events?.load, root_radius_m: cesium.radius,
                           property_counts: cesium.properties, contents_in_region_checked: cesium.contentChecked,
                           frames: cesium.frames, seconds: cesium.seconds };
      }
    }
  }
  // A tileset with contents that neither viewer loads looked fine to every other check once: a
  // roof 2,000 km long widened its tile's region until the zoomed-out camera refined nothing.
  const contents = summary.structure?.contents ?? 0;
  if (contents > 0 && summary.loadersgl && summary.loadersgl.tiles === 0) {
    fail(`loaders.gl loaded none of the ${contents} tile contents`);
  }
  if (contents > 0 && summary.tiles === 0) fail(`Cesium loaded none of the ${contents} tile contents`);
  if (options.expectFeatures !== null && summary.features !== options.expectFeatures) {
    fail(`Cesium loaded ${summary.features} features, expected ${options.expectFeatures}`);
  }
  if (options.lonlat !== null) {
    if (!summary.center) fail('no root bounding sphere centre to compare with --lonlat');
    else {
      const d = greatCircleMetres(summary.center, options.lonlat);
      summary.lonlat_distance_m = Number(d.toFixed(2));
      if (d > options.toleranceM) {
        fail(`root bounding sphere centre [${summary.center.slice(0, 2).join(', ')}] is ${d.toFixed(1)} m ` +
             `from ${options.lonlat.join(',')} (tolerance ${options.toleranceM} m)`);
      }
    }
  }
  summary.ok = failures.length === 0;
  summary.failures = failures.length;
  summary.warnings = warnings.length;
  summary.seconds = Number(((Date.now() - started) / 1000).toFixed(1));
  console.log(JSON.stringify(summary));
  process.exit(failures.length === 0 ? 0 : 1);
}

main().catch((error) => {
  console.error(`check_tileset: ${error.stack || error}`);
  process.exit(1);
});
