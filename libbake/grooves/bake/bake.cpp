// groovebake's run (seed 000 §4.1-§4.2): read the scene (validated by the reader, exit 3 on invalid
// input naming groove, segment and (u, v)), build the grid's cell lists, find the special-case
// records, pack the package, decode it again and measure the stored fp32 geometry against the scene's
// double geometry (the bake's error against its stated reference), then stage the output so it is
// committed only when everything succeeded. Each stage is timed in the report.
#include "bake/grooves/bake/bake.h"

#include <chrono>
#include <iomanip>
#include <sstream>

#include "bake/core/session.h"
#include "bake/core/vector_text.h"
#include "core/path.h"
#include "core/progress.h"
#include "grooves/bake/grid_stages.h"
#include "grooves/package/package.h"
#include "grooves/package/surface.h"

namespace bake::grooves {
namespace {

using nlohmann::json;
namespace fmt = format::grooves;

Status checkOptions(const Settings& settings) {
  BAKE_RETURN_IF_ERROR(checkWrittenExtension(settings.output, "-o", ".glb", "the package"));
  if (!(settings.cellSize >= 0) || !std::isfinite(settings.cellSize)) return usageError("--cell-size must be a finite number >= 0");
  if (settings.maxCells < 1) return usageError("--max-cells must be at least 1");
  if (!(settings.maxStretch >= 1) || !std::isfinite(settings.maxStretch))
    return usageError("--max-stretch must be a finite ratio >= 1");
  return {};
}

json optionsOf(const Settings& settings) {
  return {{"scene", settings.scene},
          {"cellSize", settings.cellSize},
          {"maxCells", settings.maxCells},
          {"specialCases", settings.specialCases},
          {"applyTo", settings.applyTo},
          {"maxStretch", settings.maxStretch},
          {"threads", settings.common.threads}};
}

json sceneStatistics(const GrooveScene& scene) {
  std::size_t arcs = 0, corners = 0;
  for (const Primitive& p : scene.primitives) {
    arcs += p.kind == Primitive::Kind::Arc ? 1 : 0;
    corners += p.cornerAtStart ? 1 : 0;
  }
  return {{"grooves", scene.grooves.size()},
          {"primitives", scene.primitives.size()},
          {"segments", scene.primitives.size() - arcs},
          {"arcs", arcs},
          {"corners", corners},
          {"profiles", scene.profiles.size()},
          {"materials", scene.materials.size()},
          {"domain", {scene.domain[0], scene.domain[1]}},
          {"wrap", scene.wrapRepeat ? fmt::kWrapRepeat : fmt::kWrapNone},
          {"wmax", scene.wmax},
          {"hmax", scene.hmax},
          {"dmax", scene.dmax},
          {"duplicatesMerged", scene.warnings.size()}};
}

json gridStatistics(const GrooveGrid& grid) {
  const GridStats stats = gridStats(grid);
  return {{"cells", {grid.cells[0], grid.cells[1]}},
          {"cellSize", {grid.cellSize.u, grid.cellSize.v}},
          {"cellCount", grid.cellCount()},
          {"primitiveRefs", grid.primitiveRefs.size()},
          {"recordRefs", grid.recordRefs.size()},
          {"meanRefsPerCell", stats.meanRefsPerCell},
          {"maxRefsPerCell", stats.maxRefsPerCell},
          {"emptyCells", stats.emptyCells},
          {"records", {{"intersections", stats.intersections},
                       {"ends", stats.ends},
                       {"corners", stats.corners},
                       {"total", grid.records.size()}}}};
}

json bufferBytes(const glb::Package& package, std::size_t fileBytes) {
  json bytes = json::object();
  for (std::size_t k = 0; k < fmt::kArrayCount && k < package.blobs.size(); ++k)
    bytes[fmt::kArrayKeys[k]] = package.blobs[k].bytes.size();
  bytes["file"] = fileBytes;
  return bytes;
}

void reportError(const StoredGeometryError& error, const GrooveGrid& grid, Report& report) {
  const double cell = std::max(grid.cellSize.u, grid.cellSize.v);
  report.addAccuracy(
      "largest distance between the stored geometry (fp32 offsets from each primitive's and record's anchor cell, "
      "rebuilt in double) and the scene's geometry: end points, joint points, record points and boxes; arc centres "
      "(far from their cell for nearly straight arcs); arc end points rebuilt from the stored centre, radius and angles; "
      "joint normals",
      "the scene's double-precision primitives, joints and records",
      {{"maxPositionError", error.maxPosition},
       {"maxPositionErrorOverCellSize", error.maxPosition / cell},
       {"maxArcCentreError", error.maxArcCentre},
       {"maxArcEndpointError", error.maxArcEndpoint},
       {"maxJointNormalError", error.maxNormal}});
}

// The texture-space scale of the pattern on the surface and the stretch of its UV layout, in the
// report, and a warning where the grooves will look distorted.
void reportSurface(const Settings& settings, const GrooveScene& scene, const GrooveSurface& surface, BakeSession& session) {
  const double unitsPerUv[2] = {scene.domain[0], scene.domain[1]};
  const UvStretch stretch = measureUvStretch(surface.mesh, unitsPerUv, settings.maxStretch);
  const std::string units = scene.units.empty() ? "texture units" : scene.units;
  json tangents = {{"source", surface.tangentsFromMesh ? "mesh" : "computed"}};
  if (!surface.tangentsFromMesh) {
    tangents["splitVertices"] = surface.computed.splitVertices;
    tangents["degenerateTriangles"] = surface.computed.degenerateTriangles;
    tangents["fallbackVertices"] = surface.computed.fallbackVertices;
    tangents["normalsComputed"] = surface.computed.normalsComputed;
    if (!surface.tangentProblem.empty()) tangents["meshTangentsUnused"] = surface.tangentProblem;
  }
  session.report().setStatistic(
      "surface", {{"mesh", settings.applyTo},
                  {"vertices", surface.mesh.vertexCount()},
                  {"triangles", surface.mesh.triangleCount()},
                  {"textureScale", {{"unitsPerUv", {unitsPerUv[0], unitsPerUv[1]}}, {"units", units}}},
                  {"worldPerTextureUnit", {{"median", stretch.medianScale}, {"min", stretch.minScale}, {"max", stretch.maxScale}}},
                  {"maxStretch", stretch.maxStretch},
                  {"maxStretchTriangle", stretch.worstTriangle},
                  {"stretchLimit", settings.maxStretch},
                  {"trianglesOverLimit", stretch.trianglesOver},
                  {"areaShareOverLimit", stretch.areaShareOver},
                  {"trianglesWithoutUvArea", stretch.noUvArea},
                  {"tangents", tangents}});
  Diagnostics& diagnostics = session.diagnostics();
  if (stretch.trianglesOver > 0) {
    std::ostringstream message;
    message << settings.applyTo << ": the grooves will look distorted on " << stretch.trianglesOver << " of "
            << surface.mesh.triangleCount() << " triangles (" << std::setprecision(3) << 100 * stretch.areaShareOver
            << " % of the area): their UV layout stretches the pattern by more than " << settings.maxStretch
            << " (--max-stretch), or scales it that much away from the median";
    if (stretch.maxStretch > settings.maxStretch)
      message << "; worst stretch " << stretch.maxStretch << " at triangle " << stretch.worstTriangle;
    if (stretch.noUvArea > 0) message << "; " << stretch.noUvArea << " triangles have no UV area";
    diagnostics.warning("uv-stretch", message.str());
  }
  if (!surface.tangentsFromMesh && surface.computed.fallbackVertices > 0)
    diagnostics.warning("tangent-fallback", settings.applyTo + ": " + std::to_string(surface.computed.fallbackVertices) +
                                                " vertices touch only triangles without UV area: their tangent is arbitrary");
  diagnostics.info(settings.applyTo + ": 1 UV unit = " + numberText(unitsPerUv[0]) + " x " + numberText(unitsPerUv[1]) +
                   " " + units + "; on the mesh 1 texture unit spans " + numberText(stretch.medianScale) +
                   " world units (median), stretch up to " + numberText(stretch.maxStretch));
}

Status bake(const Settings& settings, BakeSession& session) {
  Report& report = session.report();
  Progress progress("baking grooves", 5, progressEnabled(session.diagnostics().quiet()));
  GrooveScene scene;
  {
    StageTimer timer(&report, "read");
    BAKE_ASSIGN_OR_RETURN(scene, readGrooveScene(settings.scene));
    session.addInput(settings.scene);
    for (const std::string& file : scene.files) session.addInput(file);
  }
  for (const std::string& warning : scene.warnings) session.diagnostics().warning("duplicate-groove", settings.scene + ": " + warning);
  progress.update(1);

  GridSettings gridSettings;
  gridSettings.cellSize = settings.cellSize;
  gridSettings.maxCells = settings.maxCells;
  gridSettings.threads = int(session.threads());
  grid_detail::GridStageTimes times;
  Result<GrooveGrid> built = grid_detail::buildGrooveGridTimed(scene, gridSettings, times);
  if (!built.isOk()) {
    Status status = built.takeStatus();
    return status.inFile(settings.scene);  // the grid's errors are the scene's
  }
  GrooveGrid grid = std::move(built).value();
  report.addStage("grid", times.cells);
  report.addStage("records", times.records);
  if (!settings.specialCases) report.setStatistic("recordsLeftOut", dropSpecialCases(grid));
  progress.update(3);

  glb::Package package;
  std::vector<std::uint8_t> bytes;
  {
    StageTimer timer(&report, "pack");
    BAKE_ASSIGN_OR_RETURN(package, buildGroovePackage(scene, grid, session.threads()));
    BAKE_ASSIGN_OR_RETURN(bytes, glb::encode(package));
  }
  {
    // What a reader gets back (the package's arrays are the file's bytes), measured against the scene.
    StageTimer timer(&report, "measure");
    // Errors here come from the scene's content (values a package cannot hold): they name the scene.
    BAKE_ASSIGN_OR_RETURN(const GroovePackage stored, decodeGroovePackage(package, settings.scene, false));
    reportError(storedGeometryError(scene, grid, stored), grid, report);
  }
  if (!settings.applyTo.empty()) {
    StageTimer timer(&report, "surface");
    BAKE_ASSIGN_OR_RETURN(const GrooveSurface surface, readGrooveSurface(settings.applyTo));
    session.addInput(settings.applyTo);
    reportSurface(settings, scene, surface, session);
    applySurface(package, surface);
    BAKE_ASSIGN_OR_RETURN(bytes, glb::encode(package));
  }
  progress.update(4);
  {
    StageTimer timer(&report, "write");
    BAKE_RETURN_IF_ERROR(session.stageOutput(settings.output, bytes));
  }
  progress.finish();
  report.setStatistic("scene", sceneStatistics(scene));
  report.setStatistic("grid", gridStatistics(grid));
  report.setStatistic("bytes", bufferBytes(package, bytes.size()));
  return {};
}

std::vector<std::string> inputFiles(const Settings& settings) {
  // The drawings a scene names are inputs too (its cache key and --print-inputs); a scene that does not
  // parse lists only itself, and the bake reports why.
  std::vector<std::string> inputs{settings.scene};
  if (Result<GrooveScene> scene = readGrooveScene(settings.scene); scene.isOk())
    inputs.insert(inputs.end(), scene->files.begin(), scene->files.end());
  if (!settings.applyTo.empty()) inputs.push_back(settings.applyTo);
  return inputs;
}

}  // namespace

Status check(const Settings& settings) { return checkOptions(settings); }

Result<RunFiles> inputs(const Settings& settings) { return RunFiles{inputFiles(settings), {settings.output}}; }

Status run(const Settings& settings, Diagnostics& diagnostics) {
  BAKE_RETURN_IF_ERROR(checkOptions(settings));
  BakeSession session("groovebake", settings.common, diagnostics);
  session.report().setOptions(optionsOf(settings));
  return session.finish(bake(settings, session));
}

}  // namespace bake::grooves
