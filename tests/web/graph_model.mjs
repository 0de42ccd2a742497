// The graph editor's document model (web/src/graph_model.js) without a browser: encapsulation
// keeps what crossing edges say of themselves and the run's result; the layout survives cycles.
// Usage: node graph_model.mjs INSULA TMPDIR
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';

import { encapsulate, gatePorts, graphText, layout } from '../../web/src/graph_model.js';

const [insula, tmp] = process.argv.slice(2);
const failures = [];
const check = (ok, what) => { if (!ok) failures.push(what); };

// A disabled edge crossing the selection stays disabled once rewired to a gate.
const small = { nodes: [{ id: 'a', type: 'x' }, { id: 'b', type: 'y' }, { id: 'c', type: 'z' }],
                edges: ['a.out -> b.in', { from: 'b.out', to: 'c.in', enabled: false }] };
encapsulate(small, ['b'], 'sub', 'sub.graph.json');
check(JSON.stringify(small.edges) === '["a.out -> sub.b_in",{"from":"sub.b_out","to":"c.in","enabled":false}]',
      `rewired edges: ${JSON.stringify(small.edges)}`);

// A cycle (lot_subdivision's cut -> check) is laid out, every node placed once.
const cyclic = JSON.parse(fs.readFileSync(new URL('../../examples/graph/lot_subdivision.graph.json', import.meta.url)));
layout(cyclic);
check(cyclic.nodes.every((n) => Number.isFinite(n.ui.x) && Number.isFinite(n.ui.y)), 'a node without a place');

// The stairway's newel encapsulated: the same 17 result entities from the command line.
const fig4 = path.join(tmp, 'fig4.graph.json');
const doc = JSON.parse(fs.readFileSync(new URL('../../examples/graph/paper/fig4_stairway.graph.json', import.meta.url)));
const { file } = encapsulate(doc, ['newel', 'post'], 'newel_post', 'newel_post.graph.json');
fs.writeFileSync(path.join(tmp, 'newel_post.graph.json'), graphText(file));
fs.writeFileSync(fig4, graphText(doc));
const report = path.join(tmp, 'fig4.json');
const run = spawnSync(insula, ['build', fig4, '--report', report, '-q'], { encoding: 'utf8' });
check(run.status === 0 && JSON.parse(fs.readFileSync(report, 'utf8')).graph.leaves['stone.out'].count === 17,
      `the encapsulated stairway: ${run.stderr}`);

// Gates by internal port: one port or a list of them (the house's, and a joined output gate).
const house = JSON.parse(fs.readFileSync(new URL('../../examples/graph/parts/house.graph.json', import.meta.url)));
const houseGates = gatePorts(house.gates);
check([...houseGates.in.values()].length >= 1 && [...houseGates.out.values()].length >= 1,
      `the house's gates: ${JSON.stringify(house.gates)}`);
const joined = gatePorts({ inputs: { Lot: 'a.in' }, outputs: { Walls: ['b.out', 'c.rest'] } });
check(joined.in.get('a.in') === 'Lot' && joined.out.get('b.out') === 'Walls' && joined.out.get('c.rest') === 'Walls' &&
      joined.out.size === 2 && gatePorts(undefined).in.size === 0, 'gates of a list');

if (failures.length) {
  console.error(failures.join('\n'));
  process.exit(1);
}
console.log('graph model: encapsulation and layout checked');
