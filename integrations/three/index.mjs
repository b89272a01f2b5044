// three.js GLTFLoader plugin for BAKE_geodesic packages: every primitive with geodesic fields is drawn
// with a GeoTexture preset, using the project's own GLSL (generated/geotexture-shaders.mjs) and the
// uniform values bakeplay sets (runtime/render/geodesic.cpp, formats/geodesic-material.md).
// WebGL2 only. The materials write linear colour; present it with LinearToSrgbPresenter (or any
// linear float target plus an sRGB encode) so the bytes match bakeplay's PNGs.
import * as THREE from 'three';
import { fragmentShader, vertexShader } from './generated/geotexture-shaders.mjs';
export { BakeHatchingPlugin } from './hatching.mjs';
export { BakeRevolutionPlugin } from './revolution.mjs';

export const EXTENSION = 'BAKE_geodesic';
const ATTRIBUTE_PREFIX = '_GEODESIC_';
const MAX_FIELDS = 64;
const MAX_SLOTS = 4;

const PRESET_DEFINES = {
  isolines: 'PRESET_ISOLINES',
  'sand-water': 'PRESET_SAND_WATER',
  'moss-granite': 'PRESET_MOSS_GRANITE',
  'paint-metal-rust': 'PRESET_PAINT_METAL_RUST',
  'water-lava': 'PRESET_WATER_LAVA',
  'opacity-front': 'PRESET_OPACITY_FRONT',
  'wave-displacement': 'PRESET_WAVE',
};
export const presetNames = Object.keys(PRESET_DEFINES);

const same4 = (v) => [v, v, v, v];

// The preset's defaults (geoPresetDefaults in libbake).
export function geoPresetDefaults(preset) {
  const p = {
    preset,
    fields: [0],
    fieldsGiven: false,
    combineMin: false,
    thresholds: same4(0.3),
    widths: same4(0.02),
    speed: 0,
    noiseFrequency: 8,
    noiseAmplitude: 0,
    patternScale: 1,
    bumpScale: 1,
    colours: [[0, 0, 0], [0, 0, 0], [0, 0, 0], [0, 0, 0]],
    unreachableColour: [1, 0, 1],
    isolineSpacing: 0.05,
    isolineWidth: 1.5,
    isolineColour: [0.02, 0.02, 0.02],
    opacity: 0.2,
    wave: { amplitude: 0.04, wavelength: 0.05, reach: 0.3, displace: true, pixelsPerEdge: 6, maxLevel: 16 },
  };
  const colours = (...list) => list.forEach((c, i) => { p.colours[i] = c; });
  switch (preset) {
    case 'sand-water':
      p.thresholds = same4(0.25);
      p.noiseFrequency = 12; p.noiseAmplitude = 0.01;
      colours([0.76, 0.62, 0.38], [0.05, 0.30, 0.28]);
      break;
    case 'moss-granite':
      p.thresholds = same4(0.3); p.widths = same4(0.04);
      p.noiseFrequency = 8; p.noiseAmplitude = 0.04;
      colours([0.16, 0.30, 0.05], [0.52, 0.50, 0.47]);
      break;
    case 'paint-metal-rust':
      p.thresholds = [0.1, 0.25, 0.4, 0.4]; p.widths = [0.01, 0.03, 0.01, 0.01];
      p.noiseFrequency = 25; p.noiseAmplitude = 0.04;
      colours([0, 0, 0], [0.42, 0.15, 0.04], [0.55, 0.56, 0.58], [0.06, 0.16, 0.55]);
      break;
    case 'water-lava':
      p.fields = [0, 1];
      p.thresholds = [0.25, 0.35, 0.35, 0.35]; p.widths = [0.02, 0.03, 0.03, 0.03];
      p.noiseFrequency = 4; p.noiseAmplitude = 0.05;
      colours([0.04, 0.22, 0.42], [1.0, 0.33, 0.04], [0.11, 0.09, 0.08]);
      break;
    case 'opacity-front':
      p.thresholds = same4(0.3);
      colours([0.80, 0.74, 0.64], [0.30, 0.50, 0.80]);
      break;
    case 'wave-displacement':
      p.thresholds = same4(0.4);
      colours([0.22, 0.42, 0.58], [0.85, 0.90, 0.95]);
      break;
    default:
      break;
  }
  return p;
}

