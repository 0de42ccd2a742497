// Writes N generated building footprints (rectangles, L, T, U and irregular concave shapes, 4 to 12
// vertices) on a grid in UTM coordinates, for the mass-job benchmark.
// Usage: node bench/make_footprints.mjs N OUT.geojson [SEED]
import { writeFileSync } from "node:fs";

const count = Number(process.argv[2] ?? 10000);
const out = process.argv[3] ?? "footprints.geojson";
let state = BigInt(process.argv[4] ?? 1);
function random() {  // splitmix64, so the file is the same on every machine
  state = (state + 0x9e3779b97f4a7c15n) & 0xffffffffffffffffn;
  let z = state;
  z = ((z ^ (z >> 30n)) * 0xbf58476d1ce4e5b9n) & 0xffffffffffffffffn;
  z = ((z ^ (z >> 27n)) * 0x94d049bb133111ebn) & 0xffffffffffffffffn;
  return Number((z ^ (z >> 31n)) >> 11n) / 2 ** 53;
}
const between = (a, b) => a + (b - a) * random();

const shapes = [
  (w, d) => [[0, 0], [w, 0], [w, d], [0, d]],
  (w, d) => [[0, 0], [w, 0], [w, d * 0.45], [w * 0.4, d * 0.45], [w * 0.4, d], [0, d]],
  (w, d) => [[w * 0.35, 0], [w * 0.65, 0], [w * 0.65, d * 0.6], [w, d * 0.6], [w, d], [0, d], [0, d * 0.6],
             [w * 0.35, d * 0.6]],
  (w, d) => [[0, 0], [w, 0], [w, d], [w * 0.7, d], [w * 0.7, d * 0.4], [w * 0.3, d * 0.4], [w * 0.3, d], [0, d]],
  (w, d) => {
    const n = 5 + Math.floor(random() * 8), pts = [];
    for (let i = 0; i < n; i++) {
      const a = (2 * Math.PI * i) / n, r = between(0.55, 1.0);
      pts.push([w / 2 + (w / 2) * r * Math.cos(a), d / 2 + (d / 2) * r * Math.sin(a)]);
    }
    return pts;
  },
];

const side = Math.ceil(Math.sqrt(count));
const features = [];
for (let i = 0; i < count; i++) {
  const w = between(8, 24), d = between(8, 20);
  const x0 = 455000 + (i % side) * 30, y0 = 5428000 + Math.floor(i / side) * 30;
  const ring = shapes[i % shapes.length](w, d).map(([x, y]) => [+(x0 + x).toFixed(3), +(y0 + y).toFixed(3)]);
  ring.push(ring[0]);
  features.push({ type: "Feature", id: `b${i}`,
                  properties: { height: +between(5, 20).toFixed(1) },
                  geometry: { type: "Polygon", coordinates: [ring] } });
}
writeFileSync(out, JSON.stringify({ type: "FeatureCollection", features }));
