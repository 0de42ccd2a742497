// Drawing a building (seed 000 §3.6): the outline is drawn on a snapping grid (click to add a
// corner, click the first corner or "close" to finish; drag a corner to move it); the building is
// made of building parts side by side along one direction (each with a roof type and a roof
// height: height 0 makes a disposable part, a notch in the final building, the paper's
// "fake-concave"), each part of storeys, each storey of rooms (type and size) split along one
// direction. The tool writes the `.bldg` grammar from these choices only (no free text), so what it
// writes always parses: doors join each room to the next and the first rooms of neighbouring parts,
// the first room of the first part gets the entrance, and a stair joins the first rooms of
// consecutive storeys. It opens the `.bldg` files it can represent (drawingOf). The grammar opens
// in the editor as a file and builds as usual.

const gridMetres = 0.5;
const pixelsPerMetre = 12;
const roofs = ['Hip', 'Gable', 'Flat', 'Pyramid', 'Mansard', 'HipGlued', 'None'];
const roomTypes = ['hall', 'living', 'kitchen', 'dining', 'bedroom', 'bath', 'study', 'storage',
                   'landing', 'shop', 'office', 'atrium', 'garden'];
const sizes = ['small', 'medium', 'big'];

// A name the grammar accepts: letters, digits and underscores, not starting with a digit.
const ruleName = (text) => text.replace(/[^A-Za-z0-9_]/g, '_').replace(/^(?=\d)/, 'r');
const fixed = (x) => Number(x.toFixed(2)).toString();

const newPart = () => ({ roof: 'Hip', roofHeight: 2.5,
                         storeys: [{ rooms: [{ type: 'hall', size: 'medium' }], direction: 'horizontal' }] });

// The outline of feature `id` (its `id`, else `properties.id`) of a GeoJSON text: the outer ring
// of its (first) polygon, or null.
export function featureRing(text, id) {
  let json;
  try {
    json = JSON.parse(text);
  } catch {
    return null;
  }
  const feature = (json.features || []).find((f) => String(f.id ?? f.properties?.id) === id);
  const g = feature && feature.geometry;
  if (!g) return null;
  const ring = g.type === 'Polygon' ? g.coordinates[0] : g.type === 'MultiPolygon' ? g.coordinates[0][0] : null;
  return ring ? ring.slice(0, -1).map(([x, y]) => [x, y]) : null;
}

// The ids of a GeoJSON text's features that have polygons.
export function featureIds(text) {
  try {
    return (JSON.parse(text).features || [])
      .filter((f) => f.geometry && /Polygon$/.test(f.geometry.type))
      .map((f) => String(f.id ?? f.properties?.id ?? ''))
      .filter(Boolean);
  } catch {
    return [];
  }
}

export class DrawingTool {
  // `files`: { geojson(): [paths of the folder's GeoJSON files], read(path): Promise<text> }.
  constructor(panel, onGrammar, files) {
    this.panel = panel;
    this.onGrammar = onGrammar; // (path, text)
    this.files = files;
    this.footprint = null; // { file, feature }: the outline is that feature's (geojson(...))
    this.outline = []; // [x, y] metres, counter-clockwise once closed
    this.closed = false;
    this.initial = {};
    this.parts = [newPart()];
    this.partsDirection = 'vertical';
    this.connections = []; // [room, room]: doors the user asked for (connect)
    this.render();
  }

  // A door between two rooms (their rule names, as the plan's rooms carry them), once.
  connect(a, b) {
    if (a === b || this.connections.some(([x, y]) => (x === a && y === b) || (x === b && y === a))) {
      return false;
    }
    this.connections.push([a, b]);
    this.changed();
    return true;
  }

  // Shows the drawing of `text` (drawingOf), keeping the file's name; returns why not, or ''.
  load(text, path) {
    const drawing = drawingOf(text);
    if (drawing.why) return drawing.why;
    this.outline = drawing.outline;
    this.closed = true;
    this.parts = drawing.parts;
    this.partsDirection = drawing.partsDirection;
    this.footprint = drawing.footprint || null;
    if (this.footprint) this.previewFootprint();
    this.connections = drawing.connections;
    this.initial = { name: drawing.name, storeyHeight: String(drawing.storeyHeight) };
    this.loadedPath = path;
    this.path = path;
    this.panel.innerHTML = '';
    this.render();
    return '';
  }

