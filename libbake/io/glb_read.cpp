// GLB / glTF reader over nlohmann::json. The container is checked first (header, chunk bounds) so a
// damaged file gets a precise message; then every object we use is type- and bounds-checked, since
// packages are untrusted input. Draco-compressed primitives are decoded with Draco's decoder.
//
// Why not tinygltf (Debian 12, 2.7.0): it rejects index accessors without a bufferView, which
// KHR_draco_mesh_compression requires, so it cannot open a Draco package at all; and linking it next
// to Draco's static library lets Draco's private tinygltf (another version, another layout) replace
// it silently. Reading the document ourselves avoids both, and gives errors that name the element.
#include <bake_formats/glb.h>

#include <cstring>
#include <limits>

#include "bake/core/atomic_file.h"
#include "bake/core/input_file.h"
#include "bake/io/glb.h"
#include "core/json_read.h"
#include "io/draco_codec.h"

namespace bake::glb {
namespace {
using nlohmann::json;
namespace fmt = format::glb;
namespace fs = std::filesystem;

std::uint32_t readU32(std::span<const std::uint8_t> bytes, std::size_t offset) {
  std::uint32_t v = 0;
  std::memcpy(&v, bytes.data() + offset, 4);
  return v;
}

// The parsed document and its resolved buffers.
struct Document {
  json root;
  std::vector<std::vector<std::uint8_t>> buffers;
  std::string name;  // for messages
};

// ---- typed access to untrusted JSON ----

Location at(const Document& doc, const std::string& element) { return {doc.name, element}; }

const json& arrayMember(const json& object, const char* key) {
  static const json empty = json::array();
  const auto it = object.find(key);
  return it != object.end() && it->is_array() ? *it : empty;
}

Result<std::int64_t> integerMember(const json& object, const char* key, std::int64_t fallback, const Location& where) {
  const auto it = object.find(key);
  if (it == object.end()) return fallback;
  if (!it->is_number_integer()) return invalidInput(std::string(key) + " must be an integer", where);
  // An unsigned literal past 2^63-1 would wrap to a negative value (and be printed as one).
  if (it->is_number_unsigned() && it->get<std::uint64_t>() > std::uint64_t(std::numeric_limits<std::int64_t>::max())) {
    return invalidInput(std::string(key) + " " + it->dump() + " is out of range", where);
  }
  return it->get<std::int64_t>();
}

Result<std::int64_t> requiredInteger(const json& object, const char* key, const Location& where) {
  if (!object.contains(key)) return invalidInput(std::string("missing ") + key, where);
  return integerMember(object, key, 0, where);
}

Result<std::size_t> indexMember(const json& object, const char* key, std::size_t size, const char* what,
                                const Location& where) {
  BAKE_ASSIGN_OR_RETURN(const std::int64_t value, requiredInteger(object, key, where));
  if (value < 0 || std::uint64_t(value) >= size) {
    const bool vowel = std::string_view("aeiou").find(what[0]) != std::string_view::npos;
    return invalidInput(std::string(key) + " " + std::to_string(value) + (vowel ? " names an " : " names a ") + what +
                            " that does not exist",
                        where);
  }
  return std::size_t(value);
}

std::string stringMember(const json& object, const char* key) {
  const auto it = object.find(key);
  return it != object.end() && it->is_string() ? it->get<std::string>() : std::string();
}

template <std::size_t N>
Status numberArrayMember(const json& object, const char* key, std::array<double, N>& out, const Location& where) {
  const auto it = object.find(key);
  if (it == object.end()) return {};
  if (!it->is_array() || it->size() != N) {
    return invalidInput(std::string(key) + " must be an array of " + std::to_string(N) + " numbers", where);
  }
  for (std::size_t i = 0; i < N; ++i) {
    if (!(*it)[i].is_number()) return invalidInput(std::string(key) + " must hold numbers", where);
    out[i] = (*it)[i].get<double>();
  }
  return {};
}

// ---- containers and buffers ----

Result<std::string> glbJsonChunk(std::span<const std::uint8_t> bytes, const std::string& name,
                                 std::span<const std::uint8_t>& binChunk) {
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
  if (readU32(bytes, 16) != fmt::kChunkJson) return invalidInput("first chunk is not the JSON chunk", {name, "chunk 0"});
  const std::uint64_t jsonStart = fmt::kHeaderBytes + fmt::kChunkHeaderBytes;
  if (jsonStart + jsonLength > declared) {
    return invalidInput("JSON chunk of " + std::to_string(jsonLength) + " bytes runs past the end of the file",
                        {name, "chunk 0"});
  }
  // Every chunk after the JSON one must lie whole inside the declared length (glTF 2.0, 4.4.3); the
  // BIN chunk, when present, comes second. Unknown chunk types are skipped.
  std::uint64_t chunkHeader = jsonStart + jsonLength;
  for (int chunk = 1; chunkHeader < declared; ++chunk) {
    const std::string element = "chunk " + std::to_string(chunk);
    if (chunkHeader + fmt::kChunkHeaderBytes > declared) {
      return invalidInput("chunk header at byte " + std::to_string(chunkHeader) + " runs past the end of the file (" +
                              std::to_string(declared) + " bytes)",
                          {name, element});
    }
    const std::uint64_t length = readU32(bytes, std::size_t(chunkHeader));
    const std::uint32_t type = readU32(bytes, std::size_t(chunkHeader) + 4);
    const std::uint64_t start = chunkHeader + fmt::kChunkHeaderBytes;
    if (start + length > declared) {
      return invalidInput(std::string(type == fmt::kChunkBin ? "BIN chunk" : "chunk") + " of " + std::to_string(length) +
                              " bytes runs past the end of the file",
                          {name, element});
    }
    if (type == fmt::kChunkBin && chunk == 1) binChunk = bytes.subspan(std::size_t(start), std::size_t(length));
    chunkHeader = start + length;
  }
  return std::string(reinterpret_cast<const char*>(bytes.data() + jsonStart), std::size_t(jsonLength));
}

Result<std::vector<std::uint8_t>> decodeBase64(const std::string& text, const Location& where) {
  auto value = [](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+' || c == '-') return 62;
    if (c == '/' || c == '_') return 63;
    return -1;
  };
  std::vector<std::uint8_t> out;
  out.reserve(text.size() * 3 / 4);
  std::uint32_t accumulator = 0;
  int bits = 0;
  for (char c : text) {
    if (c == '=') break;
    const int v = value(c);
    if (v < 0) return invalidInput("data URI holds a character that is not base64", where);
    accumulator = (accumulator << 6) | std::uint32_t(v);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(std::uint8_t(accumulator >> bits));
    }
  }
  return out;
}

int hexValue(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// URI confinement: a .gltf names files beside it or below its folder, never elsewhere (an absolute
// path, "../", a link leading out), unless --allow-outside-uris says so: a package from elsewhere must
// not copy /etc/passwd or another project's files into its output.
Status checkUriConfined(const std::string& uri, const std::string& decoded, const fs::path& baseDir, const Location& where) {
  if (outsideUrisAllowed()) return {};
  const fs::path relative(decoded);
  const auto refuse = [&](const std::string& why) {
    return invalidInput("uri " + uri + " " + why + "; files outside the .gltf's folder are refused (allow them with "
                        "--allow-outside-uris)", where);
  };
  if (relative.is_absolute()) return refuse("is an absolute path");
  const fs::path normal = relative.lexically_normal();
  if (!normal.empty() && *normal.begin() == "..") return refuse("leads outside the .gltf's folder");
  std::error_code ec;
  const fs::path folder = fs::weakly_canonical(fs::absolute(baseDir), ec);
  const fs::path target = fs::weakly_canonical(fs::absolute(baseDir / relative), ec);
  if (!ec) {
    const fs::path inside = target.lexically_relative(folder);
    if (inside.empty() || *inside.begin() == "..") return refuse("leads outside the .gltf's folder (through a link)");
  }
  return {};
}

Result<std::vector<std::uint8_t>> loadBufferUri(const std::string& uri, const fs::path& baseDir, const Location& where) {
  if (uri.empty()) return invalidInput("uri is empty", where);
  if (uri.rfind("data:", 0) == 0) {
    const std::size_t comma = uri.find(',');
    if (comma == std::string::npos || comma < 7 || uri.compare(comma - 7, 7, ";base64") != 0) {
      return unsupported("only base64 data URIs are supported", where);
    }
    return decodeBase64(uri.substr(comma + 1), where);
  }
  if (uri.find("://") != std::string::npos) return unsupported("remote buffer URI " + uri, where);
  std::string decoded;  // percent-decoding of the relative path (RFC 3986 2.1: '%' and two hex digits)
  for (std::size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] != '%') {
      decoded += uri[i];
      continue;
    }
    const int high = i + 1 < uri.size() ? hexValue(uri[i + 1]) : -1, low = i + 2 < uri.size() ? hexValue(uri[i + 2]) : -1;
    if (high < 0 || low < 0 || high * 16 + low == 0) {
      return invalidInput("uri " + uri + ": \"" + uri.substr(i, 3) + "\" at character " + std::to_string(i) +
                              " is not a percent escape of a byte (%01 to %FF)",
                          where);
    }
    decoded += char(high * 16 + low);
    i += 2;
  }
  BAKE_RETURN_IF_ERROR(checkUriConfined(uri, decoded, baseDir, where));
  auto bytes = readFileBytes(baseDir / decoded);
  if (!bytes.isOk()) return Status(bytes.status().code(), "buffer file " + decoded + ": " + bytes.status().message(), where);
  return bytes;
}

