// Reading triangle meshes (io/mesh.h). OBJ, OFF, PLY and STL are parsed by OpenMesh's reader
// modules, but into our own importer that records a plain polygon soup: OpenMesh's mesh kernel would
// drop faces that break manifoldness, silently, and a baker must see every face it was given.
//
// OpenMesh's parsers report almost nothing about malformed input (a bad number just desynchronises the
// stream, a PLY header without end_header even hangs), so each text format gets a light pre-scan that
// stops at the first malformed line and names it. Binary files get size checks before and a count
// comparison after parsing; validateMesh then catches what slips through (NaN coordinates, bad
// indices). glTF/GLB goes to io/gltf.h. Finally polygons are fan-triangulated and, on request, welded.
//
// Decisions worth knowing:
// - Faces with fewer than three vertices in the file (OFF "0", "2 4 5", OBJ "f 1 2", PLY lists of
//   length < 3) are errors naming the line: none of these formats defines them as polygons.
// - Faces that list a vertex twice are cleaned: repeats are removed (as OpenMesh's OBJ reader does)
//   and a face left with fewer than three distinct vertices is dropped and counted in
//   MeshReadStats::degenerateFacesRemoved. Zero-area faces with distinct vertices are kept.
// - OBJ attributes belong to face corners. A position used with different normals or texture
//   coordinates becomes several vertices (MeshReadStats::verticesSplit); an attribute given for only
//   some corners is dropped (MeshReadStats::incompleteAttributesDropped).
// - STL has no shared vertices; OpenMesh's STL reader joins corners at equal positions (an exact weld)
//   and skips triangles that collapse by it, which we count as removed degenerate faces.
// - Element names in errors: "line N" (1-based) for text files, "face N" / "triangle N" / "vertex N"
//   (0-based, in file order) otherwise.
#include "io/mesh.h"

#include <OpenMesh/Core/IO/IOManager.hh>
#include <OpenMesh/Core/IO/Options.hh>
#include <OpenMesh/Core/IO/importer/BaseImporter.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <mutex>
#include <optional>
#include <string_view>
#include <system_error>

#include "core/atomic_file.h"
#include "io/gltf.h"
#include "mesh/weld.h"

namespace bake {
namespace fs = std::filesystem;

namespace {

// ---------------------------------------------------------------------------------------------------
// Text helpers shared by the pre-scans.

struct TextLine {
  std::size_t number = 0;  // 1-based
  std::string_view text;   // without the line break and surrounding whitespace
  std::string_view raw;    // without the "\n" only
};

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

std::string_view trimmed(std::string_view text) {
  while (!text.empty() && isBlank(text.front())) text.remove_prefix(1);
  while (!text.empty() && isBlank(text.back())) text.remove_suffix(1);
  return text;
}

// Walks a text buffer line by line ("\n" or "\r\n" endings).
class LineCursor {
 public:
  // `linesBefore`: how many lines precede `text` in the file, for numbering.
  explicit LineCursor(std::string_view text, std::size_t linesBefore = 0)
      : text_(text), number_(linesBefore) {}

  bool next(TextLine& line) {
    if (position_ >= text_.size()) return false;
    const std::size_t end = std::min(text_.find('\n', position_), text_.size());
    line.number = ++number_;
    line.raw = text_.substr(position_, end - position_);
    line.text = trimmed(line.raw);
    position_ = end + 1;
    return true;
  }

  // The next line that is not blank; `skipComments` also skips lines starting with '#'.
  bool nextContent(TextLine& line, bool skipComments) {
    while (next(line)) {
      if (line.text.empty()) continue;
      if (skipComments && line.text.front() == '#') continue;
      return true;
    }
    return false;
  }

  std::size_t lineNumber() const { return number_; }
  std::size_t offset() const { return std::min(position_, text_.size()); }  // start of the next line

 private:
  std::string_view text_;
  std::size_t position_ = 0;
  std::size_t number_ = 0;
};

std::vector<std::string_view> splitWords(std::string_view text) {
  std::vector<std::string_view> words;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && isBlank(text[i])) ++i;
    const std::size_t start = i;
    while (i < text.size() && !isBlank(text[i])) ++i;
    if (i > start) words.push_back(text.substr(start, i - start));
  }
  return words;
}

std::string inQuotes(std::string_view word) { return "'" + std::string(word) + "'"; }

bool equalsIgnoringCase(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

// Whole-word decimal number; a leading '+' is allowed like in strtod. NaN and infinities parse.
std::optional<double> parseReal(std::string_view word) {
  if (word.size() > 1 && word.front() == '+' && word[1] != '-') word.remove_prefix(1);
  double value = 0.0;
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (end != word.data() + word.size()) return std::nullopt;
  if (error == std::errc::result_out_of_range) return std::numeric_limits<double>::infinity();
  if (error != std::errc()) return std::nullopt;
  return value;
}

std::optional<long long> parseInteger(std::string_view word) {
  if (word.size() > 1 && word.front() == '+' && word[1] != '-') word.remove_prefix(1);
  long long value = 0;
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (error != std::errc() || end != word.data() + word.size()) return std::nullopt;
  return value;
}

bool fitsFloat(double value) {
  return std::isfinite(value) && std::abs(value) <= double(std::numeric_limits<float>::max());
}

Status lineError(const fs::path& path, std::size_t line, std::string message) {
  return invalidInput(std::move(message), {path.string(), "line " + std::to_string(line)});
}

Status lineUnsupported(const fs::path& path, std::size_t line, std::string message) {
  return unsupported(std::move(message), {path.string(), "line " + std::to_string(line)});
}

// Checks that `words[first, first + count)` are numbers; `finiteCount` of them (from `first`) must
// also be finite 32-bit floats. `what` names the values in messages ("vertex coordinate").
Status checkNumbers(const fs::path& path, const TextLine& line, const std::vector<std::string_view>& words,
                    std::size_t first, std::size_t count, std::size_t finiteCount, const char* what) {
  for (std::size_t i = first; i < first + count; ++i) {
    const std::optional<double> value = parseReal(words[i]);
    if (!value) {
      return lineError(path, line.number, std::string(what) + " " + inQuotes(words[i]) + " is not a number");
    }
    if (i < first + finiteCount && !fitsFloat(*value)) {
      return lineError(path, line.number,
                       std::string(what) + " " + inQuotes(words[i]) + " is not a finite 32-bit float");
    }
  }
  return {};
}

std::size_t distinctCount(std::vector<long long> values) {
  std::sort(values.begin(), values.end());
  return std::size_t(std::unique(values.begin(), values.end()) - values.begin());
}

// What a pre-scan learned that the parse that follows cannot tell.
struct Prescan {
  std::size_t degenerateFaces = 0;  // OBJ faces OpenMesh drops before they reach the importer
  // Counts from a header, all of which must arrive (binary files can end early unnoticed).
  std::optional<std::size_t> declaredVertices;
  std::optional<std::size_t> declaredFaces;
  std::string verticesWhere;  // where the declared counts stand, for errors
  std::string facesWhere;
  // STL: triangles in the file; OpenMesh drops those with two equal corners before the importer.
  std::optional<std::size_t> stlTriangles;
};

// ---------------------------------------------------------------------------------------------------
// OBJ pre-scan: v/vt/vn value counts and finiteness, face corners and index ranges.

struct ObjTotals {
  std::size_t positions = 0;
  std::size_t texcoords = 0;
  std::size_t normals = 0;
};

std::string_view firstWord(std::string_view text) {
  std::size_t end = 0;
  while (end < text.size() && !isBlank(text[end])) ++end;
  return text.substr(0, end);
}

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
  if (distinctCount(positions) < 3) ++scan.degenerateFaces;
  return {};
}

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

