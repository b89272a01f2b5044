// Constants of the BAKE_revolution package (formats/revolution.md), shared by revolbake's writer,
// the CPU ray march and the runtime's reader and shader.
#pragma once

#include <cstdint>

namespace bake::format::revolution {

inline constexpr const char* kExtension = "BAKE_revolution";
inline constexpr int kVersion = 1;

// The shape map covers the (r, h) half-plane of the profile: r (radius) across, h (height along the
// axis) down the rows, equal texel size in both. Texel (i, j) has its centre at
// r = (i + 0.5) * texelSize, h = hMin + (j + 0.5) * texelSize; r = 0 is the left edge of column 0,
// so a sampler mirrored at that edge sees the distance field's own symmetry about the axis.
// Channels: R, G = unit gradient (d/dr, d/dh) of the signed distance; B = signed distance (negative
// inside the solid); A = coverage of the texel by the solid. Rows are stored bottom (hMin) first.
inline constexpr int kShapeMapChannels = 4;

// Distance encodings ("encoding"). With scale S ("distanceScale", object units):
//   float:   RGBA 32-bit floats; B = d, R/G = gradient, A = coverage.
//   unorm16: RGBA unsigned 16-bit normalized; B = 0.5 + 0.5 d/S, R/G = 0.5 + 0.5 g, A = coverage.
//   sqrt8:   RGBA unsigned 8-bit normalized; B = 0.5 + 0.5 sign(d) sqrt(|d|/S), R/G and A as unorm16.
// (8-bit linear is not offered: at 1024^2 and above its step exceeds a texel near the surface.)
inline constexpr const char* kEncodingFloat = "float";
inline constexpr const char* kEncodingUnorm16 = "unorm16";
inline constexpr const char* kEncodingSqrt8 = "sqrt8";

// Displacement map: RG = dH/du, dH/dv of the height map H(u, v), u = angle / 2 pi (wraps), v along
// the projection's second coordinate; stored as unorm16 0.5 + 0.5 x / scale ("derivativeScale").
inline constexpr int kDisplacementChannels = 2;

// Texture projections ("projection").
inline constexpr const char* kProjectionCylindrical = "cylindrical";
inline constexpr const char* kProjectionSpherical = "spherical";
inline constexpr const char* kProjectionArcLength = "arc-length";

// Over-relaxed sphere tracing: a step of `overRelaxation` times the distance, undone when the next
// distance shows the two spheres do not overlap (Keinert et al. 2014).
inline constexpr float kDefaultOverRelaxation = 1.6f;
// A ray has hit when the decoded distance minus the safety margin is below this many texels.
inline constexpr float kHitEpsilonTexels = 0.05f;

// Most proxy bands a package may carry (the shader's uniform array).
inline constexpr int kMaxProxyBands = 64;

// Replicas (seed 001 Eq. 9: only the fractional part of the hit point's coordinates addresses the
// maps, so one shape box holds many copies of the object). "replicas" is optional:
//   {"layout": "grid", "count": [nx, ny, nz], "spacing": [sx, sy, sz], "mirror": [bx, by, bz]}
//     copy (i, j, k) is the object moved by (i sx, j sy, k sz); a mirrored axis reflects every odd
//     copy about its box's centre on that axis (the mirror-and-repetition variant, seed 001 Fig. 13);
//     each spacing is at least the shape box's extent on its axis, so copies never overlap;
//   {"layout": "ring", "count": n, "radius": R}
//     copy k is the object moved out to distance R along +x and turned 2 pi k / n about +y; each
//     copy's solid (r <= the box's rMax) must lie inside its wedge of angle 2 pi / n: R sin(pi / n)
//     >= rMax.
inline constexpr const char* kReplicas = "replicas";
inline constexpr const char* kLayoutGrid = "grid";
inline constexpr const char* kLayoutRing = "ring";
inline constexpr int kMaxReplicas = 4096;     // copies in all
inline constexpr int kMaxReplicasPerAxis = 1024;

// "selfShadow": true marches a second ray from each hit toward the light through the same box (its
// copies included); a hit on the way puts the point in shadow. Absent: false.
inline constexpr const char* kSelfShadow = "selfShadow";

// Keys of the material extension that name bufferViews: each of these objects holds one
// "bufferView" (displacementMap and arcLengthMap are optional).
inline constexpr const char* kShapeMap = "shapeMap";
inline constexpr const char* kDisplacementMap = "displacementMap";
inline constexpr const char* kArcLengthMap = "arcLengthMap";
inline constexpr const char* kBufferView = "bufferView";

}  // namespace bake::format::revolution
