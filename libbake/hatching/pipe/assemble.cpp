// Assembly rules for hatching objects (formats/tam.md). The material's BAKE_hatching object names the
// tonal art map and the optional threshold texture by image index (each image embedded in a
// bufferView as KTX2). The baked material stays, named after the scene's; a threshold texture the
// scene's material does not read (bakeplay blends tones and never does) is unreferenced, so the merge
// leaves it out, or copies it unreferenced when unused data are kept.
#include <bake_formats/tam.h>

#include "hatching/pipe/pipe.h"
#include "pipe/assemble_parts.h"

namespace bake::hatching::assembly {

using namespace pipe::detail;

namespace {

using nlohmann::json;
namespace fmt = format::tam;

constexpr const char* kImageKeys[] = {fmt::kTamImage, fmt::kThresholdImage};

Status adaptHatching(glb::Package& package, const ObjectInput& input) {
  const int index = materialWith(package, fmt::kExtension);
  if (index < 0) return input.error(std::string("not a hatching package (no material carries ") + fmt::kExtension + ")");
  json& material = package.materials[std::size_t(index)];
  json& extension = material["extensions"][fmt::kExtension];
  material["name"] = input.material.name;
  if (!input.material.readsThreshold && extension.contains(fmt::kThresholdImage)) {
    if (!input.keepUnused)
      input.drop("threshold texture (image " + std::to_string(indexAt(extension, fmt::kThresholdImage)) + ")");
    extension.erase(fmt::kThresholdImage);
  }
  return {};
}

ExtensionReferences hatchingReferences(const json& extension) {
  ExtensionReferences references;
  for (const char* key : kImageKeys)
    if (extension.contains(key)) references.images.push_back(indexAt(extension, key));
  return references;
}

void renumberHatching(json& extension, const Renumbering& renumbering) {
  for (const char* key : kImageKeys)
    if (extension.contains(key)) extension[key] = Renumbering::at(renumbering.images, indexAt(extension, key));
}

}  // namespace
}  // namespace bake::hatching::assembly

namespace bake::hatching {

const pipe::detail::TechniqueRules& assembleRules() {
  using namespace assembly;
  static const TechniqueRules rules{.extension = fmt::kExtension,
                                    .blobAlignment = 16,
                                    .adapt = adaptHatching,
                                    .references = hatchingReferences,
                                    .renumber = renumberHatching};
  return rules;
}

}  // namespace bake::hatching
