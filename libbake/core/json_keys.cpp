// JSON input helpers (core/json_keys.h).
#include "core/json_keys.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace bake {

const nlohmann::json& jsonMember(const nlohmann::json& object, const char* key) {
  static const nlohmann::json kNull;
  if (!object.is_object()) return kNull;
  const auto found = object.find(key);
  return found == object.end() ? kNull : *found;
}

double jsonNumberOr(const nlohmann::json& object, const char* key, double fallback) {
  const nlohmann::json& value = jsonMember(object, key);
  return value.is_number() ? value.get<double>() : fallback;
}

std::string jsonStringOr(const nlohmann::json& object, const char* key, const std::string& fallback) {
  const nlohmann::json& value = jsonMember(object, key);
  return value.is_string() ? value.get<std::string>() : fallback;
}

std::int64_t jsonIndexOr(const nlohmann::json& object, const char* key) {
  const nlohmann::json& value = jsonMember(object, key);
  if (value.is_number_unsigned()) {
    const std::uint64_t index = value.get<std::uint64_t>();
    return index <= std::uint64_t(std::numeric_limits<std::int64_t>::max()) ? std::int64_t(index) : -1;
  }
  if (value.is_number_integer() && value.get<std::int64_t>() >= 0) return value.get<std::int64_t>();
  return -1;
}

std::string jsonPointerChild(const std::string& parent, const std::string& key) {
  std::string escaped;
  for (char c : key) {
    if (c == '~') escaped += "~0";
    else if (c == '/') escaped += "~1";
    else escaped += c;
  }
  return parent + "/" + escaped;
}

std::string jsonPointerChild(const std::string& parent, std::size_t index) { return parent + "/" + std::to_string(index); }

std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

namespace {

std::optional<UnknownKey> unknownKeyAmong(const nlohmann::json& object, const char* const* begin, const char* const* end) {
  for (const auto& item : object.items()) {
    const std::string& key = item.key();  // a named reference, not a structured binding: lambdas capture it
    if (std::find_if(begin, end, [&](const char* k) { return key == k; }) != end) continue;
    std::string best;
    std::size_t bestDistance = std::numeric_limits<std::size_t>::max();
    for (const char* const* k = begin; k != end; ++k) {
      const std::size_t d = editDistance(key, *k);
      if (d < bestDistance) bestDistance = d, best = *k;
    }
    std::string message = "unknown key \"" + key + "\"";
    if (bestDistance <= std::max<std::size_t>(2, key.size() / 3)) message += " (did you mean \"" + best + "\"?)";
    return UnknownKey{key, message};
  }
  return std::nullopt;
}

}  // namespace

std::optional<UnknownKey> findUnknownKey(const nlohmann::json& object, std::initializer_list<const char*> known) {
  return unknownKeyAmong(object, known.begin(), known.end());
}

std::optional<UnknownKey> findUnknownKey(const nlohmann::json& object, const std::vector<const char*>& known) {
  return unknownKeyAmong(object, known.data(), known.data() + known.size());
}

Status JsonReader::error(const std::string& where, const std::string& message) const {
  return invalidInput(message, {file, where.empty() ? "/" : where});
}

Status JsonReader::object(const nlohmann::json& node, const std::string& where,
                          std::initializer_list<const char*> known) const {
  if (!node.is_object()) return error(where, "must be a JSON object");
  if (const auto unknown = unknownKeyAmong(node, known.begin(), known.end()))
    return error(jsonPointerChild(where, unknown->key), unknown->message);
  return Status::ok();
}

Status JsonReader::object(const nlohmann::json& node, const std::string& where,
                          const std::vector<const char*>& known) const {
  if (!node.is_object()) return error(where, "must be a JSON object");
  if (const auto unknown = unknownKeyAmong(node, known.data(), known.data() + known.size()))
    return error(jsonPointerChild(where, unknown->key), unknown->message);
  return Status::ok();
}

Result<double> JsonReader::number(const nlohmann::json& node, const std::string& where) const {
  if (!node.is_number()) return error(where, "must be a number");
  const double x = node.get<double>();
  if (!std::isfinite(x)) return error(where, "must be a finite number (NaN or Inf)");
  return x;
}

Result<std::string> JsonReader::string(const nlohmann::json& node, const std::string& where) const {
  if (!node.is_string()) return error(where, "must be a string");
  return node.get<std::string>();
}

}  // namespace bake
