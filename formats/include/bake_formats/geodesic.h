// Constants of the BAKE_geodesic package (formats/geodesic.md), shared by geobake's writer and the
// runtime's reader.
#pragma once

#include <cstdint>

namespace bake::format::geodesic {

inline constexpr const char* kExtension = "BAKE_geodesic";
inline constexpr int kVersion = 1;

// Field k is the vertex attribute "_GEODESIC_k" (SCALAR, FLOAT or normalized UNSIGNED_SHORT).
inline constexpr const char* kAttributePrefix = "_GEODESIC_";
inline constexpr int kMaxFields = 64;

// Vertices no path reaches (another connected component). Reachable values lie in [0, 1].
inline constexpr float kUnreachableFloat = -1.0f;
// unorm16: reachable values use 0 .. kMaxReachableUnorm16, so a shader reading the normalized value
// sees 1.0 only for unreachable vertices (reachable values are <= 65534/65535).
inline constexpr std::uint16_t kUnreachableUnorm16 = 65535;
inline constexpr std::uint16_t kMaxReachableUnorm16 = 65534;

// Encodings ("encoding"), normalisations ("normalization") and methods ("method") by name.
inline constexpr const char* kEncodingFloat = "float";
inline constexpr const char* kEncodingUnorm16 = "unorm16";
inline constexpr const char* kNormalizationPerField = "per-field";
inline constexpr const char* kNormalizationGlobal = "global";
inline constexpr const char* kNormalizationNone = "none";

// Keys of the root extension object ("fields" is also the material's list of field indices) and of
// each of its field entries.
inline constexpr const char* kKeyFields = "fields";
inline constexpr const char* kKeyEncoding = "encoding";
inline constexpr const char* kKeyNormalization = "normalization";
inline constexpr const char* kFieldAttribute = "attribute";
inline constexpr const char* kFieldName = "name";
inline constexpr const char* kFieldMaxDistance = "maxDistance";

}  // namespace bake::format::geodesic
