// The three.js hatching plugin (integrations/three/hatching.mjs) against bakeplay: bakes the
// hatching example (pipelines/hatching/hatching.json applied to bakeshape's torus, with the threshold
// texture), renders it with `bakeplay render` and with the plugin in headless Chromium (WebGL2 in
// software, SwiftShader) at the same camera, light and size, per tone mode and light kind (the point
// and spot cases change the light of the scene already loaded, so the plugin's rebuild is exercised),
// and compares the 8-bit sRGB pictures. Fails when the generated shaders are stale, when Chromium offers
// no WebGL2, or when a pair differs by more than the tolerances below.
//   node tests/web/three_hatching_test.mjs --tools BUILD/tools [--tmp DIR] [--chromium PATH]
import { spawn, spawnSync } from 'node:child_process';
import { createReadStream, existsSync, mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { createServer } from 'node:http';
import { dirname, extname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { deflateSync, inflateSync } from 'node:zlib';

const here = dirname(fileURLToPath(import.meta.url));
const sourceDir = resolve(here, '../..');
const pluginDir = join(sourceDir, 'integrations/three');

const args = process.argv.slice(2);
const arg = (name, fallback) => {
  const i = args.indexOf(name);
  return i >= 0 && i + 1 < args.length ? args[i + 1] : fallback;
};
const toolsDir = resolve(arg('--tools', join(sourceDir, 'build/tools')));
const tmp = resolve(arg('--tmp', join(sourceDir, 'build/tests/tmp/three_hatching')));
const chromium = arg('--chromium', process.env.CHROMIUM ?? '/usr/bin/chromium');
const tool = (name) => join(toolsDir, name, name);

// The view both renderers get.
const size = [400, 300];
const eye = [1.2, 2.0, 3.2];
const target = [0, 0, 0];
const packageFile = 'torus-hatched.glb';

// Tolerances. RMSE over RGB in [0, 1]; `over` is the share of pixels with a channel off by more than
// THRESHOLD 8-bit levels. Measured (SwiftShader against the native driver): blend 0.008 RMSE and
// 0.25% of pixels, scattered single pixels where a stroke edge or a mip level's weight falls a float
// rounding apart (the per-triangle values are computed in double precision on the CPU instead of in
// single precision in a geometry stage; everything else is the same). The threshold tone turns a
// texel from paper to ink over a darkness ramp of 0.02, so those roundings flip whole texels: 0.025
// RMSE and 0.55%, still isolated pixels. The tolerances leave about 2x headroom; a wrong light, frame
// or tone changes large areas (a mirrored light: RMSE above 0.1, more than 10% of pixels).
const THRESHOLD = 16;
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

function run(command, argv) {
  const result = spawnSync(command, argv, { encoding: 'utf8' });
  if (result.status !== 0) {
    console.error(`${command} ${argv.join(' ')} failed (${result.status ?? result.signal}):\n${result.stdout}${result.stderr}`);
    process.exit(1);
  }
  return result.stdout;
}

// --- PNG, 8-bit RGB or RGBA, not interlaced (what bakeplay writes and what we write).
const crcTable = Array.from({ length: 256 }, (_, n) => {
  let c = n;
  for (let k = 0; k < 8; ++k) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
  return c >>> 0;
});
const crc32 = (buf) => {
  let c = 0xffffffff;
  for (const b of buf) c = crcTable[(c ^ b) & 0xff] ^ (c >>> 8);
  return (c ^ 0xffffffff) >>> 0;
};

function writePng(path, width, height, rgba) {
  const chunk = (type, data) => {
    const out = Buffer.alloc(12 + data.length);
    out.writeUInt32BE(data.length, 0);
    out.write(type, 4, 'latin1');
    data.copy(out, 8);
    out.writeUInt32BE(crc32(out.subarray(4, 8 + data.length)), 8 + data.length);
    return out;
  };
  const header = Buffer.alloc(13);
  header.writeUInt32BE(width, 0);
  header.writeUInt32BE(height, 4);
  header.set([8, 6, 0, 0, 0], 8);
  const raw = Buffer.alloc(height * (width * 4 + 1));
  for (let y = 0; y < height; ++y) raw.set(rgba.subarray(y * width * 4, (y + 1) * width * 4), y * (width * 4 + 1) + 1);
  writeFileSync(path, Buffer.concat([Buffer.from([137, 80, 78, 71, 13, 10, 26, 10]), chunk('IHDR', header),
    chunk('IDAT', deflateSync(raw)), chunk('IEND', Buffer.alloc(0))]));
}

function readPng(path) {
  const file = readFileSync(path);
  let offset = 8, width = 0, height = 0, channels = 0;
  const idat = [];
  while (offset < file.length) {
    const length = file.readUInt32BE(offset);
    const type = file.toString('latin1', offset + 4, offset + 8);
    const data = file.subarray(offset + 8, offset + 8 + length);
    if (type === 'IHDR') {
      width = data.readUInt32BE(0);
      height = data.readUInt32BE(4);
      if (data[8] !== 8 || data[12] !== 0 || ![2, 6].includes(data[9])) throw new Error(`${path}: unsupported PNG layout`);
      channels = data[9] === 6 ? 4 : 3;
    } else if (type === 'IDAT') {
      idat.push(data);
    }
    offset += 12 + length;
  }
  const raw = inflateSync(Buffer.concat(idat));
  const stride = width * channels;
  const pixels = Buffer.alloc(stride * height);
  for (let y = 0; y < height; ++y) {
    const filter = raw[y * (stride + 1)];
    const line = raw.subarray(y * (stride + 1) + 1, (y + 1) * (stride + 1));
    for (let x = 0; x < stride; ++x) {
      const a = x >= channels ? pixels[y * stride + x - channels] : 0;
      const b = y > 0 ? pixels[(y - 1) * stride + x] : 0;
      const c = x >= channels && y > 0 ? pixels[(y - 1) * stride + x - channels] : 0;
      let predictor = 0;
      if (filter === 1) predictor = a;
      else if (filter === 2) predictor = b;
      else if (filter === 3) predictor = (a + b) >> 1;
      else if (filter === 4) {
        const p = a + b - c, pa = Math.abs(p - a), pb = Math.abs(p - b), pc = Math.abs(p - c);
        predictor = pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
      }
      pixels[y * stride + x] = (line[x] + predictor) & 0xff;
    }
  }
  return { width, height, channels, pixels };
}

function compare(reference, rgba, diffPath) {
  const { width, height, channels, pixels } = reference;
  let sum = 0, max = 0, over = 0;
  const diff = Buffer.alloc(width * height * 4);
  for (let i = 0; i < width * height; ++i) {
    let worst = 0;
    for (let c = 0; c < 3; ++c) {
      const d = Math.abs(pixels[i * channels + c] - rgba[i * 4 + c]);
      sum += (d / 255) ** 2;
      worst = Math.max(worst, d);
    }
    max = Math.max(max, worst);
    if (worst > THRESHOLD) ++over;
    diff.set([Math.min(255, worst * 8), Math.min(255, worst * 8), Math.min(255, worst * 8), 255], i * 4);
  }
  writePng(diffPath, width, height, diff);
  return { rmse: Math.sqrt(sum / (width * height * 3)), max, over: over / (width * height) };
}

// --- Renders in Chromium: a tiny server hands out the page, three.js, the plugin and the package,
// and receives the frames.
async function renderInChromium() {
  const frames = new Map();
  const files = {
    '/hatching_page.html': join(here, 'hatching_page.html'),
    '/hatching_page.mjs': join(here, 'hatching_page.mjs'),
    [`/packages/${packageFile}`]: join(tmp, packageFile),
  };
  const types = { '.html': 'text/html', '.mjs': 'text/javascript', '.js': 'text/javascript', '.glb': 'model/gltf-binary' };
  let finish;
  const finished = new Promise((r) => { finish = r; });
  const server = createServer((request, response) => {
    const url = new URL(request.url, 'http://localhost');
    if (request.method === 'POST') {
      const parts = [];
      request.on('data', (d) => parts.push(d));
      request.on('end', () => {
        const body = Buffer.concat(parts);
        response.end();
        if (url.pathname === '/frame') frames.set(url.searchParams.get('case'), body);
        else if (url.pathname === '/log') console.log(`  page: ${body}`);
        else if (url.pathname === '/done') finish({ ok: true });
        else finish({ ok: false, reason: `${url.pathname.slice(1)}: ${body}` });
      });
      return;
    }
    let file = files[url.pathname];
    if (!file && url.pathname.startsWith('/three/')) file = join(pluginDir, 'node_modules/three', url.pathname.slice(7));
    if (!file && url.pathname.startsWith('/bake-three/')) file = join(pluginDir, url.pathname.slice(12));
    if (!file || file.includes('..') || !existsSync(file)) {
      response.writeHead(404);
      response.end();
      return;
    }
    response.writeHead(200, { 'content-type': types[extname(file)] ?? 'application/octet-stream' });
    createReadStream(file).pipe(response);
  });
  await new Promise((r) => server.listen(0, '127.0.0.1', r));
  const query = new URLSearchParams({
    file: packageFile,
    cases: JSON.stringify(cases.map((c) => ({ name: c.name, tone: c.tone, light: c.option }))),
    eye: eye.join(','), target: target.join(','), w: String(size[0]), h: String(size[1]),
  });
  const url = `http://127.0.0.1:${server.address().port}/hatching_page.html?${query}`;
  const profile = join(tmp, 'chromium-profile');
  mkdirSync(profile, { recursive: true });
  const browser = spawn(chromium, ['--headless', '--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
    '--ignore-gpu-blocklist', '--no-first-run', '--disable-extensions', '--mute-audio', `--user-data-dir=${profile}`, url],
  { stdio: ['ignore', 'ignore', 'pipe'], detached: true });
  let browserLog = '';
  browser.stderr.on('data', (d) => { browserLog += d; });
  browser.on('exit', (code) => finish({ ok: false, reason: `chromium exited (${code}) before the page finished\n${browserLog}` }));
  const timer = setTimeout(() => finish({ ok: false, reason: 'timed out after 150 s' }), 150000);
  const outcome = await finished;
  clearTimeout(timer);
  try { process.kill(-browser.pid, 'SIGKILL'); } catch { /* already gone */ }
  server.close();
  return { ...outcome, frames };
}

async function main() {
  const started = Date.now();
  mkdirSync(tmp, { recursive: true });
  // Missing prerequisites skip (exit 77, ctest's SKIP_RETURN_CODE) with the reason; a browser that
  // runs but offers no WebGL2 fails.
  if (!existsSync(join(pluginDir, 'node_modules/three/build/three.module.js'))) {
    console.error(`SKIP: three.js is not installed: run npm ci in ${pluginDir}`);
    process.exit(77);
  }
  if (!existsSync(chromium)) {
    console.error(`SKIP: no Chromium at ${chromium} (set --chromium or CHROMIUM)`);
    process.exit(77);
  }
  // The shaders the plugin ships must be the project's current GLSL.
  run(process.execPath, [join(pluginDir, 'tools/generate-shaders.mjs'), '--check']);

  // As Makefile.examples bakes the hatching example (without its placement).
  const mesh = join(tmp, 'torus.glb');
  run(tool('bakeshape'), ['torus', '-o', mesh, '-q']);
  run(tool('tambake'), [join(sourceDir, 'pipelines/hatching/hatching.json'), '-o', join(tmp, 'hatching.ktx2'),
    '--threshold', join(tmp, 'hatching-threshold.ktx2'), '--apply-to', mesh, '--package', join(tmp, packageFile), '-q']);

  // bakeplay, two at a time.
  const pending = [...cases];
  const renderOne = async () => {
    for (let c; (c = pending.shift());) {
      const argv = ['render', join(tmp, packageFile), '--camera', `${eye.join(',')}:${target.join(',')}`, '--light', c.light,
        '--size', size.join('x'), '--hatching-tone', c.tone, '-q', '-o', join(tmp, `${c.name}.bakeplay.png`)];
      await new Promise((done, fail) => {
        const child = spawn(tool('bakeplay'), argv, { stdio: ['ignore', 'inherit', 'inherit'] });
        child.on('exit', (code) => (code === 0 ? done() : fail(new Error(`bakeplay ${argv.join(' ')} failed (${code})`))));
      });
    }
  };
  await Promise.all([renderOne(), renderOne()]);

  const result = await renderInChromium();
  if (!result.ok) {
    console.error(`three.js render failed: ${result.reason}`);
    process.exit(1);
  }
  let failed = false;
  console.log(`case                      RMSE    max  >${THRESHOLD}/255   tolerance (RMSE, share)`);
  for (const { name, tolerance: t } of cases) {
    const frame = result.frames.get(name);
    if (!frame) {
      console.log(`${name}: no frame from the page`);
      failed = true;
      continue;
    }
    const rgba = new Uint8Array(frame);
    writePng(join(tmp, `${name}.three.png`), size[0], size[1], rgba);
    const reference = readPng(join(tmp, `${name}.bakeplay.png`));
    const m = compare(reference, rgba, join(tmp, `${name}.diff.png`));
    const ok = m.rmse <= t.rmse && m.over <= t.over;
    failed ||= !ok;
    console.log(`${name.padEnd(25)} ${m.rmse.toFixed(4)} ${String(m.max).padStart(4)}  ${(100 * m.over).toFixed(2).padStart(6)}%   ` +
      `(${t.rmse}, ${(100 * t.over).toFixed(1)}%) ${ok ? 'ok' : 'FAIL'}`);
  }
  console.log(`images in ${tmp}; ${((Date.now() - started) / 1000).toFixed(1)} s`);
  process.exit(failed ? 1 : 0);
}

main().catch((e) => {
  console.error(e);
  process.exit(1);
});
