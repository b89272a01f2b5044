// Constants and buffer layouts of the BAKE_grooves package (formats/grooves.md), shared by
// groovebake's writer (libbake/grooves/package/package.cpp), its reader and the runtime's loader and shader.
// Every record below is laid out as a GLSL std430 struct of 16-byte members (ivec4 / uvec4 / vec4),
// so a bufferView uploads as it is and binds with glBindBufferRange.
#pragma once

#include <cstddef>
#include <cstdint>

namespace bake::format::grooves {

inline constexpr const char* kExtension = "BAKE_grooves";
inline constexpr int kVersion = 2;
// Version 1 packages (no far level) are still read; the runtime counts their footprints over more
// primitives than it holds as truncated.
inline constexpr int kOldestReadableVersion = 1;

// The shading's reach (the CPU method in libbake/grooves and the runtime shader, passed as MAX_REACH):
// the footprint box is enlarged along a direction d by at most this many heights, |d_uv| / d_w capped
// here (about 89.4 degrees from the normal), so a view or light at the horizon stays finite.
inline constexpr double kMaxReach = 100;

// Every bufferView of the extension starts at a multiple of this (GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT
// and GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT are at most 256 on every implementation we know).
inline constexpr std::uint32_t kBufferAlignment = 256;

// The extension's "bufferViews" object names each array by these keys.
inline constexpr const char* kCellStart = "cellStart";          // uint32 x (cells + 1)
inline constexpr const char* kPrimitiveRefs = "primitiveRefs";  // uint32
inline constexpr const char* kRecordStart = "recordStart";      // uint32 x (cells + 1)
inline constexpr const char* kRecordRefs = "recordRefs";        // uint32
inline constexpr const char* kRecords = "records";              // Record
inline constexpr const char* kPrimitives = "primitives";        // Primitive
inline constexpr const char* kGrooves = "grooves";              // Groove
inline constexpr const char* kProfiles = "profiles";            // Profile
inline constexpr const char* kProfilePoints = "profilePoints";  // float b, h
inline constexpr const char* kMaterials = "materials";          // Material
inline constexpr const char* kFarClasses = "farClasses";        // FarClass (version 2)
inline constexpr const char* kFarTable = "farTable";            // float64 (version 2)
inline constexpr const char* kArrayKeys[] = {kCellStart, kPrimitiveRefs, kRecordStart,   kRecordRefs, kRecords,  kPrimitives,
                                             kGrooves,   kProfiles,     kProfilePoints, kMaterials,  kFarClasses, kFarTable};
inline constexpr std::size_t kArrayCount = sizeof(kArrayKeys) / sizeof(kArrayKeys[0]);
// The arrays a version 1 package has: the first ten.
inline constexpr std::size_t kVersion1ArrayCount = 10;
// Storage-buffer binding points of the runtime shader: array k of kArrayKeys at binding k, then these.
inline constexpr std::uint32_t kAreaScratchBinding = 12;
inline constexpr std::uint32_t kAreaRetryBinding = 13;
inline constexpr std::uint32_t kFrameCountsBinding = 14;

// What one footprint's shading holds in the runtime shader (its fixed arrays): primitives found
// under the footprint's box, and classes of parallel grooves among them. A footprint over more
// primitives is shaded from the far level; more classes than the shader keeps are dropped and counted.
inline constexpr std::size_t kMaxFoundPerFootprint = 24;
inline constexpr std::size_t kMaxClassesPerFootprint = 4;

inline constexpr const char* kWrapNone = "none";
inline constexpr const char* kWrapRepeat = "repeat";

// Positions are cell-local: a point x is stored as the fp32 offset x - (origin + anchor * cellSize)
// from the corner of its anchor cell (integer column, row; may lie outside the grid when a path leaves
// a repeating domain), so a reader rebuilds it relative to any cell with an exact integer offset.

// Primitive.header.w flags.
inline constexpr std::uint32_t kPrimitiveArc = 1u << 0;           // else a segment
inline constexpr std::uint32_t kPrimitiveCornerAtStart = 1u << 1;
inline constexpr std::uint32_t kPrimitiveEndAtStart = 1u << 2;
inline constexpr std::uint32_t kPrimitiveEndAtEnd = 1u << 3;

struct alignas(16) Primitive {
  std::int32_t anchor[2];     // the cell holding the start point a
  std::uint32_t groove;       // index into grooves
  std::uint32_t flags;        // kPrimitive*
  float ends[4];              // a.u, a.v, b.u, b.v (cell-local)
  float arc[4];               // centre.u, centre.v (cell-local), radius, start angle (radians)
  float measure[4];           // sweep (radians, counter-clockwise positive), arcStart, length, 0
  float jointPoints[4];       // start joint point, end joint point (cell-local)
  float jointNormals[4];      // start joint normal, end joint normal (unit, pointing into the primitive)
};
static_assert(sizeof(Primitive) == 96);

// Record.info.x kinds (grid.h SpecialRecord::Kind).
inline constexpr std::uint32_t kRecordIntersection = 0;
inline constexpr std::uint32_t kRecordEnd = 1;
inline constexpr std::uint32_t kRecordCorner = 2;

struct alignas(16) Record {
  std::int32_t anchor[4];     // the cell holding the point; z, w = 0
  std::uint32_t info[4];      // kind, primitive 0, primitive 1, 0
  float point[4];             // point (cell-local), 0, 0
  float box[4];               // lower.u, lower.v, upper.u, upper.v (cell-local)
};
static_assert(sizeof(Record) == 64);

// Groove.kind.y perturbation kinds.
inline constexpr std::uint32_t kPerturbationNone = 0;
inline constexpr std::uint32_t kPerturbationScale = 1;
inline constexpr std::uint32_t kPerturbationOffset = 2;
// Groove.kind.x flags.
inline constexpr std::uint32_t kGrooveClosed = 1u << 0;

struct alignas(16) Groove {
  std::uint32_t indices[4];       // profile, material, first primitive, primitive count
  std::uint32_t kind[4];          // flags (kGrooveClosed), perturbation kind, 0, 0
  float perturbation[4];          // amplitude, wavelength, phase, 0
  float bounds[4];                // wmax, hmax, dmax (perturbation included), 0
};
static_assert(sizeof(Groove) == 64);

struct alignas(16) Profile {
  std::uint32_t points[4];        // first point, point count, symmetric (0/1), 0
  float bounds[4];                // wmax, hmax, dmax, 0
};
static_assert(sizeof(Profile) == 32);

// profilePoints: float pairs (b, h), 8 bytes each (std430 vec2 array), right edge to left edge.
inline constexpr std::size_t kProfilePointSize = 8;

struct alignas(16) Material {
  float albedo[4];                // r, g, b, shininess
  float specular[4];              // r, g, b, has mirror (0/1)
  float mirror[4];                // r, g, b, 0
};
static_assert(sizeof(Material) == 48);

// The far level (version 2; libbake/grooves/bake/far_level.h): per class of grooves (profile, material,
// direction), a summed-area table of band area over a uniform grid of the domain, float64 nodes
// (columns + 1) x (rows + 1) per class, u fastest. The extension's "far" object gives the grid.
struct alignas(16) FarClass {
  std::uint32_t info[4];          // profile, material, representative primitive, 0
  float direction[4];             // unit tangent u, v; the profile's wmax; 0
};
static_assert(sizeof(FarClass) == 32);
inline constexpr std::size_t kFarTableEntrySize = 8;
inline constexpr const char* kFar = "far";  // {"cells": [columns, rows], "cellSize": [u, v]}

// Keys of the extension object: the bufferView of each array (by kArrayKeys) and the item count of
// each (by the same keys, plus "cells").
inline constexpr const char* kBufferViews = "bufferViews";
inline constexpr const char* kCounts = "counts";

}  // namespace bake::format::grooves
