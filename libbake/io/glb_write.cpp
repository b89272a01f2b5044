// GLB writer (glTF 2.0, section 4.4). We assemble the JSON ourselves (nlohmann::json, keys sorted)
// rather than through tinygltf's writer so that the bytes are deterministic and every bufferView
// lands exactly where we want it: extension blobs first, at their own alignment, then vertex and
// index data aligned for direct GPU upload. Vertex elements whose size is not a multiple of 4 get a
// padded byteStride, as glTF 3.6.2.4 requires. With Draco, each primitive is compressed and then
// decoded once to learn the exact counts and bounds its accessors must state.
#include <bake_formats/glb.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <set>

#include "bake/core/atomic_file.h"
#include "bake/core/version.h"
#include "bake/io/glb.h"
#include "io/draco_codec.h"

namespace bake::glb {
namespace {
using nlohmann::json;
namespace fmt = format::glb;

const char* accessorType(int components) {
  static const char* const kTypes[] = {"SCALAR", "VEC2", "VEC3", "VEC4"};
  return (components >= 1 && components <= 4) ? kTypes[components - 1] : "SCALAR";
}

std::size_t alignUp(std::size_t value, std::size_t alignment) {
  return alignment <= 1 ? value : (value + alignment - 1) / alignment * alignment;
}

// The BIN chunk, laid out before it is written: each view records where its bytes go, and the bytes
// are copied once, straight into the finished file (assembleGlb). A large package (a groove grid of
// 100 MB) is then never grown, copied or zero-filled twice: on a virtual machine every fresh page of
// memory costs a fault, and growing one vector view by view touched twice the package's size.
class BinaryChunk {
 public:
  // Appends bytes that outlive the chunk (a package's blobs) as a new bufferView; returns its index.
  int addView(std::span<const std::uint8_t> bytes, std::size_t alignment, int target = 0,
              std::size_t byteStride = 0) {
    const std::size_t offset = alignUp(size_, std::max<std::size_t>(alignment, 1));
    pieces_.push_back({offset, bytes});
    size_ = offset + bytes.size();
    json view = {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes.size()}};
    if (target) view["target"] = target;
    if (byteStride) view["byteStride"] = byteStride;
    views_.push_back(std::move(view));
    return int(views_.size() - 1);
  }
  // The same for bytes made while encoding: the chunk keeps them (a moved vector keeps its storage,
  // so the view's span stays valid).
  int addOwnedView(std::vector<std::uint8_t>&& bytes, std::size_t alignment, int target = 0,
                   std::size_t byteStride = 0) {
    owned_.push_back(std::move(bytes));
    return addView(owned_.back(), alignment, target, byteStride);
  }
  std::size_t size() const { return size_; }
  // Writes the chunk's size() bytes to `out`, alignment gaps zeroed.
  void copyTo(std::uint8_t* out) const {
    std::size_t at = 0;
    for (const Piece& piece : pieces_) {
      std::memset(out + at, 0, piece.offset - at);
      if (!piece.bytes.empty()) std::memcpy(out + piece.offset, piece.bytes.data(), piece.bytes.size());
      at = piece.offset + piece.bytes.size();
    }
  }
  const json& views() const { return views_; }

