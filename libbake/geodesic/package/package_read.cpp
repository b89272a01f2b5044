// GeoTextures material parameters and the loader checks of BAKE_geodesic (geodesic/package/package_read.h).
#include <bake_formats/geodesic.h>

#include <algorithm>
#include <cctype>
#include <cmath>

#include "geodesic/package/package_read.h"

namespace bake::geodesic {
namespace material_detail {
namespace {
namespace fmt = format::geodesic;
}  // namespace

constexpr PresetInfo kPresets[] = {
    {GeoPreset::Isolines, "isolines", "PRESET_ISOLINES"},
    {GeoPreset::SandWater, "sand-water", "PRESET_SAND_WATER"},
    {GeoPreset::MossGranite, "moss-granite", "PRESET_MOSS_GRANITE"},
    {GeoPreset::PaintMetalRust, "paint-metal-rust", "PRESET_PAINT_METAL_RUST"},
    {GeoPreset::WaterLava, "water-lava", "PRESET_WATER_LAVA"},
    {GeoPreset::OpacityFront, "opacity-front", "PRESET_OPACITY_FRONT"},
    {GeoPreset::WaveDisplacement, "wave-displacement", "PRESET_WAVE"},
};

const PresetInfo& infoOf(GeoPreset preset) {
  for (const PresetInfo& info : kPresets) {
    if (info.preset == preset) return info;
  }
  return kPresets[0];
}

std::string attributeName(int field) { return fmt::kAttributePrefix + std::to_string(field); }

}  // namespace material_detail

namespace {

using namespace material_detail;
namespace fmt = format::geodesic;

// ---------------------------------------------------------------------------------------------
// Parameter parsing: every key optional, wrong types are errors, unknown keys are ignored.

class Reader {
 public:
  Reader(const nlohmann::json& body, Location where) : body_(body), where_(std::move(where)) {}

  Status number(const char* key, float& out, float lo, float hi) const {
    return numberIn(body_, key, key, out, lo, hi);
  }
  Status numberIn(const nlohmann::json& object, const char* key, const std::string& path, float& out,
                  float lo, float hi) const {
    if (!object.contains(key)) return {};
    const nlohmann::json& value = object[key];
    if (!value.is_number() || !std::isfinite(value.get<double>()) || value.get<double>() < lo ||
        value.get<double>() > hi) {
      return error(path + " must be a number in [" + trimmed(lo) + ", " + trimmed(hi) + "]");
    }
    out = value.get<float>();
    return {};
  }
  Status colour(const nlohmann::json& value, const std::string& path, Rgb& out) const {
    if (!value.is_array() || (value.size() != 3 && value.size() != 4))
      return error(path + " must be [r, g, b] (linear)");
    for (std::size_t c = 0; c < 3; ++c) {
      if (!value[c].is_number() || value[c].get<double>() < 0 || value[c].get<double>() > 1) {
        return error(path + " components must be numbers in [0, 1]");
      }
      out[c] = value[c].get<float>();
    }
    return {};
  }
  Status numbers(const char* key, std::array<float, 4>& out, float lo, float hi) const {
    if (!body_.contains(key)) return {};
    const nlohmann::json& list = body_[key];
    if (!list.is_array() || list.empty() || list.size() > 4)
      return error(std::string(key) + " must be a list of 1 to 4 numbers");
    for (std::size_t i = 0; i < list.size(); ++i) {
      if (!list[i].is_number() || list[i].get<double>() < lo || list[i].get<double>() > hi) {
        return error(std::string(key) + "[" + std::to_string(i) + "] must be a number in [" + trimmed(lo) +
                     ", " + trimmed(hi) + "]");
      }
      out[i] = list[i].get<float>();
    }
    for (std::size_t i = list.size(); i < 4; ++i) out[i] = out[list.size() - 1];  // the last repeats
    return {};
  }
  const nlohmann::json& object(const char* key) const {
    static const nlohmann::json empty = nlohmann::json::object();
    return body_.contains(key) && body_[key].is_object() ? body_[key] : empty;
  }
  Status requireObject(const char* key) const {
    return body_.contains(key) && !body_[key].is_object() ? error(std::string(key) + " must be an object")
                                                          : Status();
  }
  Status error(const std::string& message) const {
    return invalidInput("BAKE_geodesic material: " + message, where_);
  }
  const nlohmann::json& body() const { return body_; }