Status loadBuffers(Document& doc, std::span<const std::uint8_t> binChunk, const fs::path& baseDir) {
  const json& buffers = arrayMember(doc.root, "buffers");
  for (std::size_t b = 0; b < buffers.size(); ++b) {
    const Location where = at(doc, "buffer " + std::to_string(b));
    if (!buffers[b].is_object()) return invalidInput("must be an object", where);
    BAKE_ASSIGN_OR_RETURN(const std::int64_t length, requiredInteger(buffers[b], "byteLength", where));
    std::vector<std::uint8_t> data;
    if (buffers[b].contains("uri")) {
      BAKE_ASSIGN_OR_RETURN(data, loadBufferUri(stringMember(buffers[b], "uri"), baseDir, where));
    } else if (b == 0 && !binChunk.empty()) {
      data.assign(binChunk.begin(), binChunk.end());
    } else {
      return invalidInput("has neither a uri nor a GLB BIN chunk", where);
    }
    if (length < 0 || std::uint64_t(length) > data.size()) {
      return invalidInput("byteLength " + std::to_string(length) + " exceeds its " + std::to_string(data.size()) +
                              " bytes of data", where);
    }
    data.resize(std::size_t(length));
    doc.buffers.push_back(std::move(data));
  }
  return {};
}

// ---- bufferViews and accessors ----