 private:
  struct Piece {
    std::size_t offset;
    std::span<const std::uint8_t> bytes;
  };
  std::vector<Piece> pieces_;
  std::vector<std::vector<std::uint8_t>> owned_;
  std::size_t size_ = 0;
  json views_ = json::array();
};

// min/max per component, in the attribute's own numbers (raw integers when normalized).
void addBounds(const Attribute& attribute, json& accessor) {
  const std::size_t count = attribute.count();
  if (count == 0) return;
  Attribute raw = attribute;
  raw.normalized = false;
  const std::vector<float> values = raw.toFloats();
  json lo = json::array(), hi = json::array();
  for (int c = 0; c < attribute.components; ++c) {
    float a = values[std::size_t(c)], b = a;
    for (std::size_t i = 1; i < count; ++i) {
      const float v = values[i * std::size_t(attribute.components) + std::size_t(c)];
      a = std::min(a, v);
      b = std::max(b, v);
    }
    if (attribute.componentType == ComponentType::F32) {
      lo.push_back(a);
      hi.push_back(b);
    } else {
      lo.push_back(std::int64_t(a));
      hi.push_back(std::int64_t(b));
    }
  }
  accessor["min"] = lo;
  accessor["max"] = hi;
}

json accessorFor(const Attribute& attribute) {
  json accessor = {{"componentType", gltfComponentType(attribute.componentType)},
                   {"count", attribute.count()},
                   {"type", accessorType(attribute.components)}};
  if (attribute.normalized) accessor["normalized"] = true;
  addBounds(attribute, accessor);
  return accessor;
}

// Copies elements into a layout whose stride is a multiple of 4 bytes.
std::vector<std::uint8_t> paddedVertexData(const Attribute& attribute, std::size_t stride) {
  const std::size_t element = attribute.elementSize();
  if (stride == element) return attribute.bytes;
  std::vector<std::uint8_t> out(attribute.count() * stride, 0);
  for (std::size_t i = 0; i < attribute.count(); ++i) {
    std::memcpy(out.data() + i * stride, attribute.bytes.data() + i * element, element);
  }
  return out;
}

std::vector<std::uint8_t> packIndices(const std::vector<std::uint32_t>& indices, bool wide) {
  std::vector<std::uint8_t> out(indices.size() * (wide ? 4 : 2));
  for (std::size_t i = 0; i < indices.size(); ++i) {
    if (wide) {
      std::memcpy(out.data() + 4 * i, &indices[i], 4);
    } else {
      const auto narrow = static_cast<std::uint16_t>(indices[i]);
      std::memcpy(out.data() + 2 * i, &narrow, 2);
    }
  }
  return out;
}

bool needsWideIndices(const std::vector<std::uint32_t>& indices) {
  // 65535 is the primitive-restart value for 16-bit indices; keep it out of 16-bit buffers.
  return !indices.empty() && *std::max_element(indices.begin(), indices.end()) >= 65535u;
}

Status checkPrimitive(const Primitive& primitive, const Location& where) {
  const std::size_t count = primitive.vertexCount();
  for (const Attribute& attribute : primitive.attributes) {
    if (attribute.components < 1 || attribute.components > 4) {
      return invalidInput("attribute " + attribute.name + " has " + std::to_string(attribute.components) +
                              " components (1 to 4 allowed)", where);
    }
    if (attribute.bytes.size() % attribute.elementSize() != 0 || attribute.count() != count) {
      return invalidInput("attribute " + attribute.name + " holds " + std::to_string(attribute.count()) +
                              " elements, the primitive has " + std::to_string(count) + " vertices", where);
    }
    const bool standard = attribute.name == "POSITION" || attribute.name == "NORMAL" ||
                          attribute.name == "TANGENT" || attribute.name.find('_') != std::string::npos;
    if (!standard) {
      return invalidInput("attribute name " + attribute.name + " is neither a glTF semantic nor an "
                          "application attribute starting with '_'", where);
    }
  }
  for (std::size_t i = 0; i < primitive.indices.size(); ++i) {
    if (primitive.indices[i] >= count) {
      return invalidInput("index " + std::to_string(i) + " is " + std::to_string(primitive.indices[i]) +
                              ", past the " + std::to_string(count) + " vertices", where);
    }
  }
  return {};
}

// Writes one primitive uncompressed; returns its JSON.
json writePlainPrimitive(const Primitive& primitive, BinaryChunk& bin, json& accessors) {
  json attributes = json::object();
  for (const Attribute& attribute : primitive.attributes) {
    const std::size_t stride = alignUp(attribute.elementSize(), fmt::kVertexElementAlignment);
    json accessor = accessorFor(attribute);
    accessor["bufferView"] = bin.addOwnedView(paddedVertexData(attribute, stride), fmt::kVertexElementAlignment,
                                              fmt::kTargetArrayBuffer, stride != attribute.elementSize() ? stride : 0);
    accessors.push_back(std::move(accessor));
    attributes[attribute.name] = accessors.size() - 1;
  }
  json out = {{"attributes", attributes}, {"mode", primitive.mode}};
  if (!primitive.indices.empty()) {
    const bool wide = needsWideIndices(primitive.indices);
    json accessor = {{"componentType", wide ? fmt::kComponentU32 : fmt::kComponentU16},
                     {"count", primitive.indices.size()},
                     {"type", "SCALAR"}};
    accessor["bufferView"] = bin.addOwnedView(packIndices(primitive.indices, wide), 4,
                                              fmt::kTargetElementArrayBuffer);
    accessors.push_back(std::move(accessor));
    out["indices"] = accessors.size() - 1;
  }
  if (primitive.material >= 0) out["material"] = primitive.material;
  return out;
}

// Writes one primitive Draco-compressed; accessors state the decoded counts and bounds.
Result<json> writeDracoPrimitive(const Primitive& primitive, const DracoOptions& options, BinaryChunk& bin,
                                 json& accessors, const Location& where) {
  BAKE_ASSIGN_OR_RETURN(detail::DracoEncoded encoded, detail::dracoEncode(primitive, options));
  std::map<std::string, detail::DracoAttributeTarget> targets;
  for (const Attribute& attribute : primitive.attributes) {
    targets[attribute.name] = {encoded.attributeIds.at(attribute.name), attribute.componentType,
                               attribute.components, attribute.normalized};
  }
  Primitive decoded;
  BAKE_RETURN_IF_ERROR(detail::dracoDecode(encoded.bytes, targets, decoded, where));

  json attributes = json::object(), dracoAttributes = json::object();
  for (const Attribute& attribute : decoded.attributes) {
    accessors.push_back(accessorFor(attribute));
    attributes[attribute.name] = accessors.size() - 1;
    dracoAttributes[attribute.name] = encoded.attributeIds.at(attribute.name);
  }
  const bool wide = needsWideIndices(decoded.indices) || decoded.vertexCount() >= 65535;
  accessors.push_back({{"componentType", wide ? fmt::kComponentU32 : fmt::kComponentU16},
                       {"count", decoded.indices.size()},
                       {"type", "SCALAR"}});
  json out = {{"attributes", attributes}, {"indices", accessors.size() - 1}, {"mode", primitive.mode}};
  out["extensions"][fmt::kDracoExtension] = {{"bufferView", bin.addOwnedView(std::move(encoded.bytes), 4)},
                                             {"attributes", dracoAttributes}};
  if (primitive.material >= 0) out["material"] = primitive.material;
  return out;
}

json nodeJson(const Node& node) {
  json out = json::object();
  if (!node.name.empty()) out["name"] = node.name;
  if (node.mesh >= 0) out["mesh"] = node.mesh;
  if (node.camera >= 0) out["camera"] = node.camera;
  if (!node.extensions.empty()) out["extensions"] = node.extensions;
  if (!node.children.empty()) out["children"] = node.children;
  if (node.matrix) {
    out["matrix"] = *node.matrix;
  } else {
    if (node.translation != std::array<double, 3>{0, 0, 0}) out["translation"] = node.translation;
    if (node.rotation != std::array<double, 4>{0, 0, 0, 1}) out["rotation"] = node.rotation;
    if (node.scale != std::array<double, 3>{1, 1, 1}) out["scale"] = node.scale;
  }
  return out;
}

std::vector<int> defaultRoots(const std::vector<Node>& nodes) {
  std::vector<bool> isChild(nodes.size(), false);
  for (const Node& node : nodes) {
    for (int child : node.children) {
      if (child >= 0 && std::size_t(child) < nodes.size()) isChild[std::size_t(child)] = true;
    }
  }
  std::vector<int> roots;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (!isChild[i]) roots.push_back(int(i));
  }
  return roots;
}

