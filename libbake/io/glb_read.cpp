// GLB / glTF reader. The container is checked by hand first (header, chunk bounds) so a damaged file
// gets a precise message; tinygltf then parses the document and resolves buffers, and every accessor
// we use is bounds-checked again here (packages are untrusted input). Draco-compressed primitives are
// decoded with Draco's decoder. Materials and extension objects are kept as raw JSON from the
// document itself, so vendor extensions reach their technique's reader unchanged.
#include <bake_formats/glb.h>
#include <tiny_gltf.h>

#include <cstring>
#include <limits>

#include "core/atomic_file.h"
#include "io/draco_codec.h"
#include "io/glb.h"

namespace bake::glb {
namespace {
using nlohmann::json;
namespace fmt = format::glb;

std::uint32_t readU32(std::span<const std::uint8_t> bytes, std::size_t offset) {
  std::uint32_t v = 0;
  std::memcpy(&v, bytes.data() + offset, 4);
  return v;
}

// Checks the GLB container and returns the text of its JSON chunk.
Result<std::string> glbJsonChunk(std::span<const std::uint8_t> bytes, const std::string& name) {
  if (bytes.size() < fmt::kHeaderBytes + fmt::kChunkHeaderBytes) {
    return invalidInput("file is " + std::to_string(bytes.size()) + " bytes, too short for a GLB header",
                        {name, "header"});
  }
  if (readU32(bytes, 0) != fmt::kMagic) return invalidInput("not a GLB file (wrong magic)", {name, "header"});
  if (readU32(bytes, 4) != fmt::kVersion) {
    return unsupported("GLB container version " + std::to_string(readU32(bytes, 4)) + " (only 2 is supported)",
                       {name, "header"});
  }
  const std::uint64_t declared = readU32(bytes, 8);
  if (declared > bytes.size()) {
    return invalidInput("header declares " + std::to_string(declared) + " bytes but the file has " +
                            std::to_string(bytes.size()) + " (truncated?)", {name, "header"});
  }
  const std::uint64_t jsonLength = readU32(bytes, 12);
  if (readU32(bytes, 16) != fmt::kChunkJson) {
    return invalidInput("first chunk is not the JSON chunk", {name, "chunk 0"});
  }
  if (fmt::kHeaderBytes + fmt::kChunkHeaderBytes + jsonLength > declared) {
    return invalidInput("JSON chunk of " + std::to_string(jsonLength) + " bytes runs past the end of the file",
                        {name, "chunk 0"});
  }
  const std::uint64_t binHeader = fmt::kHeaderBytes + fmt::kChunkHeaderBytes + jsonLength;
  if (binHeader + fmt::kChunkHeaderBytes <= declared) {
    const std::uint64_t binLength = readU32(bytes, std::size_t(binHeader));
    if (readU32(bytes, std::size_t(binHeader) + 4) == fmt::kChunkBin &&
        binHeader + fmt::kChunkHeaderBytes + binLength > declared) {
      return invalidInput("BIN chunk of " + std::to_string(binLength) + " bytes runs past the end of the file",
                          {name, "chunk 1"});
    }
  }
  const char* text = reinterpret_cast<const char*>(bytes.data() + fmt::kHeaderBytes + fmt::kChunkHeaderBytes);
  return std::string(text, std::size_t(jsonLength));
}

Result<ComponentType> componentTypeOf(int code, const Location& where) {
  switch (code) {
    case fmt::kComponentI8: return ComponentType::I8;
    case fmt::kComponentU8: return ComponentType::U8;
    case fmt::kComponentI16: return ComponentType::I16;
    case fmt::kComponentU16: return ComponentType::U16;
    case fmt::kComponentU32: return ComponentType::U32;
    case fmt::kComponentF32: return ComponentType::F32;
    default: return invalidInput("unknown componentType " + std::to_string(code), where);
  }
}

Result<int> componentsOf(int type, const Location& where) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    default: return unsupported("accessor type " + std::to_string(type) + " (matrices) is not supported here", where);
  }
}

