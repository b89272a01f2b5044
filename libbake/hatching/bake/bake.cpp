// tambake's run: read the style and apply the command line's overrides, read the mesh of
// --apply-to, build the tonal art map (hatching/bake/build.h, Praun et al. 2001 section 3), measure its quality
// (hatching/bake/quality.h), encode the KTX2 TAM and the optional threshold texture, assemble the optional
// package, and stage every output so that they are committed together only when all succeeded. Each
// stage is timed in the report, and the report states the quality figures next to their targets:
// tone error against the style's target tones, nesting violations against zero (nesting holds by
// construction), ink variation and low-frequency power against a uniform ink distribution.
#include "bake/hatching/bake.h"
#include "bake/core/vector_text.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "bake/core/limits.h"
#include "bake/core/session.h"
#include "bake_formats/tam.h"
#include "core/path.h"
#include "core/progress.h"
#include "hatching/bake/bake_stages.h"

namespace bake::hatching {
namespace {

using nlohmann::json;
namespace fmt = format::tam;

bool finite3(const std::array<double, 3>& v) { return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]); }

// Two spellings of one file ("t.ktx2", "./t.ktx2", a link to it) are one output: the second write
// would replace the first.
bool sameFile(const std::string& a, const std::string& b) {
  std::error_code errorA, errorB;
  const std::filesystem::path canonicalA = std::filesystem::weakly_canonical(a, errorA);
  const std::filesystem::path canonicalB = std::filesystem::weakly_canonical(b, errorB);
  if (errorA || errorB) return std::filesystem::path(a).lexically_normal() == std::filesystem::path(b).lexically_normal();
  return canonicalA == canonicalB;
}

Status checkOptions(const Settings& settings) {
  BAKE_RETURN_IF_ERROR(checkWrittenExtension(settings.output, "-o", ".ktx2", "the TAM"));
  if (!settings.threshold.empty())
    BAKE_RETURN_IF_ERROR(checkWrittenExtension(settings.threshold, "--threshold", ".ktx2", "the threshold texture"));
  if (!settings.threshold.empty() && sameFile(settings.threshold, settings.output))
    return usageError("--threshold and -o name the same file");
  if (settings.candidates != -1 && (settings.candidates < 1 || settings.candidates > 4096))
    return usageError("--candidates must be within 1 .. 4096");
  if (settings.seed < -1) return usageError("--seed must be >= 0");
  const MaterialSettings& m = settings.material;
  if (m.mesh.empty() != m.package.empty()) return usageError("--apply-to and --package go together");
  if (!m.package.empty()) {
    BAKE_RETURN_IF_ERROR(checkWrittenExtension(m.package, "--package", ".glb", "the package"));
    if (!(m.tilesPerUnit > 0) || !std::isfinite(m.tilesPerUnit)) return usageError("--tiles-per-unit must be > 0");
    if (!std::isfinite(m.rotationDegrees)) return usageError("--rotation must be a finite number");
    if (!std::isfinite(m.translation[0]) || !std::isfinite(m.translation[1])) return usageError("--translation must be finite");
    if (m.orientation != fmt::kOrientationTowardLight && m.orientation != fmt::kOrientationAcrossLight)
      return usageError("--orientation must be toward-light or across-light");
    for (double c : m.baseColour)
      if (!(c >= 0 && c <= 1)) return usageError("--base-color components must be within [0, 1]");
    if (!finite3(m.position)) return usageError("--position must be finite");
    if (!(m.scale > 0) || !std::isfinite(m.scale)) return usageError("--scale must be > 0");
  }
  return {};
}

