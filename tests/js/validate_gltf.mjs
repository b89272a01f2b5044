// Runs the Khronos glTF-Validator on one .glb/.gltf file and prints its report summary as JSON:
// {"numErrors": N, "numWarnings": N, "numUnallowedWarnings": N, "messages": ["CODE pointer: message", ...]}
// (errors and warnings; allowed warnings: gltf_allow.mjs).
import { readFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import validator from 'gltf-validator';
import { isAllowed, loadAllowList } from './gltf_allow.mjs';

const file = process.argv[2];
if (!file) {
  console.error('usage: node validate_gltf.mjs FILE');
  process.exit(1);
}
const report = await validator.validateBytes(new Uint8Array(readFileSync(file)), {
  uri: file,
  maxIssues: 0,  // unlimited
  externalResourceFunction: (uri) =>
    Promise.resolve(new Uint8Array(readFileSync(join(dirname(file), decodeURIComponent(uri))))),
});
const messages = report.issues.messages
  .filter((m) => m.severity <= 1)
  .map((m) => `${m.severity === 0 ? 'error' : 'warning'} ${m.code} ${m.pointer ?? ''}: ${m.message}`);
const allowed = loadAllowList();
console.log(JSON.stringify({
  numErrors: report.issues.numErrors,
  numWarnings: report.issues.numWarnings,
  numUnallowedWarnings: report.issues.messages.filter((m) => m.severity === 1 && !isAllowed(allowed, m)).length,
  messages,
}));
