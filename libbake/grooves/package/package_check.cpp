// Loader checks of BAKE_grooves for `bakeplay validate` (formats/grooves.md): a package whose material
// carries the extension must decode with libbake's reader, which trusts nothing (version, header,
// every array's size against its count and stride, the CSR prefix sums, every index an array holds),
// and every mesh primitive drawn with that material needs TEXCOORD_0 (the footprint comes from it).
#include <bake_formats/grooves.h>

#include "grooves/package/package.h"

namespace bake::grooves {

Status checkGroovesPackage(const glb::Package& package, const std::string& name) {
  std::vector<bool> carries(package.materials.size(), false);
  bool any = false;
  for (std::size_t m = 0; m < package.materials.size(); ++m) {
    const nlohmann::json& material = package.materials[m];
    carries[m] = material.is_object() && material.contains("extensions") && material["extensions"].is_object() &&
                 material["extensions"].contains(format::grooves::kExtension);
    any = any || carries[m];
  }
  if (!any) return {};
  for (std::size_t m = 0; m < package.materials.size(); ++m)  // an assembled scene has several
    if (carries[m])
      BAKE_RETURN_IF_ERROR(
          decodeGrooveExtension(package, package.materials[m]["extensions"][format::grooves::kExtension], name).status());
  for (std::size_t mesh = 0; mesh < package.meshes.size(); ++mesh) {
    for (std::size_t p = 0; p < package.meshes[mesh].primitives.size(); ++p) {
      const glb::Primitive& primitive = package.meshes[mesh].primitives[p];
      if (primitive.material < 0 || std::size_t(primitive.material) >= carries.size() || !carries[std::size_t(primitive.material)])
        continue;
      if (!primitive.find("TEXCOORD_0"))
        return invalidInput(std::string(format::grooves::kExtension) + " needs TEXCOORD_0 on the mesh drawn with it",
                            {name, "mesh " + std::to_string(mesh) + " primitive " + std::to_string(p)});
    }
  }
  return {};
}

}  // namespace bake::grooves