json optionsOf(const Settings& settings) {
  json options = {{"style", settings.style},
                  {"threshold", !settings.threshold.empty()},
                  {"zstd", settings.zstd},
                  {"threads", settings.common.threads}};
  if (settings.candidates != -1) options["candidates"] = settings.candidates;
  if (settings.resolution != -1) options["resolution"] = settings.resolution;
  if (settings.seed != -1) options["seed"] = settings.seed;
  if (settings.skipLevels != 0) options["skipLevels"] = settings.skipLevels;
  const MaterialSettings& m = settings.material;
  if (!m.package.empty()) {
    options["applyTo"] = m.mesh;
    options["tilesPerUnit"] = m.tilesPerUnit;
    options["rotationDegrees"] = m.rotationDegrees;
    options["translation"] = m.translation;
    options["orientation"] = m.orientation;
    options["baseColour"] = m.baseColour;
    options["position"] = m.position;
    options["scale"] = m.scale;
  }
  return options;
}

json styleJson(const Style& style) {
  const StrokeStyle& s = style.stroke;
  json stroke = {{"kind", strokeKindName(s.kind)},
                 {"length", {s.length.min, s.length.max}},
                 {"width", {s.width.min, s.width.max}},
                 {"angle", s.angleDegrees},
                 {"angleJitter", s.angleJitterDegrees},
                 {"curvature", s.curvature},
                 {"colour", s.colour},
                 {"opacity", s.opacity},
                 {"centreOpacity", s.centreOpacity},
                 {"edgeOpacity", s.edgeOpacity},
                 {"taper", s.taper}};
  if (s.kind == StrokeKind::CrossHatching) {
    stroke["crossFrom"] = s.crossFrom;
    stroke["crossAngle"] = s.crossAngleDegrees;
  }
  if (s.kind == StrokeKind::Image) stroke["image"] = s.image;
  return {{"tones", style.tones},     {"resolution", style.resolution}, {"levels", style.levels},
          {"candidates", style.candidates}, {"blurSigma", style.blurSigma},   {"seed", style.seed},
          {"stroke", stroke}};
}

// The style file with the command line's overrides.
Status readInputs(const Settings& settings, BakeSession& session, BakeState& state) {
  StageTimer timer(&session.report(), "read");
  BAKE_ASSIGN_OR_RETURN(state.style, readStyle(settings.style));
  for (const std::string& input : state.style.inputs()) session.addInput(input);
  if (settings.resolution != -1) BAKE_RETURN_IF_ERROR(setResolution(state.style, settings.resolution, "--resolution"));
  if (settings.candidates != -1) state.style.candidates = settings.candidates;
  if (settings.seed != -1) state.style.seed = std::uint64_t(settings.seed);
  // Before any stroke is drawn: every stroke placed is chosen among K candidates, each scored over its
  // texels, and the strokes of a tone cover each level about once, so the work grows as K times the
  // texels of all the levels drawn (Praun et al. 2001's greedy choice).
  std::uint64_t texels = 0;
  for (int level = 0; level < state.style.levels; ++level) {
    const std::uint64_t side = std::uint64_t(state.style.resolution) >> level;
    texels += side * side;
  }
  BAKE_RETURN_IF_ERROR(checkBudget(Budget::TamWork, texels * std::uint64_t(std::max(1, state.style.candidates)),
                                   "candidate texels (" + std::to_string(state.style.candidates) + " candidates over " +
                                       std::to_string(texels) + " texels of " + std::to_string(state.style.levels) +
                                       " levels)",
                                   {settings.style, ""}));
  if (settings.material.mesh.empty()) return {};
  MeshReadStats stats;
  BAKE_ASSIGN_OR_RETURN(TriangleMesh mesh, readMesh(settings.material.mesh, {}, &stats));
  BAKE_RETURN_IF_ERROR(validateMesh(mesh, settings.material.mesh));
  if (mesh.triangles.empty()) return invalidInput("the mesh has no triangles", {settings.material.mesh, ""});
  session.addInput(settings.material.mesh);
  if (stats.degenerateFacesRemoved)
    session.diagnostics().warning("degenerate-faces", settings.material.mesh + ": " + std::to_string(stats.degenerateFacesRemoved) +
                                                          " faces with repeated vertices were removed");
  state.normalsComputed = ensureUnitNormals(mesh);
  state.mesh = std::move(mesh);
  return {};
}

