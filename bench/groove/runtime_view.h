// bench-groove's runtime renderer: a view of bench/groove/cases.json drawn by bakeplay's grooves
// renderer (runtime/render/grooves.h, the shaders in shaders/grooves) on a headless GL context,
// through an oblique orthographic projection whose pixels are exactly the view's footprints
// (grooves/oracle/render.h windowView), so that its image compares with the reference pixel for pixel.
#pragma once

#include <filesystem>
#include <memory>

#include "bake/core/status.h"
#include "bake/io/image.h"
#include "grooves/bake/grid.h"
#include "grooves/input/scene.h"
#include "grooves/oracle/render.h"

namespace bake::grooves {

class RuntimeViews {
 public:
  static Result<std::unique_ptr<RuntimeViews>> create();
  ~RuntimeViews();
  // Bakes the scene's package into `folder` and loads it.
  Status load(const GrooveScene& scene, const GrooveGrid& grid, const std::filesystem::path& folder);
  // The view as the runtime draws it (linear RGB, rows as the view's), and how many of its fragments
  // went to the far level.
  Result<Image> render(const View& view, const Lighting& lighting, std::size_t* farFragments = nullptr);

 private:
  struct State;
  explicit RuntimeViews(std::unique_ptr<State> state);
  std::unique_ptr<State> state_;
};

}  // namespace bake::grooves