// A material's BAKE_geodesic object -> parameters (parseGeoTexture in libbake): every key optional,
// wrong types and out-of-range values throw, unknown keys are ignored.
export function parseGeoTexture(extension) {
  const fail = (message) => { throw new Error(`BAKE_geodesic material: ${message}`); };
  if (!isObject(extension)) fail('must be an object');
  const name = 'texture' in extension ? extension.texture : 'isolines';
  if (typeof name !== 'string' || !(name in PRESET_DEFINES))
    fail(`unknown texture "${name}" (known: ${presetNames.join(', ')})`);
  const p = geoPresetDefaults(name);
  const number = (object, key, path, lo, hi) => {
    if (!(key in object)) return undefined;
    const v = object[key];
    if (typeof v !== 'number' || !Number.isFinite(v) || v < lo || v > hi) fail(`${path} must be a number in [${lo}, ${hi}]`);
    return v;
  };
  const colour = (value, path) => {
    if (!Array.isArray(value) || (value.length !== 3 && value.length !== 4)) fail(`${path} must be [r, g, b] (linear)`);
    for (let c = 0; c < 3; ++c)
      if (typeof value[c] !== 'number' || value[c] < 0 || value[c] > 1) fail(`${path} components must be numbers in [0, 1]`);
    return value.slice(0, 3);
  };
  const numbers = (key, lo, hi, out) => {
    if (!(key in extension)) return;
    const list = extension[key];
    if (!Array.isArray(list) || list.length === 0 || list.length > 4) fail(`${key} must be a list of 1 to 4 numbers`);
    list.forEach((v, i) => {
      if (typeof v !== 'number' || v < lo || v > hi) fail(`${key}[${i}] must be a number in [${lo}, ${hi}]`);
      out[i] = v;
    });
    for (let i = list.length; i < 4; ++i) out[i] = out[list.length - 1];  // the last repeats
  };
  const object = (key) => {
    if (key in extension && !isObject(extension[key])) fail(`${key} must be an object`);
    return isObject(extension[key]) ? extension[key] : {};
  };
  const set = (value, apply) => { if (value !== undefined) apply(value); };

  if ('combine' in extension) {
    if (extension.combine !== 'min' && extension.combine !== 'separate') fail('combine must be "separate" or "min"');
    p.combineMin = extension.combine === 'min';
  }
  if ('fields' in extension) {
    const list = extension.fields;
    if (!Array.isArray(list) || list.length === 0 || list.length > MAX_SLOTS) fail('fields must be a list of 1 to 4 field indices');
    for (const f of list)
      if (!Number.isInteger(f) || f < 0 || f >= MAX_FIELDS) fail(`fields must hold integers 0 to ${MAX_FIELDS - 1}`);
    p.fields = [...list];
    p.fieldsGiven = true;
  }
  if (!p.combineMin && p.fields.length > 2)
    fail('a preset reads at most two separate fields; merge more with "combine": "min"');
  numbers('thresholds', -10, 10, p.thresholds);
  numbers('widths', 0, 10, p.widths);
  set(number(extension, 'speed', 'speed', -100, 100), (v) => { p.speed = v; });
  const noise = object('frontNoise');
  set(number(noise, 'frequency', 'frontNoise.frequency', 0, 1e4), (v) => { p.noiseFrequency = v; });
  set(number(noise, 'amplitude', 'frontNoise.amplitude', 0, 10), (v) => { p.noiseAmplitude = v; });
  set(number(extension, 'patternScale', 'patternScale', 1e-3, 1e3), (v) => { p.patternScale = v; });
  set(number(extension, 'bumpScale', 'bumpScale', 0, 100), (v) => { p.bumpScale = v; });
  if ('colors' in extension) {
    const list = extension.colors;
    if (!Array.isArray(list) || list.length > 4) fail('colors must be a list of up to 4 [r, g, b]');
    list.forEach((c, i) => { p.colours[i] = colour(c, `colors[${i}]`); });
  }
  if ('unreachableColor' in extension) p.unreachableColour = colour(extension.unreachableColor, 'unreachableColor');
  const isolines = object('isolines');
  if ('color' in isolines) p.isolineColour = colour(isolines.color, 'isolines.color');
  set(number(isolines, 'spacing', 'isolines.spacing', 1e-3, 1), (v) => { p.isolineSpacing = v; });
  set(number(isolines, 'width', 'isolines.width', 0, 64), (v) => { p.isolineWidth = v; });
  set(number(extension, 'opacity', 'opacity', 0, 1), (v) => { p.opacity = v; });
  const wave = object('wave');
  set(number(wave, 'amplitude', 'wave.amplitude', -1, 1), (v) => { p.wave.amplitude = v; });
  set(number(wave, 'wavelength', 'wave.wavelength', 1e-4, 10), (v) => { p.wave.wavelength = v; });
  set(number(wave, 'reach', 'wave.reach', 1e-4, 10), (v) => { p.wave.reach = v; });
  set(number(wave, 'pixelsPerEdge', 'wave.pixelsPerEdge', 1, 1000), (v) => { p.wave.pixelsPerEdge = v; });
  set(number(wave, 'maxLevel', 'wave.maxLevel', 1, 64), (v) => { p.wave.maxLevel = v; });
  if ('displace' in wave) {
    if (typeof wave.displace !== 'boolean') fail('wave.displace must be true or false');
    p.wave.displace = wave.displace;
  }
  return p;
}

