// The hatching technique's row in the registry (techniques/registry.h): the tonal art maps tambake
// writes, drawn by real-time hatching.
#include <bake_formats/tam.h>

#include "hatching/package/package_read.h"
#include "hatching/pipe/pipe.h"
#include "techniques/registry.h"

namespace bake::techniques {

Technique hatchingTechnique() {
  return {"hatching", format::tam::kExtension, "tambake", hatching::checkHatchingPackage, {}, {}, &hatching::pipeHooks()};
}

}  // namespace bake::techniques
