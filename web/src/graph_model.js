// The graph editor's model of a `.graph.json` document (seed 003; ../shared/docs/graph-format.md):
// the parsed file itself (every field kept, key order included), with what the editor needs on
// top: each node's ports (catalogue ports, augmentation ports, ports edges name), edges as
// from/to pairs, an automatic layout for nodes without `ui` positions, fresh node ids, and the
// text the editor writes back (one node and one edge per line, so diagnostics name a line).

// `"a.out -> b.in"` or `{ from, to, ... }` as { from: ['a', 'out'], to: ['b', 'in'] }.
export function edgeEnds(edge) {
  const [from, to] = typeof edge === 'string'
    ? edge.split('->').map((s) => s.trim())
    : [edge.from, edge.to];
  const split = (ref) => {
    const dot = String(ref ?? '').lastIndexOf('.');
    return dot < 0 ? [String(ref ?? ''), ''] : [ref.slice(0, dot), ref.slice(dot + 1)];
  };
  return { from: split(from), to: split(to) };
}

// The node type of `node` in the reference (`GET /api/reference`'s nodes), or null.
// A graph's gates (graph-format §8) by the internal port each names: { in, out }, maps from
// 'node.port' to the gate's name (a gate may name one port or a list of them).
export function gatePorts(gates) {
  const side = (named) => new Map(Object.entries(named || {}).flatMap(([gate, ports]) =>
    (Array.isArray(ports) ? ports : [ports]).map((port) => [String(port), gate])));
  return { in: side(gates && gates.inputs), out: side(gates && gates.outputs) };
}

export function nodeType(reference, node) {
  return reference.nodes.find((t) => t.name === node.type) || null;
}

// The ports of `node`: { inputs: [{name, type, collective}], outputs: [...] } from its type,
// its augmentations (graph-format §3: an item's `out`, else `<kind><i>`) and, for subgraphs or
// anything else the catalogue does not say, the ports its edges name.
export function portsOf(reference, doc, node) {
  const type = nodeType(reference, node);
  const inputs = type ? type.inputs.map((p) => ({ ...p })) : [];
  const outputs = type ? type.outputs.map((p) => ({ ...p })) : [];
  const add = (list, name, like = {}) => {
    if (name && !list.some((p) => p.name === name)) list.push({ name, type: like.type || 'T', collective: false });
  };
  if (type && Array.isArray(node.augment)) {
    const seen = {};
    node.augment.forEach((item) => {
      const kind = item.kind || (type.augments[0] && type.augments[0].kind);
      const spec = type.augments.find((a) => a.kind === kind);
      const i = (seen[kind] = (seen[kind] ?? -1) + 1);
      if (spec && spec.makes_ports) add(outputs, item.out || `${kind}${i}`, type.outputs[0]);
    });
  }
  if (node.type === 'subgraph' && typeof node.graph === 'string' && node.graph.startsWith('#')) {
    const gates = ((doc.subgraphs || {})[node.graph.slice(1)] || {}).gates || {};
    Object.keys(gates.inputs || {}).forEach((g) => add(inputs, g));
    Object.keys(gates.outputs || {}).forEach((g) => add(outputs, g));
  }
  for (const edge of doc.edges || []) {
    const { from, to } = edgeEnds(edge);
    if (from[0] === node.id) add(outputs, from[1]);
    if (to[0] === node.id) add(inputs, to[1]);
  }
  return { inputs, outputs };
}

// An id not used by any node of `doc`: the type's last word, then 2, 3, ...
export function freshId(doc, type) {
  const stem = (type.split('.').pop() || 'node').replace(/[^A-Za-z0-9_]/g, '_').replace(/^(?=\d)/, 'n');
  const used = new Set((doc.nodes || []).map((n) => n.id));
  let id = stem;
  for (let k = 2; used.has(id); ++k) id = `${stem}${k}`;
  return id;
}

// A starting value for a parameter or an augmentation field without a default (its first
// choice, 1 within its range, an empty string or list...), or undefined when none fits.
export function startingValue(p) {
  if (p.choices && p.choices.length) return p.choices[0];
  const value = { number: 1, integer: 1, bool: false, string: '', vec3: [0, 0, 0], list: [] }[p.type];
  return p.min !== undefined && typeof value === 'number' ? Math.max(value, p.min) : value;
}

// A value for each required parameter of a new node, so it starts valid where it can.
export function startingParams(type) {
  const params = {};
  for (const p of type.params) {
    if (p.default !== undefined) continue;
    const value = startingValue(p);
    if (value !== undefined) params[p.name] = value;
  }
  return params;
}

// Positions for nodes without `ui.x`/`ui.y`: a row per step of the longest path from the sources
// over the edges (cycles broken where a depth-first walk meets a node on its stack), side by side
// in file order within a row; rows keep long chains inside the editor's width.
// `heightOf(node)`: a node's drawn height (rows are as tall as their tallest node, plus a gap).
export function layout(doc, heightOf = () => 80, columnWidth = 200) {
  const nodes = doc.nodes || [];
  const next = new Map(nodes.map((n) => [n.id, []]));
  for (const edge of doc.edges || []) {
    const { from, to } = edgeEnds(edge);
    if (next.has(from[0]) && next.has(to[0]) && from[0] !== to[0]) next.get(from[0]).push(to[0]);
  }
  const order = [];
  const state = new Map();
  const visit = (id) => {
    if (state.get(id)) return;
    state.set(id, 1);
    for (const t of next.get(id)) if (state.get(t) !== 1) visit(t);
    state.set(id, 2);
    order.push(id);
  };
  nodes.forEach((n) => visit(n.id));
  order.reverse(); // a topological order of the graph without its back edges
  const position = new Map(order.map((id, i) => [id, i]));
  const column = new Map(nodes.map((n) => [n.id, 0]));
  for (const id of order) {
    for (const t of next.get(id)) {
      if (position.get(t) > position.get(id)) column.set(t, Math.max(column.get(t), column.get(id) + 1));
    }
  }
  const placed = nodes.filter((n) => !(n.ui && Number.isFinite(n.ui.x) && Number.isFinite(n.ui.y)));
  const tallest = [];
  for (const n of placed) {
    const row = column.get(n.id);
    tallest[row] = Math.max(tallest[row] || 0, heightOf(n));
  }
  const top = [];
  for (let row = 0, y = 20; row < tallest.length; ++row) {
    top[row] = y;
    y += (tallest[row] || 0) + 30;
  }
  const taken = new Map();
  for (const n of placed) {
    const row = column.get(n.id);
    const k = taken.get(row) || 0;
    taken.set(row, k + 1);
    n.ui = { ...(n.ui || {}), x: 20 + k * columnWidth, y: top[row] };
  }
  return doc;
}

