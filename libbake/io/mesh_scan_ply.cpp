// Pre-scan of PLY files. The header is parsed for every PLY (OpenMesh loops forever on a header
// without end_header) and checked for what OpenMesh needs: x, y, z on the vertices, a vertex-index
// list on the faces, a list count type its reader accepts, in ASCII no list properties other than
// the face indices (its ASCII reader skips other properties one word at a time, which
// desynchronises on lists), and in binary 'end_header' exactly where OpenMesh looks for the data.
// ASCII bodies are then checked line by line against the header, binary ones for size and list
// counts. The declared counts go back to readMesh, which checks that they all arrived.
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "io/mesh_scan.h"

namespace bake::meshscan {
namespace fs = std::filesystem;

namespace {

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
  bool bigEndian = false;  // binary_big_endian
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
  header.bigEndian = format[1] == "binary_big_endian";
  // PLY has one version, 1.0; OpenMesh's reader loops forever on a version it cannot read as a number.
  {
    const std::string version(format[2]);
    char* end = nullptr;
    const double number = std::strtod(version.c_str(), &end);
    if (version.empty() || end != version.c_str() + version.size() || number != 1.0) {
      return lineError(path, line.number, "unknown PLY version " + inQuotes(format[2]) + " (expected 1.0)");
    }
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
      if (!count) return lineError(path, line.number, "malformed element line (expected: element NAME COUNT)");
      if (*count < 0) {
        return lineError(path, line.number, "element " + inQuotes(words[1]) + " has a negative count " + std::string(words[2]));
      }
      if (*count > std::numeric_limits<std::int32_t>::max()) {
        return lineError(path, line.number, "element " + inQuotes(words[1]) + " count " + std::string(words[2]) +
                                                " is more than the largest supported, " +
                                                std::to_string(std::numeric_limits<std::int32_t>::max()));
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
// `xyz`, when given, receives the line's x, y and z in double.
Status scanPlyLine(const fs::path& path, const TextLine& line, const PlyElement& element, bool isFaceElement,
                   std::size_t vertexCount, std::array<double, 3>* xyz) {
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
      const std::size_t axis = property.name == "x" ? 0 : property.name == "y" ? 1 : property.name == "z" ? 2 : 3;
      if (xyz && axis < 3) (*xyz)[axis] = realAt(words, at);
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

Status scanPlyAsciiBody(std::string_view text, const PlyHeader& header, const fs::path& path,
                        std::vector<std::array<double, 3>>& positions) {
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
      const bool isVertex = e == header.vertexElement;
      std::array<double, 3> xyz{};
      BAKE_RETURN_IF_ERROR(scanPlyLine(path, line, element, e == header.faceElement, header.vertices().count,
                                       isVertex ? &xyz : nullptr));
      if (isVertex) positions.push_back(xyz);
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

// A list count of a binary body: an integer of a PLY type, signed or not, in the file's byte order
// (the caller checked that its bytes are there).
std::int64_t readPlyCount(std::string_view text, std::size_t at, const std::string& type, bool bigEndian) {
  const std::size_t size = plyTypeSize(type);
  std::uint64_t raw = 0;
  for (std::size_t i = 0; i < size; ++i) raw = (raw << 8) | std::uint8_t(text[at + (bigEndian ? i : size - 1 - i)]);
  const bool isSigned = type == "char" || type == "int8" || type == "short" || type == "int16" || type == "int" || type == "int32";
  if (isSigned && ((raw >> (8 * size - 1)) & 1)) return std::int64_t(raw) - (std::int64_t(1) << (8 * size));
  return std::int64_t(raw);
}

// A binary body with lists, element by element: every list count must be non-negative and every
// element must fit in the bytes that are left. OpenMesh's reader trusts the counts (a negative one
// became an allocation of gigabytes). Bodies without lists are checked by their size alone.
Status scanPlyBinaryBody(std::string_view text, const PlyHeader& header, const fs::path& path) {
  std::size_t at = header.dataOffset;
  for (const PlyElement& element : header.elements) {
    const bool hasList = std::any_of(element.properties.begin(), element.properties.end(),
                                     [](const PlyProperty& property) { return property.isList(); });
    if (!hasList) {
      at += minimumPlyElementBytes(element);  // exact without lists; prescanPly checked the total
      continue;
    }
    for (std::size_t i = 0; i < element.count; ++i) {
      for (const PlyProperty& property : element.properties) {
        const std::string where = element.name + " " + std::to_string(i) + ", property " + inQuotes(property.name);
        const std::size_t size = plyTypeSize(property.isList() ? property.countType : property.type);
        if (text.size() - std::min(text.size(), at) < size) {
          return invalidInput("binary PLY is truncated: the data ends inside this element", {path.string(), where});
        }
        if (!property.isList()) {
          at += size;
          continue;
        }
        const std::int64_t count = readPlyCount(text, at, property.countType, header.bigEndian);
        if (count < 0) return invalidInput("list count " + std::to_string(count) + " is negative", {path.string(), where});
        at += size;
        const std::uint64_t items = std::uint64_t(count) * plyTypeSize(property.type);
        if (text.size() - std::min(text.size(), at) < items) {
          return invalidInput("binary PLY is truncated: a list of " + std::to_string(count) + " items runs past the end",
                              {path.string(), where});
        }
        at += std::size_t(items);
      }
    }
  }
  return {};
}

}  // namespace

Result<Prescan> prescanPly(std::string_view text, const fs::path& path) {
  BAKE_ASSIGN_OR_RETURN(const PlyHeader header, parsePlyHeader(text, path));
  Prescan scan;
  if (header.ascii) {
    BAKE_RETURN_IF_ERROR(scanPlyAsciiBody(text, header, path, scan.positions));
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
    BAKE_RETURN_IF_ERROR(scanPlyBinaryBody(text, header, path));
  }
  scan.declaredVertices = header.vertices().count;
  scan.declaredFaces = header.faceElement ? header.elements[*header.faceElement].count : 0;
  scan.verticesWhere = "line " + std::to_string(header.vertices().headerLine);
  scan.facesWhere = header.faceElement
                        ? "line " + std::to_string(header.elements[*header.faceElement].headerLine)
                        : "header";
  return scan;
}

}  // namespace bake::meshscan
