// Drawing a building (seed 000 §3.6), first part: the outline is drawn on a snapping grid (click
// to add a corner, click the first corner or "close" to finish; drag a corner to move it), the
// building part gets a roof type, a roof height and its storeys, and each storey a list of rooms
// (type and size) split along one direction. The tool writes the `.bldg` grammar from these
// choices only (no free text), so what it writes always parses; doors join each room to the next,
// the first room of the ground floor gets the entrance, and a stair joins the first rooms of
// consecutive storeys. The grammar opens in the editor as a new file and builds as usual.

const gridMetres = 0.5;
const pixelsPerMetre = 12;
const roofs = ['Hip', 'Gable', 'Flat', 'Pyramid', 'Mansard', 'HipGlued', 'None'];
const roomTypes = ['hall', 'living', 'kitchen', 'dining', 'bedroom', 'bath', 'study', 'storage',
                   'landing', 'shop', 'office', 'atrium', 'garden'];
const sizes = ['small', 'medium', 'big'];

// A name the grammar accepts: letters, digits and underscores, not starting with a digit.
const ruleName = (text) => text.replace(/[^A-Za-z0-9_]/g, '_').replace(/^(?=\d)/, 'r');
const fixed = (x) => Number(x.toFixed(2)).toString();

export class DrawingTool {
  constructor(panel, onGrammar) {
    this.panel = panel;
    this.onGrammar = onGrammar; // (name, text)
    this.outline = []; // [x, y] metres, counter-clockwise once closed
    this.closed = false;
    this.initial = {};
    this.storeys = [{ rooms: [{ type: 'hall', size: 'medium' }],
                      direction: 'horizontal' }];
    this.render();
  }

  // Shows the drawing of `text` (drawingOf), keeping the file's name; returns why not, or ''.
  load(text, path) {
    const drawing = drawingOf(text);
    if (drawing.why) return drawing.why;
    this.outline = drawing.outline;
    this.closed = true;
    this.storeys = drawing.storeys;
    this.initial = { name: drawing.name, roof: drawing.roof, roofHeight: String(drawing.roofHeight),
                     storeyHeight: String(drawing.storeyHeight) };
    this.path = path;
    this.panel.innerHTML = '';
    this.render();
    return '';
  }

  // The .bldg text of what is drawn, or null while the outline is open.
  grammar(name) {
    if (!this.closed || this.outline.length < 3) return null;
    const ring = orientedCounterClockwise(this.outline)
      .map(([x, y]) => `(${fixed(x)}, ${fixed(y)})`).join(', ');
    const roof = this.panel.querySelector('[name=roof]').value;
    const roofHeight = Number(this.panel.querySelector('[name=roof-height]').value) || 0;
    const storeyHeight = Number(this.panel.querySelector('[name=storey-height]').value) || 3;
    const lines = [];
    const rules = [];
    const floors = this.storeys.map((_, s) => `floor${s}`);
    const transitions = [];
    const roomName = (s, r) => `${ruleName(this.storeys[s].rooms[r].type)}_${s}_${r}`;
    this.storeys.forEach((storey, s) => {
      const rooms = storey.rooms.map((_, r) => roomName(s, r));
      rules.push(`floor${s} -> floor(${fixed(storeyHeight)}, vertical) : {div${s}}`);
      rules.push(`div${s} -> divisions(${storey.direction}) : {${rooms.join(', ')}}`);
      storey.rooms.forEach((room, r) => {
        rules.push(`${roomName(s, r)} -> room(${ruleName(room.type)}, ${room.size})`);
      });
      for (let r = 1; r < rooms.length; ++r) {
        transitions.push(`door${s}_${r} -> door(${rooms[r - 1]}, ${rooms[r]})`);
      }
      if (s > 0) transitions.push(`stair${s} -> stair(${roomName(s - 1, 0)}, ${roomName(s, 0)})`);
    });
    transitions.unshift(`entrance0 -> entrance(${roomName(0, 0)})`);
    const transitionNames = transitions.map((t) => t.split(' ')[0]);
    lines.push('# Drawn in the Insula studio (seed 000 §3.6); docs/bldg-language.md');
    lines.push(`building -> building("${name}", [${ring}]) : {part, ${transitionNames.join(', ')}}`);
    lines.push(`part -> buildingpart(${roof}, ${fixed(roofHeight)}) : {${floors.join(', ')}}`);
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
    this.render();
  }

