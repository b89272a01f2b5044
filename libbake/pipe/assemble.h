// Merges the baked packages of a scene into one scene package (formats/scene.md, "What the plan
// leaves out"): each object's nodes under one node named after it, placed by the scene's position,
// rotation and scale; its material replaced by the scene's; meshes, materials, images, textures and blobs
// renumbered; and, unless asked to keep them, the data no material reads not copied: unread geodesic
// fields, an unread displacement map or base colour, an unread threshold texture, special-case
// records a material does not read. Per-technique rules live in each module's pipe/assemble.cpp.
//
// Cameras and KHR_lights_punctual lights of the packages are not copied (the scene's cameras frame
// the view; each omission is listed). Meshes are written uncompressed, whatever the packages used.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "bake/core/status.h"
#include "bake/io/glb.h"
#include "pipe/scene.h"

namespace bake::pipe {

struct AssembleSettings {
  bool keepUnused = false;
};

struct AssembleReport {
  std::vector<std::string> dropped;  // "pretzel: field 'rims' (_GEODESIC_2)", ...
  std::vector<std::string> kept;     // unread data that had to stay, and why
  std::uint64_t inputBytes = 0;      // the packages' sizes
};

// packages[i] is the package of scene.objects[i].
Result<glb::Package> assemble(const Scene& scene, const std::vector<std::filesystem::path>& packages,
                              const AssembleSettings& settings, AssembleReport* report = nullptr);

}  // namespace bake::pipe