Status build(BakeSession& session, BakeState& state) {
  StageTimer timer(&session.report(), "build");
  Progress progress("building the tonal art map", 1000, progressEnabled(session.diagnostics().quiet()));
  BuildOptions options;
  options.threads = int(session.threads());
  options.progress = [&progress](double done) { progress.update(std::uint64_t(std::clamp(done, 0.0, 1.0) * 1000.0)); };
  BAKE_ASSIGN_OR_RETURN(state.tam, buildTam(state.style, options));
  progress.finish();
  return {};
}

// A tone the construction could not reach (its stroke cap ended it) is no crash, but the TAM does not
// hold what the style asked for: say so, per image, once per kind.
void warnAboutMissedTones(const BakeState& state, Diagnostics& diagnostics) {
  for (const ImageQuality& image : state.quality.images) {
    if (!(image.toneError > image.toneTolerance)) continue;
    std::ostringstream message;
    message << state.style.source << ": tone " << image.tone << " (target darkness " << image.target << ") reached "
            << image.darkness << " at " << image.side << " x " << image.side << " texels (tolerance " << image.toneTolerance
            << "): the strokes are too faint, too few or too large for it";
    diagnostics.warning("tone-missed", message.str());
  }
}

void reportQuality(const BakeState& state, Report& report) {
  const Quality& q = state.quality;
  double meanToneError = 0, minTolerance = 1;
  for (const ImageQuality& image : q.images) {
    meanToneError += image.toneError;
    minTolerance = std::min(minTolerance, image.toneTolerance);
  }
  if (!q.images.empty()) meanToneError /= double(q.images.size());
  // The same error on the 8-bit texels that are written (what the runtime samples).
  double maxStored = 0;
  for (const std::vector<double>& level : state.storedDarkness)
    for (std::size_t tone = 0; tone < level.size() && tone < state.tam.targets.size(); ++tone)
      maxStored = std::max(maxStored, std::abs(level[tone] - state.tam.targets[tone]));
  report.addAccuracy("tone error: |mean darkness - target| of every stroke-level image",
                     "the style's target tones (tolerance max(0.0025, 0.8 / side) per image)",
                     {{"maxToneError", q.maxToneError},
                      {"meanToneError", meanToneError},
                      {"maxToneErrorOverTolerance", q.maxToneErrorOverTolerance},
                      {"smallestTolerance", minTolerance},
                      {"maxToneErrorStored8Bit", maxStored},
                      {"images", q.images.size()}});
  report.addAccuracy("nesting violations: texels darker in a lighter tone; coarse-level strokes missing from a finer level",
                     "0 (Praun 2001 nesting across tones and resolutions)",
                     {{"toneViolations", q.nestingViolationsTone},
                      {"resolutionViolations", q.nestingViolationsResolution},
                      {"monotoneTones", q.monotoneTones ? 1 : 0}});
  int uniformityImages = 0;
  for (const ImageQuality& image : q.images) uniformityImages += image.uniformityChecked ? 1 : 0;
  report.addAccuracy("ink uniformity: coefficient of variation of darkness over the 16 quarter-tile windows",
                     "evenly spread ink: target <= " + numberText(kInkVariationTarget) + " on " + uniformityScope(),
                     {{"maxInkVariation", q.maxInkVariation},
                      {"target", kInkVariationTarget},
                      {"imagesChecked", uniformityImages},
                      {"maxInkVariationAllImages", q.maxInkVariationAll}});
  report.addAccuracy("low-frequency power: share of non-DC spectral power below 4 cycles per tile",
                     "no visible blotches: target <= " + numberText(kLowFrequencyPowerTarget) + " on the same images",
                     {{"maxLowFrequencyPower", q.maxLowFrequencyPower},
                      {"target", kLowFrequencyPowerTarget},
                      {"imagesChecked", uniformityImages},
                      {"maxLowFrequencyPowerAllImages", q.maxLowFrequencyPowerAll}});
  report.addAccuracy("level consistency: mean |darkness(l) - darkness(l + 1)| over tones and adjacent stroke levels",
                     "0 (the same tone at every level)", {{"meanLevelDifference", q.meanLevelDifference}});
  report.setStatistic("quality", q.toJson());
}