 private:
  static std::string trimmed(float v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", double(v));
    return text;
  }
  const nlohmann::json& body_;
  Location where_;
};

Status readFields(const Reader& in, GeoTextureParams& params) {
  const nlohmann::json& body = in.body();
  if (body.contains("combine")) {
    const std::string combine = body["combine"].is_string() ? body["combine"].get<std::string>() : "";
    if (combine != "min" && combine != "separate") return in.error("combine must be \"separate\" or \"min\"");
    params.combineMin = combine == "min";
  }
  if (body.contains(fmt::kKeyFields)) {
    const nlohmann::json& list = body[fmt::kKeyFields];
    if (!list.is_array() || list.empty() || list.size() > std::size_t(kMaxSlots)) {
      return in.error("fields must be a list of 1 to 4 field indices");
    }
    params.fields.clear();
    for (const nlohmann::json& field : list) {
      if (!field.is_number_integer() || field.get<int>() < 0 || field.get<int>() >= fmt::kMaxFields) {
        return in.error("fields must hold integers 0 to " + std::to_string(fmt::kMaxFields - 1));
      }
      params.fields.push_back(field.get<int>());
    }
    params.fieldsGiven = true;
  }
  if (!params.combineMin && params.fields.size() > 2) {
    return in.error("a preset reads at most two separate fields; merge more with \"combine\": \"min\"");
  }
  return {};
}

Status readColours(const Reader& in, GeoTextureParams& params) {
  const nlohmann::json& body = in.body();
  if (body.contains("colors")) {
    const nlohmann::json& list = body["colors"];
    if (!list.is_array() || list.size() > 4) return in.error("colors must be a list of up to 4 [r, g, b]");
    for (std::size_t i = 0; i < list.size(); ++i) {
      BAKE_RETURN_IF_ERROR(in.colour(list[i], "colors[" + std::to_string(i) + "]", params.colours[i]));
    }
  }
  if (body.contains("unreachableColor")) {
    BAKE_RETURN_IF_ERROR(in.colour(body["unreachableColor"], "unreachableColor", params.unreachableColour));
  }
  const nlohmann::json& isolines = in.object("isolines");
  if (isolines.contains("color"))
    BAKE_RETURN_IF_ERROR(in.colour(isolines["color"], "isolines.color", params.isolineColour));
  return {};
}

Status readWave(const Reader& in, GeoTextureParams::Wave& wave) {
  BAKE_RETURN_IF_ERROR(in.requireObject("wave"));
  const nlohmann::json& w = in.object("wave");
  BAKE_RETURN_IF_ERROR(in.numberIn(w, "amplitude", "wave.amplitude", wave.amplitude, -1, 1));
  BAKE_RETURN_IF_ERROR(in.numberIn(w, "wavelength", "wave.wavelength", wave.wavelength, 1e-4f, 10));
  BAKE_RETURN_IF_ERROR(in.numberIn(w, "reach", "wave.reach", wave.reach, 1e-4f, 10));
  BAKE_RETURN_IF_ERROR(in.numberIn(w, "pixelsPerEdge", "wave.pixelsPerEdge", wave.pixelsPerEdge, 1, 1000));
  BAKE_RETURN_IF_ERROR(in.numberIn(w, "maxLevel", "wave.maxLevel", wave.maxLevel, 1, 64));
  if (w.contains("displace")) {
    if (!w["displace"].is_boolean()) return in.error("wave.displace must be true or false");
    wave.displace = w["displace"].get<bool>();
  }
  return {};
}

Rgb rgb(float r, float g, float b) { return {r, g, b}; }


bool isFieldAttribute(const std::string& name) { return name.rfind(fmt::kAttributePrefix, 0) == 0; }

std::optional<int> fieldIndexOf(const std::string& name) {
  if (!isFieldAttribute(name)) return std::nullopt;
  const std::string digits = name.substr(std::string(fmt::kAttributePrefix).size());
  const auto isDigit = [](unsigned char c) { return std::isdigit(c) != 0; };
  if (digits.empty() || digits.size() > 3 || !std::all_of(digits.begin(), digits.end(), isDigit))
    return std::nullopt;
  return std::stoi(digits);
}

// The fields a material reads on one primitive: the list it gives, or the preset's default list
// trimmed to the fields present (at least field 0's slot, so a missing field 0 is still an error).

Status checkRootExtension(const glb::Package& package, const std::string& name) {
  if (!package.extensions.contains(fmt::kExtension)) return {};
  const nlohmann::json& root = package.extensions[fmt::kExtension];
  const Location where{name, std::string("extensions.") + fmt::kExtension};
  if (!root.is_object()) return invalidInput("BAKE_geodesic must be an object", where);
  std::string encoding;
  if (root.contains(fmt::kKeyEncoding)) {
    encoding = root[fmt::kKeyEncoding].is_string() ? root[fmt::kKeyEncoding].get<std::string>() : "";
    if (encoding != fmt::kEncodingFloat && encoding != fmt::kEncodingUnorm16) {
      return invalidInput("encoding must be \"float\" or \"unorm16\"", where);
    }
  }
  const nlohmann::json fields = root.value(fmt::kKeyFields, nlohmann::json::array());
  if (!fields.is_array()) return invalidInput("fields must be a list", where);
  for (std::size_t m = 0; m < package.meshes.size(); ++m) {
    for (std::size_t p = 0; p < package.meshes[m].primitives.size(); ++p) {
      const glb::Primitive& primitive = package.meshes[m].primitives[p];
      if (geodesicFieldsOf(primitive).empty()) continue;
      const Location here{name, "mesh " + std::to_string(m) + " primitive " + std::to_string(p)};
      for (const nlohmann::json& field : fields) {
        const std::string attribute = field.is_object() ? field.value(fmt::kFieldAttribute, "") : "";
        if (!fieldIndexOf(attribute))
          return invalidInput("fields entry without a valid _GEODESIC_k attribute", where);
        const glb::Attribute* a = primitive.find(attribute);
        if (!a)
          return invalidInput("field attribute " + attribute + " listed in BAKE_geodesic is missing", here);
        const bool isUnorm = a->componentType == glb::ComponentType::U16;
        if (!encoding.empty() && isUnorm != (encoding == fmt::kEncodingUnorm16)) {
          return invalidInput(attribute + " is not stored as the declared encoding \"" + encoding + "\"",
                              here);
        }
      }
    }
  }
  return {};
}

}  // namespace

namespace material_detail {

Result<std::vector<int>> resolveFields(const GeoTextureParams& params, const glb::Primitive& primitive,
                                       const Location& where) {
  std::vector<int> fields = params.fields;
  if (!params.fieldsGiven) {
    const std::vector<int> present = geodesicFieldsOf(primitive);
    std::erase_if(fields,
                  [&](int f) { return std::find(present.begin(), present.end(), f) == present.end(); });
    if (fields.empty()) fields.push_back(params.fields.front());
  }
  for (int field : fields) {
    if (!primitive.find(attributeName(field))) {
      return invalidInput("the material reads geodesic field " + std::to_string(field) +
                              " but the primitive has no " + attributeName(field) + " attribute",
                          where);
    }
  }
  // Slots hold distinct attributes (an attribute binds to one location).
  std::vector<int> distinct;
  for (int field : fields) {
    if (std::find(distinct.begin(), distinct.end(), field) == distinct.end()) distinct.push_back(field);
  }
  return distinct;
}

// Whether the package stores distances in model units (normalization "none") rather than in [0, 1].
bool storesModelUnits(const glb::Package& package) {
  const nlohmann::json& root = package.extensions.value(fmt::kExtension, nlohmann::json::object());
  return root.is_object() && root.value(fmt::kKeyNormalization, "") == fmt::kNormalizationNone;
}

// Factor from a stored value to the normalised distance the presets use: 1, or 1 / maxDistance for
// fields stored in model units.
float normalisingFactor(const glb::Package& package, const std::string& attribute) {
  if (!storesModelUnits(package)) return 1;
  for (const nlohmann::json& field :
       package.extensions[fmt::kExtension].value(fmt::kKeyFields, nlohmann::json::array())) {
    if (field.is_object() && field.value(fmt::kFieldAttribute, "") == attribute) {
      const double maxDistance = field.value(fmt::kFieldMaxDistance, 0.0);
      return maxDistance > 0 ? float(1.0 / maxDistance) : 1.0f;
    }
  }
  return 1;
}

Status checkFieldAttribute(const glb::Attribute& a, const Location& where, bool modelUnits) {
  const bool f32 = a.componentType == glb::ComponentType::F32;
  const bool unorm16 = a.componentType == glb::ComponentType::U16 && a.normalized;
  if (a.components != 1 || !(f32 || unorm16)) {
    return invalidInput(a.name + " must be SCALAR FLOAT or normalized UNSIGNED_SHORT", where);
  }
  if (!f32) return {};  // every unorm16 value is a distance or the unreachable flag 65535
  const std::vector<float> values = a.toFloats();
  for (std::size_t i = 0; i < values.size(); ++i) {
    const float v = values[i];
    const bool inRange = v >= -1e-6f && (modelUnits || v <= 1.0f + 1e-6f);
    if (!inRange && v != fmt::kUnreachableFloat) {
      return invalidInput(a.name + " vertex " + std::to_string(i) + " holds " + std::to_string(v) +
                              ": fields hold " +
                              (modelUnits ? "distances >= 0" : "normalised distances in [0, 1]") + " or " +
                              std::to_string(fmt::kUnreachableFloat) + " for unreachable vertices",
                          where);
    }
  }
  return {};
}

}  // namespace material_detail

using namespace material_detail;

// ---------------------------------------------------------------------------------------------
// Presets and parameters

const char* geoPresetName(GeoPreset preset) { return infoOf(preset).name; }

std::optional<GeoPreset> geoPresetFromName(const std::string& name) {
  for (const PresetInfo& info : kPresets) {
    if (name == info.name) return info.preset;
  }
  return std::nullopt;
}

std::vector<std::string> geoPresetNames() {
  std::vector<std::string> names;
  for (const PresetInfo& info : kPresets) names.emplace_back(info.name);
  return names;
}

GeoTextureParams geoPresetDefaults(GeoPreset preset) {
  GeoTextureParams p;
  p.preset = preset;
  switch (preset) {
    case GeoPreset::Isolines:
      break;
    case GeoPreset::SandWater:
      p.thresholds = {0.25f, 0.25f, 0.25f, 0.25f};
      p.noiseFrequency = 12, p.noiseAmplitude = 0.01f;
      p.colours = {rgb(0.76f, 0.62f, 0.38f), rgb(0.05f, 0.30f, 0.28f)};
      break;
    case GeoPreset::MossGranite:
      p.thresholds = {0.3f, 0.3f, 0.3f, 0.3f};
      p.widths = {0.04f, 0.04f, 0.04f, 0.04f};
      p.noiseFrequency = 8, p.noiseAmplitude = 0.04f;
      p.colours = {rgb(0.16f, 0.30f, 0.05f), rgb(0.52f, 0.50f, 0.47f)};
      break;
    case GeoPreset::PaintMetalRust:
      p.thresholds = {0.1f, 0.25f, 0.4f, 0.4f};
      p.widths = {0.01f, 0.03f, 0.01f, 0.01f};
      p.noiseFrequency = 25, p.noiseAmplitude = 0.04f;
      p.colours = {rgb(0, 0, 0), rgb(0.42f, 0.15f, 0.04f), rgb(0.55f, 0.56f, 0.58f),
                   rgb(0.06f, 0.16f, 0.55f)};
      break;
    case GeoPreset::WaterLava:
      p.fields = {0, 1};
      p.thresholds = {0.25f, 0.35f, 0.35f, 0.35f};
      p.widths = {0.02f, 0.03f, 0.03f, 0.03f};
      p.noiseFrequency = 4, p.noiseAmplitude = 0.05f;
      p.colours = {rgb(0.04f, 0.22f, 0.42f), rgb(1.0f, 0.33f, 0.04f), rgb(0.11f, 0.09f, 0.08f)};
      break;
    case GeoPreset::OpacityFront:
      p.thresholds = {0.3f, 0.3f, 0.3f, 0.3f};
      p.colours = {rgb(0.80f, 0.74f, 0.64f), rgb(0.30f, 0.50f, 0.80f)};
      break;
    case GeoPreset::WaveDisplacement:
      p.thresholds = {0.4f, 0.4f, 0.4f, 0.4f};
      p.colours = {rgb(0.22f, 0.42f, 0.58f), rgb(0.85f, 0.90f, 0.95f)};
      break;
  }
  return p;
}

Result<GeoTextureParams> parseGeoTexture(const nlohmann::json& extension, const Location& where) {
  const Reader in(extension, where);
  if (!extension.is_object()) return in.error("must be an object");
  const std::string name = extension.value("texture", nlohmann::json("isolines")).is_string()
                               ? extension.value("texture", std::string("isolines"))
                               : "";
  const std::optional<GeoPreset> preset = geoPresetFromName(name);
  if (!preset) {
    std::string known;
    for (const std::string& n : geoPresetNames()) known += (known.empty() ? "" : ", ") + n;
    return in.error("unknown texture \"" + name + "\" (known: " + known + ")");
  }
  GeoTextureParams params = geoPresetDefaults(*preset);
  BAKE_RETURN_IF_ERROR(readFields(in, params));
  BAKE_RETURN_IF_ERROR(in.numbers("thresholds", params.thresholds, -10, 10));
  BAKE_RETURN_IF_ERROR(in.numbers("widths", params.widths, 0, 10));
  BAKE_RETURN_IF_ERROR(in.number("speed", params.speed, -100, 100));
  BAKE_RETURN_IF_ERROR(in.requireObject("frontNoise"));
  BAKE_RETURN_IF_ERROR(in.numberIn(in.object("frontNoise"), "frequency", "frontNoise.frequency",
                                   params.noiseFrequency, 0, 1e4f));
  BAKE_RETURN_IF_ERROR(in.numberIn(in.object("frontNoise"), "amplitude", "frontNoise.amplitude",
                                   params.noiseAmplitude, 0, 10));
  BAKE_RETURN_IF_ERROR(in.number("patternScale", params.patternScale, 1e-3f, 1e3f));
  BAKE_RETURN_IF_ERROR(in.number("bumpScale", params.bumpScale, 0, 100));
  BAKE_RETURN_IF_ERROR(readColours(in, params));
  BAKE_RETURN_IF_ERROR(in.requireObject("isolines"));
  BAKE_RETURN_IF_ERROR(
      in.numberIn(in.object("isolines"), "spacing", "isolines.spacing", params.isolineSpacing, 1e-3f, 1));
  BAKE_RETURN_IF_ERROR(
      in.numberIn(in.object("isolines"), "width", "isolines.width", params.isolineWidth, 0, 64));
  BAKE_RETURN_IF_ERROR(in.number("opacity", params.opacity, 0, 1));
  BAKE_RETURN_IF_ERROR(readWave(in, params.wave));
  return params;
}

std::vector<int> geodesicFieldsOf(const glb::Primitive& primitive) {
  std::vector<int> fields;
  for (const glb::Attribute& attribute : primitive.attributes) {
    if (const auto k = fieldIndexOf(attribute.name)) fields.push_back(*k);
  }
  std::sort(fields.begin(), fields.end());
  return fields;
}

// ---------------------------------------------------------------------------------------------
// Validation

Status checkGeodesicPackage(const glb::Package& package, const std::string& name) {
  // Packages that neither declare BAKE_geodesic nor use it in a material are not checked here.
  bool used = package.extensions.contains(fmt::kExtension);
  for (const nlohmann::json& material : package.materials) {
    used = used || (material.is_object() && material.contains("extensions") &&
                    material["extensions"].is_object() && material["extensions"].contains(fmt::kExtension));
  }
  if (!used) return {};
  for (std::size_t m = 0; m < package.meshes.size(); ++m) {
    for (std::size_t p = 0; p < package.meshes[m].primitives.size(); ++p) {
      const glb::Primitive& primitive = package.meshes[m].primitives[p];
      const Location where{name, "mesh " + std::to_string(m) + " primitive " + std::to_string(p)};
      bool unorm = false, floats = false;
      for (const glb::Attribute& attribute : primitive.attributes) {
        if (!isFieldAttribute(attribute.name)) continue;
        if (!fieldIndexOf(attribute.name))
          return invalidInput(attribute.name + " is not named _GEODESIC_<k>", where);
        BAKE_RETURN_IF_ERROR(checkFieldAttribute(attribute, where, storesModelUnits(package)));
        (attribute.componentType == glb::ComponentType::U16 ? unorm : floats) = true;
      }
      if (unorm && floats) return invalidInput("geodesic fields mix float and unorm16 encodings", where);
      const int index = primitive.material;
      if (index < 0 || std::size_t(index) >= package.materials.size()) continue;
      const nlohmann::json& material = package.materials[std::size_t(index)];
      if (!material.contains("extensions") || !material["extensions"].contains(fmt::kExtension)) continue;
      const Location materialWhere{name, "material " + std::to_string(index)};
      BAKE_ASSIGN_OR_RETURN(const GeoTextureParams params,
                            parseGeoTexture(material["extensions"][fmt::kExtension], materialWhere));
      BAKE_RETURN_IF_ERROR(resolveFields(params, primitive, where).status());
    }
  }
  return checkRootExtension(package, name);
}

}  // namespace bake::geodesic
