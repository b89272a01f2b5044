// The revolution technique's row in the registry (techniques/registry.h): shape maps revolbake writes.
// bakeinfo describes every BAKE_revolution material through the package reader (so a damaged one is
// reported): the shape map's layout and encoding, the safety margin and march, the proxy bands, the
// displacement and projection, the copies in the box and self-shadowing.
#include <bake_formats/revolution.h>

#include "info/describe.h"
#include "revolution/package/package_read.h"
#include "revolution/pipe/pipe.h"
#include "techniques/registry.h"

namespace bake::techniques {
namespace {

using nlohmann::json;
using revolution::RevolutionParams;

json replicasJson(const RevolutionParams::Replicas& r) {
  switch (r.layout) {
    case RevolutionParams::Replicas::Layout::One: return nullptr;
    case RevolutionParams::Replicas::Layout::Grid:
      return {{"layout", format::revolution::kLayoutGrid}, {"count", r.count}, {"spacing", r.spacing},
              {"mirror", r.mirror}, {"copies", r.total()}};
    case RevolutionParams::Replicas::Layout::Ring:
      return {{"layout", format::revolution::kLayoutRing}, {"count", r.ringCount}, {"radius", r.ringRadius},
              {"copies", r.total()}};
  }
  return nullptr;
}

json materialJson(std::size_t index, const RevolutionParams& p) {
  json displacement = nullptr;
  if (p.displacement)
    displacement = {{"width", p.displacement->width}, {"height", p.displacement->height},
                    {"derivativeScale", p.displacement->derivativeScale}, {"heightScale", p.displacement->heightScale}};
  return {{"material", index},
          {"shapeMap", {{"width", p.shapeMap.width}, {"height", p.shapeMap.height}, {"texelSize", p.shapeMap.texelSize},
                        {"hMin", p.shapeMap.hMin}, {"encoding", revolution::encodingName(p.shapeMap.encoding)},
                        {"distanceScale", p.shapeMap.distanceScale}}},
          {"safetyMargin", p.safetyMargin},
          {"march", {{"iterations", p.iterations}, {"overRelaxation", p.overRelaxation}, {"hitEpsilon", p.hitEpsilon}}},
          {"proxyBands", p.proxyBands.size()},
          {"displacementMap", displacement},
          {"projection", {{"type", revolution::projectionName(p.projection)}, {"repeat", p.repeat}}},
          {"arcLengthMap", p.arcLengthBufferView.has_value()},
          {"replicas", replicasJson(p.replicas)},
          {"selfShadow", p.selfShadow},
          {"box", {{"min", p.boxMin()}, {"max", p.boxMax()}}}};
}

Result<json> describeRevolution(const glb::Package& package, const std::string& name) {
  json materials = json::array();
  for (const std::size_t m : materialsWith(package, format::revolution::kExtension)) {
    const json& material = package.materials[m];
    BAKE_ASSIGN_OR_RETURN(const RevolutionParams p,
                          revolution::parseRevolution(material["extensions"][format::revolution::kExtension], package,
                                                      {name, "material " + std::to_string(m)}));
    materials.push_back(materialJson(m, p));
  }
  return json{{"materials", materials}};
}

std::string formatRevolution(const json& d) {
  using info::numberText;
  using info::plural;
  using info::vectorText;
  std::string out;
  for (const json& m : d["materials"]) {
    const json& map = m["shapeMap"];
    out += "  revolution (material " + std::to_string(m["material"].get<int>()) + "): shape map " +
           std::to_string(map["width"].get<int>()) + "x" + std::to_string(map["height"].get<int>()) + " " +
           map["encoding"].get<std::string>() + ", texel " + numberText(map["texelSize"]) + ", h from " +
           numberText(map["hMin"]) + "\n";
    out += "    march: " + std::to_string(m["march"]["iterations"].get<int>()) + " iterations, over-relaxation " +
           numberText(m["march"]["overRelaxation"]) + ", safety margin " + numberText(m["safetyMargin"]) + ", " +
           plural(m["proxyBands"].get<std::size_t>(), "proxy band") + "\n";
    out += "    projection " + m["projection"]["type"].get<std::string>() + " repeated " +
           vectorText(m["projection"]["repeat"]);
    if (!m["displacementMap"].is_null())
      out += ", displacement map " + std::to_string(m["displacementMap"]["width"].get<int>()) + "x" +
             std::to_string(m["displacementMap"]["height"].get<int>());
    out += "\n";
    const json& r = m["replicas"];
    if (!r.is_null()) {
      out += "    copies: " + std::to_string(r["copies"].get<int>()) + " in a " + r["layout"].get<std::string>();
      if (r["layout"] == format::revolution::kLayoutGrid) {
        out += " " + vectorText(r["count"]) + " spaced " + vectorText(r["spacing"]);
        const json& mirror = r["mirror"];
        std::string axes;
        for (std::size_t a = 0; a < 3; ++a)
          if (mirror[a].get<bool>()) axes += "xyz"[a];
        if (!axes.empty()) out += ", mirrored along " + axes;
      } else {
        out += " of radius " + numberText(r["radius"]);
      }
      out += "\n";
    }
    out += std::string("    self-shadowing ") + (m["selfShadow"].get<bool>() ? "on" : "off") + "; box " +
           vectorText(m["box"]["min"]) + " - " + vectorText(m["box"]["max"]) + "\n";
  }
  return out;
}

}  // namespace

Technique revolutionTechnique() {
  return {"revolution", format::revolution::kExtension, "revolbake", revolution::checkRevolutionPackage,
          describeRevolution, formatRevolution, &revolution::pipeHooks()};
}

}  // namespace bake::techniques
