// bakeinfo's work: decode a package completely with the same readers the runtime uses (so anything
// bakeinfo accepts, a loader accepts too) and summarise it. Value ranges are computed from the
// decoded data, not copied from accessor min/max, so they also describe Draco-compressed attributes.
#include "info/describe.h"

#include <bake_formats/glb.h>
#include <bake_formats/ktx2.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "bake/core/atomic_file.h"
#include "bake/io/glb.h"
#include "io/ktx2.h"
#include "techniques/registry.h"

namespace bake::info {
namespace {
using nlohmann::json;
namespace fs = std::filesystem;

enum class FileKind { Glb, GltfText, Ktx2, Unknown };

FileKind sniff(const std::vector<std::uint8_t>& bytes) {
  const auto& id = format::ktx2::kIdentifier;
  if (bytes.size() >= id.size() && std::equal(id.begin(), id.end(), bytes.begin())) return FileKind::Ktx2;
  std::uint32_t magic = 0;
  if (bytes.size() >= 4) std::memcpy(&magic, bytes.data(), 4);
  if (magic == format::glb::kMagic) return FileKind::Glb;
  const std::size_t bom = bytes.size() >= 3 && bytes[0] == 0xEF && bytes[1] == 0xBB && bytes[2] == 0xBF ? 3 : 0;
  const auto first = std::find_if(bytes.begin() + std::ptrdiff_t(bom), bytes.end(), [](std::uint8_t c) { return !std::isspace(c); });
  if (first != bytes.end() && *first == '{') return FileKind::GltfText;
  return FileKind::Unknown;
}

json componentRanges(const glb::Attribute& attribute) {
  const std::vector<float> values = attribute.toFloats();
  json lo = json::array(), hi = json::array();
  const std::size_t count = attribute.count();
  for (int c = 0; c < attribute.components && count > 0; ++c) {
    float a = INFINITY, b = -INFINITY;
    bool finite = true;
    for (std::size_t i = 0; i < count; ++i) {
      const float v = values[i * std::size_t(attribute.components) + std::size_t(c)];
      if (!std::isfinite(v)) {
        finite = false;
        continue;
      }
      a = std::min(a, v);
      b = std::max(b, v);
    }
    lo.push_back(a <= b ? json(a) : json(nullptr));
    hi.push_back(a <= b ? json(b) : json(nullptr));
    if (!finite) return json{{"min", lo}, {"max", hi}, {"nonFinite", true}};
  }
  return json{{"min", lo}, {"max", hi}, {"nonFinite", false}};
}

const char* modeName(int mode) {
  static const char* const kNames[] = {"points", "lines", "line loop", "line strip", "triangles",
                                       "triangle strip", "triangle fan"};
  return mode >= 0 && mode <= 6 ? kNames[mode] : "unknown";
}

std::size_t triangleCount(const glb::Primitive& primitive) {
  const std::size_t n = primitive.indices.empty() ? primitive.vertexCount() : primitive.indices.size();
  if (primitive.mode == format::glb::kModeTriangles) return n / 3;
  if (primitive.mode == format::glb::kModeTriangleStrip || primitive.mode == format::glb::kModeTriangleFan) {
    return n >= 3 ? n - 2 : 0;
  }
  return 0;
}

json describePrimitive(const glb::Primitive& primitive) {
  json attributes = json::array();
  for (const glb::Attribute& attribute : primitive.attributes) {
    json entry = {{"name", attribute.name},
                  {"componentType", glb::componentTypeName(attribute.componentType)},
                  {"components", attribute.components},
                  {"normalized", attribute.normalized},
                  {"count", attribute.count()}};
    entry["range"] = componentRanges(attribute);
    attributes.push_back(std::move(entry));
  }
  return json{{"mode", modeName(primitive.mode)},
              {"vertices", primitive.vertexCount()},
              {"indices", primitive.indices.size()},
              {"triangles", triangleCount(primitive)},
              {"material", primitive.material},
              {"draco", primitive.dracoCompressed},
              {"attributes", attributes}};
}

// Every extension with its "version" member when it has one (ours always do), wherever it appears.
void collectExtensions(const json& value, const std::string& pointer, json& out) {
  if (value.is_object()) {
    for (const auto& [key, child] : value.items()) {
      if (key == "extensions" && child.is_object()) {
        for (const auto& [name, body] : child.items()) {
          json entry = {{"name", name}, {"at", pointer.empty() ? "/" : pointer}};
          if (body.is_object() && body.contains("version")) entry["version"] = body["version"];
          out.push_back(std::move(entry));
        }
      }
      collectExtensions(child, pointer + "/" + key, out);
    }
  } else if (value.is_array()) {
    for (std::size_t i = 0; i < value.size(); ++i) collectExtensions(value[i], pointer + "/" + std::to_string(i), out);
  }
}

json describeGlb(const glb::Package& package, const std::string& container) {
  json meshes = json::array();
  for (const glb::Mesh& mesh : package.meshes) {
    json primitives = json::array();
    for (const glb::Primitive& primitive : mesh.primitives) primitives.push_back(describePrimitive(primitive));
    meshes.push_back({{"name", mesh.name}, {"primitives", primitives}});
  }
  json namedNodes = json::array();
  for (const glb::Node& node : package.nodes) {
    if (!node.name.empty()) namedNodes.push_back(node.name);
  }
  json extensions = json::array();
  collectExtensions({{"extensions", package.extensions}}, "", extensions);
  collectExtensions({{"materials", package.materials}}, "", extensions);
  std::size_t blobBytes = 0;
  for (const glb::Blob& blob : package.blobs) blobBytes += blob.bytes.size();
  return json{{"kind", "gltf"},
              {"container", container},
              {"generator", package.generator},
              {"extensionsUsed", package.extensionsUsed},
              {"extensionsRequired", package.extensionsRequired},
              {"extensions", extensions},
              {"nodes", package.nodes.size()},
              {"namedNodes", namedNodes},
              {"materials", package.materials.size()},
              {"bufferViews", package.blobs.size()},
              {"bufferViewBytes", blobBytes},
              {"meshes", meshes}};
}

std::string printableText(const std::vector<std::uint8_t>& value) {
  std::string text(value.begin(), value.end());
  if (!text.empty() && text.back() == '\0') text.pop_back();
  const bool printable = std::all_of(text.begin(), text.end(), [](unsigned char c) { return c >= 32 || c == '\n' || c == '\t'; });
  return printable ? text : std::string();
}

json describeKtx2(const ktx2::Texture& texture, const ktx2::Header& header) {
  json levels = json::array();
  for (std::uint32_t level = 0; level < texture.levels.size(); ++level) {
    levels.push_back({{"width", texture.levelWidth(level)}, {"height", texture.levelHeight(level)},
                      {"bytes", texture.levels[level].size()}});
  }
  json metadata = json::object();
  for (const auto& [key, value] : texture.metadata) {
    const std::string text = printableText(value);
    metadata[key] = text.empty() && !value.empty() && value != std::vector<std::uint8_t>{0}
                        ? json{{"bytes", value.size()}}
                        : json(text);
  }
  return json{{"kind", "ktx2"},
              {"format", ktx2::formatName(texture.format)},
              {"vkFormat", header.vkFormat},
              {"width", texture.width},
              {"height", texture.height},
              {"layers", texture.layers},
              {"array", texture.layers > 0},
              {"levels", levels},
              {"fullMipChain", texture.levels.size() == ktx2::fullMipCount(texture.width, texture.height)},
              {"supercompression", header.supercompression == format::ktx2::kSupercompressionZstd ? "zstd" : "none"},
              {"metadata", metadata}};
}

// What each technique the package uses says of its data (the registry's describers).
Status describeTechniques(const glb::Package& package, const std::string& name, json& description) {
  for (const techniques::Technique& technique : techniques::all()) {
    if (!technique.describe || !techniques::usedBy(technique, package)) continue;
    BAKE_ASSIGN_OR_RETURN(description[technique.name], technique.describe(package, name));
  }
  return {};
}

}  // namespace

Result<json> describeFile(const fs::path& path) {
  BAKE_ASSIGN_OR_RETURN(const std::vector<std::uint8_t> bytes, readFileBytes(path));
  json description;
  switch (sniff(bytes)) {
    case FileKind::Glb: {
      BAKE_ASSIGN_OR_RETURN(const glb::Package package, glb::decode(bytes, path.string()));
      description = describeGlb(package, "glb");
      BAKE_RETURN_IF_ERROR(describeTechniques(package, path.string(), description));
      break;
    }
    case FileKind::GltfText: {
      BAKE_ASSIGN_OR_RETURN(const glb::Package package, glb::decodeFile(bytes, path));
      description = describeGlb(package, "gltf");
      BAKE_RETURN_IF_ERROR(describeTechniques(package, path.string(), description));
      break;
    }
    case FileKind::Ktx2: {
      BAKE_ASSIGN_OR_RETURN(const ktx2::Header header, ktx2::decodeHeader(bytes, path.string()));
      BAKE_ASSIGN_OR_RETURN(const ktx2::Texture texture, ktx2::decode(bytes, path.string()));
      description = describeKtx2(texture, header);
      break;
    }
    case FileKind::Unknown:
      return invalidInput(bytes.empty() ? "file is empty" : "neither a glTF (.glb/.gltf) nor a KTX2 file",
                          {path.string(), "header"});
  }
  description["file"] = path.string();
  description["bytes"] = bytes.size();
  return description;
}

namespace {

void formatGltf(const json& d, std::ostringstream& out) {
  out << d["file"].get<std::string>() << ": glTF 2.0 " << (d["container"] == "glb" ? "binary" : "text") << ", "
      << d["bytes"] << " bytes, " << plural(d["meshes"].size(), "mesh") << ", " << plural(d["nodes"].get<std::size_t>(), "node") << ", "
      << plural(d["materials"].get<std::size_t>(), "material") << ", generator \"" << d["generator"].get<std::string>() << "\"\n";
  for (const json& extension : d["extensions"]) {
    const std::string name = extension["name"];
    const bool required = std::find(d["extensionsRequired"].begin(), d["extensionsRequired"].end(), name) !=
                          d["extensionsRequired"].end();
    out << "  extension " << name;
    if (extension.contains("version")) out << " version " << extension["version"].dump();
    out << " at " << extension["at"].get<std::string>() << (required ? " (required)" : "") << "\n";
  }
  if (!d["namedNodes"].empty()) {
    out << "  named nodes:";
    for (const json& name : d["namedNodes"]) out << " " << name.get<std::string>();
    out << "\n";
  }
  for (std::size_t m = 0; m < d["meshes"].size(); ++m) {
    const json& mesh = d["meshes"][m];
    out << "  mesh " << m << (mesh["name"].get<std::string>().empty() ? "" : " \"" + mesh["name"].get<std::string>() + "\"")
        << ": " << plural(mesh["primitives"].size(), "primitive") << "\n";
    for (std::size_t p = 0; p < mesh["primitives"].size(); ++p) {
      const json& primitive = mesh["primitives"][p];
      out << "    primitive " << p << ": " << primitive["mode"].get<std::string>() << ", "
          << std::to_string(primitive["vertices"].get<std::size_t>()) + " vertices" << ", " << plural(primitive["triangles"].get<std::size_t>(), "triangle");
      if (primitive["material"].get<int>() >= 0) out << ", material " << primitive["material"];
      if (primitive["draco"].get<bool>()) out << ", Draco";
      out << "\n";
      for (const json& attribute : primitive["attributes"]) {
        out << "      " << attribute["name"].get<std::string>() << ": " << attribute["componentType"].get<std::string>()
            << " x" << attribute["components"] << (attribute["normalized"].get<bool>() ? " normalized" : "")
            << ", min " << vectorText(attribute["range"]["min"]) << " max " << vectorText(attribute["range"]["max"])
            << (attribute["range"]["nonFinite"].get<bool>() ? ", HAS NaN/Inf" : "") << "\n";
      }
    }
  }
  out << "  buffer views: " << d["bufferViews"] << " (" << d["bufferViewBytes"] << " bytes)\n";
  for (const techniques::Technique& technique : techniques::all()) {
    if (technique.formatDescription && d.contains(technique.name)) out << technique.formatDescription(d[technique.name]);
  }
}

void formatKtx2(const json& d, std::ostringstream& out) {
  out << d["file"].get<std::string>() << ": KTX2 " << d["format"].get<std::string>() << ", " << d["width"] << "x"
      << d["height"];
  if (d["array"].get<bool>()) out << ", array of " << plural(d["layers"].get<std::size_t>(), "layer");
  out << ", " << plural(d["levels"].size(), "level") << (d["fullMipChain"].get<bool>() ? " (full mip chain)" : "")
      << ", supercompression " << d["supercompression"].get<std::string>() << ", " << d["bytes"] << " bytes\n";
  for (std::size_t level = 0; level < d["levels"].size(); ++level) {
    const json& l = d["levels"][level];
    out << "  level " << level << ": " << l["width"] << "x" << l["height"] << ", " << l["bytes"] << " bytes\n";
  }
  for (const auto& [key, value] : d["metadata"].items()) {
    out << "  " << key << ": " << (value.is_string() ? value.get<std::string>() : value.dump()) << "\n";
  }
}

}  // namespace

std::string numberText(const json& value) {
  if (value.is_null()) return "-";
  std::ostringstream out;
  out.precision(6);
  out << value.get<double>();
  return out.str();
}

std::string vectorText(const json& values) {
  std::string text = "(";
  for (std::size_t i = 0; i < values.size(); ++i) text += (i ? ", " : "") + numberText(values[i]);
  return text + ")";
}

std::string plural(std::size_t n, const std::string& word) {
  if (n == 1) return "1 " + word;
  const bool sibilant = word.ends_with('s') || word.ends_with('x') || word.ends_with("sh") || word.ends_with("ch");
  return std::to_string(n) + " " + word + (sibilant ? "es" : "s");
}

std::string formatText(const json& description) {
  std::ostringstream out;
  if (description.value("kind", "") == "ktx2") {
    formatKtx2(description, out);
  } else {
    formatGltf(description, out);
  }
  return out.str();
}

}  // namespace bake::info
