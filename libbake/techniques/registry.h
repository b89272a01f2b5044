// The technique registry: one row per technique with everything the layers above the bakers need to
// know of it (its name, glTF extension and baker; the package reader's loader checks that `bakeplay
// validate` and the runtime run; what bakeinfo says of its data; its scene pipeline hooks), found by
// name or by extension.
// The built-in rows come from techniques.def; a test can add a toy technique through add().
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "bake/core/status.h"
#include "bake/io/glb.h"

namespace bake::pipe {
struct TechniqueHooks;  // pipe/technique_hooks.h
}

namespace bake::techniques {

struct Technique {
  std::string name;       // the one name in every layer: BAKE_<name>, scene files' "technique"
  std::string extension;  // the glTF extension its materials carry
  std::string tool;       // the baker that writes its packages
  // The package reader's loader checks: every material that carries the extension reads and the
  // primitives drawn with it carry what it needs; `file` names the package in errors. A package
  // without the extension passes.
  std::function<Status(const glb::Package& package, const std::string& file)> checkPackage;
  // What bakeinfo adds about the technique's data in a package that uses it; empty: nothing beyond
  // the glTF summary.
  std::function<Result<nlohmann::json>(const glb::Package& package, const std::string& file)> describe;
  // bakeinfo's text lines for that description (each ending in a newline).
  std::function<std::string(const nlohmann::json& description)> formatDescription;
  // What scene files may say of its objects, how bakepipe plans and assembles them; null: scene
  // files do not offer the technique.
  const pipe::TechniqueHooks* pipe = nullptr;
};

// Every technique, built-in ones first in techniques.def order.
const std::vector<Technique>& all();
const Technique* byName(std::string_view name);
const Technique* byExtension(std::string_view extension);
// Adds a technique (tests: a toy technique); a name or extension already registered is an error.
// Adding moves the rows: pointers and references from all(), byName() and byExtension() taken before
// no longer hold. Not thread-safe; add before any other thread reads the registry.
Status add(Technique technique);

// Whether the package (at its root) or a material of it carries the technique's extension.
bool usedBy(const Technique& technique, const glb::Package& package);
// The indices of the package's materials that carry `extension` (what a technique's describe reads).
std::vector<std::size_t> materialsWith(const glb::Package& package, std::string_view extension);

// The built-in rows, defined by each technique's module.
#define BAKE_TECHNIQUE(name) Technique name##Technique();
#include "techniques/techniques.def"
#undef BAKE_TECHNIQUE

}  // namespace bake::techniques
