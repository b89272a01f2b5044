#include "play/validate.h"

#include <bake_formats/glb.h>

#include <cmath>
#include <filesystem>

#include "bake/core/session.h"
#include "bake/io/image.h"
#include "core/output_plan.h"
#include "gl/context.h"
#include "render/geodesic.h"
#include "render/renderer.h"
#include "render/target.h"
#include "scene/scene.h"
#include "techniques/registry.h"

namespace bake::play {
namespace {

std::string primitiveName(std::size_t mesh, std::size_t primitive) {
  return "mesh " + std::to_string(mesh) + " primitive " + std::to_string(primitive);
}

// glTF 2.0, 3.7.2.1: the types allowed for the standard attributes we draw.
Status checkAttributeType(const glb::Attribute& a, const Location& where) {
  const bool f32 = a.componentType == glb::ComponentType::F32;
  if ((a.name == "POSITION" || a.name == "NORMAL") && (!f32 || a.components != 3)) {
    return invalidInput(a.name + " must be float VEC3", where);
  }
  if (a.name.rfind("TEXCOORD_", 0) == 0 && (a.components != 2 || !(f32 || a.normalized))) {
    return invalidInput(a.name + " must be VEC2 of floats or normalized integers", where);
  }
  return {};
}

Status checkFinite(const glb::Attribute& a, const Location& where) {
  if (a.componentType != glb::ComponentType::F32) return {};
  const std::vector<float> values = a.toFloats();
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values[i])) {
      return invalidInput("attribute " + a.name + " vertex " + std::to_string(i / std::size_t(a.components)) + " holds " +
                              (std::isnan(values[i]) ? "NaN" : "an infinite value"), where);
    }
  }
  return {};
}

Status checkVendorExtension(const std::string& extension, const nlohmann::json& body, const Location& where) {
  if (!body.is_object()) return invalidInput("extension " + extension + " must be an object", where);
  const auto version = body.find("version");
  if (version == body.end()) return invalidInput("extension " + extension + " lacks its \"version\" field", where);
  if (!version->is_number_integer() || version->get<std::int64_t>() < 1) {
    return invalidInput("extension " + extension + " has version " + version->dump() + "; it must be an integer >= 1", where);
  }
  return {};
}

Status checkVendorExtensions(const nlohmann::json& owner, const Location& where) {
  if (!owner.is_object() || !owner.contains("extensions") || !owner["extensions"].is_object()) return {};
  for (const auto& [extension, body] : owner["extensions"].items()) {
    if (extension.rfind(format::glb::kVendorExtensionPrefix, 0) == 0) {
      BAKE_RETURN_IF_ERROR(checkVendorExtension(extension, body, where));
    }
  }
  return {};
}

// The reference views: three-quarter front, side and top, around the package's bounds.
std::vector<Camera> referenceViews(const Scene& scene) {
  const Camera base = frameBounds(scene, 1.0f);
  const float distance = length(base.eye - base.target);
  const Vec3 directions[] = {normalize(Vec3{0.55f, 0.45f, 0.75f}), Vec3{1, 0, 0}, normalize(Vec3{0.0f, 1.0f, 0.05f})};
  std::vector<Camera> views;
  for (const Vec3& d : directions) {
    Camera camera = base;
    camera.eye = base.target + d * distance;
    views.push_back(camera);
  }
  return views;
}

struct Verdict {
  bool pass = true;
  std::string detail;
  ExitCode failure = ExitCode::InvalidInput;  // a package that could not be read at all is an I/O failure
};

Status renderViews(const Scene& scene, const ValidateSettings& settings, std::vector<Image>& views) {
  BAKE_ASSIGN_OR_RETURN(std::unique_ptr<gl::Context> context, gl::createHeadlessContext());
  gl::ShaderLibrary shaders;
  BAKE_ASSIGN_OR_RETURN(SceneRenderer renderer, SceneRenderer::create(scene, RendererRegistry::builtIn(), shaders));
  BAKE_ASSIGN_OR_RETURN(OffscreenTarget target, OffscreenTarget::create(settings.size, settings.size));
  const Light light;
  for (const Camera& camera : referenceViews(scene)) {
    const FrameContext frame{scene, camera, light, lookAt(camera.eye, camera.target, camera.up),
                             perspective(camera.yfov, 1.0f, camera.znear, camera.zfar), settings.size, settings.size};
    target.bind();
    renderer.drawFrame(frame);
    views.push_back(encodeSrgb(target.readLinearRgba()));
  }
  return {};
}

