// Assembly rules for revolution objects (formats/revolution.md). The material's BAKE_revolution
// object names its shape, displacement and arc-length maps by bufferView; the base colour is the
// standard pbrMetallicRoughness.baseColorTexture (texture -> image -> bufferView, renumbered by the
// generic merge). The baked material stays, named after the scene's; a displacement map or base
// colour texture the scene's material does not read is unreferenced, so the merge leaves it out (or,
// keeping unused data, copies it unreferenced). The arc-length map stays: it places both maps.
#include <bake_formats/revolution.h>

#include "pipe/assemble_parts.h"
#include "revolution/pipe/pipe.h"

namespace bake::revolution::assembly {

using namespace pipe::detail;

namespace {

using nlohmann::json;
namespace fmt = format::revolution;

constexpr const char* kMapKeys[] = {fmt::kShapeMap, fmt::kDisplacementMap, fmt::kArcLengthMap};

Status adaptRevolution(glb::Package& package, const ObjectInput& input) {
  const int index = materialWith(package, fmt::kExtension);
  if (index < 0) return input.error(std::string("not a revolution package (no material carries ") + fmt::kExtension + ")");
  json& material = package.materials[std::size_t(index)];
  json& extension = material["extensions"][fmt::kExtension];
  material["name"] = input.material.name;

  if (!input.material.readsDisplacement && extension.contains(fmt::kDisplacementMap)) {
    const int view = indexAt(extension[fmt::kDisplacementMap], fmt::kBufferView);
    if (!input.keepUnused) input.drop("displacement map (bufferView " + std::to_string(view) + ")");
    extension.erase(fmt::kDisplacementMap);
  }
  json& pbr = material["pbrMetallicRoughness"];
  if (!input.material.readsBaseColor && pbr.is_object() && pbr.contains("baseColorTexture")) {
    const int texture = indexAt(pbr["baseColorTexture"], "index");
    if (!input.keepUnused) input.drop("base colour texture (texture " + std::to_string(texture) + ")");
    pbr.erase("baseColorTexture");
  }
  if (pbr.is_null()) material.erase("pbrMetallicRoughness");
  return {};
}

ExtensionReferences revolutionReferences(const json& extension) {
  ExtensionReferences references;
  for (const char* key : kMapKeys)
    if (extension.contains(key)) references.blobs.push_back(indexAt(extension[key], fmt::kBufferView));
  return references;
}

void renumberRevolution(json& extension, const Renumbering& renumbering) {
  for (const char* key : kMapKeys)
    if (extension.contains(key))
      extension[key][fmt::kBufferView] = Renumbering::at(renumbering.blobs, indexAt(extension[key], fmt::kBufferView));
}

}  // namespace
}  // namespace bake::revolution::assembly

namespace bake::revolution {

const pipe::detail::TechniqueRules& assembleRules() {
  using namespace assembly;
  static const TechniqueRules rules{.extension = fmt::kExtension,
                                    .blobAlignment = 16,
                                    .adapt = adaptRevolution,
                                    .references = revolutionReferences,
                                    .renumber = renumberRevolution};
  return rules;
}

}  // namespace bake::revolution