function isObject(v) { return v !== null && typeof v === 'object' && !Array.isArray(v); }

function fieldIndexOf(name) {
  const m = /^_GEODESIC_(\d{1,3})$/.exec(name);
  return m ? Number(m[1]) : undefined;
}

// The field attributes a material reads on one primitive (resolveFields in libbake): the list it
// gives, or the preset's default list trimmed to the fields present; distinct, in order.
export function resolveFields(params, present) {
  let fields = [...params.fields];
  if (!params.fieldsGiven) {
    fields = fields.filter((f) => present.includes(f));
    if (fields.length === 0) fields.push(params.fields[0]);
  }
  for (const f of fields) {
    if (!present.includes(f))
      throw new Error(`the material reads geodesic field ${f} but the primitive has no ${ATTRIBUTE_PREFIX}${f} attribute`);
  }
  return [...new Set(fields)];
}

// Stored value -> normalised distance: 1, or 1 / maxDistance when the package stores model units.
function normalisingFactor(root, attribute) {
  if (!isObject(root) || root.normalization !== 'none') return 1;
  for (const field of Array.isArray(root.fields) ? root.fields : []) {
    if (isObject(field) && field.attribute === attribute) {
      return field.maxDistance > 0 ? 1 / field.maxDistance : 1;
    }
  }
  return 1;
}

// Bounding-box centre and the bounding-sphere radius around it, object space (noise space).
function boundsOf(position) {
  const lo = new THREE.Vector3(Infinity, Infinity, Infinity), hi = lo.clone().negate();
  const v = new THREE.Vector3();
  for (let i = 0; i < position.count; ++i) { v.fromBufferAttribute(position, i); lo.min(v); hi.max(v); }
  if (position.count === 0) return { centre: new THREE.Vector3(), radius: 1 };
  const centre = lo.add(hi).multiplyScalar(0.5);
  let radius = 0;
  for (let i = 0; i < position.count; ++i) radius = Math.max(radius, v.fromBufferAttribute(position, i).distanceTo(centre));
  return { centre, radius: radius > 0 ? radius : 1 };
}

function largestAxisScale(m) {
  const e = m.elements;
  let s = 0;
  for (let c = 0; c < 3; ++c) s = Math.max(s, Math.hypot(e[c * 4], e[c * 4 + 1], e[c * 4 + 2]));
  return s > 0 ? s : 1;
}

