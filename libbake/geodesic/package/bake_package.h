// The package of a geobake run: the mesh with its `_GEODESIC_k` attributes and the BAKE_geodesic
// description (formats/geodesic.md).
#pragma once

#include <vector>

#include "bake/io/glb.h"
#include "geodesic/bake/bake_stages.h"

namespace bake::geodesic {

glb::Package buildPackage(const TriangleMesh& mesh, const SurfaceBuild& build,
                          const std::vector<ResolvedField>& fields,
                          const std::vector<std::vector<double>>& distances,
                          const std::vector<FieldError>& errors, const Settings& settings);

}  // namespace bake::geodesic