// ---------------------------------------------------------------------------------------------------
// OFF pre-scan: header keyword, the counts line, then exactly the declared vertex and face lines.

struct OffHeader {
  bool texcoords = false;  // ST
  bool colors = false;     // C
  bool normals = false;    // N
  bool binary = false;
};

// Parses "[ST][C][N]OFF [BINARY]" the way OpenMesh does.
Result<OffHeader> parseOffHeader(const TextLine& line, const fs::path& path) {
  const std::vector<std::string_view> words = splitWords(line.text);
  std::string_view keyword = words.empty() ? std::string_view() : words[0];
  OffHeader header;
  auto takePrefix = [&keyword](std::string_view prefix) {
    if (keyword.substr(0, prefix.size()) != prefix) return false;
    keyword.remove_prefix(prefix.size());
    return true;
  };
  header.texcoords = takePrefix("ST");
  header.colors = takePrefix("C");
  header.normals = takePrefix("N");
  if (keyword == "4OFF" || keyword == "nOFF") {
    return lineUnsupported(path, line.number, "OFF files with other than 3 dimensions are not supported");
  }
  if (keyword != "OFF") {
    return lineError(path, line.number,
                     "the first line must be the OFF header keyword (OFF, NOFF, COFF, STOFF, ...)");
  }
  if (words.size() >= 2 && words[1] == "BINARY") {
    header.binary = true;
  } else if (words.size() >= 2 && words[1].front() != '#') {  // OpenMesh skips the rest of this line
    return lineUnsupported(path, line.number,
                           "the counts must be on the line after the OFF keyword, not on the same line");
  }
  return header;
}

Status scanOffVertex(const fs::path& path, const TextLine& line, const OffHeader& header) {
  const std::vector<std::string_view> words = splitWords(line.text);
  const std::size_t base = 3 + (header.normals ? 3 : 0) + (header.texcoords ? 2 : 0);
  // A colour is an index or 3-4 components; OpenMesh tells them apart by their count.
  const bool countOk =
      words.size() == base ||
      (header.colors && (words.size() == base + 1 || words.size() == base + 3 || words.size() == base + 4));
  if (!countOk) {
    return lineError(
        path, line.number,
        "expected " + std::to_string(base) + " values for a vertex, found " + std::to_string(words.size()));
  }
  BAKE_RETURN_IF_ERROR(
      checkNumbers(path, line, words, 0, words.size(), header.normals ? 6 : 3, "vertex value"));
  if (header.texcoords) {
    BAKE_RETURN_IF_ERROR(checkNumbers(path, line, words, words.size() - 2, 2, 2, "texture coordinate"));
  }
  return {};
}

Status scanOffFace(const fs::path& path, const TextLine& line, const OffHeader& header,
                   std::size_t vertexCount) {
  const std::vector<std::string_view> words = splitWords(line.text);
  const std::optional<long long> size = parseInteger(words[0]);
  if (!size || *size < 0) {
    return lineError(path, line.number, "face must start with its vertex count, found " + inQuotes(words[0]));
  }
  if (*size < 3) {
    return lineError(path, line.number,
                     "face has " + std::to_string(*size) + " vertices; at least 3 are needed");
  }
  const std::size_t expected = 1 + std::size_t(*size);
  const std::size_t extra = words.size() - std::min(words.size(), expected);
  // OpenMesh consumes trailing face colours only when the header announces them (COFF); anything else
  // would be read as the next face.
  const bool countOk = words.size() >= expected && (extra == 0 || (header.colors && extra <= 4));
  if (!countOk) {
    return lineError(path, line.number,
                     "face declares " + std::to_string(*size) + " vertices but has " +
                         std::to_string(words.size() - 1) + " values");
  }
  for (std::size_t i = 1; i < expected; ++i) {
    const std::optional<long long> index = parseInteger(words[i]);
    if (!index) {
      return lineError(path, line.number, "vertex index " + inQuotes(words[i]) + " is not an integer");
    }
    if (*index < 0 || std::size_t(*index) >= vertexCount) {
      return lineError(path, line.number,
                       "vertex index " + std::to_string(*index) + " is out of range (" +
                           std::to_string(vertexCount) + " vertices, indices start at 0)");
    }
  }
  return {};
}

struct OffCounts {
  std::size_t vertices = 0;
  std::size_t faces = 0;
};

Result<OffCounts> parseOffCounts(const TextLine& line, const fs::path& path) {
  const std::vector<std::string_view> words = splitWords(line.text);
  if (words.size() != 3) {
    return lineError(
        path, line.number,
        "expected three counts (vertices faces edges), found " + std::to_string(words.size()) + " values");
  }
  long long counts[3];
  for (int i = 0; i < 3; ++i) {
    const std::optional<long long> value = parseInteger(words[i]);
    if (!value || *value < 0 || *value > std::numeric_limits<std::int32_t>::max()) {
      return lineError(path, line.number,
                       "count " + inQuotes(words[i]) + " is not a valid non-negative integer");
    }
    counts[i] = *value;
  }
  return OffCounts{std::size_t(counts[0]), std::size_t(counts[1])};
}

