// The renderers of the techniques in the registry (libbake/techniques/techniques.def): each
// BAKE_<technique> extension has a renderer, made by <technique>Renderer(), that
// prepares the instances whose material carries it (uploading only the data its shaders read and
// compiling only the variants those instances need) and draws them each frame. Instances without a
// technique are drawn by the standard renderer (Blinn-Phong).
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "bake/core/status.h"
#include "gl/shader.h"
#include "scene/scene.h"

namespace bake::play {

struct FrameContext {
  const Scene& scene;
  const Camera& camera;
  const Light& light;
  Mat4 view;
  Mat4 projection;
  int width = 0;
  int height = 0;
  float time = 0.0f;  // seconds, for animated techniques (GeoTexture fronts)
};

class TechniqueRenderer {
 public:
  virtual ~TechniqueRenderer() = default;
  // Called once with the instances this renderer draws; the shader library outlives the renderer.
  virtual Status prepare(const Scene& scene, const std::vector<std::size_t>& instances, gl::ShaderLibrary& shaders) = 0;
  virtual void draw(const FrameContext& frame) = 0;
  // Bytes uploaded to the GPU, for the report.
  virtual std::size_t gpuBytes() const = 0;
  // What the technique measured about the last frame drawn (e.g. polygons generated), for the
  // report; null when it measures nothing.
  virtual nlohmann::json statistics() const { return nullptr; }
  // What the user should know about the last frame drawn (a result that departs from the technique's
  // method), one sentence each.
  virtual std::vector<std::string> warnings() const { return {}; }
};

using RendererFactory = std::function<std::unique_ptr<TechniqueRenderer>()>;

// The renderer of each technique (defined beside it in render/<technique>*.cpp).
#define BAKE_TECHNIQUE(name) std::unique_ptr<TechniqueRenderer> name##Renderer();
#include "techniques/techniques.def"
#undef BAKE_TECHNIQUE

class RendererRegistry {
 public:
  // The registry with every renderer of this build: the standard one under "" and one per technique.
  static const RendererRegistry& builtIn();

  void add(const std::string& extension, RendererFactory factory);
  bool has(const std::string& extension) const { return factories_.count(extension) > 0; }
  std::unique_ptr<TechniqueRenderer> create(const std::string& extension) const;

 private:
  std::map<std::string, RendererFactory> factories_;
};

// Prepares one renderer per technique the scene uses (and the standard renderer for the rest).
class SceneRenderer {
 public:
  static Result<SceneRenderer> create(const Scene& scene, const RendererRegistry& registry, gl::ShaderLibrary& shaders);
  // Clears the bound target to the background colour and draws every technique.
  void drawFrame(const FrameContext& frame);
  std::size_t gpuBytes() const;
  // The statistics of every technique that has some, keyed by technique (an object, maybe empty).
  nlohmann::json statistics() const;
  std::vector<std::string> warnings() const;  // of every technique
  const std::vector<std::string>& techniques() const { return techniques_; }

 private:
  std::vector<std::unique_ptr<TechniqueRenderer>> renderers_;
  std::vector<std::string> techniques_;
};

}  // namespace bake::play
