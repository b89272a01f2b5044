// The CSV splitter and number reader (core/csv_read.h).
#include "core/csv_read.h"

#include <cstdlib>

namespace bake {
namespace {

constexpr std::string_view kBlanks = " \t\r";

std::string_view trimmed(std::string_view text) {
  const std::size_t first = text.find_first_not_of(kBlanks);
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(kBlanks) - first + 1);
}

std::vector<std::string> splitFields(std::string_view line) {
  std::vector<std::string> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    fields.emplace_back(trimmed(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start)));
    if (comma == std::string_view::npos) return fields;
    start = comma + 1;
  }
}

CsvLine splitLine(std::string_view line, std::size_t number, CsvComments comments) {
  CsvLine out;
  out.number = number;
  const std::size_t hash = comments == CsvComments::Anywhere ? line.find('#') : std::string_view::npos;
  if (hash != std::string_view::npos) {
    out.comment = true;
    line = line.substr(0, hash);
  }
  line = trimmed(line);
  if (comments == CsvComments::LineStart && !line.empty() && line.front() == '#') {
    out.comment = true;
    return out;
  }
  if (!line.empty()) out.fields = splitFields(line);
  return out;
}

}  // namespace

std::vector<CsvLine> splitCsv(std::string_view text, CsvComments comments) {
  std::vector<CsvLine> lines;
  std::size_t start = 0, number = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    lines.push_back(splitLine(text.substr(start, end - start), ++number, comments));
    start = end + 1;
  }
  return lines;
}

bool parseCsvNumber(const std::string& field, double& out) {
  if (field.empty()) return false;
  char* end = nullptr;
  out = std::strtod(field.c_str(), &end);
  return *end == '\0';
}

}  // namespace bake
