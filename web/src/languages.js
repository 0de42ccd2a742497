// What the editor knows of Insula's languages: highlighting per file type, hover help for shape
// operations (the shared registry) and graph node types (the catalogue), both from
// `GET /api/reference`, and go-to-definition (F12, or Ctrl/Cmd-click) for rules, symbols,
// attributes and functions.
import { StreamLanguage } from '@codemirror/language';
import { json } from '@codemirror/lang-json';
import { lua } from '@codemirror/legacy-modes/mode/lua';
import { EditorView, hoverTooltip, keymap } from '@codemirror/view';

const keywords = new Set([
  'attr', 'const', 'import', 'version', 'case', 'else', 'PRIORITY', 'true', 'false', 'and', 'or',
  'not', 'function', 'local', 'return', 'if', 'then', 'end', 'for', 'in', 'do', 'DEF', 'WHERE',
  'END', 'building', 'buildingpart', 'floor', 'divisions', 'room', 'door', 'entrance', 'stair',
]);

// CGA, .bldg and PLaSM: comments, strings, numbers, keywords, operations (from the registry) and
// Symbols (capitalised names, the rules' left-hand sides). Block comments are `/* */`, or PLaSM's
// `% ... %` (across lines; PLaSM has no line comments).
function ruleLanguage(operations, plasm) {
  const [open, close] = plasm ? ['%', '%'] : ['/*', '*/'];
  return StreamLanguage.define({
    startState: () => ({ block: false }),
    token(stream, state) {
      if (state.block) {
        if (stream.skipTo(close)) {
          stream.match(close);
          state.block = false;
        } else {
          stream.skipToEnd();
        }
        return 'comment';
      }
      if (stream.match(open)) {
        state.block = true;
        return 'comment';
      }
      if (!plasm && (stream.match('//') || stream.match('#'))) {
        stream.skipToEnd();
        return 'comment';
      }
      if (stream.match(/^"(?:[^"\\]|\\.)*"?/)) return 'string';
      if (stream.match(/^-?\d+(\.\d+)?/)) return 'number';
      const word = stream.match(/^[A-Za-z_][\w.]*/);
      if (word) {
        const w = word[0];
        if (keywords.has(w)) return 'keyword';
        if (operations.has(w)) return 'builtin';
        if (/^[A-Z]/.test(w)) return 'typeName';
        return 'variableName';
      }
      if (stream.match(/^(-->|->|~>)/)) return 'operator';
      stream.next();
      return null;
    },
  });
}

export function languageFor(path, reference) {
  if (/\.(json|geojson)$/.test(path)) return json();
  if (/\.lua$/.test(path)) return StreamLanguage.define(lua);
  return ruleLanguage(new Set(reference.operations.map((o) => o.name)), /\.psm$/.test(path));
}

function wordAt(state, pos) {
  const line = state.doc.lineAt(pos);
  const text = line.text;
  let from = pos - line.from;
  let to = from;
  while (from > 0 && /[\w.]/.test(text[from - 1])) --from;
  while (to < text.length && /[\w.]/.test(text[to])) ++to;
  if (from === to) return null;
  return { word: text.slice(from, to), from: line.from + from, to: line.from + to };
}

function helpFor(word, reference) {
  const op = reference.operations.find((o) => o.name === word);
  if (op) {
    const params = op.params.map((p) => `${p.name}: ${p.type}${p.default !== undefined ? ` = ${p.default}` : ''}` +
                                        (p.doc ? ` (${p.doc})` : '')).join('\n  ');
    return `${op.name}: ${op.doc}${params ? `\n  ${params}` : ''}`;
  }
  const node = reference.nodes.find((n) => n.name === word);
  if (node) {
    const ports = (list) => list.map((p) => `${p.name}:${p.type}${p.collective ? '*' : ''}`).join(' ');
    return `${node.name} (${node.category}): ${node.doc}\n  ${ports(node.inputs)} -> ${ports(node.outputs)}` +
           (node.params.length ? `\n  params: ${node.params.map((q) => q.name).join(', ')}` : '');
  }
  return null;
}

export function hoverHelp(reference) {
  return hoverTooltip((view, pos) => {
    const at = wordAt(view.state, pos);
    const help = at && helpFor(at.word, reference);
    if (!help) return null;
    return {
      pos: at.from,
      end: at.to,
      above: true,
      create() {
        const dom = document.createElement('div');
        dom.className = 'help';
        dom.textContent = help;
        return { dom };
      },
    };
  });
}

// Where `name` is defined in `text`: a rule's left-hand side (`Name -->`, `Name ~>`, `label: Name
// ~>`, `name ->`), an attribute or constant, a function (Lua, PLaSM DEF), a graph node id.
export function definitionOf(text, name) {
  const n = name.replace(/[.*+?^${}()|[\]\\]/g, '\\$&');
  const patterns = [
    new RegExp(`^\\s*(\\w+\\s*:\\s*)?${n}\\s*(\\([^)]*\\))?\\s*(-->|->|~>)`, 'm'),
    new RegExp(`^\\s*(attr|const)\\s+${n}\\b`, 'm'),
    new RegExp(`\\bfunction\\s+${n}\\b`, 'm'),
    new RegExp(`^\\s*DEF\\s+${n}\\b`, 'm'),
    new RegExp(`"id"\\s*:\\s*"${n}"`, 'm'),
  ];
  for (const pattern of patterns) {
    const m = pattern.exec(text);
    if (m) return m.index + m[0].indexOf(name, m[0].search(/\S/) + (m[1] ? m[1].length : 0));
  }
  return -1;
}

function goToDefinition(view, pos) {
  const at = wordAt(view.state, pos);
  if (!at) return false;
  const target = definitionOf(view.state.doc.toString(), at.word);
  if (target < 0 || (target >= at.from && target <= at.to)) return false;
  view.dispatch({ selection: { anchor: target, head: target + at.word.length }, scrollIntoView: true });
  return true;
}

export const definitions = [
  keymap.of([{ key: 'F12', run: (view) => goToDefinition(view, view.state.selection.main.head) }]),
  EditorView.domEventHandlers({
    mousedown(event, view) {
      if (!(event.ctrlKey || event.metaKey)) return false;
      const pos = view.posAtCoords({ x: event.clientX, y: event.clientY });
      if (pos === null) return false;
      event.preventDefault();
      return goToDefinition(view, pos);
    },
  }),
];
