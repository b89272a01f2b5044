// three.js GLTFLoader plugin for BAKE_hatching packages (formats/tam.md): real-time hatching with
// tonal art maps (Praun et al. 2001), drawn with the project's fragment stage
// (generated/hatching-shaders.mjs from shaders/hatching/hatching.frag) and the uniforms bakeplay sets
// (runtime/render/hatching.cpp). WebGL2 has no geometry stage: what shaders/hatching/hatching.geom
// computes per triangle (the light-oriented frames of the triangle and its three neighbours, their
// hatching coordinates and blend factors) is computed here on the CPU, on an un-indexed copy of the
// mesh, so each triangle's three vertices carry exactly the values the geometry stage emits. It is
// recomputed when the light seen from the object changes. The TAM (a KTX2 2D array, one layer per
// tone, every mip level hand-made) is uploaded with every stored level; nothing is generated.
// Present the linear output with LinearToSrgbPresenter, as for BAKE_geodesic.
import * as THREE from 'three';
import { fragmentShader } from './generated/hatching-shaders.mjs';

export const EXTENSION = 'BAKE_hatching';
const MAX_TONES = 16;  // kMaxTones, formats/include/bake_formats/tam.h
const MIN_BLEND_COSINE = '0.0';  // kMinBlendCosine
const THRESHOLD_SOFTNESS = 0.02;  // kThresholdSoftness, runtime/render/hatching.cpp
const KTX2_IDENTIFIER = [0xab, 0x4b, 0x54, 0x58, 0x20, 0x32, 0x30, 0xbb, 0x0d, 0x0a, 0x1a, 0x0a];
const VK_R8_UNORM = 9, VK_R8G8B8A8_UNORM = 37;

// Replaces hatching.geom's inputs and outputs: the per-triangle values arrive as attributes; face
// normals are turned to world space here, as the geometry stage does with uNormalMatrix.
const vertexShader = `precision highp float;
in vec3 position;
in vec4 aCoordsCA, aCoordsBG;
in vec3 aBlend, aNormalC, aNormalA, aNormalB, aNormalG;
uniform mat4 uModel;
uniform mat4 uViewProj;
uniform mat3 uNormalMatrix;
out vec4 gCoordsCA;
out vec4 gCoordsBG;
out vec3 gBlend;
out vec3 gWorldPosition;
flat out vec3 gNormalC, gNormalA, gNormalB, gNormalG;
void main() {
  gCoordsCA = aCoordsCA;
  gCoordsBG = aCoordsBG;
  gBlend = aBlend;
  gNormalC = normalize(uNormalMatrix * aNormalC);
  gNormalA = normalize(uNormalMatrix * aNormalA);
  gNormalB = normalize(uNormalMatrix * aNormalB);
  gNormalG = normalize(uNormalMatrix * aNormalG);
  vec4 world = uModel * vec4(position, 1.0);
  gWorldPosition = world.xyz;
  gl_Position = uViewProj * world;
}
`;

function isObject(v) { return v !== null && typeof v === 'object' && !Array.isArray(v); }

// A KTX2 file as the bakers write it (formats/ktx2.md): uncompressed R8 or RGBA8, no
// supercompression; levels base first, each holding every layer. Anything else throws.
export function parseKtx2(buffer) {
  const bytes = new Uint8Array(buffer);
  if (bytes.length < 80 || KTX2_IDENTIFIER.some((b, i) => bytes[i] !== b)) throw new Error('not a KTX2 file');
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const u32 = (o) => view.getUint32(o, true);
  const u64 = (o) => Number(view.getBigUint64(o, true));
  const [vkFormat, , width, height, depth, layers, faces, levelCount, supercompression] =
    Array.from({ length: 9 }, (_, i) => u32(12 + 4 * i));
  if (vkFormat !== VK_R8_UNORM && vkFormat !== VK_R8G8B8A8_UNORM)
    throw new Error(`KTX2 vkFormat ${vkFormat} is not R8 or RGBA8 UNORM`);
  if (supercompression !== 0) throw new Error(`KTX2 supercompression ${supercompression} is not supported here`);
  if (depth !== 0 || faces !== 1) throw new Error('KTX2: only 2D and 2D array textures');
  const texel = vkFormat === VK_R8_UNORM ? 1 : 4;
  const levels = [];
  for (let l = 0; l < Math.max(1, levelCount); ++l) {
    const offset = u64(80 + 24 * l), length = u64(88 + 24 * l);
    const w = Math.max(1, width >> l), h = Math.max(1, height >> l);
    if (length !== w * h * Math.max(1, layers) * texel || offset + length > bytes.length)
      throw new Error(`KTX2 level ${l}: ${length} bytes at ${offset} do not hold ${w}x${h}x${Math.max(1, layers)}`);
    levels.push({ width: w, height: h, data: bytes.subarray(offset, offset + length) });
  }
  return { vkFormat, rgba: texel === 4, width, height, layers, levels };
}