// Binary OFF: the counts follow the header line as little-endian 32-bit integers. Only a size check
// here; OpenMesh would otherwise read past the end for as many faces as the header claims.
Result<Prescan> prescanBinaryOff(std::string_view text, const TextLine& header, const fs::path& path) {
  const std::size_t dataStart = std::min(text.find('\n'), text.size()) + 1;
  auto readUint = [&](std::size_t at) {
    std::uint32_t value = 0;
    std::memcpy(&value, text.data() + at, 4);  // OFF BINARY is little-endian, like this machine
    return value;
  };
  if (text.size() < dataStart + 12) {
    return lineError(path, header.number, "binary OFF ends inside its counts");
  }
  const std::uint64_t vertices = readUint(dataStart), faces = readUint(dataStart + 4);
  const std::uint64_t minimumBytes = 12 + vertices * 12 + faces * 16;
  if (text.size() - dataStart < minimumBytes) {
    return invalidInput("binary OFF is truncated: " + std::to_string(vertices) + " vertices and " +
                            std::to_string(faces) + " faces need at least " + std::to_string(minimumBytes) +
                            " bytes, the file has " + std::to_string(text.size() - dataStart),
                        {path.string(), ""});
  }
  Prescan scan;
  scan.declaredVertices = vertices;
  scan.declaredFaces = faces;
  scan.verticesWhere = scan.facesWhere = "header";
  return scan;
}

Result<Prescan> prescanOff(std::string_view text, const fs::path& path) {
  LineCursor lines(text);
  TextLine line;
  lines.next(line);  // OpenMesh insists on the keyword being the very first line
  BAKE_ASSIGN_OR_RETURN(const OffHeader header, parseOffHeader(line, path));
  if (header.binary) return prescanBinaryOff(text, line, path);

  // Blank lines are harmless (OpenMesh extracts numbers with >>); comments are not.
  auto nextDataLine = [&](TextLine& data) { return lines.nextContent(data, false); };
  auto rejectComment = [&](const TextLine& data) -> Status {
    if (data.text.front() != '#') return {};
    // OpenMesh reads OFF with stream extraction, which would take the comment for numbers.
    return lineUnsupported(path, data.number, "comments after the OFF keyword are not supported");
  };

  if (!nextDataLine(line)) {
    return lineError(path, lines.lineNumber(), "the OFF keyword is not followed by counts");
  }
  BAKE_RETURN_IF_ERROR(rejectComment(line));
  BAKE_ASSIGN_OR_RETURN(const OffCounts counts, parseOffCounts(line, path));
  const std::size_t countsLine = line.number;
  auto endsEarly = [&](const char* what, std::size_t found, std::size_t declared) {
    return lineError(path, countsLine,
                     "the header declares " + std::to_string(declared) + " " + what +
                         " but the file ends after " + std::to_string(found));
  };

  for (std::size_t v = 0; v < counts.vertices; ++v) {
    if (!nextDataLine(line)) return endsEarly("vertices", v, counts.vertices);
    BAKE_RETURN_IF_ERROR(rejectComment(line));
    BAKE_RETURN_IF_ERROR(scanOffVertex(path, line, header));
  }
  for (std::size_t f = 0; f < counts.faces; ++f) {
    if (!nextDataLine(line)) return endsEarly("faces", f, counts.faces);
    BAKE_RETURN_IF_ERROR(rejectComment(line));
    BAKE_RETURN_IF_ERROR(scanOffFace(path, line, header, counts.vertices));
  }
  if (lines.nextContent(line, true)) {
    return lineError(path, line.number,
                     "data after the " + std::to_string(counts.faces) + " faces the header declares (line " +
                         std::to_string(countsLine) + ")");
  }
  Prescan scan;
  scan.declaredVertices = counts.vertices;
  scan.declaredFaces = counts.faces;
  scan.verticesWhere = scan.facesWhere = "line " + std::to_string(countsLine);
  return scan;
}

// ---------------------------------------------------------------------------------------------------
// PLY: the header is parsed for every PLY (OpenMesh loops forever on a header without end_header);
// ASCII bodies are then checked line by line against it, binary ones for size.

struct PlyProperty {
  std::string name;
  std::string type;       // value type, for lists the item type
  std::string countType;  // lists only
  bool isList() const { return !countType.empty(); }
};

struct PlyElement {
  std::string name;
  std::size_t count = 0;
  std::size_t headerLine = 0;
  std::vector<PlyProperty> properties;
};

struct PlyHeader {
  bool ascii = false;
  std::vector<PlyElement> elements;
  std::size_t vertexElement = 0;
  std::optional<std::size_t> faceElement;
  std::size_t headerLines = 0;  // lines up to and including end_header
  std::size_t dataOffset = 0;   // first byte after the end_header line

  const PlyElement& vertices() const { return elements[vertexElement]; }
};

std::size_t plyTypeSize(std::string_view type) {
  if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
  if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
  if (type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" ||
      type == "float32") {
    return 4;
  }
  if (type == "double" || type == "float64") return 8;
  return 0;  // not a PLY type
}

bool isPlyFaceIndexList(const PlyProperty& property) {
  return property.isList() && (property.name == "vertex_indices" || property.name == "vertex_index");
}

// Vertex properties that become coordinates, normals or texture coordinates and so must be finite.
bool isPlyGeometryProperty(const std::string& name) {
  for (const char* geometric : {"x", "y", "z", "nx", "ny", "nz", "u", "v", "s", "t"}) {
    if (name == geometric) return true;
  }
  return false;
}

Status parsePlyProperty(const std::vector<std::string_view>& words, const TextLine& line,
                        const fs::path& path, PlyElement& element) {
  PlyProperty property;
  if (words.size() == 5 && words[1] == "list") {
    property.countType = words[2];
    property.type = words[3];
    property.name = words[4];
    if (plyTypeSize(property.countType) == 0 || plyTypeSize(property.type) == 0) {
      return lineError(path, line.number, "unknown PLY type in list property");
    }
    // The only list-count types OpenMesh's reader accepts.
    if (property.countType != "uchar" && property.countType != "uint8" && property.countType != "uint16" &&
        property.countType != "int") {
      return lineUnsupported(path, line.number,
                             "list count type " + inQuotes(property.countType) +
                                 " is not supported (use uchar, uint8, uint16 or int)");
    }
  } else if (words.size() == 3) {
    property.type = words[1];
    property.name = words[2];
    if (plyTypeSize(property.type) == 0) {
      return lineError(path, line.number, "unknown PLY type " + inQuotes(property.type));
    }
  } else {
    return lineError(path, line.number, "malformed property line");
  }
  element.properties.push_back(std::move(property));
  return {};
}

