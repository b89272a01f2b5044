// strokebake's run: read the stroke list (or grow strokes on a mesh), run the list's generators,
// validate and repair (validate.cpp), bake the self-shadowing per control point and light direction
// (shadow.cpp, seed 002's last paragraph), quantise and pack (package.cpp), read the package back with
// the untrusting reader, and stage the output so it is committed only when everything succeeded. The
// report states the quantisation errors measured against the input next to their bounds, the repairs,
// the counts and the stage times.
#include "bake/paintstrokes/bake.h"

#include <cmath>
#include <map>
#include <optional>

#include "bake/core/limits.h"
#include "bake/core/session.h"
#include "bake/paintstrokes/generators.h"
#include "core/path.h"
#include "core/progress.h"
#include "paintstrokes/bake/shadow.h"
#include "paintstrokes/input/input.h"
#include "paintstrokes/input/validate.h"
#include "paintstrokes/package/package.h"

namespace bake::paintstrokes {
namespace {

using nlohmann::json;
namespace fmt = format::paintstrokes;

Status checkOptions(const Settings& settings) {
  if (settings.grow.pointsPerStroke < 2) return usageError("--points must be at least 2");
  BAKE_RETURN_IF_ERROR(checkWrittenExtension(settings.output, "-o", ".glb", "the package"));
  const ShadowSettings& s = settings.shadow;
  if (!std::isfinite(s.density) || s.density < 0) return usageError("--shadow-density must be a finite number >= 0");
  if (!(s.minimum >= 0 && s.minimum <= 1)) return usageError("--shadow-minimum must be within [0, 1]");
  if (s.directions.size() > fmt::kMaxShadowDirections)
    return usageError("--light-dir given " + std::to_string(s.directions.size()) + " times (at most " +
                      std::to_string(fmt::kMaxShadowDirections) + ")");
  for (const Vec3d& d : s.directions) {
    const double length = std::hypot(d[0], d[1], d[2]);
    if (!std::isfinite(length) || !(length > 0)) return usageError("--light-dir must be a finite, non-zero vector x,y,z");
  }
  return {};
}

std::vector<Vec3d> shadowDirections(const ShadowSettings& s) {
  if (!s.enabled) return {};
  if (s.directions.empty()) return {defaultLightDirection()};
  std::vector<Vec3d> out;
  for (const Vec3d& d : s.directions) {
    const double length = std::hypot(d[0], d[1], d[2]);
    out.push_back({d[0] / length, d[1] / length, d[2] / length});
  }
  return out;
}

json optionsOf(const Settings& settings, bool grown) {
  const ShadowSettings& s = settings.shadow;
  json directions = json::array();
  for (const Vec3d& d : s.directions) directions.push_back({d[0], d[1], d[2]});
  json options = {{"input", settings.input},
                  {"shadows", s.enabled},
                  {"lightDirections", directions},
                  {"shadowDensity", s.density},
                  {"shadowMinimum", s.minimum},
                  {"threads", settings.common.threads}};
  if (grown) {
    const GrowSettings& g = settings.grow;
    options["grow"] = {{"count", g.count},   {"length", g.length},         {"radius", g.radius},
                       {"tipRadius", g.tipRadius}, {"bend", g.bend},       {"bendDirection", {g.bendDirection[0], g.bendDirection[1], g.bendDirection[2]}},
                       {"points", g.pointsPerStroke}, {"seed", g.seed},    {"lengthFrom", g.lengthFrom},
                       {"colourFrom", g.colourFrom}};
  }
  return options;
}

struct Loaded {
  StrokeSet set;
  std::optional<glb::Mesh> grownOn;
  std::vector<std::string> inputs;
};

// Texture paths a grow setting names ("texture:PATH").
void addTextureInput(const std::string& from, std::vector<std::string>& inputs) {
  const std::string prefix = "texture:";
  if (from.compare(0, prefix.size(), prefix) == 0) inputs.push_back(from.substr(prefix.size()));
}

// The strokebake option that sets a grow setting.
std::string growOptionOf(const std::string& setting) {
  static const std::map<std::string, std::string> kOptions{
      {"count", "--count"},         {"length", "--length"},       {"radius", "--radius"},
      {"tipRadius", "--tip-radius"}, {"bend", "--bend"},           {"bendDirection", "--bend-direction"},
      {"pointsPerStroke", "--points"}, {"lengthFrom", "--length-from"}, {"colourFrom", "--color-from"}};
  const auto found = kOptions.find(setting);
  return found == kOptions.end() ? setting : found->second;
}

Result<Loaded> load(const Settings& settings) {
  Loaded loaded;
  loaded.inputs.push_back(settings.input);
  if (!isStrokeList(settings.input)) {
    GrowSettings grow = settings.grow;
    grow.mesh = settings.input;
    // The grow settings came from the command line: a value out of range is a usage error naming
    // the option (a stroke list's generators report the same checks as invalid input).
    if (Status checked = checkGrowSettings(grow); !checked.isOk()) {
      return usageError(growOptionOf(checked.where().element) + ": " + checked.message());
    }
    addTextureInput(grow.lengthFrom, loaded.inputs);
    addTextureInput(grow.colourFrom, loaded.inputs);
    glb::Mesh mesh;
    BAKE_ASSIGN_OR_RETURN(loaded.set, growOnMesh(grow, budgets(), &mesh));
    loaded.grownOn = std::move(mesh);
    return loaded;
  }
  BAKE_ASSIGN_OR_RETURN(StrokeInput input, readStrokeInput(settings.input));
  loaded.set = std::move(input.set);
  for (std::size_t k = 0; k < input.generators.size(); ++k) {
    const Location where{settings.input, "generators/" + std::to_string(k)};
    BAKE_RETURN_IF_ERROR(runGenerator(input.generators[k], input.directory, where, budgets(), loaded.set, loaded.inputs,
                                      loaded.grownOn ? nullptr : &loaded.grownOn));
  }
  return loaded;
}

void reportErrors(const QuantizationError& error, const PaintstrokePackage& stored, Report& report) {
  double positionBound = 0;
  for (const fmt::Stroke& s : stored.strokes)
    positionBound = std::max({positionBound, double(s.step[0]) / 2, double(s.step[1]) / 2, double(s.step[2]) / 2});
  report.addAccuracy("largest error against the input of the stored control points: positions (per axis, uint16 over each stroke's "
                     "box, dequantised in double), radii (uint16 over each stroke's largest radius), colour, opacity and "
                     "reflectance (unorm8); bounds: half the largest stored step, half the largest radius step (a whole step for a "
                     "stroke with a radius below half its step, stored as one step), 1/510",
                     "the validated input control points (double precision)",
                     {{"maxPositionError", error.position},
                      {"positionBound", positionBound},
                      {"maxRadiusError", error.radius},
                      {"radiusBound", error.radiusBound},
                      {"maxUnormError", error.unorm},
                      {"unormBound", 1.0 / 510}});
}

json countsOf(const StrokeSet& set, std::size_t directions, const ValidationCounts& repairs, std::size_t fileBytes) {
  std::size_t points = 0;
  for (const Stroke& s : set.strokes) points += s.points.size();
  return {{"strokes", set.strokes.size()},
          {"controlPoints", points},
          {"styles", set.styles.size()},
          {"shadowDirections", directions},
          {"repairs", {{"coincidentPointsDropped", repairs.droppedPoints}, {"normalsNormalised", repairs.normalisedNormals}}},
          {"fileBytes", fileBytes}};
}

Status bake(const Settings& settings, BakeSession& session) {
  Report& report = session.report();
  Progress progress("baking paintstrokes", 5, progressEnabled(session.diagnostics().quiet()));
  Loaded loaded;
  {
    StageTimer timer(&report, "read");
    BAKE_ASSIGN_OR_RETURN(loaded, load(settings));
    for (const std::string& file : loaded.inputs) session.addInput(file);
  }
  progress.update(1);
  ValidationCounts repairs;
  {
    StageTimer timer(&report, "validate");
    BAKE_ASSIGN_OR_RETURN(repairs, validateStrokes(loaded.set, settings.input, session.diagnostics()));
    if (settings.dropUnusedStyles) report.setStatistic("stylesDropped", dropUnusedStyles(loaded.set));
  }
  progress.update(2);
  const std::vector<Vec3d> directions = shadowDirections(settings.shadow);
  std::vector<double> shadows;
  {
    StageTimer timer(&report, "shadow");
    shadows = bakeShadows(loaded.set, directions, settings.shadow.density, settings.shadow.minimum);
  }
  progress.update(3);
  QuantizationError error;
  std::vector<std::uint8_t> bytes;
  glb::Package package;
  {
    StageTimer timer(&report, "pack");
    BAKE_ASSIGN_OR_RETURN(package, buildPaintstrokePackage(loaded.set, directions, shadows,
                                                           loaded.grownOn ? &*loaded.grownOn : nullptr, &error));
    BAKE_ASSIGN_OR_RETURN(bytes, glb::encode(package));
  }
  {
    // What a reader gets back, through the same checks as any package.
    StageTimer timer(&report, "measure");
    BAKE_ASSIGN_OR_RETURN(const PaintstrokePackage stored, decodePaintstrokePackage(package, settings.output));
    reportErrors(error, stored, report);
  }
  progress.update(4);
  {
    StageTimer timer(&report, "write");
    BAKE_RETURN_IF_ERROR(session.stageOutput(settings.output, bytes));
  }
  progress.finish();
  report.setStatistic("paintstrokes", countsOf(loaded.set, directions.size(), repairs, bytes.size()));
  return {};
}

std::vector<std::string> inputFiles(const Settings& settings) {
  // A stroke list's generators name meshes and textures (relative to the list); a list that does not
  // parse lists only itself, and the bake reports why.
  std::vector<std::string> inputs{settings.input};
  if (!isStrokeList(settings.input)) {
    addTextureInput(settings.grow.lengthFrom, inputs);
    addTextureInput(settings.grow.colourFrom, inputs);
    return inputs;
  }
  Result<StrokeInput> input = readStrokeInput(settings.input);
  if (!input.isOk()) return inputs;
  for (const json& entry : input->generators) {
    const std::vector<std::string> files = generatorFiles(entry, input->directory);
    inputs.insert(inputs.end(), files.begin(), files.end());
  }
  return inputs;
}

}  // namespace

Status check(const Settings& settings) { return checkOptions(settings); }

Result<RunFiles> inputs(const Settings& settings) { return RunFiles{inputFiles(settings), {settings.output}}; }

Status run(const Settings& settings, Diagnostics& diagnostics) {
  BAKE_RETURN_IF_ERROR(checkOptions(settings));
  BakeSession session("strokebake", settings.common, diagnostics);
  session.report().setOptions(optionsOf(settings, !isStrokeList(settings.input)));
  return session.finish(bake(settings, session));
}

}  // namespace bake::paintstrokes
