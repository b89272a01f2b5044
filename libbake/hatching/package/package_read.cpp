// Reading and checking BAKE_hatching (formats/tam.md; hatching/package/package_read.h).
// Packages are untrusted: every field is checked as formats/hatching.schema.json states it (all fields
// but `threshold` required, no others), and a failure names the file, the material and the field. The
// TAM must be an embedded KTX2 2D array (one layer per tone) with the full mip chain, in R8 or RGBA8;
// when its BAKE_tam metadata lists tones they must be the material's.
#include <bake_formats/tam.h>

#include <algorithm>
#include <cmath>
#include <iterator>

#include "core/json_keys.h"
#include "core/json_read.h"
#include "hatching/package/package_read.h"

namespace bake::hatching {
namespace {

namespace fmt = format::tam;

Result<float> finiteNumber(const nlohmann::json& value, const std::string& field, const Location& where) {
  if (!value.is_number()) return invalidInput(std::string(fmt::kExtension) + "." + field + " must be a number", where);
  const double v = value.get<double>();
  if (!std::isfinite(v) || std::fabs(v) > 1e30) {
    return invalidInput(std::string(fmt::kExtension) + "." + field + " must be finite", where);
  }
  return float(v);
}

// The bytes of an embedded image with mimeType image/ktx2.
Result<std::span<const std::uint8_t>> embeddedKtx2(const glb::Package& package, const nlohmann::json& index,
                                                    const std::string& field, const Location& where) {
  const std::string name = std::string(fmt::kExtension) + "." + field;
  if (!index.is_number_integer()) return invalidInput(name + " must be an image index", where);
  const std::int64_t image = index.get<std::int64_t>();
  if (image < 0 || std::size_t(image) >= package.images.size()) {
    return invalidInput(name + " = " + std::to_string(image) + " names no image of the package (missing image; " +
                            std::to_string(package.images.size()) + " images)",
                        where);
  }
  const nlohmann::json& entry = package.images[std::size_t(image)];
  const std::string mime = jsonStringOr(entry, "mimeType", "");
  if (mime != fmt::kKtx2MimeType) {
    return invalidInput(name + ": image " + std::to_string(image) + " has mimeType \"" + mime + "\"; it must be " +
                            fmt::kKtx2MimeType,
                        where);
  }
  const std::int64_t view = jsonIndexOr(entry, "bufferView");
  if (view < 0 || std::size_t(view) >= package.blobs.size()) {
    return invalidInput(name + ": image " + std::to_string(image) + " is not embedded in a bufferView", where);
  }
  return std::span<const std::uint8_t>(package.blobs[std::size_t(view)].bytes);
}

Status checkTones(const nlohmann::json& tones, std::vector<float>& out, const Location& where) {
  const std::string name = std::string(fmt::kExtension) + ".tones";
  if (!tones.is_array() || tones.empty() || tones.size() > std::size_t(fmt::kMaxTones)) {
    return invalidInput(name + " must be an array of 1 to " + std::to_string(fmt::kMaxTones) + " numbers", where);
  }
  for (std::size_t k = 0; k < tones.size(); ++k) {
    const std::string element = "tones[" + std::to_string(k) + "]";
    BAKE_ASSIGN_OR_RETURN(const float tone, finiteNumber(tones[k], element, where));
    if (!(tone > 0.0f && tone < 1.0f)) {
      return invalidInput(name + "[" + std::to_string(k) + "] = " + std::to_string(tone) + " is outside (0, 1)", where);
    }
    if (!out.empty() && !(tone > out.back())) {
      return invalidInput(name + " must be strictly increasing: tones[" + std::to_string(k) + "] = " +
                              std::to_string(tone) + " follows " + std::to_string(out.back()),
                          where);
    }
    out.push_back(tone);
  }
  return {};
}

Status checkTam(const ktx2::Texture& tam, const HatchingParams& p, const Location& where) {
  const std::string name = std::string(fmt::kExtension) + ".tam";
  if (tam.layers == 0) return invalidInput(name + ": the TAM must be a 2D array texture (it has no layers)", where);
  if (tam.layers != p.tones.size()) {
    return invalidInput(name + ": the TAM has " + std::to_string(tam.layers) + " layers but tones lists " +
                            std::to_string(p.tones.size()) + " (layer count mismatch)",
                        where);
  }
  if (tam.format != ktx2::Format::R8 && tam.format != ktx2::Format::RGBA8) {
    return invalidInput(name + ": the TAM is " + ktx2::formatName(tam.format) + "; it must be R8_UNORM or R8G8B8A8_UNORM",
                        where);
  }
  const std::uint32_t full = ktx2::fullMipCount(tam.width, tam.height);
  if (tam.levels.size() != full) {
    return invalidInput(name + ": the TAM has " + std::to_string(tam.levels.size()) + " mip levels; a full chain for " +
                            std::to_string(tam.width) + "x" + std::to_string(tam.height) + " has " + std::to_string(full),
                        where);
  }
  const std::string metadata = tam.text(fmt::kMetadataKey);
  if (!metadata.empty()) {
    BAKE_RETURN_IF_ERROR(checkJsonDepth(metadata, where.file).atElement(name + " metadata"));
    // The metadata is advisory: text that is not JSON leaves nothing to compare.
    const Result<nlohmann::json> parsed = parseJsonText(metadata, where.file);
    const nlohmann::json meta = parsed.isOk() ? parsed.value() : nlohmann::json();
    if (meta.is_object() && meta.contains("tones") && meta["tones"].is_array()) {
      const nlohmann::json& tones = meta["tones"];
      bool same = tones.size() == p.tones.size();
      for (std::size_t k = 0; same && k < tones.size(); ++k) {
        same = tones[k].is_number() && std::fabs(tones[k].get<double>() - double(p.tones[k])) <= 1e-5;
      }
      if (!same) {
        return invalidInput(name + ": the TAM's " + fmt::kMetadataKey + " tones " + tones.dump() +
                                " differ from the material's tones",
                            where);
      }
    }
  }
  return {};
}

}  // namespace

Result<HatchingParams> parseHatching(const nlohmann::json& extension, const glb::Package& package,
                                     const Location& where) {
  const std::string ext = fmt::kExtension;
  if (!extension.is_object()) return invalidInput(ext + " must be an object", where);
  const nlohmann::json& e = extension;
  if (!e.contains("version") || !e["version"].is_number_integer() || e["version"].get<std::int64_t>() != fmt::kVersion) {
    return invalidInput(ext + ".version must be " + std::to_string(fmt::kVersion) + " (got " +
                            (e.contains("version") ? e["version"].dump() : std::string("nothing")) + ")",
                        where);
  }
  static const char* const kFields[] = {"version",     "tam",         "tones",     "tilesPerUnit", "rotation",
                                         "translation", "orientation", "baseColor", "threshold"};
  for (const auto& [key, value] : e.items()) {
    if (std::find(std::begin(kFields), std::end(kFields), key) == std::end(kFields)) {
      return invalidInput(ext + " has an unknown field \"" + key + "\"", where);
    }
  }
  for (const char* required : {"tam", "tones", "tilesPerUnit", "rotation", "translation", "orientation", "baseColor"}) {
    if (!e.contains(required)) {
      return invalidInput(ext + " lacks \"" + required + "\"" + (std::string(required) == "tam" ? " (missing image)" : ""),
                          where);
    }
  }
  HatchingParams p;
  BAKE_RETURN_IF_ERROR(checkTones(e["tones"], p.tones, where));
  BAKE_ASSIGN_OR_RETURN(p.tilesPerUnit, finiteNumber(e["tilesPerUnit"], "tilesPerUnit", where));
  if (!(p.tilesPerUnit > 0)) return invalidInput(ext + ".tilesPerUnit must be > 0", where);
  BAKE_ASSIGN_OR_RETURN(p.rotation, finiteNumber(e["rotation"], "rotation", where));
  {
    const nlohmann::json& t = e["translation"];
    if (!t.is_array() || t.size() != 2) return invalidInput(ext + ".translation must be an array of 2 numbers", where);
    for (std::size_t k = 0; k < 2; ++k) {
      BAKE_ASSIGN_OR_RETURN(p.translation[k], finiteNumber(t[k], "translation[" + std::to_string(k) + "]", where));
    }
  }
  {
    const std::string o = e["orientation"].is_string() ? e["orientation"].get<std::string>() : "";
    if (o == fmt::kOrientationTowardLight) {
      p.orientation = HatchingOrientation::TowardLight;
    } else if (o == fmt::kOrientationAcrossLight) {
      p.orientation = HatchingOrientation::AcrossLight;
    } else {
      return invalidInput(ext + ".orientation is " + e["orientation"].dump() + "; it must be \"" +
                              fmt::kOrientationTowardLight + "\" or \"" + fmt::kOrientationAcrossLight + "\"",
                          where);
    }
  }
  {
    const nlohmann::json& c = e["baseColor"];
    if (!c.is_array() || c.size() != 3) return invalidInput(ext + ".baseColor must be an array of 3 numbers", where);
    for (std::size_t k = 0; k < 3; ++k) {
      BAKE_ASSIGN_OR_RETURN(p.baseColor[k], finiteNumber(c[k], "baseColor[" + std::to_string(k) + "]", where));
      if (!(p.baseColor[k] >= 0 && p.baseColor[k] <= 1)) {
        return invalidInput(ext + ".baseColor[" + std::to_string(k) + "] = " + std::to_string(p.baseColor[k]) +
                                " is outside [0, 1]",
                            where);
      }
    }
  }
  BAKE_ASSIGN_OR_RETURN(const std::span<const std::uint8_t> bytes, embeddedKtx2(package, e[fmt::kTamImage], fmt::kTamImage, where));
  p.tamImage = e[fmt::kTamImage].get<int>();
  auto decoded = ktx2::decode(bytes, where.file + " " + where.element + " " + ext + ".tam (image " +
                                         std::to_string(p.tamImage) + ")");
  if (!decoded.isOk()) return invalidInput(ext + ".tam does not decode: " + decoded.status().message(), where);
  p.tam = std::move(decoded).value();
  BAKE_RETURN_IF_ERROR(checkTam(p.tam, p, where));

  if (e.contains(fmt::kThresholdImage)) {
    BAKE_ASSIGN_OR_RETURN(const std::span<const std::uint8_t> t, embeddedKtx2(package, e[fmt::kThresholdImage], fmt::kThresholdImage, where));
    auto threshold = ktx2::decode(t, where.file + " " + ext + ".threshold");
    if (!threshold.isOk()) return invalidInput(ext + ".threshold does not decode: " + threshold.status().message(), where);
    if (threshold->layers != 0 || threshold->format != ktx2::Format::R8 || threshold->width != p.tam.width ||
        threshold->height != p.tam.height || threshold->levels.size() != p.tam.levels.size()) {
      return invalidInput(ext + ".threshold must be a 2D R8_UNORM texture of the TAM's size and mip levels", where);
    }
    p.threshold = std::move(threshold).value();
  }
  return p;
}

Status checkHatchingPackage(const glb::Package& package, const std::string& name) {
  for (std::size_t i = 0; i < package.materials.size(); ++i) {
    const nlohmann::json& material = package.materials[i];
    if (!material.is_object() || !material.contains("extensions") || !material["extensions"].is_object()) continue;
    const nlohmann::json& extensions = material["extensions"];
    if (!extensions.contains(fmt::kExtension)) continue;
    BAKE_RETURN_IF_ERROR(parseHatching(extensions[fmt::kExtension], package, {name, "material " + std::to_string(i)}).status());
  }
  return {};
}

}  // namespace bake::hatching
