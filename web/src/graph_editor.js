// The graph editor (seed 003's visual editor, in the studio): the open `.graph.json` drawn as
// nodes and edges, edited by hand, written back into the editor's text so that every edit runs
// the graph as any edit does (the studio's build, a newer edit cancelling the older). Nodes come
// from a searchable palette of the node catalogue (`GET /api/reference`), are dragged by their
// title, connected by dragging from an output port to an input port (a connection the checker
// refuses is not made, and its message is shown), and edited in a parameter panel. After each
// run every output port shows how many entities left it and every node its executions, rounds
// and time; ports whose entities were blocked or left unprocessed are marked. Undo and redo are
// the editor's; copy and paste duplicate the selected node.
import {
  copyNode, edgeEnds, edgeText, encapsulate, freshId, gatePorts, graphText, layout, nodeType, portsOf,
  removeNode, startingParams, startingValue,
} from './graph_model.js';

const nodeWidth = 170;
const titleHeight = 34;
const portGap = 18;
const svgNs = 'http://www.w3.org/2000/svg';

const escape = (text) => String(text).replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/"/g, '&quot;');

// A parameter's value as the panel shows it: an expression or a string as typed, else JSON.
const shownValue = (v) => (v === undefined ? '' : typeof v === 'string' ? v : JSON.stringify(v));
// What the panel's text means: '' removes the parameter, '=...' is an expression, JSON is a
// literal, anything else a string.
function typedValue(text) {
  if (text === '') return undefined;
  if (text.startsWith('=')) return text;
  try {
    return JSON.parse(text);
  } catch {
    return text;
  }
}

// An edge from an output port (x1, y1) to an input port (x2, y2): leaves rightwards, arrives
// from the left, bending further when it runs backwards or down a row.
function wirePath(x1, y1, x2, y2) {
  const bend = Math.min(80, Math.max(30, Math.abs(x2 - x1) / 2, Math.abs(y2 - y1) / 3));
  return `M${x1},${y1} C${x1 + bend},${y1} ${x2 - bend},${y2} ${x2},${y2}`;
}

export class GraphEditor {
  // `host`: { text(): the editor's text, setText(text), check(text): Promise<diagnostics>,
  //           diagnostics(): the open file's last ones, undo(), redo(), path(): the open file,
  //           read(path): Promise<text>, save(path, text): Promise, open(path) }.
  constructor(panel, reference, host) {
    this.panel = panel;
    // A field typed in but not applied yet (its change has not fired): the panel is not redrawn
    // under it. Cleared before the field's own change handler runs.
    panel.addEventListener('input', (e) => { if (e.target.matches('input, textarea')) e.target.dataset.dirty = '1'; });
    panel.addEventListener('change', (e) => { delete e.target.dataset.dirty; }, true);
    this.reference = reference;
    this.host = host;
    this.selected = null; // a node id: the one the panel edits
    this.selection = new Set(); // node ids (shift-click adds): what `encapsulate` takes
    this.gates = new Map(); // subgraph file -> its gates, read once
    this.root = null; // the whole document
    this.heightOf = (node) => this.nodeHeight(node);
    this.scope = []; // inline subgraphs opened: [{ name, via: the subgraph node's id }]
    this.trail = []; // graph files a double-click came through to the one shown
    this.expecting = null; // the file a double-click (or the way back) is opening
    this.report = null;
    this.clipboard = null;
    panel.innerHTML = `
      <div class="graph-controls">
        <input name="palette" list="graph-node-types" placeholder="add a node: type to search" size="28">
        <datalist id="graph-node-types">${reference.nodes.map((t) => `<option value="${escape(t.name)}">${escape(t.category)}: ${escape(t.doc.slice(0, 80))}</option>`).join('')}</datalist>
        <button type="button" name="add-node">add</button>
        <button type="button" name="layout" title="arrange the nodes by their edges">layout</button>
        <input name="subgraph-name" placeholder="subgraph name" size="12">
        <button type="button" name="encapsulate" title="the selected nodes (shift-click) into a subgraph file">encapsulate</button>
        <button type="button" name="undo">undo</button>
        <button type="button" name="redo">redo</button>
        <span class="graph-message"></span>
      </div>
      <div class="graph-scope"></div>
      <div class="graph-body">
        <svg class="graph-canvas" tabindex="0"></svg>
        <div class="graph-params"></div>
      </div>`;
    this.svg = panel.querySelector('svg');
    this.bindControls();
  }

  message(text) {
    this.panel.querySelector('.graph-message').textContent = text;
  }

  // The studio shows what the selected node made (a run with --probe) in the 3D view and its
  // entities in the panel; told whenever the selected node (its path from the top) changes.
  notifySelection() {
    const path = this.selected ? this.prefix() + this.selected : null;
    if (path === this.probePath) return;
    this.probePath = path;
    this.probed = null;
    if (this.host.select) this.host.select(path);
  }