  // A loaded file keeps its name; a new drawing is named after its building.
  changed() {
    const name = this.panel.querySelector('[name=name]').value || 'Drawn building';
    const text = this.grammar(name);
    if (text) this.onGrammar(this.path || `${ruleName(name).toLowerCase()}.bldg`, text);
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
    const storeyRows = this.storeys.map((storey, s) => `
      <div class="storey-row" data-storey="${s}">
        <b>storey ${s}</b>
        <select name="direction">${['horizontal', 'vertical'].map((d) => `<option ${d === storey.direction ? 'selected' : ''}>${d}</option>`).join('')}</select>
        ${storey.rooms.map((room, r) => `
          <span class="room-item" data-room="${r}">
            <select name="type">${roomTypes.map((t) => `<option ${t === room.type ? 'selected' : ''}>${t}</option>`).join('')}</select>
            <select name="size">${sizes.map((z) => `<option ${z === room.size ? 'selected' : ''}>${z}</option>`).join('')}</select>
            <button type="button" name="remove-room" title="remove the room">×</button>
          </span>`).join('')}
        <button type="button" name="add-room">+ room</button>
      </div>`).join('');
    const previous = (name, fallback) => this.panel.querySelector(`[name=${name}]`)?.value ?? fallback;
    const values = { name: previous('name', this.initial.name ?? 'Drawn building'),
                     roof: previous('roof', this.initial.roof ?? 'Hip'),
                     roofHeight: previous('roof-height', this.initial.roofHeight ?? '2.5'),
                     storeyHeight: previous('storey-height', this.initial.storeyHeight ?? '3') };
    this.panel.innerHTML = `
      <div class="draw-controls">
        <label>name <input name="name" value="${values.name.replace(/"/g, '&quot;')}"></label>
        <label>roof <select name="roof">${roofs.map((r) => `<option ${r === values.roof ? 'selected' : ''}>${r}</option>`).join('')}</select></label>
        <label>roof height <input name="roof-height" type="number" min="0" step="0.5" value="${values.roofHeight}"></label>
        <label>storey height <input name="storey-height" type="number" min="2" step="0.1" value="${values.storeyHeight}"></label>
        <button type="button" name="close" ${this.closed || this.outline.length < 3 ? 'disabled' : ''}>close outline</button>
        <button type="button" name="clear">clear</button>
        <button type="button" name="add-storey">+ storey</button>
      </div>
      <svg width="${width}" height="${height}" class="draw-grid">${gridLines.join('')}${shape}${corners.join('')}</svg>
      <div class="draw-hint">${this.closed ? 'outline closed: drag a corner to move it' : 'click the grid to add corners (0.5 m steps); click the first corner to close'}</div>
      ${storeyRows}`;
    this.bind();
  }

  bind() {
    const svg = this.panel.querySelector('svg');
    svg.addEventListener('click', (event) => { if (!this.dragging) this.click(event); });
    for (const corner of svg.querySelectorAll('.corner')) {
      corner.addEventListener('mousedown', (event) => {
        if (!this.closed) return;
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
    on('[name=clear]', 'click', () => this.clear());
    on('[name=add-storey]', 'click', () => {
      this.storeys.push({ rooms: [{ type: 'landing', size: 'medium' }, { type: 'bedroom', size: 'medium' }],
                          direction: 'horizontal' });
      this.render();
      this.changed();
    });
    on('.draw-controls input, .draw-controls select', 'change', () => this.changed());
    for (const row of this.panel.querySelectorAll('.storey-row')) {
      const storey = this.storeys[Number(row.dataset.storey)];
      row.querySelector('[name=direction]').addEventListener('change', (e) => {
        storey.direction = e.target.value;
        this.changed();
      });
      row.querySelector('[name=add-room]').addEventListener('click', () => {
        storey.rooms.push({ type: 'bedroom', size: 'medium' });
        this.render();
        this.changed();
      });
      for (const item of row.querySelectorAll('.room-item')) {
        const room = storey.rooms[Number(item.dataset.room)];
        item.querySelector('[name=type]').addEventListener('change', (e) => { room.type = e.target.value; this.changed(); });
        item.querySelector('[name=size]').addEventListener('change', (e) => { room.size = e.target.value; this.changed(); });
        item.querySelector('[name=remove-room]').addEventListener('click', () => {
          if (storey.rooms.length <= 1) return;
          storey.rooms.splice(Number(item.dataset.room), 1);
          this.render();
          this.changed();
        });
      }
    }
  }
}

// The drawing a `.bldg` text describes, when the tool can show it: one building with one outline
// (no holes), one building part, its floors each holding rooms (directly or in one divisions
// container). Returns { name, outline, roof, roofHeight, storeyHeight, storeys } or { why }.
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
  const head = /^"([^"]*)"\s*,\s*\[([^\]]*)\]\s*(.*)$/.exec(building.args);
  if (!head) return { why: 'the building has no outline of its own (a GeoJSON footprint?)' };
  if (/\[/.test(head[3])) return { why: 'the outline has holes' };
  const outline = [...head[2].matchAll(/\(\s*(-?[\d.]+)\s*,\s*(-?[\d.]+)\s*\)/g)].map((p) => [Number(p[1]), Number(p[2])]);
  if (outline.length < 3) return { why: 'the outline has fewer than 3 corners' };
  const parts = building.children.map((c) => rules.get(c)).filter((r) => r && r.kind !== 'door' &&
    r.kind !== 'entrance' && r.kind !== 'stair' && r.kind !== 'window');
  if (parts.length !== 1 || parts[0].kind !== 'buildingpart') return { why: 'more than one building part' };
  const [roof, roofHeight] = parts[0].args.split(',').map((a) => a.trim());
  let storeyHeight = null;
  const storeys = [];
  for (const floorName of parts[0].children) {
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
      const [type, size] = room.args.split(',').map((a) => a.trim());
      rooms.push({ type, size: size || 'medium' });
    }
    if (rooms.length === 0) return { why: `${floorName} has no rooms` };
    storeys.push({ rooms, direction });
  }
  if (storeys.length === 0) return { why: 'the building part has no floors' };
  return { name: head[1], outline, roof, roofHeight: Number(roofHeight) || 0,
           storeyHeight: storeyHeight || 3, storeys };
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
