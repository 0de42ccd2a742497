// The drawing tool's building (seed 000 §3.6, §4.1): an outline with holes (or a GeoJSON
// footprint) and the ontology's tree, as the tool edits it and as it writes it as `.bldg` text.
//
//   building: { name, outline: [[x, y]], holes: [[[x, y]]], footprint: {file, feature} | null,
//               root: parts container, transitions: [transition], automatic: bool }
//   parts container: { kind: 'parts', symbol, orientation, children: [part node] }
//   building part:   { kind: 'part', symbol, roof, roofHeight, floors: [floor] }
//   floor:           { kind: 'floor', symbol, height, orientation, children: [division] }
//   division:        { kind: 'divisions', symbol, orientation, children } or
//                    { kind: 'room', symbol, type, size, walls, windows, entrance }
//   transition:      { symbol, kind: door|entrance|window|stair, from, to, width }
//
// Every node keeps its grammar symbol (read from the file, or a fresh one given when the text is
// written), so transitions and the plan's rooms keep naming the same rooms across edits. The text
// is written from the model only, so it always parses. With `automatic`, the tool adds its own
// doors (room to room along each floor, between the first rooms of neighbouring parts), the
// entrance and the stairs; the `transitions` the user asked for (or the file had) come too.

export const roofs = ['Hip', 'Gable', 'Flat', 'Pyramid', 'Mansard', 'HoledMansard', 'HipGlued', 'None'];
export const roomTypes = ['hall', 'living', 'kitchen', 'dining', 'bedroom', 'bath', 'study', 'storage',
                          'landing', 'shop', 'office', 'atrium', 'garden', 'corridor'];
export const sizes = ['small', 'medium', 'big'];
export const orientations = ['alternate', 'horizontal', 'vertical'];

// A symbol the grammar accepts: letters, digits and underscores, not starting with a digit.
export const ruleName = (text) => text.replace(/[^A-Za-z0-9_]/g, '_').replace(/^(?=\d)/, 'r');
// Numbers in their shortest round-trip form (as the command line's printer writes them).
const number = (x) => String(Number(x) + 0);
// A string literal of the grammar (escapes \" \\ \n \t).
export const quoted = (text) => `"${String(text).replace(/\\/g, '\\\\').replace(/"/g, '\\"')
  .replace(/\n/g, '\\n').replace(/\t/g, '\\t').replace(/[\u0000-\u001f]/g, ' ')}"`;
// A room type as written: an identifier as it is, anything else as a string ("dining room").
const typeName = (type) => (/^[A-Za-z_][A-Za-z0-9_]*$/.test(type) ? type : quoted(type));
// The grammar's bounds (docs/bldg-language.md, BLD205).
export const storeyHeights = [2, 20];
export const roofHeights = [0, 100];
export const clamp = (x, [lo, hi]) => Math.min(hi, Math.max(lo, x));

export const newRoom = (type = 'bedroom', size = 'medium') =>
  ({ kind: 'room', symbol: null, type, size, walls: 0, windows: 0, entrance: false });
export const newFloor = (height, rooms = [newRoom('hall')]) =>
  ({ kind: 'floor', symbol: null, height, orientation: 'horizontal', children: rooms });
export const newPart = (height) =>
  ({ kind: 'part', symbol: null, roof: 'Hip', roofHeight: 2.5, floors: [newFloor(height)] });

export function newBuilding() {
  return { name: 'Drawn building', outline: [], holes: [], footprint: null,
           root: { kind: 'parts', symbol: 'building', orientation: 'vertical', children: [newPart(3)] },
           transitions: [], automatic: true };
}

// The orientation of a container made by splitting a child of a container oriented `parent`:
// across it (a horizontal arrangement splits into vertically arranged pieces and vice versa).
export function across(parent) {
  if (parent === 'horizontal') return 'vertical';
  if (parent === 'vertical') return 'horizontal';
  return 'alternate';
}

export const disposable = (part) => Number(part.roofHeight) === 0;

// Every building part (leaves) in tree order.
export function leafParts(node, out = []) {
  if (node.kind === 'part') out.push(node);
  else node.children.forEach((c) => leafParts(c, out));
  return out;
}

// Every room of a floor or a divisions container in tree order.
export function leafRooms(node, out = []) {
  for (const c of node.children) {
    if (c.kind === 'room') out.push(c);
    else leafRooms(c, out);
  }
  return out;
}