  // What the probe run of the selected node found: { path, entities, count } (the studio).
  showProbe(probed) {
    this.probed = probed;
    if (this.root) this.renderParams();
  }

  // Reads the editor's text; false (and a message) when it is not a graph the editor can show.
  read() {
    try {
      const doc = JSON.parse(this.host.text());
      if (!doc || !Array.isArray(doc.nodes)) throw new Error('no "nodes" list');
      this.root = doc;
      layout(doc, this.heightOf);
      if (!this.doc) this.scope = []; // an opened subgraph that is gone from the text
      if (this.doc !== this.root) layout(this.doc, this.heightOf);
      return true;
    } catch (error) {
      this.root = null;
      this.message(`the text is not a graph yet: ${error.message}`);
      return false;
    }
  }

  // The graphs from the document down to the inline subgraph shown (§8: `#name` resolves in the
  // innermost `subgraphs` that defines it, searching outwards), or null when one is missing.
  chain() {
    if (!this.root) return null;
    const graphs = [this.root];
    for (const { name } of this.scope) {
      const found = [...graphs].reverse().map((g) => (g.subgraphs || {})[name]).find(Boolean);
      if (!found || !Array.isArray(found.nodes)) return null;
      if (!found.edges) found.edges = [];
      graphs.push(found);
    }
    return graphs;
  }

  // The graph shown and edited: the document, or the inline subgraph opened in it.
  get doc() {
    const graphs = this.chain();
    return graphs ? graphs[graphs.length - 1] : null;
  }

  // The report's names of what runs inside the subgraph shown: `houseA/door` (§13).
  prefix() {
    return this.scope.map((s) => `${s.via}/`).join('');
  }

  // The inline graph `#name` as seen from the graph shown, or null.
  inline(name) {
    const graphs = this.chain() || [];
    return [...graphs].reverse().map((g) => (g.subgraphs || {})[name]).find(Boolean) || null;
  }

  // The way here: the graph files a double-click came through (each opens again, like a tab's
  // history), then the inline subgraphs opened in this one.
  renderScope() {
    const bar = this.panel.querySelector('.graph-scope');
    if (this.scope.length === 0 && this.trail.length === 0) {
      bar.replaceChildren();
      return;
    }
    const files = this.trail.map((file, k) => `<a href="#" data-file="${k}">${escape(file)}</a>`);
    const crumbs = [...files, `<a href="#" data-depth="0">${escape(this.trail.length ? this.host.path() : 'graph')}</a>`,
                    ...this.scope.map((s, k) => `<a href="#" data-depth="${k + 1}">${escape(s.via)} (#${escape(s.name)})</a>`)];
    const hint = this.scope.length ? 'an inline subgraph' : 'a subgraph file, run on its own';
    bar.innerHTML = `${crumbs.join(' › ')} <i>(${hint}; double-click a subgraph node to open it)</i>`;
    for (const a of bar.querySelectorAll('a[data-file]')) {
      a.addEventListener('click', (e) => {
        e.preventDefault();
        const k = Number(a.dataset.file);
        this.expecting = this.trail[k];
        this.trail = this.trail.slice(0, k);
        this.host.open(this.expecting);
      });
    }
    for (const a of bar.querySelectorAll('a[data-depth]')) {
      a.addEventListener('click', (e) => {
        e.preventDefault();
        this.scope = this.scope.slice(0, Number(a.dataset.depth));
        this.selected = null;
        this.selection.clear();
        this.render();
      });
    }
  }

  // Shows the text's graph with the counts of `report` (the last run's, or null).
  show(report = this.report) {
    if (this.host.path() !== this.shownPath) {
      // Another file: nothing of the last one stays selected; the way back is kept only when a
      // double-click (or the way back) opened it.
      if (this.host.path() !== this.expecting) this.trail = [];
      this.expecting = null;
      this.shownPath = this.host.path();
      this.selected = null;
      this.selection.clear();
      this.selectedEdge = null;
      this.scope = [];
      this.message('');
    }
    if (report && report !== this.report) this.countsAt = performance.now(); // read by the browser test
    this.report = report;
    // Not under a drag: the drag ends by writing the document it moves (and draws the counts).
    if (this.dragging) return;
    if (!this.read()) {
      this.svg.replaceChildren();
      return;
    }
    this.render();
  }

  // Writes the document into the editor's text (the studio then runs it).
  write() {
    const text = graphText(this.root);
    if (text !== this.host.text()) this.host.setText(text);
    this.render();
  }

  portCount(node, port) {
    const ports = this.report && this.report.graph && this.report.graph.ports;
    return ports ? ports[`${this.prefix()}${node}.${port}`] : undefined;
  }

