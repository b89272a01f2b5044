// KHR_draco_mesh_compression for our packages: encodes one primitive with Draco's own encoder and
// decodes a compressed bufferView with Draco's decoder. Draco is linked statically: Debian's
// libdraco.so also exports a private copy of tinygltf.
#pragma once

#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "bake/core/status.h"
#include "bake/io/glb.h"

namespace bake::glb::detail {

struct DracoEncoded {
  std::vector<std::uint8_t> bytes;
  std::map<std::string, int> attributeIds;  // glTF attribute name -> Draco unique id
};

Result<DracoEncoded> dracoEncode(const Primitive& primitive, const DracoOptions& options);

// What the glTF accessor of a compressed attribute says it holds.
struct DracoAttributeTarget {
  int dracoId = -1;
  ComponentType componentType = ComponentType::F32;
  int components = 1;
  bool normalized = false;
};

// Fills primitive.indices and the named attributes from a compressed bufferView. `where` names the
// mesh and primitive in errors.
Status dracoDecode(std::span<const std::uint8_t> bytes,
                   const std::map<std::string, DracoAttributeTarget>& targets, Primitive& primitive,
                   const Location& where);

}  // namespace bake::glb::detail