// Visits every node: parts, containers, floors, divisions and rooms.
function eachNode(node, visit) {
  visit(node);
  if (node.kind === 'part') node.floors.forEach((f) => eachNode(f, visit));
  else (node.children || []).forEach((c) => eachNode(c, visit));
}

// The room named `symbol` and the container holding it, or null.
export function findRoom(building, symbol) {
  let found = null;
  eachNode(building.root, (n) => {
    if (found || n.kind === 'room' || n.kind === 'part') return;
    for (const c of n.children || []) {
      if (c.kind === 'room' && c.symbol === symbol) found = { room: c, parent: n };
    }
  });
  return found;
}

// Splits `child` of container `parent` (a building part or a room): in its place comes a
// container across the parent's orientation holding it and `fresh`.
export function split(parent, child, fresh) {
  const kind = child.kind === 'room' ? 'divisions' : 'parts';
  const at = parent.children.indexOf(child);
  parent.children[at] = { kind, symbol: null, orientation: across(parent.orientation), children: [child, fresh] };
}

// Removes `child` of `parent` when it is not the container's last child; true when removed.
export function remove(parent, child) {
  if (parent.children.length <= 1) return false;
  parent.children.splice(parent.children.indexOf(child), 1);
  return true;
}

// The storey (its floor's index in its building part) of every named room.
export function roomStoreys(building) {
  const storeys = new Map();
  leafParts(building.root).forEach((part) => part.floors.forEach((floor, s) => {
    leafRooms(floor).forEach((room) => { if (room.symbol) storeys.set(room.symbol, s); });
  }));
  return storeys;
}

// Whether transition `t` joins rooms that exist, on the storeys its kind needs.
export function transitionFits(t, storeys) {
  if (!storeys.has(t.from)) return false;
  if (t.kind === 'entrance' || t.kind === 'window') return true;
  if (!storeys.has(t.to)) return false;
  const rise = storeys.get(t.to) - storeys.get(t.from);
  return t.kind === 'stair' ? rise === 1 : rise === 0;
}

// Gives every node without a symbol a fresh one; returns the set of symbols in use.
function nameAll(building) {
  const used = new Set(['building']);
  eachNode(building.root, (n) => { if (n.symbol) used.add(n.symbol); });
  building.transitions.forEach((t) => { if (t.symbol) used.add(t.symbol); });
  const fresh = (base) => {
    const stem = ruleName(base);
    let name = stem;
    for (let k = 2; used.has(name); ++k) name = `${stem}${k}`;
    used.add(name);
    return name;
  };
  eachNode(building.root, (n) => {
    if (n.symbol) return;
    n.symbol = fresh(n.kind === 'room' ? n.type : n.kind);
  });
  return fresh;
}

function orientedCounterClockwise(ring) {
  let twiceArea = 0;
  for (let i = 0; i < ring.length; ++i) {
    const [x0, y0] = ring[i];
    const [x1, y1] = ring[(i + 1) % ring.length];
    twiceArea += x0 * y1 - x1 * y0;
  }
  return twiceArea >= 0 ? ring : [...ring].reverse();
}

// The tool's own doors, entrance and stairs (see the top of this file), skipping any the building
// already has between the same rooms.
function automaticTransitions(building, have, fresh) {
  const out = [];
  const joined = (kind, from, to) => have.concat(out).some((t) => t.kind === kind &&
    ((t.from === from && t.to === to) || (t.from === to && t.to === from)));
  const add = (kind, from, to) => {
    if (joined(kind, from, to)) return;
    out.push({ symbol: fresh(kind === 'door' ? 'door' : kind), kind, from, to, width: 0 });
  };
  const kept = leafParts(building.root).filter((p) => !disposable(p));
  kept.forEach((part) => {
    part.floors.forEach((floor, s) => {
      const rooms = leafRooms(floor);
      for (let r = 1; r < rooms.length; ++r) add('door', rooms[r - 1].symbol, rooms[r].symbol);
      if (s > 0) add('stair', leafRooms(part.floors[s - 1])[0].symbol, rooms[0].symbol);
    });
  });
  const firsts = kept.map((p) => leafRooms(p.floors[0])[0].symbol);
  if (firsts.length > 0 && !have.some((t) => t.kind === 'entrance')) add('entrance', firsts[0], '');
  for (let k = 1; k < firsts.length; ++k) add('door', firsts[k - 1], firsts[k]);
  return out;
}

function transitionRule(t) {
  const rooms = t.kind === 'door' || t.kind === 'stair' ? `${t.from}, ${t.to}` : t.from;
  return `${t.symbol} -> ${t.kind}(${rooms}${t.width > 0 ? `, ${number(t.width)}` : ''})`;
}

