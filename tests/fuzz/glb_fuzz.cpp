// GLB packages as the runtime reads them: glb::decode (glTF JSON, buffers, accessors, Draco), then
// every technique's package reader through the registry (libbake/techniques/registry.h): the loader
// checks `bakeplay validate` and the runtime run (BAKE_hatching with its embedded KTX2 levels), and
// the describers of bakeinfo.
#include <span>

#include "bake/io/glb.h"
#include "techniques/registry.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  bake::Result<bake::glb::Package> package = bake::glb::decode(std::span<const std::uint8_t>(data, size), "fuzz.glb");
  if (!package.isOk()) return 0;
  for (const bake::techniques::Technique& technique : bake::techniques::all()) {
    (void)technique.checkPackage(*package, "fuzz.glb");
    if (technique.describe && bake::techniques::usedBy(technique, *package)) (void)technique.describe(*package, "fuzz.glb");
  }
  return 0;
}