// Checks what OpenMesh needs from the elements: x, y, z on the vertices, a vertex-index list on the
// faces, and in ASCII no list properties it would misread.
Status checkPlyElements(PlyHeader& header, const fs::path& path) {
  bool haveVertices = false;
  for (std::size_t e = 0; e < header.elements.size(); ++e) {
    if (header.elements[e].name == "vertex") {
      header.vertexElement = e;
      haveVertices = true;
    }
    if (header.elements[e].name == "face") header.faceElement = e;
  }
  if (!haveVertices) {
    return invalidInput("the PLY header declares no vertex element", {path.string(), "header"});
  }
  const PlyElement& vertices = header.vertices();
  for (const char* axis : {"x", "y", "z"}) {
    const bool found = std::any_of(vertices.properties.begin(), vertices.properties.end(),
                                   [&](const PlyProperty& p) { return p.name == axis && !p.isList(); });
    if (!found) {
      return lineError(path, vertices.headerLine,
                       std::string("the vertex element has no '") + axis + "' property");
    }
  }
  if (header.faceElement) {
    const PlyElement& faces = header.elements[*header.faceElement];
    if (std::none_of(faces.properties.begin(), faces.properties.end(), isPlyFaceIndexList)) {
      return lineError(path, faces.headerLine, "the face element has no vertex_indices list");
    }
  }
  if (!header.ascii) return {};
  // OpenMesh's ASCII reader skips other properties one word at a time, which desynchronises on lists.
  for (std::size_t e = 0; e < header.elements.size(); ++e) {
    for (const PlyProperty& property : header.elements[e].properties) {
      if (property.isList() && !(e == header.faceElement && isPlyFaceIndexList(property))) {
        return lineUnsupported(path, header.elements[e].headerLine,
                               "list property " + inQuotes(property.name) + " of element " +
                                   inQuotes(header.elements[e].name) + " is not supported in ASCII PLY");
      }
    }
  }
  return {};
}

// OpenMesh finds binary data by assuming "\nend_header\n" right after the last word of the previous
// header line; a comment or trailing blanks there would shift every value read.
Status checkPlyBinaryLayout(const TextLine& previous, const TextLine& endHeader, const fs::path& path) {
  const std::string_view previousKeyword = firstWord(previous.text);
  const bool crlf = !previous.raw.empty() && previous.raw.back() == '\r';
  const std::string_view previousContent =
      crlf ? previous.raw.substr(0, previous.raw.size() - 1) : previous.raw;
  const bool fits = previousKeyword != "comment" && previousKeyword != "obj_info" &&
                    !previousContent.empty() && !isBlank(previousContent.back()) &&
                    endHeader.raw == (crlf ? "end_header\r" : "end_header");
  if (fits) return {};
  return lineUnsupported(path, endHeader.number,
                         "binary PLY needs 'end_header' right after a property or element line, without "
                         "trailing blanks (OpenMesh locates the data that way)");
}

Result<PlyHeader> parsePlyHeader(std::string_view text, const fs::path& path) {
  PlyHeader header;
  LineCursor lines(text);
  TextLine line;
  lines.next(line);
  if (line.text != "ply" && line.text != "PLY") {
    return lineError(path, line.number, "the first line must be 'ply'");
  }
  if (!lines.next(line)) return lineError(path, line.number + 1, "missing format line");
  const std::vector<std::string_view> format = splitWords(line.text);
  if (format.size() != 3 || format[0] != "format") {
    return lineError(path, line.number, "malformed format line");
  }
  if (format[1] == "ascii") {
    header.ascii = true;
  } else if (format[1] != "binary_little_endian" && format[1] != "binary_big_endian") {
    return lineError(path, line.number, "unknown PLY format " + inQuotes(format[1]));
  }
  TextLine previous = line;
  while (true) {
    if (!lines.next(line)) {
      return invalidInput("the PLY header has no end_header line", {path.string(), "header"});
    }
    const std::vector<std::string_view> words = splitWords(line.text);
    if (words.empty()) return lineError(path, line.number, "blank line inside the PLY header");
    if (words[0] == "end_header") break;
    previous = line;
    if (words[0] == "comment" || words[0] == "obj_info") continue;
    if (words[0] == "element") {
      const std::optional<long long> count = words.size() == 3 ? parseInteger(words[2]) : std::nullopt;
      if (!count || *count < 0 || *count > std::numeric_limits<std::int32_t>::max()) {
        return lineError(path, line.number, "malformed element line (expected: element NAME COUNT)");
      }
      header.elements.push_back({std::string(words[1]), std::size_t(*count), line.number, {}});
    } else if (words[0] == "property") {
      if (header.elements.empty()) return lineError(path, line.number, "property before any element");
      BAKE_RETURN_IF_ERROR(parsePlyProperty(words, line, path, header.elements.back()));
    } else {
      return lineError(path, line.number, "unknown PLY header keyword " + inQuotes(words[0]));
    }
  }
  if (!header.ascii) BAKE_RETURN_IF_ERROR(checkPlyBinaryLayout(previous, line, path));
  header.headerLines = line.number;
  header.dataOffset = lines.offset();
  BAKE_RETURN_IF_ERROR(checkPlyElements(header, path));
  return header;
}

// One ASCII element line against its properties: value counts, numbers, finiteness of geometry, and
// for faces the vertex count and index range.
Status scanPlyLine(const fs::path& path, const TextLine& line, const PlyElement& element, bool isFaceElement,
                   std::size_t vertexCount) {
  const std::vector<std::string_view> words = splitWords(line.text);
  std::size_t at = 0;
  auto tooFew = [&]() {
    return lineError(path, line.number,
                     "too few values for element " + inQuotes(element.name) + " (found " +
                         std::to_string(words.size()) + ")");
  };
  for (const PlyProperty& property : element.properties) {
    if (!property.isList()) {
      if (at >= words.size()) return tooFew();
      const bool mustBeFinite = element.name == "vertex" && isPlyGeometryProperty(property.name);
      const std::string what = inQuotes(property.name) + " value";
      BAKE_RETURN_IF_ERROR(checkNumbers(path, line, words, at, 1, mustBeFinite ? 1 : 0, what.c_str()));
      ++at;
      continue;
    }
    if (at >= words.size()) return tooFew();
    const std::optional<long long> length = parseInteger(words[at]);
    if (!length || *length < 0) {
      return lineError(path, line.number,
                       "list length " + inQuotes(words[at]) + " is not a non-negative integer");
    }
    ++at;
    if (words.size() - at < std::size_t(*length)) return tooFew();
    const bool isIndexList = isFaceElement && isPlyFaceIndexList(property);
    if (isIndexList && *length < 3) {
      return lineError(path, line.number,
                       "face has " + std::to_string(*length) + " vertices; at least 3 are needed");
    }
    for (long long i = 0; i < *length; ++i, ++at) {
      const std::optional<long long> index = parseInteger(words[at]);
      if (!index) {
        return lineError(path, line.number, "list value " + inQuotes(words[at]) + " is not an integer");
      }
      if (isIndexList && (*index < 0 || std::size_t(*index) >= vertexCount)) {
        return lineError(path, line.number,
                         "vertex index " + std::to_string(*index) + " is out of range (" +
                             std::to_string(vertexCount) + " vertices, indices start at 0)");
      }
    }
  }
  if (at != words.size()) {
    return lineError(path, line.number,
                     "too many values for element " + inQuotes(element.name) + " (expected " +
                         std::to_string(at) + ", found " + std::to_string(words.size()) + ")");
  }
  return {};
}