  // Where port `port` of node `node` is drawn.
  // How tall `node` is drawn: its title and a row per port.
  nodeHeight(node) {
    const { inputs, outputs } = this.ports(node);
    return titleHeight + 14 + Math.max(inputs.length, outputs.length, 1) * portGap;
  }

  // The ports of `node`; a subgraph file's gates once read.
  ports(node) {
    const ports = portsOf(this.reference, this.doc, node);
    if (node.type === 'subgraph' && typeof node.graph === 'string' && node.graph.startsWith('#')) {
      return this.withGates(ports, (this.inline(node.graph.slice(1)) || {}).gates);
    }
    const file = this.subgraphFile(node);
    if (!file) return ports;
    if (!this.gates.has(file)) {
      this.gates.set(file, null);
      this.host.read(file).then((text) => {
        this.gates.set(file, JSON.parse(text).gates || {});
        if (this.doc) this.render();
      }).catch(() => {});
    }
    return this.withGates(ports, this.gates.get(file));
  }

  // `ports` with the gates of a subgraph added as its ports.
  withGates(ports, gates) {
    if (gates) {
      const add = (list, name) => { if (!list.some((p) => p.name === name)) list.push({ name, type: 'T', collective: false }); };
      Object.keys(gates.inputs || {}).forEach((g) => add(ports.inputs, g));
      Object.keys(gates.outputs || {}).forEach((g) => add(ports.outputs, g));
    }
    return ports;
  }

  // The studio path of a subgraph node's file (relative to the open graph's folder), or null.
  subgraphFile(node) {
    if (node.type !== 'subgraph' || typeof node.graph !== 'string' || node.graph.startsWith('#')) return null;
    const open = this.host.path();
    const folder = open.includes('/') ? open.slice(0, open.lastIndexOf('/') + 1) : '';
    return folder + node.graph;
  }

  portAt(node, port, output) {
    const ports = this.ports(node);
    const list = output ? ports.outputs : ports.inputs;
    const i = Math.max(0, list.findIndex((p) => p.name === port));
    return [node.ui.x + (output ? nodeWidth : 0), node.ui.y + titleHeight + 10 + i * portGap];
  }