// The TAM as a 2D array texture with every stored level. three.js uploads explicit mip levels of an
// array texture only through CompressedArrayTexture, and there only for RGBAFormat without a
// compressed format, so R8 texels are widened to RGBA (the shader reads .r; values unchanged).
function tamTexture(ktx) {
  const mipmaps = ktx.levels.map(({ width, height, data }) => {
    if (ktx.rgba) return { width, height, data: new Uint8Array(data) };
    const rgba = new Uint8Array(data.length * 4);
    for (let i = 0; i < data.length; ++i) rgba.set([data[i], data[i], data[i], 255], 4 * i);
    return { width, height, data: rgba };
  });
  const texture = new THREE.CompressedArrayTexture(mipmaps, ktx.width, ktx.height, ktx.layers, THREE.RGBAFormat,
    THREE.UnsignedByteType);
  trilinearRepeating(texture);
  return texture;
}

// The threshold texture: R8 2D with every stored level.
function thresholdTexture(ktx) {
  const base = ktx.levels[0];
  const texture = new THREE.DataTexture(new Uint8Array(base.data), base.width, base.height, THREE.RedFormat,
    THREE.UnsignedByteType);
  texture.mipmaps = ktx.levels.map(({ width, height, data }) => ({ width, height, data: new Uint8Array(data) }));
  trilinearRepeating(texture);
  return texture;
}

// As bakeplay: trilinear over the stored chain, repeating both ways (the tiles wrap).
function trilinearRepeating(texture) {
  texture.minFilter = THREE.LinearMipmapLinearFilter;
  texture.magFilter = THREE.LinearFilter;
  texture.wrapS = texture.wrapT = THREE.RepeatWrapping;
  texture.generateMipmaps = false;
  texture.flipY = false;
  texture.unpackAlignment = 1;
  texture.colorSpace = THREE.NoColorSpace;
  texture.needsUpdate = true;
}

// A material's BAKE_hatching object -> parameters (parseHatching in libbake): the fields it requires
// and their ranges; wrong ones throw.
export function parseHatching(extension) {
  const fail = (message) => { throw new Error(`BAKE_hatching material: ${message}`); };
  if (!isObject(extension)) fail('must be an object');
  if (extension.version !== 1) fail('version must be 1');
  for (const key of ['tam', 'tones', 'tilesPerUnit', 'rotation', 'translation', 'orientation', 'baseColor'])
    if (!(key in extension)) fail(`lacks "${key}"`);
  const finite = (v, name) => {
    if (typeof v !== 'number' || !Number.isFinite(v)) fail(`${name} must be a finite number`);
    return v;
  };
  const { tones } = extension;
  if (!Array.isArray(tones) || tones.length === 0 || tones.length > MAX_TONES) fail(`tones must hold 1 to ${MAX_TONES} numbers`);
  tones.forEach((t, k) => {
    finite(t, `tones[${k}]`);
    if (!(t > 0 && t < 1) || (k > 0 && !(t > tones[k - 1]))) fail('tones must increase strictly within (0, 1)');
  });
  const tilesPerUnit = finite(extension.tilesPerUnit, 'tilesPerUnit');
  if (!(tilesPerUnit > 0)) fail('tilesPerUnit must be > 0');
  const translation = extension.translation;
  if (!Array.isArray(translation) || translation.length !== 2) fail('translation must be 2 numbers');
  const baseColor = extension.baseColor;
  if (!Array.isArray(baseColor) || baseColor.length !== 3) fail('baseColor must be 3 numbers');
  baseColor.forEach((c, k) => { if (!(finite(c, `baseColor[${k}]`) >= 0 && c <= 1)) fail('baseColor must lie in [0, 1]'); });
  if (extension.orientation !== 'toward-light' && extension.orientation !== 'across-light')
    fail('orientation must be "toward-light" or "across-light"');
  if (!Number.isInteger(extension.tam)) fail('tam must be an image index');
  if ('threshold' in extension && !Number.isInteger(extension.threshold)) fail('threshold must be an image index');
  return {
    tam: extension.tam,
    threshold: extension.threshold,
    tones: [...tones],
    tilesPerUnit,
    rotation: finite(extension.rotation, 'rotation'),
    translation: translation.map((v, k) => finite(v, `translation[${k}]`)),
    acrossLight: extension.orientation === 'across-light',
    baseColor: [...baseColor],
  };
}

