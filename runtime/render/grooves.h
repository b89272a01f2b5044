// Grooved surfaces (seed 000, Bosch et al. 2008, §4-§7) over a BAKE_grooves package
// (formats/grooves.md): the preview plane, or any mesh with TEXCOORD_0, drawn with a fragment shader
// that runs the seed's method per pixel exactly as libbake's CPU oracle (libbake/grooves/oracle/shade.h)
// does. The package's arrays are decoded and checked by libbake (decodeGroovePackage) and uploaded as
// they are, one storage buffer holding every bufferView at its 256-byte aligned offset, each bound
// with glBindBufferRange; the grid header goes into a small uniform block.
//
// grooves.cpp uploads and draws; libbake's reader (grooves/package/package.h) decodes and checks.
#pragma once

#include <array>
#include <map>
#include <string>
#include <vector>

#include <bake_formats/grooves.h>

#include "bake/io/glb.h"
#include "grooves/package/package.h"
#include "render/gpu_mesh.h"
#include "render/renderer.h"

namespace bake::play {

struct GroovesOptions {
  int maxBounces = 2;           // mirror reflections followed (seed §7); the rendering model's maxBounces
  bool shadingInputs = false;   // also write F, A1, A2, E, L to colour attachments 1-3 (tests)
  // Special cases sampled by area (seed §6), as the CPU method does; off: line sampled like the rest
  // (a shader variant that compiles in seconds instead of minutes on llvmpipe).
  bool areaSampling = true;
  // Mirror bounces (seed §7) in footprints sampled by area traced as beams, as the CPU method does.
  // Off by default: a mirror piece there reflects only the environment, the cheaper model (llvmpipe
  // renders the engraved plate's view 70 times slower traced).
  bool areaReflections = false;
  // Tests: area samples taken as cut short by a loop cap whatever the driver, so that the retry
  // passes run: 1 in the first pass (shaded again whole), 2 also in the whole-footprint retry passes
  // (shaded again by parts), 3 also in the passes of the whole footprint by parts (shaded again by
  // quarters), 4 as 2 and by parts in node 0 of each level but the deepest (leaves of every level).
  int forceRetries = 0;
  // The most retry draws per frame (each shades one pixel again, alone or one part of it; a pixel
  // still cut short when they run out is line sampled, counted in the warning). On llvmpipe a draw
  // that runs into its loop cap costs a few milliseconds: dense packages list thousands of pixels.
  std::uint32_t retryDraws = 2048;
};

// The loader checks are libbake's (grooves/package/package.h).
using grooves::checkGroovesPackage;

class GroovesRenderer : public TechniqueRenderer {
 public:
  explicit GroovesRenderer(GroovesOptions options = {}) : options_(options) {}
  GroovesRenderer(const GroovesRenderer&) = delete;
  GroovesRenderer& operator=(const GroovesRenderer&) = delete;
  ~GroovesRenderer() override;

  Status prepare(const Scene& scene, const std::vector<std::size_t>& instances,
                 gl::ShaderLibrary& shaders) override;
  void draw(const FrameContext& frame) override;
  std::size_t gpuBytes() const override;
  // Of the last frame: fragments shaded from the far level or truncated, special-case fragments
  // sampled by area and those line sampled instead.
  nlohmann::json statistics() const override;
  std::vector<std::string> warnings() const override;

 private:
  // The area sampling arenas (special cases), one per slot layout: a variant cuts its arena into
  // slots of its own size (shaders/grooves/area_polygon.glsl), so draws of variants with different
  // sizes running at once must not share one (their slots would overlap). Keyed by the package
  // defines that set the size.
  unsigned areaScratchFor(const std::vector<std::string>& packageDefines);
  std::map<std::vector<std::string>, unsigned> areaScratch_;
  void clearAreaRetry(int width, int height);
  unsigned areaRetry_ = 0;  // retry lists, sums and per-pixel marks (shaders/grooves/area_retry.glsl)
  std::size_t retryBytes_ = 0;
  std::uint32_t retryPasses_ = 0;  // of the last frame
  std::uint32_t retriedByParts_ = 0;  // of the last frame: pixels shaded again by smaller parts
  std::uint32_t retriesUnfinished_ = 0;  // of the last frame: listed pixels left line sampled (no draws left)
  std::uint32_t retryDrawsSpent_ = 0;    // of the last frame, against GroovesOptions::retryDraws
  // The shader's per-frame counts (far_level.glsl): fragments shaded from the far level, over more
  // primitives than it holds without a far level (a version 1 package: the rest dropped), and with
  // more classes of grooves than it keeps (the rest dropped).
  unsigned frameCounts_ = 0;
  // One uploaded package: the buffer of its bufferViews and their ranges, and the header block.
  struct Upload {
    unsigned storage = 0, header = 0;
    std::array<std::size_t, format::grooves::kArrayCount> offset{}, size{};
  };
  struct Item {
    GpuPrimitive mesh;
    unsigned program = 0;
    Mat4 world;
    std::size_t upload = 0;
    bool areaSampling = false;  // its variant samples special cases by area (and retries)
    unsigned areaScratch = 0;   // then its arena
  };
  // Which pass a draw belongs to (area_retry.glsl uAreaRetry, uAreaPartLevel, uAreaPart, uRetrySlot,
  // uAreaBeam, uRetryRootLevel).
  struct RetryPass {
    int kind = 0, level = 1, part = 0, slot = 0, beam = -1, rootLevel = 0;
  };
  // A node of the quadtree of parts of a footprint shaded again by parts: the pixel's place in the
  // second list, the part (row-major at its level).
  struct RetryNode {
    std::size_t slot = 0;
    int part = 0;
  };
  void drawItem(const Item& item, const FrameContext& frame, int number, const RetryPass& retry) const;
  std::vector<std::array<int, 2>> retryList(int list) const;
  bool drawRetryPass(const FrameContext& frame, std::array<int, 2> pixel, const RetryPass& retry);
  void drawRetryPasses(const FrameContext& frame);
  void drawRetriesByParts(const FrameContext& frame, const std::vector<std::array<int, 2>>& pixels);
  std::vector<RetryNode> childrenOfCutNodes(int level, const std::vector<RetryNode>& nodes, std::size_t pixels) const;
  GroovesOptions options_;
  std::vector<Upload> uploads_;
  std::vector<Item> items_;
  std::size_t bytes_ = 0;
};

}  // namespace bake::play
