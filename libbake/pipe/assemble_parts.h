// The parts of scene assembly (pipe/assemble.h) shared by the generic merge (assemble.cpp) and the
// per-technique rules (<module>/pipe/assemble.cpp, which the technique's scene hooks point at): what
// an object's package is adapted against, how the indices a technique's extension holds are found
// and renumbered, and the shape of a technique's rules.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bake/core/status.h"
#include "bake/io/glb.h"
#include "pipe/assemble.h"
#include "pipe/scene.h"

namespace bake::pipe::detail {

// One object being assembled: its scene entry, the scene's material for it, its package file.
struct ObjectInput {
  const Scene& scene;
  const Object& object;
  const Material& material;
  std::string file;
  bool keepUnused = false;
  AssembleReport& report;

  // "OBJECT: WHAT" in the dropped list.
  void drop(const std::string& what) const { report.dropped.push_back(object.name + ": " + what); }
  void keep(const std::string& whatAndWhy) const { report.kept.push_back(object.name + ": " + whatAndWhy); }
  // An invalid-input error naming the package file and the object.
  Status error(const std::string& message) const;
};

// Indices (in the package's own numbering) that one material extension points at.
struct ExtensionReferences {
  std::vector<int> blobs, images, textures;
};

// Old index -> new index in the assembled package, -1 for what was not copied.
struct Renumbering {
  std::vector<int> blobs, images, textures, samplers;

  static int at(const std::vector<int>& map, int old) {
    return old >= 0 && std::size_t(old) < map.size() ? map[std::size_t(old)] : -1;
  }
};

// An extension that names each of its arrays by bufferView under one object, {VIEWS: {KEY: index}}
// (grooves, paintstrokes): its references are those indices.
struct BufferViewTable {
  const char* viewsKey = nullptr;  // null: the technique has no such table
  std::span<const char* const> arrayKeys;

  ExtensionReferences references(const nlohmann::json& extension) const;
  void renumber(nlohmann::json& extension, const Renumbering& renumbering) const;
};

// How one technique's packages are assembled.
struct TechniqueRules {
  const char* extension;            // BAKE_<technique>
  std::uint32_t blobAlignment = 16;  // offset alignment of the package's data in the binary chunk
  // Checks that the package is this technique's, makes its material the scene's and, unless
  // keepUnused, removes what that material does not read (each removal reported). Data the material
  // stops referencing need not be removed from the package: the merge copies only what is referenced.
  Status (*adapt)(glb::Package& package, const ObjectInput& input);
  // The indices a material's extension object holds (with bufferViews below, not needed).
  ExtensionReferences (*references)(const nlohmann::json& extension) = nullptr;
  // Rewrites those indices to the assembled package's.
  void (*renumber)(nlohmann::json& extension, const Renumbering& renumbering) = nullptr;
  // Merges the technique's root extension object (when it has one) into the assembled package's.
  Status (*mergeRoot)(nlohmann::json& assembledExtensions, const glb::Package& package, const ObjectInput& input) =
      nullptr;
  // Indices held in a bufferView table, found and renumbered besides those of the two hooks above.
  BufferViewTable bufferViews{};
};

// All the indices `rules` find in a material's extension object, and their renumbering.
ExtensionReferences referencesOf(const TechniqueRules& rules, const nlohmann::json& extension);
void renumberReferences(const TechniqueRules& rules, nlohmann::json& extension, const Renumbering& renumbering);

// Whether a material JSON carries `extension` as an object.
bool hasExtension(const nlohmann::json& material, const char* extension);
// The index of the first material carrying `extension`, or -1.
int materialWith(const glb::Package& package, const char* extension);

// The integer at `object[key]`, or -1 when it is missing or not an integer.
int indexAt(const nlohmann::json& object, const char* key);

}  // namespace bake::pipe::detail
