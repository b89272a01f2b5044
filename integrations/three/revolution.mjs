// three.js GLTFLoader plugin for BAKE_revolution packages (revolution mapping, Ragragui et al. 2025):
// every primitive whose material carries the extension is drawn as bakeplay draws it
// (runtime/render/revolution.cpp): the back faces of the shape box are rasterised and the project's
// own fragment shader (generated/revolution-shaders.mjs) marches each pixel's ray through the shape
// map. The package's preview mesh is not drawn. Maps are read from the package's bufferViews with the
// native formats, filters and wraps (formats/revolution.md); the unorm16 maps are widened to float32
// textures (WebGL2 has no filterable 16-bit normalised format without an extension), which needs
// OES_texture_float_linear. WebGL2 only; the material writes linear colour (see LinearToSrgbPresenter).
import * as THREE from 'three';
import { fragmentShader, vertexShader } from './generated/revolution-shaders.mjs';

export const REVOLUTION_EXTENSION = 'BAKE_revolution';
const VERSION = 1;
const MAX_PROXY_BANDS = 64;         // bake_formats/revolution.h kMaxProxyBands
const DEFAULT_OVER_RELAXATION = 1.6;
const HIT_EPSILON_TEXELS = 0.05;
const MAX_REPLICAS = 4096;
const MAX_REPLICAS_PER_AXIS = 1024;
const TEXEL_BYTES = { float: 16, unorm16: 8, sqrt8: 4 };
const ENCODING_DEFINES = { float: 'ENCODING_FLOAT', unorm16: 'ENCODING_UNORM16', sqrt8: 'ENCODING_SQRT8' };
const PROJECTION_DEFINES = {
  cylindrical: 'PROJECTION_CYLINDRICAL', spherical: 'PROJECTION_SPHERICAL', 'arc-length': 'PROJECTION_ARC_LENGTH',
};

const isObject = (v) => v !== null && typeof v === 'object' && !Array.isArray(v);
const f32 = Math.fround;  // the native reader keeps floats