Result<std::span<const std::uint8_t>> bufferViewBytes(const Document& doc, std::size_t index, std::size_t* stride = nullptr) {
  const Location where = at(doc, "bufferView " + std::to_string(index));
  const json& view = arrayMember(doc.root, "bufferViews").at(index);
  if (!view.is_object()) return invalidInput("must be an object", where);
  BAKE_ASSIGN_OR_RETURN(const std::size_t buffer, indexMember(view, "buffer", doc.buffers.size(), "buffer", where));
  BAKE_ASSIGN_OR_RETURN(const std::int64_t offset, integerMember(view, "byteOffset", 0, where));
  BAKE_ASSIGN_OR_RETURN(const std::int64_t length, requiredInteger(view, "byteLength", where));
  BAKE_ASSIGN_OR_RETURN(const std::int64_t byteStride, integerMember(view, "byteStride", 0, where));
  const std::vector<std::uint8_t>& data = doc.buffers[buffer];
  if (offset < 0 || length < 0 || std::uint64_t(offset) > data.size() || std::uint64_t(length) > data.size() - std::uint64_t(offset)) {
    return invalidInput("bytes " + std::to_string(offset) + "+" + std::to_string(length) + " run past buffer " +
                            std::to_string(buffer) + " of " + std::to_string(data.size()) + " bytes", where);
  }
  if (byteStride < 0 || byteStride > 252) return invalidInput("byteStride " + std::to_string(byteStride) + " is out of range", where);
  if (stride) *stride = std::size_t(byteStride);
  return std::span<const std::uint8_t>(data.data() + offset, std::size_t(length));
}

