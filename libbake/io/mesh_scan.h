// Line-level pre-scans of the text-based mesh formats, run by readMesh (io/mesh_read.cpp) before
// OpenMesh parses the file. OpenMesh's parsers report almost nothing about malformed input (a bad
// number just desynchronises the stream, a PLY header without end_header even hangs), so each format
// gets a light scan that stops at the first malformed line and names it, plus size checks for the
// binary variants. One file per format (mesh_scan_obj/off/ply/stl.cpp); the text helpers they share
// live in mesh_scan_common.cpp. Internal to io/, not part of the library's API.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "bake/core/status.h"

namespace bake::meshscan {

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
  std::size_t objFaces = 0;  // OBJ face lines (each one triangle or more)
  // Vertex coordinates as the text gives them, in double (OBJ, OFF and PLY in ASCII; empty otherwise),
  // in file order: OpenMesh's parsers read them as float.
  std::vector<std::array<double, 3>> positions;
};

// The per-format scans; `text` is the whole file. Each returns the first problem as an error naming
// the file and line (or element).
Result<Prescan> prescanObj(std::string_view text, const std::filesystem::path& path);
Result<Prescan> prescanOff(std::string_view text, const std::filesystem::path& path);
Result<Prescan> prescanPly(std::string_view text, const std::filesystem::path& path);
Result<Prescan> prescanStl(std::string_view bytes, const std::filesystem::path& path);
// Binary when the size matches the triangle count in the header (OpenMesh's own rule).
bool isBinaryStl(std::string_view bytes);

// ---------------------------------------------------------------------------------------------------
// Text helpers shared by the pre-scans (mesh_scan_common.cpp).

struct TextLine {
  std::size_t number = 0;  // 1-based
  std::string_view text;   // without the line break and surrounding whitespace
  std::string_view raw;    // without the "\n" only
};

bool isBlank(char c);
std::string_view trimmed(std::string_view text);
std::string_view firstWord(std::string_view text);
std::vector<std::string_view> splitWords(std::string_view text);
std::string inQuotes(std::string_view word);

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

// Whole-word integer; a leading '+' is allowed like in strtol.
std::optional<long long> parseInteger(std::string_view word);

// Errors naming "line N" of `path`.
Status lineError(const std::filesystem::path& path, std::size_t line, std::string message);
Status lineUnsupported(const std::filesystem::path& path, std::size_t line, std::string message);

// Checks that `words[first, first + count)` are numbers; `finiteCount` of them (from `first`) must
// also be finite 32-bit floats. `what` names the values in messages ("vertex coordinate").
Status checkNumbers(const std::filesystem::path& path, const TextLine& line,
                    const std::vector<std::string_view>& words, std::size_t first, std::size_t count,
                    std::size_t finiteCount, const char* what);

// The number at `words[at]` in double, and the three from `first`, for words checkNumbers accepted.
double realAt(const std::vector<std::string_view>& words, std::size_t at);
std::array<double, 3> coordinatesAt(const std::vector<std::string_view>& words, std::size_t first);

}  // namespace bake::meshscan