const vec3 = (a) => new THREE.Vector3(a[0], a[1], a[2]);

// Options: preset (draw every field-carrying primitive with this preset, as bakeplay --geotexture),
// light { direction: [x, y, z] towards the light, colour: [r, g, b] linear }, time (seconds).
// `options` is read at every frame, so changing time or light later takes effect.
export class BakeGeodesicPlugin {
  constructor(parser, options = {}) {
    this.parser = parser;
    this.name = EXTENSION;
    this.options = options;
    if (options.preset !== undefined && !(options.preset in PRESET_DEFINES))
      throw new Error(`preset "${options.preset}" is not a GeoTexture preset (known: ${presetNames.join(', ')})`);
  }

  afterRoot(result) {
    const json = this.parser.json;
    const root = json.extensions?.[EXTENSION];
    const meshes = [];
    result.scene.traverse((object) => { if (object.isMesh) meshes.push(object); });
    for (const mesh of meshes) {
      const ref = this.parser.associations.get(mesh);
      if (!ref || ref.meshes === undefined || ref.primitives === undefined) continue;
      const primitive = json.meshes[ref.meshes].primitives[ref.primitives];
      const extension = this.materialExtension(primitive, root);
      if (extension) this.attach(mesh, primitive, extension, root);
    }
  }

  // The BAKE_geodesic object that applies to a primitive, as bakeplay chooses it; null: not drawn here.
  materialExtension(primitive, root) {
    const present = Object.keys(primitive.attributes).filter((a) => fieldIndexOf(a) !== undefined);
    if (present.length === 0) return null;
    const material = primitive.material !== undefined ? this.parser.json.materials?.[primitive.material] : undefined;
    const extensions = material?.extensions ?? {};
    const preset = this.options.preset;
    if (extensions[EXTENSION]) return preset ? { ...extensions[EXTENSION], texture: preset } : extensions[EXTENSION];
    // Another technique owns the material; a bare primitive gets the default only in a BAKE_geodesic package.
    if (Object.keys(extensions).some((e) => e.startsWith('BAKE_'))) return null;
    if (!preset && !root) return null;
    return { version: 1, texture: preset ?? 'isolines' };
  }

