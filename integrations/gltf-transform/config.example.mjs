// A gltf-transform --config module: the CLI's own extensions plus ours.
//   gltf-transform copy in.glb out.glb --config node_modules/bake-gltf-transform/config.example.mjs
// (run from a folder whose node_modules holds @gltf-transform/core and @gltf-transform/extensions).
import * as core from '@gltf-transform/core';
import { ALL_EXTENSIONS } from '@gltf-transform/extensions';
import { createBakeExtensions } from './index.mjs';

export default { extensions: [...ALL_EXTENSIONS, ...createBakeExtensions(core)] };
