// Assembly rules for groove objects (formats/grooves.md). The material's BAKE_grooves object names
// its arrays (ten, twelve from version 2 with the far level) by bufferView ("bufferViews") and gives their item counts ("counts"); each array
// starts at a multiple of 256 bytes. When the scene's material does not read special cases, the
// record arrays become empty as the format stores them: `records` and `recordRefs` one zeroed item
// with count 0, `recordStart` all zero (cells + 1 of them), so every cell lists no record and the
// shader line-samples everywhere. The package is decoded with the checked reader first.
#include <bake_formats/grooves.h>

#include "grooves/package/package.h"
#include "grooves/pipe/pipe.h"
#include "pipe/assemble_parts.h"

namespace bake::grooves::assembly {

using namespace pipe::detail;

namespace {

using nlohmann::json;
namespace fmt = format::grooves;

// A new blob of `bytes` zeros at the format's alignment; its index.
int addZeroBlob(glb::Package& package, std::size_t bytes) {
  package.blobs.push_back(glb::Blob{std::vector<std::uint8_t>(bytes, 0), fmt::kBufferAlignment});
  return int(package.blobs.size() - 1);
}

// Points the record arrays at empty ones (new blobs; the old ones are left unreferenced).
void removeRecords(glb::Package& package, json& extension, std::uint64_t cells) {
  json& views = extension[fmt::kBufferViews];
  views[fmt::kRecords] = addZeroBlob(package, sizeof(fmt::Record));
  views[fmt::kRecordRefs] = addZeroBlob(package, sizeof(std::uint32_t));
  views[fmt::kRecordStart] = addZeroBlob(package, (cells + 1) * sizeof(std::uint32_t));
  extension[fmt::kCounts][fmt::kRecords] = 0;
  extension[fmt::kCounts][fmt::kRecordRefs] = 0;
}

Status adaptGrooves(glb::Package& package, const ObjectInput& input) {
  const int index = materialWith(package, fmt::kExtension);
  if (index < 0) return input.error(std::string("not a grooves package (no material carries ") + fmt::kExtension + ")");
  auto decoded = grooves::decodeGroovePackage(package, input.file);
  if (!decoded.isOk())
    return Status(decoded.status().code(), "object '" + input.object.name + "': " + decoded.status().message(),
                  decoded.status().where());
  json& material = package.materials[std::size_t(index)];
  material["name"] = input.material.name;
  if (input.material.readsSpecialCases) return {};
  json& extension = material["extensions"][fmt::kExtension];
  if (decoded->records.empty()) {
    input.keep("no special-case records to leave out (the pattern has none)");
    return {};
  }
  if (!input.keepUnused)
    input.drop("special-case records (" + std::to_string(decoded->records.size()) + " records, " +
               std::to_string(decoded->recordRefs.size()) + " cell references)");
  removeRecords(package, extension, std::uint64_t(decoded->header.cells[0]) * decoded->header.cells[1]);
  return {};
}

}  // namespace
}  // namespace bake::grooves::assembly

namespace bake::grooves {

const pipe::detail::TechniqueRules& assembleRules() {
  using namespace assembly;
  static const TechniqueRules rules{.extension = fmt::kExtension,
                                    .blobAlignment = fmt::kBufferAlignment,
                                    .adapt = adaptGrooves,
                                    .bufferViews = {fmt::kBufferViews, fmt::kArrayKeys}};
  return rules;
}

}  // namespace bake::grooves
