// The allow-list of glTF-Validator warnings our packages may carry (gltf_allowed_warnings.json: CODE ->
// {pointer: regular expression, reason}): a warning is allowed when its code is listed and its JSON
// pointer matches. Errors are never allowed.
import { readFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));

export function loadAllowList(file = join(here, 'gltf_allowed_warnings.json')) {
  const list = JSON.parse(readFileSync(file, 'utf8'));
  if (list === null || typeof list !== 'object' || Array.isArray(list)) throw new Error(`${file}: not a JSON object`);
  const rules = {};
  for (const [code, rule] of Object.entries(list)) {
    if (typeof rule?.pointer !== 'string' || typeof rule?.reason !== 'string' || rule.reason.length === 0)
      throw new Error(`${file}: ${code} needs "pointer" (a regular expression) and a "reason"`);
    rules[code] = new RegExp(rule.pointer);
  }
  return rules;
}

export function isAllowed(rules, message) {
  return message.severity === 1 && message.code in rules && rules[message.code].test(message.pointer ?? '');
}
