#include <cstdio>
#include "bake/core/vector_text.h"

#include <cctype>
#include <cmath>
#include <cstdlib>

namespace bake {
namespace {

bool parseNumbers(const std::string& text, double* out, std::size_t count) {
  const char* at = text.c_str();
  for (std::size_t k = 0; k < count; ++k) {
    char* end = nullptr;
    out[k] = std::strtod(at, &end);
    if (end == at || !std::isfinite(out[k])) return false;
    at = end;
    while (std::isspace(static_cast<unsigned char>(*at))) ++at;
    if (k + 1 < count) {
      if (*at != ',') return false;
      ++at;
    }
  }
  return *at == '\0';
}

template <std::size_t N>
Result<std::array<double, N>> parseVector(const std::string& text, const std::string& option, const char* form) {
  std::array<double, N> values{};
  if (!parseNumbers(text, values.data(), N)) {
    return usageError(option + " " + text + ": expected " + form + " (" + std::to_string(N) + " finite numbers)");
  }
  return values;
}

}  // namespace

Result<std::array<double, 3>> parseTriple(const std::string& text, const std::string& option, const char* form) {
  return parseVector<3>(text, option, form);
}

Result<std::array<double, 2>> parsePair(const std::string& text, const std::string& option, const char* form) {
  return parseVector<2>(text, option, form);
}

std::string numberText(double value, int digits) {
  char text[48];
  std::snprintf(text, sizeof text, "%.*g", digits, value);
  return text;
}

}  // namespace bake
