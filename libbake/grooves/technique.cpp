// The grooves technique's row in the registry (techniques/registry.h): the groove grids groovebake
// writes. bakeinfo describes every BAKE_grooves material through the package decoder (so a damaged one
// is reported): the domain and its wrapping, the grid and the far level (cells and cell size), the
// grooves' extent (wmax, hmax, dmax), and the stored records: grooves, profiles, materials,
// primitives, special-case records and the grid's references to them.
#include <bake_formats/grooves.h>

#include "grooves/package/package.h"
#include "grooves/pipe/pipe.h"
#include "info/describe.h"
#include "techniques/registry.h"

namespace bake::techniques {
namespace {

using nlohmann::json;
namespace fmt = format::grooves;

Result<json> describeGrooves(const glb::Package& package, const std::string& name) {
  json materials = json::array();
  for (const std::size_t m : materialsWith(package, fmt::kExtension)) {
    const json& material = package.materials[m];
    BAKE_ASSIGN_OR_RETURN(const grooves::GroovePackage p,
                          grooves::decodeGrooveExtension(package, material["extensions"][fmt::kExtension], name));
    const grooves::GroovePackageHeader& h = p.header;
    materials.push_back({{"material", m},
                         {"version", h.version},
                         {"units", h.units},
                         {"domain", {h.domain[0], h.domain[1]}},
                         {"wrap", h.wrapRepeat ? "repeat" : "none"},
                         {"grid", {{"cells", {h.cells[0], h.cells[1]}}, {"cellSize", {h.cellSize[0], h.cellSize[1]}}}},
                         {"far", {{"cells", {h.farCells[0], h.farCells[1]}}, {"cellSize", {h.farCellSize[0], h.farCellSize[1]}},
                                  {"classes", p.farClasses.size()}}},
                         {"wmax", h.wmax},
                         {"hmax", h.hmax},
                         {"dmax", h.dmax},
                         {"grooves", p.grooves.size()},
                         {"profiles", h.profileNames},
                         {"materials", h.materialNames},
                         {"baseMaterial", h.baseMaterial},
                         {"primitives", p.primitives.size()},
                         {"primitiveRefs", p.primitiveRefs.size()},
                         {"records", p.records.size()},
                         {"recordRefs", p.recordRefs.size()}});
  }
  return json{{"materials", materials}};
}

std::string namesText(const json& names) {
  std::string out;
  for (const json& n : names) out += (out.empty() ? "" : ", ") + n.get<std::string>();
  return out;
}

std::string formatGrooves(const json& d) {
  using info::numberText;
  using info::plural;
  using info::vectorText;
  std::string out;
  for (const json& m : d["materials"]) {
    const std::string units = " " + m["units"].get<std::string>();
    out += "  grooves (material " + std::to_string(m["material"].get<int>()) + ", version " +
           std::to_string(m["version"].get<int>()) + "): domain " + vectorText(m["domain"]) + units + ", wrap " +
           m["wrap"].get<std::string>() + "\n";
    out += "    grid " + std::to_string(m["grid"]["cells"][0].get<int>()) + "x" + std::to_string(m["grid"]["cells"][1].get<int>()) +
           " cells of " + vectorText(m["grid"]["cellSize"]) + units;
    if (m["far"]["cells"][0].get<int>() > 0)
      out += "; far level " + std::to_string(m["far"]["cells"][0].get<int>()) + "x" +
             std::to_string(m["far"]["cells"][1].get<int>()) + " cells, " +
             plural(m["far"]["classes"].get<std::size_t>(), "class");
    out += "\n    widest " + numberText(m["wmax"]) + ", highest " + numberText(m["hmax"]) + ", deepest " +
           numberText(m["dmax"]) + units + "\n";
    out += "    " + plural(m["grooves"].get<std::size_t>(), "groove") + ", " +
           plural(m["primitives"].get<std::size_t>(), "primitive") + " (" +
           plural(m["primitiveRefs"].get<std::size_t>(), "cell reference") + "), " +
           plural(m["records"].get<std::size_t>(), "special-case record") + " (" +
           plural(m["recordRefs"].get<std::size_t>(), "cell reference") + ")\n";
    out += "    profiles: " + namesText(m["profiles"]) + "; materials: " + namesText(m["materials"]) + " (base: " +
           std::to_string(m["baseMaterial"].get<int>()) + ")\n";
  }
  return out;
}

}  // namespace

Technique groovesTechnique() {
  return {"grooves", format::grooves::kExtension, "groovebake", grooves::checkGroovesPackage,
          describeGrooves, formatGrooves, &grooves::pipeHooks()};
}

}  // namespace bake::techniques