Status scanPlyAsciiBody(std::string_view text, const PlyHeader& header, const fs::path& path) {
  LineCursor lines(text.substr(header.dataOffset), header.headerLines);
  TextLine line;
  for (std::size_t e = 0; e < header.elements.size(); ++e) {
    const PlyElement& element = header.elements[e];
    for (std::size_t i = 0; i < element.count; ++i) {
      if (!lines.nextContent(line, false)) {
        return lineError(path, element.headerLine,
                         "the header declares " + std::to_string(element.count) + " " + element.name +
                             " elements but the file ends after " + std::to_string(i));
      }
      BAKE_RETURN_IF_ERROR(
          scanPlyLine(path, line, element, e == header.faceElement, header.vertices().count));
    }
  }
  if (lines.nextContent(line, false)) {
    return lineError(path, line.number, "data after the elements the header declares");
  }
  return {};
}

// Bytes one element needs at least: fixed-size properties exactly, lists their count and, for the
// face index list, three indices.
std::uint64_t minimumPlyElementBytes(const PlyElement& element) {
  std::uint64_t bytes = 0;
  for (const PlyProperty& property : element.properties) {
    if (!property.isList()) {
      bytes += plyTypeSize(property.type);
    } else {
      bytes += plyTypeSize(property.countType) +
               (isPlyFaceIndexList(property) ? 3 * plyTypeSize(property.type) : 0);
    }
  }
  return bytes * element.count;
}

Result<Prescan> prescanPly(std::string_view text, const fs::path& path) {
  BAKE_ASSIGN_OR_RETURN(const PlyHeader header, parsePlyHeader(text, path));
  if (header.ascii) {
    BAKE_RETURN_IF_ERROR(scanPlyAsciiBody(text, header, path));
  } else {
    std::uint64_t minimum = 0;
    for (const PlyElement& element : header.elements) minimum += minimumPlyElementBytes(element);
    const std::uint64_t available = text.size() - std::min(text.size(), header.dataOffset);
    if (available < minimum) {
      return invalidInput("binary PLY is truncated: the header's elements need at least " +
                              std::to_string(minimum) + " bytes, the file has " + std::to_string(available) +
                              " after the header",
                          {path.string(), ""});
    }
  }
  Prescan scan;
  scan.declaredVertices = header.vertices().count;
  scan.declaredFaces = header.faceElement ? header.elements[*header.faceElement].count : 0;
  scan.verticesWhere = "line " + std::to_string(header.vertices().headerLine);
  scan.facesWhere = header.faceElement
                        ? "line " + std::to_string(header.elements[*header.faceElement].headerLine)
                        : "header";
  return scan;
}

// ---------------------------------------------------------------------------------------------------
// STL: binary when the size matches the triangle count in the header (OpenMesh's own rule), ASCII
// otherwise. OpenMesh merges equal positions and drops triangles with two equal corners; the
// difference between declared and delivered triangles is counted as removed degenerate faces.

constexpr std::size_t kStlHeaderBytes = 84;
constexpr std::size_t kStlTriangleBytes = 50;

std::optional<std::uint32_t> binaryStlTriangleCount(std::string_view bytes) {
  if (bytes.size() < kStlHeaderBytes) return std::nullopt;
  std::uint32_t count = 0;
  std::memcpy(&count, bytes.data() + 80, 4);  // little-endian, like this machine
  return count;
}