  render() {
    const doc = this.doc;
    const graph = (this.report && this.report.graph) || {};
    const parts = [];
    let right = 0;
    let bottom = 0;
    const byId = new Map(doc.nodes.map((n) => [n.id, n]));
    (doc.edges || []).forEach((edge, e) => {
      const { from, to } = edgeEnds(edge);
      const a = byId.get(from[0]);
      const b = byId.get(to[0]);
      if (!a || !b) return;
      const [x1, y1] = this.portAt(a, from[1], true);
      const [x2, y2] = this.portAt(b, to[1], false);
      const off = typeof edge === 'object' && edge.enabled === false;
      parts.push(`<path class="graph-edge${off ? ' off' : ''}${this.selectedEdge === e ? ' selected' : ''}" data-edge="${e}"
        d="${wirePath(x1, y1, x2, y2)}"/>`);
    });
    // The shown graph's own gates (graph-format §8): the ports it exposes when encapsulated, an
    // opened subgraph's or a subgraph file's, marked with the gate's name outside the node.
    const gateOf = gatePorts(doc.gates);
    const gateMark = (side, node, port, x, y) => {
      const gate = gateOf[side].get(`${node.id}.${port}`);
      if (!gate) return '';
      const at = side === 'in' ? `x="${x - 9}" text-anchor="end"` : `x="${x + 9}"`;
      return `<text class="graph-gate" data-gate="${escape(gate)}" ${at} y="${y + (side === 'in' ? 4 : 14)}">${side === 'in' ? `${escape(gate)} ▸` : `▸ ${escape(gate)}`}</text>`;
    };
    for (const node of doc.nodes) {
      const { inputs, outputs } = this.ports(node);
      const height = this.nodeHeight(node);
      const { x, y } = node.ui;
      right = Math.max(right, x + nodeWidth + 60);
      bottom = Math.max(bottom, y + height + 20);
      const runs = (graph.node_runs || {})[this.prefix() + node.id];
      const known = node.type === 'subgraph' || node.type === 'note' || nodeType(this.reference, node);
      parts.push(`<g class="graph-node${this.selected === node.id || this.selection.has(node.id) ? ' selected' : ''}${known ? '' : ' unknown'}${node.enabled === false ? ' off' : ''}" data-node="${escape(node.id)}">
        <rect x="${x}" y="${y}" width="${nodeWidth}" height="${height}" rx="5"/>
        <text class="graph-title" x="${x + 8}" y="${y + 14}">${escape(node.id)}</text>
        <text class="graph-type" x="${x + 8}" y="${y + 27}">${escape(node.type)}</text>
        ${runs ? `<text class="graph-runs" x="${x + nodeWidth - 6}" y="${y + 14}" text-anchor="end">${runs.executions}×${runs.rounds} ${runs.seconds !== undefined ? `${(1000 * runs.seconds).toFixed(1)} ms` : ''}</text>` : ''}
        ${inputs.map((p, i) => {
          const py = y + titleHeight + 10 + i * portGap;
          const unprocessed = (graph.unprocessed || {})[`${this.prefix()}${node.id}.${p.name}`];
          const gate = gateOf.in.get(`${node.id}.${p.name}`);
          return `<circle class="graph-port in${p.collective ? ' collective' : ''}${unprocessed ? ' warn' : ''}${gate ? ' gate' : ''}" cx="${x}" cy="${py}" r="5" data-port="${escape(p.name)}" data-side="in"><title>${escape(`${p.name}: ${p.type}${p.collective ? ', collective' : ''}${gate ? `; input gate ${gate}` : ''}${unprocessed ? `; ${unprocessed} unprocessed` : ''}`)}</title></circle>
            <text class="graph-port-name" x="${x + 9}" y="${py + 4}">${escape(p.name)}</text>${gateMark('in', node, p.name, x, py)}`;
        }).join('')}
        ${outputs.map((p, i) => {
          const py = y + titleHeight + 10 + i * portGap;
          const count = this.portCount(node.id, p.name);
          const blocked = (graph.blocked || {})[`${this.prefix()}${node.id}.${p.name}`];
          const gate = gateOf.out.get(`${node.id}.${p.name}`);
          return `<circle class="graph-port out${blocked ? ' warn' : ''}${gate ? ' gate' : ''}" cx="${x + nodeWidth}" cy="${py}" r="5" data-port="${escape(p.name)}" data-side="out"><title>${escape(`${p.name}: ${p.type}${gate ? `; output gate ${gate}` : ''}${blocked ? `; ${blocked} blocked` : ''}`)}</title></circle>
            <text class="graph-port-name" x="${x + nodeWidth - 9}" y="${py + 4}" text-anchor="end">${escape(p.name)}</text>${gateMark('out', node, p.name, x + nodeWidth, py)}
            ${count !== undefined ? `<text class="graph-count${blocked ? ' warn' : ''}" data-count="${escape(`${node.id}.${p.name}`)}" x="${x + nodeWidth + 8}" y="${py - 4}">${count}</text>` : ''}`;
        }).join('')}
      </g>`);
    }
    // The whole graph in the panel's width, down to 45% (then the panel scrolls).
    // Input gates' names stand left of their nodes: room for them left of x = 0.
    this.left = gateOf.in.size ? -80 : 0;
    const [width, height] = [Math.max(right, 400) - this.left, Math.max(bottom, 200)];
    const room = (this.panel.clientWidth || width) - 16;
    this.scale = Math.max(0.45, Math.min(1, room / width));
    this.svg.setAttribute('viewBox', `${this.left} 0 ${width} ${height}`);
    this.svg.setAttribute('width', Math.round(width * this.scale));
    this.svg.setAttribute('height', Math.round(height * this.scale));
    this.svg.innerHTML = parts.join('');
    this.bindCanvas();
    this.renderScope();
    this.renderParams();
  }

  // The selected node's parameters (every one of its type: literal or `=expression`), its
  // diagnostics, and what left its leaf ports in the last run.
  renderParams() {
    this.notifySelection();
    // Drawn into a detached box first: the panel is replaced only when it would change, so the
    // field the user is typing in is not taken away by a run that ends.
    const shown = this.panel.querySelector('.graph-params');
    // Nor while a field of the same node is being typed in (a probe's table arriving, a run):
    // drawn when the focus leaves it.
    const typing = shown.contains(document.activeElement) && document.activeElement.dataset.dirty === '1';
    if (typing && this.selected && shown.dataset.node === this.selected) {
      if (!this.paramsDeferred) {
        this.paramsDeferred = true;
        const resume = (event) => {
          const next = event.relatedTarget;
          if (next && shown.contains(next) && next.dataset.dirty === '1') {
            shown.addEventListener('focusout', resume, { once: true }); // on to the next field
            return;
          }
          this.paramsDeferred = false;
          setTimeout(() => this.renderParams(), 0); // after the field's change has been applied
        };
        shown.addEventListener('focusout', resume, { once: true });
      }
      return;
    }
    const box = document.createElement('div');
    box.dataset.node = this.selected || '';
    box.className = 'graph-params';
    this.fillParams(box);
    if (box.innerHTML !== this.paramsHtml) {
      this.paramsHtml = box.innerHTML;
      shown.replaceWith(box);
    }
  }

