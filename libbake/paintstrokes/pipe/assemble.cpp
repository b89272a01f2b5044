// Assembly rules for paintstroke objects (formats/paintstrokes.md). The material's BAKE_paintstrokes
// object names its four arrays (strokes, points, styles, shadows) by bufferView, each at a multiple
// of 256 bytes. The package is decoded with the checked reader first. When the scene's material does
// not read shadows, the self-shadowing table becomes empty as the format stores it (no directions,
// the shadows array one zeroed byte with count 0), so the strokes are drawn unshadowed; the old table
// is left unreferenced (copied unreferenced when unused data are kept).
#include <bake_formats/paintstrokes.h>

#include "paintstrokes/package/package.h"
#include "paintstrokes/pipe/pipe.h"
#include "pipe/assemble_parts.h"

namespace bake::paintstrokes::assembly {

using namespace pipe::detail;

namespace {

using nlohmann::json;
namespace fmt = format::paintstrokes;

void removeShadows(glb::Package& package, json& extension) {
  package.blobs.push_back(glb::Blob{std::vector<std::uint8_t>(1, 0), fmt::kBufferAlignment});
  extension[fmt::kBufferViews][fmt::kShadows] = int(package.blobs.size() - 1);
  extension[fmt::kCounts][fmt::kShadows] = 0;
  extension["shadowDirections"] = json::array();
}

Status adaptPaintstrokes(glb::Package& package, const ObjectInput& input) {
  const int index = materialWith(package, fmt::kExtension);
  if (index < 0) return input.error(std::string("not a paintstrokes package (no material carries ") + fmt::kExtension + ")");
  auto decoded = decodePaintstrokePackage(package, input.file);
  if (!decoded.isOk())
    return Status(decoded.status().code(), "object '" + input.object.name + "': " + decoded.status().message(),
                  decoded.status().where());
  json& material = package.materials[std::size_t(index)];
  material["name"] = input.material.name;
  if (input.material.readsShadows || decoded->shadowDirections.empty()) return {};
  if (!input.keepUnused)
    input.drop("self-shadowing table (" + std::to_string(decoded->shadowDirections.size()) + " directions, " +
               std::to_string(decoded->shadows.size()) + " values)");
  removeShadows(package, material["extensions"][fmt::kExtension]);
  return {};
}

}  // namespace
}  // namespace bake::paintstrokes::assembly

namespace bake::paintstrokes {

const pipe::detail::TechniqueRules& assembleRules() {
  using namespace assembly;
  static const TechniqueRules rules{.extension = fmt::kExtension,
                                    .blobAlignment = fmt::kBufferAlignment,
                                    .adapt = adaptPaintstrokes,
                                    .bufferViews = {fmt::kBufferViews, fmt::kArrayKeys}};
  return rules;
}

}  // namespace bake::paintstrokes