// Validates one package; a failed check is a verdict, not an error of the run.
Verdict validateOne(const std::string& file, const std::string& golden, const ValidateSettings& settings,
                    BakeSession& session, std::size_t index) {
  auto fail = [](const Status& status) {
    return Verdict{false, status.describe(), status.code() == ExitCode::Io ? ExitCode::Io : ExitCode::InvalidInput};
  };
  session.addInput(file);
  auto package = glb::read(file);
  if (!package.isOk()) return fail(package.status());
  if (const Status s = checkPackageStructure(*package, file); !s.isOk()) return fail(s);

  const RendererRegistry& registry = RendererRegistry::builtIn();
  auto scene = loadScene({file}, session.diagnostics(), [&](const std::string& e) { return registry.has(e); });
  if (!scene.isOk()) return fail(scene.status());
  if (const Status s = attachGeoTextures(*scene, ""); !s.isOk()) return fail(s);  // bare fields compile too
  std::vector<Image> views;
  if (const Status s = renderViews(*scene, settings, views); !s.isOk()) return fail(s);

  Verdict verdict{true, "structure ok, shaders compiled, " + std::to_string(views.size()) + " views rendered"};
  if (!settings.viewsDirectory.empty()) {
    for (std::size_t v = 0; v < views.size(); ++v) {
      const std::string stem = std::filesystem::path(file).stem().string();
      const std::filesystem::path path = std::filesystem::path(settings.viewsDirectory) / (stem + ".view" + std::to_string(v) + ".png");
      if (const Status s = writeImage(path, views[v], PixelType::U8); !s.isOk()) return fail(s);
      session.recordWrittenOutput(path);
    }
  }
  if (golden.empty()) return verdict;
  session.addInput(golden);
  auto expected = readImage(golden);
  if (!expected.isOk()) return fail(expected.status());
  auto difference = compareImages(views[0], *expected, settings.tolerance.threshold);
  if (!difference.isOk()) return fail(Status(difference.status()).inFile(golden));
  session.report().addAccuracy("package " + std::to_string(index) + " reference view 0", "golden image " + golden,
                               {{"rmse", difference->rmse}, {"maxError", difference->maxError},
                                {"percentOver", difference->percentOver}, {"threshold", difference->threshold}});
  const bool within = withinTolerance(*difference, settings.tolerance);
  verdict.pass = within;
  char allowed[96];
  std::snprintf(allowed, sizeof allowed, " (allowed: RMSE %g, %g%% of pixels over)", settings.tolerance.rmse,
                settings.tolerance.percentOver);
  verdict.detail += std::string(within ? ", matches " : ", DIFFERS from ") + golden + ": " + describe(*difference) + allowed;
  return verdict;
}

}  // namespace

Status runValidate(const ValidateSettings& settings, Diagnostics& diagnostics, std::FILE* out) {
  if (!settings.goldens.empty() && settings.goldens.size() != settings.packages.size()) {
    return usageError("give one --golden per package (" + std::to_string(settings.packages.size()) + "), or none");
  }
  if (settings.size < 16 || settings.size > 4096) return usageError("--size must be 16 to 4096");
  if (!settings.viewsDirectory.empty()) {
    // Made when missing (with its parents), as `mkdir -p` would.
    std::error_code error;
    std::filesystem::create_directories(settings.viewsDirectory, error);
    if (!std::filesystem::is_directory(settings.viewsDirectory)) {
      return ioError(std::string("--views: not a directory") + (error ? " and cannot be made: " + error.message() : ""),
                     {settings.viewsDirectory, ""});
    }
  }
  const OutputPlanScope planScope;
  {
    RunFiles files{settings.packages, {}};
    files.inputs.insert(files.inputs.end(), settings.goldens.begin(), settings.goldens.end());
    BAKE_RETURN_IF_ERROR(planOutputs(files, settings.common));
  }
  BakeSession session("bakeplay", settings.common, diagnostics);
  session.report().setOptions({{"command", "validate"}, {"goldens", settings.goldens}, {"size", settings.size},
                               {"tolerance", {{"rmse", settings.tolerance.rmse}, {"threshold", settings.tolerance.threshold},
                                              {"percentOver", settings.tolerance.percentOver}}}});
  std::size_t failed = 0, unreadable = 0;
  nlohmann::json verdicts = nlohmann::json::array();
  {
    StageTimer timer(&session.report(), "validate");
    for (std::size_t i = 0; i < settings.packages.size(); ++i) {
      const std::string& file = settings.packages[i];
      const Verdict verdict = validateOne(file, settings.goldens.empty() ? "" : settings.goldens[i], settings, session, i);
      // -q: only the failures are printed.
      if (!verdict.pass || !settings.common.quiet)
        std::fprintf(out, "%s %s: %s\n", verdict.pass ? "PASS" : "FAIL", file.c_str(), verdict.detail.c_str());
      verdicts.push_back({{"package", file}, {"pass", verdict.pass}, {"detail", verdict.detail}});
      failed += verdict.pass ? 0 : 1;
      unreadable += !verdict.pass && verdict.failure == ExitCode::Io ? 1 : 0;
    }
  }
  session.report().setStatistic("verdicts", verdicts);
  Status outcome;
  if (failed > 0) {
    // Exit 2 when every failed package failed because it could not be read (exit codes, docs/conventions.md).
    outcome = Status(unreadable == failed ? ExitCode::Io : ExitCode::InvalidInput,
                     std::to_string(failed) + " of " + std::to_string(settings.packages.size()) + " packages failed validation");
  }
  return session.finish(outcome);
}

Status checkPackageStructure(const glb::Package& package, const std::string& name) {
  for (std::size_t m = 0; m < package.meshes.size(); ++m) {
    for (std::size_t p = 0; p < package.meshes[m].primitives.size(); ++p) {
      const Location where{name, primitiveName(m, p)};
      const glb::Primitive& primitive = package.meshes[m].primitives[p];
      if (!primitive.find("POSITION")) return invalidInput("the primitive has no POSITION", where);
      for (const glb::Attribute& attribute : primitive.attributes) {
        BAKE_RETURN_IF_ERROR(checkAttributeType(attribute, where));
        BAKE_RETURN_IF_ERROR(checkFinite(attribute, where));
      }
    }
  }
  BAKE_RETURN_IF_ERROR(checkVendorExtensions({{"extensions", package.extensions}}, {name, "extensions"}));
  for (std::size_t i = 0; i < package.materials.size(); ++i) {
    BAKE_RETURN_IF_ERROR(checkVendorExtensions(package.materials[i], {name, "material " + std::to_string(i)}));
  }
  // Each technique's loader checks (libbake's package readers, through the registry).
  for (const techniques::Technique& technique : techniques::all()) {
    if (technique.checkPackage) BAKE_RETURN_IF_ERROR(technique.checkPackage(package, name));
  }
  return {};
}

}  // namespace bake::play
