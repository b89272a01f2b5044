// Renders the hatched package for each case (tone mode and light) with the three.js hatching plugin
// and posts the frame's bytes (RGBA, top row first) to the test's server.
// Query: file, cases (name;tone;light, the light as the plugin's option in JSON), eye, target, w, h.
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { BakeHatchingPlugin, LinearToSrgbPresenter, bakeplayCamera } from '/bake-three/index.mjs';

const post = (path, body) => fetch(path, { method: 'POST', body });
const log = (message) => post('/log', String(message));
const originalError = console.error;
console.error = (...args) => { log(`console.error: ${args.join(' ')}`); originalError(...args); };
window.addEventListener('error', (e) => log(`error: ${e.message}`));
window.addEventListener('unhandledrejection', (e) => log(`unhandled: ${e.reason?.stack ?? e.reason}`));

const query = new URLSearchParams(location.search);
const numbers = (key) => query.get(key).split(',').map(Number);
const width = Number(query.get('w')), height = Number(query.get('h'));

async function main() {
  const canvas = document.createElement('canvas');
  canvas.width = width;
  canvas.height = height;
  document.body.appendChild(canvas);
  const gl = canvas.getContext('webgl2', { antialias: false, alpha: false, preserveDrawingBuffer: true });
  if (!gl) {
    await post('/nowebgl2', 'canvas.getContext("webgl2") returned null');
    return;
  }
  await log(`WebGL2: ${gl.getParameter(gl.VERSION)}; renderer ${gl.getParameter(gl.RENDERER)}`);
  const renderer = new THREE.WebGLRenderer({ canvas, context: gl, antialias: false });
  renderer.setPixelRatio(1);
  renderer.setSize(width, height, false);
  renderer.toneMapping = THREE.NoToneMapping;
  const presenter = new LinearToSrgbPresenter(renderer);
  const bytes = await (await fetch(`/packages/${query.get('file')}`)).arrayBuffer();

  // One load per tone mode; later cases of a mode change the light of the loaded scene, which
  // exercises the plugin's rebuild when the light changes.
  const loaded = new Map();
  for (const entry of JSON.parse(query.get('cases'))) {
    const started = performance.now();
    if (!loaded.has(entry.tone)) {
      const options = { tone: entry.tone, light: entry.light };
      const loader = new GLTFLoader();
      loader.register((parser) => new BakeHatchingPlugin(parser, options));
      const scene = (await loader.parseAsync(bytes.slice(0), '/')).scene;
      scene.updateMatrixWorld(true);
      const bounds = new THREE.Box3().setFromObject(scene, true);
      loaded.set(entry.tone, { scene, options, camera: bakeplayCamera(numbers('eye'), numbers('target'), width / height, bounds) });
    }
    const { scene, options, camera } = loaded.get(entry.tone);
    options.light = entry.light;
    presenter.render(scene, camera);
    const pixels = new Uint8Array(width * height * 4);
    gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
    const rows = new Uint8Array(pixels.length);  // GL's first row is the bottom one
    for (let y = 0; y < height; ++y) rows.set(pixels.subarray((height - 1 - y) * width * 4, (height - y) * width * 4), y * width * 4);
    await log(`${entry.name}: ${(performance.now() - started).toFixed(0)} ms`);
    await post(`/frame?case=${entry.name}`, rows);
  }
  await post('/done', '');
}

main().catch((e) => post('/fatal', String(e?.stack ?? e)));
