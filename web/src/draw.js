// Drawing a building (seed 000 §3.6): the outline is drawn on a snapping grid (click to add a
// corner, click the first corner or "close" to finish; drag a corner to move it), with holes
// (courtyards) drawn the same way inside it, or taken from a GeoJSON feature. The building is a
// tree (draw_model.js): containers of building parts side by side, each building part with a
// roof type and height (0: a disposable part, the paper's "fake-concave" notch) and storeys, each
// storey a tree of division containers and rooms. "split" turns a part or a room into a container
// across its parent's arrangement holding it and a new one (a horizontal part splits into
// vertically arranged sub-parts and vice versa). Inputs are lists and bounded numbers, and the
// text is written from the model, so the grammar that comes out always parses. Any `.bldg` the
// command line reads opens in the tool (read by the server's parser: POST /api/drawing).

import {
  buildingOf, clamp, findRoom, grammar, leafParts, newBuilding, newFloor, newPart, newRoom,
  orientations, remove, roofHeights, roofs, roomStoreys, roomTypes, ruleName, sizes, split,
  storeyHeights, transitionFits,
} from './draw_model.js';

const gridMetres = 0.5;
const gridWidth = 480;
const gridHeight = 300;

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

// The ids of a GeoJSON text's features that have one polygon (a building needs one).
export function featureIds(text) {
  try {
    return (JSON.parse(text).features || [])
      .filter((f) => f.geometry && (f.geometry.type === 'Polygon' ||
                                    (f.geometry.type === 'MultiPolygon' && f.geometry.coordinates.length === 1)))
      .map((f) => String(f.id ?? f.properties?.id ?? ''))
      .filter(Boolean);
  } catch {
    return [];
  }
}

// Whether segments ab and cd cross or touch (shared end points excepted).
function segmentsMeet(a, b, c, d) {
  const side = (p, q, r) => Math.sign((q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]));
  const same = (p, q) => p[0] === q[0] && p[1] === q[1];
  if (same(a, c) || same(a, d) || same(b, c) || same(b, d)) return false;
  const within = (p, q, r) => Math.min(p[0], q[0]) <= r[0] && r[0] <= Math.max(p[0], q[0]) &&
    Math.min(p[1], q[1]) <= r[1] && r[1] <= Math.max(p[1], q[1]);
  const [d1, d2, d3, d4] = [side(c, d, a), side(c, d, b), side(a, b, c), side(a, b, d)];
  if (d1 !== d2 && d3 !== d4 && d1 && d2 && d3 && d4) return true;
  return (!d1 && within(c, d, a)) || (!d2 && within(c, d, b)) || (!d3 && within(a, b, c)) || (!d4 && within(a, b, d));
}

// The edges of `ring` (closed when `closed`).
function edgesOf(ring, closed) {
  const edges = [];
  for (let i = 0; i + 1 < ring.length; ++i) edges.push([ring[i], ring[i + 1]]);
  if (closed && ring.length >= 3) edges.push([ring[ring.length - 1], ring[0]]);
  return edges;
}

// Why the rings (outer first, then holes) are not a valid outline, or '': no ring crosses itself
// or another, no three consecutive corners on a line, holes inside the outer ring (what the
// builder checks, BLD206, said while drawing).
export function outlineProblem(rings, closedFlags) {
  for (let r = 0; r < rings.length; ++r) {
    const ring = rings[r];
    const n = ring.length;
    const closed = closedFlags[r];
    for (let i = 0; i < n; ++i) {
      if (!closed && (i === 0 || i === n - 1)) continue;
      const [a, b, c] = [ring[(i + n - 1) % n], ring[i], ring[(i + 1) % n]];
      if ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) === 0) {
        return 'three corners on a line';
      }
    }
  }
  const all = rings.map((ring, r) => edgesOf(ring, closedFlags[r]));
  for (let r = 0; r < all.length; ++r) {
    for (let s = r; s < all.length; ++s) {
      for (let i = 0; i < all[r].length; ++i) {
        for (let j = r === s ? i + 1 : 0; j < all[s].length; ++j) {
          if (segmentsMeet(...all[r][i], ...all[s][j])) return r === s ? 'an edge crosses another' : 'a hole meets the outline or another hole';
        }
      }
    }
  }
  for (let r = 1; r < rings.length; ++r) {
    if (rings[r].some((p) => !inside(rings[0], p))) return 'a hole lies inside the outline';
  }
  return '';
}

