// Small packages for the scene-assembly tests (tests/pipe/assemble_test.cpp and
// tests/runtime/assemble_render_test.cpp), baked with the bakers' library entry points: a torus
// mesh, a geodesic torus with three fields, a groove plate whose grooves have ends, a corner and an
// intersection (so special-case records exist), a revolved vase with a displacement map and a base
// colour texture, and a hatched torus with its threshold texture; and scene objects and materials
// named with their technique. The option structs' defaults are the unit tests' inputs; the GL tests
// ask for finer or larger variants.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "bake/core/diagnostics.h"
#include "bake/geodesic/bake.h"
#include "bake/hatching/bake.h"
#include "bake/io/glb.h"
#include "bake/io/image.h"
#include "bake/mesh/patterns.h"
#include "bake/mesh/shape_tool.h"
#include "bake/revolution/bake.h"
#include "grooves/bake/grid.h"
#include "grooves/input/scene.h"
#include "grooves/package/package.h"
#include "pipe/scene.h"

namespace bake::test {

inline void writeText(const std::filesystem::path& path, const std::string& text) { std::ofstream(path) << text; }

// The shape tool's torus as DIR/torus.glb.
inline std::filesystem::path bakeTorus(const std::filesystem::path& dir, int resolution, Diagnostics& diagnostics) {
  ShapeToolSettings shape;
  shape.shape.name = "torus";
  shape.shape.resolution = resolution;
  shape.output = (dir / "torus.glb").string();
  EXPECT_TRUE(runShapeTool(shape, diagnostics).isOk());
  return shape.output;
}

struct TorusFieldsOptions {
  int torusResolution = 12;
  int sourceStep = 10;  // field a from vertex 0, b from vertex step, c from vertices 2 step and 3 step
  geodesic::Normalization normalization = geodesic::Normalization::PerField;
};

// Three fields on a torus, float encoding, as DIR/torus-fields.glb.
inline std::filesystem::path bakeTorusFields(const std::filesystem::path& dir, const TorusFieldsOptions& options = {}) {
  Diagnostics diagnostics("test", true);
  const std::filesystem::path torus = bakeTorus(dir, options.torusResolution, diagnostics);
  const auto vertex = [&](int k) { return std::to_string(k * options.sourceStep); };
  writeText(dir / "sources.json", R"({"fields": [
    {"name": "a", "sources": [{"vertex": )" + vertex(0) + R"(}]},
    {"name": "b", "sources": [{"vertex": )" + vertex(1) + R"(}]},
    {"name": "c", "sources": [{"vertex": )" + vertex(2) + R"(}, {"vertex": )" + vertex(3) + R"(}]}]})");
  geodesic::Settings settings;
  settings.input = torus.string();
  settings.sourcesFile = (dir / "sources.json").string();
  settings.output = (dir / "torus-fields.glb").string();
  settings.normalization = options.normalization;
  settings.common.quiet = true;
  const Status status = geodesic::run(settings, diagnostics);
  EXPECT_TRUE(status.isOk()) << status.describe();
  return settings.output;
}

struct GroovePlateOptions {
  double halfWidth = 0.2;  // of the vee profile
  double depth = 0.1;
  double lineStart = 0.2;  // y where the line crossing the polyline begins
  std::array<double, 3> albedo{0.55, 0.55, 0.6};
};