// A material's BAKE_revolution object -> parameters, with the checks and defaults of parseRevolution
// (libbake/revolution/package/package_read.cpp). viewBytes(i): byte length of bufferView i, or
// undefined when there is none.
export function parseRevolution(extension, viewBytes) {
  const fail = (field, message) => { throw new Error(`${REVOLUTION_EXTENSION} ${field} ${message}`); };
  if (!isObject(extension)) throw new Error(`${REVOLUTION_EXTENSION} must be an object`);
  const fields = (body, path) => {
    const name = (key) => (path ? `${path}.${key}` : key);
    const has = (key) => isObject(body) && key in body;
    const number = (key, lo, hi) => {
      if (!has(key)) fail(name(key), 'is missing');
      const v = body[key];
      if (typeof v !== 'number' || !Number.isFinite(v)) fail(name(key), `must be a finite number, not ${JSON.stringify(v)}`);
      if (v < lo || v > hi) fail(name(key), `is ${v}; it must be in [${lo}, ${hi}]`);
      return v;
    };
    return {
      has,
      at: (key) => body[key],
      name,
      number,
      positive: (key, hi = 1e30) => {
        const v = number(key, 0, hi);
        if (!(v > 0)) fail(name(key), 'must be positive');
        return v;
      },
      integer: (key, lo, hi) => {
        if (!has(key)) fail(name(key), 'is missing');
        const v = body[key];
        if (!Number.isInteger(v) || v < lo || v > hi) fail(name(key), `must be an integer in [${lo}, ${hi}], not ${JSON.stringify(v)}`);
        return v;
      },
      string: (key) => {
        if (!has(key)) fail(name(key), 'is missing');
        if (typeof body[key] !== 'string') fail(name(key), `must be a string, not ${JSON.stringify(body[key])}`);
        return body[key];
      },
      object: (key) => {
        if (!has(key)) fail(name(key), 'is missing');
        if (!isObject(body[key])) fail(name(key), 'must be an object');
        return fields(body[key], name(key));
      },
    };
  };
  const checkView = (f, index, bytes, layout) => {
    const actual = viewBytes(index);
    if (actual === undefined) fail(f.name('bufferView'), `is ${index} but the package has no such bufferView`);
    if (actual !== bytes) fail(f.name('bufferView'), `(bufferView ${index}) holds ${actual} bytes; ${layout} needs ${bytes}`);
  };

  const root = fields(extension, '');
  const version = root.integer('version', 1, 2 ** 30);
  if (version !== VERSION) throw new Error(`${REVOLUTION_EXTENSION} version ${version} is not known (this plugin reads version ${VERSION})`);
  const p = {};

  const s = root.object('shapeMap');
  const map = {
    width: s.integer('width', 1, 16384),
    height: s.integer('height', 1, 16384),
    texelSize: f32(s.positive('texelSize')),
    hMin: f32(s.number('hMin', -1e30, 1e30)),
    encoding: s.string('encoding'),
    distanceScale: 1,
  };
  if (!(map.encoding in TEXEL_BYTES)) fail('shapeMap.encoding', `is "${map.encoding}"; known: float, unorm16, sqrt8`);
  if (map.encoding !== 'float') map.distanceScale = f32(s.positive('distanceScale'));
  map.bufferView = s.integer('bufferView', 0, 2 ** 30);
  checkView(s, map.bufferView, map.width * map.height * TEXEL_BYTES[map.encoding], `${map.width}x${map.height} RGBA ${map.encoding}`);
  map.rMax = f32(map.width * map.texelSize);
  map.hMax = f32(map.hMin + map.height * map.texelSize);
  p.shapeMap = map;

  p.safetyMargin = f32(root.number('safetyMargin', 0, 1e30));
  const march = root.object('march');
  p.iterations = march.integer('iterations', 1, 4096);
  // omega < 2 keeps the undo test of over-relaxed sphere tracing meaningful.
  p.overRelaxation = f32(march.has('overRelaxation') ? march.number('overRelaxation', 1, 1.999) : DEFAULT_OVER_RELAXATION);
  p.hitEpsilon = f32(march.has('hitEpsilon') ? march.number('hitEpsilon', 0, 1e30) : HIT_EPSILON_TEXELS * map.texelSize);

  p.proxyBands = [];
  if (root.has('proxyBands')) {
    const list = root.at('proxyBands');
    if (!Array.isArray(list)) fail('proxyBands', 'must be a list of [hMin, hMax, rMax]');
    if (list.length > MAX_PROXY_BANDS) fail('proxyBands', `holds ${list.length} bands; at most ${MAX_PROXY_BANDS} are allowed`);
    list.forEach((band, b) => {
      const field = `proxyBands[${b}]`;
      if (!Array.isArray(band) || band.length !== 3) fail(field, 'must be [hMin, hMax, rMax]');
      if (!band.every((v) => typeof v === 'number' && Number.isFinite(v))) fail(field, `must hold three finite numbers, not ${JSON.stringify(band)}`);
      const v = band.map(f32);
      if (!(v[0] < v[1])) fail(field, `has hMin >= hMax: ${JSON.stringify(band)}`);
      if (!(v[2] > 0)) fail(field, `has rMax <= 0: ${JSON.stringify(band)}`);
      p.proxyBands.push(v);
    });
  }

  p.displacement = null;
  if (root.has('displacementMap')) {
    const d = root.object('displacementMap');
    const displacement = {
      width: d.integer('width', 1, 16384),
      height: d.integer('height', 1, 16384),
      derivativeScale: f32(d.number('derivativeScale', 0, 1e30)),
    };
    if (d.has('heightScale')) displacement.heightScale = f32(d.number('heightScale', 0, 1e30));
    displacement.bufferView = d.integer('bufferView', 0, 2 ** 30);
    checkView(d, displacement.bufferView, displacement.width * displacement.height * 4, `${displacement.width}x${displacement.height} RG unorm16`);
    p.displacement = displacement;
  }

  p.projection = 'cylindrical';
  p.repeat = [1, 1];
  p.sphereCentreH = f32(0.5 * (map.hMin + map.hMax));
  if (root.has('projection')) {
    const projection = root.object('projection');
    p.projection = projection.string('type');
    if (!(p.projection in PROJECTION_DEFINES)) fail('projection.type', `is "${p.projection}"; known: cylindrical, spherical, arc-length`);
    if (projection.has('repeat')) {
      const r = projection.at('repeat');
      if (!Array.isArray(r) || r.length !== 2 || !r.every((v) => typeof v === 'number' && Number.isFinite(v) && v > 0))
        fail('projection.repeat', `must be [u, v], two positive numbers, not ${JSON.stringify(r)}`);
      p.repeat = r.map(f32);
    }
    if (projection.has('sphereCentreH')) p.sphereCentreH = f32(projection.number('sphereCentreH', -1e30, 1e30));
  }
  p.arcLengthBufferView = null;
  if (root.has('arcLengthMap')) {
    const a = root.object('arcLengthMap');
    p.arcLengthBufferView = a.integer('bufferView', 0, 2 ** 30);
    checkView(a, p.arcLengthBufferView, map.width * map.height * 2, 'one R unorm16 per shape-map texel');
  }
  if (p.projection === 'arc-length' && p.arcLengthBufferView === null) fail('arcLengthMap', 'is missing; the arc-length projection reads it');

  p.selfShadow = false;
  if (root.has('selfShadow')) {
    if (typeof root.at('selfShadow') !== 'boolean') fail('selfShadow', 'must be true or false');
    p.selfShadow = root.at('selfShadow');
  }
  p.replicas = { layout: 'one', count: [1, 1, 1], spacing: [0, 0, 0], mirror: [0, 0, 0], ringCount: 0, ringRadius: 0 };
  if (root.has('replicas')) {
    const r = root.object('replicas');
    const layout = r.string('layout');
    const replicas = p.replicas;
    if (layout === 'grid') {
      replicas.layout = 'grid';
      if (!r.has('count')) fail('replicas.count', 'is missing');
      const triple = (key, lo, hi) => {
        const v = r.at(key);
        if (!Array.isArray(v) || v.length !== 3 || !v.every((x) => typeof x === 'number' && Number.isFinite(x) && x >= lo && x <= hi))
          fail(`replicas.${key}`, `must be three numbers in [${lo}, ${hi}], not ${JSON.stringify(v)}`);
        return v;
      };
      const count = triple('count', 1, MAX_REPLICAS_PER_AXIS);
      const extent = [f32(2 * map.rMax), f32(map.hMax - map.hMin), f32(2 * map.rMax)];
      if (!count.every(Number.isInteger)) fail('replicas.count', `must hold whole numbers, not ${JSON.stringify(count)}`);
      replicas.count = [...count];
      replicas.spacing = [...extent];
      if (count[0] * count[1] * count[2] > MAX_REPLICAS) fail('replicas.count', `asks for more than ${MAX_REPLICAS} copies`);
      if (r.has('spacing')) {
        const spacing = triple('spacing', 0, 1e30);
        for (let a = 0; a < 3; ++a) {
          if (spacing[a] < extent[a] * (1 - 1e-6))
            fail('replicas.spacing', `is ${JSON.stringify(spacing)}; each must be at least the shape box's extent on its axis (${extent.join(', ')}) so copies do not overlap`);
          replicas.spacing[a] = Math.max(f32(spacing[a]), extent[a]);
        }
      }
      if (r.has('mirror')) {
        const m = r.at('mirror');
        if (!Array.isArray(m) || m.length !== 3 || !m.every((x) => typeof x === 'boolean'))
          fail('replicas.mirror', `must be three booleans (x, y, z), not ${JSON.stringify(m)}`);
        replicas.mirror = m.map((x) => (x ? 1 : 0));
      }
    } else if (layout === 'ring') {
      replicas.layout = 'ring';
      replicas.ringCount = r.integer('count', 2, MAX_REPLICAS_PER_AXIS);
      const radius = r.positive('radius');
      const needed = map.rMax / Math.sin(Math.PI / replicas.ringCount);
      if (radius * Math.sin(Math.PI / replicas.ringCount) < map.rMax * (1 - 1e-6))
        fail('replicas.radius', `is ${radius}; ${replicas.ringCount} copies of radius ${map.rMax} need a ring radius of at least ${needed}`);
      replicas.ringRadius = f32(radius);
    } else {
      fail('replicas.layout', `is "${layout}"; known: grid, ring`);
    }
  }
  return p;
}

