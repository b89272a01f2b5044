// What every test page shares: the query, messages to the test's server (log lines, console errors,
// frames, the end), a WebGL2 canvas with a three.js renderer and the sRGB presenter, and reading a
// frame back top row first, as bakeplay's PNGs are stored.
import * as THREE from 'three';
import { LinearToSrgbPresenter } from '/bake-three/index.mjs';

export const post = (path, body) => fetch(path, { method: 'POST', body });
export const log = (message) => post('/log', String(message));
for (const level of ['error', 'warn']) {
  const original = console[level];
  console[level] = (...args) => { log(`console.${level}: ${args.join(' ')}`); original(...args); };
}
window.addEventListener('error', (e) => log(`error: ${e.message}`));
window.addEventListener('unhandledrejection', (e) => log(`unhandled: ${e.reason?.stack ?? e.reason}`));

export const query = new URLSearchParams(location.search);
export const numbers = (key) => query.get(key).split(',').map(Number);
export const width = Number(query.get('w')), height = Number(query.get('h'));

// The canvas's context, renderer and presenter; null (the server told) when there is no WebGL2.
async function startRenderer() {
  const canvas = document.createElement('canvas');
  canvas.width = width;
  canvas.height = height;
  document.body.appendChild(canvas);
  const gl = canvas.getContext('webgl2', { antialias: false, alpha: false, preserveDrawingBuffer: true });
  if (!gl) {
    await post('/nowebgl2', 'canvas.getContext("webgl2") returned null');
    return null;
  }
  await log(`WebGL2: ${gl.getParameter(gl.VERSION)}; renderer ${gl.getParameter(gl.RENDERER)}`);
  const renderer = new THREE.WebGLRenderer({ canvas, context: gl, antialias: false });
  renderer.setPixelRatio(1);
  renderer.setSize(width, height, false);
  renderer.toneMapping = THREE.NoToneMapping;
  return { gl, presenter: new LinearToSrgbPresenter(renderer) };
}

// Posts the canvas's frame as case `name` (RGBA; GL's first row is the bottom one).
async function postFrame(gl, name) {
  const pixels = new Uint8Array(width * height * 4);
  gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
  const rows = new Uint8Array(pixels.length);
  for (let y = 0; y < height; ++y) rows.set(pixels.subarray((height - 1 - y) * width * 4, (height - y) * width * 4), y * width * 4);
  await post(`/frame?case=${name}`, rows);
}

// Runs a page: `drawCases(presenter, frame)` draws every case, calling `frame(name)` after each; the
// server then hears the end, or the failure.
export function runPage(drawCases) {
  (async () => {
    const started = await startRenderer();
    if (!started) return;
    await drawCases(started.presenter, (name) => postFrame(started.gl, name));
    await post('/done', '');
  })().catch((e) => post('/fatal', String(e?.stack ?? e)));
}