// Whether point `p` lies inside ring `ring` (even-odd rule).
function inside(ring, [x, y]) {
  let within = false;
  for (let i = 0, j = ring.length - 1; i < ring.length; j = i++) {
    const [xi, yi] = ring[i];
    const [xj, yj] = ring[j];
    if ((yi > y) !== (yj > y) && x < ((xj - xi) * (y - yi)) / (yj - yi) + xi) within = !within;
  }
  return within;
}

// The view { left, bottom, scale } that shows `ring` in the middle of the grid at most `largest`
// pixels a unit. A drawn outline's corner is kept on whole metres (so the 0.5 m grid lines stay
// on it); a footprint (degrees: hundreds of thousands of pixels a unit) is shown where it is.
export function fitView(ring, largest = 12) {
  const xs = ring.map((p) => p[0]);
  const ys = ring.map((p) => p[1]);
  const [minX, minY, maxX, maxY] = [Math.min(...xs), Math.min(...ys), Math.max(...xs), Math.max(...ys)];
  const scale = Math.min(largest, (0.8 * gridWidth) / (maxX - minX || 1), (0.8 * gridHeight) / (maxY - minY || 1));
  const centre = (lo, hi, pixels) => (lo + hi) / 2 - pixels / scale / 2;
  const whole = Number.isFinite(largest) ? Math.floor : (v) => v;
  return { left: whole(centre(minX, maxX, gridWidth)), bottom: whole(centre(minY, maxY, gridHeight)), scale };
}

