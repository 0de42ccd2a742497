// The CityJSON 2.0.2 schemas for ajv, shared by tools/validate_cityjson.mjs and
// tools/validate_cityjsonseq.mjs. The schema folder defaults to $INSULA_CITYJSON_SCHEMA, else
// tools/schemas/cityjson-2.0.2 (a copy of the official CityJSON 2.0.2 schemas, CC0, so a fresh
// clone validates without anything beside it); `--schema-dir DIR` as the first arguments overrides
// both. Every *.json of the folder but the requested roots is registered by its $id, so $refs
// between them resolve.
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import Ajv from 'ajv';
import addFormats from 'ajv-formats';

const here = path.dirname(fileURLToPath(import.meta.url));

export function loadJson(file) {
  return JSON.parse(fs.readFileSync(file, 'utf8'));
}

// { schemaDir, files }: the schema folder and the remaining arguments.
export function parseArguments(argv) {
  let args = argv;
  let schemaDir = process.env.INSULA_CITYJSON_SCHEMA ??
      path.resolve(here, 'schemas', 'cityjson-2.0.2');
  if (args[0] === '--schema-dir') {
    schemaDir = args[1];
    args = args.slice(2);
  }
  return { schemaDir, files: args };
}

// One compiled validator per root file name of `schemaDir` (exits with status 2 when one is
// missing).
export function makeValidators(schemaDir, rootNames) {
  const roots = rootNames.map((name) => {
    const file = path.join(schemaDir, name);
    if (!fs.existsSync(file)) {
      console.error(`error: CityJSON schema not found: ${file}`);
      process.exit(2);
    }
    return loadJson(file);
  });
  // strict: false because the CityJSON schemas keep their definitions as top-level keywords.
  const ajv = new Ajv({ allErrors: true, strict: false });
  addFormats(ajv);
  const rootIds = new Set(roots.map((root) => root.$id));
  for (const name of fs.readdirSync(schemaDir).sort()) {
    if (!name.endsWith('.json') || rootNames.includes(name)) continue;
    const schema = loadJson(path.join(schemaDir, name));
    if (schema.$id && !rootIds.has(schema.$id) && !ajv.getSchema(schema.$id)) ajv.addSchema(schema);
  }
  return roots.map((root) => ajv.compile(root));
}
