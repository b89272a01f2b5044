// A toy technique added through the registry alone (libbake/techniques/registry.h and the runtime's
// RendererRegistry): nothing else in the library or the runtime knows it, yet `bakeplay validate`'s
// package checks run its loader checks, bakeinfo describes its data, the scene renderer hands its
// instances to its renderer, and scene files plan and assemble its objects through its scene hooks.
#include <gtest/gtest.h>

#include <GL/glcorearb.h>

#include "bake/core/diagnostics.h"
#include "info/describe.h"
#include "pipe/assemble.h"
#include "pipe/assemble_parts.h"
#include "pipe/plan.h"
#include "pipe/scene.h"
#include "pipe/technique_hooks.h"
#include "play/validate.h"
#include "render/renderer.h"
#include "render/target.h"
#include "runtime/gl_test.h"
#include "support/golden.h"
#include "techniques/registry.h"

namespace bake::play {
namespace {

constexpr const char* kToyExtension = "BAKE_toy";

const nlohmann::json& toyOf(const nlohmann::json& material) { return material["extensions"][kToyExtension]; }

// The toy's format: a material extension {"version": 1, "colour": [r, g, b]}, each in [0, 1].
Status checkToyPackage(const glb::Package& package, const std::string& file) {
  for (std::size_t m = 0; m < package.materials.size(); ++m) {
    const nlohmann::json& material = package.materials[m];
    if (!material.contains("extensions") || !material["extensions"].contains(kToyExtension)) continue;
    const nlohmann::json& colour = toyOf(material).value("colour", nlohmann::json());
    bool valid = colour.is_array() && colour.size() == 3;
    for (std::size_t c = 0; valid && c < 3; ++c) valid = colour[c].is_number() && colour[c] >= 0 && colour[c] <= 1;
    if (!valid) return invalidInput("BAKE_toy colour must be three numbers in [0, 1]", {file, "material " + std::to_string(m)});
  }
  return {};
}

// Fills the frame with the colour of its first instance's material: enough to see that the scene
// renderer chose it.
class ToyRenderer : public TechniqueRenderer {
 public:
  Status prepare(const Scene& scene, const std::vector<std::size_t>& instances, gl::ShaderLibrary&) override {
    if (instances.empty()) return internalError("the toy renderer got no instances");
    const nlohmann::json& colour = toyOf(scene.material(scene.instances[instances[0]]))["colour"];
    for (int c = 0; c < 3; ++c) colour_[c] = colour[c].get<float>();
    instances_ = instances.size();
    return {};
  }
  void draw(const FrameContext&) override {
    glClearColor(colour_[0], colour_[1], colour_[2], 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
  }
  std::size_t gpuBytes() const override { return 0; }
  nlohmann::json statistics() const override { return {{"toyInstances", instances_}}; }

 private:
  float colour_[3] = {0, 0, 0};
  std::size_t instances_ = 0;
};

// The toy's scene hooks: objects may give a "shade" option, which becomes toybake's --shade; the
// assembled material is the scene's (named after it), the toy extension kept as baked.
const pipe::TechniqueHooks& toyPipeHooks() {
  static const pipe::detail::TechniqueRules rules{
      .extension = kToyExtension,
      .adapt = [](glb::Package& package, const pipe::detail::ObjectInput& input) -> Status {
        const int index = pipe::detail::materialWith(package, kToyExtension);
        if (index < 0) return input.error("not a toy package");
        package.materials[std::size_t(index)]["name"] = input.material.name;
        return {};
      },
      .references = [](const nlohmann::json&) { return pipe::detail::ExtensionReferences{}; },
      .renumber = [](nlohmann::json&, const pipe::detail::Renumbering&) {}};
  static const pipe::TechniqueHooks hooks{
      .optionKeys = {"shade"},
      .plan = [](pipe::ObjectPlanner& planner, const pipe::Object& object, pipe::Step& step) -> Status {
        planner.addInput(step, planner.resolve(object.input));
        pipe::ObjectPlanner::option(step, object.options, "shade", "--shade");
        step.outputs.push_back(planner.baked(object, ".glb"));
        return {};
      },
      .assemble = &rules};
  return hooks;
}

// Registered once per process: the registry is process-wide.
const techniques::Technique& toyTechnique() {
  static const techniques::Technique* row = [] {
    techniques::Technique toy;
    toy.name = "toy";
    toy.extension = kToyExtension;
    toy.tool = "toybake";
    toy.checkPackage = checkToyPackage;
    toy.describe = [](const glb::Package& package, const std::string&) -> Result<nlohmann::json> {
      for (const nlohmann::json& material : package.materials)
        if (material.contains("extensions") && material["extensions"].contains(kToyExtension))
          return nlohmann::json{{"colour", toyOf(material)["colour"]}};
      return nlohmann::json();
    };
    toy.formatDescription = [](const nlohmann::json& d) { return "  toy: colour " + info::vectorText(d["colour"]) + "\n"; };
    toy.pipe = &toyPipeHooks();
    const Status added = techniques::add(toy);
    EXPECT_TRUE(added.isOk()) << added.describe();
    return techniques::byName("toy");
  }();
  return *row;
}

glb::Package toyPackage(const nlohmann::json& colour) {
  glb::Primitive primitive;
  const std::vector<float> positions = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
  primitive.attributes.push_back(glb::Attribute::fromFloats("POSITION", 3, positions));
  primitive.indices = {0, 1, 2, 0, 2, 3};
  primitive.material = 0;
  glb::Package package;
  package.meshes.push_back({"quad", {primitive}});
  package.materials = nlohmann::json::array({{{"name", "toy"}, {"extensions", {{kToyExtension, {{"version", 1}, {"colour", colour}}}}}}});
  return package;
}

TEST(ToyTechnique, RegistryFindsItByNameAndExtension) {
  const techniques::Technique& toy = toyTechnique();
  EXPECT_EQ(techniques::byExtension(kToyExtension), &toy);
  EXPECT_EQ(toy.tool, "toybake");
  EXPECT_FALSE(techniques::add(toy).isOk()) << "a second row of the same name must be refused";
  EXPECT_TRUE(techniques::usedBy(toy, toyPackage({0.1, 0.2, 0.3})));
  EXPECT_FALSE(techniques::usedBy(*techniques::byName("grooves"), toyPackage({0.1, 0.2, 0.3})));
}

TEST(ToyTechnique, ValidateRunsItsLoaderChecks) {
  toyTechnique();
  EXPECT_TRUE(checkPackageStructure(toyPackage({0.1, 0.2, 0.3}), "toy.glb").isOk());
  const Status bad = checkPackageStructure(toyPackage({0.1, 2.0, 0.3}), "toy.glb");
  EXPECT_EQ(bad.code(), ExitCode::InvalidInput);
  EXPECT_EQ(bad.describe(), "toy.glb: material 0: BAKE_toy colour must be three numbers in [0, 1]");
}

TEST(ToyTechnique, BakeinfoDescribesItsData) {
  toyTechnique();
  const std::filesystem::path file = test::freshTempDir("toy_technique_describe") / "toy.glb";
  ASSERT_TRUE(glb::write(file, toyPackage({0.25, 0.5, 1})).isOk());
  Result<nlohmann::json> description = info::describeFile(file);
  ASSERT_TRUE(description.isOk()) << description.status().describe();
  EXPECT_EQ((*description)["toy"]["colour"], nlohmann::json({0.25, 0.5, 1}));
  EXPECT_NE(info::formatText(*description).find("  toy: colour (0.25, 0.5, 1)\n"), std::string::npos)
      << info::formatText(*description);
}

TEST(ToyTechnique, ScenesPlanAndAssembleItsObjects) {
  toyTechnique();
  const std::filesystem::path dir = test::freshTempDir("toy_technique_scene");
  ASSERT_TRUE(glb::write(dir / "input.glb", toyPackage({0.25, 0.5, 1})).isOk());
  const nlohmann::json document = {
      {"version", 1},
      {"objects", {{{"name", "cube"}, {"technique", "toy"}, {"input", "input.glb"}, {"options", {{"shade", 0.5}}},
                    {"material", "paint"}}}},
      {"materials", {{{"name", "paint"}, {"technique", "toy"}}}}};
  Result<pipe::Scene> scene = pipe::parseScene(document, dir / "scene.json");
  ASSERT_TRUE(scene.isOk()) << scene.status().describe();

  pipe::PlanSettings settings;
  settings.outputDirectory = dir / "out";
  Result<pipe::Plan> plan = pipe::makePlan(*scene, settings);
  ASSERT_TRUE(plan.isOk()) << plan.status().describe();
  ASSERT_EQ(plan->steps.size(), 1u);
  const pipe::Step& step = plan->steps[0];
  EXPECT_EQ(step.id, "toybake:cube");
  const std::string package = (dir / "out" / "cube.toy.glb").string();
  EXPECT_EQ(step.arguments,
            (std::vector<std::string>{(dir / "input.glb").string(), "--shade", "0.5", "-o", package, "-q"}));

  // An option the toy's hooks do not list is refused with the object's element named.
  nlohmann::json unknown = document;
  unknown["objects"][0]["options"] = {{"shadow", 1}};
  const Result<pipe::Scene> refused = pipe::parseScene(unknown, dir / "scene.json");
  ASSERT_FALSE(refused.isOk());
  EXPECT_NE(refused.status().describe().find("/objects/0/options/shadow"), std::string::npos) << refused.status().describe();

  // The baked package (here the input itself) assembles under the scene's material name.
  Result<glb::Package> assembled = pipe::assemble(*scene, {dir / "input.glb"}, {});
  ASSERT_TRUE(assembled.isOk()) << assembled.status().describe();
  ASSERT_EQ(assembled->materials.size(), 1u);
  EXPECT_EQ(assembled->materials[0]["name"], "paint");
  EXPECT_EQ(toyOf(assembled->materials[0])["colour"], nlohmann::json({0.25, 0.5, 1}));
}

class ToyTechniqueRender : public test::GlTest {};

TEST_F(ToyTechniqueRender, SceneRendererHandsItsInstancesToItsRenderer) {
  toyTechnique();
  const std::filesystem::path file = test::freshTempDir("toy_technique_render") / "toy.glb";
  ASSERT_TRUE(glb::write(file, toyPackage({0.25, 0.5, 1})).isOk());
  RendererRegistry registry = RendererRegistry::builtIn();
  registry.add(kToyExtension, [] { return std::make_unique<ToyRenderer>(); });
  Diagnostics diagnostics("test", true);
  Result<Scene> scene = loadScene({file}, diagnostics, [&](const std::string& e) { return registry.has(e); });
  ASSERT_TRUE(scene.isOk()) << scene.status().describe();
  gl::ShaderLibrary shaders;
  Result<SceneRenderer> renderer = SceneRenderer::create(*scene, registry, shaders);
  ASSERT_TRUE(renderer.isOk()) << renderer.status().describe();
  EXPECT_EQ(renderer->techniques(), std::vector<std::string>{kToyExtension});
  EXPECT_EQ(renderer->statistics()[kToyExtension]["toyInstances"], 1);
  Result<OffscreenTarget> target = OffscreenTarget::create(8, 8);
  ASSERT_TRUE(target.isOk());
  target->bind();
  const Camera camera = frameBounds(*scene, 1.0f);
  const Light light;
  renderer->drawFrame({*scene, camera, light, lookAt(camera.eye, camera.target, camera.up),
                       perspective(camera.yfov, 1.0f, camera.znear, camera.zfar), 8, 8});
  const Image image = target->readLinearRgba();
  EXPECT_NEAR(image.at(4, 4, 0), 0.25f, 1e-3f);
  EXPECT_NEAR(image.at(4, 4, 1), 0.5f, 1e-3f);
  EXPECT_NEAR(image.at(4, 4, 2), 1.0f, 1e-3f);
}

}  // namespace
}  // namespace bake::play