bool isBinaryStl(std::string_view bytes) {
  const std::optional<std::uint32_t> count = binaryStlTriangleCount(bytes);
  return count && bytes.size() == kStlHeaderBytes + std::uint64_t(*count) * kStlTriangleBytes;
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

// ---------------------------------------------------------------------------------------------------
// The importer OpenMesh's readers feed: a polygon soup with per-corner attributes.

struct Corner {
  std::uint32_t vertex = 0;
  bool hasNormal = false;
  bool hasTexcoord = false;
  Vec3f normal{};
  Vec2f texcoord{};
};

struct PolygonSoup {
  std::vector<Vec3f> positions;
  std::vector<Corner> corners;
  std::vector<std::size_t> polygonStarts;  // into corners; a polygon ends where the next starts
  std::size_t facesOffered = 0;            // every face the reader passed, kept or not
  std::size_t degenerateFaces = 0;         // fewer than three distinct vertices: dropped
  std::vector<Corner> vertexAttributes;    // per-vertex formats: attributes of every vertex
};

// Where the reader's normals and texture coordinates belong. OBJ sets them per face corner just before
// adding the face; OFF and PLY set them once per vertex before any face. (A corner-scope face that
// OpenMesh skips, having fewer than 3 distinct vertices, leaves its attributes pending for the next
// face; they only matter if that face uses the same vertex without giving the attribute itself.)
enum class AttributeScope { PerVertex, PerCorner };

class SoupImporter final : public OpenMesh::IO::BaseImporter {
 public:
  using VertexHandle = OpenMesh::VertexHandle;
  using FaceHandle = OpenMesh::FaceHandle;
  using HalfedgeHandle = OpenMesh::HalfedgeHandle;
  using EdgeHandle = OpenMesh::EdgeHandle;

  explicit SoupImporter(AttributeScope scope) : scope_(scope) {}

  PolygonSoup& soup() {
    if (scope_ == AttributeScope::PerVertex) soup_.vertexAttributes = vertexAttributes_;
    return soup_;
  }
  // The first face that referred to a vertex that does not exist, if any.
  const std::optional<std::string>& problem() const { return problem_; }

  VertexHandle add_vertex(const OpenMesh::Vec3f& point) override {
    soup_.positions.push_back({point[0], point[1], point[2]});
    vertexAttributes_.emplace_back();
    return VertexHandle(int(soup_.positions.size() - 1));
  }
  VertexHandle add_vertex(const OpenMesh::Vec3d& point) override {
    return add_vertex(OpenMesh::Vec3f(float(point[0]), float(point[1]), float(point[2])));
  }
  VertexHandle add_vertex() override { return add_vertex(OpenMesh::Vec3f(0.0f, 0.0f, 0.0f)); }
  void set_point(VertexHandle vertex, const OpenMesh::Vec3f& point) override {
    if (isValid(vertex)) soup_.positions[vertex.idx()] = {point[0], point[1], point[2]};
  }

  void set_normal(VertexHandle vertex, const OpenMesh::Vec3f& normal) override {
    if (Corner* attributes = attributesFor(vertex)) {
      attributes->hasNormal = true;
      attributes->normal = {normal[0], normal[1], normal[2]};
    }
  }
  void set_normal(VertexHandle vertex, const OpenMesh::Vec3d& normal) override {
    set_normal(vertex, OpenMesh::Vec3f(float(normal[0]), float(normal[1]), float(normal[2])));
  }
  void set_texcoord(VertexHandle vertex, const OpenMesh::Vec2f& texcoord) override {
    if (Corner* attributes = attributesFor(vertex)) {
      attributes->hasTexcoord = true;
      attributes->texcoord = {texcoord[0], texcoord[1]};
    }
  }

  FaceHandle add_face(const VHandles& indices) override {
    const std::size_t faceNumber = soup_.facesOffered++;
    std::vector<VertexHandle> distinct;
    for (VertexHandle vertex : indices) {
      if (!isValid(vertex)) {
        if (!problem_) {
          problem_ = "face " + std::to_string(faceNumber) + " refers to vertex " +
                     std::to_string(vertex.idx()) + ", but there are " +
                     std::to_string(soup_.positions.size()) + " vertices";
        }
        pending_.clear();
        return FaceHandle();
      }
      if (std::find(distinct.begin(), distinct.end(), vertex) == distinct.end()) distinct.push_back(vertex);
    }
    if (distinct.size() < 3) {
      ++soup_.degenerateFaces;
      pending_.clear();
      return FaceHandle();
    }
    soup_.polygonStarts.push_back(soup_.corners.size());
    for (VertexHandle vertex : distinct) soup_.corners.push_back(cornerFor(vertex));
    pending_.clear();
    return FaceHandle(int(soup_.polygonStarts.size() - 1));
  }

  size_t n_vertices() const override { return soup_.positions.size(); }
  size_t n_faces() const override { return soup_.polygonStarts.size(); }
  size_t n_edges() const override { return 0; }

  // Everything below is either half-edge plumbing (only the .om reader uses it) or data we do not
  // keep: colours, face normals, status bits, 3D texture coordinates, materials.
  HalfedgeHandle add_edge(VertexHandle, VertexHandle) override { return HalfedgeHandle(); }
  FaceHandle add_face(HalfedgeHandle) override { return FaceHandle(); }
  void add_face_texcoords(FaceHandle, VertexHandle, const std::vector<OpenMesh::Vec2f>&) override {}
  void add_face_texcoords(FaceHandle, VertexHandle, const std::vector<OpenMesh::Vec3f>&) override {}
  void set_face_texindex(FaceHandle, int) override {}
  void set_halfedge(VertexHandle, HalfedgeHandle) override {}
  void set_color(VertexHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(VertexHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_color(VertexHandle, const OpenMesh::Vec4f&) override {}
  void set_status(VertexHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_next(HalfedgeHandle, HalfedgeHandle) override {}
  void set_face(HalfedgeHandle, FaceHandle) override {}
  void request_face_texcoords2D() override {}
  void set_texcoord(HalfedgeHandle, const OpenMesh::Vec2f&) override {}
  void set_texcoord(VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_texcoord(HalfedgeHandle, const OpenMesh::Vec3f&) override {}
  void set_status(HalfedgeHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_color(EdgeHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(EdgeHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(EdgeHandle, const OpenMesh::Vec3f&) override {}
  void set_color(EdgeHandle, const OpenMesh::Vec4f&) override {}
  void set_status(EdgeHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_normal(FaceHandle, const OpenMesh::Vec3f&) override {}
  void set_normal(FaceHandle, const OpenMesh::Vec3d&) override {}
  void set_color(FaceHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(FaceHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(FaceHandle, const OpenMesh::Vec3f&) override {}
  void set_color(FaceHandle, const OpenMesh::Vec4f&) override {}
  void set_status(FaceHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void add_texture_information(int, std::string) override {}

 private:
  bool isValid(VertexHandle vertex) const {
    return vertex.idx() >= 0 && std::size_t(vertex.idx()) < soup_.positions.size();
  }

  // Per-vertex scope: the vertex's own slot. Per-corner scope: a slot for the face being assembled.
  Corner* attributesFor(VertexHandle vertex) {
    if (!isValid(vertex)) return nullptr;
    if (scope_ == AttributeScope::PerVertex) return &vertexAttributes_[vertex.idx()];
    for (Corner& corner : pending_) {
      if (corner.vertex == std::uint32_t(vertex.idx())) return &corner;
    }
    pending_.push_back({std::uint32_t(vertex.idx())});
    return &pending_.back();
  }

  Corner cornerFor(VertexHandle vertex) const {
    Corner corner;
    if (scope_ == AttributeScope::PerVertex) {
      corner = vertexAttributes_[vertex.idx()];
    } else {
      for (const Corner& pending : pending_) {
        if (pending.vertex == std::uint32_t(vertex.idx())) corner = pending;
      }
    }
    corner.vertex = std::uint32_t(vertex.idx());
    return corner;
  }

  AttributeScope scope_;
  PolygonSoup soup_;
  std::vector<Corner> vertexAttributes_;  // per-vertex scope
  std::vector<Corner> pending_;           // per-corner scope: attributes for the next face
  std::optional<std::string> problem_;
};

// ---------------------------------------------------------------------------------------------------
// Calling OpenMesh.

// OpenMesh's log streams buffer partial lines; flushing while disabled discards them instead of letting
// them surface after re-enabling.
class QuietOpenMeshLogs {
 public:
  QuietOpenMeshLogs() {
    for (int i = 0; i < 3; ++i) {
      wasEnabled_[i] = stream(i).is_enabled();
      stream(i).disable();
    }
  }
  ~QuietOpenMeshLogs() {
    for (int i = 0; i < 3; ++i) {
      stream(i).flush();
      if (wasEnabled_[i]) stream(i).enable();
    }
  }
  QuietOpenMeshLogs(const QuietOpenMeshLogs&) = delete;
  QuietOpenMeshLogs& operator=(const QuietOpenMeshLogs&) = delete;

 private:
  static OpenMesh::mostream& stream(int i) { return i == 0 ? omerr() : i == 1 ? omlog() : omout(); }
  bool wasEnabled_[3] = {};
};

// The reader modules are process-wide singletons that keep per-file state, and the log switches are
// global: one OpenMesh read at a time.
std::mutex& openMeshMutex() {
  static std::mutex mutex;
  return mutex;
}

bool parseWithOpenMesh(const fs::path& path, SoupImporter& importer) {
  OpenMesh::IO::Options options;
  options += OpenMesh::IO::Options::VertexNormal;
  options += OpenMesh::IO::Options::VertexTexCoord;
  std::lock_guard<std::mutex> lock(openMeshMutex());
  QuietOpenMeshLogs quiet;
  return OpenMesh::IO::IOManager().read(path.string(), importer, options);
}

// ---------------------------------------------------------------------------------------------------
// Polygon soup to triangle mesh.

template <class T>
bool sameBits(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}

// Gives each corner the index of a vertex with its position and attributes: the first attribute
// combination seen for a position keeps the original vertex, later different ones get copies.
std::vector<std::uint32_t> assignCornerVertices(const PolygonSoup& soup, bool withNormals, bool withTexcoords,
                                                TriangleMesh& mesh, MeshReadStats& stats) {
  std::vector<std::uint32_t> cornerVertex(soup.corners.size());
  if (!withNormals && !withTexcoords) {
    for (std::size_t c = 0; c < soup.corners.size(); ++c) cornerVertex[c] = soup.corners[c].vertex;
    return cornerVertex;
  }
  // Unreferenced vertices keep the attributes a per-vertex format gave them, zeros otherwise.
  if (withNormals) mesh.normals.assign(mesh.positions.size(), Vec3f{});
  if (withTexcoords) mesh.texcoords.assign(mesh.positions.size(), Vec2f{});
  for (std::size_t v = 0; v < soup.vertexAttributes.size(); ++v) {
    if (withNormals && soup.vertexAttributes[v].hasNormal) mesh.normals[v] = soup.vertexAttributes[v].normal;
    if (withTexcoords && soup.vertexAttributes[v].hasTexcoord) {
      mesh.texcoords[v] = soup.vertexAttributes[v].texcoord;
    }
  }
  // Variants of each original vertex as a linked list through `variants`.
  struct Variant {
    std::uint32_t vertex;
    std::int64_t next;
  };
  std::vector<Variant> variants;
  std::vector<std::int64_t> firstVariant(soup.positions.size(), -1);
  auto matches = [&](std::uint32_t vertex, const Corner& corner) {
    return (!withNormals || sameBits(mesh.normals[vertex], corner.normal)) &&
           (!withTexcoords || sameBits(mesh.texcoords[vertex], corner.texcoord));
  };
  for (std::size_t c = 0; c < soup.corners.size(); ++c) {
    const Corner& corner = soup.corners[c];
    std::int64_t* link = &firstVariant[corner.vertex];
    while (*link >= 0 && !matches(variants[*link].vertex, corner)) link = &variants[*link].next;
    if (*link < 0) {
      const bool firstUse = firstVariant[corner.vertex] < 0;
      const std::uint32_t vertex = firstUse ? corner.vertex : std::uint32_t(mesh.positions.size());
      if (!firstUse) {
        mesh.positions.push_back(soup.positions[corner.vertex]);
        if (withNormals) mesh.normals.emplace_back();
        if (withTexcoords) mesh.texcoords.emplace_back();
        ++stats.verticesSplit;
      }
      if (withNormals) mesh.normals[vertex] = corner.normal;
      if (withTexcoords) mesh.texcoords[vertex] = corner.texcoord;
      *link = std::int64_t(variants.size());
      variants.push_back({vertex, -1});
    }
    cornerVertex[c] = variants[*link].vertex;
  }
  return cornerVertex;
}

// An attribute is kept only when every corner has it.
bool attributeIsComplete(const PolygonSoup& soup, bool Corner::*present, MeshReadStats& stats) {
  const std::size_t count = std::size_t(
      std::count_if(soup.corners.begin(), soup.corners.end(), [&](const Corner& c) { return c.*present; }));
  if (count > 0 && count < soup.corners.size()) ++stats.incompleteAttributesDropped;
  return count > 0 && count == soup.corners.size();
}

Result<TriangleMesh> triangulate(PolygonSoup&& soup, const fs::path& path, MeshReadStats& stats) {
  if (soup.positions.size() > std::numeric_limits<std::uint32_t>::max() / 2) {
    return unsupported("too many vertices for 32-bit indices", {path.string(), ""});
  }
  TriangleMesh mesh;
  mesh.positions = soup.positions;
  const bool withNormals = attributeIsComplete(soup, &Corner::hasNormal, stats);
  const bool withTexcoords = attributeIsComplete(soup, &Corner::hasTexcoord, stats);
  const std::vector<std::uint32_t> cornerVertex =
      assignCornerVertices(soup, withNormals, withTexcoords, mesh, stats);
  // Fan from each polygon's first corner.
  for (std::size_t p = 0; p < soup.polygonStarts.size(); ++p) {
    const std::size_t begin = soup.polygonStarts[p];
    const std::size_t end =
        p + 1 < soup.polygonStarts.size() ? soup.polygonStarts[p + 1] : soup.corners.size();
    if (end - begin > 3) ++stats.polygonsTriangulated;
    for (std::size_t c = begin + 1; c + 1 < end; ++c) {
      mesh.triangles.push_back({cornerVertex[begin], cornerVertex[c], cornerVertex[c + 1]});
    }
  }
  return mesh;
}

// ---------------------------------------------------------------------------------------------------
// Putting it together.

enum class MeshFormat { Obj, Off, Ply, Stl, Gltf, Unknown };

MeshFormat formatOf(const std::string& extension) {
  if (extension == ".obj") return MeshFormat::Obj;
  if (extension == ".off") return MeshFormat::Off;
  if (extension == ".ply") return MeshFormat::Ply;
  if (extension == ".stl") return MeshFormat::Stl;
  if (extension == ".gltf" || extension == ".glb") return MeshFormat::Gltf;
  return MeshFormat::Unknown;
}

std::string lowercase(std::string text) {
  for (char& c : text) c = char(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

Result<Prescan> prescan(MeshFormat format, std::string_view bytes, const fs::path& path) {
  switch (format) {
    case MeshFormat::Obj: return prescanObj(bytes, path);
    case MeshFormat::Off: return prescanOff(bytes, path);
    case MeshFormat::Ply: return prescanPly(bytes, path);
    case MeshFormat::Stl: return prescanStl(bytes, path);
    default: return internalError("no pre-scan for this format", {path.string(), ""});
  }
}

// After parsing: every declared element must have arrived (binary files end early silently).
Status checkDeclaredCounts(const Prescan& scan, const PolygonSoup& soup, const fs::path& path) {
  if (scan.declaredVertices && soup.positions.size() != *scan.declaredVertices) {
    return invalidInput("the header declares " + std::to_string(*scan.declaredVertices) + " vertices, " +
                            std::to_string(soup.positions.size()) + " were read (truncated file?)",
                        {path.string(), scan.verticesWhere});
  }
  if (scan.declaredFaces && soup.facesOffered != *scan.declaredFaces) {
    return invalidInput("the header declares " + std::to_string(*scan.declaredFaces) + " faces, " +
                            std::to_string(soup.facesOffered) + " were read (truncated file?)",
                        {path.string(), scan.facesWhere});
  }
  return {};
}

Result<TriangleMesh> readWithOpenMesh(const fs::path& path, MeshFormat format, MeshReadStats& stats) {
  BAKE_ASSIGN_OR_RETURN(const std::vector<std::uint8_t> bytes, readFileBytes(path));
  if (bytes.empty()) return invalidInput("the file is empty", {path.string(), ""});
  const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  BAKE_ASSIGN_OR_RETURN(const Prescan scan, prescan(format, text, path));

  SoupImporter importer(format == MeshFormat::Obj ? AttributeScope::PerCorner : AttributeScope::PerVertex);
  if (!parseWithOpenMesh(path, importer)) {
    return invalidInput("OpenMesh could not parse the file", {path.string(), ""});
  }
  if (importer.problem()) return invalidInput(*importer.problem(), {path.string(), ""});
  PolygonSoup& soup = importer.soup();
  BAKE_RETURN_IF_ERROR(checkDeclaredCounts(scan, soup, path));

  stats.degenerateFacesRemoved += soup.degenerateFaces + scan.degenerateFaces;
  if (scan.stlTriangles) {
    stats.degenerateFacesRemoved += *scan.stlTriangles - std::min(*scan.stlTriangles, soup.facesOffered);
  }
  return triangulate(std::move(soup), path, stats);
}

Status checkFinite(const float* values, int count, const std::string& name, std::size_t vertex,
                   const char* what) {
  for (int i = 0; i < count; ++i) {
    if (!std::isfinite(values[i])) {
      return invalidInput(std::string(what) + " is not finite", {name, "vertex " + std::to_string(vertex)});
    }
  }
  return {};
}

}  // namespace

Status validateMesh(const TriangleMesh& mesh, const std::string& name) {
  const std::size_t vertexCount = mesh.positions.size();
  if (!mesh.normals.empty() && mesh.normals.size() != vertexCount) {
    return invalidInput("there are " + std::to_string(mesh.normals.size()) + " normals for " +
                            std::to_string(vertexCount) + " vertices",
                        {name, ""});
  }
  if (!mesh.texcoords.empty() && mesh.texcoords.size() != vertexCount) {
    return invalidInput("there are " + std::to_string(mesh.texcoords.size()) + " texture coordinates for " +
                            std::to_string(vertexCount) + " vertices",
                        {name, ""});
  }
  for (std::size_t v = 0; v < vertexCount; ++v) {
    BAKE_RETURN_IF_ERROR(checkFinite(mesh.positions[v].data(), 3, name, v, "position"));
    if (!mesh.normals.empty()) {
      BAKE_RETURN_IF_ERROR(checkFinite(mesh.normals[v].data(), 3, name, v, "normal"));
    }
    if (!mesh.texcoords.empty()) {
      BAKE_RETURN_IF_ERROR(checkFinite(mesh.texcoords[v].data(), 2, name, v, "texture coordinate"));
    }
  }
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (std::uint32_t index : mesh.triangles[t]) {
      if (index >= vertexCount) {
        return invalidInput("vertex index " + std::to_string(index) + " is out of range (" +
                                std::to_string(vertexCount) + " vertices)",
                            {name, "triangle " + std::to_string(t)});
      }
    }
  }
  return {};
}

Result<TriangleMesh> readMesh(const fs::path& path, const MeshReadOptions& options, MeshReadStats* stats) {
  MeshReadStats localStats;
  MeshReadStats& counts = stats ? *stats : localStats;
  counts = {};
  if (!std::isfinite(options.weldTolerance) || options.weldTolerance < 0.0) {
    return usageError("the weld tolerance must be a finite, non-negative number");
  }
  const std::string extension = lowercase(path.extension().string());
  const MeshFormat format = formatOf(extension);
  if (format == MeshFormat::Unknown) {
    const std::string what = extension.empty() ? "a file without extension" : "extension '" + extension + "'";
    return unsupported("unknown mesh format: " + what + " (expected .obj, .ply, .off, .stl, .gltf or .glb)",
                       {path.string(), ""});
  }

  TriangleMesh mesh;
  if (format == MeshFormat::Gltf) {
    BAKE_ASSIGN_OR_RETURN(mesh, readGltfMesh(path, &counts));
  } else {
    BAKE_ASSIGN_OR_RETURN(mesh, readWithOpenMesh(path, format, counts));
  }
  if (mesh.triangles.empty()) {
    return invalidInput(counts.degenerateFacesRemoved
                            ? "every face is degenerate (fewer than 3 distinct vertices)"
                            : "the file contains no faces",
                        {path.string(), ""});
  }
  BAKE_RETURN_IF_ERROR(validateMesh(mesh, path.string()));

  if (options.weld) {
    const WeldStats weld = weldVertices(mesh, options.weldTolerance);
    counts.verticesWelded += weld.verticesWelded;
    counts.degenerateFacesRemoved += weld.degenerateTrianglesRemoved;
    if (mesh.triangles.empty()) {
      return invalidInput("every triangle collapsed when welding vertices", {path.string(), ""});
    }
  }
  return mesh;
}

}  // namespace bake
