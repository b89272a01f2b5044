// Scene loading: reads each package with libbake's reader (the same code bakeinfo trusts), places
// every primitive instance in world space, and picks up the first perspective camera and the first
// directional KHR_lights_punctual light. Extensions are checked against what the runtime can draw.
#include "scene/scene.h"

#include <bake_formats/glb.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <sstream>

#include "bake/core/vector_text.h"
#include "core/csv_read.h"
#include "core/json_keys.h"
#include "io/glb_scene.h"

namespace bake::play {
namespace {

constexpr const char* kLightsExtension = "KHR_lights_punctual";

bool handledByCore(const std::string& extension) {
  return extension == format::glb::kDracoExtension || extension == kLightsExtension;
}

Status checkExtensions(const glb::Package& package, const std::string& file, Diagnostics& diagnostics,
                       const std::function<bool(const std::string&)>& isKnownTechnique) {
  for (const std::string& extension : package.extensionsUsed) {
    if (handledByCore(extension) || isKnownTechnique(extension)) continue;
    const bool required = std::find(package.extensionsRequired.begin(), package.extensionsRequired.end(), extension) !=
                          package.extensionsRequired.end();
    if (required) {
      return unsupported("extension " + extension + " is required but this runtime has no renderer for it",
                         {file, "extensionsRequired"});
    }
    diagnostics.warning("unknown-extension", file + ": extension " + extension + " is not known; drawn without it");
  }
  return {};
}

Vec3 column(const glb::WorldMatrix& m, int c) { return {float(m[c * 4]), float(m[c * 4 + 1]), float(m[c * 4 + 2])}; }

// Cameras and lights are optional hints: one of a shape this runtime does not read is ignored, like
// any glTF viewer would, and never throws (every part is read leniently).
void takeCamera(const glb::Package& package, const glb::Node& node, const glb::WorldMatrix& world, Scene& scene) {
  if (scene.fileCamera || node.camera < 0) return;
  const nlohmann::json& camera = package.cameras[std::size_t(node.camera)];
  const nlohmann::json& p = jsonMember(camera, "perspective");
  if (jsonStringOr(camera, "type", "") != "perspective" || !p.is_object()) return;
  Camera out;
  out.eye = column(world, 3);
  out.target = out.eye - normalize(column(world, 2));  // cameras look down their local -Z
  out.up = normalize(column(world, 1));
  out.yfov = float(jsonNumberOr(p, "yfov", 0.7));
  out.znear = float(jsonNumberOr(p, "znear", 0.01));
  out.zfar = float(jsonNumberOr(p, "zfar", 1000.0));
  scene.fileCamera = out;
}

void takeLight(const glb::Package& package, const glb::Node& node, const glb::WorldMatrix& world, Scene& scene) {
  if (scene.fileLight || !node.extensions.contains(kLightsExtension)) return;
  const nlohmann::json& lights = jsonMember(jsonMember(package.extensions, kLightsExtension), "lights");
  const double index = jsonNumberOr(node.extensions[kLightsExtension], "light", -1);
  if (!lights.is_array() || !(index >= 0) || index >= double(lights.size()) || index != std::floor(index)) return;
  const nlohmann::json& chosen = lights[std::size_t(index)];
  const std::string type = jsonStringOr(chosen, "type", "");
  Light light;
  light.direction = normalize(column(world, 2));  // the light shines down its local -Z
  if (type == "point" || type == "spot") {
    light.kind = type == "point" ? LightKind::Point : LightKind::Spot;
    light.position = column(world, 3);
    light.spotDirection = normalize(column(world, 2) * -1.0f);
    if (type == "spot") {
      const nlohmann::json& spot = jsonMember(chosen, "spot");
      light.cutoff = float(std::clamp(jsonNumberOr(spot, "outerConeAngle", 0.7853981633974483), 1e-4, 1.5707963267948966));
      // KHR_lights_punctual fades between the inner and outer cone; the seed's spot is OpenGL's, with an
      // exponent, read from the light's extras (0: even inside the cone).
      light.exponent = float(std::max(0.0, jsonNumberOr(jsonMember(chosen, "extras"), "spotExponent", 0.0)));
    }
  } else if (type != "directional") {
    return;
  }
  const nlohmann::json& colour = jsonMember(chosen, "color");
  if (colour.is_array() && colour.size() == 3 && colour[0].is_number() && colour[1].is_number() && colour[2].is_number())
    light.colour = {colour[0].get<float>(), colour[1].get<float>(), colour[2].get<float>()};
  scene.fileLight = light;
}

void growBounds(Scene& scene, const Instance& instance, bool& first) {
  const glb::Attribute* position = scene.primitive(instance).find("POSITION");
  if (!position) return;
  const std::vector<float> p = position->toFloats();
  for (std::size_t v = 0; v + 2 < p.size(); v += 3) {
    const Vec3 w = transformPoint(instance.world, {p[v], p[v + 1], p[v + 2]});
    for (int k = 0; k < 3; ++k) {
      scene.boundsMin[k] = first ? w[k] : std::min(scene.boundsMin[k], w[k]);
      scene.boundsMax[k] = first ? w[k] : std::max(scene.boundsMax[k], w[k]);
    }
    first = false;
  }
}

Status addPackage(Scene& scene, glb::Package package, const std::string& file, bool& firstPoint) {
  const std::size_t index = scene.packages.size();
  scene.packages.push_back(std::move(package));
  scene.files.push_back(file);
  const glb::Package& stored = scene.packages.back();
  return glb::forEachNode(stored, file, [&](const glb::Node& node, const glb::WorldMatrix& world) {
    takeCamera(stored, node, world, scene);
    takeLight(stored, node, world, scene);
    if (node.mesh < 0) return;
    for (std::size_t p = 0; p < stored.meshes[std::size_t(node.mesh)].primitives.size(); ++p) {
      scene.instances.push_back({index, std::size_t(node.mesh), p, fromDoubles(world)});
      growBounds(scene, scene.instances.back(), firstPoint);
    }
  });
}

Result<Vec3> parseVector(const std::string& text, const std::string& what) {
  BAKE_ASSIGN_OR_RETURN(const auto v, parseTriple(text, what));
  return Vec3{float(v[0]), float(v[1]), float(v[2])};
}

}  // namespace

const glb::Primitive& Scene::primitive(const Instance& instance) const {
  return packages[instance.package].meshes[instance.mesh].primitives[instance.primitive];
}

const nlohmann::json& Scene::material(const Instance& instance) const {
  static const nlohmann::json none;
  const int index = primitive(instance).material;
  const nlohmann::json& materials = packages[instance.package].materials;
  return index >= 0 && std::size_t(index) < materials.size() ? materials[std::size_t(index)] : none;
}

std::string Scene::technique(const Instance& instance) const {
  const nlohmann::json& m = material(instance);
  if (!m.is_object() || !m.contains("extensions") || !m["extensions"].is_object()) return "";
  for (const auto& [name, body] : m["extensions"].items()) {
    if (name.rfind(format::glb::kVendorExtensionPrefix, 0) == 0) return name;
  }
  return "";
}

Result<Scene> loadScene(const std::vector<std::filesystem::path>& files, Diagnostics& diagnostics,
                        const std::function<bool(const std::string&)>& isKnownTechnique) {
  Scene scene;
  bool firstPoint = true;
  for (const auto& file : files) {
    BAKE_ASSIGN_OR_RETURN(glb::Package package, glb::read(file));
    BAKE_RETURN_IF_ERROR(checkExtensions(package, file.string(), diagnostics, isKnownTechnique));
    BAKE_RETURN_IF_ERROR(addPackage(scene, std::move(package), file.string(), firstPoint));
  }
  if (scene.instances.empty()) return invalidInput("the scene has nothing to draw (no mesh instances)");
  if (scene.fileLight) aimAtScene(*scene.fileLight, scene);
  return scene;
}

Camera frameBounds(const Scene& scene, float aspect) {
  const Vec3 centre = (scene.boundsMin + scene.boundsMax) * 0.5f;
  const float radius = std::max(length(scene.boundsMax - scene.boundsMin) * 0.5f, 1e-6f);
  Camera camera;
  const float fit = radius / std::sin(camera.yfov / 2) / std::min(1.0f, aspect);
  const Vec3 direction = normalize(Vec3{0.55f, 0.45f, 0.75f});
  camera.target = centre;
  camera.eye = centre + direction * (fit * 1.05f);
  camera.znear = std::max(fit - radius * 1.5f, fit * 1e-3f);
  camera.zfar = fit + radius * 1.5f;
  return camera;
}

Result<Camera> parseCamera(const std::string& text, const Scene& scene, float aspect) {
  Camera camera = frameBounds(scene, aspect);
  const std::size_t colon = text.find(':');
  BAKE_ASSIGN_OR_RETURN(camera.eye, parseVector(text.substr(0, colon), "--camera eye"));
  if (colon != std::string::npos) {
    BAKE_ASSIGN_OR_RETURN(camera.target, parseVector(text.substr(colon + 1), "--camera target"));
  }
  if (length(camera.eye - camera.target) == 0) return usageError("--camera: the eye and the target coincide");
  const float reach = length(camera.eye - camera.target) + length(scene.boundsMax - scene.boundsMin);
  camera.znear = reach * 1e-4f;
  camera.zfar = reach * 2;
  return camera;
}

Result<Light> parseLight(const std::string& text) {
  Light light;
  const auto parts = [&] {
    std::vector<std::string> out;
    std::stringstream stream(text);
    for (std::string part; std::getline(stream, part, ':');) out.push_back(part);
    return out;
  }();
  const std::string kind = parts.empty() ? "" : parts[0];
  if (kind != "point" && kind != "spot") {
    BAKE_ASSIGN_OR_RETURN(light.direction, parseVector(text, "--light"));
    if (length(light.direction) == 0) return usageError("--light: the direction is zero");
    light.direction = normalize(light.direction);
    return light;
  }
  const bool counted = kind == "point" ? parts.size() == 2 : parts.size() == 4 || parts.size() == 5;
  if (!counted)
    return usageError("--light \"" + text + "\": expected point:X,Y,Z or spot:X,Y,Z:DX,DY,DZ:CUTOFF_DEGREES[:EXPONENT]");
  light.kind = kind == "point" ? LightKind::Point : LightKind::Spot;
  BAKE_ASSIGN_OR_RETURN(light.position, parseVector(parts[1], "--light"));
  light.direction = length(light.position) > 0 ? normalize(light.position) : Vec3{0, 0, 1};
  if (kind == "point") return light;
  BAKE_ASSIGN_OR_RETURN(light.spotDirection, parseVector(parts[2], "--light"));
  if (length(light.spotDirection) == 0) return usageError("--light: the spot's direction is zero");
  light.spotDirection = normalize(light.spotDirection);
  double cutoff = 0;
  if (!parseCsvNumber(parts[3], cutoff) || !(cutoff > 0 && cutoff <= 90))
    return usageError("--light: the spot's cut-off \"" + parts[3] + "\" must be an angle in degrees, above 0 and at most 90");
  light.cutoff = float(cutoff * 3.14159265358979323846 / 180);
  if (parts.size() == 5) {
    double exponent = 0;
    if (!parseCsvNumber(parts[4], exponent) || !(exponent >= 0 && exponent <= 128))
      return usageError("--light: the spot's exponent \"" + parts[4] + "\" must be a number from 0 to 128");
    light.exponent = float(exponent);
  }
  return light;
}

void aimAtScene(Light& light, const Scene& scene) {
  if (light.kind == LightKind::Directional) return;
  const Vec3 toLight = light.position - (scene.boundsMin + scene.boundsMax) * 0.5f;
  if (length(toLight) > 0) light.direction = normalize(toLight);
}

}  // namespace bake::play
