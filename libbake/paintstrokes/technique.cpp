// The paintstrokes technique's row in the registry (techniques/registry.h): the stroke sets strokebake
// writes. bakeinfo describes a package's strokes through the package reader, so a damaged one is
// reported.
#include <bake_formats/paintstrokes.h>

#include "info/describe.h"
#include "paintstrokes/package/package.h"
#include "paintstrokes/pipe/pipe.h"
#include "techniques/registry.h"

namespace bake::techniques {
namespace {

Result<nlohmann::json> describePaintstrokes(const glb::Package& package, const std::string& name) {
  BAKE_ASSIGN_OR_RETURN(const paintstrokes::PaintstrokePackage p, paintstrokes::decodePaintstrokePackage(package, name));
  return nlohmann::json{{"strokes", p.strokes.size()},
                        {"controlPoints", p.points.size()},
                        {"styles", p.styleNames},
                        {"shadowDirections", p.shadowDirections},
                        {"bounds", {{"min", p.boundsMin}, {"max", p.boundsMax}}}};
}

std::string formatPaintstrokes(const nlohmann::json& p) {
  using info::plural;
  using info::vectorText;
  std::string out = "  paintstrokes: " + plural(p["strokes"].get<std::size_t>(), "stroke") + ", " +
                    plural(p["controlPoints"].get<std::size_t>(), "control point") + ", " +
                    plural(p["styles"].size(), "style") + ":";
  for (const nlohmann::json& name : p["styles"]) out += " " + name.get<std::string>();
  out += "\n    shadow directions: " + std::to_string(p["shadowDirections"].size());
  for (const nlohmann::json& direction : p["shadowDirections"]) out += " " + vectorText(direction);
  out += "\n    bounds " + vectorText(p["bounds"]["min"]) + " - " + vectorText(p["bounds"]["max"]) + "\n";
  return out;
}

}  // namespace

Technique paintstrokesTechnique() {
  return {"paintstrokes", format::paintstrokes::kExtension, "strokebake", paintstrokes::checkPaintstrokePackage,
          describePaintstrokes, formatPaintstrokes, &paintstrokes::pipeHooks()};
}

}  // namespace bake::techniques