// Triangle adjacency as runtime/render/hatching_adjacency.cpp builds it: positions welded by their
// float bits (-0 = +0); for edge (k, k+1) of a triangle the first other triangle on that edge gives
// its vertex off the edge; a boundary edge repeats the triangle's own opposite vertex.
export function triangleAdjacency(positions, indices) {
  const bits = new Uint32Array(new Float32Array(positions.map((v) => (v === 0 ? 0 : v))).buffer);
  const first = new Map();
  const welded = new Uint32Array(positions.length / 3);
  for (let v = 0; v < welded.length; ++v) {
    const key = `${bits[3 * v]},${bits[3 * v + 1]},${bits[3 * v + 2]}`;
    if (!first.has(key)) first.set(key, v);
    welded[v] = first.get(key);
  }
  const triangles = indices.length / 3;
  const id = (t, c) => welded[indices[3 * t + c]];
  const n = welded.length;
  const edgeKey = (a, b) => (a < b ? a * n + b : b * n + a);
  const edges = new Map();
  for (let t = 0; t < triangles; ++t) {
    for (let e = 0; e < 3; ++e) {
      const a = id(t, e), b = id(t, (e + 1) % 3);
      if (a === b) continue;
      const key = edgeKey(a, b);
      const users = edges.get(key);
      if (users) users.push(t); else edges.set(key, [t]);
    }
  }
  const opposite = new Uint32Array(triangles * 3);  // per (triangle, edge): a vertex index
  for (let t = 0; t < triangles; ++t) {
    for (let e = 0; e < 3; ++e) {
      const a = id(t, e), b = id(t, (e + 1) % 3);
      let found = indices[3 * t + (e + 2) % 3];
      if (a !== b) {
        search: for (const other of edges.get(edgeKey(a, b))) {
          if (other === t) continue;
          for (let c = 0; c < 3; ++c) {
            const w = id(other, c);
            if (w !== a && w !== b) { found = indices[3 * other + c]; break search; }
          }
        }
      }
      opposite[3 * t + e] = found;
    }
  }
  return opposite;
}

const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const scale = (a, s) => [a[0] * s, a[1] * s, a[2] * s];
const normalise = (a) => scale(a, 1 / Math.hypot(a[0], a[1], a[2]));

// hatching.geom's frameOf: the (T, B, N) frame of triangle (a, b, c) for the object-space light.
function frameOf(a, b, c, light, acrossLight) {
  let l = light.direction;
  if (light.point) l = sub(light.position, scale([a[0] + b[0] + c[0], a[1] + b[1] + c[1], a[2] + b[2] + c[2]], 1 / 3));
  const e1 = sub(b, a), e2 = sub(c, a);
  let n = cross(e1, e2);
  const len = Math.hypot(n[0], n[1], n[2]);
  const valid = len > 1e-7 * (dot(e1, e1) + dot(e2, e2)) && len > 0;
  n = valid ? scale(n, 1 / len) : [0, 0, 1];
  let projected = sub(l, scale(n, dot(l, n)));
  if (dot(projected, projected) < 1e-12) {
    const m = n.map(Math.abs);
    const axis = m[0] <= m[1] && m[0] <= m[2] ? [1, 0, 0] : m[1] <= m[2] ? [0, 1, 0] : [0, 0, 1];
    projected = sub(axis, scale(n, dot(axis, n)));
  }
  const bt = normalise(projected);
  const tt = cross(bt, n);
  return acrossLight ? { t: bt, b: tt, n, valid } : { t: tt, b: bt, n, valid };
}

