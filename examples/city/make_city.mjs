// A generated city of N building footprints for `insula mass`, the benchmarks and the README
// (issue 17 item 7): a street grid of varying spacing and width (every fourth street an avenue,
// a diagonal avenue through the centre), blocks split into lots along their edges (perimeter
// blocks round a courtyard, detached houses at the edge, a few parks), one footprint per lot with
// a setback: rectangles, L, T, U, courtyard buildings (a polygon with a hole) downtown, chamfered
// and irregular ones on corners. Heights fall with the distance from the centre; roofs are flat
// downtown and pitched outside.
//
// Usage: node examples/city/make_city.mjs N OUT.geojson [--seed S] [--crs EPSG:32633]
//                                         [--origin X,Y] [--check | --no-check]
//
// Deterministic: the same N and seed give the same bytes on every machine (integer hashing and
// only + - * / sqrt on doubles: no Math.random, no Date, no trigonometry). The output is written
// in 1 MB chunks, so a million buildings need little memory. Blocks are filled in order of their
// distance from the centre until N footprints are written.
//
// Checks (by default for N <= 200000, --check forces them): every lot is disjoint from every other
// (a grid of 64 m cells), every footprint lies inside its lot minus the setback, every ring is
// simple, outer rings counter-clockwise and holes clockwise, area > 20 m2 and width > 3 m (twice
// the area over the perimeter). A failed check throws: the file is not to be trusted.
import { openSync, writeSync, closeSync } from "node:fs";

// ---- arguments ----------------------------------------------------------------------------------
const usage = "usage: node make_city.mjs N OUT.geojson [--seed S] [--crs EPSG:N] [--origin X,Y] " +
              "[--check | --no-check]";
const positional = [];
let seed = 1, crs = "EPSG:32633", origin = [455000, 5428000], check = null;
for (let k = 2; k < process.argv.length; k++) {
  const a = process.argv[k];
  if (a === "--seed") seed = Number(process.argv[++k]);
  else if (a === "--crs") crs = process.argv[++k];
  else if (a === "--origin") origin = String(process.argv[++k]).split(",").map(Number);
  else if (a === "--check") check = true;
  else if (a === "--no-check") check = false;
  else if (a === "-h" || a === "--help") { console.log(usage); process.exit(0); }
  else if (a.startsWith("--")) { console.error(`unknown option ${a}\n${usage}`); process.exit(2); }
  else positional.push(a);
}
const count = Number(positional[0]);
const outPath = positional[1];
const crsMatch = /^EPSG:(\d+)$/.exec(crs ?? "");
if (positional.length !== 2 || !Number.isInteger(count) || count < 1 || !Number.isInteger(seed) ||
    seed < 0 || seed > 0xffffffff || !crsMatch || origin.length !== 2 ||
    !origin.every(Number.isFinite)) {
  console.error(usage);
  process.exit(2);
}
if (check === null) check = count <= 200000;

// ---- deterministic randomness -------------------------------------------------------------------
function mix32(h) {  // murmur3 finalizer
  h ^= h >>> 16; h = Math.imul(h, 0x85ebca6b);
  h ^= h >>> 13; h = Math.imul(h, 0xc2b2ae35);
  return (h ^ (h >>> 16)) >>> 0;
}
function hash(...values) {
  let h = 0x9747b28c;
  for (const v of values) h = mix32((h ^ mix32((v | 0) + 0x632be5ab)) + 0x7f4a7c15 | 0);
  return h;
}
const hash01 = (...values) => hash(...values) / 4294967296;
function makeRandom(state) {  // splitmix32: one generator per block, so blocks are independent
  state >>>= 0;
  const next = () => {
    state = (state + 0x9e3779b9) >>> 0;
    let z = state;
    z = Math.imul(z ^ (z >>> 16), 0x21f0aaad);
    z = Math.imul(z ^ (z >>> 15), 0x735a2d97);
    return ((z ^ (z >>> 15)) >>> 0) / 4294967296;
  };
  next.between = (a, b) => a + (b - a) * next();
  next.int = (a, b) => a + Math.floor((b - a + 1) * next());  // a..b inclusive
  next.pick = (weighted) => {  // [[value, weight], ...]
    let total = 0;
    for (const [, w] of weighted) total += w;
    let r = next() * total;
    for (const [v, w] of weighted) if ((r -= w) < 0) return v;
    return weighted[weighted.length - 1][0];
  };
  return next;
}

