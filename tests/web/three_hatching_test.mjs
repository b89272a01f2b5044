// The three.js hatching plugin (integrations/three/hatching.mjs) against bakeplay: bakes the
// hatching example (pipelines/hatching/hatching.json applied to bakeshape's torus, with the threshold
// texture), renders it with `bakeplay render` and with the plugin in headless Chromium (WebGL2 in
// software, SwiftShader) at the same camera, light and size, per tone mode and light kind (the point
// and spot cases change the light of the scene already loaded, so the plugin's rebuild is exercised),
// and compares the 8-bit sRGB pictures. Fails when the generated shaders are stale, when Chromium offers
// no WebGL2, or when a pair differs by more than the tolerances below.
//   node tests/web/three_hatching_test.mjs --tools BUILD/tools [--tmp DIR] [--chromium PATH]
import { join } from 'node:path';
import { checkPrerequisites, finishInChromium, main, options, run, runAll, sourceDir } from './support.mjs';

const { tmp, chromium, tool } = options('three_hatching');

// The view both renderers get.
const size = [400, 300];
const eye = [1.2, 2.0, 3.2];
const target = [0, 0, 0];
const packageFile = 'torus-hatched.glb';

// Tolerances. RMSE over RGB in [0, 1]; `over` is the share of pixels with a channel off by more than
// THRESHOLD (support.mjs) 8-bit levels. Measured (SwiftShader against the native driver): blend 0.008 RMSE and
// 0.25% of pixels, scattered single pixels where a stroke edge or a mip level's weight falls a float
// rounding apart (the per-triangle values are computed in double precision on the CPU instead of in
// single precision in a geometry stage; everything else is the same). The threshold tone turns a
// texel from paper to ink over a darkness ramp of 0.02, so those roundings flip whole texels: 0.025
// RMSE and 0.55%, still isolated pixels. The tolerances leave about 2x headroom; a wrong light, frame
// or tone changes large areas (a mirrored light: RMSE above 0.1, more than 10% of pixels).
const standard = { rmse: 0.015, over: 0.006 };
const threshold = { rmse: 0.045, over: 0.012 };
// Cases: bakeplay's --light and --hatching-tone, and the same as the plugin's options.
const cases = [
  { name: 'blend-directional', light: '0.3,0.8,0.5', option: { direction: [0.3, 0.8, 0.5] }, tone: 'blend', tolerance: standard },
  { name: 'threshold-directional', light: '0.3,0.8,0.5', option: { direction: [0.3, 0.8, 0.5] }, tone: 'threshold', tolerance: threshold },
  { name: 'blend-point', light: 'point:1.5,1.2,2', option: { point: [1.5, 1.2, 2] }, tone: 'blend', tolerance: standard },
  { name: 'blend-spot', light: 'spot:0,0.5,3:0,-0.1,-1:25:2', tone: 'blend', tolerance: standard,
    option: { spot: [0, 0.5, 3], spotDirection: [0, -0.1, -1], cutoffDegrees: 25, exponent: 2 } },
];

main(async () => {
  const started = Date.now();
  checkPrerequisites({ tmp, chromium });

  // As Makefile.examples bakes the hatching example (without its placement).
  const mesh = join(tmp, 'torus.glb');
  run(tool('bakeshape'), ['torus', '-o', mesh, '-q']);
  run(tool('tambake'), [join(sourceDir, 'pipelines/hatching/hatching.json'), '-o', join(tmp, 'hatching.ktx2'),
    '--threshold', join(tmp, 'hatching-threshold.ktx2'), '--apply-to', mesh, '--package', join(tmp, packageFile), '-q']);

  await runAll(cases.map((c) => [tool('bakeplay'), ['render', join(tmp, packageFile), '--camera', `${eye.join(',')}:${target.join(',')}`,
    '--light', c.light, '--size', size.join('x'), '--hatching-tone', c.tone, '-q', '-o', join(tmp, `${c.name}.bakeplay.png`)]]));

  await finishInChromium({
    page: 'hatching_page', tmp, chromium, cases, size, label: 'case', width: 25, started,
    files: { [`/packages/${packageFile}`]: join(tmp, packageFile) },
    query: {
      file: packageFile,
      cases: JSON.stringify(cases.map((c) => ({ name: c.name, tone: c.tone, light: c.option }))),
      eye: eye.join(','), target: target.join(','), w: String(size[0]), h: String(size[1]),
    },
  });
});