const escape = (text) => String(text).replace(/&/g, '&amp;').replace(/"/g, '&quot;').replace(/</g, '&lt;');
const option = (list, chosen) => [...new Set([...list, chosen])].filter((v) => v !== undefined)
  .map((v) => `<option ${v === chosen ? 'selected' : ''}>${escape(v)}</option>`).join('');

export class DrawingTool {
  // `files`: { geojson(): [paths of the folder's GeoJSON files], read(path): Promise<text>,
  //            parse(text, path): Promise<POST /api/drawing's answer> }.
  constructor(panel, onGrammar, files) {
    this.panel = panel;
    this.onGrammar = onGrammar; // (path, text)
    this.files = files;
    this.building = newBuilding();
    this.closed = false; // the outer ring
    this.hole = -1; // the hole being drawn, or -1
    // What the grid shows: world metres (left, bottom) at its lower-left corner, pixels a metre.
    this.view = { left: 0, bottom: 0, scale: 12 };
    this.render();
  }

  // Fits the view to `ring` (a loaded outline, at most 12 pixels a metre, or a footprint in its
  // file's units, metres or degrees, at any scale).
  fit(ring, largest = 12) {
    if (ring.length > 0) this.view = fitView(ring, largest);
  }

  // Screen pixels of world point `p` on the grid.
  toScreen([x, y]) {
    const { left, bottom, scale } = this.view;
    return [(x - left) * scale, gridHeight - (y - bottom) * scale];
  }

  storeyHeight() {
    return clamp(Number(this.panel.querySelector('[name=storey-height]')?.value) || 3, storeyHeights);
  }

  // A door between two rooms (their symbols, as the plan's rooms carry them), once.
  // Rooms on consecutive storeys get a stair (from the lower), rooms on one storey a door.
  connect(a, b) {
    const t = this.building.transitions;
    const storeys = roomStoreys(this.building);
    const [from, to] = storeys.get(a) > storeys.get(b) ? [b, a] : [a, b];
    const kind = storeys.get(from) === storeys.get(to) ? 'door' : 'stair';
    const candidate = { symbol: null, kind, from, to, width: 0 };
    if (a === b || !transitionFits(candidate, storeys) ||
        t.some((x) => x.kind === kind && ((x.from === a && x.to === b) || (x.from === b && x.to === a)))) {
      return false;
    }
    t.push(candidate);
    this.changed();
    return true;
  }

  // Splits the room `symbol` (the plan's right-click "split"): a new room beside it.
  splitRoom(symbol) {
    const found = findRoom(this.building, symbol);
    if (!found) return false;
    split(found.parent, found.room, newRoom());
    this.redraw();
    return true;
  }

  // Removes the room `symbol` unless it is its container's last.
  removeRoom(symbol) {
    const found = findRoom(this.building, symbol);
    if (!found || !remove(found.parent, found.room)) return false;
    this.redraw();
    return true;
  }

  // Shows the building of `text` (read by the server), keeping the file's name; returns why not,
  // or ''.
  async load(text, path) {
    const answer = await this.files.parse(text, path);
    if (!answer.ok) return answer.diagnostics[0] || 'the file does not parse';
    const building = buildingOf(answer.building);
    if (building.footprint) {
      // Nothing changes until the footprint is read (a file that is not there leaves the tool
      // as it was).
      try {
        building.outline = await this.footprintRing(building.footprint, path);
      } catch (error) {
        return `its footprint: ${error.message || error}`;
      }
    }
    this.building = building;
    this.closed = true;
    this.hole = -1;
    this.fit(building.outline, building.footprint ? Infinity : 12);
    this.loadedPath = path;
    this.path = path;
    const first = leafParts(this.building.root)[0];
    this.initialStoreyHeight = first && first.floors[0].height > 0 ? first.floors[0].height : 3;
    this.panel.innerHTML = '';
    this.render();
    return '';
  }

  // Uses the footprint `feature` of GeoJSON `file` as the outline (the grammar's geojson(...));
  // the grid shows it scaled to fit.
  async useFootprint(file, feature) {
    this.building.footprint = { file, feature };
    this.building.holes = [];
    this.hole = -1;
    this.closed = true;
    await this.previewFootprint();
    this.changed();
  }

  // The outline of a footprint, its file named relative to the drawing's `.bldg` (as the command
  // line reads it).
  async footprintRing({ file, feature }, bldgPath) {
    const folder = bldgPath && bldgPath.includes('/') ? bldgPath.slice(0, bldgPath.lastIndexOf('/') + 1) : '';
    return featureRing(await this.files.read(folder + file), feature) || [];
  }

  async previewFootprint() {
    // Shown in the file's own coordinates (metres or degrees), fitted to the grid.
    this.building.outline = await this.footprintRing(this.building.footprint, this.loadedPath);
    this.fit(this.building.outline, Infinity);
    this.render();
  }

  // The .bldg text of what is drawn, or null while the outline is open.
  grammar(name) {
    if (!this.closed) return null;
    this.building.name = name;
    // A hole still being drawn is not written.
    const drawing = this.hole >= 0 ? this.building.holes[this.hole] : null;
    const written = { ...this.building, holes: this.building.holes.filter((h) => h !== drawing) };
    const text = grammar(written);
    this.building.transitions = written.transitions; // as grammar() kept them
    return text;
  }

  // Metres under the mouse, snapped to the grid.
  snapped(event) {
    const box = this.panel.querySelector('svg').getBoundingClientRect();
    const x = this.view.left + (event.clientX - box.left) / this.view.scale;
    const y = this.view.bottom + (box.bottom - event.clientY) / this.view.scale;
    return [Math.round(x / gridMetres) * gridMetres, Math.round(y / gridMetres) * gridMetres];
  }

  // A click on the grid: a corner of the outline, or of the hole being drawn (inside the outline).
  click(event) {
    const drawingHole = this.closed && this.hole >= 0;
    if (this.closed && !drawingHole) return;
    const ring = drawingHole ? this.building.holes[this.hole] : this.building.outline;
    const p = this.snapped(event);
    const first = ring[0];
    if (ring.length >= 3 && first[0] === p[0] && first[1] === p[1]) {
      this.close();
      return;
    }
    const last = ring[ring.length - 1];
    if (last && last[0] === p[0] && last[1] === p[1]) return;
    ring.push(p);
    const problem = this.problem(true);
    if (problem) {
      ring.pop();
      this.hint(`not there: ${problem}`);
      return;
    }
    this.render();
  }

  // What is wrong with the outline and holes as drawn ('' when nothing); `open`: the ring being
  // drawn is not closed yet.
  problem(open = false) {
    const { outline, holes } = this.building;
    const rings = [outline, ...holes];
    const closed = rings.map((_, r) => !open || (r === 0 ? this.closed : r - 1 !== this.hole));
    if (!this.closed) return outlineProblem([outline], [!open]);
    return outlineProblem(rings, closed);
  }

  close() {
    const ring = this.hole >= 0 ? this.building.holes[this.hole] : this.building.outline;
    if (!ring || ring.length < 3) return;
    const drawing = this.hole;
    if (drawing >= 0) this.hole = -1;
    else this.closed = true;
    const problem = this.problem();
    if (problem) {
      if (drawing >= 0) this.hole = drawing;
      else this.closed = false;
      this.hint(`cannot close: ${problem}`);
      return;
    }
    this.render();
    this.changed();
  }

  clear() {
    this.building.outline = [];
    this.building.holes = [];
    this.building.footprint = null;
    this.closed = false;
    this.hole = -1;
    this.render();
  }

  // A new drawing: an empty grid, one part, one storey, a hall; the next edit opens a new file.
  startNew() {
    this.building = newBuilding();
    this.loadedPath = null;
    this.initialStoreyHeight = 3;
    this.view = { left: 0, bottom: 0, scale: 12 };
    this.panel.innerHTML = '';
    this.clear();
  }

  hint(text) {
    const hint = this.panel.querySelector('.draw-hint');
    if (hint) hint.textContent = text;
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

  redraw() {
    this.render();
    this.changed();
  }

  gridSvg() {
    const { outline, holes, footprint } = this.building;
    const gridLines = [];
    // A line every metre (every 5 m when metres would be closer than 4 pixels), every 5th darker.
    const { left, bottom, scale } = this.view;
    const step = scale >= 4 ? 1 : scale >= 0.8 ? 5 : 10 ** Math.ceil(Math.log10(4 / scale));
    const lines = (from, pixels, draw) => {
      for (let k = Math.ceil(from / step); (k * step - from) * scale <= pixels; ++k) {
        draw((k * step - from) * scale, k % 5 ? 'minor' : 'major');
      }
    };
    lines(left, gridWidth, (x, c) => gridLines.push(`<line x1="${x}" y1="0" x2="${x}" y2="${gridHeight}" class="${c}"/>`));
    lines(bottom, gridHeight, (y, c) => gridLines.push(`<line x1="0" y1="${gridHeight - y}" x2="${gridWidth}" y2="${gridHeight - y}" class="${c}"/>`));
    const screen = (ring) => ring.map((p) => this.toScreen(p).join(','));
    const closedRings = [this.closed ? outline : null, ...holes.filter((_, h) => h !== this.hole)].filter(Boolean);
    const area = closedRings.length
      ? `<path d="${closedRings.map((r) => `M${screen(r).join('L')}Z`).join('')}" class="outline closed" fill-rule="evenodd"/>`
      : '';
    const open = !this.closed ? outline : this.hole >= 0 ? holes[this.hole] : null;
    const line = open ? `<polyline points="${screen(open).join(' ')}" class="outline"/>` : '';
    const corners = [outline, ...holes].flatMap((ring, r) => (footprint && r === 0 ? [] : screen(ring).map((p, i) => {
      const [cx, cy] = p.split(',');
      return `<circle cx="${cx}" cy="${cy}" r="4" class="corner" data-ring="${r}" data-corner="${i}"/>`;
    })));
    return `<svg width="${gridWidth}" height="${gridHeight}" class="draw-grid">${gridLines.join('')}${area}${line}${corners.join('')}</svg>`;
  }

  // The tree's HTML; every node's block carries data-node, its index in this.nodes.
  treeHtml() {
    this.nodes = [];
    const id = (node, parent) => this.nodes.push({ node, parent }) - 1;
    const orientationSelect = (o) => `<select name="orientation" title="how the children are arranged">${option(orientations, o)}</select>`;
    const removeButton = (parent, what) => (parent && parent.children.length > 1
      ? `<button type="button" name="remove" title="remove the ${what}">×</button>` : '');
    const division = (d, parent) => {
      const n = id(d, parent);
      if (d.kind === 'room') {
        return `<span class="room-item" data-node="${n}" data-symbol="${escape(d.symbol || '')}">
            <select name="type">${option(roomTypes, d.type)}</select>
            <select name="size">${option(sizes, d.size)}</select>
            <input name="walls" type="number" min="0" max="32" placeholder="walls" title="walls (0: as the subdivision gives, or 3-32)" value="${d.walls || ''}">
            <input name="windows" type="number" min="0" max="32" placeholder="win." title="windows on exterior walls" value="${d.windows || ''}">
            <label title="an entrance door from outside"><input name="entrance" type="checkbox" ${d.entrance ? 'checked' : ''}>entry</label>
            <button type="button" name="split" title="split the room: a container across its row holding it and a new room">split</button>
            ${removeButton(parent, 'room')}
          </span>`;
      }
      return `<span class="division-group" data-node="${n}">
          <i>rooms</i> ${orientationSelect(d.orientation)}
          <button type="button" name="add-room">+ room</button>${removeButton(parent, 'container')}
          ${d.children.map((c) => division(c, d)).join('')}
        </span>`;
    };
    const part = (p, parent) => {
      const n = id(p, parent);
      if (p.kind === 'parts') {
        return `<div class="part-group" data-node="${n}">
            <b>parts</b> ${orientationSelect(p.orientation)}
            <button type="button" name="add-part">+ part</button>${removeButton(parent, 'container')}
            ${p.children.map((c) => part(c, p)).join('')}
          </div>`;
      }
      const storeys = p.floors.map((f, s) => {
        const fn = id(f, p);
        return `<div class="storey-row" data-node="${fn}">
            <b>storey ${s}</b> ${orientationSelect(f.orientation)}
            <button type="button" name="add-room">+ room</button>
            ${p.floors.length > 1 ? '<button type="button" name="remove-storey" title="remove the storey">×</button>' : ''}
            ${f.children.map((c) => division(c, f)).join('')}
          </div>`;
      }).join('');
      return `<div class="part-block" data-node="${n}">
          <b>part</b>
          <label>roof <select name="part-roof">${option(roofs, p.roof)}</select></label>
          <label title="0: a disposable part, removed after the subdivision (a notch)">roof height
            <input name="part-roof-height" type="number" min="0" step="0.5" value="${p.roofHeight}"></label>
          <button type="button" name="add-storey">+ storey</button>
          <button type="button" name="split" title="split the part: a container across its row holding it and a new part">split</button>
          ${removeButton(parent, 'part')}
          ${storeys}
        </div>`;
    };
    const root = this.building.root;
    const rootId = id(root, null);
    return `<div class="part-group building-root" data-node="${rootId}">
        <b>building</b> parts ${orientationSelect(root.orientation)}
        <button type="button" name="add-part">+ part</button>
        ${root.children.map((c) => part(c, root)).join('')}
      </div>`;
  }

  render() {
    const b = this.building;
    const previous = (name, fallback) => this.panel.querySelector(`[name=${name}]`)?.value ?? fallback;
    const name = previous('name', b.name);
    const storeyHeight = previous('storey-height', String(this.initialStoreyHeight ?? 3));
    const hint = b.footprint
      ? `the outline of feature ${b.footprint.feature} of ${b.footprint.file} (shown scaled to fit)`
      : !this.closed ? 'click the grid to add corners (0.5 m steps); click the first corner to close'
        : this.hole >= 0 ? 'click inside the outline to add the hole\'s corners; click its first corner to close it'
          : 'outline closed: drag a corner to move it';
    this.panel.innerHTML = `
      <div class="draw-controls">
        <label>name <input name="name" value="${escape(name)}"></label>
        <label>storey height <input name="storey-height" type="number" min="2" step="0.1" value="${storeyHeight}"></label>
        <label title="doors room to room and between parts, the entrance and the stairs, written by the tool">
          <input name="automatic" type="checkbox" ${b.automatic ? 'checked' : ''}>automatic doors</label>
        <label title="the outline of a feature of a GeoJSON file beside the drawing">footprint from
          <select name="footprint-file"><option value="">(drawn)</option>${this.files.geojson().map((f) => `<option ${b.footprint?.file === f ? 'selected' : ''}>${escape(f)}</option>`).join('')}</select>
          <select name="footprint-feature">${b.footprint ? `<option>${escape(b.footprint.feature)}</option>` : ''}</select></label>
        <button type="button" name="close" ${(this.closed && this.hole < 0) ? 'disabled' : ''}>close outline</button>
        <button type="button" name="add-hole" ${!this.closed || this.hole >= 0 || b.footprint ? 'disabled' : ''} title="a courtyard: draw its corners inside the outline">+ hole</button>
        <button type="button" name="remove-hole" ${b.holes.length === 0 || this.hole >= 0 ? 'disabled' : ''}>− hole</button>
        <button type="button" name="clear">clear</button>
        <button type="button" name="new" title="a new drawing (the open file stays as it is)">new</button>
      </div>
      ${this.gridSvg()}
      <div class="draw-hint">${escape(hint)}</div>
      ${this.treeHtml()}`;
    this.bind();
  }

  bindCorners(svg) {
    for (const corner of svg.querySelectorAll('.corner')) {
      corner.addEventListener('mousedown', (event) => {
        if (!this.closed || this.building.footprint) return;
        event.preventDefault();
        const r = Number(corner.dataset.ring);
        const ring = r === 0 ? this.building.outline : this.building.holes[r - 1];
        const i = Number(corner.dataset.corner);
        const before = ring[i];
        const move = (e) => {
          this.dragging = true;
          ring[i] = this.snapped(e);
          const [cx, cy] = this.toScreen(ring[i]);
          corner.setAttribute('cx', cx);
          corner.setAttribute('cy', cy);
        };
        const up = () => {
          window.removeEventListener('mousemove', move);
          window.removeEventListener('mouseup', up);
          if (this.dragging) {
            const problem = this.problem(this.hole >= 0);
            if (problem) ring[i] = before;
            this.redraw();
            if (problem) this.hint(`not there: ${problem}`);
          }
          setTimeout(() => { this.dragging = false; }, 0);
        };
        window.addEventListener('mousemove', move);
        window.addEventListener('mouseup', up);
      });
    }
  }

  bind() {
    const svg = this.panel.querySelector('svg');
    svg.addEventListener('click', (event) => { if (!this.dragging && !this.building.footprint) this.click(event); });
    this.bindCorners(svg);
    const on = (selector, event, handler) => {
      for (const el of this.panel.querySelectorAll(selector)) el.addEventListener(event, handler);
    };
    on('.draw-controls [name=close]', 'click', () => this.close());
    on('.draw-controls [name=clear]', 'click', () => this.clear());
    on('.draw-controls [name=new]', 'click', () => this.startNew());
    on('.draw-controls [name=add-hole]', 'click', () => {
      this.building.holes.push([]);
      this.hole = this.building.holes.length - 1;
      this.render();
    });
    on('.draw-controls [name=remove-hole]', 'click', () => {
      this.building.holes.pop();
      this.redraw();
    });
    on('.draw-controls [name=automatic]', 'change', (e) => {
      this.building.automatic = e.target.checked;
      this.changed();
    });
    on('.draw-controls [name=name]', 'change', () => this.changed());
    on('.draw-controls [name=storey-height]', 'change', () => {
      const height = this.storeyHeight();
      this.panel.querySelector('[name=storey-height]').value = height;
      for (const { node } of this.nodes) if (node.kind === 'floor') node.height = height;
      this.changed();
    });
    on('[name=footprint-file]', 'change', async (e) => {
      const file = e.target.value;
      const features = this.panel.querySelector('[name=footprint-feature]');
      if (!file) {
        this.clear();
        return;
      }
      const ids = featureIds(await this.files.read(file));
      features.replaceChildren(new Option('(feature)', ''), ...ids.map((i) => new Option(i, i)));
    });
    on('[name=footprint-feature]', 'change', (e) => {
      const file = this.panel.querySelector('[name=footprint-file]').value;
      if (file && e.target.value) this.useFootprint(file, e.target.value);
    });
    for (const block of this.panel.querySelectorAll('[data-node]')) this.bindNode(block);
  }

  // The controls of one tree node (only its own: nested blocks bind theirs).
  bindNode(block) {
    const { node, parent } = this.nodes[Number(block.dataset.node)];
    const own = (name) => [...block.querySelectorAll(`[name=${name}]`)].find((el) => el.closest('[data-node]') === block);
    const listen = (name, event, handler) => own(name)?.addEventListener(event, handler);
    listen('orientation', 'change', (e) => { node.orientation = e.target.value; this.changed(); });
    listen('remove', 'click', () => { if (remove(parent, node)) this.redraw(); });
    listen('split', 'click', () => {
      split(parent, node, node.kind === 'room' ? newRoom() : newPart(this.storeyHeight()));
      this.redraw();
    });
    listen('add-part', 'click', () => { node.children.push(newPart(this.storeyHeight())); this.redraw(); });
    listen('add-room', 'click', () => { node.children.push(newRoom()); this.redraw(); });
    if (node.kind === 'part') {
      listen('part-roof', 'change', (e) => { node.roof = e.target.value; this.changed(); });
      listen('part-roof-height', 'change', (e) => {
        node.roofHeight = clamp(Number(e.target.value) || 0, roofHeights);
        e.target.value = node.roofHeight;
        this.changed();
      });
      listen('add-storey', 'click', () => {
        // As tall as the storey below (0 keeps the restriction rules' storey height).
        const below = node.floors[node.floors.length - 1];
        node.floors.push(newFloor(below ? below.height : this.storeyHeight(), [newRoom('landing'), newRoom('bedroom')]));
        this.redraw();
      });
    }
    if (node.kind === 'floor') {
      listen('remove-storey', 'click', () => {
        if (parent.floors.length <= 1) return;
        parent.floors.splice(parent.floors.indexOf(node), 1);
        this.redraw();
      });
    }
    if (node.kind === 'room') {
      listen('type', 'change', (e) => { node.type = e.target.value; this.changed(); });
      listen('size', 'change', (e) => { node.size = e.target.value; this.changed(); });
      listen('walls', 'change', (e) => {
        const walls = Math.round(Number(e.target.value) || 0);
        node.walls = walls >= 3 && walls <= 32 ? walls : 0; // the grammar's bounds
        e.target.value = node.walls || '';
        this.changed();
      });
      listen('windows', 'change', (e) => {
        node.windows = Math.min(32, Math.max(0, Math.round(Number(e.target.value) || 0)));
        this.changed();
      });
      listen('entrance', 'change', (e) => { node.entrance = e.target.checked; this.changed(); });
    }
  }
}
