// Renders each case (a BAKE_revolution package at its own view) with the three.js plugin and posts the
// frame's bytes (RGBA, top row first) to the test's server.
// Query: cases (JSON list of { name, file, eye, target }), light (x,y,z), w, h.
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { BakeRevolutionPlugin, LinearToSrgbPresenter, bakeplayCamera } from '/bake-three/index.mjs';

const post = (path, body) => fetch(path, { method: 'POST', body });
const log = (message) => post('/log', String(message));
const originalError = console.error, originalWarn = console.warn;
console.error = (...args) => { log(`console.error: ${args.join(' ')}`); originalError(...args); };
console.warn = (...args) => { log(`console.warn: ${args.join(' ')}`); originalWarn(...args); };
window.addEventListener('error', (e) => log(`error: ${e.message}`));
window.addEventListener('unhandledrejection', (e) => log(`unhandled: ${e.reason?.stack ?? e.reason}`));

const query = new URLSearchParams(location.search);
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
  const options = { light: { direction: query.get('light').split(',').map(Number) } };

  for (const c of JSON.parse(query.get('cases'))) {
    const bytes = await (await fetch(`/packages/${c.file}`)).arrayBuffer();
    const loader = new GLTFLoader();
    loader.register((parser) => new BakeRevolutionPlugin(parser, options));
    const gltf = await loader.parseAsync(bytes, '/');
    const scene = gltf.scene;
    scene.updateMatrixWorld(true);
    // bakeplay's near and far planes come from the bounds of the package's mesh (the preview), which
    // the plugin has replaced by the shape box.
    const bounds = new THREE.Box3();
    scene.traverse((object) => {
      const preview = object.userData.bakeRevolution?.previewBounds;
      if (preview) bounds.union(preview.clone().applyMatrix4(object.matrixWorld));
    });
    const camera = bakeplayCamera(c.eye, c.target, width / height, bounds);
    presenter.render(scene, camera);
    const pixels = new Uint8Array(width * height * 4);
    gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
    const rows = new Uint8Array(pixels.length);  // GL's first row is the bottom one
    for (let y = 0; y < height; ++y) rows.set(pixels.subarray((height - 1 - y) * width * 4, (height - y) * width * 4), y * width * 4);
    await post(`/frame?case=${c.name}`, rows);
  }
  await post('/done', '');
}

main().catch((e) => post('/fatal', String(e?.stack ?? e)));
