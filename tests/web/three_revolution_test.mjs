// The three.js revolution mapping plugin (integrations/three/revolution.mjs) against bakeplay: bakes
// the example packages of Makefile.examples (vase, ring, plate: unorm16 shape maps, arc-length
// projection, base colour images, bump maps on the vase and ring; balusters: a grid of copies; knobs: a
// ring of copies; all self-shadowed), renders each with `bakeplay render` and with the plugin in
// headless Chromium (WebGL2 in software, SwiftShader) at the same camera, light and size, and compares
// the 8-bit sRGB pictures. Fails when the generated shaders are stale, when Chromium offers no WebGL2,
// or when a pair differs by more than the tolerances below.
//   node tests/web/three_revolution_test.mjs --tools BUILD/tools [--tmp DIR] [--chromium PATH] [--light X,Y,Z]
import { join } from 'node:path';
import { checkPrerequisites, finishInChromium, main, options, runAll, sourceDir } from './support.mjs';

const { arg, tmp, chromium, tool } = options('three_revolution');

// The light and size both renderers get; each package has its own view (they stand apart in the
// examples' scene). --light overrides the plugin's light only: a way to see the test fail.
const size = [320, 240];
const light = [0.3, 0.8, 0.5];
const pluginLight = arg('--light', light.join(',')).split(',').map(Number);

// Tolerances. RMSE over RGB in [0, 1]; `over` is the share of pixels with a channel off by more than
// THRESHOLD (support.mjs) 8-bit levels. What differs between SwiftShader and the native GL driver: silhouettes
// (where a ray grazes the solid the march's last sample decides, and a quad whose neighbour misses
// takes its texture level from meaningless derivatives, which drivers resolve differently) and one or
// two levels of texture filtering. Measured: RMSE at most 0.013, at most 0.2% of pixels over; anything
// more is a bug.
const standard = { rmse: 0.02, over: 0.005 };
const pipelines = join(sourceDir, 'pipelines/revolution');
// The example packages and their revolbake arguments (Makefile.examples).
const cases = [
  { name: 'vase', profile: 'vase.json', bake: ['--base-color', 'glaze.png', '--height-map', 'hammered.png', '--height-scale', '0.004'],
    eye: [0.9, 1.0, 1.6], target: [0, 0.45, 0], tolerance: standard },
  { name: 'ring', profile: 'ring.json', bake: ['--base-color', 'bands.png', '--height-map', 'knurl.png', '--height-scale', '0.003', '--position', '1.3,0,0'],
    eye: [2.3, 1.1, 1.3], target: [1.3, 0.22, 0], tolerance: standard },
  { name: 'plate', profile: 'plate.json', bake: ['--base-color', 'bands.png', '--position', '-1.6,0,0'],
    eye: [-0.6, 1.5, 2.0], target: [-1.6, 0.05, 0], tolerance: standard },
  { name: 'balusters', profile: 'baluster.json', bake: ['--grid', '5,1,1', '--grid-spacing', '0.55,0,0', '--position', '-1.1,0,-1.6'],
    eye: [0.8, 1.3, 0.9], target: [0.07, 0.45, -1.6], tolerance: standard },
  { name: 'knobs', profile: 'knob.json', bake: ['--ring', '8', '--position', '2.9,0,0.3'],
    eye: [3.8, 1.2, 1.8], target: [2.9, 0.15, 0.3], tolerance: standard },
  // Variants the examples leave out: the other encodings and projections, a mirrored grid, no shadows.
  { name: 'vase-float-cylindrical', profile: 'vase.json', bake: ['--encoding', 'float', '--projection', 'cylindrical', '--resolution', '512',
    '--base-color', 'glaze.png', '--height-map', 'hammered.png', '--height-scale', '0.004'],
  eye: [0.9, 1.0, 1.6], target: [0, 0.45, 0], tolerance: standard },
  { name: 'baluster-sqrt8-spherical-mirror', profile: 'baluster.json', bake: ['--encoding', 'sqrt8', '--projection', 'spherical', '--resolution', '512',
    '--base-color', 'bands.png', '--grid', '2,2,1', '--mirror', 'y', '--no-self-shadow'],
  eye: [1.4, 1.7, 3.4], target: [0.15, 0.95, 0], tolerance: standard },
];
const patterns = ['glaze', 'bands', 'hammered', 'knurl'];

main(async () => {
  const started = Date.now();
  checkPrerequisites({ tmp, chromium });

  await runAll(patterns.map((p) => [tool('bakeshape'), [p, '--resolution', '512', '-o', join(tmp, `${p}.png`), '-q']]));
  await runAll(cases.map((c) => [tool('revolbake'), [join(pipelines, c.profile), '-o', join(tmp, `${c.name}.glb`), '-q',
    ...c.bake.map((a) => (a.endsWith('.png') ? join(tmp, a) : a))]]));
  await runAll(cases.map((c) => [tool('bakeplay'), ['render', join(tmp, `${c.name}.glb`), '--camera', `${c.eye.join(',')}:${c.target.join(',')}`,
    '--light', light.join(','), '--size', size.join('x'), '-q', '-o', join(tmp, `${c.name}.bakeplay.png`)]]));

  await finishInChromium({
    page: 'revolution_page', tmp, chromium, cases, size, label: 'package', width: 32, started,
    files: Object.fromEntries(cases.map((c) => [`/packages/${c.name}.glb`, join(tmp, `${c.name}.glb`)])),
    query: {
      cases: JSON.stringify(cases.map((c) => ({ name: c.name, file: `${c.name}.glb`, eye: c.eye, target: c.target }))),
      light: pluginLight.join(','), w: String(size[0]), h: String(size[1]),
    },
  });
});
