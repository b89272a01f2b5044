// Pre-scan of OFF files: the header keyword, the counts line, then exactly the declared vertex and
// face lines. OpenMesh reads OFF with stream extraction, so a comment after the keyword would be
// taken for numbers and a line with too many or too few values shifts everything after it (trailing
// face colours are consumed only when the header announces them); each of these is reported naming
// its line. Binary OFF only gets a size check, as OpenMesh would otherwise read past the end for as
// many faces as the header claims. The declared counts go back to readMesh, which checks that they
// all arrived.
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "io/mesh_scan.h"

namespace bake::meshscan {
namespace fs = std::filesystem;

namespace {

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

Status scanOffVertex(const fs::path& path, const TextLine& line, const OffHeader& header,
                     std::vector<std::array<double, 3>>& positions) {
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
  positions.push_back(coordinatesAt(words, 0));
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

}  // namespace

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

  Prescan scan;
  for (std::size_t v = 0; v < counts.vertices; ++v) {
    if (!nextDataLine(line)) return endsEarly("vertices", v, counts.vertices);
    BAKE_RETURN_IF_ERROR(rejectComment(line));
    BAKE_RETURN_IF_ERROR(scanOffVertex(path, line, header, scan.positions));
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
  scan.declaredVertices = counts.vertices;
  scan.declaredFaces = counts.faces;
  scan.verticesWhere = scan.facesWhere = "line " + std::to_string(countsLine);
  return scan;
}

}  // namespace bake::meshscan