  // Uses the footprint `feature` of GeoJSON `file` as the outline (the grammar's geojson(...));
  // the grid shows it scaled to fit.
  async useFootprint(file, feature) {
    this.footprint = { file, feature };
    this.closed = true;
    await this.previewFootprint();
    this.changed();
  }

  async previewFootprint() {
    const ring = featureRing(await this.files.read(this.footprint.file), this.footprint.feature) || [];
    const xs = ring.map((p) => p[0]);
    const ys = ring.map((p) => p[1]);
    const [minX, minY] = [Math.min(...xs), Math.min(...ys)];
    const span = Math.max(Math.max(...xs) - minX, Math.max(...ys) - minY) || 1;
    const fit = Math.min(480, 300) / pixelsPerMetre * 0.8;  // metres of grid the preview fills
    this.outline = ring.map(([x, y]) => [1 + (x - minX) / span * fit, 1 + (y - minY) / span * fit]);
    this.closed = true;
    this.render();
  }

  // The .bldg text of what is drawn, or null while the outline is open.
  grammar(name) {
    if (!this.closed || (!this.footprint && this.outline.length < 3)) return null;
    const ring = this.footprint
      ? null
      : orientedCounterClockwise(this.outline).map(([x, y]) => `(${fixed(x)}, ${fixed(y)})`).join(', ');
    const storeyHeight = Number(this.panel.querySelector('[name=storey-height]').value) || 3;
    const rules = [];
    const transitions = [];
    const roomName = (p, s, r) => `${ruleName(this.parts[p].storeys[s].rooms[r].type)}_${p}_${s}_${r}`;
    // Disposable parts (height 0) are removed after the subdivision: nothing leads into them.
    const kept = (p) => this.parts[p].roofHeight > 0 || this.parts[p].roof === 'None';
    this.parts.forEach((part, p) => {
      const floors = part.storeys.map((_, s) => `floor${p}_${s}`);
      rules.push(`part${p} -> buildingpart(${part.roof}, ${fixed(part.roofHeight)}) : {${floors.join(', ')}}`);
      part.storeys.forEach((storey, s) => {
        const rooms = storey.rooms.map((_, r) => roomName(p, s, r));
        rules.push(`floor${p}_${s} -> floor(${fixed(storeyHeight)}, vertical) : {div${p}_${s}}`);
        rules.push(`div${p}_${s} -> divisions(${storey.direction}) : {${rooms.join(', ')}}`);
        storey.rooms.forEach((room, r) => {
          // walls (0: as the subdivision gives; 3-32), windows (0-32), an entrance of its own.
          const extra = room.walls || room.windows !== undefined || room.entrance
            ? `, ${room.walls || 0}, ${room.windows ?? 0}${room.entrance ? ', true' : ''}`
            : '';
          rules.push(`${roomName(p, s, r)} -> room(${ruleName(room.type)}, ${room.size}${extra})`);
        });
        if (!kept(p)) return;
        for (let r = 1; r < rooms.length; ++r) {
          transitions.push(`door${p}_${s}_${r} -> door(${rooms[r - 1]}, ${rooms[r]})`);
        }
        if (s > 0) transitions.push(`stair${p}_${s} -> stair(${roomName(p, s - 1, 0)}, ${roomName(p, s, 0)})`);
      });
    });
    const keptParts = this.parts.map((_, p) => p).filter(kept);
    if (keptParts.length > 0) {
      transitions.unshift(`entrance0 -> entrance(${roomName(keptParts[0], 0, 0)})`);
    }
    for (let k = 1; k < keptParts.length; ++k) {
      transitions.push(`link${keptParts[k]} -> door(${roomName(keptParts[k - 1], 0, 0)}, ${roomName(keptParts[k], 0, 0)})`);
    }
    // Doors the user connected, while both rooms still exist.
    const names = new Set(rules.map((r) => r.split(' ')[0]));
    this.connections = this.connections.filter(([a, b]) => names.has(a) && names.has(b));
    this.connections.forEach(([a, b], k) => transitions.push(`connect${k} -> door(${a}, ${b})`));
    const transitionNames = transitions.map((t) => t.split(' ')[0]);
    const top = this.parts.length === 1 ? 'part0' : 'parts';
    const lines = ['# Drawn in the Insula studio (seed 000 §3.6); docs/bldg-language.md',
                   `building -> building("${name}", ${this.footprint
                     ? `geojson("${this.footprint.file}", "${this.footprint.feature}")`
                     : `[${ring}]`}) : {${[top, ...transitionNames].join(', ')}}`];
    if (this.parts.length > 1) {
      lines.push(`parts -> buildingparts(${this.partsDirection}) : {${this.parts.map((_, p) => `part${p}`).join(', ')}}`);
    }
    return [...lines, ...rules, ...transitions].join('\n') + '\n';
  }

