#!/usr/bin/env node
// Validates glTF files with the Khronos glTF-Validator (npm gltf-validator, installed in
// tools/node_modules by scripts/install-deps.sh). Prints a summary per file and every message of
// severity error or warning; exits 1 if any file has an error or a warning, 2 on usage problems.
//   node tests/gltf/validate.js FILE.glb|FILE.gltf...
'use strict';
const fs = require('fs');
const path = require('path');

let validator;
try {
  validator = require(path.join(__dirname, '..', '..', 'tools', 'node_modules', 'gltf-validator'));
} catch (e) {
  console.error('gltf-validator is not installed: run scripts/install-deps.sh (npm install in tools/)');
  process.exit(2);
}

const SEVERITY = ['error', 'warning', 'info', 'hint'];

async function validate(file) {
  const bytes = new Uint8Array(fs.readFileSync(file));
  const dir = path.dirname(file);
  const report = await validator.validateBytes(bytes, {
    uri: path.basename(file),
    maxIssues: 100,
    externalResourceFunction: (uri) => new Promise((resolve, reject) => {
      fs.readFile(path.join(dir, decodeURIComponent(uri)), (err, data) => {
        if (err) reject(err.toString()); else resolve(new Uint8Array(data));
      });
    }),
  });
  const i = report.issues;
  console.log(`${file}: ${i.numErrors} errors, ${i.numWarnings} warnings, ${i.numInfos} infos, ` +
              `${i.numHints} hints`);
  for (const m of i.messages) {
    if (m.severity <= 1) {
      console.log(`  ${SEVERITY[m.severity]} ${m.code}: ${m.message} (${m.pointer || m.offset || ''})`);
    }
  }
  return i.numErrors === 0 && i.numWarnings === 0;
}

(async () => {
  const files = process.argv.slice(2);
  if (files.length === 0) {
    console.error('usage: validate.js FILE.glb|FILE.gltf...');
    process.exit(2);
  }
  let ok = true;
  for (const f of files) {
    try {
      ok = (await validate(f)) && ok;
    } catch (e) {
      console.log(`${f}: cannot validate: ${e}`);
      ok = false;
    }
  }
  process.exit(ok ? 0 : 1);
})();
