// revolbake's run: read the profile, compute the signed shape map, encode it and measure its safety
// margin, choose the projection, build the displacement map, find the iteration budget with the CPU
// march against the analytic intersection, write the package. Each stage is timed in the report, and
// the report states every error next to the reference it was measured against.
#include "bake/revolution/bake.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "bake/core/limits.h"
#include "bake/core/session.h"
#include "bake/io/glb.h"
#include "bake/io/image.h"
#include "bake/io/mesh.h"
#include "bake_formats/revolution.h"
#include "core/path.h"
#include "revolution/bake/bake_stages.h"
#include "revolution/input/profile_extract.h"
#include "revolution/oracle/march.h"

namespace bake::revolution {
namespace {

using nlohmann::json;

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

Result<ProfileKind> resolveKind(const Settings& settings) {
  if (settings.kind != ProfileKind::Auto) return settings.kind;
  const std::string ext = lowerExtension(settings.input);
  if (ext == ".json") return ProfileKind::Json;
  if (ext == ".csv" || ext == ".txt") return ProfileKind::Csv;
  if (ext == ".svg") return ProfileKind::Svg;
  if (ext == ".png" || ext == ".exr" || ext == ".tif" || ext == ".tiff" || ext == ".jpg" || ext == ".pgm")
    return ProfileKind::Image;
  if (ext == ".obj" || ext == ".ply" || ext == ".off" || ext == ".stl" || ext == ".gltf" || ext == ".glb")
    return ProfileKind::Mesh;
  return Status(ExitCode::Usage, "cannot tell the kind of profile from the extension '" + ext +
                                     "'; give --input-kind json|csv|svg|image|mesh",
                {settings.input, ""});
}

const char* kindName(ProfileKind kind) {
  switch (kind) {
    case ProfileKind::Json: return "json";
    case ProfileKind::Csv: return "csv";
    case ProfileKind::Svg: return "svg";
    case ProfileKind::Image: return "image";
    case ProfileKind::Mesh: return "mesh";
    case ProfileKind::Auto: break;
  }
  return "auto";
}

Status checkReplicaOptions(const Settings& settings) {
  const int limit = format::revolution::kMaxReplicasPerAxis;
  for (int count : settings.grid)
    if (count < 1 || count > limit) return usageError("--grid counts must be within 1 .. " + std::to_string(limit));
  if (double(settings.grid[0]) * settings.grid[1] * settings.grid[2] > format::revolution::kMaxReplicas)
    return usageError("--grid asks for more than " + std::to_string(format::revolution::kMaxReplicas) + " copies");
  for (double spacing : settings.gridSpacing)
    if (!(spacing >= 0) || !std::isfinite(spacing)) return usageError("--grid-spacing values must be >= 0 (0: the box's extent)");
  if (settings.mirror.find_first_not_of("xyz") != std::string::npos)
    return usageError("--mirror takes the axes to mirror, letters among x, y, z (e.g. y), not '" + settings.mirror + "'");
  if (settings.ring != 0 && (settings.ring < 2 || settings.ring > limit))
    return usageError("--ring must be within 2 .. " + std::to_string(limit) + " copies");
  const bool gridAsked = settings.grid != std::array<int, 3>{1, 1, 1};
  if (settings.ring != 0 && (gridAsked || !settings.mirror.empty()))
    return usageError("--ring cannot be combined with --grid or --mirror: copies form a grid or a ring");
  if (!(settings.ringRadius >= 0) || !std::isfinite(settings.ringRadius)) return usageError("--ring-radius must be >= 0");
  if (settings.ringRadius > 0 && settings.ring == 0) return usageError("--ring-radius needs --ring");
  return {};
}

Status checkOptions(const Settings& settings) {
  BAKE_RETURN_IF_ERROR(checkWrittenExtension(settings.output, "-o", ".glb", "the package"));
  if (settings.resolution < 16 || settings.resolution > 16384)
    return usageError("--resolution must be within 16 .. 16384 texels");
  if (settings.paddingTexels < 1 || settings.paddingTexels > 256) return usageError("--padding must be within 1 .. 256 texels");
  if (!(settings.targetError > 0 && settings.targetError < 1)) return usageError("--target-error must be within (0, 1)");
  if (settings.proxyBands < 1 || settings.proxyBands > format::revolution::kMaxProxyBands)
    return usageError("--proxy-bands must be within 1 .. " + std::to_string(format::revolution::kMaxProxyBands));
  if (!(settings.overRelaxation >= 1 && settings.overRelaxation < 2)) return usageError("--over-relaxation must be within [1, 2)");
  if (!(settings.heightScale > 0) || !std::isfinite(settings.heightScale)) return usageError("--height-scale must be > 0");
  if (settings.imageTexelSize < 0 || !std::isfinite(settings.imageTexelSize)) return usageError("--texel-size must be >= 0");
  BAKE_RETURN_IF_ERROR(checkReplicaOptions(settings));
  for (const auto& [option, value] : {std::pair{"--repeat-u", settings.repeatU}, std::pair{"--repeat-v", settings.repeatV}}) {
    if (value < 0) {
      char text[64];
      std::snprintf(text, sizeof text, "%g", value);
      return usageError(std::string(option) + " " + text + ": must be >= 0 (0: from the projection)");
    }
  }
  return {};
}

json optionsOf(const Settings& settings) {
  return {{"resolution", settings.resolution},
          {"padding", settings.paddingTexels},
          {"encoding", encodingName(settings.encoding)},
          {"heightMap", settings.heightMap},
          {"heightScale", settings.heightScale},
          {"projection", settings.projection ? projectionName(*settings.projection) : "auto"},
          {"repeat", {settings.repeatU, settings.repeatV}},
          {"targetError", settings.targetError},
          {"proxyBands", settings.proxyBands},
          {"overRelaxation", settings.overRelaxation},
          {"texelSize", settings.imageTexelSize},
          {"position", settings.position},
          {"grid", settings.grid},
          {"gridSpacing", settings.gridSpacing},
          {"mirror", settings.mirror},
          {"ring", settings.ring},
          {"ringRadius", settings.ringRadius},
          {"selfShadow", settings.selfShadow},
          {"threads", settings.common.threads}};
}

// Reads the input into a profile and a distance field.
Status readAndMeasure(const Settings& settings, ProfileKind kind, BakeSession& session, BakeState& state) {
  Report& report = session.report();
  Diagnostics& diagnostics = session.diagnostics();
  std::vector<std::string> repairs;
  if (kind == ProfileKind::Image) {
    CoverageImage image;
    {
      StageTimer timer(&report, "read");
      BAKE_ASSIGN_OR_RETURN(image, readCoverageImage(settings.input, settings.imageTexelSize));
      state.profile = contourOfCoverage(image);
      state.profile.source = settings.input;
      if (state.profile.contours.empty()) return invalidInput("the image holds no shape (no coverage above 0.5)", {settings.input, ""});
      BAKE_RETURN_IF_ERROR(validateProfile(state.profile, repairs).inFile(settings.input));
    }
    StageTimer timer(&report, "distance");
    state.binaryInput = isBinary(image);
    state.field = state.binaryInput ? distanceFromBinary(image) : distanceFromCoverage(image);
    state.exactReference = false;
  } else {
    {
      StageTimer timer(&report, "read");
      switch (kind) {
        case ProfileKind::Json: {
          BAKE_ASSIGN_OR_RETURN(state.profile, readProfileJson(settings.input));
          break;
        }
        case ProfileKind::Csv: {
          BAKE_ASSIGN_OR_RETURN(state.profile, readProfileCsv(settings.input));
          break;
        }
        case ProfileKind::Svg: {
          BAKE_ASSIGN_OR_RETURN(state.profile, readProfileSvg(settings.input, settings.svgPathId));
          break;
        }
        case ProfileKind::Mesh: {
          MeshReadOptions options;
          options.weld = true;
          BAKE_ASSIGN_OR_RETURN(const TriangleMesh mesh, readMesh(settings.input, options));
          BAKE_RETURN_IF_ERROR(validateMesh(mesh, settings.input));
          BAKE_ASSIGN_OR_RETURN(MeshProfile fromMesh, profileOfMesh(mesh, settings.input));
          state.profile = std::move(fromMesh.profile);
          state.meshAxis = fromMesh.axis;
          state.meshDeviation = json{{"maxDeviation", fromMesh.maxDeviation},
                                     {"rmsDeviation", fromMesh.rmsDeviation},
                                     {"maxDeviationRelative", fromMesh.maxDeviation / std::max(1e-300, fromMesh.objectSize)},
                                     {"verticesMeasured", fromMesh.vertices},
                                     {"axisPitch", fromMesh.axis.pitch}};
          break;
        }
        default: return internalError("unexpected profile kind");
      }
      state.profile.source = settings.input;
      // Before the profile is checked and the distances computed: both visit every piece for every
      // texel (or every other piece), so a profile of a million pieces would run for minutes.
      std::uint64_t pieces = 0;
      for (const Contour& contour : state.profile.contours) pieces += contour.segments.size();
      const std::uint64_t side = std::uint64_t(std::max(1, settings.resolution));
      BAKE_RETURN_IF_ERROR(checkBudget(Budget::ProfileWork, side * side * std::max<std::uint64_t>(pieces, 1),
                                       "distance evaluations (" + std::to_string(pieces) + " profile pieces at " +
                                           std::to_string(side) + "x" + std::to_string(side) + " texels)",
                                       {settings.input, ""}));
      BAKE_RETURN_IF_ERROR(validateProfile(state.profile, repairs).inFile(settings.input));
    }
    StageTimer timer(&report, "distance");
    state.field = distanceFromProfile(state.profile, gridForBounds(profileBounds(state.profile), settings.resolution,
                                                                    settings.paddingTexels));
    state.exactReference = true;
  }
  for (const std::string& repair : repairs) diagnostics.warning("profile-repaired", repair);
  return {};
}

Status bake(const Settings& settings, BakeSession& session) {
  Report& report = session.report();
  Diagnostics& diagnostics = session.diagnostics();
  session.addInput(settings.input);
  if (!settings.heightMap.empty()) session.addInput(settings.heightMap);
  if (!settings.baseColorTexture.empty()) session.addInput(settings.baseColorTexture);
  BAKE_ASSIGN_OR_RETURN(const ProfileKind kind, resolveKind(settings));

  BakeState state;
  BAKE_RETURN_IF_ERROR(readAndMeasure(settings, kind, session, state));
  warnAboutThinFeatures(state, diagnostics);
  {
    StageTimer timer(&report, "encode");
    encodeAndMeasure(settings, state, report, diagnostics);
  }
  {
    StageTimer timer(&report, "projection");
    chooseTextureProjection(settings, state);
  }
  if (!settings.heightMap.empty()) {
    StageTimer timer(&report, "displacement");
    BAKE_RETURN_IF_ERROR(buildDisplacement(settings, state));
  }
  {
    StageTimer timer(&report, "march");
    measureMarch(settings, state, report, diagnostics);
  }
  {
    StageTimer timer(&report, "write");
    BAKE_ASSIGN_OR_RETURN(const glb::Package package, buildPackage(settings, state));
    BAKE_ASSIGN_OR_RETURN(const auto bytes, glb::encode(package));
    BAKE_RETURN_IF_ERROR(session.stageOutput(settings.output, bytes));
  }
  report.setStatistic("inputKind", kindName(kind));
  report.setStatistic("shapeMap", {{"width", state.field.grid.width},
                                   {"height", state.field.grid.height},
                                   {"texelSize", state.field.grid.texelSize},
                                   {"hMin", state.field.grid.hMin},
                                   {"encoding", encodingName(settings.encoding)},
                                   {"bytes", state.encoded.bytes.size()}});
  report.setStatistic("contours", state.profile.contours.size());
  if (!state.meshDeviation.is_null()) report.setStatistic("meshOfRevolution", state.meshDeviation);
  return {};
}

}  // namespace

Status check(const Settings& settings) { return checkOptions(settings); }

Result<RunFiles> inputs(const Settings& settings) {
  RunFiles run{{settings.input}, {settings.output}};
  if (!settings.heightMap.empty()) run.inputs.push_back(settings.heightMap);
  if (!settings.baseColorTexture.empty()) run.inputs.push_back(settings.baseColorTexture);
  return run;
}

Status run(const Settings& settings, Diagnostics& diagnostics) {
  BAKE_RETURN_IF_ERROR(checkOptions(settings));
  BakeSession session("revolbake", settings.common, diagnostics);
  session.report().setOptions(optionsOf(settings));
  return session.finish(bake(settings, session));
}

}  // namespace bake::revolution
