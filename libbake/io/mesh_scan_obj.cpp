// Pre-scan of OBJ files, run before OpenMesh's OBJ reader: v/vt/vn value counts and finiteness,
// face corners and index ranges. OpenMesh reports almost nothing about malformed input (a bad
// number just desynchronises its stream), so the first malformed line is named here instead. Faces
// with fewer than three corners are errors; faces with fewer than three distinct vertices are
// dropped by OpenMesh's reader before our importer sees them, so they are counted here
// (Prescan::degenerateFaces).
#include <algorithm>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/mesh_scan.h"

namespace bake::meshscan {
namespace fs = std::filesystem;

namespace {

struct ObjTotals {
  std::size_t positions = 0;
  std::size_t texcoords = 0;
  std::size_t normals = 0;
};

// Positive OBJ indices may refer to elements defined further down (OpenMesh reads all of them first),
// so the ranges need the totals up front.
ObjTotals countObjElements(std::string_view text) {
  ObjTotals totals;
  LineCursor lines(text);
  TextLine line;
  while (lines.nextContent(line, true)) {
    const std::string_view keyword = firstWord(line.text);
    if (keyword == "v") ++totals.positions;
    if (keyword == "vt") ++totals.texcoords;
    if (keyword == "vn") ++totals.normals;
  }
  return totals;
}

// One face corner "v", "v/t", "v//n" or "v/t/n"; absent parts are 0 (never a valid OBJ index).
struct ObjCorner {
  long long position = 0;
  long long texcoord = 0;
  long long normal = 0;
};

std::optional<ObjCorner> parseObjCorner(std::string_view word) {
  std::vector<std::string_view> parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t slash = word.find('/', start);
    parts.push_back(
        word.substr(start, slash == std::string_view::npos ? std::string_view::npos : slash - start));
    if (slash == std::string_view::npos) break;
    start = slash + 1;
  }
  if (parts.size() > 3 || parts[0].empty() || parts.back().empty()) return std::nullopt;
  ObjCorner corner;
  long long* fields[3] = {&corner.position, &corner.texcoord, &corner.normal};
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (parts[i].empty()) continue;  // "v//n"
    const std::optional<long long> value = parseInteger(parts[i]);
    if (!value) return std::nullopt;
    *fields[i] = *value;
  }
  return corner;
}

// Resolves a 1-based or negative (relative: -1 = latest so far) OBJ index to 0-based, or explains why
// it is out of range.
std::optional<std::string> objIndexProblem(long long index, std::size_t definedSoFar, std::size_t total,
                                           const char* what) {
  if (index == 0) return std::string(what) + " index 0 is invalid (OBJ indices start at 1)";
  if (index > 0 && std::size_t(index) > total) {
    return std::string(what) + " index " + std::to_string(index) + " is out of range (the file has " +
           std::to_string(total) + ")";
  }
  if (index < 0 && std::size_t(-(index + 1)) >= definedSoFar) {
    return "relative " + std::string(what) + " index " + std::to_string(index) +
           " reaches before the first one (" + std::to_string(definedSoFar) + " defined so far)";
  }
  return std::nullopt;
}

long long resolveObjIndex(long long index, std::size_t definedSoFar) {
  return index > 0 ? index - 1 : (long long)definedSoFar + index;
}

Status checkObjValueCount(const fs::path& path, const TextLine& line, std::size_t found,
                          std::initializer_list<std::size_t> allowed, const char* expected) {
  if (std::find(allowed.begin(), allowed.end(), found) != allowed.end()) return {};
  return lineError(path, line.number,
                   "expected " + std::string(expected) + ", found " + std::to_string(found) + " values");
}

std::size_t distinctCount(std::vector<long long> values) {
  std::sort(values.begin(), values.end());
  return std::size_t(std::unique(values.begin(), values.end()) - values.begin());
}

Status scanObjFace(const fs::path& path, const TextLine& line, const std::vector<std::string_view>& words,
                   const ObjTotals& soFar, const ObjTotals& totals, Prescan& scan) {
  const std::size_t cornerCount = words.size() - 1;
  if (cornerCount < 3) {
    return lineError(path, line.number,
                     "face has " + std::to_string(cornerCount) + " vertices; at least 3 are needed");
  }
  std::vector<long long> positions;
  for (std::size_t i = 1; i < words.size(); ++i) {
    const std::optional<ObjCorner> corner = parseObjCorner(words[i]);
    if (!corner) {
      return lineError(path, line.number,
                       "face corner " + inQuotes(words[i]) +
                           " is not of the form v, v/t, v//n or v/t/n with integer indices");
    }
    std::optional<std::string> problem =
        objIndexProblem(corner->position, soFar.positions, totals.positions, "vertex");
    if (!problem && corner->texcoord != 0) {
      problem = objIndexProblem(corner->texcoord, soFar.texcoords, totals.texcoords, "texture coordinate");
    }
    if (!problem && corner->normal != 0) {
      problem = objIndexProblem(corner->normal, soFar.normals, totals.normals, "normal");
    }
    if (problem) return lineError(path, line.number, *problem);
    positions.push_back(resolveObjIndex(corner->position, soFar.positions));
  }
  // OpenMesh's OBJ reader drops such faces before our importer sees them; count them here.
  ++scan.objFaces;
  if (distinctCount(positions) < 3) ++scan.degenerateFaces;
  return {};
}

}  // namespace

Result<Prescan> prescanObj(std::string_view text, const fs::path& path) {
  const ObjTotals totals = countObjElements(text);
  ObjTotals soFar;
  Prescan scan;
  LineCursor lines(text);
  TextLine line;
  while (lines.nextContent(line, true)) {
    const std::vector<std::string_view> words = splitWords(line.text);
    const std::string_view keyword = words[0];
    const std::size_t values = words.size() - 1;
    if (keyword == "v") {
      // x y z, optionally w (homogeneous) and/or an r g b colour.
      BAKE_RETURN_IF_ERROR(checkObjValueCount(path, line, values, {3, 4, 6, 7}, "3 coordinates (x y z)"));
      BAKE_RETURN_IF_ERROR(checkNumbers(path, line, words, 1, values, 3, "vertex coordinate"));
      scan.positions.push_back(coordinatesAt(words, 1));
      ++soFar.positions;
    } else if (keyword == "vt") {
      if (values == 1) {
        return lineUnsupported(path, line.number, "1D texture coordinates are not supported (need u and v)");
      }
      BAKE_RETURN_IF_ERROR(checkObjValueCount(path, line, values, {2, 3}, "2 or 3 texture coordinates"));
      BAKE_RETURN_IF_ERROR(checkNumbers(path, line, words, 1, values, 2, "texture coordinate"));
      ++soFar.texcoords;
    } else if (keyword == "vn") {
      BAKE_RETURN_IF_ERROR(checkObjValueCount(path, line, values, {3}, "3 normal components"));
      BAKE_RETURN_IF_ERROR(checkNumbers(path, line, words, 1, values, 3, "normal component"));
      ++soFar.normals;
    } else if (keyword == "f") {
      BAKE_RETURN_IF_ERROR(scanObjFace(path, line, words, soFar, totals, scan));
    }
    // Everything else (o, g, s, usemtl, mtllib, l, p, vp, ...) carries nothing we read.
  }
  return scan;
}

}  // namespace bake::meshscan