// The box the march is rasterised over (RevolutionParams::boxMin/boxMax): one copy's shape box, grown
// to hold every copy.
export function drawnBox(p) {
  const r = p.shapeMap.rMax;
  const { replicas } = p;
  if (replicas.layout === 'ring') {
    const outer = f32(replicas.ringRadius + r);
    return { min: [-outer, p.shapeMap.hMin, -outer], max: [outer, p.shapeMap.hMax, outer] };
  }
  const max = [r, p.shapeMap.hMax, r];
  if (replicas.layout === 'grid') for (let a = 0; a < 3; ++a) max[a] = f32(max[a] + (replicas.count[a] - 1) * replicas.spacing[a]);
  return { min: [-r, p.shapeMap.hMin, -r], max };
}

// Most cells one ray crosses (Replicas::mostCellsCrossed).
function cellBudget(replicas) {
  if (replicas.layout === 'grid') return replicas.count[0] + replicas.count[1] + replicas.count[2] - 2;
  if (replicas.layout === 'ring') return replicas.ringCount + 1;
  return 1;
}

// The box's twelve triangles, counter-clockwise seen from outside (bakeplay's boxPrimitive).
function boxGeometry(box) {
  const corners = [];
  for (let i = 0; i < 8; ++i) {
    corners.push(i & 1 ? box.max[0] : box.min[0], i & 2 ? box.max[1] : box.min[1], i & 4 ? box.max[2] : box.min[2]);
  }
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.Float32BufferAttribute(corners, 3));
  geometry.setIndex([0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5, 0, 1, 5, 0, 5, 4,
    2, 6, 7, 2, 7, 3, 0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6]);
  geometry.computeBoundingBox();
  geometry.computeBoundingSphere();
  return geometry;
}