// The document as text: top-level fields in their order, each node and each edge on a line of
// its own, other values on one line when short.
export function graphText(doc) {
  const lines = ['{'];
  const keys = Object.keys(doc);
  keys.forEach((key, k) => {
    const comma = k + 1 < keys.length ? ',' : '';
    const value = doc[key];
    if ((key === 'nodes' || key === 'edges') && Array.isArray(value)) {
      if (value.length === 0) {
        lines.push(`  ${JSON.stringify(key)}: []${comma}`);
        return;
      }
      lines.push(`  ${JSON.stringify(key)}: [`);
      value.forEach((item, i) => lines.push(`    ${JSON.stringify(item)}${i + 1 < value.length ? ',' : ''}`));
      lines.push(`  ]${comma}`);
      return;
    }
    const one = JSON.stringify(value);
    const text = one.length <= 100 ? one : JSON.stringify(value, null, 2).replace(/\n/g, '\n  ');
    lines.push(`  ${JSON.stringify(key)}: ${text}${comma}`);
  });
  lines.push('}');
  return `${lines.join('\n')}\n`;
}

// The edge `from` ('node.port') -> `to` as the file writes it.
export const edgeText = (from, to) => `${from} -> ${to}`;

// Removes node `id` and every edge touching it.
export function removeNode(doc, id) {
  doc.nodes = doc.nodes.filter((n) => n.id !== id);
  doc.edges = (doc.edges || []).filter((e) => {
    const { from, to } = edgeEnds(e);
    return from[0] !== id && to[0] !== id;
  });
}

// A copy of node `node` with a fresh id, moved by (dx, dy).
export function copyNode(doc, node, dx = 30, dy = 30) {
  const copy = JSON.parse(JSON.stringify(node));
  copy.id = freshId(doc, node.id.replace(/\d+$/, '') || node.type);
  copy.ui = { ...(copy.ui || {}), x: (node.ui?.x ?? 0) + dx, y: (node.ui?.y ?? 0) + dy };
  return copy;
}

// Encapsulates the nodes `ids` of `doc` into a subgraph file (seed 003 §3.7; graph-format §8):
// returns { file: the subgraph document, node: the subgraph node that replaces them } and
// rewrites `doc` (the nodes and their edges replaced by the node; edges crossing the selection
// rewired to its gates). Each crossing port becomes a gate named `<node>_<port>`. The subgraph
// declares the graph's parameters and attributes: the node passes every parameter through
// (`"= name"`) and maps every attribute to itself, so the run is the same as before.
export function encapsulate(doc, ids, name, graphPath) {
  const inside = new Set(ids);
  const gates = { inputs: {}, outputs: {} };
  const inner = [];
  const outer = [];
  const gateOf = ([node, port]) => `${node}_${port}`;
  // An edge rewired to a gate keeps its own fields (`enabled`, `ui`) when written as an object.
  const rewired = (edge, from, to) => (typeof edge === 'string' ? edgeText(from, to) : { ...edge, from, to });
  for (const edge of doc.edges || []) {
    const { from, to } = edgeEnds(edge);
    const [fromIn, toIn] = [inside.has(from[0]), inside.has(to[0])];
    if (fromIn && toIn) {
      inner.push(edge);
    } else if (toIn) {
      gates.inputs[gateOf(to)] = `${to[0]}.${to[1]}`;
      outer.push(rewired(edge, `${from[0]}.${from[1]}`, `${name}.${gateOf(to)}`));
    } else if (fromIn) {
      gates.outputs[gateOf(from)] = `${from[0]}.${from[1]}`;
      outer.push(rewired(edge, `${name}.${gateOf(from)}`, `${to[0]}.${to[1]}`));
    } else {
      outer.push(edge);
    }
  }
  const chosen = doc.nodes.filter((n) => inside.has(n.id));
  const file = { format: 'insula-graph', version: 1, name };
  if (doc.parameters) file.parameters = doc.parameters;
  if (doc.attributes) file.attributes = doc.attributes;
  file.nodes = chosen;
  file.edges = inner;
  file.gates = gates;
  const node = { id: name, type: 'subgraph', graph: graphPath };
  const parameters = Object.keys(doc.parameters || {});
  if (parameters.length) node.params = Object.fromEntries(parameters.map((p) => [p, `= ${p}`]));
  const attributes = Object.keys(doc.attributes || {});
  if (attributes.length) node.attributes = Object.fromEntries(attributes.map((a) => [a, a]));
  node.ui = { x: chosen[0]?.ui?.x ?? 20, y: chosen[0]?.ui?.y ?? 20 };
  doc.nodes = [...doc.nodes.filter((n) => !inside.has(n.id)), node];
  doc.edges = outer;
  return { file, node };
}
