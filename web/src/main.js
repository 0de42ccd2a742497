// The studio's page (docs/studio.md): the folder's files, an editor whose text is checked and built
// as it changes (diagnostics underlined at their line:column), and a 3D view of the last good
// build. Talks to `insula studio` through its API with the token the URL carries.
import { EditorView, basicSetup } from 'codemirror';
import { setDiagnostics, lintGutter } from '@codemirror/lint';
import { Compartment } from '@codemirror/state';
import { Viewport } from './viewport.js';
import { definitions, hoverHelp, languageFor } from './languages.js';
import { DrawingTool } from './draw.js';
import { GraphEditor } from './graph_editor.js';
import { redo, undo } from '@codemirror/commands';

const token = new URLSearchParams(location.search).get('token') || '';
// Grammars and programs are built; footprint files show their mass model (`insula mass`).
const editable = /\.(cga|bldg|lua|psm|graph\.json|geojson|osm)$/;
const lotFiles = /\.(geojson|osm)$/;
const buildDelayMs = 80; // a pause in typing; a newer edit also cancels the build in flight

const state = {
  path: null, // the open file
  saved: '', // its text as on disk
  sequence: 0, // edits made; an answer to an older one is dropped
  building: 0,
  lastBuild: null, // the last answer of /api/build
  probe: null, // the graph editor's selected node, whose output the view highlights
  probed: null, // what its last probe run found (read by the browser test)
  diagnostics: [],
};
window.studio = state; // read (and state.editor driven) by the browser test, tests/web/studio.mjs

// `wanted` says whether the answer is still needed (a build an edit has not superseded).
async function api(path, options = {}, wanted = () => true) {
  // 503: the server runs as many checks and builds as it allows (superseded ones may still be
  // stopping, slowly on a loaded machine); a moment later there is room. Asked again for as long
  // as the answer is wanted, up to a minute.
  const started = performance.now();
  for (;;) {
    const response = await fetch(path, {
      ...options,
      headers: { 'X-Insula-Token': token, ...(options.headers || {}) },
    });
    if (response.status === 503 && wanted() && performance.now() - started < 60000) {
      await new Promise((resolve) => setTimeout(resolve, 100));
      continue;
    }
    if (!response.ok) throw new Error(`${path}: ${response.status} ${await response.text()}`);
    return response;
  }
}

// A job (/api/build, /api/report) for as long as its answer is wanted. The server cancels a
// job when a newer one for the same file starts; a request that reached it late (a retry after a
// 503, a slow thread) can cancel a newer edit's job, so a cancelled answer that is still wanted is
// asked for again.
async function job(path, body, wanted) {
  for (;;) {
    const answer = await (await api(path, { method: 'POST', body }, wanted)).json();
    if (!answer.cancelled || !wanted()) return answer;
    await new Promise((resolve) => setTimeout(resolve, 50)); // a stopping server cancels every job
  }
}

const element = (id) => document.getElementById(id);
const setStatus = (text) => { element('status').textContent = text; };

const viewport = new Viewport(element('viewport'), (picked) => {
  element('picked').textContent = picked;
});
state.viewport = viewport; // read by the browser test

const language = new Compartment();
const help = new Compartment();
let reference = { operations: [], nodes: [] };

const editor = new EditorView({
  parent: element('editor'),
  extensions: [
    basicSetup,
    lintGutter(),
    language.of([]),
    help.of([]),
    definitions,
    EditorView.updateListener.of((update) => {
      if (update.docChanged) edited();
    }),
  ],
});

state.editor = editor;

function edited() {
  element('save').disabled = editor.state.doc.toString() === state.saved;
  const sequence = ++state.sequence;
  setTimeout(() => { if (sequence === state.sequence) build(sequence); }, buildDelayMs);
}