  // Metres under the mouse, snapped to the grid.
  snapped(event) {
    const svg = this.panel.querySelector('svg');
    const box = svg.getBoundingClientRect();
    const x = (event.clientX - box.left) / pixelsPerMetre;
    const y = (box.bottom - event.clientY) / pixelsPerMetre;
    return [Math.round(x / gridMetres) * gridMetres, Math.round(y / gridMetres) * gridMetres];
  }

  click(event) {
    if (this.closed) return;
    const p = this.snapped(event);
    const first = this.outline[0];
    if (this.outline.length >= 3 && first[0] === p[0] && first[1] === p[1]) {
      this.close();
      return;
    }
    const last = this.outline[this.outline.length - 1];
    if (last && last[0] === p[0] && last[1] === p[1]) return;
    this.outline.push(p);
    this.render();
  }

  close() {
    if (this.outline.length < 3) return;
    this.closed = true;
    this.render();
    this.changed();
  }

  clear() {
    this.outline = [];
    this.closed = false;
    this.footprint = null;
    this.render();
  }

  // A loaded file keeps its name; a new drawing is named after its building.
  changed() {
    const name = this.panel.querySelector('[name=name]').value || 'Drawn building';
    const text = this.grammar(name);
    if (!text) return;
    // The file the drawing writes (main.js compares it with the open file).
    this.path = this.loadedPath || `${ruleName(name).toLowerCase()}.bldg`;
    this.onGrammar(this.path, text);
  }

