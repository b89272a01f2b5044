// glTF 2.0 input for meshes (see io/glb.h for our packages): flattens every mesh instance of the
// default scene into one triangle mesh in world space, keeping named nodes as named points.
#pragma once

#include <filesystem>

#include "bake/core/status.h"
#include "bake/io/mesh.h"

namespace bake {

// `nearOrigin`: see MeshReadOptions::nearOrigin (world positions are computed in double either way).
Result<TriangleMesh> readGltfMesh(const std::filesystem::path& path, MeshReadStats* stats = nullptr,
                                  bool nearOrigin = false);

}  // namespace bake
