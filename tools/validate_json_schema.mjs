#!/usr/bin/env node
// Validates JSON files against one JSON Schema with ajv (draft 2020-12 or draft-07, chosen by
// the schema's $schema). Used by tests/cli/cga_transform.sh for docs/cga-model.schema.json.
// Usage: node tools/validate_json_schema.mjs SCHEMA.json FILE.json...
// Exit status: 0 when every file is valid, 1 otherwise (errors are printed), 2 on usage error.
import fs from 'node:fs';
import Ajv from 'ajv';
import Ajv2020 from 'ajv/dist/2020.js';

const [schemaFile, ...files] = process.argv.slice(2);
if (!schemaFile || files.length === 0) {
  console.error('usage: node validate_json_schema.mjs SCHEMA.json FILE.json...');
  process.exit(2);
}

let schema;
try {
  schema = JSON.parse(fs.readFileSync(schemaFile, 'utf8'));
} catch (error) {
  console.error(`error: cannot read schema ${schemaFile}: ${error.message}`);
  process.exit(2);
}
const draft2020 = String(schema.$schema ?? '').includes('2020-12');
const ajv = draft2020 ? new Ajv2020({ allErrors: true, strict: true, allowUnionTypes: true })
                      : new Ajv({ allErrors: true, strict: true, allowUnionTypes: true });
let validate;
try {
  validate = ajv.compile(schema);
} catch (error) {
  console.error(`error: invalid schema ${schemaFile}: ${error.message}`);
  process.exit(2);
}

let ok = true;
for (const file of files) {
  let document;
  try {
    document = JSON.parse(fs.readFileSync(file, 'utf8'));
  } catch (error) {
    console.log(`${file}: error: cannot read JSON: ${error.message}`);
    ok = false;
    continue;
  }
  if (validate(document)) {
    console.log(`${file}: valid`);
    continue;
  }
  ok = false;
  for (const e of validate.errors.slice(0, 20)) {
    console.log(`${file}: error: ${e.instancePath || '/'} ${e.message} ${JSON.stringify(e.params)}`);
  }
}
process.exit(ok ? 0 : 1);
