// Parts of the package model shared by the writer and the reader: component types, attribute
// conversions, node transforms and Draco's quantisation bound.
#include <bake_formats/glb.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "bake/io/glb.h"

namespace bake::glb {

int gltfComponentType(ComponentType type) {
  switch (type) {
    case ComponentType::I8: return format::glb::kComponentI8;
    case ComponentType::U8: return format::glb::kComponentU8;
    case ComponentType::I16: return format::glb::kComponentI16;
    case ComponentType::U16: return format::glb::kComponentU16;
    case ComponentType::U32: return format::glb::kComponentU32;
    case ComponentType::F32: return format::glb::kComponentF32;
  }
  return 0;
}

std::size_t componentSize(ComponentType type) {
  switch (type) {
    case ComponentType::I8:
    case ComponentType::U8: return 1;
    case ComponentType::I16:
    case ComponentType::U16: return 2;
    case ComponentType::U32:
    case ComponentType::F32: return 4;
  }
  return 0;
}

const char* componentTypeName(ComponentType type) {
  switch (type) {
    case ComponentType::I8: return "i8";
    case ComponentType::U8: return "u8";
    case ComponentType::I16: return "i16";
    case ComponentType::U16: return "u16";
    case ComponentType::U32: return "u32";
    case ComponentType::F32: return "f32";
  }
  return "?";
}

Attribute Attribute::fromFloats(std::string name, int components, std::span<const float> values) {
  Attribute attribute{std::move(name), ComponentType::F32, components, false, {}};
  attribute.bytes.resize(values.size_bytes());
  std::memcpy(attribute.bytes.data(), values.data(), values.size_bytes());
  return attribute;
}

Attribute Attribute::fromUnorm16(std::string name, int components, std::span<const float> values) {
  Attribute attribute{std::move(name), ComponentType::U16, components, true, {}};
  attribute.bytes.resize(values.size() * 2);
  for (std::size_t i = 0; i < values.size(); ++i) {
    const float clamped = std::clamp(values[i], 0.0f, 1.0f);
    const auto q = static_cast<std::uint16_t>(std::lround(double(clamped) * 65535.0));
    std::memcpy(attribute.bytes.data() + 2 * i, &q, 2);
  }
  return attribute;
}

namespace {
template <class T>
float componentAsFloat(const std::uint8_t* p, bool normalized, double scale) {
  T value;
  std::memcpy(&value, p, sizeof(T));
  if (!normalized) return float(value);
  // glTF 2.0, 3.11: signed normalized values use max(c / (2^(n-1) - 1), -1).
  return float(std::max(double(value) / scale, -1.0));
}
}  // namespace

std::vector<float> Attribute::toFloats() const {
  const std::size_t size = componentSize(componentType);
  const std::size_t n = size ? bytes.size() / size : 0;
  std::vector<float> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint8_t* p = bytes.data() + i * size;
    switch (componentType) {
      case ComponentType::I8: out[i] = componentAsFloat<std::int8_t>(p, normalized, 127.0); break;
      case ComponentType::U8: out[i] = componentAsFloat<std::uint8_t>(p, normalized, 255.0); break;
      case ComponentType::I16: out[i] = componentAsFloat<std::int16_t>(p, normalized, 32767.0); break;
      case ComponentType::U16: out[i] = componentAsFloat<std::uint16_t>(p, normalized, 65535.0); break;
      case ComponentType::U32: out[i] = componentAsFloat<std::uint32_t>(p, normalized, 4294967295.0); break;
      case ComponentType::F32: std::memcpy(&out[i], p, 4); break;
    }
  }
  return out;
}

const Attribute* Primitive::find(const std::string& name) const {
  for (const Attribute& attribute : attributes) {
    if (attribute.name == name) return &attribute;
  }
  return nullptr;
}

std::size_t Primitive::vertexCount() const {
  const Attribute* position = find("POSITION");
  if (position) return position->count();
  return attributes.empty() ? 0 : attributes.front().count();
}

std::array<double, 16> Node::localMatrix() const {
  if (matrix) return *matrix;
  const auto [x, y, z, w] = rotation;
  // Column-major T * R * S (glTF 2.0, 3.5.3).
  const double r[9] = {1 - 2 * (y * y + z * z), 2 * (x * y + z * w),     2 * (x * z - y * w),
                       2 * (x * y - z * w),     1 - 2 * (x * x + z * z), 2 * (y * z + x * w),
                       2 * (x * z + y * w),     2 * (y * z - x * w),     1 - 2 * (x * x + y * y)};
  std::array<double, 16> m{};
  for (int column = 0; column < 3; ++column) {
    for (int row = 0; row < 3; ++row) m[column * 4 + row] = r[column * 3 + row] * scale[column];
  }
  m[12] = translation[0];
  m[13] = translation[1];
  m[14] = translation[2];
  m[15] = 1.0;
  return m;
}

int dracoQuantizationBits(const Attribute& attribute, const DracoOptions& options) {
  if (attribute.componentType != ComponentType::F32) return 0;  // integers are stored losslessly
  if (attribute.name == "POSITION") return options.positionBits;
  if (attribute.name == "NORMAL") return options.normalBits;
  if (attribute.name.rfind("TEXCOORD_", 0) == 0) return options.texcoordBits;
  return options.genericBits;
}

double dracoQuantizationBound(const Attribute& attribute, const DracoOptions& options) {
  const int bits = dracoQuantizationBits(attribute, options);
  if (bits <= 0) return 0.0;
  const std::vector<float> values = attribute.toFloats();
  double range = 0.0;
  for (int c = 0; c < attribute.components; ++c) {
    float lo = INFINITY, hi = -INFINITY;
    for (std::size_t i = std::size_t(c); i < values.size(); i += std::size_t(attribute.components)) {
      lo = std::min(lo, values[i]);
      hi = std::max(hi, values[i]);
    }
    if (lo <= hi) range = std::max(range, double(hi) - double(lo));
  }
  return range / (std::ldexp(1.0, bits) - 1.0) / 2.0;
}

}  // namespace bake::glb