// Per-triangle values of hatching.geom for every triangle, un-indexed: three vertices per triangle.
// light: { direction } (unit, object space) or { point: true, position } (object space).
export function hatchingAttributes(positions, indices, opposite, params, light, out) {
  const triangles = indices.length / 3;
  const cosR = Math.cos(params.rotation), sinR = Math.sin(params.rotation);
  const [tx, ty] = params.translation;
  const coords = (v, f) => {
    const s = dot(v, f.t) * params.tilesPerUnit, t = dot(v, f.b) * params.tilesPerUnit;
    return [cosR * s - sinR * t + tx, sinR * s + cosR * t + ty];
  };
  const ontoPlane = (v, p, n) => sub(v, scale(n, dot(sub(v, p), n)));
  const at = (i) => [positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]];
  const same = (a, b) => a[0] === b[0] && a[1] === b[1] && a[2] === b[2];
  const { position, coordsCA, coordsBG, blend, normals } = out;
  for (let t = 0; t < triangles; ++t) {
    const v = [at(indices[3 * t]), at(indices[3 * t + 1]), at(indices[3 * t + 2])];
    const o = [at(opposite[3 * t]), at(opposite[3 * t + 1]), at(opposite[3 * t + 2])];
    const fc = frameOf(v[0], v[1], v[2], light, params.acrossLight);
    if (!fc.valid) {
      // Zero area: the geometry stage draws nothing; three equal positions draw nothing either.
      for (let i = 0; i < 3; ++i) position.set(v[0], 9 * t + 3 * i);
      continue;
    }
    const fn = [], cosine = [];
    for (let k = 0; k < 3; ++k) {
      fn[k] = frameOf(v[(k + 1) % 3], v[k], o[k], light, params.acrossLight);
      const boundary = same(o[k], v[(k + 2) % 3]);
      cosine[k] = fn[k].valid && !boundary ? dot(fc.n, fn[k].n) : -1;
      if (cosine[k] <= Number(MIN_BLEND_COSINE)) cosine[k] = -1;
    }
    const faceNormals = [fc.n, ...fn.map((f) => (f.valid ? f.n : fc.n))];
    for (let i = 0; i < 3; ++i) {
      const row = 3 * t + i;
      const h = [0, 1, 2].map((k) => coords(ontoPlane(v[i], v[k], fn[k].n), fn[k]));
      const f = [0, 1, 2].map((k) => (i === (k + 2) % 3 || cosine[k] < 0 ? -1 : cosine[k]));
      position.set(v[i], 3 * row);
      coordsCA.set([...coords(v[i], fc), ...h[0]], 4 * row);
      coordsBG.set([...h[1], ...h[2]], 4 * row);
      blend.set(f, 3 * row);
      faceNormals.forEach((n, k) => normals[k].set(n, 3 * row));
    }
  }
}

// The light bakeplay gets from --light: a direction towards it, or a point or spot light.
// options.light: { direction: [x, y, z] } | { point: [x, y, z] } |
//   { spot: [x, y, z], spotDirection: [dx, dy, dz], cutoffDegrees, exponent }.
function lightOf(options) {
  const light = options.light ?? {};
  if (light.spot) {
    return {
      kind: 2,
      position: new THREE.Vector3().fromArray(light.spot),
      spotDirection: new THREE.Vector3().fromArray(light.spotDirection ?? [0, -1, 0]).normalize(),
      cosCutoff: Math.cos(THREE.MathUtils.degToRad(light.cutoffDegrees ?? 45)),
      exponent: light.exponent ?? 0,
    };
  }
  if (light.point) return { kind: 1, position: new THREE.Vector3().fromArray(light.point) };
  return { kind: 0, direction: new THREE.Vector3().fromArray(light.direction ?? [0.4, 0.8, 0.45]).normalize() };
}

