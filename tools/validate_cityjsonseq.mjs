#!/usr/bin/env node
// Validates CityJSONSeq files (`.city.jsonl`, CityJSON 2.0 text sequences) with ajv (draft-07):
// line 1 against the CityJSON 2.0.2 schema (cityjson.min.schema.json, with no city objects and no
// vertices), every other line against cityjsonfeature.min.schema.json (the official CityJSONFeature
// schema with its $refs resolved). Also checks what the schemas cannot: every vertex index of a
// line is an integer below that line's vertex count, the feature's "id" is one of its city objects,
// city object ids are unique across the lines, lines end in LF (no CR) and none is empty.
// Usage: node tools/validate_cityjsonseq.mjs [--schema-dir DIR] FILE...
// The schema folder: see tools/cityjson_schemas.mjs.
// Prints FILE:LINE: message for each failure (at most 50 per file) and a summary line per valid
// file. Exit status: 0 when every file is valid, 1 otherwise, 2 on usage error.
import fs from 'node:fs';
import { makeValidators, parseArguments } from './cityjson_schemas.mjs';

const { schemaDir, files } = parseArguments(process.argv.slice(2));
if (files.length === 0 || !schemaDir) {
  console.error('usage: node validate_cityjsonseq.mjs [--schema-dir DIR] FILE.city.jsonl...');
  process.exit(2);
}

const [validateHeader, validateFeature] =
    makeValidators(schemaDir, ['cityjson.min.schema.json', 'cityjsonfeature.min.schema.json']);

// Every vertex index under a geometry's "boundaries" (nested arrays of integers).
function* indices(boundaries) {
  if (Array.isArray(boundaries)) {
    for (const item of boundaries) yield* indices(item);
  } else {
    yield boundaries;
  }
}

function checkFile(file) {
  const problems = [];
  const report = (line, message) => problems.push(`${file}:${line}: ${message}`);
  const schemaErrors = (line, errors) => {
    for (const error of errors.slice(0, 10)) {
      const hint = error.keyword === 'not' && error.instancePath === '' ?
          ' (a CityJSONFeature has no transform, version, metadata, geometry-templates or ' +
              'extensions: they belong to the first line)' :
          '';
      report(line, `${error.instancePath || '/'}: ${error.message}${hint}`);
    }
  };
  let text;
  try {
    text = fs.readFileSync(file, 'utf8');
  } catch (error) {
    report(0, `cannot read: ${error.message}`);
    return problems;
  }
  const lines = text.split('\n');
  if (lines[lines.length - 1] === '') {
    lines.pop();
  } else {
    report(lines.length, 'the last line does not end with a line feed');
  }
  if (lines.length === 0) {
    report(1, 'empty file: no CityJSON header line');
    return problems;
  }
  const ids = new Map();  // city object id -> line
  let objects = 0;
  let vertices = 0;
  lines.forEach((raw, i) => {
    const line = i + 1;
    if (raw.endsWith('\r')) report(line, 'ends with CR LF; lines end with LF');
    if (raw.trim() === '') {
      report(line, 'empty line');
      return;
    }
    let value;
    try {
      value = JSON.parse(raw);
    } catch (error) {
      report(line, `not JSON: ${error.message}`);
      return;
    }
    if (line === 1) {
      if (!validateHeader(value)) schemaErrors(line, validateHeader.errors);
      if (value?.type !== 'CityJSON') report(line, 'the first line must be a "CityJSON" object');
      if (Object.keys(value?.CityObjects ?? {}).length !== 0) {
        report(line, 'the header line must have no city objects');
      }
      if ((value?.vertices ?? []).length !== 0) report(line, 'the header line must have no vertices');
      if (!value?.transform) report(line, 'the header line has no "transform"');
      return;
    }
    if (!validateFeature(value)) {
      schemaErrors(line, validateFeature.errors);
      return;
    }
    const count = value.vertices.length;
    vertices += count;
    if (!(value.id in value.CityObjects)) {
      report(line, `the feature id "${value.id}" is none of its city objects`);
    }
    for (const [id, object] of Object.entries(value.CityObjects)) {
      ++objects;
      if (ids.has(id)) report(line, `city object id "${id}" already used on line ${ids.get(id)}`);
      else ids.set(id, line);
      (object.geometry ?? []).forEach((geometry, g) => {
        for (const index of indices(geometry.boundaries)) {
          if (!Number.isInteger(index) || index < 0 || index >= count) {
            report(line, `${id}: geometry ${g}: vertex index ${index} out of range (${count} ` +
                         'vertices on this line)');
            break;
          }
        }
      });
    }
  });
  if (problems.length === 0) {
    console.log(`${file}: valid CityJSONSeq (${lines.length - 1} features, ${objects} city ` +
                `objects, ${vertices} vertices)`);
  }
  return problems;
}

let ok = true;
for (const file of files) {
  const problems = checkFile(file);
  if (problems.length > 0) {
    ok = false;
    for (const problem of problems.slice(0, 50)) console.log(problem);
    if (problems.length > 50) console.log(`${file}: ${problems.length - 50} more problems`);
  }
}
process.exit(ok ? 0 : 1);
