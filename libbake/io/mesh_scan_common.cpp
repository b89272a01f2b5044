// Text helpers shared by the mesh pre-scans (io/mesh_scan.h): whitespace tokenising, whole-word
// number parsing and checks, and the builders of errors that name a line. The line reader itself,
// LineCursor, is small enough to live in the header.
#include <charconv>
#include <cmath>
#include <limits>
#include <system_error>

#include "io/mesh_scan.h"

namespace bake::meshscan {
namespace fs = std::filesystem;

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

std::string_view trimmed(std::string_view text) {
  while (!text.empty() && isBlank(text.front())) text.remove_prefix(1);
  while (!text.empty() && isBlank(text.back())) text.remove_suffix(1);
  return text;
}

std::string_view firstWord(std::string_view text) {
  std::size_t end = 0;
  while (end < text.size() && !isBlank(text[end])) ++end;
  return text.substr(0, end);
}

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

std::optional<long long> parseInteger(std::string_view word) {
  if (word.size() > 1 && word.front() == '+' && word[1] != '-') word.remove_prefix(1);
  long long value = 0;
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (error != std::errc() || end != word.data() + word.size()) return std::nullopt;
  return value;
}

namespace {

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

bool fitsFloat(double value) {
  return std::isfinite(value) && std::abs(value) <= double(std::numeric_limits<float>::max());
}

}  // namespace

Status lineError(const fs::path& path, std::size_t line, std::string message) {
  return invalidInput(std::move(message), {path.string(), "line " + std::to_string(line)});
}

Status lineUnsupported(const fs::path& path, std::size_t line, std::string message) {
  return unsupported(std::move(message), {path.string(), "line " + std::to_string(line)});
}

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

double realAt(const std::vector<std::string_view>& words, std::size_t at) { return parseReal(words[at]).value_or(0.0); }

std::array<double, 3> coordinatesAt(const std::vector<std::string_view>& words, std::size_t first) {
  return {realAt(words, first), realAt(words, first + 1), realAt(words, first + 2)};
}

}  // namespace bake::meshscan
