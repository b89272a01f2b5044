// A scene as the runtime sees it: the packages given on the command line (several files make one
// scene), every mesh instance placed in world space, a camera and a light (from the files, from the
// command line, or framed automatically), and which BAKE_* extensions appear where. Loading is pure
// CPU work, so scenes can be checked without a GL context.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "bake/core/diagnostics.h"
#include "bake/core/status.h"
#include "bake/io/glb.h"
#include "scene/math.h"

namespace bake::play {

struct Camera {
  Vec3 eye{0, 0, 3};
  Vec3 target{0, 0, 0};
  Vec3 up{0, 1, 0};
  float yfov = 0.7f;  // radians
  float znear = 0.01f;
  float zfar = 100.0f;
};

// A light of KHR_lights_punctual. Techniques that take one direction use `direction`; hatching (seed
// 004 §3.2) also takes point and spot lights as they are: the direction to the light per triangle
// from its position, and the spot's cut-off and exponent.
enum class LightKind { Directional, Point, Spot };

struct Light {
  Vec3 direction{0.4f, 0.8f, 0.45f};  // towards the light, world space (point, spot: from the scene's centre)
  Vec3 colour{1, 1, 1};
  LightKind kind = LightKind::Directional;
  Vec3 position{0, 0, 0};        // point, spot: world space
  Vec3 spotDirection{0, 0, -1};  // spot: the way it shines, unit
  float cutoff = 0.7853982f;     // spot: half-angle of the cone in radians (KHR outerConeAngle)
  float exponent = 0;            // spot: falloff (cos of the angle off the axis)^exponent inside the cone
  // Constant radiance of the rest of the scene: grooves' mirror bounces that leave the surface see it
  // (seed 000 §7); black unless given.
  Vec3 environment{0, 0, 0};
};

struct Instance {
  std::size_t package = 0;
  std::size_t mesh = 0;
  std::size_t primitive = 0;
  Mat4 world = identity();
};

struct Scene {
  std::vector<std::string> files;
  std::vector<glb::Package> packages;
  std::vector<Instance> instances;
  Vec3 boundsMin{0, 0, 0}, boundsMax{0, 0, 0};
  std::optional<Camera> fileCamera;
  std::optional<Light> fileLight;

  const glb::Primitive& primitive(const Instance& instance) const;
  // The material JSON of an instance (null when it has none).
  const nlohmann::json& material(const Instance& instance) const;
  // The BAKE_* extension of an instance's material, or "" for standard shading.
  std::string technique(const Instance& instance) const;
};

// Several files make one scene. `isKnownTechnique` says whether a BAKE_* extension has a registered
// renderer: an unknown one is a warning, or an error when the file lists it in extensionsRequired.
Result<Scene> loadScene(const std::vector<std::filesystem::path>& files, Diagnostics& diagnostics,
                        const std::function<bool(const std::string&)>& isKnownTechnique);

// The bundled example scene shown when no file is given (a lit torus knot, built in code).
Scene defaultScene();

// A camera that frames the scene's bounds from a pleasant three-quarter view.
Camera frameBounds(const Scene& scene, float aspect);

// "x,y,z" or "x,y,z:tx,ty,tz" (eye, then optional target).
Result<Camera> parseCamera(const std::string& text, const Scene& scene, float aspect);
// "x,y,z": direction towards the light; "point:x,y,z" a point light there; "spot:x,y,z:dx,dy,dz:
// cutoff[:exponent]" a spot light there shining along (dx, dy, dz), cut-off in degrees.
Result<Light> parseLight(const std::string& text);
// A point or spot light's `direction` (for the techniques that take one): from the scene's centre
// toward the light.
void aimAtScene(Light& light, const Scene& scene);

}  // namespace bake::play
