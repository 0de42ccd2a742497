// The drawing tool's model (web/src/draw_model.js) without a browser: trees the tool can make
// (parts split into sub-parts and back, rooms split into containers, holes, a disposable part)
// are written as `.bldg` text that the command line builds with the rooms drawn; symbols stay put
// across edits; removing a room takes its doors with it.
// Usage: node draw_model.mjs INSULA TMPDIR
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';

import {
  findRoom, grammar, leafParts, newBuilding, newFloor, newPart, newRoom, remove, split,
} from '../../web/src/draw_model.js';
import { fitView, outlineProblem } from '../../web/src/draw.js';

const [insula, tmp] = process.argv.slice(2);
const failures = [];
const check = (ok, what) => { if (!ok) failures.push(what); };

// Builds `text` from the command line; returns its report.
function build(name, text) {
  const file = path.join(tmp, `${name}.bldg`);
  fs.writeFileSync(file, text);
  const report = path.join(tmp, `${name}.json`);
  const run = spawnSync(insula, ['build', file, '--report', report, '-o', path.join(tmp, `${name}.glb`), '-q'],
                        { encoding: 'utf8' });
  if (run.status !== 0) {
    failures.push(`${name} does not build: ${run.stderr}\n${text}`);
    return null;
  }
  return JSON.parse(fs.readFileSync(report, 'utf8'));
}

// A 16 x 12 m house: one part, one storey, a hall and two rooms.
const house = newBuilding();
house.name = 'Tree house';
house.outline = [[0, 0], [16, 0], [16, 12], [0, 12]];
const floor = house.root.children[0].floors[0];
floor.children.push(newRoom('kitchen'), newRoom('bedroom'));
let text = grammar(house);
check(text.includes('building -> building("Tree house", [(0, 0), (16, 0), (16, 12), (0, 12)], vertical)'),
      `the axiom: ${text.split('\n')[1]}`);
let report = build('house', text);
check(report && report.rooms.length === 3, 'three rooms');
check(report && report.doors.length >= 2, 'automatic doors');
const kitchen = floor.children[1].symbol;

// The kitchen split: a divisions container across the storey's row holding it and a new room.
split(floor, floor.children[1], newRoom('storage'));
text = grammar(house);
const container = floor.children[1];
check(container.kind === 'divisions' && container.orientation === 'vertical',
      `a split room's container lies across its row: ${container.kind} ${container.orientation}`);
check(text.includes(`${container.symbol} -> divisions(vertical) : {${kitchen}, storage}`),
      `the container's rule: ${text}`);
report = build('split_room', text);
check(report && report.rooms.length === 4, `four rooms after the split: ${report && report.rooms.length}`);
check(findRoom(house, kitchen)?.parent === container, 'the kitchen keeps its symbol inside the container');

// The storage room split again: a container inside the container (divisions inside divisions).
split(container, container.children[1], newRoom('bath'));
report = build('deep_rooms', grammar(house));
check(report && report.rooms.length === 5, `five rooms two containers deep: ${report && report.rooms.length}`);

// The part split: the building's row is vertical, so its sub-parts lie side by side horizontally;
// the new part split again comes back vertical.
const first = house.root.children[0];
split(house.root, first, newPart(3));
const parts = house.root.children[0];
check(parts.kind === 'parts' && parts.orientation === 'horizontal', 'a split part becomes a horizontal container');
split(parts, parts.children[1], newPart(3));
check(parts.children[1].kind === 'parts' && parts.children[1].orientation === 'vertical',
      'the sub-part splits back into a vertical container');
text = grammar(house);
report = build('deep_parts', text);
check(report && report.rooms.length === 7, `rooms of three parts: ${report && report.rooms.length}`);
check(leafParts(house.root).length === 3, 'three building parts');
check(/buildingparts\(horizontal\) : \{part, parts\d*\}/.test(text), `nested parts in the grammar: ${text}`);

// A courtyard: a hole in the outline.
house.holes = [[[6, 4], [10, 4], [10, 8], [6, 8]]];
text = grammar(house);
check(text.includes('[(6, 4), (10, 4), (10, 8), (6, 8)], vertical)'), 'the hole in the axiom');
report = build('courtyard', text);
check(report !== null, 'the building with a courtyard builds');

