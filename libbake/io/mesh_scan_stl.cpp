// Pre-scan of STL files: binary when the size matches the triangle count in the header (OpenMesh's
// own rule), ASCII otherwise. Binary corners must be finite, because OpenMesh maps positions to
// vertices with a comparison that treats NaN as equal to anything. ASCII files are checked against
// the solid / facet normal / outer loop / vertex grammar line by line, and 'outer' anywhere but an
// 'outer loop' line is refused, as OpenMesh starts a triangle at any line containing it. OpenMesh
// merges equal positions and drops triangles with two equal corners; the triangle count found here
// lets readMesh count the difference as removed degenerate faces.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "io/mesh_scan.h"

namespace bake::meshscan {
namespace fs = std::filesystem;

namespace {

bool equalsIgnoringCase(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

constexpr std::size_t kStlHeaderBytes = 84;
constexpr std::size_t kStlTriangleBytes = 50;

std::optional<std::uint32_t> binaryStlTriangleCount(std::string_view bytes) {
  if (bytes.size() < kStlHeaderBytes) return std::nullopt;
  std::uint32_t count = 0;
  std::memcpy(&count, bytes.data() + 80, 4);  // little-endian, like this machine
  return count;
}

// OpenMesh maps positions to vertices with a comparison that treats NaN as equal to anything, so a
// non-finite corner would silently become some other vertex: reject them before.
Result<Prescan> prescanBinaryStl(std::string_view bytes, const fs::path& path) {
  const std::uint32_t count = *binaryStlTriangleCount(bytes);
  for (std::uint32_t t = 0; t < count; ++t) {
    const char* corners = bytes.data() + kStlHeaderBytes + std::size_t(t) * kStlTriangleBytes + 12;
    for (int i = 0; i < 9; ++i) {
      float value;
      std::memcpy(&value, corners + 4 * i, 4);
      if (!std::isfinite(value)) {
        return invalidInput("corner coordinate is not finite",
                            {path.string(), "triangle " + std::to_string(t)});
      }
    }
  }
  Prescan scan;
  scan.stlTriangles = count;
  return scan;
}

// The ASCII grammar as a sequence of expected keywords per line.
enum class StlState { Solid, FacetOrEnd, OuterLoop, Vertex, EndLoop, EndFacet, AfterEnd };

Status stlExpected(const fs::path& path, const TextLine& line, const char* expected) {
  return lineError(path, line.number,
                   std::string("expected '") + expected + "', found " + inQuotes(line.text.substr(0, 40)));
}

Result<Prescan> prescanAsciiStl(std::string_view text, const fs::path& path) {
  Prescan scan;
  scan.stlTriangles = 0;
  StlState state = StlState::Solid;
  int cornersSeen = 0;
  LineCursor lines(text);
  TextLine line;
  while (lines.nextContent(line, false)) {
    const std::vector<std::string_view> words = splitWords(line.text);
    const std::string_view keyword = words[0];
    auto is = [&](std::string_view expected) { return equalsIgnoringCase(keyword, expected); };
    const bool isLoopLine = is("outer") && words.size() == 2 && equalsIgnoringCase(words[1], "loop");
    if (!isLoopLine && (line.text.find("outer") != std::string_view::npos ||
                        line.text.find("OUTER") != std::string_view::npos)) {
      // OpenMesh starts a triangle at any line containing "outer", e.g. in a solid's name.
      return lineUnsupported(path, line.number,
                             "'outer' outside an 'outer loop' line confuses the STL reader");
    }
    switch (state) {
      case StlState::Solid:
      case StlState::AfterEnd:
        if (!is("solid")) return stlExpected(path, line, "solid");
        state = StlState::FacetOrEnd;
        break;
      case StlState::FacetOrEnd:
        if (is("endsolid")) {
          state = StlState::AfterEnd;
          break;
        }
        if (!is("facet") || words.size() != 5 || !equalsIgnoringCase(words[1], "normal")) {
          return stlExpected(path, line, "facet normal NX NY NZ");
        }
        BAKE_RETURN_IF_ERROR(checkNumbers(path, line, words, 2, 3, 0, "normal component"));
        state = StlState::OuterLoop;
        break;
      case StlState::OuterLoop:
        if (!isLoopLine) return stlExpected(path, line, "outer loop");
        state = StlState::Vertex;
        cornersSeen = 0;
        break;
      case StlState::Vertex:
        if (is("endloop")) {
          return lineError(
              path, line.number,
              "facet has " + std::to_string(cornersSeen) + " vertices; STL facets are triangles");
        }
        if (!is("vertex") || words.size() != 4) return stlExpected(path, line, "vertex X Y Z");
        BAKE_RETURN_IF_ERROR(checkNumbers(path, line, words, 1, 3, 3, "vertex coordinate"));
        if (++cornersSeen == 3) state = StlState::EndLoop;
        break;
      case StlState::EndLoop:
        if (!is("endloop")) {
          return lineError(path, line.number, "expected 'endloop': STL facets are triangles");
        }
        state = StlState::EndFacet;
        break;
      case StlState::EndFacet:
        if (!is("endfacet")) return stlExpected(path, line, "endfacet");
        ++*scan.stlTriangles;
        state = StlState::FacetOrEnd;
        break;
    }
  }
  // A missing final "endsolid" is common in exported files and harmless; a cut facet is not.
  if (state != StlState::FacetOrEnd && state != StlState::AfterEnd) {
    return lineError(path, lines.lineNumber(), "the file ends inside a facet");
  }
  return scan;
}

}  // namespace

bool isBinaryStl(std::string_view bytes) {
  const std::optional<std::uint32_t> count = binaryStlTriangleCount(bytes);
  return count && bytes.size() == kStlHeaderBytes + std::uint64_t(*count) * kStlTriangleBytes;
}

Result<Prescan> prescanStl(std::string_view bytes, const fs::path& path) {
  if (isBinaryStl(bytes)) return prescanBinaryStl(bytes, path);
  if (equalsIgnoringCase(firstWord(trimmed(bytes.substr(0, 64))), "solid")) {
    return prescanAsciiStl(bytes, path);
  }
  if (const std::optional<std::uint32_t> count = binaryStlTriangleCount(bytes)) {
    return invalidInput("neither ASCII STL (no 'solid' at the start) nor binary STL: the header declares " +
                            std::to_string(*count) + " triangles (" +
                            std::to_string(kStlHeaderBytes + std::uint64_t(*count) * kStlTriangleBytes) +
                            " bytes) but the file has " + std::to_string(bytes.size()) + " bytes",
                        {path.string(), ""});
  }
  return invalidInput("too short for binary STL and not ASCII STL (no 'solid' at the start)",
                      {path.string(), ""});
}

}  // namespace bake::meshscan
