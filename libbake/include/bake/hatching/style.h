// The style of a tonal art map (formats/tam.md, formats/tam-style.schema.json): tones, sizes, the
// stroke style and its random ranges, the construction's candidate count and seed. Read from JSON
// with errors naming the file and the JSON pointer of the element at fault.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "bake/core/status.h"
#include "bake/stroke/paintstroke.h"

namespace bake::hatching {

enum class StrokeKind { Hatching, CrossHatching, Stippling, Image };

struct Range {
  double min = 0, max = 0;
};

struct StrokeStyle {
  StrokeKind kind = StrokeKind::Hatching;
  Range length{0.3, 0.5};          // fraction of the tile side
  Range width{1.0, 1.5};           // pixels, the same at every level
  double angleDegrees = 0;         // direction of the strokes in the tile (0 = along +x)
  double angleJitterDegrees = 5;   // uniform jitter around it
  double curvature = 0.05;         // lateral bend of the middle point, fraction of the length
  int crossFrom = -1;              // cross-hatching: first tone (0-based) that adds the crossing strokes
  double crossAngleDegrees = 90;   // angle of the crossing strokes relative to `angleDegrees`
  std::array<double, 3> colour{0, 0, 0};  // ink colour; not black -> RGBA8 output
  double opacity = 1;
  double centreOpacity = 1, edgeOpacity = 0.8;  // breadthwise opacity
  double taper = 0.15;             // fraction of the length tapered at each end
  std::string image;               // Image kind: path of the stroke image (resolved against the style file)
  stroke::StrokeTexture texture;   // Image kind: loaded alpha
};

struct Style {
  std::string source;              // the style file, for messages
  std::vector<double> tones;       // target darkness per tone, strictly increasing in (0, 1)
  int resolution = 256;            // finest level's side (power of two)
  int levels = 4;                  // levels drawn with strokes: resolution, resolution/2, ...
  bool levelsGiven = false;        // the file gave `levels` (else it follows the resolution)
  StrokeStyle stroke;
  int candidates = 16;             // K: random candidates per stroke (Praun 2001)
  double blurSigma = 1.0;          // pixels: the blur under which tone progress is measured
  std::uint64_t seed = 1;

  bool coloured() const;           // ink colour other than black -> RGBA8
  std::vector<std::string> inputs() const;  // files the style reads (the style itself, the stroke image)
};

// Reads and validates a style file: every error names the file and the JSON pointer
// (e.g. "/stroke/width/min"). `tones` may be given as a count (evenly spaced darkness) or as values.
// With `loadImage` false the stroke image's path is resolved but the image is not read (for
// --print-inputs, which must list inputs that do not exist yet).
Result<Style> readStyle(const std::string& path);
Result<Style> readStyle(const std::string& path, bool loadImage);
Result<Style> parseStyle(const std::string& jsonText, const std::string& source, const std::string& baseDir);
Result<Style> parseStyle(const std::string& jsonText, const std::string& source, const std::string& baseDir,
                         bool loadImage);

// The default stroke level count for a resolution: the coarsest stroke level stays >= 8 texels
// wide, and at most 4 levels.
int defaultLevels(int resolution);

// Changes the resolution (an override of the style's): `levels` follows it when the file did not
// give it; both are checked (power of two within 8 .. 4096, levels within 1 .. log2(resolution)),
// errors naming `where` (e.g. "--resolution").
Status setResolution(Style& style, int resolution, const std::string& where);

const char* strokeKindName(StrokeKind kind);

}  // namespace bake::hatching
