// What the three.js-against-bakeplay tests (tests/web/three_*_test.mjs) share: their command line,
// running tools, PNG files, the image comparison and its table, the local server and headless
// Chromium that render the plugin's side, and the skip checks. Each test keeps what it bakes, its
// cases, views and tolerances.
import { spawn, spawnSync } from 'node:child_process';
import { createReadStream, existsSync, mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { createServer } from 'node:http';
import { createRequire } from 'node:module';
import { dirname, extname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

export const here = dirname(fileURLToPath(import.meta.url));
export const sourceDir = resolve(here, '../..');
export const pluginDir = join(sourceDir, 'integrations/three');

// The plugin's package holds the tests' node modules (three.js, pngjs) as devDependencies.
const requireFromPlugin = createRequire(join(pluginDir, 'package.json'));

// Share of pixels counted as "over": a channel off by more than this many 8-bit levels.
export const THRESHOLD = 16;

// --tools, --tmp (default build/tests/tmp/<name>) and --chromium (or CHROMIUM), plus `arg` for a
// test's own options.
export function options(name) {
  const args = process.argv.slice(2);
  const arg = (option, fallback) => {
    const i = args.indexOf(option);
    return i >= 0 && i + 1 < args.length ? args[i + 1] : fallback;
  };
  const toolsDir = resolve(arg('--tools', join(sourceDir, 'build/tools')));
  return {
    arg,
    tmp: resolve(arg('--tmp', join(sourceDir, 'build/tests/tmp', name))),
    chromium: arg('--chromium', process.env.CHROMIUM ?? '/usr/bin/chromium'),
    tool: (tool) => join(toolsDir, tool, tool),
  };
}

export function run(command, argv) {
  const result = spawnSync(command, argv, { encoding: 'utf8' });
  if (result.status !== 0) {
    console.error(`${command} ${argv.join(' ')} failed (${result.status ?? result.signal}):\n${result.stdout}${result.stderr}`);
    process.exit(1);
  }
  return result.stdout;
}

// Runs [command, argv] pairs two at a time (the machine's cores); rejects on the first failure.
export async function runAll(commands) {
  const pending = [...commands];
  const worker = async () => {
    for (let c; (c = pending.shift());) {
      await new Promise((done, fail) => {
        const child = spawn(c[0], c[1], { stdio: ['ignore', 'inherit', 'inherit'] });
        child.on('exit', (code) => (code === 0 ? done() : fail(new Error(`${c[0]} ${c[1].join(' ')} failed (${code})`))));
      });
    }
  };
  await Promise.all([worker(), worker()]);
}

// Missing prerequisites skip (exit 77, ctest's SKIP_RETURN_CODE) with the reason; a browser that
// runs but offers no WebGL2 fails later. Then the shaders the plugin ships must be the project's
// current GLSL.
export function checkPrerequisites({ tmp, chromium }) {
  mkdirSync(tmp, { recursive: true });
  const modules = join(pluginDir, 'node_modules');
  if (!existsSync(join(modules, 'three/build/three.module.js')) || !existsSync(join(modules, 'pngjs/package.json'))) {
    console.error(`SKIP: three.js or pngjs is not installed: run npm ci in ${pluginDir}`);
    process.exit(77);
  }
  if (!existsSync(chromium)) {
    console.error(`SKIP: no Chromium at ${chromium} (set --chromium or CHROMIUM)`);
    process.exit(77);
  }
  run(process.execPath, [join(pluginDir, 'tools/generate-shaders.mjs'), '--check']);
}

// --- PNG through pngjs, loaded on first use so that a missing install skips instead of throwing.
let png;
const PNG = () => (png ??= requireFromPlugin('pngjs').PNG);

export function writePng(path, width, height, rgba) {
  writeFileSync(path, PNG().sync.write({ width, height, data: Buffer.from(rgba.buffer, rgba.byteOffset, rgba.byteLength) }));
}

// Any PNG, as 8-bit RGBA (pngjs expands RGB and other layouts).
export function readPng(path) {
  const { width, height, data } = PNG().sync.read(readFileSync(path));
  return { width, height, channels: 4, pixels: data };
}

// RMSE over RGB in [0, 1], the largest channel difference, the share of pixels over THRESHOLD, and a
// grey diff image (8x the largest channel difference).
export function compare(reference, rgba, diffPath) {
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

// Writes <case>.three.png and <case>.diff.png next to <case>.bakeplay.png, prints one line a case
// against its tolerance ({ rmse, over }) under `label`, and says whether all passed.
export function compareFrames(cases, frames, { tmp, size, label, width }) {
  let failed = false;
  console.log(`${label.padEnd(width)} RMSE    max  >${THRESHOLD}/255   tolerance (RMSE, share)`);
  for (const { name, tolerance: t } of cases) {
    const frame = frames.get(name);
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
    console.log(`${name.padEnd(width)} ${m.rmse.toFixed(4)} ${String(m.max).padStart(4)}  ${(100 * m.over).toFixed(2).padStart(6)}%   ` +
      `(${t.rmse}, ${(100 * t.over).toFixed(1)}%) ${ok ? 'ok' : 'FAIL'}`);
  }
  return !failed;
}

// --- Renders in Chromium: a tiny server hands out the page (tests/web/<page>.html and .mjs), three.js
// (/three/), the plugin (/bake-three/) and `files` (URL path -> file), and receives the frames
// (POST /frame?case=NAME), log lines (/log), the end (/done) or an error (any other path).
export async function renderInChromium({ page, files: extra, query, tmp, chromium }) {
  const frames = new Map();
  const files = {
    [`/${page}.html`]: join(here, `${page}.html`),
    [`/${page}.mjs`]: join(here, `${page}.mjs`),
    '/page_support.mjs': join(here, 'page_support.mjs'),
    ...extra,
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
  const url = `http://127.0.0.1:${server.address().port}/${page}.html?${new URLSearchParams(query)}`;
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

// Renders in Chromium, compares with the bakeplay pictures, prints the table and exits: 1 when the
// page failed or a case is out of tolerance, else 0.
export async function finishInChromium({ cases, size, label, width, started, ...render }) {
  const result = await renderInChromium(render);
  if (!result.ok) {
    console.error(`three.js render failed: ${result.reason}`);
    process.exit(1);
  }
  const ok = compareFrames(cases, result.frames, { tmp: render.tmp, size, label, width });
  console.log(`images in ${render.tmp}; ${((Date.now() - started) / 1000).toFixed(1)} s`);
  process.exit(ok ? 0 : 1);
}

// Runs the test's main, failing (exit 1) on any exception.
export function main(body) {
  body().catch((e) => {
    console.error(e);
    process.exit(1);
  });
}