Status bake(const Settings& settings, BakeSession& session) {
  Report& report = session.report();
  BakeState state;
  BAKE_RETURN_IF_ERROR(readInputs(settings, session, state));
  BAKE_RETURN_IF_ERROR(build(session, state));
  {
    StageTimer timer(&report, "measure");
    state.quality = measureQuality(state.tam);
  }
  warnAboutMissedTones(state, session.diagnostics());
  ktx2::WriteOptions writeOptions;
  writeOptions.zstd = settings.zstd;
  {
    StageTimer timer(&report, "encode");
    BAKE_ASSIGN_OR_RETURN(ktx2::Texture texture, tamTexture(state.tam, state.style));
    for (int level = 0; level < state.tam.strokeLevels; ++level) state.storedDarkness.push_back(storedDarkness(texture, level));
    BAKE_RETURN_IF_ERROR(dropFinestLevels(texture, settings.skipLevels));
    BAKE_ASSIGN_OR_RETURN(state.tamBytes, ktx2::encode(texture, writeOptions));
    if (!settings.threshold.empty()) {
      BAKE_ASSIGN_OR_RETURN(ktx2::Texture threshold, thresholdKtx(state.tam, state.style));
      BAKE_RETURN_IF_ERROR(dropFinestLevels(threshold, settings.skipLevels));
      BAKE_ASSIGN_OR_RETURN(state.thresholdBytes, ktx2::encode(threshold, writeOptions));
    }
  }
  {
    StageTimer timer(&report, "write");
    BAKE_RETURN_IF_ERROR(session.stageOutput(settings.output, state.tamBytes));
    if (!settings.threshold.empty()) BAKE_RETURN_IF_ERROR(session.stageOutput(settings.threshold, state.thresholdBytes));
    if (state.mesh) {
      BAKE_ASSIGN_OR_RETURN(const glb::Package package, buildPackage(settings, state));
      BAKE_ASSIGN_OR_RETURN(const auto bytes, glb::encode(package));
      BAKE_RETURN_IF_ERROR(session.stageOutput(settings.material.package, bytes));
    }
  }
  reportQuality(state, report);
  report.setStatistic("style", styleJson(state.style));
  report.setStatistic("tam", {{"tones", state.tam.tones},
                              {"resolution", state.tam.resolution},
                              {"strokeLevels", state.tam.strokeLevels},
                              {"mipLevels", state.tam.mipLevels},
                              {"skippedLevels", settings.skipLevels},
                              {"format", state.tam.coloured ? "R8G8B8A8_UNORM" : "R8_UNORM"},
                              {"strokes", state.tam.strokes.size()},
                              {"bytes", state.tamBytes.size()}});
  if (!state.thresholdBytes.empty()) report.setStatistic("thresholdBytes", state.thresholdBytes.size());
  if (state.mesh)
    report.setStatistic("mesh", {{"vertices", state.mesh->vertexCount()},
                                 {"triangles", state.mesh->triangleCount()},
                                 {"normalsComputed", state.normalsComputed}});
  return {};
}

}  // namespace

Status check(const Settings& settings) { return checkOptions(settings); }

// The stroke image is listed, not read: a build system asks before the inputs exist.
Result<RunFiles> inputs(const Settings& settings) {
  BAKE_ASSIGN_OR_RETURN(const Style style, readStyle(settings.style, false));
  RunFiles run{style.inputs(), {settings.output}};
  const MaterialSettings& material = settings.material;
  if (!material.mesh.empty()) run.inputs.push_back(material.mesh);
  if (!settings.threshold.empty()) run.outputs.push_back(settings.threshold);
  if (!material.mesh.empty() && !material.package.empty()) run.outputs.push_back(material.package);
  return run;
}

Status run(const Settings& settings, Diagnostics& diagnostics) {
  BAKE_RETURN_IF_ERROR(checkOptions(settings));
  BakeSession session("tambake", settings.common, diagnostics);
  session.report().setOptions(optionsOf(settings));
  return session.finish(bake(settings, session));
}

}  // namespace bake::hatching
