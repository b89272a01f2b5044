#include "io/gltf.h"

namespace bake {

// Placeholder until the glTF mesh reader lands in this file.
Result<TriangleMesh> readGltfMesh(const std::filesystem::path& path, MeshReadStats*) {
  return unsupported("glTF mesh input is not implemented yet", {path.string(), ""});
}

}  // namespace bake