// A disposable part (roof height 0): its rooms go, nothing leads into it.
const last = leafParts(house.root)[2];
last.roofHeight = 0;
text = grammar(house);
check(!text.split('\n').some((l) => / -> (door|stair)\(/.test(l) && l.includes(last.floors[0].children[0].symbol)),
      'a door leads into the disposable part');
report = build('disposable', text);
check(report && report.rooms.length === 6, `the disposable part's room is gone: ${report && report.rooms.length}`);

// Removing a room takes the door the user connected to it.
house.transitions.push({ symbol: null, kind: 'door', from: kitchen, to: 'bath', width: 0 });
text = grammar(house);
check(text.includes(`-> door(${kitchen}, bath)`), 'the connected door');
remove(container.children[1], container.children[1].children[1]);
text = grammar(house);
check(!text.includes(`door(${kitchen}, bath)`), 'a door into a removed room stays');
check(house.transitions.length === 0, 'the removed room\'s transition is forgotten');
check(build('removed', text) !== null, 'the building without the room builds');
const lone = newBuilding().root.children[0].floors[0];
check(!remove(lone, lone.children[0]) && lone.children.length === 1, 'a storey\'s last room removed');

// Names, room types and footprint files are written as the grammar's strings, whatever they hold.
const odd = newBuilding();
odd.name = 'Lot "7" \\ north\nwing';
odd.outline = [[0, 0], [10, 0], [10, 8], [0, 8]];
odd.root.children[0].floors[0].children[0].type = 'dining room';
text = grammar(odd);
check(text.includes('building("Lot \\"7\\" \\\\ north\\nwing"') && text.includes('room("dining room", medium)'),
      `names and types as strings: ${text}`);
check(build('odd_names', text) !== null, 'a building with odd names builds');
odd.footprint = { file: 'my "lots".geojson', feature: 'lot \\ 7' };
check(grammar(odd).includes('geojson("my \\"lots\\".geojson", "lot \\\\ 7")'), 'the footprint file and feature escaped');

// Transitions that no longer fit are dropped: a door whose room moved to another storey (its
// storey below removed), a stair that no longer climbs one storey; a new room never takes the
// name of a removed one with its doors.
const tall = newBuilding();
tall.outline = [[0, 0], [12, 0], [12, 9], [0, 9]];
tall.automatic = false;
const tower = tall.root.children[0];
tower.floors.push(newFloor(3, [newRoom('landing')]));
grammar(tall);  // names the rooms: hall (storey 0), landing (storey 1)
tall.transitions.push({ symbol: null, kind: 'stair', from: 'hall', to: 'landing', width: 0 });
check(grammar(tall).includes('-> stair(hall, landing)'), 'the stair');
tower.floors.splice(0, 1);  // landing is now on storey 0
text = grammar(tall);
check(!text.includes('stair('), `a stair that no longer climbs: ${text}`);
check(build('storey_removed', text) !== null, 'the building without its ground storey builds');
tower.floors[0].children.push(newRoom('hall'));
text = grammar(tall);
check(!text.includes('stair(') && !text.includes('door('), 'a new room took a removed one\'s doors');

// The outline checks the grid makes while drawing (BLD206 before the builder says it).
const square = [[0, 0], [10, 0], [10, 10], [0, 10]];
check(outlineProblem([square], [true]) === '', 'a square is fine');
check(outlineProblem([[[0, 0], [5, 0], [10, 0], [10, 10]]], [true]) === 'three corners on a line', 'collinear corners');
check(outlineProblem([[[0, 0], [10, 10], [10, 0], [0, 10]]], [true]) === 'an edge crosses another', 'a bow tie');
check(outlineProblem([square, [[0, 2], [3, 2], [3, 5], [0, 5]]], [true, true]) !== '', 'a hole on the outline');
check(outlineProblem([square, [[12, 2], [13, 2], [13, 5]]], [true, true]) === 'a hole lies inside the outline', 'a hole outside');
const notched = [[0, 0], [10, 0], [10, 10], [6, 10], [6, 5], [4, 5], [4, 10], [0, 10]];
check(outlineProblem([notched, [[2, 7], [8, 7], [8, 8], [2, 8]]], [true, true]) !== '', 'a hole across the notch');
check(outlineProblem([square, [[2, 2], [4, 2], [4, 4], [2, 4]]], [true, true]) === '', 'a courtyard is fine');

// The grid shows a footprint where it is: a building of a real OpenStreetMap export, in degrees,
// lands inside the 480 x 300 grid (it once fell a degree off, the view snapped to whole units).
const lonLat = [[59.5779, 56.9903], [59.5786, 56.9905], [59.5787, 56.9904], [59.5780, 56.9902]];
const view = fitView(lonLat, Infinity);
const inGrid = lonLat.every(([x, y]) => {
  const [sx, sy] = [(x - view.left) * view.scale, 300 - (y - view.bottom) * view.scale];
  return sx >= 0 && sx <= 480 && sy >= 0 && sy <= 300;
});
check(inGrid, `a lon/lat footprint off the grid: ${JSON.stringify(view)}`);
const drawnView = fitView([[0, 0], [12, 0], [12, 10], [0, 10]]);
check(Number.isInteger(drawnView.left) && Number.isInteger(drawnView.bottom) && drawnView.scale === 12,
      `a drawn outline's view: ${JSON.stringify(drawnView)}`);

if (failures.length) {
  console.error(failures.join('\n'));
  process.exit(1);
}
console.log('draw model: trees, names, transitions and outlines checked');
