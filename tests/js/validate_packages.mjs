#!/usr/bin/env node
// Runs the Khronos glTF-Validator (npm gltf-validator, pinned in package.json) offline on .glb/.gltf files.
//
//   node tests/js/validate_packages.mjs [--json OUT] [--allow FILE] [-q] FILE...
//
// Prints per file the counts of errors, warnings, infos and hints, then every error and warning as
// "  SEVERITY CODE POINTER: message". External resources (buffers, images) are read relative to the
// file's folder; data: URIs are decoded by the validator itself. --json OUT writes the full reports
// ({"validatorVersion", "reports": {FILE: report}}).
//
// Exit status: 0 when no file has an error or a warning the allow-list does not cover (default:
// gltf_allowed_warnings.json next to this script; see gltf_allow.mjs); 1 when some file fails; 2 on a
// usage error or an unreadable input or allow-list.
import { readFileSync, writeFileSync } from 'node:fs';
import { dirname, resolve, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import validator from 'gltf-validator';
import { isAllowed, loadAllowList } from './gltf_allow.mjs';

const here = dirname(fileURLToPath(import.meta.url));
const usage = 'usage: node validate_packages.mjs [--json OUT] [--allow FILE] [-q] FILE.glb|FILE.gltf...';

let jsonOut = null;
let allowFile = join(here, 'gltf_allowed_warnings.json');
let quiet = false;
const files = [];
const args = process.argv.slice(2);
for (let i = 0; i < args.length; i++) {
  const a = args[i];
  if (a === '--json' || a === '--allow') {
    if (i + 1 >= args.length) { console.error(`validate: ${a} needs a value\n${usage}`); process.exit(2); }
    if (a === '--json') jsonOut = args[++i]; else allowFile = args[++i];
  } else if (a === '-q' || a === '--quiet') {
    quiet = true;
  } else if (a === '-h' || a === '--help') {
    console.log(usage); process.exit(0);
  } else if (a === '--') {
    files.push(...args.slice(i + 1)); break;
  } else if (a.startsWith('-')) {
    console.error(`validate: unknown option ${a}\n${usage}`); process.exit(2);
  } else {
    files.push(a);
  }
}
if (files.length === 0) { console.error(usage); process.exit(2); }

let allowed;
try {
  allowed = loadAllowList(allowFile);
} catch (e) {
  console.error(`validate: ${e.message}`); process.exit(2);
}

const SEVERITY = ['error', 'warning', 'info', 'hint'];
const reports = {};
let failed = 0;
let unreadable = 0;

for (const file of files) {
  let bytes;
  try {
    bytes = new Uint8Array(readFileSync(file));
  } catch (e) {
    console.error(`validate: ${file}: ${e.message}`); unreadable++; continue;
  }
  const folder = dirname(resolve(file));
  let report;
  try {
    report = await validator.validateBytes(bytes, {
      uri: file,
      format: file.toLowerCase().endsWith('.glb') ? 'glb' : file.toLowerCase().endsWith('.gltf') ? 'gltf' : undefined,
      maxIssues: 0, // unlimited
      externalResourceFunction: (uri) => {
        // Only plain relative references: no scheme (http:, file:), no absolute path.
        if (/^[a-zA-Z][a-zA-Z0-9+.-]*:/.test(uri) || uri.startsWith('/')) {
          return Promise.reject(new Error(`not a relative URI: ${uri}`));
        }
        try {
          return Promise.resolve(new Uint8Array(readFileSync(resolve(folder, decodeURIComponent(uri)))));
        } catch (e) {
          return Promise.reject(e);
        }
      },
    });
  } catch (e) {
    console.error(`validate: ${file}: the validator failed: ${e?.message ?? e}`); unreadable++; continue;
  }
  reports[file] = report;
  const { numErrors, numWarnings, numInfos, numHints, messages } = report.issues;
  const blocking = messages.filter((m) => m.severity === 0 || (m.severity === 1 && !isAllowed(allowed, m)));
  const bad = numErrors > 0 || blocking.length > 0;
  if (bad) failed++;
  console.log(`${bad ? 'FAIL' : 'ok  '} ${file}: ${numErrors} errors, ${numWarnings} warnings, ${numInfos} infos, ${numHints} hints`);
  if (quiet && !bad) continue;
  for (const m of messages) {
    if (m.severity > 1) continue;
    const allowedTag = isAllowed(allowed, m) ? ' (allowed)' : '';
    const where = m.pointer ?? (m.offset !== undefined ? `@${m.offset}` : '');
    console.log(`  ${SEVERITY[m.severity]} ${m.code} ${where}: ${m.message}${allowedTag}`);
  }
}

if (jsonOut) {
  writeFileSync(jsonOut, JSON.stringify({ validatorVersion: validator.version(), reports }, null, 2) + '\n');
}
if (files.length > 1) {
  console.log(`validate: ${files.length - failed - unreadable} passed, ${failed} failed, ${unreadable} unreadable (gltf-validator ${validator.version()})`);
}
process.exit(unreadable ? 2 : failed ? 1 : 0);
