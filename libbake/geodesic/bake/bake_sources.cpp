// Sources of the fields. Vertex sources refer to input vertex indices (before welding); point and node
// sources are snapped once to their nearest surface point (snap.h) and kept as a face + barycentric
// point. A sources file lists fields, each the combined min-field of its sources; command-line sources
// give one field each, or one combined field with --combine.
#include <cmath>

#include "bake_formats/geodesic.h"

#include "bake/core/atomic_file.h"
#include "core/json_keys.h"
#include "core/json_read.h"
#include "geodesic/bake/bake_stages.h"
#include "geodesic/input/farthest.h"
#include "geodesic/input/snap.h"

namespace bake::geodesic {
namespace {

using nlohmann::json;

Result<std::vector<FieldSpec>> readSourcesFile(const std::string& path) {
  // readFileBytes refuses a directory (an ifstream on one fails like malformed JSON).
  BAKE_ASSIGN_OR_RETURN(const std::vector<std::uint8_t> bytes, readFileBytes(path));
  const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  BAKE_ASSIGN_OR_RETURN(json document, parseJsonText(text, path));
  if (!document.is_object() || !document.contains("fields") || !document["fields"].is_array())
    return invalidInput("expected an object with a \"fields\" array", {path, ""});
  // Strict keys: a misspelt key would otherwise silently bake something else.
  if (const auto unknown = findUnknownKey(document, {"$schema", "description", "fields"}))
    return invalidInput(unknown->message, {path, ""});
  std::vector<FieldSpec> fields;
  const json& list = document["fields"];
  if (list.size() > std::size_t(format::geodesic::kMaxFields)) {
    return invalidInput("lists " + std::to_string(list.size()) + " fields; a package holds at most " +
                            std::to_string(format::geodesic::kMaxFields),
                        {path, "fields"});
  }
  for (std::size_t f = 0; f < list.size(); ++f) {
    const std::string where = "fields[" + std::to_string(f) + "]";
    const json& entry = list[f];
    if (!entry.is_object() || !entry.contains("sources") || !entry["sources"].is_array() ||
        entry["sources"].empty())
      return invalidInput("a field needs a non-empty \"sources\" array", {path, where});
    if (const auto unknown = findUnknownKey(entry, {"name", "sources"})) return invalidInput(unknown->message, {path, where});
    FieldSpec field;
    field.name = entry.contains("name") && entry["name"].is_string() ? entry["name"].get<std::string>()
                                                                     : "field " + std::to_string(f);
    const json& sources = entry["sources"];
    for (std::size_t s = 0; s < sources.size(); ++s) {
      const std::string element = where + ".sources[" + std::to_string(s) + "]";
      const json& source = sources[s];
      SourceSpec spec;
      spec.origin = path + ": " + element;
      if (!source.is_object() || source.size() != 1) {
        return invalidInput("a source is an object with exactly one of \"vertex\", \"point\", \"node\"", {path, element});
      }
      if (const auto unknown = findUnknownKey(source, {"vertex", "point", "node"}))
        return invalidInput(unknown->message, {path, element});
      if (source.contains("vertex") && source["vertex"].is_number_integer() && source["vertex"].get<std::int64_t>() >= 0 &&
          source["vertex"].get<std::int64_t>() <= std::int64_t(UINT32_MAX)) {
        spec.kind = SourceSpec::Kind::Vertex;
        spec.vertex = source["vertex"].get<std::uint32_t>();
      } else if (source.contains("point") && source["point"].is_array() && source["point"].size() == 3 &&
                 source["point"][0].is_number() && source["point"][1].is_number() && source["point"][2].is_number()) {
        spec.kind = SourceSpec::Kind::Point;
        for (int k = 0; k < 3; ++k) spec.point[k] = source["point"][k].get<double>();
        if (!std::isfinite(spec.point[0]) || !std::isfinite(spec.point[1]) || !std::isfinite(spec.point[2]))
          return invalidInput("the point is not finite", {path, element});
      } else if (source.contains("node") && source["node"].is_string()) {
        spec.kind = SourceSpec::Kind::Node;
        spec.node = source["node"].get<std::string>();
      } else {
        return invalidInput("a source is {\"vertex\": index}, {\"point\": [x, y, z]} or {\"node\": \"name\"}",
                            {path, element});
      }
      field.sources.push_back(std::move(spec));
    }
    fields.push_back(std::move(field));
  }
  return fields;
}

std::vector<SourceSpec> commandLineSources(const Settings& settings) {
  std::vector<SourceSpec> specs;
  for (std::int64_t v : settings.sourceVertices) {
    SourceSpec spec;
    spec.kind = SourceSpec::Kind::Vertex;
    spec.vertex = std::uint32_t(v);
    spec.origin = "--source-vertex " + std::to_string(v);
    specs.push_back(spec);
  }
  for (const auto& p : settings.sourcePoints) {
    SourceSpec spec;
    spec.kind = SourceSpec::Kind::Point;
    spec.point = p;
    spec.origin = "--source-point";
    specs.push_back(spec);
  }
  for (const auto& name : settings.sourceNodes) {
    SourceSpec spec;
    spec.kind = SourceSpec::Kind::Node;
    spec.node = name;
    spec.origin = "--source-node " + name;
    specs.push_back(spec);
  }
  return specs;
}

Status resolveOne(const SourceSpec& spec, const TriangleMesh& mesh, const SurfaceBuild& build,
                  const std::string& file, ResolvedField& field) {
  const Surface& surface = build.surface;
  if (spec.kind == SourceSpec::Kind::Vertex) {
    if (spec.vertex >= mesh.vertexCount())
      return invalidInput("source vertex " + std::to_string(spec.vertex) + " does not exist (the mesh has " +
                              std::to_string(mesh.vertexCount()) + " vertices)",
                          {file, spec.origin});
    const std::uint32_t v = build.vertexMap[spec.vertex];
    if (surface.facesOfVertex(v).empty())
      return invalidInput("source vertex " + std::to_string(spec.vertex) + " belongs to no face", {file, spec.origin});
    field.points.push_back(vertexPoint(surface, v));
    field.snapDistances.push_back(0.0);
    return {};
  }
  Vec3d target = spec.point;  // world coordinates, as the surface's origin is
  if (spec.kind == SourceSpec::Kind::Node) {
    const NamedPoint* found = nullptr;
    for (const NamedPoint& named : mesh.namedPoints)
      if (named.name == spec.node) found = &named;
    if (!found) return invalidInput("no node named \"" + spec.node + "\" in the input", {file, spec.origin});
    // Named points are relative to the mesh's origin, like its positions.
    for (int k = 0; k < 3; ++k) target[k] = mesh.origin[k] + double(found->position[k]);
  }
  const SnappedPoint snapped = snapToSurface(surface, target);
  field.points.push_back(snapped.point);
  field.snapDistances.push_back(snapped.distance);
  return {};
}

// --fields: the named fields of the sources file, in file order; a name the file lacks is an error.
Result<std::vector<FieldSpec>> selectFields(std::vector<FieldSpec> specs, const Settings& settings) {
  if (settings.onlyFields.empty()) return specs;
  for (const std::string& name : settings.onlyFields) {
    bool found = false;
    for (const FieldSpec& spec : specs) found = found || spec.name == name;
    if (!found) return invalidInput("--fields: no field named \"" + name + "\"", {settings.sourcesFile, "fields"});
  }
  std::vector<FieldSpec> kept;
  for (FieldSpec& spec : specs)
    for (const std::string& name : settings.onlyFields)
      if (spec.name == name) {
        kept.push_back(std::move(spec));
        break;
      }
  return kept;
}

}  // namespace

Result<std::vector<ResolvedField>> resolveFields(const Settings& settings, const TriangleMesh& mesh,
                                                 const SurfaceBuild& build, Diagnostics& diagnostics) {
  const Surface& surface = build.surface;
  if (surface.triangleCount() == 0) return invalidInput("the mesh has no faces with three distinct corners", {settings.input, ""});

  std::vector<FieldSpec> specs;
  if (!settings.sourcesFile.empty()) {
    BAKE_ASSIGN_OR_RETURN(specs, readSourcesFile(settings.sourcesFile));
    BAKE_ASSIGN_OR_RETURN(specs, selectFields(std::move(specs), settings));
  }
  std::vector<SourceSpec> loose = commandLineSources(settings);
  if (settings.autoSources > 0) {
    const std::vector<std::uint32_t> samples = farthestPointSamples(surface, settings.autoSources);
    if (samples.size() < settings.autoSources)
      diagnostics.warning("auto-sources", "asked for " + std::to_string(settings.autoSources) +
                                              " farthest-point sources, the mesh has only " +
                                              std::to_string(samples.size()) + " distinct vertices");
    // Report them as input vertex indices: the first input vertex that maps to each surface vertex.
    std::vector<std::int64_t> firstInput(surface.vertexCount(), -1);
    for (std::size_t v = 0; v < build.vertexMap.size(); ++v)
      if (firstInput[build.vertexMap[v]] < 0) firstInput[build.vertexMap[v]] = std::int64_t(v);
    for (std::size_t i = 0; i < samples.size(); ++i) {
      SourceSpec spec;
      spec.kind = SourceSpec::Kind::Vertex;
      spec.vertex = std::uint32_t(firstInput[samples[i]]);
      spec.origin = "--auto-sources sample " + std::to_string(i);
      loose.push_back(spec);
    }
  }
  if (settings.combine && !loose.empty()) {
    specs.push_back({"combined", loose});
  } else {
    for (const SourceSpec& spec : loose) specs.push_back({spec.origin, {spec}});
  }
  if (specs.empty())
    return usageError("no sources: give --source-vertex, --source-point, --source-node, --sources or --auto-sources");
  if (specs.size() > std::size_t(format::geodesic::kMaxFields))
    return usageError("at most " + std::to_string(format::geodesic::kMaxFields) + " fields per package (got " +
                      std::to_string(specs.size()) + ")");

  std::vector<ResolvedField> fields;
  for (const FieldSpec& spec : specs) {
    ResolvedField field;
    field.name = spec.name;
    field.specs = spec.sources;
    for (const SourceSpec& source : spec.sources)
      BAKE_RETURN_IF_ERROR(resolveOne(source, mesh, build, settings.input, field));
    fields.push_back(std::move(field));
  }
  return fields;
}

}  // namespace bake::geodesic
