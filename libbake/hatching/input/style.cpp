// The style reader (hatching/style.h; formats/tam.md "Style file", formats/tam-style.schema.json). A style
// is one JSON object; every field has a default, so "{}" is a valid style. Validation is strict,
// because a typo in a key would otherwise bake the default silently: unknown keys are errors (with the
// nearest known key as a suggestion), and every error names the file and the JSON pointer of the
// element at fault ("/stroke/width/min"). `tones` is either a list of target darkness values,
// strictly increasing in (0, 1), or a count N, which means the evenly spaced darkness
// 0.9 (k + 1) / N for k = 0 .. N - 1: the lightest tone is 0.9 / N, the darkest 0.9, which keeps the
// darkest layer short of solid ink so its strokes still read as strokes. The stroke image of the
// `image` kind is resolved against the style file's folder and read as ink alpha: its alpha channel
// when it has one, else the darkness (1 - grey) of its first channels.
#include "bake/hatching/style.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "bake/core/atomic_file.h"
#include "bake/io/image.h"
#include "bake_formats/tam.h"
#include "core/json_keys.h"
#include "core/json_read.h"

namespace bake::hatching {
namespace {

using nlohmann::json;

constexpr double kEvenDarkest = 0.9;  // darkest tone of an evenly spaced `tones: N`

std::string jsonPointer(const std::string& parent, const std::string& key) { return jsonPointerChild(parent, key); }

// Reads the fields of one JSON object, each checked, each error located by its JSON pointer.
class ObjectReader {
 public:
  ObjectReader(const json& object, std::string pointer, const std::string& file)
      : object_(object), pointer_(std::move(pointer)), file_(file) {}

  Status checkObject() const {
    if (!object_.is_object()) return error(pointer_, "must be a JSON object");
    return {};
  }
  // Every key of the object must be one of `known`.
  Status checkKeys(std::initializer_list<const char*> known) const {
    if (const auto unknown = findUnknownKey(object_, known)) return error(jsonPointer(pointer_, unknown->key), unknown->message);
    return {};
  }

  bool has(const char* key) const { return object_.contains(key); }
  const json& at(const char* key) const { return object_.at(key); }
  std::string pointer(const char* key) const { return jsonPointer(pointer_, key); }

  // A finite number within [lo, hi] (or (lo, hi] when `openLow`), left unchanged when absent.
  Status number(const char* key, double& out, double lo, double hi, bool openLow = false) const {
    if (!has(key)) return {};
    const json& value = at(key);
    if (!value.is_number()) return error(pointer(key), "must be a number");
    const double x = value.get<double>();
    if (!std::isfinite(x)) return error(pointer(key), "must be a finite number");
    if (openLow ? !(x > lo) : !(x >= lo)) return error(pointer(key), "is " + show(x) + ", must be " + (openLow ? "> " : ">= ") + show(lo));
    if (!(x <= hi)) return error(pointer(key), "is " + show(x) + ", must be <= " + show(hi));
    out = x;
    return {};
  }

  Status integer(const char* key, long long& out, long long lo, long long hi) const {
    if (!has(key)) return {};
    const json& value = at(key);
    if (!value.is_number_integer()) return error(pointer(key), "must be an integer");
    if (value.is_number_unsigned() && value.get<std::uint64_t>() > std::uint64_t(std::numeric_limits<long long>::max()))
      return error(pointer(key), "is too large, must be <= " + std::to_string(hi));
    const long long x = value.get<long long>();
    if (x < lo || x > hi)
      return error(pointer(key), "is " + std::to_string(x) + ", must be within " + std::to_string(lo) + " .. " + std::to_string(hi));
    out = x;
    return {};
  }

  Status range(const char* key, Range& out, double lo, double hi, bool openLow) const {
    if (!has(key)) return {};
    ObjectReader inner(at(key), pointer(key), file_);
    BAKE_RETURN_IF_ERROR(inner.checkObject());
    BAKE_RETURN_IF_ERROR(inner.checkKeys({"min", "max"}));
    BAKE_RETURN_IF_ERROR(inner.number("min", out.min, lo, hi, openLow));
    BAKE_RETURN_IF_ERROR(inner.number("max", out.max, lo, hi, openLow));
    if (!(out.min <= out.max))
      return error(pointer(key), "min " + show(out.min) + " is greater than max " + show(out.max));
    return {};
  }

  Status error(const std::string& where, const std::string& message) const {
    return invalidInput(message, {file_, where.empty() ? "/" : where});
  }

