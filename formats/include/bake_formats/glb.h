// Byte-level constants of glTF 2.0 binary packages (.glb), shared by libbake's writer and the
// runtime's reader. glTF 2.0 specification, section 4.4 (GLB file format) and 5.1 (accessor types).
#pragma once

#include <cstdint>

namespace bake::format::glb {

inline constexpr std::uint32_t kMagic = 0x46546C67;       // "glTF"
inline constexpr std::uint32_t kVersion = 2;
inline constexpr std::uint32_t kChunkJson = 0x4E4F534A;   // "JSON"
inline constexpr std::uint32_t kChunkBin = 0x004E4942;    // "BIN\0"
inline constexpr std::uint32_t kHeaderBytes = 12;
inline constexpr std::uint32_t kChunkHeaderBytes = 8;
inline constexpr std::uint32_t kChunkAlignment = 4;

// accessor.componentType
inline constexpr int kComponentI8 = 5120;
inline constexpr int kComponentU8 = 5121;
inline constexpr int kComponentI16 = 5122;
inline constexpr int kComponentU16 = 5123;
inline constexpr int kComponentU32 = 5125;
inline constexpr int kComponentF32 = 5126;

// bufferView.target
inline constexpr int kTargetArrayBuffer = 34962;
inline constexpr int kTargetElementArrayBuffer = 34963;

// mesh.primitive.mode
inline constexpr int kModePoints = 0;
inline constexpr int kModeTriangles = 4;
inline constexpr int kModeTriangleStrip = 5;
inline constexpr int kModeTriangleFan = 6;

// Vertex attributes must start on 4-byte boundaries (glTF 2.0, 3.6.2.4 "Data alignment").
inline constexpr std::uint32_t kVertexElementAlignment = 4;

// Application-specific attribute names start with an underscore (glTF 2.0, 3.7.2.1).
inline constexpr char kApplicationAttributePrefix = '_';
// Our vendor extensions are BAKE_<technique>, each with an integer "version" member.
inline constexpr const char* kVendorExtensionPrefix = "BAKE_";
inline constexpr const char* kDracoExtension = "KHR_draco_mesh_compression";

}  // namespace bake::format::glb