  fillParams(box) {
    const node = this.doc.nodes.find((n) => n.id === this.selected);
    if (!node) {
      this.renderGraphFields(box);
      return;
    }
    const type = nodeType(this.reference, node);
    const params = node.params || {};
    const specs = type ? type.params : Object.keys(params).map((name) => ({ name, type: 'any' }));
    const idPattern = new RegExp(`"id"\\s*:\\s*"${node.id}"`);
    const line = this.host.text().split('\n').findIndex((l) => idPattern.test(l)) + 1;
    const diagnostics = (this.host.diagnostics() || []).filter((d) => d.line === line);
    // What the node made (its probe run), else what of it reached the results.
    const probed = this.probed && this.probed.path === `${this.prefix()}${node.id}` ? this.probed : null;
    const entities = probed ? probed.entities
      : ((this.report && this.report.graph && this.report.graph.entities) || [])
        .filter((e) => e.port.startsWith(`${this.prefix()}${node.id}.`));
    box.innerHTML = `
      <b>${escape(node.id)}</b> <code>${escape(node.type)}</code>
      <div class="graph-doc">${escape(type ? type.doc : '')}</div>
      ${specs.map((p) => `
        <label class="graph-param" title="${escape(`${p.type}${p.default !== undefined ? ` = ${JSON.stringify(p.default)}` : ' (required)'}${p.min !== undefined ? `, >= ${p.min}` : ''}${p.max !== undefined ? `, <= ${p.max}` : ''}${p.per_entity ? ', per entity' : ''}`)}">
          <span>${escape(p.name)}</span>
          <input name="param" data-param="${escape(p.name)}" value="${escape(shownValue(params[p.name]))}"
                 placeholder="${escape(p.default !== undefined ? JSON.stringify(p.default) : 'required')}">
        </label>`).join('')}
      ${type && type.writes.length ? `<div class="graph-doc">node attributes to graph attributes:</div>${type.writes.map((w) => `
        <label class="graph-param" title="the graph attribute that receives the node attribute '${escape(w)}' (empty: discarded)">
          <span>${escape(w)} →</span>
          <input name="mapping" data-write="${escape(w)}" value="${escape((node.attributes || {})[w] ?? '')}" placeholder="(discarded)">
        </label>`).join('')}` : ''}
      ${type && type.augments.length ? this.augmentsHtml(type, node) : ''}
      <div class="graph-typed error"></div>
      <div class="graph-diagnostics">${diagnostics.map((d) => `<div class="${d.severity}">${escape(`${d.code}: ${d.message}`)}</div>`).join('')}</div>
      ${entities.length ? `<table class="graph-entities"><tr><th>entity</th><th>port</th><th>attributes</th></tr>${entities.slice(0, 50).map((e) =>
        `<tr><td>${e.id} ${escape(e.type)}</td><td>${escape(e.port)}</td><td>${escape(JSON.stringify(e.attributes))}</td></tr>`).join('')}</table>` : ''}`;
    // The node as the document holds it when the field changes (a run may have read it again).
    const current = () => this.doc.nodes.find((n) => n.id === node.id);
    // Augmentation items (graph-format §3): their fields, their output port, added and removed.
    const items = () => {
      const n = current();
      if (n && !Array.isArray(n.augment)) n.augment = [];
      return n ? n.augment : null;
    };
    const tidy = () => {
      const n = current();
      if (n && n.augment && n.augment.length === 0) delete n.augment;
      this.write();
    };
    for (const input of box.querySelectorAll('[name=augment-field]')) {
      input.addEventListener('change', () => {
        const list = items();
        const item = list && list[Number(input.dataset.item)];
        if (!item) return;
        const value = input.dataset.field === 'out' ? input.value.trim() || undefined : typedValue(input.value);
        if (value === undefined) delete item[input.dataset.field];
        else item[input.dataset.field] = value;
        tidy();
      });
    }
    for (const button of box.querySelectorAll('[name=augment-remove]')) {
      button.addEventListener('click', () => {
        const list = items();
        if (list) list.splice(Number(button.dataset.item), 1);
        tidy();
      });
    }
    for (const button of box.querySelectorAll('[name=augment-add]')) {
      button.addEventListener('click', () => {
        const list = items();
        if (!list) return;
        const item = type.augments.length > 1 ? { kind: button.dataset.kind } : {};
        const spec = type.augments.find((a) => a.kind === button.dataset.kind);
        for (const f of spec.fields) {
          if (f.default === undefined && startingValue(f) !== undefined) item[f.name] = startingValue(f);
        }
        list.push(item);
        tidy();
      });
    }
    for (const input of box.querySelectorAll('[name=mapping]')) {
      input.addEventListener('change', () => {
        const n = current();
        if (!n) return;
        const next = { ...(n.attributes || {}) };
        if (input.value.trim()) next[input.dataset.write] = input.value.trim();
        else delete next[input.dataset.write];
        if (Object.keys(next).length) n.attributes = next;
        else delete n.attributes;
        this.write();
      });
    }
    for (const input of box.querySelectorAll('[name=param]')) {
      input.addEventListener('input', () => this.checkTyped(node.id, input));
      input.addEventListener('change', () => {
        const n = current();
        if (!n) return;
        const value = typedValue(input.value);
        const next = { ...(n.params || {}) };
        if (value === undefined) delete next[input.dataset.param];
        else next[input.dataset.param] = value;
        n.params = next;
        this.write();
      });
    }
  }