  static std::string show(double x) {
    std::ostringstream out;
    out << x;
    return out.str();
  }

 private:
  const json& object_;
  std::string pointer_;
  const std::string& file_;
};

Status readTones(const ObjectReader& root, Style& style) {
  if (!root.has("tones")) return {};
  const json& tones = root.at("tones");
  const std::string where = root.pointer("tones");
  const int maxTones = format::tam::kMaxTones;
  if (tones.is_number_integer()) {
    long long count = 0;
    BAKE_RETURN_IF_ERROR(root.integer("tones", count, 1, maxTones));
    style.tones.clear();
    for (long long k = 0; k < count; ++k) style.tones.push_back(kEvenDarkest * double(k + 1) / double(count));
    return {};
  }
  if (!tones.is_array()) return root.error(where, "must be a tone count or a list of darkness values");
  if (tones.empty()) return root.error(where, "needs at least one tone");
  if (tones.size() > std::size_t(maxTones))
    return root.error(where, "has " + std::to_string(tones.size()) + " tones, at most " + std::to_string(maxTones) + " are allowed");
  style.tones.clear();
  for (std::size_t k = 0; k < tones.size(); ++k) {
    const std::string element = where + "/" + std::to_string(k);
    if (!tones[k].is_number()) return root.error(element, "must be a number");
    const double t = tones[k].get<double>();
    if (!(t > 0 && t < 1)) return root.error(element, "is " + ObjectReader::show(t) + ", a tone's darkness must be within (0, 1)");
    if (k > 0 && !(t > style.tones.back()))
      return root.error(element, "is " + ObjectReader::show(t) + ", tones must be strictly increasing (the previous is " +
                                     ObjectReader::show(style.tones.back()) + ")");
    style.tones.push_back(t);
  }
  return {};
}

Result<StrokeKind> kindOf(const ObjectReader& reader) {
  if (!reader.has("kind")) return StrokeKind::Hatching;
  const json& value = reader.at("kind");
  for (StrokeKind kind : {StrokeKind::Hatching, StrokeKind::CrossHatching, StrokeKind::Stippling, StrokeKind::Image})
    if (value.is_string() && value.get<std::string>() == strokeKindName(kind)) return kind;
  return reader.error(reader.pointer("kind"), "is " + value.dump() +
                                                  ", must be one of \"hatching\", \"cross-hatching\", \"stippling\", \"image\"");
}

// The stroke image as ink alpha (see the file comment).
Result<stroke::StrokeTexture> loadStrokeImage(const std::string& path, const std::string& styleFile, const std::string& pointer) {
  // Read once through the bounded reader, like every input: a pipe or a device is read as far as it
  // goes, a directory or a missing file is refused there.
  Result<Image> read = readImage(path);
  if (!read.isOk()) {
    // The style's element names the image; the image's own reason follows.
    return Status(read.status().code(), "the stroke image " + read.status().describe(), {styleFile, pointer});
  }
  const Image& image = read.value();
  if (image.width < 2 || image.height < 1 || image.channels < 1)
    return invalidInput("the stroke image " + path + " must be at least 2 x 1 pixels", {styleFile, pointer});
  stroke::StrokeTexture texture;
  texture.width = image.width;
  texture.height = image.height;
  texture.alpha.resize(std::size_t(image.width) * std::size_t(image.height));
  const bool hasAlpha = image.channels == 2 || image.channels == 4;
  const int greyChannels = hasAlpha ? image.channels - 1 : std::min(image.channels, 3);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      float a;
      if (hasAlpha) {
        a = image.at(x, y, image.channels - 1);
      } else {
        float grey = 0;
        for (int c = 0; c < greyChannels; ++c) grey += image.at(x, y, c);
        a = 1.0f - grey / float(greyChannels);
      }
      if (!std::isfinite(a)) return invalidInput("the stroke image holds a value that is not finite", {path, "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ")"});
      texture.alpha[std::size_t(y) * image.width + x] = std::clamp(a, 0.0f, 1.0f);
    }
  }
  if (*std::max_element(texture.alpha.begin(), texture.alpha.end()) <= 0.0f)
    return invalidInput("the stroke image holds no ink (alpha 0, or white without alpha, everywhere)", {path, ""});
  return texture;
}

Status readStroke(const ObjectReader& root, const std::string& baseDir, bool loadImage, Style& style) {
  if (!root.has("stroke")) return {};
  ObjectReader reader(root.at("stroke"), root.pointer("stroke"), style.source);
  BAKE_RETURN_IF_ERROR(reader.checkObject());
  BAKE_RETURN_IF_ERROR(reader.checkKeys({"kind", "length", "width", "angle", "angleJitter", "curvature", "crossFrom",
                                         "crossAngle", "colour", "opacity", "centreOpacity", "edgeOpacity", "taper",
                                         "image"}));
  StrokeStyle& s = style.stroke;
  BAKE_ASSIGN_OR_RETURN(s.kind, kindOf(reader));
  BAKE_RETURN_IF_ERROR(reader.range("length", s.length, 0, 1, true));
  BAKE_RETURN_IF_ERROR(reader.range("width", s.width, 0, 1024, true));
  BAKE_RETURN_IF_ERROR(reader.number("angle", s.angleDegrees, -360, 360));
  BAKE_RETURN_IF_ERROR(reader.number("angleJitter", s.angleJitterDegrees, 0, 180));
  BAKE_RETURN_IF_ERROR(reader.number("curvature", s.curvature, -1, 1));
  BAKE_RETURN_IF_ERROR(reader.number("crossAngle", s.crossAngleDegrees, -180, 180));
  BAKE_RETURN_IF_ERROR(reader.number("opacity", s.opacity, 0, 1, true));
  BAKE_RETURN_IF_ERROR(reader.number("centreOpacity", s.centreOpacity, 0, 1));
  BAKE_RETURN_IF_ERROR(reader.number("edgeOpacity", s.edgeOpacity, 0, 1));
  BAKE_RETURN_IF_ERROR(reader.number("taper", s.taper, 0, 0.5));
  if (s.centreOpacity == 0 && s.edgeOpacity == 0)
    return reader.error(reader.pointer(reader.has("centreOpacity") ? "centreOpacity" : "edgeOpacity"),
                        "centreOpacity and edgeOpacity are both 0: the strokes would carry no ink");
  if (reader.has("colour")) {
    const json& colour = reader.at("colour");
    if (!colour.is_array() || colour.size() != 3) return reader.error(reader.pointer("colour"), "must be [R, G, B]");
    for (int c = 0; c < 3; ++c) {
      const std::string element = reader.pointer("colour") + "/" + std::to_string(c);
      if (!colour[c].is_number()) return reader.error(element, "must be a number");
      const double v = colour[c].get<double>();
      if (!(v >= 0 && v <= 1)) return reader.error(element, "is " + ObjectReader::show(v) + ", must be within [0, 1]");
      s.colour[c] = v;
    }
  }
  const long long tones = static_cast<long long>(style.tones.size());
  if (reader.has("crossFrom")) {
    if (s.kind != StrokeKind::CrossHatching)
      return reader.error(reader.pointer("crossFrom"), "applies only to the \"cross-hatching\" kind");
    long long crossFrom = 0;
    BAKE_RETURN_IF_ERROR(reader.integer("crossFrom", crossFrom, 0, tones - 1));
    s.crossFrom = int(crossFrom);
  } else if (s.kind == StrokeKind::CrossHatching) {
    s.crossFrom = int(tones / 2);  // the darker half of the tones crosses
  }
  if (reader.has("image")) {
    if (s.kind != StrokeKind::Image) return reader.error(reader.pointer("image"), "applies only to the \"image\" kind");
    if (!reader.at("image").is_string() || reader.at("image").get<std::string>().empty())
      return reader.error(reader.pointer("image"), "must be the path of an image file");
    const std::filesystem::path image(reader.at("image").get<std::string>());
    s.image = (image.is_absolute() || baseDir.empty() ? image : std::filesystem::path(baseDir) / image).lexically_normal().string();
    if (loadImage) {
      BAKE_ASSIGN_OR_RETURN(s.texture, loadStrokeImage(s.image, style.source, reader.pointer("image")));
    }
  } else if (s.kind == StrokeKind::Image) {
    return reader.error(reader.pointer("kind"), "the \"image\" kind needs \"image\": the path of the stroke image");
  }
  return {};
}

}  // namespace