Result<ComponentType> componentTypeOf(std::int64_t code, const Location& where) {
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

Result<int> componentsOf(const std::string& type, const Location& where) {
  if (type == "SCALAR") return 1;
  if (type == "VEC2") return 2;
  if (type == "VEC3") return 3;
  if (type == "VEC4") return 4;
  if (type == "MAT2" || type == "MAT3" || type == "MAT4") return unsupported("matrix accessors are not supported here", where);
  return invalidInput("unknown accessor type \"" + type + "\"", where);
}

// The accessor's declared layout, without its data.
Result<Attribute> accessorLayout(const Document& doc, std::size_t index, const std::string& attributeName) {
  const Location where = at(doc, "accessor " + std::to_string(index));
  const json& accessor = arrayMember(doc.root, "accessors").at(index);
  if (!accessor.is_object()) return invalidInput("must be an object", where);
  if (accessor.contains("sparse")) return unsupported("sparse accessors are not supported", where);
  Attribute out;
  out.name = attributeName;
  BAKE_ASSIGN_OR_RETURN(const std::int64_t code, requiredInteger(accessor, "componentType", where));
  BAKE_ASSIGN_OR_RETURN(out.componentType, componentTypeOf(code, where));
  BAKE_ASSIGN_OR_RETURN(out.components, componentsOf(stringMember(accessor, "type"), where));
  const auto normalized = accessor.find("normalized");
  out.normalized = normalized != accessor.end() && normalized->is_boolean() && normalized->get<bool>();
  return out;
}

Result<Attribute> readAccessor(const Document& doc, std::size_t index, const std::string& attributeName) {
  const Location where = at(doc, "accessor " + std::to_string(index));
  BAKE_ASSIGN_OR_RETURN(Attribute out, accessorLayout(doc, index, attributeName));
  const json& accessor = arrayMember(doc.root, "accessors")[index];
  BAKE_ASSIGN_OR_RETURN(const std::int64_t count, requiredInteger(accessor, "count", where));
  const std::size_t element = out.elementSize();
  if (count < 0 || count > std::numeric_limits<std::uint32_t>::max()) {
    return invalidInput("count " + std::to_string(count) + " is out of range", where);
  }
  if (!accessor.contains("bufferView")) {  // all zeros (glTF 2.0, 3.6.2.1), but never more than the file could mean
    if (std::uint64_t(count) * element > (std::uint64_t(1) << 31)) return invalidInput("count is implausibly large", where);
    out.bytes.assign(std::size_t(count) * element, 0);
    return out;
  }
  BAKE_ASSIGN_OR_RETURN(const std::size_t viewIndex,
                        indexMember(accessor, "bufferView", arrayMember(doc.root, "bufferViews").size(), "bufferView", where));
  std::size_t stride = 0;
  BAKE_ASSIGN_OR_RETURN(const std::span<const std::uint8_t> view, bufferViewBytes(doc, viewIndex, &stride));
  if (stride == 0) stride = element;
  if (stride < element) return invalidInput("its bufferView's byteStride is smaller than one element", where);
  BAKE_ASSIGN_OR_RETURN(const std::int64_t offset, integerMember(accessor, "byteOffset", 0, where));
  const std::uint64_t needed = count == 0 ? 0 : std::uint64_t(count - 1) * stride + element;
  if (offset < 0 || std::uint64_t(offset) > view.size() || needed > view.size() - std::uint64_t(offset)) {
    return invalidInput(std::to_string(count) + " elements from byte " + std::to_string(offset) +
                            " run past bufferView " + std::to_string(viewIndex) + " of " + std::to_string(view.size()) + " bytes",
                        where);
  }
  out.bytes.resize(std::size_t(count) * element);
  for (std::size_t i = 0; i < std::size_t(count); ++i) {
    std::memcpy(out.bytes.data() + i * element, view.data() + std::size_t(offset) + i * stride, element);
  }
  return out;
}

Result<std::vector<std::uint32_t>> readIndices(const Document& doc, std::size_t index) {
  BAKE_ASSIGN_OR_RETURN(const Attribute raw, readAccessor(doc, index, "indices"));
  if (raw.components != 1 || (raw.componentType != ComponentType::U8 && raw.componentType != ComponentType::U16 &&
                              raw.componentType != ComponentType::U32)) {
    return invalidInput("indices must be unsigned integer scalars", at(doc, "accessor " + std::to_string(index)));
  }
  std::vector<std::uint32_t> indices(raw.count());
  const std::size_t size = componentSize(raw.componentType);
  for (std::size_t i = 0; i < indices.size(); ++i) std::memcpy(&indices[i], raw.bytes.data() + i * size, size);
  return indices;
}

// ---- meshes, nodes, scenes ----

Status readDracoPrimitive(const Document& doc, const json& extension, const json& attributes, Primitive& out,
                          const Location& where) {
  if (!extension.is_object() || !extension.contains("attributes") || !extension["attributes"].is_object()) {
    return invalidInput(std::string(fmt::kDracoExtension) + " needs bufferView and attributes", where);
  }
  BAKE_ASSIGN_OR_RETURN(const std::size_t viewIndex,
                        indexMember(extension, "bufferView", arrayMember(doc.root, "bufferViews").size(), "bufferView", where));
  BAKE_ASSIGN_OR_RETURN(const std::span<const std::uint8_t> bytes, bufferViewBytes(doc, viewIndex));
  const std::size_t accessorCount = arrayMember(doc.root, "accessors").size();
  std::map<std::string, detail::DracoAttributeTarget> targets;
  for (const auto& [name, id] : extension["attributes"].items()) {
    if (!id.is_number_integer() || !attributes.contains(name)) {
      return invalidInput("Draco attribute " + name + " is not an attribute of the primitive", where);
    }
    BAKE_ASSIGN_OR_RETURN(const std::size_t accessor, indexMember(attributes, name.c_str(), accessorCount, "accessor", where));
    BAKE_ASSIGN_OR_RETURN(const Attribute layout, accessorLayout(doc, accessor, name));
    targets[name] = {id.get<int>(), layout.componentType, layout.components, layout.normalized};
  }
  return detail::dracoDecode(bytes, targets, out, where);
}

Result<Primitive> readPrimitive(const Document& doc, const json& source, const Location& where) {
  if (!source.is_object() || !source.contains("attributes") || !source["attributes"].is_object()) {
    return invalidInput("a primitive needs an attributes object", where);
  }
  Primitive out;
  BAKE_ASSIGN_OR_RETURN(const std::int64_t mode, integerMember(source, "mode", fmt::kModeTriangles, where));
  if (mode < 0 || mode > fmt::kModeTriangleFan) return invalidInput("mode " + std::to_string(mode) + " is not a glTF mode", where);
  out.mode = int(mode);
  if (source.contains("material")) {
    BAKE_ASSIGN_OR_RETURN(const std::size_t material,
                          indexMember(source, "material", arrayMember(doc.root, "materials").size(), "material", where));
    out.material = int(material);
  }
  const json& attributes = source["attributes"];
  const auto extensions = source.find("extensions");
  if (extensions != source.end() && extensions->is_object() && extensions->contains(fmt::kDracoExtension)) {
    out.dracoCompressed = true;
    BAKE_RETURN_IF_ERROR(readDracoPrimitive(doc, (*extensions)[fmt::kDracoExtension], attributes, out, where));
  }
  const std::size_t accessorCount = arrayMember(doc.root, "accessors").size();
  for (const auto& [name, ignored] : attributes.items()) {
    if (out.find(name)) continue;  // decoded from Draco
    BAKE_ASSIGN_OR_RETURN(const std::size_t accessor, indexMember(attributes, name.c_str(), accessorCount, "accessor", where));
    BAKE_ASSIGN_OR_RETURN(Attribute attribute, readAccessor(doc, accessor, name));
    out.attributes.push_back(std::move(attribute));
  }
  if (!out.dracoCompressed && source.contains("indices")) {
    BAKE_ASSIGN_OR_RETURN(const std::size_t accessor, indexMember(source, "indices", accessorCount, "accessor", where));
    BAKE_ASSIGN_OR_RETURN(out.indices, readIndices(doc, accessor));
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

Result<Node> readNode(const Document& doc, std::size_t index) {
  const Location where = at(doc, "node " + std::to_string(index));
  const json& source = arrayMember(doc.root, "nodes")[index];
  if (!source.is_object()) return invalidInput("must be an object", where);
  Node node;
  node.name = stringMember(source, "name");
  if (source.contains("mesh")) {
    BAKE_ASSIGN_OR_RETURN(const std::size_t mesh, indexMember(source, "mesh", arrayMember(doc.root, "meshes").size(), "mesh", where));
    node.mesh = int(mesh);
  }
  if (source.contains("camera")) {
    BAKE_ASSIGN_OR_RETURN(const std::size_t camera,
                          indexMember(source, "camera", arrayMember(doc.root, "cameras").size(), "camera", where));
    node.camera = int(camera);
  }
  if (source.contains("extensions") && source["extensions"].is_object()) node.extensions = source["extensions"];
  const std::size_t nodeCount = arrayMember(doc.root, "nodes").size();
  for (const json& child : arrayMember(source, "children")) {
    if (!child.is_number_integer() || child.get<std::int64_t>() < 0 || std::uint64_t(child.get<std::int64_t>()) >= nodeCount) {
      return invalidInput("child " + child.dump() + " is not a valid node", where);
    }
    if (std::size_t(child.get<std::int64_t>()) == index) {
      return invalidInput("node " + std::to_string(index) + " is its own child (cycle)", where);
    }
    node.children.push_back(child.get<int>());
  }
  if (source.contains("matrix")) {
    std::array<double, 16> m{};
    BAKE_RETURN_IF_ERROR(numberArrayMember(source, "matrix", m, where));
    node.matrix = m;
  }
  BAKE_RETURN_IF_ERROR(numberArrayMember(source, "translation", node.translation, where));
  BAKE_RETURN_IF_ERROR(numberArrayMember(source, "rotation", node.rotation, where));
  BAKE_RETURN_IF_ERROR(numberArrayMember(source, "scale", node.scale, where));
  return node;
}

// glTF 2.0 (3.5.3): the nodes form disjoint strict trees. No node is the child of two nodes, no chain
// of children leads back to its start, and a scene lists each of its roots once, none of them a child.
Status checkNodeForest(const Document& doc, const std::vector<Node>& nodes, const std::vector<int>& roots) {
  std::vector<int> parent(nodes.size(), -1);
  for (std::size_t n = 0; n < nodes.size(); ++n) {
    for (const int child : nodes[n].children) {
      if (parent[std::size_t(child)] >= 0) {
        return invalidInput("child " + std::to_string(child) + " is already a child of node " +
                                std::to_string(parent[std::size_t(child)]) + " (a node has one parent at most)",
                            at(doc, "node " + std::to_string(n)));
      }
      parent[std::size_t(child)] = int(n);
    }
  }
  // With one parent each, a cycle is a chain of parents that comes back to a node on it.
  enum : char { kUnseen, kOnChain, kReachesRoot };
  std::vector<char> state(nodes.size(), kUnseen);
  for (std::size_t n = 0; n < nodes.size(); ++n) {
    std::vector<int> chain;
    int node = int(n);
    while (node >= 0 && state[std::size_t(node)] == kUnseen) {
      state[std::size_t(node)] = kOnChain;
      chain.push_back(node);
      node = parent[std::size_t(node)];
    }
    if (node >= 0 && state[std::size_t(node)] == kOnChain) {
      return invalidInput("node " + std::to_string(node) + " is its own ancestor (cycle)", at(doc, "node " + std::to_string(node)));
    }
    for (const int seen : chain) state[std::size_t(seen)] = kReachesRoot;
  }
  std::vector<bool> listed(nodes.size(), false);
  for (const int root : roots) {
    const Location where = at(doc, "scene root node " + std::to_string(root));
    if (listed[std::size_t(root)]) return invalidInput("listed twice", where);
    if (parent[std::size_t(root)] >= 0) {
      return invalidInput("is a child of node " + std::to_string(parent[std::size_t(root)]) + ", not a root", where);
    }
    listed[std::size_t(root)] = true;
  }
  return {};
}

Result<std::vector<int>> readSceneRoots(const Document& doc) {
  const json& scenes = arrayMember(doc.root, "scenes");
  if (scenes.empty()) return std::vector<int>{};
  BAKE_ASSIGN_OR_RETURN(const std::int64_t scene, integerMember(doc.root, "scene", 0, at(doc, "scene")));
  if (scene < 0 || std::size_t(scene) >= scenes.size()) return invalidInput("default scene does not exist", at(doc, "scene"));
  std::vector<int> roots;
  const Location where = at(doc, "scene " + std::to_string(scene));
  for (const json& root : arrayMember(scenes[std::size_t(scene)], "nodes")) {
    if (!root.is_number_integer() || root.get<std::int64_t>() < 0 ||
        std::size_t(root.get<std::int64_t>()) >= arrayMember(doc.root, "nodes").size()) {
      return invalidInput("root node " + root.dump() + " does not exist", where);
    }
    roots.push_back(root.get<int>());
  }
  return roots;
}

std::vector<std::string> stringArray(const json& value) {
  std::vector<std::string> out;
  for (const json& item : value) {
    if (item.is_string()) out.push_back(item.get<std::string>());
  }
  return out;
}

Result<Package> toPackage(const Document& doc) {
  Package package;
  const json& asset = doc.root.value("asset", json::object());
  if (!asset.is_object() || stringMember(asset, "version") != "2.0") {
    return unsupported("asset.version is \"" + (asset.is_object() ? stringMember(asset, "version") : std::string()) +
                           "\"; only glTF 2.0 is supported", at(doc, "asset"));
  }
  package.generator = stringMember(asset, "generator");
  package.extensionsUsed = stringArray(arrayMember(doc.root, "extensionsUsed"));
  package.extensionsRequired = stringArray(arrayMember(doc.root, "extensionsRequired"));
  if (doc.root.contains("extensions") && doc.root["extensions"].is_object()) package.extensions = doc.root["extensions"];
  package.materials = arrayMember(doc.root, "materials");
  package.cameras = arrayMember(doc.root, "cameras");
  package.images = arrayMember(doc.root, "images");
  package.textures = arrayMember(doc.root, "textures");
  package.samplers = arrayMember(doc.root, "samplers");

  for (std::size_t v = 0; v < arrayMember(doc.root, "bufferViews").size(); ++v) {
    BAKE_ASSIGN_OR_RETURN(const std::span<const std::uint8_t> bytes, bufferViewBytes(doc, v));
    package.blobs.push_back(Blob{{bytes.begin(), bytes.end()}, 1});
  }
  const json& meshes = arrayMember(doc.root, "meshes");
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    Mesh mesh{meshes[m].is_object() ? stringMember(meshes[m], "name") : "", {}};
    const json& primitives = meshes[m].is_object() ? arrayMember(meshes[m], "primitives") : json::array();
    for (std::size_t p = 0; p < primitives.size(); ++p) {
      const Location where = at(doc, "mesh " + std::to_string(m) + " primitive " + std::to_string(p));
      BAKE_ASSIGN_OR_RETURN(Primitive primitive, readPrimitive(doc, primitives[p], where));
      mesh.primitives.push_back(std::move(primitive));
    }
    package.meshes.push_back(std::move(mesh));
  }
  for (std::size_t n = 0; n < arrayMember(doc.root, "nodes").size(); ++n) {
    BAKE_ASSIGN_OR_RETURN(Node node, readNode(doc, n));
    package.nodes.push_back(std::move(node));
  }
  BAKE_ASSIGN_OR_RETURN(package.sceneRoots, readSceneRoots(doc));
  BAKE_RETURN_IF_ERROR(checkNodeForest(doc, package.nodes, package.sceneRoots));
  return package;
}

Result<json> parseJson(const std::string& text, const std::string& name) {
  BAKE_ASSIGN_OR_RETURN(json root, parseJsonText(text, name, "the glTF JSON is not valid JSON"));
  if (!root.is_object()) return invalidInput("the glTF JSON is not a JSON object", {name, "JSON"});
  return root;
}

}  // namespace

Result<Package> decode(std::span<const std::uint8_t> bytes, const std::string& name) {
  std::span<const std::uint8_t> binChunk;
  BAKE_ASSIGN_OR_RETURN(const std::string text, glbJsonChunk(bytes, name, binChunk));
  Document doc;
  doc.name = name;
  BAKE_ASSIGN_OR_RETURN(doc.root, parseJson(text, name));
  BAKE_RETURN_IF_ERROR(loadBuffers(doc, binChunk, fs::path(name).parent_path()));
  return toPackage(doc);
}

Result<Package> read(const fs::path& path) {
  BAKE_ASSIGN_OR_RETURN(const std::vector<std::uint8_t> bytes, readFileBytes(path));
  return decodeFile(bytes, path);
}

Result<Package> decodeFile(std::span<const std::uint8_t> bytes, const fs::path& path) {
  std::uint32_t magic = 0;
  if (bytes.size() >= 4) std::memcpy(&magic, bytes.data(), 4);
  if (magic == fmt::kMagic) return decode(bytes, path.string());
  Document doc;
  doc.name = path.string();
  const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  BAKE_ASSIGN_OR_RETURN(doc.root, parseJson(std::string(withoutByteOrderMark(text)), doc.name));
  BAKE_RETURN_IF_ERROR(loadBuffers(doc, {}, path.parent_path().empty() ? fs::path(".") : path.parent_path()));
  return toPackage(doc);
}

}  // namespace bake::glb
