// Renders the hatched package for each case (tone mode and light) with the three.js hatching plugin
// and posts the frame's bytes (RGBA, top row first) to the test's server.
// Query: file, cases (name;tone;light, the light as the plugin's option in JSON), eye, target, w, h.
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { BakeHatchingPlugin, bakeplayCamera } from '/bake-three/index.mjs';
import { height, log, numbers, query, runPage, width } from '/page_support.mjs';

runPage(async (presenter, frame) => {
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
    await log(`${entry.name}: ${(performance.now() - started).toFixed(0)} ms`);
    await frame(entry.name);
  }
});