  render() {
    const width = 480;
    const height = 300;
    const points = this.outline.map(([x, y]) => `${x * pixelsPerMetre},${height - y * pixelsPerMetre}`);
    const gridLines = [];
    for (let x = 0; x <= width; x += pixelsPerMetre) {
      gridLines.push(`<line x1="${x}" y1="0" x2="${x}" y2="${height}" class="${x % (5 * pixelsPerMetre) ? 'minor' : 'major'}"/>`);
    }
    for (let y = height; y >= 0; y -= pixelsPerMetre) {
      gridLines.push(`<line x1="0" y1="${y}" x2="${width}" y2="${y}" class="${(height - y) % (5 * pixelsPerMetre) ? 'minor' : 'major'}"/>`);
    }
    const shape = this.closed
      ? `<polygon points="${points.join(' ')}" class="outline closed"/>`
      : `<polyline points="${points.join(' ')}" class="outline"/>`;
    const corners = points.map((p, i) => {
      const [cx, cy] = p.split(',');
      return `<circle cx="${cx}" cy="${cy}" r="4" class="corner" data-corner="${i}"/>`;
    });
    const option = (list, chosen) => list.map((v) => `<option ${v === chosen ? 'selected' : ''}>${v}</option>`).join('');
    const storeyRow = (storey, p, s) => `
      <div class="storey-row" data-part="${p}" data-storey="${s}">
        <b>storey ${s}</b>
        <select name="direction">${option(['horizontal', 'vertical'], storey.direction)}</select>
        ${storey.rooms.map((room, r) => `
          <span class="room-item" data-room="${r}">
            <select name="type">${option(roomTypes, room.type)}</select>
            <select name="size">${option(sizes, room.size)}</select>
            <input name="walls" type="number" min="0" max="32" placeholder="walls" title="walls (0: as the subdivision gives, or 3-32)" value="${room.walls || ''}">
            <input name="windows" type="number" min="0" max="32" placeholder="win." title="windows on exterior walls (0 when empty)" value="${room.windows ?? ''}">
            <label title="an entrance door from outside"><input name="entrance" type="checkbox" ${room.entrance ? 'checked' : ''}>entry</label>
            <button type="button" name="remove-room" title="remove the room">×</button>
          </span>`).join('')}
        <button type="button" name="add-room">+ room</button>
      </div>`;
    const partBlocks = this.parts.map((part, p) => `
      <div class="part-block" data-part="${p}">
        <b>part ${p}</b>
        <label>roof <select name="part-roof">${option(roofs, part.roof)}</select></label>
        <label title="0: a disposable part, removed after the subdivision (a notch)">roof height
          <input name="part-roof-height" type="number" min="0" step="0.5" value="${part.roofHeight}"></label>
        <button type="button" name="add-storey">+ storey</button>
        ${this.parts.length > 1 ? '<button type="button" name="remove-part">× part</button>' : ''}
        ${part.storeys.map((storey, s) => storeyRow(storey, p, s)).join('')}
      </div>`).join('');
    const previous = (name, fallback) => this.panel.querySelector(`[name=${name}]`)?.value ?? fallback;
    const values = { name: previous('name', this.initial.name ?? 'Drawn building'),
                     storeyHeight: previous('storey-height', this.initial.storeyHeight ?? '3') };
    this.panel.innerHTML = `
      <div class="draw-controls">
        <label>name <input name="name" value="${values.name.replace(/"/g, '&quot;')}"></label>
        <label>storey height <input name="storey-height" type="number" min="2" step="0.1" value="${values.storeyHeight}"></label>
        <label>parts side by side <select name="parts-direction">${option(['vertical', 'horizontal'], this.partsDirection)}</select></label>
        <button type="button" name="add-part">+ part</button>
        <label title="the outline of a feature of a GeoJSON file beside the drawing">footprint from
          <select name="footprint-file"><option value="">(drawn)</option>${this.files.geojson().map((f) => `<option ${this.footprint?.file === f ? 'selected' : ''}>${f}</option>`).join('')}</select>
          <select name="footprint-feature">${this.footprint ? `<option>${this.footprint.feature}</option>` : ''}</select></label>
        <button type="button" name="close" ${this.closed || this.outline.length < 3 ? 'disabled' : ''}>close outline</button>
        <button type="button" name="clear">clear</button>
      </div>
      <svg width="${width}" height="${height}" class="draw-grid">${gridLines.join('')}${shape}${corners.join('')}</svg>
      <div class="draw-hint">${this.footprint ? `the outline of feature ${this.footprint.feature} of ${this.footprint.file} (shown scaled to fit)` : this.closed ? 'outline closed: drag a corner to move it' : 'click the grid to add corners (0.5 m steps); click the first corner to close'}</div>
      ${partBlocks}`;
    this.bind();
  }

