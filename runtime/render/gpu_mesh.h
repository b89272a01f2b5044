// Primitives on the GPU: one immutable buffer per attribute and one for indices, bound to a vertex
// array with OpenGL 4.5 direct state access. Attributes keep their stored type (float, or normalized
// integers such as 16-bit geodesic fields) and are fetched at the locations the renderer chooses.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "bake/core/status.h"
#include "bake/io/glb.h"

namespace bake::play {

class GpuPrimitive {
 public:
  // `locations` maps attribute names ("POSITION", "_GEODESIC_0", ...) to shader input locations;
  // attributes not listed are not uploaded (the runtime loads only what a shader reads).
  static Result<GpuPrimitive> upload(const glb::Primitive& primitive, const std::map<std::string, int>& locations);

  GpuPrimitive() = default;
  GpuPrimitive(GpuPrimitive&& other) noexcept;
  GpuPrimitive& operator=(GpuPrimitive&& other) noexcept;
  GpuPrimitive(const GpuPrimitive&) = delete;
  GpuPrimitive& operator=(const GpuPrimitive&) = delete;
  ~GpuPrimitive();

  void draw() const;
  // Draws a triangle list as 3-vertex patches, for programs with tessellation stages.
  void drawAsPatches() const;
  bool has(const std::string& attribute) const;
  std::size_t uploadedBytes() const { return bytes_; }

 private:
  void release();

  unsigned vao_ = 0;
  std::vector<unsigned> buffers_;
  std::vector<std::string> attributes_;
  unsigned mode_ = 0;
  int count_ = 0;
  bool indexed_ = false;
  std::size_t bytes_ = 0;
};

}  // namespace bake::play