  attach(mesh, primitive, extension, root) {
    const params = parseGeoTexture(extension);
    const present = Object.keys(primitive.attributes).map(fieldIndexOf).filter((k) => k !== undefined);
    const fields = resolveFields(params, present);
    const source = mesh.geometry;
    const geometry = new THREE.BufferGeometry();  // shares the buffers, adds the slot aliases
    geometry.setIndex(source.index);
    for (const [name, attribute] of Object.entries(source.attributes)) geometry.setAttribute(name, attribute);
    for (const group of source.groups) geometry.addGroup(group.start, group.count, group.materialIndex);

    const defines = { [PRESET_DEFINES[params.preset]]: '', FIELD_COUNT: fields.length };
    if (params.combineMin) defines.COMBINE_MIN = '';
    if (geometry.getAttribute('normal')) defines.HAS_NORMALS = '';
    const fieldScale = new THREE.Vector4(1, 1, 1, 1);
    let unorm = false;
    fields.forEach((k, slot) => {
      const name = `${ATTRIBUTE_PREFIX}${k}`;
      const attribute = source.getAttribute(name.toLowerCase());
      if (!attribute || attribute.itemSize !== 1) throw new Error(`${name} must be a SCALAR attribute`);
      const isUnorm = attribute.array instanceof Uint16Array && attribute.normalized;
      if (!isUnorm && !(attribute.array instanceof Float32Array))
        throw new Error(`${name} must be SCALAR FLOAT or normalized UNSIGNED_SHORT`);
      if (slot > 0 && isUnorm !== unorm) throw new Error('the fields a material reads mix encodings');
      unorm = isUnorm;
      fieldScale.setComponent(slot, normalisingFactor(root, name));
      geometry.setAttribute(`aField${slot}`, attribute);
    });
    if (unorm) defines.FIELD_UNORM16 = '';
    // No tessellation in WebGL2: wave-displacement bumps the normal only (bakeplay's displace: false).
    const translucent = params.preset === 'opacity-front';
    if (translucent) defines.TRANSLUCENT = '';

    const { centre, radius } = boundsOf(geometry.getAttribute('position'));
    const p = params;
    const uniforms = {
      uModel: { value: new THREE.Matrix4() },
      uViewProj: { value: new THREE.Matrix4() },
      uNormalMatrix: { value: new THREE.Matrix3() },
      uLightDir: { value: new THREE.Vector3() },
      uLightColour: { value: new THREE.Vector3(1, 1, 1) },
      uCameraPos: { value: new THREE.Vector3() },
      uObjectCentre: { value: centre },
      uObjectRadius: { value: radius },
      uHeightScale: { value: radius },
      uFieldScale: { value: fieldScale },
      uTime: { value: 0 },
      uSpeed: { value: p.speed },
      uThresholds: { value: new THREE.Vector4(...p.thresholds) },
      uWidths: { value: new THREE.Vector4(...p.widths) },
      uFrontNoise: { value: new THREE.Vector2(p.noiseFrequency, p.noiseAmplitude) },
      uPatternScale: { value: p.patternScale },
      uBumpScale: { value: p.bumpScale },
      uColours: { value: p.colours.map(vec3) },
      uUnreachableColour: { value: vec3(p.unreachableColour) },
      uIsolineSpacing: { value: p.isolineSpacing },
      uIsolineWidth: { value: p.isolineWidth },
      uIsolineColour: { value: vec3(p.isolineColour) },
      uOpacity: { value: p.opacity },
      uWave: { value: new THREE.Vector4(p.wave.amplitude, p.wave.wavelength, p.wave.reach, 0) },
      uWaveFront0: { value: p.thresholds[0] },
      uWaveFront1: { value: p.thresholds[1] },
      uPass: { value: 0 },
    };
    const options = this.options;
    const update = (object, camera) => {
      object.updateWorldMatrix(true, false);
      uniforms.uModel.value.copy(object.matrixWorld);
      uniforms.uNormalMatrix.value.getNormalMatrix(object.matrixWorld);
      uniforms.uViewProj.value.multiplyMatrices(camera.projectionMatrix, camera.matrixWorldInverse);
      uniforms.uCameraPos.value.setFromMatrixPosition(camera.matrixWorld);
      uniforms.uHeightScale.value = radius * largestAxisScale(object.matrixWorld);
      const light = options.light ?? {};
      uniforms.uLightDir.value.fromArray(light.direction ?? [0.4, 0.8, 0.45]).normalize();
      uniforms.uLightColour.value.fromArray(light.colour ?? [1, 1, 1]);
      const time = options.time ?? 0;
      uniforms.uTime.value = time;
      uniforms.uWaveFront0.value = p.thresholds[0] + p.speed * time;
      uniforms.uWaveFront1.value = p.thresholds[1] + p.speed * time;
    };
    // bakeplay draws both faces with depth test LESS and no culling.
    const makeMaterial = (pass) => {
      const material = new THREE.RawShaderMaterial({
        name: `BAKE_geodesic ${p.preset}${pass ? ' (translucent)' : ''}`,
        glslVersion: THREE.GLSL3,
        vertexShader,
        fragmentShader,
        defines,
        uniforms: { ...uniforms, uPass: { value: pass } },
        side: THREE.DoubleSide,
        depthFunc: THREE.LessDepth,
      });
      if (pass === 1) {
        // Blended over the opaque pass, without depth writes; destination alpha is kept.
        Object.assign(material, {
          transparent: true,
          depthWrite: false,
          blending: THREE.CustomBlending,
          blendSrc: THREE.SrcAlphaFactor,
          blendDst: THREE.OneMinusSrcAlphaFactor,
          blendSrcAlpha: THREE.ZeroFactor,
          blendDstAlpha: THREE.OneFactor,
        });
      }
      return material;
    };
    mesh.geometry = geometry;
    mesh.material = makeMaterial(0);
    mesh.userData.bakeGeodesic = { params, fields };
    mesh.onBeforeRender = (renderer, scene, camera) => update(mesh, camera);
    if (translucent) {
      const second = new THREE.Mesh(geometry, makeMaterial(1));
      second.name = `${mesh.name} (translucent)`;
      second.onBeforeRender = (renderer, scene, camera) => update(mesh, camera);
      mesh.add(second);
    }
  }
}

