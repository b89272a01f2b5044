// Draco encode/decode of one glTF primitive (KHR_draco_mesh_compression). Float attributes are
// quantised with the bits of DracoOptions (error bound range / (2^bits - 1) / 2, see glb.h); integer
// attributes are stored losslessly. Edgebreaker is the default method; the sequential method keeps
// vertex and triangle order when a caller needs it.
#include "io/draco_codec.h"

#include <draco/compression/config/compression_shared.h>
#include <draco/compression/decode.h>
#include <draco/compression/expert_encode.h>
#include <draco/mesh/mesh.h>

#include <bake_formats/glb.h>

#include <cstring>

namespace bake::glb::detail {

namespace {

draco::DataType dracoDataType(ComponentType type) {
  switch (type) {
    case ComponentType::I8: return draco::DT_INT8;
    case ComponentType::U8: return draco::DT_UINT8;
    case ComponentType::I16: return draco::DT_INT16;
    case ComponentType::U16: return draco::DT_UINT16;
    case ComponentType::U32: return draco::DT_UINT32;
    case ComponentType::F32: return draco::DT_FLOAT32;
  }
  return draco::DT_INVALID;
}

draco::GeometryAttribute::Type dracoSemantic(const std::string& name) {
  if (name == "POSITION") return draco::GeometryAttribute::POSITION;
  if (name == "NORMAL") return draco::GeometryAttribute::NORMAL;
  if (name.rfind("TEXCOORD_", 0) == 0) return draco::GeometryAttribute::TEX_COORD;
  if (name.rfind("COLOR_", 0) == 0) return draco::GeometryAttribute::COLOR;
  return draco::GeometryAttribute::GENERIC;
}

template <class T>
void appendConverted(const draco::PointAttribute& attribute, draco::PointIndex point, int components,
                     std::vector<std::uint8_t>& out) {
  T values[4] = {};
  attribute.ConvertValue<T>(attribute.mapped_index(point), static_cast<int8_t>(components), values);
  const std::size_t offset = out.size();
  out.resize(offset + sizeof(T) * std::size_t(components));
  std::memcpy(out.data() + offset, values, sizeof(T) * std::size_t(components));
}

void appendPointValue(const draco::PointAttribute& attribute, draco::PointIndex point,
                      const DracoAttributeTarget& target, std::vector<std::uint8_t>& out) {
  switch (target.componentType) {
    case ComponentType::I8: return appendConverted<std::int8_t>(attribute, point, target.components, out);
    case ComponentType::U8: return appendConverted<std::uint8_t>(attribute, point, target.components, out);
    case ComponentType::I16: return appendConverted<std::int16_t>(attribute, point, target.components, out);
    case ComponentType::U16: return appendConverted<std::uint16_t>(attribute, point, target.components, out);
    case ComponentType::U32: return appendConverted<std::uint32_t>(attribute, point, target.components, out);
    case ComponentType::F32: return appendConverted<float>(attribute, point, target.components, out);
  }
}

}  // namespace

Result<DracoEncoded> dracoEncode(const Primitive& primitive, const DracoOptions& options) {
  if (primitive.mode != format::glb::kModeTriangles) {
    return unsupported("Draco compression needs a triangle primitive");
  }
  const std::size_t vertexCount = primitive.vertexCount();
  draco::Mesh mesh;
  mesh.set_num_points(static_cast<std::uint32_t>(vertexCount));
  if (primitive.indices.empty()) {
    for (std::uint32_t v = 0; v + 2 < vertexCount; v += 3) {
      mesh.AddFace({draco::PointIndex(v), draco::PointIndex(v + 1), draco::PointIndex(v + 2)});
    }
  } else {
    for (std::size_t i = 0; i + 2 < primitive.indices.size(); i += 3) {
      mesh.AddFace({draco::PointIndex(primitive.indices[i]), draco::PointIndex(primitive.indices[i + 1]),
                    draco::PointIndex(primitive.indices[i + 2])});
    }
  }

  DracoEncoded encoded;
  std::vector<std::pair<int, int>> quantization;  // (draco attribute id, bits)
  for (const Attribute& attribute : primitive.attributes) {
    draco::GeometryAttribute geometry;
    geometry.Init(dracoSemantic(attribute.name), nullptr, static_cast<std::uint8_t>(attribute.components),
                  dracoDataType(attribute.componentType), attribute.normalized,
                  static_cast<std::int64_t>(attribute.elementSize()), 0);
    const int id = mesh.AddAttribute(geometry, true, static_cast<std::uint32_t>(vertexCount));
    draco::PointAttribute* stored = mesh.attribute(id);
    for (std::size_t v = 0; v < vertexCount; ++v) {
      stored->SetAttributeValue(draco::AttributeValueIndex(static_cast<std::uint32_t>(v)),
                                attribute.bytes.data() + v * attribute.elementSize());
    }
    encoded.attributeIds[attribute.name] = int(stored->unique_id());
    const int bits = dracoQuantizationBits(attribute, options);
    if (bits > 0) quantization.emplace_back(id, bits);
  }

  draco::ExpertEncoder encoder(mesh);
  for (const auto& [id, bits] : quantization) encoder.SetAttributeQuantization(id, bits);
  encoder.SetSpeedOptions(options.speed, options.speed);
  encoder.SetEncodingMethod(options.preserveOrder ? draco::MESH_SEQUENTIAL_ENCODING
                                                  : draco::MESH_EDGEBREAKER_ENCODING);
  draco::EncoderBuffer buffer;
  const draco::Status status = encoder.EncodeToBuffer(&buffer);
  if (!status.ok()) return internalError(std::string("Draco encoder failed: ") + status.error_msg());
  encoded.bytes.assign(buffer.data(), buffer.data() + buffer.size());
  return encoded;
}

Status dracoDecode(std::span<const std::uint8_t> bytes,
                   const std::map<std::string, DracoAttributeTarget>& targets, Primitive& primitive,
                   const Location& where) {
  draco::DecoderBuffer buffer;
  buffer.Init(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  draco::Decoder decoder;
  auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
  if (!decoded.ok()) {
    return invalidInput(std::string("Draco data cannot be decoded: ") + decoded.status().error_msg(), where);
  }
  const std::unique_ptr<draco::Mesh> mesh = std::move(decoded).value();
  const std::uint32_t points = mesh->num_points();

  primitive.indices.clear();
  primitive.indices.reserve(std::size_t(mesh->num_faces()) * 3);
  for (draco::FaceIndex f(0); f < mesh->num_faces(); ++f) {
    for (int corner = 0; corner < 3; ++corner) primitive.indices.push_back(mesh->face(f)[corner].value());
  }

  for (const auto& [name, target] : targets) {
    const draco::PointAttribute* attribute = mesh->GetAttributeByUniqueId(std::uint32_t(target.dracoId));
    if (attribute == nullptr) {
      return invalidInput("attribute " + name + " names Draco attribute " + std::to_string(target.dracoId) +
                              ", which the compressed data does not contain",
                          where);
    }
    if (attribute->num_components() < target.components) {
      return invalidInput("attribute " + name + " has " + std::to_string(attribute->num_components()) +
                              " components in the Draco data, the accessor says " +
                              std::to_string(target.components),
                          where);
    }
    Attribute out{name, target.componentType, target.components, target.normalized, {}};
    out.bytes.reserve(std::size_t(points) * out.elementSize());
    for (draco::PointIndex p(0); p < points; ++p) appendPointValue(*attribute, p, target, out.bytes);
    primitive.attributes.push_back(std::move(out));
  }
  return {};
}

}  // namespace bake::glb::detail