// The `.bldg` text of `building`, or null while its outline is open.
export function grammar(building) {
  if (!building.footprint && building.outline.length < 3) return null;
  // Transitions whose rooms are still there, on the storeys they need (a door on one storey, a
  // stair one storey up): a removed room or storey takes its doors with it. Filtered before new
  // rooms are named, so a new room never takes a removed one's name and its doors.
  const storeys = roomStoreys(building);
  building.transitions = building.transitions.filter((t) => transitionFits(t, storeys));
  const fresh = nameAll(building);
  const rules = [];
  const orientation = (o, comma) => (o === 'alternate' ? '' : `${comma ? ', ' : ''}${o}`);
  const set = (names) => ` : {${names.join(', ')}}`;
  const division = (d) => {
    if (d.kind === 'room') {
      const extra = d.walls || d.windows || d.entrance
        ? `, ${d.walls || 0}, ${d.windows || 0}${d.entrance ? ', true' : ''}` : '';
      rules.push(`${d.symbol} -> room(${typeName(d.type)}, ${d.size}${extra})`);
      return;
    }
    rules.push(`${d.symbol} -> divisions(${orientation(d.orientation, false)})${set(d.children.map((c) => c.symbol))}`);
    d.children.forEach(division);
  };
  const part = (p) => {
    if (p.kind === 'parts') {
      rules.push(`${p.symbol} -> buildingparts(${orientation(p.orientation, false)})${set(p.children.map((c) => c.symbol))}`);
      p.children.forEach(part);
      return;
    }
    rules.push(`${p.symbol} -> buildingpart(${p.roof}, ${number(p.roofHeight)})${set(p.floors.map((f) => f.symbol))}`);
    for (const f of p.floors) {
      const height = f.height > 0 ? number(f.height) : '';
      const args = [height, f.orientation === 'alternate' ? '' : f.orientation].filter(Boolean).join(', ');
      rules.push(`${f.symbol} -> floor(${args})${set(f.children.map((c) => c.symbol))}`);
      f.children.forEach(division);
    }
  };
  building.root.children.forEach(part);
  building.transitions.forEach((t) => { if (!t.symbol) t.symbol = fresh(t.kind === 'door' ? 'connect' : t.kind); });
  const transitions = building.automatic
    ? [...automaticTransitions(building, building.transitions, fresh), ...building.transitions]
    : building.transitions;
  const ring = (r) => `[${r.map(([x, y]) => `(${number(x)}, ${number(y)})`).join(', ')}]`;
  const shape = building.footprint
    ? `geojson(${quoted(building.footprint.file)}, ${quoted(building.footprint.feature)})`
    : [ring(orientedCounterClockwise(building.outline)), ...building.holes.filter((h) => h.length >= 3).map(ring)].join(', ');
  const children = [...building.root.children.map((c) => c.symbol), ...transitions.map((t) => t.symbol)];
  return ['# Drawn in the Insula studio (seed 000 §3.6); docs/bldg-language.md',
          `${building.root.symbol} -> building(${quoted(building.name)}, ${shape}${orientation(building.root.orientation, true)})${set(children)}`,
          ...rules, ...transitions.map(transitionRule)].join('\n') + '\n';
}

// The tool's building from the server's reading of a `.bldg` text (POST /api/drawing,
// src/apps/studio/drawing.cc). Its transitions are kept as they are; the tool adds none.
export function buildingOf(json) {
  const division = (d) => (d.kind === 'room'
    ? { kind: 'room', symbol: d.symbol, type: d.type, size: d.size, walls: d.walls, windows: d.windows, entrance: d.entrance }
    : { kind: 'divisions', symbol: d.symbol, orientation: d.orientation, children: d.children.map(division) });
  const part = (p) => (p.kind === 'part'
    ? { kind: 'part', symbol: p.symbol, roof: p.roof, roofHeight: p.roof_height,
        floors: p.floors.map((f) => ({ kind: 'floor', symbol: f.symbol, height: f.height, orientation: f.orientation,
                                       children: f.children.map(division) })) }
    : { kind: 'parts', symbol: p.symbol, orientation: p.orientation, children: p.children.map(part) });
  return { name: json.name, outline: json.outline, holes: json.holes, footprint: json.footprint,
           root: part(json.parts),
           transitions: json.transitions.map((t) => ({ ...t })), automatic: false };
}