// Options: light (see lightOf; default the direction [0.4, 0.8, 0.45]), tone ('blend', the default,
// or 'threshold': Webb et al. 2002 with the package's threshold texture, as --hatching-tone).
// `options` is read at every frame; a light that changes as seen from the object rebuilds the
// per-triangle attributes on the CPU.
export class BakeHatchingPlugin {
  constructor(parser, options = {}) {
    this.parser = parser;
    this.name = EXTENSION;
    this.options = options;
    if (options.tone !== undefined && options.tone !== 'blend' && options.tone !== 'threshold')
      throw new Error(`tone must be "blend" or "threshold", not "${options.tone}"`);
  }

  async afterRoot(result) {
    const json = this.parser.json;
    const meshes = [];
    result.scene.traverse((object) => { if (object.isMesh) meshes.push(object); });
    const textures = new Map();  // image index -> texture, shared by the package's materials
    for (const mesh of meshes) {
      const ref = this.parser.associations.get(mesh);
      if (!ref || ref.meshes === undefined || ref.primitives === undefined) continue;
      const primitive = json.meshes[ref.meshes].primitives[ref.primitives];
      const material = primitive.material !== undefined ? json.materials?.[primitive.material] : undefined;
      const extension = material?.extensions?.[EXTENSION];
      if (!extension) continue;
      const params = parseHatching(extension);
      if ((primitive.mode ?? 4) !== 4) throw new Error('BAKE_hatching draws triangle lists only');
      const tam = await this.texture(params.tam, textures, (ktx) => {
        if (ktx.layers !== params.tones.length)
          throw new Error(`the TAM has ${ktx.layers} layers but tones lists ${params.tones.length}`);
        return tamTexture(ktx);
      });
      let threshold = null;
      if (this.options.tone === 'threshold' && params.threshold !== undefined) {
        threshold = await this.texture(params.threshold, textures, (ktx) => {
          if (ktx.layers !== 0 || ktx.rgba || ktx.width !== tam.image.width || ktx.levels.length !== tam.mipmaps.length)
            throw new Error('the threshold texture must be a 2D R8 texture of the TAM\'s size and levels');
          return thresholdTexture(ktx);
        });
      }
      this.attach(mesh, params, tam, threshold);
    }
  }

  async texture(image, cache, make) {
    if (cache.has(image)) return cache.get(image);
    const entry = this.parser.json.images?.[image];
    if (!entry || entry.mimeType !== 'image/ktx2' || entry.bufferView === undefined)
      throw new Error(`BAKE_hatching: image ${image} is not an embedded image/ktx2`);
    const texture = make(parseKtx2(await this.parser.getDependency('bufferView', entry.bufferView)));
    cache.set(image, texture);
    return texture;
  }