// A texture of `channels` float32 components from a bufferView's little-endian texels. unorm16 and
// float32 both become float32 (the unorm16 values c / 65535, as the GPU decodes them before filtering).
function dataTexture(bytes, width, height, channels, kind, wrapS, wrapT) {
  let data;
  let type = THREE.FloatType;
  const count = width * height * channels;
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  if (kind === 'float') {
    data = new Float32Array(count);
    for (let i = 0; i < count; ++i) data[i] = view.getFloat32(i * 4, true);
  } else if (kind === 'unorm16') {
    data = new Float32Array(count);
    for (let i = 0; i < count; ++i) data[i] = view.getUint16(i * 2, true) / 65535;
  } else {  // unorm8: filterable as it is
    data = new Uint8Array(bytes.buffer, bytes.byteOffset, count);
    type = THREE.UnsignedByteType;
  }
  const format = { 1: THREE.RedFormat, 2: THREE.RGFormat, 4: THREE.RGBAFormat }[channels];
  const texture = new THREE.DataTexture(data, width, height, format, type);
  texture.wrapS = wrapS;
  texture.wrapT = wrapT;
  texture.minFilter = THREE.LinearFilter;
  texture.magFilter = THREE.LinearFilter;
  texture.generateMipmaps = false;
  texture.flipY = false;          // row 0 is the bottom row (h = hMin, v = 0), as uploaded natively
  texture.unpackAlignment = 1;
  texture.colorSpace = THREE.NoColorSpace;
  texture.needsUpdate = true;
  return texture;
}

// glTF's default material colour is white; bakeplay draws a primitive without material light grey.
function baseColourOf(material) {
  const fallback = isObject(material) ? 1 : 0.8;
  const colour = [fallback, fallback, fallback, 1];
  const factor = material?.pbrMetallicRoughness?.baseColorFactor;
  if (Array.isArray(factor) && factor.length === 4) factor.forEach((v, i) => { if (typeof v === 'number') colour[i] = v; });
  return colour;
}

// Options: light { direction: [x, y, z] towards the light (world), colour: [r, g, b] linear }, read at
// every frame.
export class BakeRevolutionPlugin {
  constructor(parser, options = {}) {
    this.parser = parser;
    this.name = REVOLUTION_EXTENSION;
    this.options = options;
    this.cache = new Map();  // maps shared by several primitives are made once
  }

  async afterRoot(result) {
    const json = this.parser.json;
    const meshes = [];
    result.scene.traverse((object) => { if (object.isMesh) meshes.push(object); });
    const pending = [];
    for (const mesh of meshes) {
      const ref = this.parser.associations.get(mesh);
      if (!ref || ref.meshes === undefined || ref.primitives === undefined) continue;
      const primitive = json.meshes[ref.meshes].primitives[ref.primitives];
      const material = primitive.material !== undefined ? json.materials?.[primitive.material] : undefined;
      const extension = material?.extensions?.[REVOLUTION_EXTENSION];
      if (extension) pending.push(this.attach(mesh, primitive.material, material, extension));
    }
    await Promise.all(pending);
  }

  viewBytes(index) {
    const view = this.parser.json.bufferViews?.[index];
    return view ? view.byteLength : undefined;
  }

  async bufferView(index) {
    return new Uint8Array(await this.parser.getDependency('bufferView', index));
  }

  shared(key, make) {
    if (!this.cache.has(key)) this.cache.set(key, make());
    return this.cache.get(key);
  }

