// Mesh loading and cleaning: readMesh (OpenMesh behind our pre-scans) on OBJ, OFF, PLY or STL, the
// format chosen from the content like a user's file extension would, then welding with a tolerance
// and the geodesic surface build (welding, duplicate faces, edges, components).
#include <cstring>

#include "bake/geodesic/surface.h"
#include "bake/io/mesh.h"
#include "fuzz_support.h"

namespace {

const char* extensionOf(const std::uint8_t* data, std::size_t size) {
  auto startsWith = [&](const char* prefix) {
    const std::size_t n = std::strlen(prefix);
    return size >= n && std::memcmp(data, prefix, n) == 0;
  };
  if (startsWith("ply")) return "ply";
  if (startsWith("OFF") || startsWith("NOFF") || startsWith("COFF") || startsWith("STOFF")) return "off";
  if (startsWith("solid")) return "stl";
  if (size >= 84) {  // binary STL: 80-byte header, triangle count, 50 bytes per triangle
    std::uint32_t count = 0;
    std::memcpy(&count, data + 80, 4);
    if (84 + 50 * std::uint64_t(count) == size) return "stl";
  }
  return "obj";
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path path = bake::fuzz::writeInput(data, size, std::string("mesh.") + extensionOf(data, size));
  bake::MeshReadOptions options;
  options.weld = true;
  options.weldTolerance = 1e-6;
  bake::Result<bake::TriangleMesh> mesh = bake::readMesh(path, options);
  if (!mesh.isOk()) return 0;
  bake::geodesic::SurfaceBuild build = bake::geodesic::buildSurface(*mesh, 1e-3);
  (void)build;
  return 0;
}