// Every extension named anywhere in the document, for extensionsUsed.
void collectExtensionNames(const json& value, std::set<std::string>& names) {
  if (value.is_object()) {
    for (const auto& [key, child] : value.items()) {
      if (key == "extensions" && child.is_object()) {
        for (const auto& [name, ignored] : child.items()) names.insert(name);
      }
      collectExtensionNames(child, names);
    }
  } else if (value.is_array()) {
    for (const json& child : value) collectExtensionNames(child, names);
  }
}

std::vector<std::uint8_t> assembleGlb(const std::string& jsonText, const BinaryChunk& bin) {
  const std::size_t textSize = alignUp(jsonText.size(), fmt::kChunkAlignment);
  const std::size_t binSize = alignUp(bin.size(), fmt::kChunkAlignment);
  const std::size_t total = fmt::kHeaderBytes + fmt::kChunkHeaderBytes + textSize +
                            (bin.size() == 0 ? 0 : fmt::kChunkHeaderBytes + binSize);
  std::vector<std::uint8_t> out(total);  // the one allocation of the file's bytes
  std::size_t at = 0;
  auto put32 = [&](std::uint32_t v) {
    for (int i = 0; i < 4; ++i) out[at++] = std::uint8_t(v >> (8 * i));
  };
  put32(fmt::kMagic);
  put32(fmt::kVersion);
  put32(std::uint32_t(total));
  put32(std::uint32_t(textSize));
  put32(fmt::kChunkJson);
  std::memcpy(out.data() + at, jsonText.data(), jsonText.size());
  std::memset(out.data() + at + jsonText.size(), ' ', textSize - jsonText.size());
  at += textSize;
  if (bin.size() != 0) {
    put32(std::uint32_t(binSize));
    put32(fmt::kChunkBin);
    bin.copyTo(out.data() + at);  // the padding after it is already zero
  }
  return out;
}

}  // namespace

