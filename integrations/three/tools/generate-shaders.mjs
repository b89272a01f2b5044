// Builds generated/{geotexture,hatching,revolution}-shaders.mjs from the project's GLSL (shaders/), so
// the three.js plugins draw with the very shaders bakeplay compiles. Steps: resolve `#include`
// (relative to the including file; `common/...` relative to shaders/), each file once (they carry
// include guards), then adapt desktop GLSL 4.x to GLSL ES 3.00: precision qualifiers (samplers too),
// no uniform default initialisers, no texture bindings, textureQueryLevels as a uniform, attributes as
// plain `in` under the names three.js binds. Hatching takes the fragment stage only (hatching.mjs
// replaces the geometry stage).
// The `#version 300 es` line is left to three.js (glslVersion: THREE.GLSL3).
//   node tools/generate-shaders.mjs          write the module
//   node tools/generate-shaders.mjs --check  exit 1 when the committed module is out of date
import { readFileSync, writeFileSync } from 'node:fs';
import { dirname, join, relative, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const packageDir = resolve(here, '..');
const shadersDir = resolve(packageDir, '../../shaders');
const outputPath = join(packageDir, 'generated/geotexture-shaders.mjs');
// Hatching: the fragment stage only; WebGL2 has no geometry stage, so hatching.mjs computes what
// hatching.geom computes on the CPU and feeds it through its own small vertex shader.
const hatchingOutputPath = join(packageDir, 'generated/hatching-shaders.mjs');

// three.js binds geometry attributes by name: POSITION -> position, NORMAL -> normal; the plugin
// aliases each field slot's attribute as aField<slot>, so those names stay.
const attributeNames = { aPosition: 'position', aNormal: 'normal' };

function resolveInclude(name, fromFile) {
  if (name.startsWith('common/')) return join(shadersDir, name);
  return join(dirname(fromFile), name);
}

// Inlines includes depth first; `used` collects every file read, in order.
function expand(file, seen, used) {
  if (seen.has(file)) return `// (${relative(shadersDir, file)} already included)\n`;
  seen.add(file);
  used.push(relative(shadersDir, file));
  const lines = readFileSync(file, 'utf8').split('\n');
  const out = [];
  for (const line of lines) {
    const include = line.match(/^\s*#\s*include\s+"([^"]+)"\s*$/);
    if (include) {
      const target = resolveInclude(include[1], file);
      out.push(`// ---- ${relative(shadersDir, target)}`);
      out.push(expand(target, seen, used).replace(/\n$/, ''));
      out.push(`// ---- end of ${relative(shadersDir, target)}`);
    } else {
      out.push(line);
    }
  }
  return out.join('\n') + (out[out.length - 1] === '' ? '' : '\n');
}

function adaptToEs(source, stage) {
  let text = source;
  // GLSL ES 3.00 has no uniform initialisers; the plugin sets every uniform explicitly.
  text = text.replace(/^(\s*uniform\s+\w+\s+\w+(?:\[\d+\])?)\s*=[^;]*;/gm, '$1;');
  if (stage === 'vertex') {
    text = text.replace(/^\s*layout\s*\(\s*location\s*=\s*\d+\s*\)\s*in\s+/gm, 'in ');
    for (const [from, to] of Object.entries(attributeNames)) {
      text = text.replace(new RegExp(`\\b${from}\\b`, 'g'), to);
    }
  }
  // Texture units are the application's business in WebGL2 (three.js assigns them).
  text = text.replace(/layout\s*\(\s*binding\s*=\s*\d+\s*\)\s*uniform\s+/g, 'uniform ');
  // ES 3.00 has no textureQueryLevels: the level count becomes a uniform bakeLevels_<sampler>.
  const queried = [...new Set([...text.matchAll(/\btextureQueryLevels\s*\(\s*(\w+)\s*\)/g)].map((m) => m[1]))];
  for (const sampler of queried) {
    text = text.replace(new RegExp(`\\btextureQueryLevels\\s*\\(\\s*${sampler}\\s*\\)`, 'g'), `bakeLevels_${sampler}`);
    text = text.replace(new RegExp(`^(\\s*uniform\\s+\\w+\\s+${sampler}\\s*;.*)$`, 'm'), `$1\nuniform int bakeLevels_${sampler};`);
  }
  // Samplers without a default precision in ES 3.00 need one where they are used.
  const samplerPrecision = ['sampler2DArray', 'sampler3D', 'isampler2D', 'usampler2D']
    .filter((type) => new RegExp(`\\b${type}\\b`).test(text))
    .map((type) => `precision highp ${type};\n`).join('');
  // Integer hashes need 32-bit ints and the noises full float precision in both stages.
  return 'precision highp float;\nprecision highp int;\n' + samplerPrecision + text;
}

function build(stages = [
  ['vertexShader', 'vertex', join(shadersDir, 'geodesic/geotexture.vert')],
  ['fragmentShader', 'fragment', join(shadersDir, 'geodesic/geotexture.frag')],
]) {
  const allUsed = [];
  const parts = [];
  for (const [name, stage, file] of stages) {
    const used = [];
    const text = adaptToEs(expand(file, new Set(), used), stage);
    allUsed.push(...used.filter((u) => !allUsed.includes(u)));
    const literal = text.replace(/\\/g, '\\\\').replace(/`/g, '\\`').replace(/\$\{/g, '\\${');
    parts.push(`export const ${name} = \`${literal}\`;\n`);
  }
  const header = [
    '// GENERATED FILE, do not edit: run `node tools/generate-shaders.mjs` in integrations/three.',
    '// GLSL ES 3.00 adaptation of these files under shaders/:',
    ...allUsed.map((u) => `//   ${u}`),
    '',
  ].join('\n');
  return `${header}\nexport const sources = ${JSON.stringify(allUsed)};\n\n${parts.join('\n')}`;
}

const outputs = [
  [outputPath, build()],
  [hatchingOutputPath, build([['fragmentShader', 'fragment', join(shadersDir, 'hatching/hatching.frag')]])],
  // Revolution mapping: the ray march runs in the fragment stage; the vertex stage only places the box.
  [join(packageDir, 'generated/revolution-shaders.mjs'), build([
    ['vertexShader', 'vertex', join(shadersDir, 'revolution/revolution.vert')],
    ['fragmentShader', 'fragment', join(shadersDir, 'revolution/revolution.frag')],
  ])],
];
if (process.argv.includes('--check')) {
  let stale = false;
  for (const [path, generated] of outputs) {
    let committed = '';
    try {
      committed = readFileSync(path, 'utf8');
    } catch {
      // a missing file is out of date too
    }
    if (committed !== generated) {
      console.error(`${relative(process.cwd(), path)} is out of date with shaders/: run node tools/generate-shaders.mjs`);
      stale = true;
    }
  }
  if (stale) process.exit(1);
  console.log('generated shaders are up to date');
} else {
  for (const [path, generated] of outputs) {
    writeFileSync(path, generated);
    console.log(`wrote ${relative(process.cwd(), path)}`);
  }
}