  // A parameter checked as it is typed, before it is applied: the document with the field's text
  // goes to the checker, and an error on the node's line marks the field with its message.
  checkTyped(id, input) {
    const asked = (this.typedChecks = (this.typedChecks || 0) + 1);
    clearTimeout(this.typedTimer);
    this.typedTimer = setTimeout(async () => {
      const n = this.doc.nodes.find((x) => x.id === id);
      if (!n) return;
      const params = n.params;
      const value = typedValue(input.value);
      n.params = { ...(params || {}) };
      if (value === undefined) delete n.params[input.dataset.param];
      else n.params[input.dataset.param] = value;
      const text = graphText(this.root);
      n.params = params;
      const pattern = new RegExp(`"id"\\s*:\\s*"${id}"`);
      const line = text.split('\n').findIndex((l) => pattern.test(l)) + 1;
      let errors = [];
      try {
        errors = (await this.host.check(text)).filter((d) => d.severity === 'error' && d.line === line);
      } catch {
        return; // the next keystroke asks again
      }
      if (asked !== this.typedChecks || !input.isConnected) return;
      input.classList.toggle('invalid', errors.length > 0);
      input.title = errors.map((d) => `${d.code}: ${d.message}`).join('\n');
      const said = input.closest('.graph-params') && input.closest('.graph-params').querySelector('.graph-typed');
      if (said) said.textContent = errors.length ? `${errors[0].code}: ${errors[0].message}` : '';
    }, 150);
  }

  // The node's augmentation items as rows of fields (and `out` where items make ports), with a
  // button to add an item of each kind.
  augmentsHtml(type, node) {
    const items = Array.isArray(node.augment) ? node.augment : [];
    const rows = items.map((item, i) => {
      const kind = item.kind || type.augments[0].kind;
      const spec = type.augments.find((a) => a.kind === kind) || type.augments[0];
      const fields = spec.fields.map((f) => `
        <label title="${escape(f.type)}">${escape(f.name)}
          <input name="augment-field" data-item="${i}" data-field="${escape(f.name)}" value="${escape(shownValue(item[f.name]))}" size="8"></label>`).join('');
      const out = spec.makes_ports ? `<label title="the output port it feeds (items sharing it share a port)">out
          <input name="augment-field" data-item="${i}" data-field="out" value="${escape(item.out ?? '')}" placeholder="${escape(`${kind}${i}`)}" size="8"></label>` : '';
      return `<div class="graph-augment"><i>${escape(kind)} ${i}</i>${fields}${out}
        <button type="button" name="augment-remove" data-item="${i}" title="remove the item">×</button></div>`;
    }).join('');
    const adds = type.augments.map((a) => `<button type="button" name="augment-add" data-kind="${escape(a.kind)}">+ ${escape(a.kind)}</button>`).join(' ');
    return `<div class="graph-doc">augmentations (in priority order):</div>${rows}${adds}`;
  }

  // With no node selected: the graph's own fields, its parameters and attributes (§6, §7) as JSON.
  renderGraphFields(box) {
    const field = (name, title) => `
      <label class="graph-field" title="${escape(title)}"><span>${name}</span>
        <textarea name="graph-${name}" rows="3" spellcheck="false">${escape(JSON.stringify(this.doc[name] || {}))}</textarea></label>`;
    box.innerHTML = `
      <i>click a node to edit it; drag from an output port to an input port to connect; Delete removes
      the selection; Ctrl-C / Ctrl-V copy a node</i>
      ${field('parameters', 'graph parameters: name -> { type, default, min, max, doc }')}
      ${field('attributes', 'attributes entities may carry: name -> { type, default }')}`;
    for (const name of ['parameters', 'attributes']) {
      const area = box.querySelector(`[name=graph-${name}]`);
      area.addEventListener('change', () => {
        let value;
        try {
          value = JSON.parse(area.value || '{}');
        } catch (error) {
          this.message(`${name}: not JSON (${error.message})`);
          return;
        }
        if (value && typeof value === 'object' && Object.keys(value).length) this.doc[name] = value;
        else delete this.doc[name];
        this.write();
      });
    }
  }

