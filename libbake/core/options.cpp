#include "core/options.h"

#include "core/version.h"

namespace bake {

const char* toolkitVersion() { return kToolkitVersion; }

}  // namespace bake
