// Renders each case (a package, with a preset override or with the package's own material) with the
// three.js plugin and posts the frame's bytes (RGBA, top row first) to the test's server.
// Query: cases (name:package:preset, the preset may be empty), eye, target, light (x,y,z lists), w, h.
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { BakeGeodesicPlugin, LinearToSrgbPresenter, bakeplayCamera } from '/bake-three/index.mjs';

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
  const options = { light: { direction: numbers('light') }, time: 0 };
  const packages = new Map();

  for (const entry of query.get('cases').split(',')) {
    const [name, file, preset] = entry.split(':');
    if (!packages.has(file)) packages.set(file, await (await fetch(`/packages/${file}`)).arrayBuffer());
    const loader = new GLTFLoader();
    loader.register((parser) => new BakeGeodesicPlugin(parser, preset ? { ...options, preset } : options));
    const gltf = await loader.parseAsync(packages.get(file).slice(0), '/');
    const scene = gltf.scene;
    scene.updateMatrixWorld(true);
    const bounds = new THREE.Box3().setFromObject(scene, true);
    const camera = bakeplayCamera(numbers('eye'), numbers('target'), width / height, bounds);
    presenter.render(scene, camera);
    const pixels = new Uint8Array(width * height * 4);
    gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
    const rows = new Uint8Array(pixels.length);  // GL's first row is the bottom one
    for (let y = 0; y < height; ++y) rows.set(pixels.subarray((height - 1 - y) * width * 4, (height - y) * width * 4), y * width * 4);
    await post(`/frame?case=${name}`, rows);
  }
  await post('/done', '');
}

main().catch((e) => post('/fatal', String(e?.stack ?? e)));