  addNode(typeName) {
    const type = this.reference.nodes.find((t) => t.name === typeName);
    if (!type) {
      this.message(`no node type '${typeName}'`);
      return;
    }
    const id = freshId(this.doc, type.name);
    const node = { id, type: type.name };
    const params = startingParams(type);
    if (Object.keys(params).length) node.params = params;
    // The first free place of a grid three nodes wide.
    const free = (x, y) => this.doc.nodes.every((n) => Math.abs(n.ui.x - x) >= 150 || Math.abs(n.ui.y - y) >= 90);
    let k = 0;
    while (!free(20 + (k % 3) * 200, 20 + Math.floor(k / 3) * 110)) ++k;
    node.ui = { x: 20 + (k % 3) * 200, y: 20 + Math.floor(k / 3) * 110 };
    this.doc.nodes.push(node);
    this.selected = id;
    this.write();
    this.message(`added ${id}`);
  }

  // Connects `from` ('node.port') to `to` unless the checker finds an error in the new edge (a
  // type, a direction, a duplicate: its own message is shown and the graph stays as it was).
  async connect(from, to) {
    // The whole document with the edge added to the graph shown (it may be an inline subgraph).
    const graph = this.doc;
    const edges = graph.edges || [];
    const withEdge = [...edges, edgeText(from, to)];
    graph.edges = withEdge;
    const text = graphText(this.root);
    graph.edges = edges;
    const lines = text.split('\n');
    const line = lines.length - lines.slice().reverse().findIndex((l) => l.includes(JSON.stringify(edgeText(from, to)))) ;
    const fresh = (await this.host.check(text)).filter((d) => d.severity === 'error' && d.line === line);
    if (fresh.length) {
      this.message(`refused: ${fresh[0].code}: ${fresh[0].message}`);
      return false;
    }
    graph.edges = withEdge;
    this.write();
    this.message(`connected ${from} -> ${to}`);
    return true;
  }

  // The selected nodes into `<name>.graph.json` beside the open graph, saved; the graph keeps a
  // subgraph node in their place.
  async encapsulateSelection(name) {
    const ids = [...this.selection];
    if (ids.length === 0) {
      this.message('select nodes first (shift-click)');
      return;
    }
    if (!/^[A-Za-z_][A-Za-z0-9_]*$/.test(name) || this.doc.nodes.some((n) => n.id === name)) {
      this.message('the subgraph needs a name: letters, digits, _, not a node id already');
      return;
    }
    const file = `${name}.graph.json`;
    const { file: sub } = encapsulate(this.doc, ids, name, file);
    const path = this.subgraphFile({ type: 'subgraph', graph: file });
    try {
      await this.host.save(path, graphText(sub));
    } catch (error) {
      this.show(); // the document as the text still has it
      this.message(`not encapsulated: ${error.message || error}`);
      return;
    }
    this.gates.set(path, sub.gates);
    this.selection.clear();
    this.selected = name;
    this.write();
    this.message(`encapsulated ${ids.join(', ')} into ${path}`);
  }

  removeSelection() {
    if (this.selectedEdge !== undefined && this.selectedEdge !== null) {
      this.doc.edges.splice(this.selectedEdge, 1);
      this.selectedEdge = null;
      this.write();
    } else if (this.selected) {
      removeNode(this.doc, this.selected);
      this.selected = null;
      this.write();
    }
  }

  bindControls() {
    const on = (name, handler) => this.panel.querySelector(`[name=${name}]`).addEventListener('click', handler);
    on('add-node', () => { if (this.doc) this.addNode(this.panel.querySelector('[name=palette]').value.trim()); });
    this.panel.querySelector('[name=palette]').addEventListener('keydown', (e) => {
      if (e.key === 'Enter' && this.doc) this.addNode(e.target.value.trim());
    });
    on('layout', () => {
      if (!this.doc) return;
      this.doc.nodes.forEach((n) => { if (n.ui) { delete n.ui.x; delete n.ui.y; } });
      layout(this.doc, this.heightOf);
      this.write();
    });
    on('encapsulate', () => {
      if (this.doc) this.encapsulateSelection(this.panel.querySelector('[name=subgraph-name]').value.trim());
    });
    on('undo', () => this.host.undo());
    on('redo', () => this.host.redo());
    this.svg.addEventListener('keydown', (e) => {
      const key = e.key.toLowerCase();
      if (e.key === 'Delete' || e.key === 'Backspace') this.removeSelection();
      else if ((e.ctrlKey || e.metaKey) && key === 'z') (e.shiftKey ? this.host.redo() : this.host.undo());
      else if ((e.ctrlKey || e.metaKey) && key === 'y') this.host.redo();
      else if ((e.ctrlKey || e.metaKey) && key === 'c' && this.selected) {
        this.clipboard = JSON.parse(JSON.stringify(this.doc.nodes.find((n) => n.id === this.selected)));
        this.message(`copied ${this.selected}`);
      } else if ((e.ctrlKey || e.metaKey) && key === 'v' && this.clipboard && this.doc) {
        const copy = copyNode(this.doc, this.clipboard);
        this.doc.nodes.push(copy);
        this.selected = copy.id;
        this.write();
        this.message(`pasted ${copy.id}`);
      } else {
        return;
      }
      e.preventDefault();
    });
  }