// ---- the street grid ----------------------------------------------------------------------------
// Ground area per building (blocks and streets), measured on generated cities: it sets the
// radius the height and zone gradients are scaled to.
const areaPerBuilding = 900;
const radius = Math.max(150, Math.sqrt((count * areaPerBuilding) / Math.PI));

class Axis {  // street centre lines ..., pos(-1), pos(0) = 0, pos(1), ... along x or y
  constructor(id) { this.id = id; this.plus = [0]; this.minus = [0]; }
  spacing(i, at) {  // distance between street i and i + 1: 70-110 m downtown, up to 120-180 m
    const base = 90 + 60 * Math.min(1, Math.abs(at) / radius);
    return base * (0.78 + 0.44 * hash01(seed, this.id, i));
  }
  pos(i) {
    if (i >= 0) {
      while (this.plus.length <= i) {
        const j = this.plus.length - 1;
        this.plus.push(this.plus[j] + this.spacing(j, this.plus[j]));
      }
      return this.plus[i];
    }
    while (this.minus.length <= -i) {
      const j = -(this.minus.length - 1);
      this.minus.push(this.minus[-j] - this.spacing(j - 1, this.minus[-j]));
    }
    return this.minus[-i];
  }
  width(i) {  // street i: an avenue every fourth street, else 11-17 m
    return i % 4 === 0 ? 26 + 4 * hash01(seed, this.id, i, 7) : 11 + 6 * hash01(seed, this.id, i, 9);
  }
  block(i) { return [this.pos(i) + this.width(i) / 2, this.pos(i + 1) - this.width(i + 1) / 2]; }
}
const xs = new Axis(1), ys = new Axis(2);

// The diagonal avenue through the centre, direction (2, 1): lots it touches are left empty.
const diagonal = { dx: 2 / Math.sqrt(5), dy: 1 / Math.sqrt(5), half: 16 };
function onDiagonal(x0, y0, x1, y1) {
  let lo = Infinity, hi = -Infinity;
  for (const [x, y] of [[x0, y0], [x1, y0], [x1, y1], [x0, y1]]) {
    const d = -diagonal.dy * x + diagonal.dx * y;
    lo = Math.min(lo, d); hi = Math.max(hi, d);
  }
  return lo < diagonal.half && hi > -diagonal.half;
}

// Blocks in order of their centre's distance from (0, 0): all blocks of the square [-m, m) that
// are nearer than its edge, then the next ring of a square twice as large, and so on.
function* blocks() {
  let done = -1;
  for (let m = 4; ; m *= 2) {
    const limit = Math.min(-xs.pos(-m), xs.pos(m), -ys.pos(-m), ys.pos(m));
    const cells = [];
    for (let j = -m; j < m; j++) {
      for (let i = -m; i < m; i++) {
        const cx = (xs.pos(i) + xs.pos(i + 1)) / 2, cy = (ys.pos(j) + ys.pos(j + 1)) / 2;
        const d = Math.sqrt(cx * cx + cy * cy);
        if (d > done && d <= limit) cells.push([d, i, j]);
      }
    }
    cells.sort((a, b) => a[0] - b[0] || a[2] - b[2] || a[1] - b[1]);
    for (const c of cells) yield c;
    done = limit;
  }
}

// ---- lots ---------------------------------------------------------------------------------------
// A lot is an axis-aligned rectangle with a frame: u along its street front, v into the block,
// origin at a front corner ("S", "N", "W", "E": the side its street is on). For a corner lot the
// origin is the street corner. Frames are rotations, so counter-clockwise stays counter-clockwise.
function frameOf(lot) {
  const { x0, y0, x1, y1, front } = lot;
  switch (front) {
    case "S": return { w: x1 - x0, d: y1 - y0, map: (u, v) => [x0 + u, y0 + v] };
    case "N": return { w: x1 - x0, d: y1 - y0, map: (u, v) => [x1 - u, y1 - v] };
    case "W": return { w: y1 - y0, d: x1 - x0, map: (u, v) => [x0 + v, y1 - u] };
    default: return { w: y1 - y0, d: x1 - x0, map: (u, v) => [x1 - v, y0 + u] };  // "E"
  }
}

