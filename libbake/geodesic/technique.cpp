// The geodesic technique's row in the registry (techniques/registry.h): GeoTextures over the
// per-vertex distance fields geobake writes.
#include <bake_formats/geodesic.h>

#include "geodesic/package/package_read.h"
#include "geodesic/pipe/pipe.h"
#include "techniques/registry.h"

namespace bake::techniques {

Technique geodesicTechnique() {
  return {"geodesic", format::geodesic::kExtension, "geobake", geodesic::checkGeodesicPackage, {}, {}, &geodesic::pipeHooks()};
}

}  // namespace bake::techniques