Result<std::vector<std::uint8_t>> encode(const Package& package, const WriteOptions& options) {
  BinaryChunk bin;
  for (const Blob& blob : package.blobs) bin.addView(blob.bytes, blob.alignment);

  json accessors = json::array(), meshes = json::array();
  for (std::size_t m = 0; m < package.meshes.size(); ++m) {
    const Mesh& mesh = package.meshes[m];
    json primitives = json::array();
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
      const Primitive& primitive = mesh.primitives[p];
      const Location where{"", "mesh " + std::to_string(m) + " primitive " + std::to_string(p)};
      BAKE_RETURN_IF_ERROR(checkPrimitive(primitive, where));
      if (options.draco.enabled && primitive.mode == fmt::kModeTriangles) {
        BAKE_ASSIGN_OR_RETURN(json written, writeDracoPrimitive(primitive, options.draco, bin, accessors, where));
        primitives.push_back(std::move(written));
      } else {
        primitives.push_back(writePlainPrimitive(primitive, bin, accessors));
      }
    }
    json meshJson = {{"primitives", primitives}};
    if (!mesh.name.empty()) meshJson["name"] = mesh.name;
    meshes.push_back(std::move(meshJson));
  }

  std::vector<Node> nodes = package.nodes;
  if (nodes.empty()) {  // make every mesh visible in viewers
    for (std::size_t m = 0; m < package.meshes.size(); ++m) {
      nodes.push_back(Node{package.meshes[m].name, int(m), {}, std::nullopt});
    }
  }

  json root = {{"asset", {{"version", "2.0"}, {"generator", std::string("bake ") + kToolkitVersion}}}};
  if (!accessors.empty()) root["accessors"] = accessors;
  if (!meshes.empty()) root["meshes"] = meshes;
  if (!nodes.empty()) {
    root["nodes"] = json::array();
    for (const Node& node : nodes) root["nodes"].push_back(nodeJson(node));
    root["scenes"] = json::array({{{"nodes", package.sceneRoots.empty() ? defaultRoots(nodes) : package.sceneRoots}}});
    root["scene"] = 0;
  }
  if (!package.materials.empty()) root["materials"] = package.materials;
  if (!package.cameras.empty()) root["cameras"] = package.cameras;
  if (!package.images.empty()) root["images"] = package.images;
  if (!package.textures.empty()) root["textures"] = package.textures;
  if (!package.samplers.empty()) root["samplers"] = package.samplers;
  if (!package.extensions.empty()) root["extensions"] = package.extensions;
  if (!bin.views().empty()) root["bufferViews"] = bin.views();
  if (bin.size() != 0) root["buffers"] = json::array({{{"byteLength", bin.size()}}});

  std::set<std::string> used;
  collectExtensionNames(root, used);
  std::set<std::string> required(package.extensionsRequired.begin(), package.extensionsRequired.end());
  if (used.count(fmt::kDracoExtension)) required.insert(fmt::kDracoExtension);  // no fallback data
  for (const std::string& name : required) used.insert(name);
  if (!used.empty()) root["extensionsUsed"] = std::vector<std::string>(used.begin(), used.end());
  if (!required.empty()) root["extensionsRequired"] = std::vector<std::string>(required.begin(), required.end());

  // glTF JSON is UTF-8 (glTF 2.0, 3.2); a name taken from a file name need not be. Bytes that are not
  // UTF-8 become U+FFFD instead of an exception from the serializer.
  return assembleGlb(root.dump(-1, ' ', false, json::error_handler_t::replace), bin);
}

Status write(const std::filesystem::path& path, const Package& package, const WriteOptions& options) {
  auto bytes = encode(package, options);
  if (!bytes.isOk()) return bytes.takeStatus().inFile(path.string());
  return writeFileAtomic(path, *bytes);
}

}  // namespace bake::glb
