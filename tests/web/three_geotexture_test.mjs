// The three.js GeoTextures plugin (integrations/three) against bakeplay: bakes a pretzel with three
// geodesic fields (float, plus unorm16 and model-unit variants that carry their own material),
// renders it per preset with `bakeplay render` and with the plugin in headless
// Chromium (WebGL2 in software, SwiftShader), at the same camera, light and size, and compares the
// 8-bit sRGB pictures. Fails when the generated shaders are stale, when Chromium offers no WebGL2,
// or when a pair differs by more than the tolerances below.
//   node tests/web/three_geotexture_test.mjs --tools BUILD/tools [--tmp DIR] [--chromium PATH]
import { join } from 'node:path';
import { checkPrerequisites, finishInChromium, main, options, run, runAll, sourceDir } from './support.mjs';

const { tmp, chromium, tool } = options('three_geotexture');

// The view both renderers get.
const size = [400, 300];
const eye = [2.4, 2.8, 6.2];
const target = [0, 0, 0];
const light = [0.3, 0.8, 0.5];

// Tolerances, per preset. RMSE over RGB in [0, 1]; `over` is the share of pixels with a channel off
// by more than THRESHOLD (support.mjs) 8-bit levels. Edges (a triangle's pixel coverage rule) and the last bits
// of float noise differ between SwiftShader and the native GL driver; anything else is a bug.
const standard = { rmse: 0.02, over: 0.015 };
const tolerances = {
  isolines: standard,
  'sand-water': standard,
  'moss-granite': standard,
  'paint-metal-rust': standard,
  'water-lava': standard,
  'opacity-front': standard,
  // WebGL2 has no tessellation: the plugin bumps the normal only, while bakeplay displaces the
  // surface, so silhouettes and crests move (docs/engines.md).
  'wave-displacement': { rmse: 0.06, over: 0.05 },
};
const presets = Object.keys(tolerances);
// Cases: every preset forced on the float package (as --geotexture), and the packages' own materials
// (written by geobake --geotexture) for the unorm16 encoding and for distances in model units.
const cases = [
  ...presets.map((preset) => ({ name: preset, file: 'pretzel-fields.glb', preset, tolerance: tolerances[preset] })),
  { name: 'unorm16-own-material', file: 'pretzel-unorm16.glb', preset: '', tolerance: standard },
  { name: 'model-units-own-material', file: 'pretzel-model-units.glb', preset: '', tolerance: standard },
];

main(async () => {
  const started = Date.now();
  checkPrerequisites({ tmp, chromium });

  const mesh = join(tmp, 'pretzel.glb'), fields = join(tmp, 'pretzel-fields.glb');
  run(tool('bakeshape'), ['pretzel', '--resolution', '48', '-o', mesh, '-q']);
  const sources = ['--sources', join(sourceDir, 'pipelines/geodesic/sources.json'), '-q'];
  run(tool('geobake'), [mesh, ...sources, '-o', fields]);
  run(tool('geobake'), [mesh, ...sources, '--encoding', 'unorm16', '--geotexture', 'sand-water', '-o', join(tmp, 'pretzel-unorm16.glb')]);
  run(tool('geobake'), [mesh, ...sources, '--normalize', 'none', '--geotexture', 'isolines', '-o', join(tmp, 'pretzel-model-units.glb')]);

  await runAll(cases.map((c) => [tool('bakeplay'), ['render', join(tmp, c.file), '--camera', `${eye.join(',')}:${target.join(',')}`,
    '--light', light.join(','), '--size', size.join('x'), ...(c.preset ? ['--geotexture', c.preset] : []), '-q',
    '-o', join(tmp, `${c.name}.bakeplay.png`)]]));

  await finishInChromium({
    page: 'page', tmp, chromium, cases, size, label: 'case', width: 25, started,
    files: Object.fromEntries(cases.map((c) => [`/packages/${c.file}`, join(tmp, c.file)])),
    query: {
      cases: cases.map((c) => `${c.name}:${c.file}:${c.preset}`).join(','), eye: eye.join(','), target: target.join(','), light: light.join(','),
      w: String(size[0]), h: String(size[1]),
    },
  });
});
