// 3D paintstrokes (seed 002, Neulander & van de Panne 1998) over a BAKE_paintstrokes package
// (formats/paintstrokes.md): generalized cylinders whose path and radius are Catmull-Rom splines
// through control points, tessellated anew for every view on the GPU. The package's arrays (strokes,
// points, styles, baked shadows) are uploaded as they are and read by shaders/paintstrokes/; the
// runtime adds one array, the segments (stroke, first control point), and draws each segment as a
// patch of 4 control points. The tessellation control stage chooses the subdivision along the length
// from the projected size and curvature against a tolerance in pixels and across from the quality
// level (1, 2 or 4 polygons); the evaluation stage places the vertices on the half of the cylinder
// that faces the viewer.
//
// The reference (--stroke-tubes SIDESxSTEPS) draws the same strokes as fixed tubes tessellated on the
// CPU at load, shaded by the same formulas from the true surface normal.
//
// libbake reads and checks the extension (paintstrokes/package/package.h); paintstrokes_tubes.cpp builds the tubes;
// paintstrokes.cpp uploads and draws.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bake/io/glb.h"
#include "paintstrokes/package/package.h"
#include "render/renderer.h"

namespace bake::play {

// ---------------------------------------------------------------------------------------------
// paintstrokes_tubes.cpp

struct PaintstrokeOptions {
  int quality = 1;           // 0, 1, 2: format::paintstrokes::kPolygonsAcross[quality] polygons across
  float tolerance = 0.5f;    // screen-space tolerance of the subdivision along the length, pixels
  int tubeSides = 0;         // > 0: draw fixed tubes tessellated on the CPU instead (the reference)
  int tubeSteps = 0;         // rings per segment of those tubes
  bool tubes() const { return tubeSides > 0; }
  // "quality 1, tolerance 0.5 px" or "tubes 64x32", for reports.
  std::string describe() const;
};

// Checks the values of the command-line options (usage errors): quality 0..2, tolerance a finite
// number in [0.01, 1000] pixels, tubes empty or "SIDES[xSTEPS]" with SIDES in 3..1024 and STEPS in
// 1..1024 (STEPS defaults to SIDES / 2, at least 1).
Result<PaintstrokeOptions> makePaintstrokeOptions(int quality, double tolerance, const std::string& tubes);

// The package is read and checked by libbake (paintstrokes/package/package.h).
using paintstrokes::readPaintstrokes;
using paintstrokes::checkPaintstrokePackage;

// Fixed tubes around every stroke: `sides` vertices around, `steps` rings per segment. Each vertex
// is position, outward normal, unit tangent (model space), the parameter t in [0, 1] along its
// segment, the segment's first control point (global index) and the stroke index.
struct TubeVertex {
  float position[3];
  float normal[3];
  float tangent[3];
  float t;
  std::uint32_t point;
  std::uint32_t stroke;
};
static_assert(sizeof(TubeVertex) == 48);

struct TubeMesh {
  std::vector<TubeVertex> vertices;
  std::vector<std::uint32_t> indices;  // triangles, counter-clockwise seen from outside
};
TubeMesh buildStrokeTubes(const paintstrokes::PaintstrokePackage& package, int sides, int steps);

// ---------------------------------------------------------------------------------------------
// paintstrokes.cpp

// What the last frame generated: triangles counted by a GL_PRIMITIVES_GENERATED query around the
// strokes' draw, vertices (tessellated grids counted in the control stage, or the tubes' vertices).
struct PaintstrokeCounts {
  std::uint64_t polygons = 0;
  std::uint64_t vertices = 0;
  std::uint64_t predictedPolygons = 0;  // what the levels chosen should give (the tube mesh's triangles)
  std::uint64_t segments = 0;           // segments drawn (patches, or tube sections)
};

class PaintstrokesRenderer : public TechniqueRenderer {
 public:
  explicit PaintstrokesRenderer(PaintstrokeOptions options = {}) : options_(options) {}
  PaintstrokesRenderer(const PaintstrokesRenderer&) = delete;
  PaintstrokesRenderer& operator=(const PaintstrokesRenderer&) = delete;
  ~PaintstrokesRenderer() override;

  Status prepare(const Scene& scene, const std::vector<std::size_t>& instances,
                 gl::ShaderLibrary& shaders) override;
  void draw(const FrameContext& frame) override;
  std::size_t gpuBytes() const override;
  nlohmann::json statistics() const override;

  // Counts of the last frame drawn (waits for it).
  PaintstrokeCounts lastFrameCounts() const;
  const PaintstrokeOptions& options() const { return options_; }

 private:
  struct Upload {
    unsigned storage = 0;                  // the package's four arrays, then the segments
    std::size_t offset[5]{}, size[5]{};
    std::uint32_t segmentCount = 0;
    std::uint32_t shadowDirections = 0;
    std::vector<float> directions;         // shadowDirections x 3
    unsigned tubeVao = 0, tubeBuffers[2]{};
    std::uint32_t tubeIndexCount = 0, tubeVertexCount = 0;
    std::size_t strokes = 0, points = 0;
  };
  struct Item {
    std::size_t upload = 0;
    Mat4 world;
  };
  PaintstrokeOptions options_;
  std::vector<Upload> uploads_;
  std::vector<Item> items_;
  unsigned program_ = 0, emptyVao_ = 0, counters_ = 0, query_ = 0;
  bool drawn_ = false;
  std::size_t bytes_ = 0;
};

}  // namespace bake::play
