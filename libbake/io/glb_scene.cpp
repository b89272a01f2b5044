#include "io/glb_scene.h"

namespace bake::glb {
namespace {

constexpr WorldMatrix kIdentity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

std::vector<int> rootsOf(const Package& package) {
  if (!package.sceneRoots.empty()) return package.sceneRoots;
  std::vector<bool> isChild(package.nodes.size(), false);
  for (const Node& node : package.nodes) {
    for (int child : node.children) isChild[std::size_t(child)] = true;
  }
  std::vector<int> roots;
  for (std::size_t i = 0; i < package.nodes.size(); ++i) {
    if (!isChild[i]) roots.push_back(int(i));
  }
  return roots;
}

// Depth first with an explicit stack, never recursion: a chain of 100,000 nodes is a valid glTF and
// must not overflow the call stack. Children are visited in order, as a recursive walk would.
Status visitTree(const Package& package, const std::string& name, int root, std::vector<bool>& onPath,
                 const std::function<void(const Node&, const WorldMatrix&)>& visit) {
  struct Frame {
    int node;
    WorldMatrix world;
    std::size_t nextChild;
  };
  std::vector<Frame> stack;
  auto enter = [&](int index, const WorldMatrix& parent) -> Status {
    if (onPath[std::size_t(index)]) {
      return invalidInput("node " + std::to_string(index) + " is its own ancestor (cycle)", {name, "node " + std::to_string(index)});
    }
    onPath[std::size_t(index)] = true;
    const Node& node = package.nodes[std::size_t(index)];
    stack.push_back({index, multiplyMatrices(parent, node.localMatrix()), 0});
    visit(node, stack.back().world);
    return {};
  };
  BAKE_RETURN_IF_ERROR(enter(root, kIdentity));
  while (!stack.empty()) {
    Frame& top = stack.back();
    const std::vector<int>& children = package.nodes[std::size_t(top.node)].children;
    if (top.nextChild < children.size()) {
      const int child = children[top.nextChild++];
      const WorldMatrix world = top.world;
      BAKE_RETURN_IF_ERROR(enter(child, world));
    } else {
      onPath[std::size_t(top.node)] = false;
      stack.pop_back();
    }
  }
  return {};
}

}  // namespace

WorldMatrix multiplyMatrices(const WorldMatrix& a, const WorldMatrix& b) {
  WorldMatrix m{};
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      double sum = 0;
      for (int k = 0; k < 4; ++k) sum += a[k * 4 + r] * b[c * 4 + k];
      m[c * 4 + r] = sum;
    }
  }
  return m;
}

Status forEachNode(const Package& package, const std::string& name,
                   const std::function<void(const Node&, const WorldMatrix&)>& visit) {
  std::vector<bool> onPath(package.nodes.size(), false);
  for (int root : rootsOf(package)) BAKE_RETURN_IF_ERROR(visitTree(package, name, root, onPath, visit));
  return {};
}

}  // namespace bake::glb
