// Walks the node hierarchy of a package's default scene (or, without a scene, every node that is no
// node's child), handing each node its world matrix. Cycles in the node graph are errors.
#pragma once

#include <array>
#include <functional>

#include "bake/core/status.h"
#include "bake/io/glb.h"

namespace bake::glb {

using WorldMatrix = std::array<double, 16>;  // column-major

WorldMatrix multiplyMatrices(const WorldMatrix& a, const WorldMatrix& b);

Status forEachNode(const Package& package, const std::string& name,
                   const std::function<void(const Node& node, const WorldMatrix& world)>& visit);

}  // namespace bake::glb
