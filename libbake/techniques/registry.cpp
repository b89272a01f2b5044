#include "techniques/registry.h"

namespace bake::techniques {
namespace {

std::vector<Technique>& rows() {
  static std::vector<Technique> table = [] {
    std::vector<Technique> built;
#define BAKE_TECHNIQUE(name) built.push_back(name##Technique());
#include "techniques/techniques.def"
#undef BAKE_TECHNIQUE
    return built;
  }();
  return table;
}

}  // namespace

const std::vector<Technique>& all() { return rows(); }

const Technique* byName(std::string_view name) {
  for (const Technique& technique : rows())
    if (technique.name == name) return &technique;
  return nullptr;
}

const Technique* byExtension(std::string_view extension) {
  for (const Technique& technique : rows())
    if (technique.extension == extension) return &technique;
  return nullptr;
}

Status add(Technique technique) {
  if (technique.name.empty() || technique.extension.empty()) return internalError("a technique needs a name and an extension");
  if (byName(technique.name) || byExtension(technique.extension)) {
    return internalError("technique " + technique.name + " (" + technique.extension + ") is already registered");
  }
  rows().push_back(std::move(technique));
  return {};
}

std::vector<std::size_t> materialsWith(const glb::Package& package, std::string_view extension) {
  std::vector<std::size_t> indices;
  for (std::size_t m = 0; m < package.materials.size(); ++m) {
    const nlohmann::json& material = package.materials[m];
    if (material.is_object() && material.contains("extensions") && material["extensions"].is_object() &&
        material["extensions"].contains(extension))
      indices.push_back(m);
  }
  return indices;
}

bool usedBy(const Technique& technique, const glb::Package& package) {
  if (package.extensions.is_object() && package.extensions.contains(technique.extension)) return true;
  return !materialsWith(package, technique.extension).empty();
}

}  // namespace bake::techniques