  // Point of a mouse event in the canvas's coordinates (its viewBox, drawn at this.scale).
  point(event) {
    const box = this.svg.getBoundingClientRect();
    const scale = this.scale || 1;
    return [(event.clientX - box.left) / scale + (this.left || 0), (event.clientY - box.top) / scale];
  }

  bindCanvas() {
    this.svg.onmousedown = (event) => {
      const port = event.target.closest('.graph-port');
      const nodeEl = event.target.closest('.graph-node');
      const edgeEl = event.target.closest('.graph-edge');
      this.svg.focus();
      if (port && port.dataset.side === 'out') {
        this.dragWire(event, nodeEl.dataset.node, port.dataset.port);
      } else if (nodeEl && event.shiftKey) {
        const id = nodeEl.dataset.node;
        if (this.selection.has(id)) this.selection.delete(id);
        else this.selection.add(id);
        this.render();
      } else if (nodeEl) {
        this.selected = nodeEl.dataset.node;
        this.selection = new Set([this.selected]);
        this.selectedEdge = null;
        this.dragNode(event, nodeEl);
      } else if (edgeEl) {
        this.selectedEdge = Number(edgeEl.dataset.edge);
        this.selected = null;
        this.render();
      } else {
        this.selected = null;
        this.selection.clear();
        this.selectedEdge = null;
        this.render();
      }
    };
    // A subgraph opens in the studio (its own file: run and previewed alone, §8).
    this.svg.ondblclick = (event) => {
      const nodeEl = event.target.closest('.graph-node');
      const node = nodeEl && this.doc.nodes.find((n) => n.id === nodeEl.dataset.node);
      const file = node && this.subgraphFile(node);
      if (file) {
        this.trail = [...this.trail, this.host.path()];
        this.expecting = file;
        this.host.open(file);
      } else if (node && node.type === 'subgraph' && this.inline(String(node.graph).slice(1))) {
        // An inline subgraph: shown in place of its graph (the bar above leads back).
        this.scope = [...this.scope, { name: String(node.graph).slice(1), via: node.id }];
        this.selected = null;
        this.selection.clear();
        layout(this.doc, this.heightOf);
        this.render();
      }
    };
  }

  dragNode(event, element) {
    const node = this.doc.nodes.find((n) => n.id === element.dataset.node);
    const [sx, sy] = this.point(event);
    const [ox, oy] = [node.ui.x, node.ui.y];
    let moved = false;
    this.dragging = true;
    const move = (e) => {
      const [x, y] = this.point(e);
      if (!moved && Math.hypot(x - sx, y - sy) < 3) return;
      moved = true;
      node.ui = { ...node.ui, x: Math.max(0, Math.round(ox + x - sx)), y: Math.max(0, Math.round(oy + y - sy)) };
      element.setAttribute('transform', `translate(${node.ui.x - ox},${node.ui.y - oy})`);
    };
    const up = () => {
      window.removeEventListener('mousemove', move);
      window.removeEventListener('mouseup', up);
      this.dragging = false;
      if (moved) {
        this.write();
      } else {
        // A click: the selection marked on the nodes drawn (a redraw would lose a double-click).
        for (const g of this.svg.querySelectorAll('.graph-node')) {
          g.classList.toggle('selected', this.selection.has(g.dataset.node));
        }
        this.renderParams();
      }
    };
    window.addEventListener('mousemove', move);
    window.addEventListener('mouseup', up);
  }

  dragWire(event, nodeId, port) {
    const node = this.doc.nodes.find((n) => n.id === nodeId);
    const [x1, y1] = this.portAt(node, port, true);
    const wire = document.createElementNS(svgNs, 'path');
    wire.setAttribute('class', 'graph-edge wire');
    this.svg.append(wire);
    this.dragging = true;
    const move = (e) => {
      const [x2, y2] = this.point(e);
      wire.setAttribute('d', `M${x1},${y1} L${x2},${y2}`);
    };
    const up = (e) => {
      window.removeEventListener('mousemove', move);
      window.removeEventListener('mouseup', up);
      this.dragging = false;
      wire.remove();
      const target = document.elementFromPoint(e.clientX, e.clientY);
      const input = target && target.closest && target.closest('.graph-port.in');
      if (input) this.connect(`${nodeId}.${port}`, `${input.closest('.graph-node').dataset.node}.${input.dataset.port}`);
    };
    window.addEventListener('mousemove', move);
    window.addEventListener('mouseup', up);
  }
}
