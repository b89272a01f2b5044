// Our packages are glTF 2.0 binaries (.glb) whose standard parts stay standard and whose baked data
// live in vendor extensions BAKE_<technique>. This is the in-memory form of such a package, its
// writer (optionally Draco-compressing the meshes with KHR_draco_mesh_compression) and its reader.
// The reader also accepts any other glTF 2.0 file (.glb or .gltf), as the input of a bake.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include <nlohmann/json.hpp>

#include "bake/core/status.h"

namespace bake::glb {

enum class ComponentType { I8, U8, I16, U16, U32, F32 };

int gltfComponentType(ComponentType type);  // 5120 ...
std::size_t componentSize(ComponentType type);
const char* componentTypeName(ComponentType type);  // "u16", ...

// One vertex attribute: `count` elements of `components` values, tightly packed, little-endian.
struct Attribute {
  std::string name;  // "POSITION", "NORMAL", "TEXCOORD_0", "_GEODESIC_0", ...
  ComponentType componentType = ComponentType::F32;
  int components = 1;
  bool normalized = false;
  std::vector<std::uint8_t> bytes;

  std::size_t elementSize() const { return componentSize(componentType) * std::size_t(components); }
  std::size_t count() const { return elementSize() ? bytes.size() / elementSize() : 0; }

  static Attribute fromFloats(std::string name, int components, std::span<const float> values);
  // Quantises values in [0, 1] to normalized unsigned 16-bit integers (rounding to nearest).
  static Attribute fromUnorm16(std::string name, int components, std::span<const float> values);
  // Values as floats, dequantised by the glTF rules for normalized integers.
  std::vector<float> toFloats() const;
};

struct Primitive {
  int mode = 4;  // triangles
  std::vector<Attribute> attributes;
  std::vector<std::uint32_t> indices;  // empty: non-indexed
  int material = -1;
  bool dracoCompressed = false;  // set by the reader: the file stored it with KHR_draco_mesh_compression

  const Attribute* find(const std::string& name) const;
  std::size_t vertexCount() const;
};

struct Mesh {
  std::string name;
  std::vector<Primitive> primitives;
};

struct Node {
  std::string name;
  int mesh = -1;
  std::vector<int> children;
  std::optional<std::array<double, 16>> matrix;  // column-major; replaces T/R/S when present
  std::array<double, 3> translation{0, 0, 0};
  std::array<double, 4> rotation{0, 0, 0, 1};  // quaternion x, y, z, w
  std::array<double, 3> scale{1, 1, 1};
  int camera = -1;
  nlohmann::json extensions = nlohmann::json::object();  // e.g. KHR_lights_punctual

  std::array<double, 16> localMatrix() const;
};

// Bytes of a bufferView that an extension refers to by index (a grid, a texture, ...).
struct Blob {
  std::vector<std::uint8_t> bytes;
  std::uint32_t alignment = 16;  // offset alignment in the binary chunk, for direct upload
};

// An array of trivially copyable records as a blob, for a package's bufferViews. glTF forbids empty
// bufferViews: an empty array is stored as one zeroed record (its count, elsewhere, says 0).
template <class T>
Blob blobOf(const std::vector<T>& items, std::uint32_t alignment) {
  static_assert(std::is_trivially_copyable_v<T>);
  Blob blob;
  blob.alignment = alignment;
  blob.bytes.assign(std::max<std::size_t>(1, items.size()) * sizeof(T), 0);
  if (!items.empty()) std::memcpy(blob.bytes.data(), items.data(), items.size() * sizeof(T));
  return blob;
}

struct Package {
  std::vector<Mesh> meshes;
  std::vector<Node> nodes;
  std::vector<int> sceneRoots;  // empty: every node without a parent
  nlohmann::json materials = nlohmann::json::array();  // glTF material objects, kept as JSON
  nlohmann::json cameras = nlohmann::json::array();    // glTF camera objects, kept as JSON
  // glTF images, textures and samplers, kept as JSON; an embedded image names its blob by
  // "bufferView" (blob i is bufferView i).
  nlohmann::json images = nlohmann::json::array();
  nlohmann::json textures = nlohmann::json::array();
  nlohmann::json samplers = nlohmann::json::array();
  nlohmann::json extensions = nlohmann::json::object();  // top-level extension objects by name
  std::vector<std::string> extensionsRequired;
  // Written as bufferViews 0..n-1, before any vertex data, so extensions refer to blob i as
  // bufferView i. A package that was read back holds every bufferView of the file here.
  std::vector<Blob> blobs;
  // Filled by the reader: extensions named in extensionsUsed, and the generator string.
  std::vector<std::string> extensionsUsed;
  std::string generator;
};

struct DracoOptions {
  bool enabled = false;
  bool preserveOrder = false;  // sequential encoding keeps vertex and triangle order (larger files)
  int positionBits = 14;
  int normalBits = 10;
  int texcoordBits = 12;
  int genericBits = 14;  // colours and application attributes (_NAME)
  int speed = 3;         // Draco encoder speed 0 (best compression) .. 10 (fastest)
};

struct WriteOptions {
  DracoOptions draco;
};

// Bits Draco uses for an attribute under these options (0: not quantised, e.g. integer data).
int dracoQuantizationBits(const Attribute& attribute, const DracoOptions& options);
// Largest error Draco's quantisation can give this attribute: range / (2^bits - 1) / 2, where range
// is the largest extent of its values over all components. Not for NORMAL, which Draco codes
// octahedrally (its error is an angle, not this bound).
double dracoQuantizationBound(const Attribute& attribute, const DracoOptions& options);

Result<std::vector<std::uint8_t>> encode(const Package& package, const WriteOptions& options = {});
Status write(const std::filesystem::path& path, const Package& package, const WriteOptions& options = {});

// `name` is used in error messages. Draco-compressed primitives are decoded.
Result<Package> decode(std::span<const std::uint8_t> bytes, const std::string& name = "<memory>");
// .glb or .gltf (external buffers and data URIs resolved relative to the file).
Result<Package> read(const std::filesystem::path& path);
// What read() makes of the bytes of the file at `path` (already read): a GLB, or a .gltf whose
// buffer files are found beside it.
Result<Package> decodeFile(std::span<const std::uint8_t> bytes, const std::filesystem::path& path);

}  // namespace bake::glb
