#!/usr/bin/env bash
# A .bldg village plans and builds every lot at an origin of its own (apps/cli/bldg_village.cc,
# lot_origin), so a lot's building does not depend on where the file's origin falls, which moves
# with the other lots. Four rotated rectangles, each alone in its file, against all four moved
# 600 km west in one file with two far-away lots that put the file's origin about a kilometre from
# them: the same outcome (built or skipped "no stair fits"), counts, doors and stairs, the same
# room areas (1e-6 relative), and the same geometry, every vertex moved by the translation (within
# the OBJ's micrometre) and every building's volume the same (1e-6 relative). Planned in the
# file's frame, lots a and b were skipped alone and built in the shared file, and the areas of c
# and d differed.
source "$(dirname "$0")/lib/common.sh"
grammar=$root/examples/bldg/two_storey.bldg

# id and outer ring (meters, no CRS: an unknown metric one), all far enough from (0, 0) that each
# file is read at an origin of its own (its bounding box's centre, rounded down).
lots='{
  "a": [[640384.744, 5780213.144], [640385.336, 5780219.319], [640377.664, 5780220.055], [640377.072, 5780213.88]],
  "b": [[640997.733, 5780669.413], [641003.717, 5780675.592], [640999.634, 5780679.546], [640993.65, 5780673.367]],
  "c": [[640078.507, 5780830.043], [640092.101, 5780831.254], [640091.237, 5780840.955], [640077.643, 5780839.744]],
  "d": [[640602.626, 5780600.341], [640613.148, 5780605.873], [640609.263, 5780613.262], [640598.741, 5780607.731]]}'
node -e '
  const fs = require("fs");
  const [dir, text] = process.argv.slice(1);
  const lots = JSON.parse(text);
  const feature = (id, ring) => ({type: "Feature", id, properties: {},
    geometry: {type: "Polygon", coordinates: [[...ring, ring[0]]]}});
  const file = (features) => JSON.stringify({type: "FeatureCollection", features});
  const moved = (ring) => ring.map(([x, y]) => [x - 600000, y]);
  const square = (x, y) => [[x, y], [x + 10, y], [x + 10, y + 10], [x, y + 10]];
  for (const [id, ring] of Object.entries(lots)) fs.writeFileSync(`${dir}/${id}.geojson`, file([feature(id, ring)]));
  const all = Object.entries(lots).map(([id, ring]) => feature(id, moved(ring)));
  all.push(feature("far_sw", square(38000, 5778000)), feature("far_ne", square(43000, 5783000)));
  fs.writeFileSync(`${dir}/moved.geojson`, file(all));' "$tmp" "$lots"

for id in a b c d moved; do
  expect_exit 0 "build $id" "$insula" build "$grammar" --lot "$tmp/$id.geojson" --keep-going -q \
    -o "$tmp/$id.obj" --report "$tmp/$id.json"
done
node -e '
  const fs = require("fs");
  const [dir] = process.argv.slice(1);
  // Per OBJ object: its vertices in the CRS frame (the OBJ is Y-up: x, z, -y) and its volume
  // about its first vertex (so a translation leaves it alone).
  function objects(name) {
    const origin = JSON.parse(fs.readFileSync(`${dir}/${name}.origin.json`)).origin;
    const text = fs.readFileSync(`${dir}/${name}.obj`, "utf8");
    const all = [];
    const out = {};
    let current = null;
    for (const line of text.split("\n")) {
      const f = line.split(" ");
      if (f[0] === "o") out[f[1]] = current = {world: [], volume: 0, ref: null};
      if (f[0] === "v") {
        const p = f.slice(1, 4).map(Number);
        all.push(p);
        current.world.push([p[0] + origin[0], -p[2] + origin[1], p[1] + origin[2]]);
        if (current.ref === null) current.ref = p;
      }
      if (f[0] === "f") {
        const q = f.slice(1).map((s) => all[parseInt(s, 10) - 1].map((c, k) => c - current.ref[k]));
        for (let k = 1; k + 1 < q.length; ++k) {
          const [a, b, c] = [q[0], q[k], q[k + 1]];
          current.volume += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                             a[2] * (b[0] * c[1] - b[1] * c[0])) / 6;
        }
      }
    }
    return out;
  }
  const outcome = (report, id) => {
    const built = report.buildings.find((b) => b.id === id);
    if (built) return {built: true, b: built};
    const skipped = report.skipped_lots.find((s) => s.id === id);
    return {built: false, reason: skipped ? skipped.reason : "missing"};
  };
  const close = (x, y, rel) => Math.abs(x - y) <= rel * Math.max(1, Math.abs(x), Math.abs(y));
  const moved = JSON.parse(fs.readFileSync(`${dir}/moved.json`));
  const movedObjects = objects("moved");
  let problems = [];
  let built = 0;
  for (const id of ["a", "b", "c", "d"]) {
    const alone = outcome(JSON.parse(fs.readFileSync(`${dir}/${id}.json`)), id);
    const there = outcome(moved, id);
    if (alone.built !== there.built) {
      problems.push(`${id}: alone ${alone.built ? "built" : "skipped: " + alone.reason}, ` +
                    `moved ${there.built ? "built" : "skipped: " + there.reason}`);
      continue;
    }
    if (!alone.built) continue;
    ++built;
    const [p, q] = [alone.b, there.b];
    if (JSON.stringify(p.counts) !== JSON.stringify(q.counts)) problems.push(`${id}: counts`);
    for (const k of ["doors", "entrances", "windows", "stairs"])
      if (p[k].length !== q[k].length) problems.push(`${id}: ${k}`);
    if (p.rooms.length !== q.rooms.length) problems.push(`${id}: rooms`);
    p.rooms.forEach((r, i) => {
      const s = q.rooms[i] || {};
      if (r.name !== s.name || !close(r.area, s.area, 1e-6) || !close(r.floor_area, s.floor_area, 1e-6))
        problems.push(`${id}: room ${r.name} ${r.area} / ${s.name} ${s.area}`);
    });
    const [u, v] = [objects(id)[id], movedObjects[id]];
    if (!u || !v || u.world.length !== v.world.length) {
      problems.push(`${id}: vertex count`);
      continue;
    }
    const far = u.world.findIndex((w, i) => Math.abs(w[0] - 600000 - v.world[i][0]) > 2e-6 ||
      Math.abs(w[1] - v.world[i][1]) > 2e-6 || Math.abs(w[2] - v.world[i][2]) > 2e-6);
    if (far >= 0) problems.push(`${id}: vertex ${far} not moved by the translation`);
    if (!(u.volume > 0) || !close(u.volume, v.volume, 1e-6)) problems.push(`${id}: volume ${u.volume} / ${v.volume}`);
  }
  if (built < 2) problems.push(`only ${built} lots built`);
  if (problems.length) { console.log(problems.join("\n")); process.exit(1); }' "$tmp" ||
  fail "a lot alone and moved 600 km among far-away lots: the same building"

finish bldg_lot_origin
