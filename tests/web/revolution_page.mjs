// Renders each case (a BAKE_revolution package at its own view) with the three.js plugin and posts the
// frame's bytes (RGBA, top row first) to the test's server.
// Query: cases (JSON list of { name, file, eye, target }), light (x,y,z), w, h.
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { BakeRevolutionPlugin, bakeplayCamera } from '/bake-three/index.mjs';
import { height, numbers, query, runPage, width } from '/page_support.mjs';

runPage(async (presenter, frame) => {
  const options = { light: { direction: numbers('light') } };
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
    presenter.render(scene, bakeplayCamera(c.eye, c.target, width / height, bounds));
    await frame(c.name);
  }
});
