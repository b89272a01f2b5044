// Constants of tonal art maps (formats/tam.md): the KTX2 file tambake writes and the BAKE_hatching
// material extension that points a mesh at one. Shared by tambake's writer, the runtime's reader and
// the hatching shaders' uniforms.
#pragma once

namespace bake::format::tam {

inline constexpr int kVersion = 1;

// KTX2 key/value entry holding the TAM's description as JSON text (NUL-terminated, as KTX2 asks):
// {"version", "tones" [darkness per layer, light -> dark], "strokeLevels" (levels drawn with strokes,
//  the rest of the mip chain is box-filtered), "style", "seed", "colour" (bool)}.
inline constexpr const char* kMetadataKey = "BAKE_tam";

// Texel values are paper brightness: 1 (255) is untouched paper, 0 is full ink. Layer k is tone k;
// tone values are the target mean ink darkness (1 - mean brightness) of that layer, increasing.
// R8 for black ink; RGBA8 for coloured ink (RGB = the composited colour, A = brightness).
inline constexpr int kMaxTones = 16;

// The threshold texture (Webb et al. 2002, fine tone control): R8, same size and mip chain as the
// TAM, one layer; a texel holds the darkness at which it turns to ink (ink >= kThresholdInk), ordered
// by the stroke that first inked it and spaced so that inking every texel at or below a darkness
// reproduces that darkness (formats/tam.md), or 255 when no tone inks it. Its KTX2 metadata entry
// kMetadataKey carries the same JSON plus "threshold": true.
inline constexpr double kThresholdInk = 0.5;

// glTF material extension pointing a mesh at a TAM embedded in the package (an image with
// mimeType "image/ktx2" in a bufferView).
inline constexpr const char* kExtension = "BAKE_hatching";
inline constexpr const char* kKtx2MimeType = "image/ktx2";

// Hatching orientation (seed 004 section 3.2, figure 14): strokes along the light's projection on
// the triangle (B = projected light) or across it.
inline constexpr const char* kOrientationTowardLight = "toward-light";
inline constexpr const char* kOrientationAcrossLight = "across-light";

// Adjacent triangles whose normals make an angle above 90 degrees do not blend (seed 004 section 3.3).
inline constexpr float kMinBlendCosine = 0.0f;

// Keys of the BAKE_hatching extension that hold indices into the package's images.
inline constexpr const char* kTamImage = "tam";
inline constexpr const char* kThresholdImage = "threshold";

}  // namespace bake::format::tam