Result<std::span<const std::uint8_t>> bufferViewBytes(const tinygltf::Model& model, int index,
                                                      const std::string& name) {
  const Location where{name, "bufferView " + std::to_string(index)};
  if (index < 0 || std::size_t(index) >= model.bufferViews.size()) {
    return invalidInput("bufferView index is out of range", where);
  }
  const tinygltf::BufferView& view = model.bufferViews[std::size_t(index)];
  if (view.buffer < 0 || std::size_t(view.buffer) >= model.buffers.size()) {
    return invalidInput("refers to buffer " + std::to_string(view.buffer) + ", which does not exist", where);
  }
  const std::vector<unsigned char>& data = model.buffers[std::size_t(view.buffer)].data;
  if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset) {
    return invalidInput("bytes " + std::to_string(view.byteOffset) + "+" + std::to_string(view.byteLength) +
                            " run past its buffer of " + std::to_string(data.size()) + " bytes", where);
  }
  return std::span<const std::uint8_t>(data.data() + view.byteOffset, view.byteLength);
}

// Reads an accessor into tightly packed bytes, checking every bound.
Result<Attribute> readAccessor(const tinygltf::Model& model, int index, const std::string& attributeName,
                               const std::string& name) {
  const Location where{name, "accessor " + std::to_string(index)};
  if (index < 0 || std::size_t(index) >= model.accessors.size()) {
    return invalidInput("accessor index is out of range", where);
  }
  const tinygltf::Accessor& accessor = model.accessors[std::size_t(index)];
  if (accessor.sparse.isSparse) return unsupported("sparse accessors are not supported", where);
  Attribute out;
  out.name = attributeName;
  BAKE_ASSIGN_OR_RETURN(out.componentType, componentTypeOf(accessor.componentType, where));
  BAKE_ASSIGN_OR_RETURN(out.components, componentsOf(accessor.type, where));
  out.normalized = accessor.normalized;
  const std::size_t element = out.elementSize();
  if (accessor.count > std::numeric_limits<std::uint32_t>::max()) {
    return invalidInput("count " + std::to_string(accessor.count) + " is too large", where);
  }
  if (accessor.bufferView < 0) {  // all zeros (glTF 3.6.2.1)
    out.bytes.assign(accessor.count * element, 0);
    return out;
  }
  BAKE_ASSIGN_OR_RETURN(std::span<const std::uint8_t> view, bufferViewBytes(model, accessor.bufferView, name));
  const std::size_t stride =
      model.bufferViews[std::size_t(accessor.bufferView)].byteStride ? model.bufferViews[std::size_t(accessor.bufferView)].byteStride : element;
  if (stride < element) return invalidInput("byteStride is smaller than one element", where);
  const std::size_t needed = accessor.count == 0 ? 0 : (accessor.count - 1) * stride + element;
  if (accessor.byteOffset > view.size() || needed > view.size() - accessor.byteOffset) {
    return invalidInput(std::to_string(accessor.count) + " elements from byte " + std::to_string(accessor.byteOffset) +
                            " run past its bufferView of " + std::to_string(view.size()) + " bytes", where);
  }
  out.bytes.resize(accessor.count * element);
  for (std::size_t i = 0; i < accessor.count; ++i) {
    std::memcpy(out.bytes.data() + i * element, view.data() + accessor.byteOffset + i * stride, element);
  }
  return out;
}

Result<std::vector<std::uint32_t>> readIndices(const tinygltf::Model& model, int index, const std::string& name) {
  BAKE_ASSIGN_OR_RETURN(Attribute raw, readAccessor(model, index, "indices", name));
  const Location where{name, "accessor " + std::to_string(index)};
  if (raw.components != 1 || raw.componentType == ComponentType::F32 || raw.componentType == ComponentType::I8 ||
      raw.componentType == ComponentType::I16) {
    return invalidInput("indices must be unsigned integer scalars", where);
  }
  std::vector<std::uint32_t> indices(raw.count());
  const std::size_t size = componentSize(raw.componentType);
  for (std::size_t i = 0; i < indices.size(); ++i) {
    std::uint32_t v = 0;
    std::memcpy(&v, raw.bytes.data() + i * size, size);  // little-endian
    indices[i] = v;
  }
  return indices;
}

