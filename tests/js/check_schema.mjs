// Validates a JSON file against a JSON Schema (draft-07) with Ajv and prints
// {"valid": bool, "errors": ["pointer: message", ...]}.
import { readFileSync } from 'node:fs';
import Ajv from 'ajv';
import addFormats from 'ajv-formats';

const [schemaPath, documentPath] = process.argv.slice(2);
if (!schemaPath || !documentPath) {
  console.error('usage: node check_schema.mjs SCHEMA.json DOCUMENT.json');
  process.exit(1);
}
const ajv = new Ajv({ allErrors: true, strict: true, allowUnionTypes: true });
addFormats(ajv);
const validate = ajv.compile(JSON.parse(readFileSync(schemaPath, 'utf8')));
const valid = validate(JSON.parse(readFileSync(documentPath, 'utf8')));
console.log(JSON.stringify({
  valid,
  errors: (validate.errors ?? []).map((e) => `${e.instancePath || '/'}: ${e.message}`),
}));
