#!/usr/bin/env node
// Validates CityJSON 2.0 files against the CityJSON 2.0.2 JSON schemas with ajv (draft-07).
// Usage: node tools/validate_cityjson.mjs [--schema-dir DIR] FILE...
// The schema folder defaults to $INSULA_CITYJSON_SCHEMA, else tools/schemas/cityjson-2.0.2 (a copy of
// the official CityJSON 2.0.2 schemas, so a fresh clone validates without anything beside it). cityjson.min.schema.json is the root;
// every other *.schema.json in the folder is registered by its $id so $refs between them resolve.
// Exit status: 0 when every file is valid, 1 otherwise (errors are printed), 2 on usage error.
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import Ajv from 'ajv';
import addFormats from 'ajv-formats';

const here = path.dirname(fileURLToPath(import.meta.url));
let args = process.argv.slice(2);
let schemaDir = process.env.INSULA_CITYJSON_SCHEMA ??
    path.resolve(here, 'schemas', 'cityjson-2.0.2');
if (args[0] === '--schema-dir') {
  schemaDir = args[1];
  args = args.slice(2);
}
if (args.length === 0 || !schemaDir) {
  console.error('usage: node validate_cityjson.mjs [--schema-dir DIR] FILE.city.json...');
  process.exit(2);
}

function loadJson(file) {
  return JSON.parse(fs.readFileSync(file, 'utf8'));
}

function makeValidator() {
  const rootFile = path.join(schemaDir, 'cityjson.min.schema.json');
  if (!fs.existsSync(rootFile)) {
    console.error(`error: CityJSON schema not found: ${rootFile}`);
    process.exit(2);
  }
  // strict: false because the CityJSON schemas keep their definitions as top-level keywords.
  const ajv = new Ajv({ allErrors: true, strict: false });
  addFormats(ajv);
  const root = loadJson(rootFile);
  for (const name of fs.readdirSync(schemaDir).sort()) {
    if (!name.endsWith('.json') || name === 'cityjson.min.schema.json') continue;
    const schema = loadJson(path.join(schemaDir, name));
    if (schema.$id && schema.$id !== root.$id && !ajv.getSchema(schema.$id)) ajv.addSchema(schema);
  }
  return ajv.compile(root);
}

const validate = makeValidator();
let ok = true;
for (const file of args) {
  let document;
  try {
    document = loadJson(file);
  } catch (error) {
    console.log(`${file}: error: cannot read JSON: ${error.message}`);
    ok = false;
    continue;
  }
  if (validate(document)) {
    const objects = Object.keys(document.CityObjects ?? {}).length;
    console.log(`${file}: valid CityJSON ${document.version} (${objects} city objects, ` +
                `${(document.vertices ?? []).length} vertices)`);
  } else {
    ok = false;
    console.log(`${file}: ${validate.errors.length} schema errors`);
    for (const error of validate.errors.slice(0, 50)) {
      console.log(`  ${error.instancePath || '/'}: ${error.message}`);
    }
  }
}
process.exit(ok ? 0 : 1);
