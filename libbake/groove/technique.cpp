// The grooves technique's row in the registry (techniques/registry.h): the groove grids groovebake
// writes.
#include <bake_formats/grooves.h>

#include "groove/package/package.h"
#include "techniques/registry.h"

namespace bake::techniques {

Technique groovesTechnique() {
  return {"grooves", format::grooves::kExtension, "groovebake", groove::checkGroovesPackage, {}, {}};
}

}  // namespace bake::techniques