const char* strokeKindName(StrokeKind kind) {
  switch (kind) {
    case StrokeKind::Hatching: return "hatching";
    case StrokeKind::CrossHatching: return "cross-hatching";
    case StrokeKind::Stippling: return "stippling";
    case StrokeKind::Image: return "image";
  }
  return "hatching";
}

bool Style::coloured() const { return stroke.colour[0] != 0 || stroke.colour[1] != 0 || stroke.colour[2] != 0; }

std::vector<std::string> Style::inputs() const {
  std::vector<std::string> files;
  if (!source.empty()) files.push_back(source);
  if (stroke.kind == StrokeKind::Image && !stroke.image.empty()) files.push_back(stroke.image);
  return files;
}

int defaultLevels(int resolution) {
  int log2 = 0;
  while ((1 << log2) < resolution && log2 < 30) ++log2;
  return std::clamp(log2 - 2, 1, 4);
}

namespace {
Status validateSizes(const Style& style, const std::string& resolutionWhere, const std::string& levelsWhere) {
  const int r = style.resolution;
  if (r < 8 || r > 4096 || (r & (r - 1)) != 0)
    return invalidInput("resolution is " + std::to_string(r) + ", must be a power of two within 8 .. 4096",
                        {style.source, resolutionWhere});
  int log2 = 0;
  while ((1 << log2) < r) ++log2;
  if (style.levels < 1 || style.levels > log2)
    return invalidInput("levels is " + std::to_string(style.levels) + ", must be within 1 .. " + std::to_string(log2) +
                            " (log2 of the resolution " + std::to_string(r) + ")",
                        {style.source, levelsWhere});
  return {};
}
}  // namespace