  // The material's base colour image, decoded from its bufferView as bakeplay does (whatever the
  // glTF sampler says: sRGB, repeating, trilinear mipmaps); null without one.
  async baseColourTexture(material) {
    const info = material?.pbrMetallicRoughness?.baseColorTexture;
    if (!info) return null;
    const json = this.parser.json;
    const texture = json.textures?.[info.index];
    if (!texture) throw new Error('pbrMetallicRoughness.baseColorTexture names no texture of the package');
    const image = json.images?.[texture.source];
    if (!image) throw new Error(`texture ${info.index} has no image source`);
    if (image.bufferView === undefined) throw new Error(`image ${texture.source} (base colour) is not embedded in a bufferView`);
    const bytes = await this.bufferView(image.bufferView);
    const bitmap = await createImageBitmap(new Blob([bytes], { type: image.mimeType ?? 'image/png' }),
      { premultiplyAlpha: 'none', colorSpaceConversion: 'none', imageOrientation: 'none' });
    const result = new THREE.Texture(bitmap);
    result.flipY = false;  // the image's top row first, as bakeplay uploads it; the shader samples 1 - v
    result.colorSpace = THREE.SRGBColorSpace;
    result.wrapS = THREE.RepeatWrapping;
    result.wrapT = THREE.RepeatWrapping;
    result.minFilter = THREE.LinearMipmapLinearFilter;
    result.magFilter = THREE.LinearFilter;
    result.generateMipmaps = true;
    result.needsUpdate = true;
    return result;
  }

