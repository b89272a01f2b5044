// Renders each case (a package, with a preset override or with the package's own material) with the
// three.js plugin and posts the frame's bytes (RGBA, top row first) to the test's server.
// Query: cases (name:package:preset, the preset may be empty), eye, target, light (x,y,z lists), w, h.
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { BakeGeodesicPlugin, bakeplayCamera } from '/bake-three/index.mjs';
import { height, numbers, query, runPage, width } from '/page_support.mjs';

runPage(async (presenter, frame) => {
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
    presenter.render(scene, bakeplayCamera(numbers('eye'), numbers('target'), width / height, bounds));
    await frame(name);
  }
});
