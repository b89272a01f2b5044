// GLB packages as the runtime reads them: glb::decode (glTF JSON, buffers, accessors, Draco), then
// the BAKE_* extension readers that need no GL context: libbake's groove and paintstroke package
// decoders and the runtime's loader checks of BAKE_geodesic, BAKE_revolution, BAKE_hatching (with
// its embedded KTX2 levels) and BAKE_grooves, which `bakeplay validate` runs.
#include <span>

#include "groove/package.h"
#include "io/glb.h"
#include "render/geodesic.h"
#include "render/grooves.h"
#include "render/hatching.h"
#include "render/revolution.h"
#include "strokes/package.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  bake::Result<bake::glb::Package> package = bake::glb::decode(std::span<const std::uint8_t>(data, size), "fuzz.glb");
  if (!package.isOk()) return 0;
  (void)bake::groove::decodeGroovePackage(*package, "fuzz.glb");
  (void)bake::strokes::decodePaintstrokePackage(*package, "fuzz.glb");
  (void)bake::play::checkGeodesicPackage(*package, "fuzz.glb");
  (void)bake::play::checkRevolutionPackage(*package, "fuzz.glb");
  (void)bake::play::checkHatchingPackage(*package, "fuzz.glb");
  (void)bake::play::checkGroovesPackage(*package, "fuzz.glb");
  return 0;
}
