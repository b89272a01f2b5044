// glTF-Transform extensions for the bake toolchain's BAKE_* glTF extensions (formats/*.md), so that
// gltf-transform and scripts built on @gltf-transform/core read, copy, prune, deduplicate and write
// our packages with the baked data intact.
//
// Every BAKE_* object refers to binary data by index: a "bufferView" number (BAKE_revolution's maps),
// an object of them ("bufferViews": BAKE_grooves' and BAKE_paintstrokes' arrays), or an image index
// (BAKE_hatching's "tam" and "threshold"). glTF-Transform renumbers and repacks buffers and images on
// every write, so each extension keeps the bytes of its bufferViews and references to its images
// (which keeps them through `prune`), and writes the object back with the new indices. Everything
// else in the object is kept as it was read. Vertex attributes (_GEODESIC_k) are glTF-Transform's own.
//
// Usage, with the caller's own @gltf-transform/core (no second copy of it is loaded):
//   import * as core from '@gltf-transform/core';
//   import { createBakeExtensions } from 'bake-gltf-transform';
//   const io = new core.NodeIO().registerExtensions(createBakeExtensions(core));
// As a gltf-transform --config module: see config.example.mjs.

// Where each extension keeps its references (formats/*.md).
const LAYOUTS = {
  BAKE_geodesic: { levels: ['root', 'material'], bufferViewKeys: [], imageKeys: [] },
  BAKE_revolution: { levels: ['material'], bufferViewKeys: ['bufferView'], imageKeys: [] },
  BAKE_hatching: { levels: ['material'], bufferViewKeys: [], imageKeys: ['tam', 'threshold'] },
  BAKE_grooves: { levels: ['material'], bufferViewKeys: ['bufferViews'], imageKeys: [] },
  BAKE_paintstrokes: { levels: ['material'], bufferViewKeys: ['bufferViews'], imageKeys: [] },
};

export const BAKE_EXTENSION_NAMES = Object.keys(LAYOUTS);

// The paths (arrays of keys) of every bufferView index in `value`: a number under a key named in
// `keys`, or each number of an object under such a key.
function bufferViewPaths(value, keys, path = [], out = []) {
  if (Array.isArray(value)) {
    value.forEach((item, i) => bufferViewPaths(item, keys, [...path, i], out));
  } else if (value !== null && typeof value === 'object') {
    for (const [key, child] of Object.entries(value)) {
      if (keys.includes(key) && Number.isInteger(child)) out.push([...path, key]);
      else if (keys.includes(key) && child !== null && typeof child === 'object' && !Array.isArray(child)) {
        for (const [name, index] of Object.entries(child)) if (Number.isInteger(index)) out.push([...path, key, name]);
      } else bufferViewPaths(child, keys, [...path, key], out);
    }
  }
  return out;
}

function getPath(value, path) {
  return path.reduce((node, key) => node[key], value);
}

function setPath(value, path, replacement) {
  getPath(value, path.slice(0, -1))[path[path.length - 1]] = replacement;
}

export function createBakeExtensions(core) {
  const { Extension, ExtensionProperty, PropertyType, RefList } = core;
  return BAKE_EXTENSION_NAMES.map((name) => {
    const layout = LAYOUTS[name];

    // One BAKE_* object: its JSON (indices left as read), the bytes of each bufferView it names (in
    // the order of `paths`), and the images it names (in the order of layout.imageKeys present).
    class BakeData extends ExtensionProperty {
      static EXTENSION_NAME = name;
      init() {
        this.extensionName = name;
        this.propertyType = `${name}Data`;
        this.parentTypes = [PropertyType.ROOT, PropertyType.MATERIAL];
      }
      getDefaults() {
        return Object.assign(super.getDefaults(), { body: {}, paths: [], blobs: [], imageKeys: [], images: new RefList() });
      }
    }

    class BakeExtension extends Extension {
      static EXTENSION_NAME = name;
      extensionName = name;
      prewriteTypes = [PropertyType.BUFFER];

      read(context) {
        const json = context.jsonDoc.json;
        const take = (body) => {
          const data = new BakeData(this.document.getGraph());
          const copy = structuredClone(body);
          const paths = bufferViewPaths(copy, layout.bufferViewKeys);
          const blobs = paths.map((path) => {
            const index = getPath(copy, path);
            const bytes = context.bufferViews[index];
            if (!bytes) throw new Error(`${name}: bufferView ${index} does not exist`);
            return bytes.slice();
          });
          data.set('body', copy).set('paths', paths).set('blobs', blobs);
          const imageKeys = layout.imageKeys.filter((key) => Number.isInteger(copy[key]));
          data.set('imageKeys', imageKeys);
          for (const key of imageKeys) {
            const texture = context.textures[copy[key]];
            if (!texture) throw new Error(`${name}: image ${copy[key]} does not exist`);
            data.addRef('images', texture);
          }
          return data;
        };
        if (layout.levels.includes('root') && json.extensions && json.extensions[name]) {
          this.document.getRoot().setExtension(name, take(json.extensions[name]));
        }
        if (layout.levels.includes('material')) {
          (json.materials || []).forEach((materialDef, index) => {
            if (materialDef.extensions && materialDef.extensions[name]) {
              context.materials[index].setExtension(name, take(materialDef.extensions[name]));
            }
          });
        }
        return this;
      }

      // The bytes go into the document's first buffer before it is laid out, as extra bufferViews.
      prewrite(context) {
        const buffer = this.document.getRoot().listBuffers()[0];
        for (const data of this.dataInUse()) {
          if (!context.otherBufferViews.has(buffer)) context.otherBufferViews.set(buffer, []);
          context.otherBufferViews.get(buffer).push(...data.get('blobs'));
        }
        return this;
      }

      write(context) {
        const json = context.jsonDoc.json;
        const body = (data) => {
          const out = structuredClone(data.get('body'));
          data.get('paths').forEach((path, i) => setPath(out, path, context.otherBufferViewsIndexMap.get(data.get('blobs')[i])));
          const images = data.listRefs('images');
          data.get('imageKeys').forEach((key, i) => {
            out[key] = context.imageIndexMap.get(images[i]);
          });
          return out;
        };
        const root = this.document.getRoot().getExtension(name);
        if (root) {
          json.extensions = json.extensions || {};
          json.extensions[name] = body(root);
        }
        for (const material of this.document.getRoot().listMaterials()) {
          const data = material.getExtension(name);
          if (!data) continue;
          const index = context.materialIndexMap.get(material);
          const materialDef = json.materials[index];
          materialDef.extensions = materialDef.extensions || {};
          materialDef.extensions[name] = body(data);
        }
        return this;
      }

      dataInUse() {
        const all = [];
        const root = this.document.getRoot().getExtension(name);
        if (root) all.push(root);
        for (const material of this.document.getRoot().listMaterials()) {
          const data = material.getExtension(name);
          if (data) all.push(data);
        }
        return all;
      }
    }
    return BakeExtension;
  });
}
