// The revolution technique's row in the registry (techniques/registry.h): shape maps revolbake writes.
#include <bake_formats/revolution.h>

#include "revolution/package/package_read.h"
#include "revolution/pipe/pipe.h"
#include "techniques/registry.h"

namespace bake::techniques {

Technique revolutionTechnique() {
  return {"revolution", format::revolution::kExtension, "revolbake", revolution::checkRevolutionPackage, {}, {}, &revolution::pipeHooks()};
}

}  // namespace bake::techniques
