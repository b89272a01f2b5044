// Loader checks of BAKE_paintstrokes (formats/paintstrokes.md) beyond the structure the decoder
// checks (package_read.cpp): the values a shader turns into colours must be in range (opacities and
// ambient in [0, 1], specular >= 0, edge softness > 0), and the centrelines drawn with the material
// must be a LINES primitive with one position per control point. Used by the runtime before upload,
// by `bakeplay validate` and by bakeinfo.
#include <bake_formats/paintstrokes.h>

#include <string>
#include <vector>

#include "core/json_keys.h"
#include "paintstrokes/package/package.h"

namespace bake::paintstrokes {
namespace {

namespace fmt = format::paintstrokes;

Status checkRange(float value, float lo, float hi, const std::string& field, const Location& where) {
  if (!(value >= lo && value <= hi)) {
    return invalidInput(std::string(fmt::kExtension) + ": " + field + " = " + std::to_string(value) + " is outside [" +
                            std::to_string(lo) + ", " + std::to_string(hi) + "]",
                        where);
  }
  return {};
}

Status checkStyles(const PaintstrokePackage& p, const Location& where) {
  for (std::size_t k = 0; k < p.styles.size(); ++k) {
    const fmt::Style& s = p.styles[k];
    const std::string name = std::string(fmt::kStyles) + "/" + std::to_string(k);
    static const char* const kOpacity[] = {"centre opacity", "edge opacity", "volume opacity across", "volume opacity along"};
    for (int i = 0; i < 4; ++i) BAKE_RETURN_IF_ERROR(checkRange(s.opacity[i], 0, 1, name + " " + kOpacity[i], where));
    for (int i = 0; i < 3; ++i) BAKE_RETURN_IF_ERROR(checkRange(s.specular[i], 0, 1e3f, name + " specular", where));
    BAKE_RETURN_IF_ERROR(checkRange(s.specular[3], 0, 1e4f, name + " shininess", where));
    BAKE_RETURN_IF_ERROR(checkRange(s.shading[0], 0, 1, name + " ambient", where));
    BAKE_RETURN_IF_ERROR(checkRange(s.shading[1], 1e-3f, 1e3f, name + " edge softness (pixels)", where));
  }
  return {};
}

}  // namespace

Result<PaintstrokePackage> readPaintstrokes(const glb::Package& package, const nlohmann::json& extension,
                                                      const Location& where) {
  const std::string name = where.element.empty() ? where.file : where.file + ": " + where.element;
  BAKE_ASSIGN_OR_RETURN(PaintstrokePackage decoded, decodePaintstrokeExtension(package, extension, name));
  BAKE_RETURN_IF_ERROR(checkStyles(decoded, where));
  return decoded;
}

Status checkPaintstrokePackage(const glb::Package& package, const std::string& name) {
  std::vector<std::size_t> pointCount(package.materials.size(), 0);
  std::vector<bool> carries(package.materials.size(), false);
  for (std::size_t m = 0; m < package.materials.size(); ++m) {
    const nlohmann::json& extension = jsonMember(jsonMember(package.materials[m], "extensions"), fmt::kExtension);
    if (extension.is_null()) continue;
    BAKE_ASSIGN_OR_RETURN(const PaintstrokePackage decoded,
                          readPaintstrokes(package, extension, {name, "material " + std::to_string(m)}));
    carries[m] = true;
    pointCount[m] = decoded.points.size();
  }
  for (std::size_t mesh = 0; mesh < package.meshes.size(); ++mesh) {
    for (std::size_t p = 0; p < package.meshes[mesh].primitives.size(); ++p) {
      const glb::Primitive& primitive = package.meshes[mesh].primitives[p];
      if (primitive.material < 0 || std::size_t(primitive.material) >= carries.size() || !carries[std::size_t(primitive.material)])
        continue;
      const Location where{name, "mesh " + std::to_string(mesh) + " primitive " + std::to_string(p)};
      if (primitive.mode != 1) {
        return invalidInput(std::string(fmt::kExtension) + " is drawn on a LINES primitive (glTF mode 1) of the centrelines; this one has mode " +
                                std::to_string(primitive.mode),
                            where);
      }
      const std::size_t points = pointCount[std::size_t(primitive.material)];
      if (primitive.vertexCount() != points) {
        return invalidInput("the centrelines hold " + std::to_string(primitive.vertexCount()) + " positions but the " +
                                fmt::kExtension + " material has " + std::to_string(points) + " control points",
                            where);
      }
    }
  }
  return {};
}

}  // namespace bake::paintstrokes