  async attach(mesh, materialIndex, material, extension) {
    const p = parseRevolution(extension, (i) => this.viewBytes(i));
    const map = p.shapeMap;
    const defines = {
      [ENCODING_DEFINES[map.encoding]]: '',
      [PROJECTION_DEFINES[p.projection]]: '',
      MAX_PROXY_BANDS,
    };
    if (p.replicas.layout === 'grid') defines.REPLICAS_GRID = '';
    if (p.replicas.layout === 'ring') defines.REPLICAS_RING = '';
    if (p.selfShadow) defines.SELF_SHADOW = '';

    const shapeKind = map.encoding === 'sqrt8' ? 'unorm8' : map.encoding;
    const shapeMap = await this.shared(`view ${map.bufferView} shape`, async () =>
      dataTexture(await this.bufferView(map.bufferView), map.width, map.height, 4, shapeKind,
        THREE.MirroredRepeatWrapping, THREE.ClampToEdgeWrapping));
    let displacementMap = null, arcLengthMap = null, colourMap = null;
    if (p.displacement) {
      defines.HAS_DISPLACEMENT = '';
      const d = p.displacement;
      displacementMap = await this.shared(`view ${d.bufferView} displacement`, async () =>
        dataTexture(await this.bufferView(d.bufferView), d.width, d.height, 2, 'unorm16',
          THREE.RepeatWrapping, THREE.RepeatWrapping));
    }
    if (p.projection === 'arc-length') {
      arcLengthMap = await this.shared(`view ${p.arcLengthBufferView} arc length`, async () =>
        dataTexture(await this.bufferView(p.arcLengthBufferView), map.width, map.height, 1, 'unorm16',
          THREE.MirroredRepeatWrapping, THREE.ClampToEdgeWrapping));
    }
    colourMap = await this.shared(`material ${materialIndex} colour`, () => this.baseColourTexture(material));
    if (colourMap) defines.HAS_BASE_COLOR_TEXTURE = '';

    const box = drawnBox(p);
    for (let a = 0; a < 3; ++a) if (!(box.min[a] < box.max[a])) throw new Error("the shape map's box is empty");
    const bands = new Float32Array(MAX_PROXY_BANDS * 3);
    p.proxyBands.forEach((band, i) => bands.set(band, i * 3));
    const r = p.replicas;
    const uniforms = {
      uObjectToClip: { value: new THREE.Matrix4() },
      uClipToObject: { value: new THREE.Matrix4() },
      uModel: { value: new THREE.Matrix4() },
      uNormalMatrix: { value: new THREE.Matrix3() },
      uViewport: { value: new THREE.Vector2(1, 1) },
      uShapeGrid: { value: new THREE.Vector4(map.width, map.height, map.texelSize, map.hMin) },
      uDistanceScale: { value: map.distanceScale },
      uSafetyMargin: { value: p.safetyMargin },
      uHitEpsilon: { value: p.hitEpsilon },
      uOverRelaxation: { value: p.overRelaxation },
      uIterations: { value: p.iterations },
      uBoxMin: { value: new THREE.Vector3(-map.rMax, map.hMin, -map.rMax) },
      uBoxMax: { value: new THREE.Vector3(map.rMax, map.hMax, map.rMax) },
      uReplicaBoxMin: { value: new THREE.Vector3(...box.min) },
      uReplicaBoxMax: { value: new THREE.Vector3(...box.max) },
      uGridCount: { value: Int32Array.from(r.count) },
      uGridSpacing: { value: new THREE.Vector3(...r.spacing) },
      uGridMirror: { value: Int32Array.from(r.mirror) },
      uRingCount: { value: r.ringCount },
      uRingRadius: { value: r.ringRadius },
      uCellBudget: { value: cellBudget(r) },
      uBandCount: { value: p.proxyBands.length },
      uBands: { value: bands },
      uRepeat: { value: new THREE.Vector2(...p.repeat) },
      uSphereCentreH: { value: p.sphereCentreH },
      uDerivativeScale: { value: p.displacement ? p.displacement.derivativeScale : 0 },
      uBaseColor: { value: new THREE.Vector4(...baseColourOf(material)) },
      uLightDir: { value: new THREE.Vector3() },
      uLightColour: { value: new THREE.Vector3(1, 1, 1) },
      uCameraPos: { value: new THREE.Vector3() },
      uLightDirObject: { value: new THREE.Vector3() },
      uShapeMap: { value: shapeMap },
      uDisplacementMap: { value: displacementMap },
      uArcLengthMap: { value: arcLengthMap },
      uBaseColorTexture: { value: colourMap },
    };

    const options = this.options;
    const viewport = new THREE.Vector4();
    const toObject = new THREE.Matrix3();
    let checked = false;
    const update = (renderer, camera) => {
      if (!checked) {
        checked = true;
        // Without linear filtering of float textures the march would read the nearest texel only.
        if ((map.encoding !== 'sqrt8' || p.displacement || arcLengthMap) && !renderer.extensions.has('OES_texture_float_linear'))
          console.warn(`${REVOLUTION_EXTENSION}: this WebGL2 context lacks OES_texture_float_linear; shape maps will not be filtered`);
      }
      mesh.updateWorldMatrix(true, false);
      const world = mesh.matrixWorld;
      const u = uniforms;
      u.uObjectToClip.value.multiplyMatrices(camera.projectionMatrix, camera.matrixWorldInverse).multiply(world);
      u.uClipToObject.value.copy(u.uObjectToClip.value).invert();  // in double, as bakeplay does
      u.uModel.value.copy(world);
      u.uNormalMatrix.value.getNormalMatrix(world);
      // The shader rebuilds rays from gl_FragCoord over the viewport's size: the viewport must start at
      // the origin of the drawing buffer (as bakeplay's does).
      renderer.getCurrentViewport(viewport);
      u.uViewport.value.set(viewport.z, viewport.w);
      const light = options.light ?? {};
      u.uLightDir.value.fromArray(light.direction ?? [0.4, 0.8, 0.45]).normalize();
      u.uLightColour.value.fromArray(light.colour ?? [1, 1, 1]);
      // Directions go to object space by the inverse of the model's linear part, the normal matrix's
      // transpose.
      toObject.copy(u.uNormalMatrix.value).transpose();
      u.uLightDirObject.value.copy(u.uLightDir.value).applyMatrix3(toObject).normalize();
      u.uCameraPos.value.setFromMatrixPosition(camera.matrixWorld);
    };

    const shaderMaterial = new THREE.RawShaderMaterial({
      name: `${REVOLUTION_EXTENSION} ${material?.name ?? materialIndex}`,
      glslVersion: THREE.GLSL3,
      vertexShader,
      fragmentShader,
      defines,
      uniforms,
      // Back faces only: every ray through the box gets one fragment, even from inside the box. three.js
      // flips the winding itself under a mirroring transform, as bakeplay does.
      side: THREE.BackSide,
      depthFunc: THREE.LessDepth,
    });
    const preview = mesh.geometry;
    preview.computeBoundingBox();
    mesh.userData.bakeRevolution = { params: p, previewBounds: preview.boundingBox.clone() };
    mesh.geometry = boxGeometry(box);
    mesh.material = shaderMaterial;
    mesh.onBeforeRender = (renderer, scene, camera) => update(renderer, camera);
  }
}