// Splits length L into pieces of about `target` (each at least `min`).
function split(random, L, target, min) {
  let k = Math.max(1, Math.round(L / target));
  while (k > 1 && L / k < min * 1.25) k--;
  const raw = [];
  let sum = 0;
  for (let i = 0; i < k; i++) { const w = 0.75 + 0.5 * random(); raw.push(w); sum += w; }
  return raw.map((w) => (w / sum) * L);
}

// The lots of a perimeter block [x0,x1]x[y0,y1] of depth D: four corner lots, then the lots along
// each edge; the rest is the courtyard.
function perimeterLots(random, x0, y0, x1, y1, D, target, min) {
  const W = x1 - x0, H = y1 - y0;
  D = Math.min(D, W / 2, H / 2);
  const cw = W - 2 * D < min ? W / 2 : D, ch = H - 2 * D < min ? H / 2 : D;
  const lots = [
    { x0, y0, x1: x0 + cw, y1: y0 + ch, front: "S", corner: true },
    { x0: x1 - cw, y0, x1, y1: y0 + ch, front: "E", corner: true },
    { x0: x1 - cw, y0: y1 - ch, x1, y1, front: "N", corner: true },
    { x0, y0: y1 - ch, x1: x0 + cw, y1, front: "W", corner: true },
  ];
  if (cw === D) {  // south and north edges
    let x = x0 + D;
    for (const w of split(random, W - 2 * D, target, min)) {
      lots.push({ x0: x, y0, x1: x + w, y1: y0 + D, front: "S" });
      x += w;
    }
    x = x1 - D;
    for (const w of split(random, W - 2 * D, target, min)) {
      lots.push({ x0: x - w, y0: y1 - D, x1: x, y1, front: "N" });
      x -= w;
    }
  }
  if (ch === D) {  // east and west edges
    let y = y0 + D;
    for (const w of split(random, H - 2 * D, target, min)) {
      lots.push({ x0: x1 - D, y0: y, x1, y1: y + w, front: "E" });
      y += w;
    }
    y = y1 - D;
    for (const w of split(random, H - 2 * D, target, min)) {
      lots.push({ x0, y0: y - w, x1: x0 + D, y1: y, front: "W" });
      y -= w;
    }
  }
  // Corners first, then the south, north, east and west edges.
  return lots;
}

// ---- footprint shapes, in the lot frame on [0,a]x[0,b], counter-clockwise -----------------------
const shapes = {
  rect: (a, b) => [[0, 0], [a, 0], [a, b], [0, b]],
  L: (random, a, b) => {
    const c = Math.max(5, random.between(0.4, 0.6) * b), p = Math.max(5, random.between(0.35, 0.6) * a);
    return random() < 0.5 ? [[0, 0], [a, 0], [a, c], [p, c], [p, b], [0, b]]
                          : [[0, 0], [a, 0], [a, b], [a - p, b], [a - p, c], [0, c]];
  },
  T: (random, a, b) => {
    const c = Math.max(5, random.between(0.4, 0.55) * b);
    const s = Math.max(5, random.between(0.3, 0.45) * a), p0 = (a - s) / 2, p1 = p0 + s;
    return [[0, 0], [a, 0], [a, c], [p1, c], [p1, b], [p0, b], [p0, c], [0, c]];
  },
  U: (random, a, b) => {
    const c = Math.max(5, random.between(0.35, 0.5) * b);
    const m = Math.max(5, Math.min(random.between(0.22, 0.32) * a, (a - 5) / 2));
    return [[0, 0], [a, 0], [a, b], [a - m, b], [a - m, c], [m, c], [m, b], [0, b]];
  },
  // A corner building wrapping the street corner at (0, 0): chamfered, with slanted inner sides.
  corner: (random, a, b) => {
    const e = random.between(0.45, 0.65) * Math.min(a, b), c = random.between(0.2, 0.45) * e;
    const e1 = Math.min(b, e * random.between(0.8, 1.2)), e2 = Math.min(a, e * random.between(0.8, 1.2));
    if (a - e < 5 || b - e < 5 || e < 7) return [[c, 0], [a, 0], [a, b], [0, b], [0, c]];
    return [[c, 0], [a, 0], [a, e1], [e, e], [e2, b], [0, b], [0, c]];
  },
  // An irregular detached house: a rectangle with one corner cut and one side stepped.
  irregular: (random, a, b) => {
    const c = random.between(0.25, 0.4) * Math.min(a, b), s = random.between(0.2, 0.35) * b;
    const t = random.between(0.3, 0.5) * a;
    return [[c, 0], [a, 0], [a, b - s], [a - t, b - s], [a - t, b], [0, b], [0, c]];
  },
};