Status readDracoPrimitive(const tinygltf::Model& model, const json& extension,
                          const tinygltf::Primitive& source, Primitive& out, const std::string& name,
                          const Location& where) {
  if (!extension.contains("bufferView") || !extension["bufferView"].is_number_integer() ||
      !extension.contains("attributes") || !extension["attributes"].is_object()) {
    return invalidInput(std::string(fmt::kDracoExtension) + " needs bufferView and attributes", where);
  }
  BAKE_ASSIGN_OR_RETURN(std::span<const std::uint8_t> bytes,
                        bufferViewBytes(model, extension["bufferView"].get<int>(), name));
  std::map<std::string, detail::DracoAttributeTarget> targets;
  for (const auto& [attributeName, accessorIndex] : source.attributes) {
    const json& id = extension["attributes"].value(attributeName, json());
    if (!id.is_number_integer()) continue;  // not compressed: read below
    if (accessorIndex < 0 || std::size_t(accessorIndex) >= model.accessors.size()) {
      return invalidInput("attribute " + attributeName + " refers to a missing accessor", where);
    }
    const tinygltf::Accessor& accessor = model.accessors[std::size_t(accessorIndex)];
    detail::DracoAttributeTarget target;
    target.dracoId = id.get<int>();
    BAKE_ASSIGN_OR_RETURN(target.componentType, componentTypeOf(accessor.componentType, where));
    BAKE_ASSIGN_OR_RETURN(target.components, componentsOf(accessor.type, where));
    target.normalized = accessor.normalized;
    targets[attributeName] = target;
  }
  return detail::dracoDecode(bytes, targets, out, where);
}

Result<Primitive> readPrimitive(const tinygltf::Model& model, const json& rawPrimitive,
                                const tinygltf::Primitive& source, const std::string& name, const Location& where) {
  Primitive out;
  out.mode = source.mode < 0 ? fmt::kModeTriangles : source.mode;
  out.material = source.material;
  if (out.material >= int(model.materials.size())) {
    return invalidInput("material " + std::to_string(out.material) + " does not exist", where);
  }
  const json* draco = nullptr;
  if (rawPrimitive.contains("extensions") && rawPrimitive["extensions"].contains(fmt::kDracoExtension)) {
    draco = &rawPrimitive["extensions"][fmt::kDracoExtension];
    BAKE_RETURN_IF_ERROR(readDracoPrimitive(model, *draco, source, out, name, where));
  }
  for (const auto& [attributeName, accessorIndex] : source.attributes) {
    if (out.find(attributeName)) continue;  // decoded from Draco
    BAKE_ASSIGN_OR_RETURN(Attribute attribute, readAccessor(model, accessorIndex, attributeName, name));
    out.attributes.push_back(std::move(attribute));
  }
  if (!draco && source.indices >= 0) {
    BAKE_ASSIGN_OR_RETURN(out.indices, readIndices(model, source.indices, name));
  }
  const std::size_t vertices = out.vertexCount();
  for (const Attribute& attribute : out.attributes) {
    if (attribute.count() != vertices) {
      return invalidInput("attribute " + attribute.name + " has " + std::to_string(attribute.count()) +
                              " elements, POSITION has " + std::to_string(vertices), where);
    }
  }
  for (std::size_t i = 0; i < out.indices.size(); ++i) {
    if (out.indices[i] >= vertices) {
      return invalidInput("index " + std::to_string(i) + " is " + std::to_string(out.indices[i]) + ", past the " +
                              std::to_string(vertices) + " vertices", where);
    }
  }
  return out;
}

Result<Node> readNode(const tinygltf::Model& model, std::size_t index, const std::string& name) {
  const tinygltf::Node& source = model.nodes[index];
  const Location where{name, "node " + std::to_string(index)};
  Node node;
  node.name = source.name;
  node.mesh = source.mesh;
  if (node.mesh >= int(model.meshes.size())) return invalidInput("mesh " + std::to_string(node.mesh) + " does not exist", where);
  for (int child : source.children) {
    if (child < 0 || std::size_t(child) >= model.nodes.size() || std::size_t(child) == index) {
      return invalidInput("child " + std::to_string(child) + " is not a valid node", where);
    }
    node.children.push_back(child);
  }
  if (source.matrix.size() == 16) {
    std::array<double, 16> m{};
    std::copy(source.matrix.begin(), source.matrix.end(), m.begin());
    node.matrix = m;
  }
  if (source.translation.size() == 3) std::copy(source.translation.begin(), source.translation.end(), node.translation.begin());
  if (source.rotation.size() == 4) std::copy(source.rotation.begin(), source.rotation.end(), node.rotation.begin());
  if (source.scale.size() == 3) std::copy(source.scale.begin(), source.scale.end(), node.scale.begin());
  return node;
}

