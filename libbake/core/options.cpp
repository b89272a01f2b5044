#include "bake/core/options.h"

#include "bake/core/version.h"

namespace bake {

const char* toolkitVersion() { return kToolkitVersion; }

}  // namespace bake