// The diagnostics of the open file as the editor's lint marks and as lines below.
function showDiagnostics(diagnostics) {
  state.diagnostics = diagnostics;
  const doc = editor.state.doc;
  const marks = [];
  for (const d of diagnostics) {
    if (d.file !== state.path || d.line < 1 || d.line > doc.lines) continue;
    const line = doc.line(d.line);
    const from = Math.min(line.from + Math.max(0, d.column - 1), line.to);
    const word = /^[\w."#]+/.exec(doc.sliceString(from, line.to));
    marks.push({ from, to: Math.max(from + (word ? word[0].length : 1), from), severity: d.severity,
                 message: `${d.code}: ${d.message}` });
  }
  editor.dispatch(setDiagnostics(editor.state, marks));
  const list = element('diagnostics');
  list.replaceChildren(...diagnostics.map((d) => {
    const row = document.createElement('div');
    row.className = d.severity;
    row.textContent = `${d.file}:${d.line}:${d.column}: ${d.severity}[${d.code}]: ${d.message}`;
    row.onclick = () => {
      if (d.file !== state.path || d.line > editor.state.doc.lines) return;
      const at = editor.state.doc.line(d.line).from + d.column - 1;
      editor.dispatch({ selection: { anchor: at }, scrollIntoView: true });
      editor.focus();
    };
    return row;
  }));
}

function buildQuery() {
  const query = new URLSearchParams({ path: state.path, seed: element('seed').value || '0' });
  if (element('lot').value) query.set('lot', element('lot').value);
  if (element('by-class').checked) query.set('colours', 'class');
  return query;
}

async function build(sequence) {
  if (!state.path) return;
  setStatus('building…');
  ++state.building;
  try {
    const started = performance.now();
    const text = editor.state.doc.toString();
    const current = () => sequence === state.sequence;
    // The graph editor's counts from a run without output, in parallel: they come before the
    // model is written (a city's GLB takes longer than its run).
    if (graphShown()) {
      job(`/api/report?${buildQuery()}`, text, current)
        .then((counts) => { if (sequence === state.sequence && counts.ok) showGraph(counts.report); })
        .catch(() => {});
    }
    const query = buildQuery();
    if (graphShown()) query.set('behind', '1'); // the report run above goes first
    const answer = await job(`/api/build?${query}`, text, current);
    if (sequence !== state.sequence || answer.cancelled) return; // a newer edit took over
    answer.sequence = sequence;
    showDiagnostics(answer.diagnostics);
    showGraph(answer.report);
    if (!answer.ok) {
      state.lastBuild = answer;
      const errors = answer.diagnostics.filter((d) => d.severity === 'error').length;
      setStatus(errors ? `${errors} error(s)` : `failed: ${answer.output.split('\n')[0]}`);
      return;
    }
    const answered = performance.now();
    const model = await (await api(answer.model)).arrayBuffer();
    if (sequence !== state.sequence) return;
    const fetched = performance.now();
    answer.objects = await viewport.show(model);
    answer.timings = { answer: Math.round(answered - started), fetch: Math.round(fetched - answered),
                       show: Math.round(performance.now() - fetched) };
    await showPlan(answer.plan);
    answer.ms = Math.round(performance.now() - started);
    state.lastBuild = answer; // once shown
    showCounts(answer.report, answer.objects, answer.ms);
    setStatus('built');
    if (state.probe && graphShown()) probe(state.probe); // the selected node's output, edited
  } catch (error) {
    if (sequence !== state.sequence) return;
    // Still an answer to this edit: what waits for the build of the last edit is not left waiting.
    state.lastBuild = { ok: false, sequence, error: String(error) };
    setStatus(String(error));
  } finally {
    --state.building;
  }
}

// The graph editor's selected node (`path`, "sub/node" inside an inline subgraph; null: none):
// what it made, from a run of the same text that writes that node's output entities instead of
// the results (`insula build --probe`), drawn over the faded model and listed in the panel.
async function probe(path) {
  state.probe = path;
  state.probed = null;
  const sequence = state.sequence;
  const wanted = () => state.probe === path && state.sequence === sequence;
  try {
    if (!path) {
      await viewport.highlight(null);
      return;
    }
    const query = buildQuery();
    query.set('probe', path);
    query.set('behind', '1'); // the next edit's counts go first
    const answer = await job(`/api/build?${query}`, editor.state.doc.toString(), wanted);
    if (!wanted() || answer.cancelled) return;
    const model = answer.ok ? await (await api(answer.model, {}, wanted)).arrayBuffer() : null;
    if (!wanted()) return;
    const meshes = await viewport.highlight(model);
    state.probed = { path, sequence, meshes, ok: answer.ok, entities: answer.ok ? answer.report.graph.entities || [] : [],
                     count: answer.ok ? answer.report.results : 0 };
    if (graphEditor) graphEditor.showProbe(state.probed);
  } catch (error) {
    if (wanted()) setStatus(String(error));
  }
}

// A .bldg building's floor plans (the command line's SVG, a panel per storey); a click on a room
// names it.
async function showPlan(url) {
  const panel = element('plan');
  if (!url) {
    panel.replaceChildren();
    return;
  }
  const text = await (await api(url)).text();
  const svg = new DOMParser().parseFromString(text, 'image/svg+xml').documentElement;
  svg.removeAttribute('width');
  svg.removeAttribute('height');
  panel.replaceChildren(document.importNode(svg, true));
  for (const room of panel.querySelectorAll('path[data-room]')) {
    room.addEventListener('click', () => {
      const name = room.dataset.room;
      if (state.connectFrom) {
        // The second room of a connection the drawing tool was asked for (right-click, connect).
        const from = state.connectFrom;
        state.connectFrom = null;
        const joined = state.drawing && state.drawing.connect(from, name);
        setStatus(joined ? `connected ${from} and ${name}` : `${from} and ${name}: no new door`);
        return;
      }
      element('picked').textContent = room.querySelector('title')?.textContent || name;
    });
    // Right-click: "connect" this room to the next one clicked, when the drawing tool shows the
    // open file (seed 000 §3.6).
    room.addEventListener('contextmenu', (event) => {
      if (!state.drawing || element('draw').hidden || state.drawing.path !== state.path) return;
      event.preventDefault();
      showRoomMenu(event.clientX, event.clientY, room.dataset.room);
    });
  }
}

// The plan's room menu while the drawing tool shows the open file: connect the room to the next
// one clicked, split it (a new room beside it), remove it.
function showRoomMenu(x, y, room) {
  const menu = element('menu');
  menu.style.left = `${x}px`;
  menu.style.top = `${y}px`;
  menu.hidden = false;
  menu.replaceChildren();
  const item = (name, text, action) => {
    const button = document.createElement('button');
    button.name = name;
    button.textContent = text;
    button.onclick = () => {
      menu.hidden = true;
      action();
    };
    menu.append(button);
  };
  item('connect', `connect ${room} to…`, () => {
    state.connectFrom = room;
    setStatus(`click the room to connect ${room} to`);
  });
  item('split', `split ${room}`, () => {
    if (!state.drawing.splitRoom(room)) setStatus(`${room} is not in the drawing`);
  });
  item('remove', `remove ${room}`, () => {
    if (!state.drawing.removeRoom(room)) setStatus(`${room} is the last room of its row`);
  });
  setTimeout(() => document.addEventListener('click', () => { menu.hidden = true; }, { once: true }), 0);
}

function showCounts(report, objects, ms) {
  const lines = [`${objects} objects, edit to view ${ms} ms`];
  for (const key of ['lots', 'buildings', 'terminals', 'storeys', 'rooms', 'results']) {
    const value = report && report[key];
    if (typeof value === 'number') lines.push(`${key}: ${value}`);
    if (Array.isArray(value)) lines.push(`${key}: ${value.length}`);
  }
  const seconds = (report && report.seconds) || {};
  for (const [stage, s] of Object.entries(seconds)) lines.push(`${stage}: ${(1000 * s).toFixed(0)} ms`);
  element('counts').textContent = lines.join('\n');
}

async function open(path) {
  const started = performance.now();
  const text = await (await api(`/api/file?path=${encodeURIComponent(path)}`)).text();
  state.openTimings = { fetch: Math.round(performance.now() - started) };
  state.path = path;
  state.saved = text;
  state.connectFrom = null; // a connection asked for in another file
  viewport.fitted = false;
  element('picked').textContent = '';
  element('current').textContent = path;
  for (const row of element('files').children) row.classList.toggle('open', row.dataset.path === path);
  editor.dispatch({
    changes: { from: 0, to: editor.state.doc.length, insert: text },
    effects: language.reconfigure(languageFor(path, reference)),
  });
  element('save').disabled = true;
  state.openTimings.editor = Math.round(performance.now() - started);
}

async function save() {
  const text = editor.state.doc.toString();
  await api(`/api/file?path=${encodeURIComponent(state.path)}`, { method: 'PUT', body: text });
  state.saved = text;
  element('save').disabled = true;
  element('current').textContent = state.path;
  setStatus(`saved ${state.path}`);
  await listFiles();
}

// Writes the current text's result into the folder's exports/ (the file list shows it).
async function exportResult() {
  const query = buildQuery();
  query.set('format', element('format').value);
  setStatus('exporting…');
  const answer = await (await api(`/api/export?${query}`, {
    method: 'POST', body: editor.state.doc.toString(),
  })).json();
  state.lastExport = answer;
  setStatus(answer.ok ? `wrote ${answer.files.join(', ')}` : 'export failed');
  if (answer.ok) await listFiles();
}

// `text` in the editor as the new file `path`, not yet saved (save keeps it); it builds as usual.
function openUnsaved(path, text) {
  const fresh = state.path !== path;
  state.path = path;
  state.saved = null; // not on disk yet
  element('current').textContent = `${path} (not saved)`;
  for (const row of element('files').children) row.classList.toggle('open', row.dataset.path === path);
  if (fresh) {
    element('picked').textContent = '';
    viewport.fitted = false;
  }
  editor.dispatch({
    changes: { from: 0, to: editor.state.doc.length, insert: text },
    effects: language.reconfigure(languageFor(path, reference)),
  });
  element('save').disabled = false;
}

// A stochastic building from the form and the seed: shown at once and opened in the editor under a
// name of its own, not yet saved (save keeps it).
async function randomBuilding() {
  const query = new URLSearchParams({ seed: element('seed').value || '0',
                                      shape: element('random-shape').value,
                                      parts: element('random-parts').value || '0' });
  const list = element('random-list').value.trim();
  if (list) query.set('room_list', list);
  else query.set('rooms', element('random-rooms').value.trim());
  setStatus('generating…');
  const answer = await (await api(`/api/random?${query}`, { method: 'POST' })).json();
  if (!answer.ok) {
    setStatus(`random: ${answer.output.split('\n')[0]}`);
    return;
  }
  openUnsaved(`random_${query.get('shape')}_${query.get('seed')}.bldg`, answer.bldg);
  state.lastRandom = answer;
}

async function listFiles() {
  const { folder, files } = await (await api('/api/files')).json();
  element('folder').textContent = folder;
  const rows = [];
  const lots = element('lot');
  const chosen = lots.value;
  lots.replaceChildren(new Option('(none)', ''));
  for (const f of files) {
    if (lotFiles.test(f.path)) lots.add(new Option(f.path, f.path));
    if (!editable.test(f.path)) continue;
    const row = document.createElement('div');
    row.textContent = f.path;
    row.dataset.path = f.path;
    row.classList.toggle('open', f.path === state.path);
    row.onclick = () => open(f.path);
    rows.push(row);
  }
  lots.value = chosen;
  element('files').replaceChildren(...rows);
}

// The graph editor, on the open .graph.json while its panel is shown.
let graphEditor = null;
const graphShown = () => graphEditor && !element('graph').hidden && /\.graph\.json$/.test(state.path || '');
function showGraph(report) {
  if (graphShown()) graphEditor.show(report);
}

function toggleGraph() {
  const panel = element('graph');
  panel.hidden = !panel.hidden;
  if (panel.hidden) {
    // No highlight without the editor: shown again with it.
    if (graphEditor) graphEditor.probePath = null;
    if (state.probe) probe(null);
    return;
  }
  if (!/\.graph\.json$/.test(state.path || '')) {
    panel.hidden = true;
    setStatus('the graph editor edits .graph.json files: open one first');
    return;
  }
  if (!graphEditor) {
    graphEditor = new GraphEditor(panel, reference, {
      text: () => editor.state.doc.toString(),
      setText: (text) => editor.dispatch({ changes: { from: 0, to: editor.state.doc.length, insert: text } }),
      check: async (text) => (await (await api(`/api/check?path=${encodeURIComponent(state.path)}`,
                                                 { method: 'POST', body: text })).json()).diagnostics,
      diagnostics: () => state.diagnostics.filter((d) => d.file === state.path),
      undo: () => undo(editor),
      redo: () => redo(editor),
      path: () => state.path,
      read: async (path) => (await api(`/api/file?path=${encodeURIComponent(path)}`)).text(),
      save: async (path, text) => {
        await api(`/api/file?path=${encodeURIComponent(path)}`, { method: 'PUT', body: text });
        await listFiles();
      },
      open: (path) => open(path).catch((error) => setStatus(String(error))),
      select: (path) => probe(path),
    });
    state.graph = graphEditor;
  }
  graphEditor.show(state.lastBuild && state.lastBuild.ok ? state.lastBuild.report : null);
}

async function start() {
  reference = await (await api('/api/reference')).json();
  editor.dispatch({ effects: help.reconfigure(hoverHelp(reference)) });
  await listFiles();
  element('save').onclick = save;
  element('export').onclick = () => exportResult().catch((error) => setStatus(String(error)));
  element('graph-toggle').onclick = toggleGraph;
  element('random-toggle').onclick = () => { element('random').hidden = !element('random').hidden; };
  let drawing = null;
  element('draw-toggle').onclick = () => {
    const panel = element('draw');
    panel.hidden = !panel.hidden;
    if (!panel.hidden && !drawing) {
      drawing = new DrawingTool(panel, (path, text) => {
        if (path === state.path) {
          // The open file, redrawn: its text changes as an edit would change it.
          editor.dispatch({ changes: { from: 0, to: editor.state.doc.length, insert: text } });
        } else {
          openUnsaved(path, text);
        }
      }, {
        // GeoJSON files at the top of the folder, where the drawing's own file is written.
        geojson: () => [...element('lot').options].map((o) => o.value)
          .filter((f) => f.endsWith('.geojson') && !f.includes('/')),
        read: async (file) => (await api(`/api/file?path=${encodeURIComponent(file)}`)).text(),
        parse: async (text, path) => (await api(`/api/drawing?path=${encodeURIComponent(path)}`,
                                                { method: 'POST', body: text })).json(),
      });
      state.drawing = drawing;
    }
    // An open .bldg the tool can show is drawn in it (else the tool says why not).
    if (!panel.hidden && state.path && /\.bldg$/.test(state.path)) {
      const shown = state.path;
      drawing.load(editor.state.doc.toString(), shown).then((why) => {
        setStatus(why ? `the drawing tool cannot show ${shown}: ${why}` : `drawing ${shown}`);
      }).catch((error) => setStatus(String(error)));
    }
  };
  element('random').onsubmit = (event) => {
    event.preventDefault();
    randomBuilding().catch((error) => setStatus(String(error)));
  };
  element('lot').onchange = () => {
    viewport.fitted = false; // other lots stand elsewhere
    edited();
  };
  element('seed').onchange = () => edited();
  element('cut').oninput = () => viewport.cut(Number(element('cut').value));
  element('roofs').onchange = () => viewport.showRoofs(element('roofs').checked);
  element('furniture').onchange = () => viewport.showFurniture(element('furniture').checked);
  element('by-class').onchange = () => edited();
  element('next-seed').onclick = () => {
    element('seed').value = String(Number(element('seed').value || 0) + 1);
    edited();
  };
  const wanted = new URLSearchParams(location.search).get('open');
  if (wanted) await open(wanted);
}

start().catch((error) => setStatus(String(error)));