  bind() {
    const svg = this.panel.querySelector('svg');
    svg.addEventListener('click', (event) => { if (!this.dragging && !this.footprint) this.click(event); });
    for (const corner of svg.querySelectorAll('.corner')) {
      corner.addEventListener('mousedown', (event) => {
        if (!this.closed || this.footprint) return;
        event.preventDefault();
        const i = Number(corner.dataset.corner);
        const move = (e) => {
          this.dragging = true;
          this.outline[i] = this.snapped(e);
          const p = this.outline[i];
          corner.setAttribute('cx', p[0] * pixelsPerMetre);
          corner.setAttribute('cy', 300 - p[1] * pixelsPerMetre);
          const points = this.outline.map(([x, y]) => `${x * pixelsPerMetre},${300 - y * pixelsPerMetre}`);
          svg.querySelector('.outline').setAttribute('points', points.join(' '));
        };
        const up = () => {
          window.removeEventListener('mousemove', move);
          window.removeEventListener('mouseup', up);
          if (this.dragging) this.changed();
          setTimeout(() => { this.dragging = false; }, 0);
        };
        window.addEventListener('mousemove', move);
        window.addEventListener('mouseup', up);
      });
    }
    const on = (selector, event, handler) => {
      for (const el of this.panel.querySelectorAll(selector)) el.addEventListener(event, handler);
    };
    on('[name=close]', 'click', () => this.close());
    on('[name=footprint-file]', 'change', async (e) => {
      const file = e.target.value;
      const features = this.panel.querySelector('[name=footprint-feature]');
      if (!file) {
        this.clear();
        return;
      }
      const ids = featureIds(await this.files.read(file));
      features.replaceChildren(new Option('(feature)', ''), ...ids.map((id) => new Option(id, id)));
    });
    on('[name=footprint-feature]', 'change', (e) => {
      const file = this.panel.querySelector('[name=footprint-file]').value;
      if (file && e.target.value) this.useFootprint(file, e.target.value);
    });
    on('[name=clear]', 'click', () => this.clear());
    const redraw = () => {
      this.render();
      this.changed();
    };
    on('[name=add-part]', 'click', () => {
      this.parts.push(newPart());
      redraw();
    });
    on('[name=parts-direction]', 'change', (e) => {
      this.partsDirection = e.target.value;
      this.changed();
    });
    on('.draw-controls input', 'change', () => this.changed());
    for (const block of this.panel.querySelectorAll('.part-block')) {
      const p = Number(block.dataset.part);
      const part = this.parts[p];
      block.querySelector('[name=part-roof]').addEventListener('change', (e) => {
        part.roof = e.target.value;
        this.changed();
      });
      block.querySelector('[name=part-roof-height]').addEventListener('change', (e) => {
        part.roofHeight = Math.max(0, Number(e.target.value) || 0);
        this.changed();
      });
      block.querySelector('[name=add-storey]').addEventListener('click', () => {
        part.storeys.push({ rooms: [{ type: 'landing', size: 'medium' }, { type: 'bedroom', size: 'medium' }],
                            direction: 'horizontal' });
        redraw();
      });
      block.querySelector('[name=remove-part]')?.addEventListener('click', () => {
        this.parts.splice(p, 1);
        redraw();
      });
    }
    for (const row of this.panel.querySelectorAll('.storey-row')) {
      const storey = this.parts[Number(row.dataset.part)].storeys[Number(row.dataset.storey)];
      row.querySelector('[name=direction]').addEventListener('change', (e) => {
        storey.direction = e.target.value;
        this.changed();
      });
      row.querySelector('[name=add-room]').addEventListener('click', () => {
        storey.rooms.push({ type: 'bedroom', size: 'medium' });
        redraw();
      });
      for (const item of row.querySelectorAll('.room-item')) {
        const room = storey.rooms[Number(item.dataset.room)];
        item.querySelector('[name=type]').addEventListener('change', (e) => { room.type = e.target.value; this.changed(); });
        item.querySelector('[name=size]').addEventListener('change', (e) => { room.size = e.target.value; this.changed(); });
        item.querySelector('[name=walls]').addEventListener('change', (e) => {
          const walls = Math.round(Number(e.target.value) || 0);
          room.walls = walls >= 3 && walls <= 32 ? walls : 0;  // the grammar's bounds
          e.target.value = room.walls || '';
          this.changed();
        });
        item.querySelector('[name=windows]').addEventListener('change', (e) => {
          room.windows = e.target.value === '' ? undefined : Math.min(32, Math.max(0, Math.round(Number(e.target.value) || 0)));
          this.changed();
        });
        item.querySelector('[name=entrance]').addEventListener('change', (e) => { room.entrance = e.target.checked; this.changed(); });
        item.querySelector('[name=remove-room]').addEventListener('click', () => {
          if (storey.rooms.length <= 1) return;
          storey.rooms.splice(Number(item.dataset.room), 1);
          redraw();
        });
      }
    }
  }
}