Result<Package> fromModel(const tinygltf::Model& model, const json& document, const std::string& name) {
  Package package;
  package.generator = model.asset.generator;
  package.extensionsUsed = model.extensionsUsed;
  package.extensionsRequired = model.extensionsRequired;
  if (document.contains("extensions") && document["extensions"].is_object()) package.extensions = document["extensions"];
  if (document.contains("materials") && document["materials"].is_array()) package.materials = document["materials"];

  for (std::size_t v = 0; v < model.bufferViews.size(); ++v) {
    BAKE_ASSIGN_OR_RETURN(std::span<const std::uint8_t> bytes, bufferViewBytes(model, int(v), name));
    package.blobs.push_back(Blob{{bytes.begin(), bytes.end()}, 1});
  }
  const json& rawMeshes = document.value("meshes", json::array());
  for (std::size_t m = 0; m < model.meshes.size(); ++m) {
    Mesh mesh{model.meshes[m].name, {}};
    for (std::size_t p = 0; p < model.meshes[m].primitives.size(); ++p) {
      const Location where{name, "mesh " + std::to_string(m) + " primitive " + std::to_string(p)};
      const json& rawPrimitive = rawMeshes.at(m).at("primitives").at(p);
      BAKE_ASSIGN_OR_RETURN(Primitive primitive, readPrimitive(model, rawPrimitive, model.meshes[m].primitives[p], name, where));
      mesh.primitives.push_back(std::move(primitive));
    }
    package.meshes.push_back(std::move(mesh));
  }
  for (std::size_t n = 0; n < model.nodes.size(); ++n) {
    BAKE_ASSIGN_OR_RETURN(Node node, readNode(model, n, name));
    package.nodes.push_back(std::move(node));
  }
  if (!model.scenes.empty()) {
    const int scene = model.defaultScene >= 0 && std::size_t(model.defaultScene) < model.scenes.size() ? model.defaultScene : 0;
    for (int root : model.scenes[std::size_t(scene)].nodes) {
      if (root < 0 || std::size_t(root) >= model.nodes.size()) {
        return invalidInput("root node " + std::to_string(root) + " does not exist", {name, "scene " + std::to_string(scene)});
      }
      package.sceneRoots.push_back(root);
    }
  }
  return package;
}

Result<json> parseDocument(const std::string& text, const std::string& name) {
  json document = json::parse(text, nullptr, false);
  if (document.is_discarded() || !document.is_object()) {
    return invalidInput("the glTF JSON is not a valid JSON object", {name, "JSON"});
  }
  return document;
}

Status tinygltfFailure(const std::string& error, const std::string& name) {
  std::string message = error.empty() ? "tinygltf could not parse the document" : error;
  while (!message.empty() && (message.back() == '\n' || message.back() == ' ')) message.pop_back();
  return invalidInput(message, {name, ""});
}

}  // namespace

Result<Package> decode(std::span<const std::uint8_t> bytes, const std::string& name) {
  BAKE_ASSIGN_OR_RETURN(const std::string text, glbJsonChunk(bytes, name));
  BAKE_ASSIGN_OR_RETURN(const json document, parseDocument(text, name));
  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string error, warning;
  if (bytes.size() > std::numeric_limits<unsigned int>::max()) return unsupported("file larger than 4 GiB", {name, ""});
  if (!loader.LoadBinaryFromMemory(&model, &error, &warning, bytes.data(), static_cast<unsigned int>(bytes.size()))) {
    return tinygltfFailure(error, name);
  }
  return fromModel(model, document, name);
}

Result<Package> read(const std::filesystem::path& path) {
  BAKE_ASSIGN_OR_RETURN(const std::vector<std::uint8_t> bytes, readFileBytes(path));
  std::string extension = path.extension().string();
  for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (extension != ".gltf") return decode(bytes, path.string());

  const std::string text(bytes.begin(), bytes.end());
  BAKE_ASSIGN_OR_RETURN(const json document, parseDocument(text, path.string()));
  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string error, warning;
  const std::string baseDir = path.parent_path().empty() ? "." : path.parent_path().string();
  if (!loader.LoadASCIIFromString(&model, &error, &warning, text.c_str(), static_cast<unsigned int>(text.size()), baseDir)) {
    return tinygltfFailure(error, path.string());
  }
  return fromModel(model, document, path.string());
}

}  // namespace bake::glb
