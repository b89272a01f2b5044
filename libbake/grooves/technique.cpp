// The grooves technique's row in the registry (techniques/registry.h): the groove grids groovebake
// writes.
#include <bake_formats/grooves.h>

#include "grooves/package/package.h"
#include "grooves/pipe/pipe.h"
#include "techniques/registry.h"

namespace bake::techniques {

Technique groovesTechnique() {
  return {"grooves", format::grooves::kExtension, "groovebake", grooves::checkGroovesPackage, {}, {}, &grooves::pipeHooks()};
}

}  // namespace bake::techniques
