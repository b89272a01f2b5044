#include "render/renderer.h"

#include <GL/glcorearb.h>

#include "render/standard.h"
#include "techniques/registry.h"

namespace bake::play {

const RendererRegistry& RendererRegistry::builtIn() {
  static const RendererRegistry registry = [] {
    RendererRegistry r;
    r.add("", [] { return std::make_unique<StandardRenderer>(); });
    // One renderer per technique of the registry (libbake/techniques/techniques.def).
#define BAKE_TECHNIQUE(name) r.add(techniques::name##Technique().extension, &name##Renderer);
#include "techniques/techniques.def"
#undef BAKE_TECHNIQUE
    return r;
  }();
  return registry;
}

void RendererRegistry::add(const std::string& extension, RendererFactory factory) {
  factories_[extension] = std::move(factory);
}

std::unique_ptr<TechniqueRenderer> RendererRegistry::create(const std::string& extension) const {
  const auto it = factories_.find(extension);
  return it == factories_.end() ? nullptr : it->second();
}

Result<SceneRenderer> SceneRenderer::create(const Scene& scene, const RendererRegistry& registry,
                                            gl::ShaderLibrary& shaders) {
  // Group instances by technique; an extension without a renderer falls back to standard shading
  // (loadScene has already warned, or refused when the extension was required).
  std::map<std::string, std::vector<std::size_t>> groups;
  for (std::size_t i = 0; i < scene.instances.size(); ++i) {
    const std::string technique = scene.technique(scene.instances[i]);
    groups[registry.has(technique) ? technique : ""].push_back(i);
  }
  SceneRenderer out;
  for (const auto& [technique, instances] : groups) {
    std::unique_ptr<TechniqueRenderer> renderer = registry.create(technique);
    BAKE_RETURN_IF_ERROR(renderer->prepare(scene, instances, shaders));
    out.renderers_.push_back(std::move(renderer));
    out.techniques_.push_back(technique.empty() ? "standard" : technique);
  }
  return out;
}

void SceneRenderer::drawFrame(const FrameContext& frame) {
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glClearColor(0.06f, 0.065f, 0.075f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  for (auto& renderer : renderers_) renderer->draw(frame);
}

std::size_t SceneRenderer::gpuBytes() const {
  std::size_t total = 0;
  for (const auto& renderer : renderers_) total += renderer->gpuBytes();
  return total;
}

std::vector<std::string> SceneRenderer::warnings() const {
  std::vector<std::string> out;
  for (const auto& renderer : renderers_) {
    std::vector<std::string> w = renderer->warnings();
    out.insert(out.end(), w.begin(), w.end());
  }
  return out;
}

nlohmann::json SceneRenderer::statistics() const {
  nlohmann::json out = nlohmann::json::object();
  for (std::size_t i = 0; i < renderers_.size(); ++i) {
    nlohmann::json s = renderers_[i]->statistics();
    if (!s.is_null()) out[techniques_[i]] = std::move(s);
  }
  return out;
}

}  // namespace bake::play