// Renders linear colour into a half-float target and encodes it to sRGB on the canvas (clamped, the
// exact sRGB curve, no tone mapping), as bakeplay does before writing 8-bit PNGs.
export class LinearToSrgbPresenter {
  constructor(renderer, { clearColour = [0.06, 0.065, 0.075] } = {}) {
    this.renderer = renderer;
    this.clearColour = new THREE.Color().setRGB(...clearColour, THREE.LinearSRGBColorSpace);
    const size = renderer.getDrawingBufferSize(new THREE.Vector2());
    this.target = new THREE.WebGLRenderTarget(size.x, size.y, {
      type: THREE.HalfFloatType,
      format: THREE.RGBAFormat,
      depthBuffer: true,
      minFilter: THREE.NearestFilter,
      magFilter: THREE.NearestFilter,
      generateMipmaps: false,
    });
    this.material = new THREE.RawShaderMaterial({
      glslVersion: THREE.GLSL3,
      uniforms: { uLinear: { value: this.target.texture } },
      vertexShader: `precision highp float;
in vec3 position;
void main() { gl_Position = vec4(position.xy, 0.0, 1.0); }`,
      fragmentShader: `precision highp float;
uniform sampler2D uLinear;
out vec4 fragColor;
vec3 encode(vec3 c) {
  c = clamp(c, 0.0, 1.0);
  return mix(1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, c * 12.92, vec3(lessThanEqual(c, vec3(0.0031308))));
}
void main() { fragColor = vec4(encode(texelFetch(uLinear, ivec2(gl_FragCoord.xy), 0).rgb), 1.0); }`,
      depthTest: false,
      depthWrite: false,
    });
    const triangle = new THREE.BufferGeometry();
    triangle.setAttribute('position', new THREE.Float32BufferAttribute([-1, -1, 0, 3, -1, 0, -1, 3, 0], 3));
    this.quad = new THREE.Mesh(triangle, this.material);
    this.quad.frustumCulled = false;
    this.quadCamera = new THREE.OrthographicCamera();
  }

  render(scene, camera) {
    const r = this.renderer;
    const size = r.getDrawingBufferSize(new THREE.Vector2());
    if (size.x !== this.target.width || size.y !== this.target.height) this.target.setSize(size.x, size.y);
    const previous = { target: r.getRenderTarget(), clear: r.getClearColor(new THREE.Color()), alpha: r.getClearAlpha() };
    r.setRenderTarget(this.target);
    r.setClearColor(this.clearColour, 1);
    r.clear(true, true, true);
    r.render(scene, camera);
    r.setRenderTarget(null);
    r.render(this.quad, this.quadCamera);
    r.setRenderTarget(previous.target);
    r.setClearColor(previous.clear, previous.alpha);
  }

  dispose() {
    this.target.dispose();
    this.material.dispose();
    this.quad.geometry.dispose();
  }
}

// The camera bakeplay builds for `--camera EYE:TARGET` on a scene with these world bounds: vertical
// field of view 0.7 rad, up +Y, near = reach * 1e-4 and far = reach * 2, where reach is the eye's
// distance to the target plus the bounds' diagonal.
export function bakeplayCamera(eye, target, aspect, bounds) {
  const e = vec3(eye), t = vec3(target);
  const reach = e.distanceTo(t) + bounds.max.distanceTo(bounds.min);
  const camera = new THREE.PerspectiveCamera(THREE.MathUtils.radToDeg(0.7), aspect, reach * 1e-4, reach * 2);
  camera.up.set(0, 1, 0);
  camera.position.copy(e);
  camera.lookAt(t);
  camera.updateMatrixWorld();
  camera.updateProjectionMatrix();
  return camera;
}
