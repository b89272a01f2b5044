// gltf-transform --config module for the tests: the CLI's own extensions plus the project's BAKE_*
// modules (integrations/gltf-transform), built on this folder's @gltf-transform/core.
import * as core from '@gltf-transform/core';
import { ALL_EXTENSIONS } from '@gltf-transform/extensions';
import { createBakeExtensions } from '../../integrations/gltf-transform/index.mjs';

export default { extensions: [...ALL_EXTENSIONS, ...createBakeExtensions(core)] };
