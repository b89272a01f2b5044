// The hatching technique's row in the registry (techniques/registry.h): the tonal art maps tambake
// writes, drawn by real-time hatching. bakeinfo describes every BAKE_hatching material through the
// package reader (so a damaged one is reported): the tones, the placement of the hatching on the
// surface, and the embedded TAM and threshold textures (format, size, layers, mip levels), with the
// darkness each tone's finest level actually holds.
#include <bake_formats/tam.h>

#include <cmath>
#include <numbers>

#include "hatching/bake/bake_stages.h"
#include "hatching/package/package_read.h"
#include "hatching/pipe/pipe.h"
#include "info/describe.h"
#include "techniques/registry.h"

namespace bake::techniques {
namespace {

using nlohmann::json;
namespace fmt = format::tam;

json textureJson(const ktx2::Texture& t) {
  return {{"format", ktx2::formatName(t.format)}, {"width", t.width}, {"height", t.height},
          {"layers", t.layers}, {"levels", t.levels.size()}};
}

Result<json> describeHatching(const glb::Package& package, const std::string& name) {
  json materials = json::array();
  for (const std::size_t m : materialsWith(package, fmt::kExtension)) {
    const json& material = package.materials[m];
    BAKE_ASSIGN_OR_RETURN(const hatching::HatchingParams p,
                          hatching::parseHatching(material["extensions"][fmt::kExtension], package,
                                                  {name, "material " + std::to_string(m)}));
    materials.push_back(
        {{"material", m},
         {"tones", p.tones},
         {"measuredDarkness", hatching::storedDarkness(p.tam, 0)},
         {"tilesPerUnit", p.tilesPerUnit},
         {"rotationDegrees", p.rotation * 180.0 / std::numbers::pi},
         {"translation", p.translation},
         {"orientation", p.orientation == hatching::HatchingOrientation::TowardLight ? fmt::kOrientationTowardLight
                                                                                      : fmt::kOrientationAcrossLight},
         {"baseColor", p.baseColor},
         {"tam", {{"image", p.tamImage}, {"texture", textureJson(p.tam)}}},
         {"threshold", p.threshold ? textureJson(*p.threshold) : json()}});
  }
  return json{{"materials", materials}};
}

std::string formatHatching(const json& d) {
  using info::numberText;
  using info::plural;
  using info::vectorText;
  std::string out;
  for (const json& m : d["materials"]) {
    const json& tam = m["tam"]["texture"];
    out += "  hatching (material " + std::to_string(m["material"].get<int>()) + "): TAM image " +
           std::to_string(m["tam"]["image"].get<int>()) + ", " + tam["format"].get<std::string>() + " " +
           std::to_string(tam["width"].get<int>()) + "x" + std::to_string(tam["height"].get<int>()) + ", " +
           plural(tam["layers"].get<std::size_t>(), "tone") + ", " + plural(tam["levels"].get<std::size_t>(), "mip level");
    if (!m["threshold"].is_null()) out += "; threshold texture " + m["threshold"]["format"].get<std::string>();
    out += "\n    tones (darkness asked / held by the finest level):";
    for (std::size_t t = 0; t < m["tones"].size(); ++t) {
      out += " " + numberText(m["tones"][t]);
      if (t < m["measuredDarkness"].size()) out += "/" + numberText(m["measuredDarkness"][t]);
    }
    out += "\n    tiles per unit " + numberText(m["tilesPerUnit"]) + ", rotated " + numberText(m["rotationDegrees"]) +
           " degrees, shifted " + vectorText(m["translation"]) + " tiles, strokes " +
           m["orientation"].get<std::string>() + ", base colour " + vectorText(m["baseColor"]) + "\n";
  }
  return out;
}

}  // namespace

Technique hatchingTechnique() {
  return {"hatching", format::tam::kExtension, "tambake", hatching::checkHatchingPackage,
          describeHatching, formatHatching, &hatching::pipeHooks()};
}

}  // namespace bake::techniques
