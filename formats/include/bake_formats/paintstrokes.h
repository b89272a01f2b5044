// Constants and buffer layouts of the BAKE_paintstrokes package (formats/paintstrokes.md), shared by
// strokebake's writer (libbake/paintstrokes/package.cpp), its reader and the runtime's loader and shaders
// (shaders/paintstrokes/, which receive the constants as #defines). A paintstroke (seed 002) is a
// generalized cylinder: a Catmull-Rom path through control points whose radius (Catmull-Rom too),
// colour, opacity and reflectance vary along the length. Records are std430 layouts (16-byte members)
// so every bufferView uploads as it is and binds with glBindBufferRange.
#pragma once

#include <cstddef>
#include <cstdint>

namespace bake::format::paintstrokes {

inline constexpr const char* kExtension = "BAKE_paintstrokes";
inline constexpr int kVersion = 1;

// Every bufferView of the extension starts at a multiple of this (largest SSBO offset alignment).
inline constexpr std::uint32_t kBufferAlignment = 256;

// The extension's "bufferViews" and "counts" objects name each array by these keys.
inline constexpr const char* kStrokes = "strokes";   // Stroke, one per stroke
inline constexpr const char* kPoints = "points";     // ControlPoint, every stroke's points in order
inline constexpr const char* kStyles = "styles";     // Style
inline constexpr const char* kShadows = "shadows";   // uint8 unorm, points x shadowDirections
inline constexpr const char* kArrayKeys[] = {kStrokes, kPoints, kStyles, kShadows};
inline constexpr std::size_t kArrayCount = sizeof(kArrayKeys) / sizeof(kArrayKeys[0]);
inline constexpr const char* kBufferViews = "bufferViews";
inline constexpr const char* kCounts = "counts";

// Limits a reader enforces (and the writer never exceeds).
inline constexpr std::uint32_t kMaxPointsPerStroke = 65535;
inline constexpr std::uint32_t kMaxShadowDirections = 16;
inline constexpr std::uint32_t kMaxStyles = 256;

// Quantisation (the error bounds strokebake reports):
// - a control point's position is 3 x uint16 over its stroke's own box: p = origin + q * step, so the
//   error per axis is at most step / 2 = extent / 65535 / 2;
// - its radius is uint16 over the stroke's largest radius: r = q * radiusStep (radiusStep =
//   rmax / 65535), error at most radiusStep / 2; a stored radius is never 0 (q >= 1);
// - colour, opacity, reflectance and baked shadow are 8-bit unorm, error at most 1 / 510.
inline constexpr double kPositionLevels = 65535;
inline constexpr double kRadiusLevels = 65535;

// Stroke.info.w flags.
inline constexpr std::uint32_t kStrokeClosed = 1u << 0;  // reserved in version 1 (never written)

struct alignas(16) Stroke {
  std::uint32_t info[4];    // first point, point count (>= 2), style index, flags
  float origin[4];          // quantisation origin x, y, z; radiusStep
  float step[4];            // quantisation step x, y, z (extent / 65535; 0 on a flat axis); 0
  float sphere[4];          // culling sphere: centre x, y, z, radius; holds the whole interpolated
                            // path swept by its radius (Catmull-Rom overshoot included)
};
static_assert(sizeof(Stroke) == 64);

// One control point, 16 bytes, read in GLSL as a uvec4 (little-endian):
//   x: position q.x | q.y << 16      y: q.z | radius q << 16
//   z: colour r | g << 8 | b << 16 | opacity << 24 (8-bit unorm each; colour is linear RGB)
//   w: reflectance | 0 << 8 | 0 << 16 | 0 << 24 (reflectance: unorm scale of the lit colour)
struct ControlPoint {
  std::uint16_t position[3];
  std::uint16_t radius;
  std::uint8_t colour[3];
  std::uint8_t opacity;
  std::uint8_t reflectance;
  std::uint8_t reserved[3];  // zero
};
static_assert(sizeof(ControlPoint) == 16);

struct alignas(16) Style {
  float opacity[4];         // centre opacity, edge opacity (breadthwise, seed 002), volume opacity
                            // across the path (view orthogonal to it), along the path (view along it)
  float specular[4];        // r, g, b, shininess (Blinn-Phong exponent)
  float shading[4];         // ambient, edge softness in pixels (antialiasing ramp), 0, 0
};
static_assert(sizeof(Style) == 48);

// Baked self-shadowing (seed 002, last paragraph): `shadows` holds, per control point and per
// direction of the extension's "shadowDirections" (unit vectors towards the light, in the package's
// model space), the 8-bit unorm scale of the point's reflectance for light from that direction:
// shadows[point * directionCount + k]. With no direction the array is empty (count 0, one zeroed
// item stored) and strokes are unshadowed. The shader weights the directions by
// max(dot(L, d_k), 0)^kShadowBlendExponent, normalised (nearest direction when all weights are 0).
inline constexpr float kShadowBlendExponent = 8.0f;

// Quality levels of the runtime's view-dependent tessellation (seed 002): the visible side of each
// segment is covered by 1, 2 or 4 polygons across its breadth.
inline constexpr int kQualityLevels = 3;
inline constexpr int kPolygonsAcross[kQualityLevels] = {1, 2, 4};

}  // namespace bake::format::paintstrokes