// The drawing a `.bldg` text describes, when the tool can show it: one building with one outline
// (no holes), one building part or one container of building parts, their floors each holding
// rooms (directly or in one divisions container). Returns { name, outline, parts,
// partsDirection, storeyHeight } or { why }.
// Transitions are not read: the tool writes its own (doors room to room, the entrance, stairs).
export function drawingOf(text) {
  const rules = new Map();
  for (const raw of text.split('\n')) {
    const line = raw.replace(/#.*$/, '').trim();
    const m = /^(\w+)\s*->\s*(\w+)\s*\((.*)\)\s*(?::\s*\{([^}]*)\})?\s*$/.exec(line);
    if (!line) continue;
    if (!m) return { why: `a rule the tool cannot read: ${line.slice(0, 60)}` };
    rules.set(m[1], { kind: m[2], args: m[3], children: m[4] ? m[4].split(',').map((c) => c.trim()).filter(Boolean) : [] });
  }
  const buildings = [...rules.values()].filter((r) => r.kind === 'building');
  if (buildings.length !== 1) return { why: 'not one building rule' };
  const building = buildings[0];
  const fromFile = /^"([^"]*)"\s*,\s*geojson\(\s*"([^"]*)"\s*,\s*"([^"]*)"\s*\)\s*$/.exec(building.args);
  const head = fromFile ? [null, fromFile[1], '', ''] : /^"([^"]*)"\s*,\s*\[([^\]]*)\]\s*(.*)$/.exec(building.args);
  if (!head) return { why: 'an outline the tool cannot read' };
  if (/\[/.test(head[3])) return { why: 'the outline has holes' };
  const outline = [...head[2].matchAll(/\(\s*(-?[\d.]+)\s*,\s*(-?[\d.]+)\s*\)/g)].map((p) => [Number(p[1]), Number(p[2])]);
  if (!fromFile && outline.length < 3) return { why: 'the outline has fewer than 3 corners' };
  const structure = building.children.map((c) => rules.get(c)).filter((r) => r && r.kind !== 'door' &&
    r.kind !== 'entrance' && r.kind !== 'stair' && r.kind !== 'window');
  if (structure.length !== 1) return { why: 'the building holds more than one part or container' };
  let partRules = structure;
  let partsDirection = 'vertical';
  if (structure[0].kind === 'buildingparts') {
    partsDirection = structure[0].args.trim() || 'vertical';
    partRules = structure[0].children.map((c) => rules.get(c));
  }
  if (partRules.some((r) => !r || r.kind !== 'buildingpart')) {
    return { why: 'building parts inside building parts are not in the tool yet' };
  }
  let storeyHeight = null;
  const parts = [];
  for (const partRule of partRules) {
    const [roof, roofHeight] = partRule.args.split(',').map((a) => a.trim());
    const storeys = [];
    for (const floorName of partRule.children) {
      const floor = rules.get(floorName);
      if (!floor || floor.kind !== 'floor') return { why: `${floorName} is not a floor` };
      const args = floor.args.split(',').map((a) => a.trim()).filter(Boolean);
      const height = args.find((a) => /^[\d.]+$/.test(a));
      if (height && storeyHeight === null) storeyHeight = Number(height);
      let direction = args.find((a) => a === 'horizontal' || a === 'vertical') || 'horizontal';
      let roomNames = floor.children;
      if (roomNames.length === 1 && rules.get(roomNames[0])?.kind === 'divisions') {
        const divisions = rules.get(roomNames[0]);
        direction = divisions.args.trim() || direction;
        roomNames = divisions.children;
      }
      const rooms = [];
      for (const roomName of roomNames) {
        const room = rules.get(roomName);
        if (!room || (room.kind !== 'room' && room.kind !== 'division')) {
          return { why: `${roomName}: divisions inside divisions are not in the tool yet` };
        }
        const [type, size, walls, windows, entrance] = room.args.split(',').map((a) => a.trim());
        const read = { type, size: size || 'medium' };
        if (walls !== undefined && Number(walls) > 0) read.walls = Number(walls);
        if (windows !== undefined) read.windows = Number(windows);
        if (entrance === 'true') read.entrance = true;
        rooms.push(read);
      }
      if (rooms.length === 0) return { why: `${floorName} has no rooms` };
      storeys.push({ rooms, direction });
    }
    if (storeys.length === 0) return { why: 'a building part has no floors' };
    parts.push({ roof, roofHeight: Number(roofHeight) || 0, storeys });
  }
  const connections = [];
  for (const [name, rule] of rules) {
    if (rule.kind === 'door' && name.startsWith('connect')) {
      connections.push(rule.args.split(',').slice(0, 2).map((a) => a.trim()));
    }
  }
  return { name: head[1], outline, parts, partsDirection, storeyHeight: storeyHeight || 3,
           connections, footprint: fromFile ? { file: fromFile[2], feature: fromFile[3] } : null };
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
