#!/usr/bin/env node
// Validates CityJSON 2.0 files against the CityJSON 2.0.2 JSON schemas with ajv (draft-07).
// Usage: node tools/validate_cityjson.mjs [--schema-dir DIR] FILE...
// The schema folder: see tools/cityjson_schemas.mjs. cityjson.min.schema.json is the root.
// Exit status: 0 when every file is valid, 1 otherwise (errors are printed), 2 on usage error.
import { loadJson, makeValidators, parseArguments } from './cityjson_schemas.mjs';

const { schemaDir, files } = parseArguments(process.argv.slice(2));
if (files.length === 0 || !schemaDir) {
  console.error('usage: node validate_cityjson.mjs [--schema-dir DIR] FILE.city.json...');
  process.exit(2);
}

const [validate] = makeValidators(schemaDir, ['cityjson.min.schema.json']);
let ok = true;
for (const file of files) {
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
