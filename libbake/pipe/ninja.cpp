// Ninja file writer (pipe/ninja.h). Placeholder.
#include "pipe/ninja.h"

namespace bake::pipe {

std::string ninjaFile(const Scene&, const Plan&, const NinjaSettings&) { return {}; }

}  // namespace bake::pipe