Status setResolution(Style& style, int resolution, const std::string& where) {
  style.resolution = resolution;
  if (!style.levelsGiven) style.levels = defaultLevels(resolution);
  Status status = validateSizes(style, where, style.levelsGiven ? "/levels" : where);
  if (!status.isOk()) return Status(ExitCode::Usage, where + ": " + status.message());
  return {};
}

Result<Style> parseStyle(const std::string& jsonText, const std::string& source, const std::string& baseDir, bool loadImage) {
  BAKE_ASSIGN_OR_RETURN(json document, parseJsonText(jsonText, source, "malformed JSON"));
  Style style;
  style.source = source;
  style.tones.clear();
  for (int k = 0; k < 6; ++k) style.tones.push_back(kEvenDarkest * double(k + 1) / 6.0);  // "tones": 6
  ObjectReader root(document, "", source);
  BAKE_RETURN_IF_ERROR(root.checkObject());
  BAKE_RETURN_IF_ERROR(root.checkKeys({"$schema", "description", "tones", "resolution", "levels", "stroke", "candidates",
                                       "blurSigma", "seed"}));
  if (root.has("$schema") && !root.at("$schema").is_string()) return root.error("/$schema", "must be a string");
  if (root.has("description") && !root.at("description").is_string()) return root.error("/description", "must be a string");
  BAKE_RETURN_IF_ERROR(readTones(root, style));
  long long value = 0;
  if (root.has("resolution")) {
    BAKE_RETURN_IF_ERROR(root.integer("resolution", value, 1, 1 << 30));
    style.resolution = int(value);
  }
  if (root.has("levels")) {
    BAKE_RETURN_IF_ERROR(root.integer("levels", value, 1, 64));
    style.levels = int(value);
    style.levelsGiven = true;
  } else {
    style.levels = defaultLevels(style.resolution);
  }
  BAKE_RETURN_IF_ERROR(validateSizes(style, "/resolution", "/levels"));
  if (root.has("candidates")) {
    BAKE_RETURN_IF_ERROR(root.integer("candidates", value, 1, 4096));
    style.candidates = int(value);
  }
  BAKE_RETURN_IF_ERROR(root.number("blurSigma", style.blurSigma, 0, 64));
  if (root.has("seed")) {
    const json& seed = root.at("seed");
    if (!seed.is_number_integer() || (!seed.is_number_unsigned() && seed.get<long long>() < 0))
      return root.error("/seed", "must be a non-negative integer");
    style.seed = seed.get<std::uint64_t>();
  }
  BAKE_RETURN_IF_ERROR(readStroke(root, baseDir, loadImage, style));
  return style;
}

Result<Style> parseStyle(const std::string& jsonText, const std::string& source, const std::string& baseDir) {
  return parseStyle(jsonText, source, baseDir, true);
}

Result<Style> readStyle(const std::string& path, bool loadImage) {
  // readFileBytes refuses a directory (an ifstream reads one as an empty file).
  BAKE_ASSIGN_OR_RETURN(const std::vector<std::uint8_t> bytes, readFileBytes(path));
  return parseStyle(std::string(bytes.begin(), bytes.end()), path, std::filesystem::path(path).parent_path().string(), loadImage);
}

Result<Style> readStyle(const std::string& path) { return readStyle(path, true); }

}  // namespace bake::hatching