// ---- checks ---------------------------------------------------------------------------------
function signedArea(ring) {
  let s = 0;
  for (let i = 0; i < ring.length; i++) {
    const [x0, y0] = ring[i], [x1, y1] = ring[(i + 1) % ring.length];
    s += x0 * y1 - x1 * y0;
  }
  return s / 2;
}
function perimeter(ring) {
  let s = 0;
  for (let i = 0; i < ring.length; i++) {
    const [x0, y0] = ring[i], [x1, y1] = ring[(i + 1) % ring.length];
    s += Math.hypot(x1 - x0, y1 - y0);
  }
  return s;
}
function segmentsCross(p, q, r, s) {  // proper or touching intersection of pq and rs
  const o = (a, b, c) => Math.sign((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
  const on = (a, b, c) => Math.min(a[0], b[0]) - 1e-9 <= c[0] && c[0] <= Math.max(a[0], b[0]) + 1e-9 &&
                          Math.min(a[1], b[1]) - 1e-9 <= c[1] && c[1] <= Math.max(a[1], b[1]) + 1e-9;
  const d1 = o(r, s, p), d2 = o(r, s, q), d3 = o(p, q, r), d4 = o(p, q, s);
  if (d1 * d2 < 0 && d3 * d4 < 0) return true;
  return (d1 === 0 && on(r, s, p)) || (d2 === 0 && on(r, s, q)) || (d3 === 0 && on(p, q, r)) ||
         (d4 === 0 && on(p, q, s));
}
function checkRings(id, rings) {
  const edges = [];
  rings.forEach((ring, k) => {
    const area = signedArea(ring);
    if (k === 0 && !(area > 20)) throw new Error(`${id}: outer ring area ${area} (not > 20 m2, or clockwise)`);
    if (k > 0 && !(area < 0)) throw new Error(`${id}: hole ${k} is not clockwise`);
    if (k === 0 && !((2 * area) / perimeter(ring) > 3)) throw new Error(`${id}: narrower than 3 m`);
    for (let i = 0; i < ring.length; i++) edges.push([k, i, ring[i], ring[(i + 1) % ring.length], ring.length]);
  });
  for (let e = 0; e < edges.length; e++) {
    for (let f = e + 1; f < edges.length; f++) {
      const [k, i, p, q, n] = edges[e], [l, j, r, s] = edges[f];
      if (k === l && (j === i + 1 || (i === 0 && j === n - 1))) continue;  // neighbours share a vertex
      if (segmentsCross(p, q, r, s)) throw new Error(`${id}: ring ${k} edge ${i} meets ring ${l} edge ${j}`);
    }
  }
  for (const [x, y] of rings.slice(1).flat()) {  // holes inside the outer ring (point in polygon)
    let inside = false;
    const ring = rings[0];
    for (let i = 0, j = ring.length - 1; i < ring.length; j = i++) {
      const [xi, yi] = ring[i], [xj, yj] = ring[j];
      if ((yi > y) !== (yj > y) && x < ((xj - xi) * (y - yi)) / (yj - yi) + xi) inside = !inside;
    }
    if (!inside) throw new Error(`${id}: hole vertex outside the outer ring`);
  }
}
const lotGrid = new Map();
function checkLot(lot) {
  const cell = 64, e = 1e-6;
  const keys = [];
  for (let gx = Math.floor(lot.x0 / cell); gx <= Math.floor(lot.x1 / cell); gx++) {
    for (let gy = Math.floor(lot.y0 / cell); gy <= Math.floor(lot.y1 / cell); gy++) keys.push(gx * 1e6 + gy);
  }
  for (const key of keys) {
    for (const o of lotGrid.get(key) ?? []) {
      if (Math.min(lot.x1, o.x1) - Math.max(lot.x0, o.x0) > e && Math.min(lot.y1, o.y1) - Math.max(lot.y0, o.y0) > e) {
        throw new Error(`lots overlap: ${JSON.stringify(lot)} and ${JSON.stringify(o)}`);
      }
    }
  }
  const box = { x0: lot.x0, y0: lot.y0, x1: lot.x1, y1: lot.y1 };
  for (const key of keys) {
    const list = lotGrid.get(key);
    if (list) list.push(box); else lotGrid.set(key, [box]);
  }
}
// In the lot frame: inside the lot, at least 0.3 m from its sides and back (the front is a street).
function checkInside(id, lot, frameRings) {
  const { w, d } = frameOf(lot);
  for (const [u, v] of frameRings.flat()) {
    if (!(u >= 0.3 - 1e-9 && u <= w - 0.3 + 1e-9 && v >= -1e-9 && v <= d - 0.3 + 1e-9)) {
      throw new Error(`${id}: vertex (${u}, ${v}) outside its ${w} x ${d} m lot ${JSON.stringify(lot)}`);
    }
  }
}

// ---- buildings ----------------------------------------------------------------------------------
const pitchedAny = [["hip", 5], ["mansard", 1]];
function roofFor(random, zone, simple, holed) {
  if (holed) return random() < 0.7 ? "flat" : "holed_mansard";
  if (zone === 0) return random.pick([["flat", 85], ["mansard", 10], ["hip", 5]]);
  if (zone === 1) {
    return simple ? random.pick([["flat", 30], ["mansard", 15], ["hip", 20], ["gable", 20], ["gambrel", 5],
                                 ["half_hipped", 10]])
                  : random.pick([["flat", 45], ["mansard", 15], ["hip", 40]]);
  }
  return simple ? random.pick([["gable", 35], ["hip", 25], ["half_hipped", 12], ["saltbox", 8],
                               ["gambrel", 8], ["pyramid", 4], ["shed", 8]])
                : random.pick(pitchedAny);
}

// The footprint of one lot: [rings in lot frame (u, v)], with roof, levels and use, or null.
function building(random, lot, zone, levelsBase, blockFactor) {
  const { w, d } = frameOf(lot);
  let rings, kind;
  if (zone === 2) {  // detached house: set back 3-7 m from the street, 2-3 m from the sides
    const sf = random.between(3, 7), ss = random.between(2, 3.5);
    const a = Math.min(w - 2 * ss, random.between(8, 15)), b = Math.min(d - sf - 2, random.between(8, 13));
    if (a < 7 || b < 7) return null;
    const u0 = ss + random() * (w - 2 * ss - a);
    kind = lot.corner && a >= 10 && b >= 10 ? "irregular"
         : random.pick([["rect", 55], ["L", a >= 11 && b >= 10 ? 25 : 0], ["T", a >= 13 && b >= 11 ? 10 : 0],
                        ["irregular", a >= 10 && b >= 10 ? 10 : 0]]);
    let ring = (kind === "rect" ? shapes.rect(a, b) : shapes[kind](random, a, b)).map(([u, v]) => [u0 + u, sf + v]);
    const k = random.int(-2, 2);  // a small turn in its lot, when it still fits
    if (k !== 0) {
      const n = Math.sqrt(1 + (k / 12) * (k / 12)), c = 1 / n, s = k / 12 / n;
      const cu = u0 + a / 2, cv = sf + b / 2;
      const turned = ring.map(([u, v]) => [cu + c * (u - cu) - s * (v - cv), cv + s * (u - cu) + c * (v - cv)]);
      if (turned.every(([u, v]) => u >= 1.5 && u <= w - 1.5 && v >= 1.5 && v <= d - 1.5)) ring = turned;
    }
    rings = [ring];
  } else {  // row and perimeter buildings: 0.4-0.6 m from the sides, 0-1.5 m from the street
    const ss = random.between(0.4, 0.6), sf = random() < 0.6 ? 0 : random.between(0.5, 1.5);
    const a = w - 2 * ss, b = Math.min(d - sf - 0.5, Math.max(7, (d - sf) * random.between(0.7, 1)));
    if (a < 6 || b < 6) return null;
    if (lot.courtyard && a >= 30 && b >= 30) {
      kind = "courtyard";
      const m = Math.min(random.between(9, 14), (a - 8) / 2, (b - 8) / 2);
      rings = [shapes.rect(a, b), [[m, m], [m, b - m], [a - m, b - m], [a - m, m]]];
    } else if (lot.corner) {
      kind = "corner";
      rings = [shapes.corner(random, a, b)];
    } else {
      kind = random.pick([["rect", 60], ["L", a >= 12 && b >= 12 ? 15 : 0], ["T", a >= 14 && b >= 12 ? 12 : 0],
                          ["U", a >= 16 && b >= 12 ? 13 : 0]]);
      rings = [kind === "rect" ? shapes.rect(a, b) : shapes[kind](random, a, b)];
    }
    rings = rings.map((ring) => ring.map(([u, v]) => [ss + u, sf + v]));
  }
  let levels = Math.max(1, Math.round(levelsBase * blockFactor * random.between(0.8, 1.2)));
  if (zone === 2) levels = Math.min(levels, random() < 0.3 ? 1 : 2);
  if (zone === 0 && kind === "rect" && random() < 0.1) levels = Math.round(levels * random.between(1.8, 2.6));
  const use = zone === 0 ? random.pick([["commercial", 35], ["office", 30], ["retail", 10], ["mixed", 25]])
            : zone === 1 ? random.pick([["residential", 60], ["mixed", 25], ["commercial", 10], ["public", 5]])
            : "residential";
  const storey = use === "residential" ? random.between(2.8, 3.1) : random.between(3.2, 3.8);
  const height = levels * storey + (use === "commercial" || use === "retail" ? 1.5 : 0);
  const simple = kind === "rect";
  let roof = roofFor(random, zone, simple, kind === "courtyard");
  if (levels >= 12 && roof !== "flat") roof = "flat";  // towers
  return { rings, kind, roof, levels, height, use,
           pitch: roof === "flat" ? null : zone === 2 ? random.int(25, 45) : random.int(20, 35) };
}

// ---- output -------------------------------------------------------------------------------------
const fd = openSync(outPath, "w");
let chunk = [], chunkBytes = 0, bytes = 0;
function write(text) {
  chunk.push(text);
  chunkBytes += text.length;
  if (chunkBytes > 1 << 20) flush();
}
function flush() {
  const data = chunk.join("");
  writeSync(fd, data);
  bytes += Buffer.byteLength(data);
  chunk = []; chunkBytes = 0;
}
const [ox, oy] = origin;
const fmt = (v) => {  // metres to mm, no "-0.000", no trailing zeros
  const s = (Math.round(v * 1000) / 1000).toFixed(3).replace(/\.?0+$/, "");
  return s === "-0" ? "0" : s;
};
write(`{"type":"FeatureCollection","name":"insula-city","crs":{"type":"name","properties":` +
      `{"name":"urn:ogc:def:crs:EPSG::${crsMatch[1]}"}},"features":[\n`);

let written = 0, blockCount = 0, parks = 0, maxDistance = 0;
const kinds = {}, roofs = {};
for (const [dist, i, j] of blocks()) {
  if (written >= count) break;
  const random = makeRandom(hash(seed, i, j, 0x51ab));
  const [x0, x1] = xs.block(i), [y0, y1] = ys.block(j);
  const t = dist / radius + (random() - 0.5) * 0.15;  // zones with ragged borders
  const zone = t < 0.3 ? 0 : t < 0.65 ? 1 : 2;
  if (random() < (zone === 2 ? 0.03 : 0.05) && (i !== 0 || j !== 0)) { parks++; continue; }
  blockCount++;
  let lots;
  if (zone === 0 && random() < 0.3) {  // courtyard buildings: the block in 1-2 x 1-2 parts
    const nx = x1 - x0 > 90 ? 2 : 1, ny = y1 - y0 > 90 ? 2 : 1;
    lots = [];
    for (let b = 0; b < ny; b++) {
      for (let a = 0; a < nx; a++) {
        const lx0 = x0 + ((x1 - x0) * a) / nx, lx1 = x0 + ((x1 - x0) * (a + 1)) / nx;
        const ly0 = y0 + ((y1 - y0) * b) / ny, ly1 = y0 + ((y1 - y0) * (b + 1)) / ny;
        lots.push({ x0: lx0, y0: ly0, x1: lx1, y1: ly1, front: b === 0 ? "S" : "N", courtyard: true });
      }
    }
  } else if (zone === 0) {
    lots = perimeterLots(random, x0, y0, x1, y1, random.between(14, 20), random.between(12, 22), 8);
  } else if (zone === 1) {
    lots = perimeterLots(random, x0, y0, x1, y1, random.between(12, 18), random.between(9, 16), 7);
  } else {
    lots = perimeterLots(random, x0, y0, x1, y1, random.between(24, 34), random.between(15, 24), 13);
  }
  const levelsBase = zone === 2 ? 2 : 2 + 14 / (1 + (dist / (0.3 * radius)) ** 2);
  const blockFactor = random.between(0.7, 1.3);
  for (const lot of lots) {
    if (written >= count) break;
    if (onDiagonal(lot.x0, lot.y0, lot.x1, lot.y1)) continue;
    if (random() < 0.03) continue;  // a vacant lot
    const b = building(random, lot, zone, levelsBase, blockFactor);
    if (!b) continue;
    const { map } = frameOf(lot);
    const rings = b.rings.map((ring) => ring.map(([u, v]) => map(u, v)));
    const id = `b${written}`;
    if (check) {
      checkLot(lot);
      checkInside(id, lot, b.rings);
      checkRings(id, rings.map((ring) => ring.map(([x, y]) => [Math.round(x * 1000) / 1000, Math.round(y * 1000) / 1000])));
    }
    const coordinates = rings.map((ring) =>
      "[" + [...ring, ring[0]].map(([x, y]) => `[${fmt(ox + x)},${fmt(oy + y)}]`).join(",") + "]").join(",");
    const pitch = b.pitch === null ? "" : `,"pitch":${b.pitch}`;
    write(`${written ? ",\n" : ""}{"type":"Feature","id":"${id}","properties":{"id":"${id}",` +
          `"height":${fmt(Math.round(b.height * 10) / 10)},"building:levels":${b.levels},"roof":"${b.roof}"${pitch},` +
          `"use":"${b.use}","shape":"${b.kind}"},"geometry":{"type":"Polygon","coordinates":[${coordinates}]}}`);
    written++;
    kinds[b.kind] = (kinds[b.kind] ?? 0) + 1;
    roofs[b.roof] = (roofs[b.roof] ?? 0) + 1;
    maxDistance = Math.max(maxDistance, dist);
  }
}
write("\n]}\n");
flush();
closeSync(fd);
console.error(`${outPath}: ${written} buildings in ${blockCount} blocks (${parks} parks), ` +
              `city radius ${Math.round(maxDistance)} m (gradient radius ${Math.round(radius)} m), ` +
              `${(bytes / 1e6).toFixed(1)} MB${check ? ", checked" : ""}`);
console.error(`  shapes ${JSON.stringify(kinds)}\n  roofs ${JSON.stringify(roofs)}`);