// A 10 x 10 plate with an open polyline and a line crossing it: ends, a corner and an intersection,
// so special-case records exist. Written as DIR/NAME.glb.
inline std::filesystem::path bakeGroovePlate(const std::filesystem::path& dir, const std::string& name,
                                             const GroovePlateOptions& options = {}) {
  const auto number = [](double value) { return nlohmann::json(value).dump(); };
  const std::string vee = "[[" + number(-options.halfWidth) + ", 0], [0, " + number(-options.depth) + "], [" +
                          number(options.halfWidth) + ", 0]]";
  const std::string albedo = nlohmann::json(options.albedo).dump();
  const std::string line = "[[5, " + number(options.lineStart) + "], [5, 6]]";
  const std::string text = R"({"version": 1, "domain": {"size": [10, 10]},
    "profiles": {"vee": {"points": )" + vee + R"(}},
    "materials": {"steel": {"albedo": )" + albedo + R"(, "specular": [0.5, 0.5, 0.5], "shininess": 40}},
    "base": "steel",
    "grooves": [{"profile": "vee", "path": {"polyline": [[1, 1], [8, 1], [8, 8]]}},
                {"profile": "vee", "path": {"line": )" + line + R"(}}]})";
  auto scene = grooves::parseGrooveScene(text, name + ".json");
  EXPECT_TRUE(scene.isOk()) << scene.status().describe();
  auto grid = grooves::buildGrooveGrid(*scene, {});
  EXPECT_TRUE(grid.isOk()) << grid.status().describe();
  auto package = grooves::buildGroovePackage(*scene, *grid);
  EXPECT_TRUE(package.isOk()) << package.status().describe();
  const std::filesystem::path file = dir / (name + ".glb");
  EXPECT_TRUE(glb::write(file, *package).isOk());
  return file;
}

struct VaseOptions {
  int resolution = 64;
  double heightScale = revolution::Settings{}.heightScale;
};

// A vase-like revolved profile with a displacement map (the "hammered" pattern) and a base colour
// texture ("glaze"), as DIR/vase.glb.
inline std::filesystem::path bakeVase(const std::filesystem::path& dir, const VaseOptions& options = {}) {
  for (const char* pattern : {"hammered", "glaze"}) {
    auto image = makePattern(pattern, 64);
    EXPECT_TRUE(image.isOk()) << image.status().describe();
    EXPECT_TRUE(writeImage(dir / (std::string(pattern) + ".png"), *image, PixelType::U8).isOk());
  }
  writeText(dir / "profile.json", R"({"contours": [{"closed": false, "points": [[0.3, 0], [0.4, 0.5], [0.2, 1]]}]})");
  revolution::Settings settings;
  settings.input = (dir / "profile.json").string();
  settings.output = (dir / "vase.glb").string();
  settings.resolution = options.resolution;
  settings.heightMap = (dir / "hammered.png").string();
  settings.heightScale = options.heightScale;
  settings.baseColorTexture = (dir / "glaze.png").string();
  settings.common.quiet = true;
  Diagnostics diagnostics("test", true);
  const Status status = revolution::run(settings, diagnostics);
  EXPECT_TRUE(status.isOk()) << status.describe();
  return settings.output;
}

struct HatchedTorusOptions {
  int torusResolution = 12;
  std::string style = R"({"tones": 3, "resolution": 32, "levels": 1, "candidates": 2})";
  double tilesPerUnit = hatching::MaterialSettings{}.tilesPerUnit;
};

// A small TAM (DIR/tam.ktx2) with its threshold texture (DIR/threshold.ktx2) applied to a torus, as
// DIR/hatched.glb.
inline std::filesystem::path bakeHatchedTorus(const std::filesystem::path& dir, const HatchedTorusOptions& options = {}) {
  Diagnostics diagnostics("test", true);
  const std::filesystem::path torus = bakeTorus(dir, options.torusResolution, diagnostics);
  writeText(dir / "style.json", options.style);
  hatching::Settings settings;
  settings.style = (dir / "style.json").string();
  settings.output = (dir / "tam.ktx2").string();
  settings.threshold = (dir / "threshold.ktx2").string();
  settings.material.mesh = torus.string();
  settings.material.package = (dir / "hatched.glb").string();
  settings.material.tilesPerUnit = options.tilesPerUnit;
  settings.common.quiet = true;
  const Status status = hatching::run(settings, diagnostics);
  EXPECT_TRUE(status.isOk()) << status.describe();
  return settings.material.package;
}

inline pipe::Object objectOf(const std::string& name, const std::string& technique, std::size_t material = 0) {
  pipe::Object object;
  object.name = name;
  object.technique = technique;
  object.material = material;
  return object;
}

inline pipe::Material materialOf(const std::string& name, const std::string& technique) {
  pipe::Material material;
  material.name = name;
  material.technique = technique;
  return material;
}

}  // namespace bake::test
