#!/usr/bin/env node
// Validates glTF 2.0 files (.glb or .gltf) with the Khronos glTF validator (npm gltf-validator).
// Usage: node tools/validate_gltf.mjs FILE...
// Prints one summary line per file and every error (warnings and infos are counted, errors are
// listed). Exit status: 0 when every file has 0 errors, 1 otherwise (also when a file cannot be
// read or is not glTF at all), 2 on usage error.
import fs from 'node:fs';
import path from 'node:path';
import validator from 'gltf-validator';

async function validateFile(file) {
  let bytes;
  try {
    bytes = new Uint8Array(fs.readFileSync(file));
  } catch (error) {
    console.log(`${file}: error: cannot read: ${error.message}`);
    return false;
  }
  let report;
  try {
    report = await validator.validateBytes(bytes, {
      uri: path.basename(file),
      maxIssues: 1000,
      externalResourceFunction: (uri) =>
        new Promise((resolve, reject) => {
          const resolved = path.resolve(path.dirname(file), decodeURIComponent(uri));
          fs.readFile(resolved, (error, data) => (error ? reject(error.toString()) : resolve(data)));
        }),
    });
  } catch (error) {
    console.log(`${file}: error: not a glTF asset: ${error}`);
    return false;
  }
  const issues = report.issues;
  console.log(`${file}: ${issues.numErrors} errors, ${issues.numWarnings} warnings, ` +
              `${issues.numInfos} infos, ${issues.numHints} hints`);
  for (const message of issues.messages) {
    if (message.severity === 0 || process.env.GLTF_VALIDATOR_VERBOSE) {
      const level = ['error', 'warning', 'info', 'hint'][message.severity] ?? 'issue';
      console.log(`  ${level} ${message.code} at ${message.pointer ?? '?'}: ${message.message}`);
    }
  }
  return issues.numErrors === 0;
}

const files = process.argv.slice(2);
if (files.length === 0) {
  console.error('usage: node validate_gltf.mjs FILE.glb|FILE.gltf...');
  process.exit(2);
}
let ok = true;
for (const file of files) ok = (await validateFile(file)) && ok;
process.exit(ok ? 0 : 1);