  attach(mesh, params, tam, threshold) {
    const source = mesh.geometry;
    const p = source.getAttribute('position');
    const positions = new Float32Array(p.count * 3);
    for (let i = 0; i < p.count; ++i) positions.set([p.getX(i), p.getY(i), p.getZ(i)], 3 * i);
    let indices = source.index ? Uint32Array.from(source.index.array) : Uint32Array.from({ length: p.count }, (_, i) => i);
    indices = indices.subarray(0, indices.length - (indices.length % 3));
    const opposite = triangleAdjacency(positions, indices);

    const rows = indices.length;
    const geometry = new THREE.BufferGeometry();
    const attribute = (name, size) => {
      const a = new THREE.BufferAttribute(new Float32Array(rows * size), size);
      geometry.setAttribute(name, a);
      return a;
    };
    const attributes = {
      position: attribute('position', 3),
      coordsCA: attribute('aCoordsCA', 4),
      coordsBG: attribute('aCoordsBG', 4),
      blend: attribute('aBlend', 3),
      normals: ['aNormalC', 'aNormalA', 'aNormalB', 'aNormalG'].map((name) => attribute(name, 3)),
    };
    const arrays = {
      position: attributes.position.array,
      coordsCA: attributes.coordsCA.array,
      coordsBG: attributes.coordsBG.array,
      blend: attributes.blend.array,
      normals: attributes.normals.map((a) => a.array),
    };

    const defines = { MAX_TONES, MIN_BLEND_COSINE };
    if (params.acrossLight) defines.ACROSS_LIGHT = '';
    if (threshold) defines.THRESHOLD_TONE = '';
    const tones = new Array(MAX_TONES).fill(1);
    params.tones.forEach((t, k) => { tones[k] = t; });
    const uniforms = {
      uModel: { value: new THREE.Matrix4() },
      uViewProj: { value: new THREE.Matrix4() },
      uNormalMatrix: { value: new THREE.Matrix3() },
      uTam: { value: tam },
      uToneCount: { value: params.tones.length },
      uTones: { value: tones },
      uLightDir: { value: new THREE.Vector3(0, 0, 1) },
      uLightKind: { value: 0 },
      uLightPos: { value: new THREE.Vector3() },
      uSpotDirection: { value: new THREE.Vector3(0, -1, 0) },
      uSpotCosCutoff: { value: Math.cos(Math.PI / 4) },
      uSpotExponent: { value: 0 },
      uBaseColor: { value: new THREE.Vector3().fromArray(params.baseColor) },
    };
    if (threshold) {
      Object.assign(uniforms, {
        uThreshold: { value: threshold },
        uThresholdSoftness: { value: THRESHOLD_SOFTNESS },
        bakeLevels_uThreshold: { value: threshold.mipmaps.length },
      });
    }
    geometry.boundingBox = source.boundingBox;
    geometry.boundingSphere = source.boundingSphere;
    if (!geometry.boundingSphere) geometry.computeBoundingSphere();

    let builtFor = '';
    const inverse = new THREE.Matrix4(), inverse3 = new THREE.Matrix3();
    const rebuild = (light, world) => {
      // The light as hatching.geom sees it: M^-1 L for a direction, the position in object space.
      inverse.copy(world).invert();
      let objectLight;
      if (light.kind === 0) {
        inverse3.setFromMatrix4(inverse);
        objectLight = { direction: light.direction.clone().applyMatrix3(inverse3).normalize().toArray() };
      } else {
        objectLight = { point: true, position: light.position.clone().applyMatrix4(inverse).toArray() };
      }
      const key = JSON.stringify(objectLight);
      if (key === builtFor) return;
      builtFor = key;
      hatchingAttributes(positions, indices, opposite, params, objectLight, arrays);
      for (const a of [attributes.position, attributes.coordsCA, attributes.coordsBG, attributes.blend, ...attributes.normals])
        a.needsUpdate = true;
    };
    const options = this.options;
    const update = (camera) => {
      mesh.updateWorldMatrix(true, false);
      uniforms.uModel.value.copy(mesh.matrixWorld);
      uniforms.uNormalMatrix.value.getNormalMatrix(mesh.matrixWorld);
      uniforms.uViewProj.value.multiplyMatrices(camera.projectionMatrix, camera.matrixWorldInverse);
      const light = lightOf(options);
      uniforms.uLightKind.value = light.kind;
      if (light.kind === 0) {
        uniforms.uLightDir.value.copy(light.direction);
      } else {
        uniforms.uLightPos.value.copy(light.position);
        // Read by the shaders for directional lights only.
        uniforms.uLightDir.value.copy(light.position).normalize();
      }
      if (light.kind === 2) {
        uniforms.uSpotDirection.value.copy(light.spotDirection);
        uniforms.uSpotCosCutoff.value = light.cosCutoff;
        uniforms.uSpotExponent.value = light.exponent;
      }
      rebuild(light, mesh.matrixWorld);
    };
    mesh.updateWorldMatrix(true, false);
    rebuild(lightOf(options), mesh.matrixWorld);

    // bakeplay draws both faces with depth test LESS and no culling.
    mesh.geometry = geometry;
    mesh.material = new THREE.RawShaderMaterial({
      name: 'BAKE_hatching',
      glslVersion: THREE.GLSL3,
      vertexShader,
      fragmentShader,
      defines,
      uniforms,
      side: THREE.DoubleSide,
      depthFunc: THREE.LessDepth,
    });
    mesh.userData.bakeHatching = { params, tone: threshold ? 'threshold' : 'blend' };
    mesh.onBeforeRender = (renderer, scene, camera) => update(camera);
    // Attributes changed in onBeforeRender would reach the GPU a frame late (three.js uploads
    // geometry before that hook); the renderer updates world matrices first, so rebuild there.
    const updateMatrixWorld = mesh.updateMatrixWorld;
    mesh.updateMatrixWorld = function (force) {
      updateMatrixWorld.call(this, force);
      rebuild(lightOf(options), this.matrixWorld);
    };
  }
}
