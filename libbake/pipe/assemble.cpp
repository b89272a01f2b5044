// Scene assembly (pipe/assemble.h). Placeholder until the merge lands.
#include "pipe/assemble.h"

namespace bake::pipe {

Result<glb::Package> assemble(const Scene&, const std::vector<std::filesystem::path>&, const AssembleSettings&,
                              AssembleReport*) {
  return unsupported("bakepipe assemble is not implemented yet");
}

}  // namespace bake::pipe
