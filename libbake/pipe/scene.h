// Scene descriptions (formats/scene.md): the objects of a scene, the authoring input and technique of
// each, the materials and what baked data each reads, and the cameras that bound the screen size.
// The reader checks what the schema says and what it cannot (unique names, materials that exist and
// match the object's technique, geodesic field names that exist in the object's sources file) and
// names the element at fault; what an object or material of one technique may say is that
// technique's (pipe/technique_hooks.h).
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bake/core/status.h"

namespace bake::pipe {

// A file made by bakeshape before any bake.
struct Generated {
  std::string output;  // file name in the output directory
  std::string shape;
  std::optional<int> resolution;
};

// A path as the scene gives it, resolved: either a file beside the scene or a generated file.
struct InputPath {
  std::filesystem::path path;  // absolute for a source file; the bare file name for a generated one
  bool generated = false;
};

struct Object {
  std::string name;
  std::string technique;  // a registry name (techniques/registry.h) whose row has scene hooks
  InputPath input;
  std::optional<InputPath> sources;    // geodesic
  std::optional<InputPath> mesh;       // hatching (required), grooves (optional: else the preview plane)
  std::optional<InputPath> baseColor;  // revolution
  std::optional<InputPath> heightMap;  // revolution
  nlohmann::json options = nlohmann::json::object();  // as the scene gives them (formats/scene.md)
  std::array<double, 3> position{0, 0, 0};
  std::array<double, 4> rotation{0, 0, 0, 1};  // unit quaternion x, y, z, w (glTF's)
  double scale = 1;
  std::size_t material = 0;  // index into Scene::materials
  // Geodesic: the field names of the sources file, in file order.
  std::vector<std::string> fieldNames;
};

struct Material {
  std::string name;
  std::string technique;
  // Geodesic: the BAKE_geodesic material object with "fields" as names (empty: the first field).
  nlohmann::json geotexture = nlohmann::json::object();
  std::vector<std::string> fields;
  bool readsBaseColor = true;
  bool readsDisplacement = true;
  bool readsThreshold = false;
  bool readsSpecialCases = true;
  bool readsShadows = true;
};

struct Camera {
  std::string name;
  std::array<double, 3> eye{0, 0, 5};
  std::array<double, 3> target{0, 0, 0};
  double yfovDegrees = 45;
  int width = 1024;
  int height = 768;
};

// A light of the assembled scene (KHR_lights_punctual): directional (shining from `position` toward
// `target`), point (at `position`) or spot (at `position`, toward `target`, the cone's half-angle
// `cutoffDegrees` and OpenGL's falloff exponent, kept in the light's extras.spotExponent).
struct SceneLight {
  std::string name;
  std::string type = "directional";
  std::array<double, 3> position{0, 5, 5};
  std::array<double, 3> target{0, 0, 0};
  std::array<double, 3> colour{1, 1, 1};
  double intensity = 1;
  double cutoffDegrees = 45;
  double exponent = 0;
};

struct Scene {
  std::filesystem::path file;       // the scene file, absolute
  std::filesystem::path directory;  // its directory: relative paths start here
  std::string name;
  std::vector<Generated> generated;
  std::vector<Object> objects;
  std::vector<Material> materials;
  std::vector<Camera> cameras;
  std::vector<SceneLight> lights;
  std::optional<std::array<double, 2>> pixelsPerUnit;  // explicit [min, max]

  const Material& materialOf(const Object& object) const { return materials[object.material]; }
  // The geodesic field names the object's material reads (its sources' first field by default).
  std::vector<std::string> fieldsRead(const Object& object) const;
};

Result<Scene> readScene(const std::filesystem::path& path);
Result<Scene> parseScene(const nlohmann::json& document, const std::filesystem::path& path);

}  // namespace bake::pipe
